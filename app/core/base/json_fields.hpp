#pragma once
// Strict reading of JSON objects for sessions and presets: every problem
// becomes an InputError naming the source, the field path and what is accepted.

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/base/enum_names.hpp"
#include "core/base/errors.hpp"
#include "core/base/names.hpp"

namespace morphogen {

// The float a double rounds to, infinite past float's range (where a plain
// conversion is undefined).
inline float asFloat(double v) {
    const double largest = std::numeric_limits<float>::max();
    if (v > largest || v < -largest)
        return v > 0 ? std::numeric_limits<float>::infinity()
                     : -std::numeric_limits<float>::infinity();
    return float(v);
}

inline std::string typeName(const nlohmann::json& j) {
    return j.type_name();
}

// Reads fields of one JSON object and reports problems as "source: field 'a.b' ...".
class FieldReader {
public:
    FieldReader(const nlohmann::json& object, std::string source, std::string prefix)
        : m_object(object), m_source(std::move(source)), m_prefix(std::move(prefix)) {
        if (!m_object.is_object())
            fail(m_prefix.empty() ? "the top level" : "field '" + m_prefix + "'",
                 "must be a JSON object, got " + typeName(m_object));
    }

    [[noreturn]] void fail(const std::string& what, const std::string& problem) const {
        throw InputError(m_source + ": " + what + " " + problem);
    }
    std::string path(const std::string& key) const {
        return m_prefix.empty() ? key : m_prefix + "." + key;
    }
    [[noreturn]] void failField(const std::string& key, const std::string& problem) const {
        fail("field '" + path(key) + "'", problem);
    }

    const nlohmann::json* find(const std::string& key) const {
        auto it = m_object.find(key);
        return it == m_object.end() ? nullptr : &*it;
    }

    void rejectUnknown(std::initializer_list<const char*> known) const {
        for (auto it = m_object.begin(); it != m_object.end(); ++it) {
            bool ok = false;
            for (const char* k : known)
                ok = ok || it.key() == k;
            if (!ok)
                fail(
                    "unknown field '" + path(it.key()) + "'",
                    "(accepted: " + joinNames(known) + ")" +
                        didYouMean(it.key(), std::vector<std::string>(known.begin(), known.end())));
        }
    }

    std::string string(const std::string& key, const std::string& fallback) const {
        const nlohmann::json* j = find(key);
        if (!j)
            return fallback;
        if (!j->is_string())
            failField(key, "must be a string, got " + typeName(*j));
        return j->get<std::string>();
    }

    // A string naming one value of an enumeration: `parse` reads the names,
    // `accepted` lists them for the error.
    template <class E>
    E choice(const std::string& key, E fallback, std::optional<E> (*parse)(std::string_view),
             const std::string& accepted) const {
        if (!find(key))
            return fallback;
        const std::string name = string(key, "");
        const std::optional<E> value = parse(name);
        if (!value)
            failField(key, "is '" + name + "', accepted: " + accepted +
                               didYouMean(name, splitNameList(accepted)));
        return *value;
    }

    bool boolean(const std::string& key, bool fallback) const {
        const nlohmann::json* j = find(key);
        if (!j)
            return fallback;
        if (!j->is_boolean())
            failField(key, "must be true or false, got " + typeName(*j));
        return j->get<bool>();
    }

    double number(const std::string& key, double fallback, double min, double max) const {
        const nlohmann::json* j = find(key);
        if (!j)
            return fallback;
        return numberValue(*j, key, min, max);
    }

    double numberValue(const nlohmann::json& j, const std::string& key, double min,
                       double max) const {
        if (!j.is_number())
            failField(key, "must be a number, got " + typeName(j));
        const double v = j.get<double>();
        // Most fields are stored as floats and written back as the double of
        // that float: dt 1e-6 comes back as 9.99999997e-07. A value whose
        // float is a bound's float is the bound (clamped), so every session
        // the program writes reads back.
        const bool inRange =
            (v >= min && v <= max) || (asFloat(v) >= asFloat(min) && asFloat(v) <= asFloat(max));
        if (!std::isfinite(v) || !inRange) {
            std::ostringstream os;
            os << "is " << v << ", accepted range is [" << min << ", " << max << "]";
            failField(key, os.str());
        }
        return std::clamp(v, min, max);
    }

    long long integer(const std::string& key, long long fallback, long long min,
                      long long max) const {
        const nlohmann::json* j = find(key);
        if (!j)
            return fallback;
        if (!j->is_number_integer())
            failField(key, "must be an integer, got " + typeName(*j));
        const std::string accepted =
            ", accepted range is [" + std::to_string(min) + ", " + std::to_string(max) + "]";
        // Past LLONG_MAX (up to 2^64 - 1) a signed cast would wrap to a negative value.
        if (j->is_number_unsigned() &&
            j->get<unsigned long long>() > static_cast<unsigned long long>(max))
            failField(key, "is " + std::to_string(j->get<unsigned long long>()) + accepted);
        const long long v = j->get<long long>();
        if (v < min || v > max)
            failField(key, "is " + std::to_string(v) + accepted);
        return v;
    }

    const std::string& source() const { return m_source; }

private:
    const nlohmann::json& m_object;
    std::string m_source;
    std::string m_prefix;
};

} // namespace morphogen
