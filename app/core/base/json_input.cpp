#include "core/base/json_input.hpp"

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"

namespace morphogen {

namespace {

// Line and column (from 1) of `offset` in `text`.
std::string position(std::string_view text, std::size_t offset) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// nlohmann's message without its "[json.exception.parse_error.101] " prefix.
std::string withoutPrefix(const std::string& what) {
    const std::size_t close = what.find("] ");
    return what.rfind("[json.exception.", 0) == 0 && close != std::string::npos
               ? what.substr(close + 2)
               : what;
}

} // namespace

int jsonNestingDepth(std::string_view text, int stopAbove, std::size_t* offset) {
    int depth = 0, deepest = 0;
    bool inString = false, escaped = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                inString = false;
            continue;
        }
        if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > deepest) {
                deepest = depth;
                if (offset)
                    *offset = i;
                if (deepest > stopAbove)
                    return deepest;
            }
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

nlohmann::json parseJsonText(std::string_view text, const std::string& source) {
    if (std::int64_t(text.size()) > kMaxJsonBytes)
        throw InputError(source + ": " + std::to_string(text.size()) +
                         " bytes of JSON; accepted are up to " + std::to_string(kMaxJsonBytes) +
                         " bytes (16 MiB)");
    std::size_t at = 0;
    if (jsonNestingDepth(text, kMaxJsonDepth, &at) > kMaxJsonDepth)
        throw InputError(source + ": arrays and objects nested more than " +
                         std::to_string(kMaxJsonDepth) + " levels deep (at " + position(text, at) +
                         "); accepted are up to " + std::to_string(kMaxJsonDepth) + " levels");
    // nlohmann keeps the last of two equal keys in an object; a file that
    // says a thing twice is refused instead, naming the key and where it is.
    struct Level {
        bool object;
        std::string path;
        std::set<std::string> keys;
    };
    std::vector<Level> levels;
    std::string key; // the key whose value comes next
    const auto childPath = [&]() {
        if (levels.empty())
            return std::string();
        const Level& parent = levels.back();
        return parent.object ? (parent.path.empty() ? key : parent.path + "." + key)
                             : parent.path + "[]";
    };
    const nlohmann::json::parser_callback_t checkKeys =
        [&](int, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
            using Event = nlohmann::json::parse_event_t;
            switch (event) {
            case Event::object_start:
            case Event::array_start:
                levels.push_back({event == Event::object_start, childPath(), {}});
                break;
            case Event::object_end:
            case Event::array_end:
                if (!levels.empty())
                    levels.pop_back();
                break;
            case Event::key:
                key = parsed.get<std::string>();
                if (!levels.empty() && !levels.back().keys.insert(key).second)
                    throw InputError(source + ": key '" + childPath() +
                                     "' appears twice in one object; give each key once");
                break;
            case Event::value:
                break;
            }
            return true;
        };
    try {
        return nlohmann::json::parse(text.begin(), text.end(), checkKeys);
    } catch (const nlohmann::json::parse_error& e) {
        throw InputError(source + ": not valid JSON: " + oneLine(withoutPrefix(e.what())));
    } catch (const nlohmann::json::out_of_range& e) {
        // 406: a number such as 1e400 that no double holds; nlohmann names it
        // but not where it is.
        if (e.id == 406)
            throw InputError(source + ": not valid JSON: " + oneLine(withoutPrefix(e.what())) +
                             " (numbers must be within about +-1.8e308)");
        throw InputError(source + ": not valid JSON: " + oneLine(withoutPrefix(e.what())));
    } catch (const nlohmann::json::exception& e) {
        throw InputError(source + ": not valid JSON: " + oneLine(withoutPrefix(e.what())));
    }
}

std::string readInputFile(const std::string& path, const std::string& what) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (fs::is_directory(status))
        throw InputError(path + ": is a folder, not a " + what);
    if (fs::is_regular_file(status)) {
        const std::uintmax_t size = fs::file_size(path, ec);
        if (!ec && size > std::uintmax_t(kMaxJsonBytes))
            throw InputError(path + ": the " + what + " is " + std::to_string(size) +
                             " bytes; accepted are up to " + std::to_string(kMaxJsonBytes) +
                             " bytes (16 MiB)");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(path + ": cannot open " + what + " (does it exist and is it readable?)");
    // A pipe or device has no size up front: read one byte past the limit.
    std::string text;
    char buffer[65536];
    while (in && std::int64_t(text.size()) <= kMaxJsonBytes) {
        in.read(buffer, sizeof buffer);
        text.append(buffer, std::size_t(in.gcount()));
    }
    if (std::int64_t(text.size()) > kMaxJsonBytes)
        throw InputError(path + ": the " + what + " is over " + std::to_string(kMaxJsonBytes) +
                         " bytes; accepted are up to " + std::to_string(kMaxJsonBytes) +
                         " bytes (16 MiB)");
    if (in.bad())
        throw InputError(path + ": reading the " + what + " failed");
    return text;
}

std::string oneLine(std::string_view text, std::size_t maxLength) {
    std::string line;
    bool space = false;
    for (const char c : text) {
        const bool control = static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
        if (control || c == ' ') {
            space = !line.empty();
            continue;
        }
        if (space)
            line += ' ';
        space = false;
        line += c;
    }
    if (line.size() > maxLength)
        line = line.substr(0, maxLength > 3 ? maxLength - 3 : 0) + "...";
    return line;
}

} // namespace morphogen
