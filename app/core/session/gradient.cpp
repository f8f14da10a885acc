#include "core/session/gradient.hpp"

#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/base/errors.hpp"
#include "core/base/json_input.hpp"

namespace morphogen {

namespace {

using Rgb = std::array<float, 3>;

int hexDigit(char c) {
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

std::string trim(const std::string& s) {
    const std::size_t a = s.find_first_not_of(" \t\r\n");
    if (a == std::string::npos)
        return "";
    return s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1);
}

const char* const kAccepted = "accepted: #rgb or #rrggbb hex colours, 2 to 16 of them";

Rgb colourItem(const std::string& item, const std::string& what) {
    const std::optional<Rgb> rgb = parseHexColour(item);
    if (!rgb)
        throw InputError(what + ": '" + item + "' is not a colour (" + kAccepted + ")");
    return *rgb;
}

} // namespace

bool isCustomColormapName(std::string_view name) {
    static const char* const custom = "custom";
    if (name.size() != 6)
        return false;
    for (std::size_t i = 0; i < 6; ++i)
        if (std::tolower((unsigned char)name[i]) != custom[i])
            return false;
    return true;
}

std::optional<Rgb> parseHexColour(std::string_view text) {
    if (text.size() != 4 && text.size() != 7)
        return std::nullopt;
    if (text[0] != '#')
        return std::nullopt;
    const bool shortForm = text.size() == 4;
    Rgb rgb{};
    for (std::size_t k = 0; k < 3; ++k) {
        int value = 0;
        if (shortForm) {
            const int d = hexDigit(text[1 + k]);
            if (d < 0)
                return std::nullopt;
            value = d * 17; // #abc is #aabbcc
        } else {
            const int hi = hexDigit(text[1 + 2 * k]), lo = hexDigit(text[2 + 2 * k]);
            if (hi < 0 || lo < 0)
                return std::nullopt;
            value = hi * 16 + lo;
        }
        rgb[k] = float(value) / 255.0f;
    }
    return rgb;
}

std::string hexColour(const Rgb& rgb) {
    static const char* const digits = "0123456789abcdef";
    std::string s = "#";
    for (float c : rgb) {
        const long v = std::lround(std::fmin(std::fmax(c, 0.0f), 1.0f) * 255.0f);
        s += digits[v / 16];
        s += digits[v % 16];
    }
    return s;
}

void checkGradientStops(std::size_t count, const std::string& what) {
    if (count < 2 || count > std::size_t(kMaxGradientStops))
        throw InputError(what + ": " + std::to_string(count) + " colour" + (count == 1 ? "" : "s") +
                         " given (" + kAccepted + ")");
}

std::vector<Rgb> parseGradient(const std::string& list, const std::string& what) {
    std::vector<Rgb> stops;
    std::stringstream in(list);
    std::string item;
    while (std::getline(in, item, ','))
        stops.push_back(colourItem(trim(item), what));
    checkGradientStops(stops.size(), what + " '" + list + "'");
    return stops;
}

std::vector<Rgb> loadPaletteFile(const std::string& path) {
    const std::string text = readInputFile(path, "palette file");
    const std::string head = trim(text);
    std::vector<Rgb> stops;
    if (!head.empty() && (head[0] == '[' || head[0] == '{')) {
        nlohmann::json j = parseJsonText(text, path + " (palette)");
        if (j.is_object()) {
            if (j.size() != 1 || !j.contains("colours"))
                throw InputError(path + ": a JSON palette object has one key, \"colours\"");
            j = j["colours"];
        }
        if (!j.is_array())
            throw InputError(path + ": \"colours\" must be an array of hex strings");
        for (const nlohmann::json& c : j) {
            if (!c.is_string())
                throw InputError(path + ": palette entry " + c.dump() + " is not a string (" +
                                 kAccepted + ")");
            stops.push_back(colourItem(c.get<std::string>(), path));
        }
    } else {
        std::stringstream lines(text);
        std::string line;
        while (std::getline(lines, line)) {
            if (trim(line).rfind("//", 0) == 0)
                continue;
            for (char& c : line)
                if (c == ',')
                    c = ' ';
            std::stringstream words(line);
            std::string word;
            while (words >> word)
                stops.push_back(colourItem(word, path));
        }
    }
    checkGradientStops(stops.size(), path);
    return stops;
}

} // namespace morphogen
