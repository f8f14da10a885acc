// The one matcher behind every "did you mean": close typos get the intended
// name, unrelated names get nothing, and spellings fold case and '-'/'_'.

#include <gtest/gtest.h>

#include "core/base/names.hpp"

using namespace morphogen;

namespace {

const std::vector<std::string> kMaps = {"grey",  "two-colour", "viridis",
                                        "magma", "inferno",    "coolwarm"};

} // namespace

TEST(Names, SameSpellingFoldsCaseAndSeparators) {
    EXPECT_TRUE(sameSpelling("Two_Colour", "two-colour"));
    EXPECT_TRUE(sameSpelling("semi-implicit", "semi_implicit"));
    EXPECT_FALSE(sameSpelling("semi implicit", "semi_implicit"));
    EXPECT_FALSE(sameSpelling("grey", "greys"));
    EXPECT_TRUE(sameSpelling("", ""));
}

TEST(Names, EditDistanceCountsSwapsAsOne) {
    EXPECT_EQ(editDistance("", ""), 0u);
    EXPECT_EQ(editDistance("abc", ""), 3u);
    EXPECT_EQ(editDistance("", "ab"), 2u);
    EXPECT_EQ(editDistance("viridis", "virdis"), 1u);     // deletion
    EXPECT_EQ(editDistance("gs_coral", "gs_corall"), 1u); // insertion
    EXPECT_EQ(editDistance("magma", "mamga"), 1u);        // swap of neighbours
    EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
    EXPECT_EQ(editDistance("ca", "abc"), 3u); // optimal string alignment, not full Damerau
    EXPECT_EQ(editDistance("inferno", "inferno"), 0u);
}

TEST(Names, ClosestNameFindsTyposAndPrefixes) {
    EXPECT_EQ(closestName("virdis", kMaps), "viridis");
    EXPECT_EQ(closestName("magam", kMaps), "magma");
    EXPECT_EQ(closestName("Inferno", kMaps), "inferno");
    EXPECT_EQ(closestName("two_color", kMaps), "two-colour");
    EXPECT_EQ(closestName("cool", kMaps), "coolwarm"); // prefix
    EXPECT_EQ(closestName("FF", {"F", "k"}), "F");
    EXPECT_EQ(closestName("f", {"F", "k"}), "F");
    EXPECT_EQ(closestName("gs_corall", {"gs_spots", "gs_coral", "gs_worms"}), "gs_coral");
}

TEST(Names, NothingCloseGivesNothing) {
    EXPECT_FALSE(closestName("rainbow", kMaps));
    EXPECT_FALSE(closestName("", kMaps));
    EXPECT_FALSE(closestName("xyz", {"F", "k"}));
    EXPECT_FALSE(closestName("ab", {"F", "k"})); // short names allow one edit only
    EXPECT_FALSE(closestName("x", {"F", "k"}));  // nothing left of the name
    EXPECT_FALSE(closestName("Q", {"u", "v"}));
    EXPECT_FALSE(closestName("co", kMaps)); // prefixes need 3 characters
    EXPECT_FALSE(closestName("viridis", {}));
}

TEST(Names, TiesGoToTheEarlierCandidate) {
    EXPECT_EQ(closestName("ab", {"abc", "abd"}), "abc");
    EXPECT_EQ(closestName("abd", {"abc", "abd"}), "abd"); // an exact match beats an earlier one
}

TEST(Names, DidYouMeanWordsTheSuggestion) {
    EXPECT_EQ(didYouMean("virdis", kMaps), " (did you mean 'viridis'?)");
    EXPECT_EQ(didYouMean("rainbow", kMaps), "");
}

TEST(Names, SplitNameListReadsJoinedLists) {
    EXPECT_EQ(splitNameList("a, b, c"), (std::vector<std::string>{"a", "b", "c"}));
    EXPECT_EQ(splitNameList("5-point,9-point"), (std::vector<std::string>{"5-point", "9-point"}));
    EXPECT_TRUE(splitNameList("").empty());
    EXPECT_EQ(splitNameList("one"), (std::vector<std::string>{"one"}));
}
