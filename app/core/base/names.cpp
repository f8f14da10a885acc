#include "core/base/names.hpp"

#include <algorithm>
#include <cctype>

namespace morphogen {

namespace {

char folded(char c) {
    return c == '-' ? '_' : char(std::tolower(static_cast<unsigned char>(c)));
}

std::string foldedName(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(), folded);
    return out;
}

std::size_t closeEnough(std::size_t length) {
    return length < 5 ? 1 : std::max<std::size_t>(2, length / 3);
}

} // namespace

bool sameSpelling(std::string_view a, std::string_view b) {
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (folded(a[i]) != folded(b[i]))
            return false;
    return true;
}

std::size_t editDistance(std::string_view a, std::string_view b) {
    const std::size_t n = a.size(), m = b.size();
    // Three rows: the swap of neighbours looks two rows back.
    std::vector<std::size_t> before(m + 1), previous(m + 1), current(m + 1);
    for (std::size_t j = 0; j <= m; ++j)
        previous[j] = j;
    for (std::size_t i = 1; i <= n; ++i) {
        current[0] = i;
        for (std::size_t j = 1; j <= m; ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                current[j] = std::min(current[j], before[j - 2] + 1);
        }
        std::swap(before, previous);
        std::swap(previous, current);
    }
    return previous[m];
}

std::optional<std::string> closestName(std::string_view name,
                                       const std::vector<std::string>& candidates) {
    const std::string typed = foldedName(name);
    if (typed.empty())
        return std::nullopt;
    const std::size_t limit = closeEnough(typed.size());
    std::optional<std::string> best;
    std::size_t bestDistance = limit + 1;
    for (const std::string& candidate : candidates) {
        const std::string folded = foldedName(candidate);
        const std::size_t d = editDistance(typed, folded);
        // Rewriting every character is no resemblance ('x' for 'F').
        if (d < bestDistance && d < std::max(typed.size(), folded.size())) {
            bestDistance = d;
            best = candidate;
        }
    }
    if (best || typed.size() < 3)
        return best;
    for (const std::string& candidate : candidates)
        if (foldedName(candidate).compare(0, typed.size(), typed) == 0)
            return candidate;
    return std::nullopt;
}

std::string didYouMean(std::string_view name, const std::vector<std::string>& candidates) {
    const std::optional<std::string> match = closestName(name, candidates);
    return match ? " (did you mean '" + *match + "'?)" : std::string();
}

std::vector<std::string> splitNameList(std::string_view list) {
    std::vector<std::string> names;
    std::size_t start = 0;
    while (start <= list.size()) {
        std::size_t end = list.find(',', start);
        if (end == std::string_view::npos)
            end = list.size();
        std::string_view item = list.substr(start, end - start);
        while (!item.empty() && item.front() == ' ')
            item.remove_prefix(1);
        while (!item.empty() && item.back() == ' ')
            item.remove_suffix(1);
        if (!item.empty())
            names.emplace_back(item);
        start = end + 1;
    }
    return names;
}

} // namespace morphogen
