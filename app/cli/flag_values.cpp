#include "cli/flag_values.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/base/errors.hpp"

namespace morphogen::cli {

namespace {

std::string trimmed(const std::string& text) {
    const std::size_t first = text.find_first_not_of(" \t");
    if (first == std::string::npos)
        return "";
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

} // namespace

long long integerFlag(const std::string& flag, const std::string& text, long long min,
                      long long max, const std::string& hint) {
    const std::string t = trimmed(text);
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(t.c_str(), &end, 10);
    if (t.empty() || *end != '\0' || errno == ERANGE || v < min || v > max)
        throw InputError(flag + " '" + text + "': accepted are whole numbers " +
                         std::to_string(min) + ".." + std::to_string(max) + hint);
    return v;
}

double numberFlag(const std::string& flag, const std::string& text, double min, double max,
                  const std::string& hint) {
    const std::string t = trimmed(text);
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (t.empty() || *end != '\0' || !std::isfinite(v) || v < min || v > max) {
        std::ostringstream os;
        os << flag << " '" << text << "': accepted are numbers in [" << min << ", " << max << "]"
           << hint;
        throw InputError(os.str());
    }
    return v;
}

} // namespace morphogen::cli
