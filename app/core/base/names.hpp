#pragma once
// Names the user types: one spelling rule (case and '-'/'_' do not matter) and
// one "did you mean" for every place that refuses a name.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace morphogen {

// True when a and b differ only in letter case and in '-' versus '_'.
bool sameSpelling(std::string_view a, std::string_view b);

// Optimal-string-alignment (restricted Damerau-Levenshtein) distance: inserts,
// deletes, substitutions and swaps of neighbours each count one.
std::size_t editDistance(std::string_view a, std::string_view b);

// The candidate the user most likely meant by `name`, if one is close: an
// edit distance (ignoring case and '-'/'_') of at most 1 for names under 5
// characters, else at most max(2, a third of the length), and fewer edits than
// the longer name has characters ('x' is not close to 'F'); failing that, the
// candidate that `name` (3 characters or more) begins. Ties go to the earlier
// candidate.
std::optional<std::string> closestName(std::string_view name,
                                       const std::vector<std::string>& candidates);

// " (did you mean 'X'?)" for the closest candidate, or "" when none is close.
std::string didYouMean(std::string_view name, const std::vector<std::string>& candidates);

// "a, b, c" (as joinNames writes a list of accepted names) back to its names.
std::vector<std::string> splitNameList(std::string_view list);

} // namespace morphogen
