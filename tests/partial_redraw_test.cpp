// The designer's partial redraw on a software rasterizer (ui/partial_redraw.hpp):
// which windows a frame redraws, and when it must draw whole. GL-free: the plan.

#include <gtest/gtest.h>

#include "ui/partial_redraw.hpp"

using namespace morphogen::ui;

namespace {

// The designer's layout at 1600 x 1000, GL's way up: menu bar, controls,
// canvas, side panel, status line (side by side, sharing their edges).
std::vector<RedrawList> layout() {
    return {{"##status", 1, {0, 0, 1600, 27}},
            {"Library", 2, {1300, 25, 300, 955}},
            {"Canvas", 3, {341, 26, 958, 954}},
            {"Controls", 4, {0, 25, 340, 955}},
            {"##MainMenuBar", 5, {0, 979, 1600, 21}}};
}

PartialRedraw designerRedraw() {
    return PartialRedraw({"Canvas", "Model"}, {"Canvas"});
}

} // namespace

TEST(PartialRedraw, RedrawsTheLiveAndChangedWindowsOnly) {
    PartialRedraw r = designerRedraw();
    std::vector<RedrawList> lists = layout();
    // The first frames are whole (both buffers of a swap chain).
    EXPECT_TRUE(r.plan(lists, 1600, 1000, false).whole);
    EXPECT_TRUE(r.plan(lists, 1600, 1000, false).whole);
    // Nothing changed: only the canvas (live), not cleared (opaque).
    RedrawPlan p = r.plan(lists, 1600, 1000, false);
    ASSERT_FALSE(p.whole);
    ASSERT_EQ(p.redraw, std::vector<int>({2}));
    EXPECT_EQ(p.clear, std::vector<bool>({false}));
    // The status line's text changed: it too, cleared first.
    lists[0].hash = 11;
    p = r.plan(lists, 1600, 1000, false);
    ASSERT_FALSE(p.whole);
    EXPECT_EQ(p.redraw, std::vector<int>({0, 2}));
    EXPECT_EQ(p.clear, std::vector<bool>({true, false}));
    // A screenshot asks for a whole frame.
    EXPECT_TRUE(r.plan(lists, 1600, 1000, true).whole);
    EXPECT_FALSE(r.plan(lists, 1600, 1000, false).whole);
}

TEST(PartialRedraw, DrawsWholeWhenWindowsComeGoMoveOrOverlap) {
    PartialRedraw r = designerRedraw();
    std::vector<RedrawList> lists = layout();
    for (int i = 0; i < 3; ++i)
        r.plan(lists, 1600, 1000, false);
    // A tooltip appears (a new list), and goes.
    std::vector<RedrawList> tooltip = lists;
    tooltip.push_back({"##Tooltip_00", 9, {600, 400, 120, 40}});
    EXPECT_TRUE(r.plan(tooltip, 1600, 1000, false).whole);
    EXPECT_TRUE(r.plan(lists, 1600, 1000, false).whole);
    EXPECT_FALSE(r.plan(lists, 1600, 1000, false).whole);
    // A window moves (its old pixels must go).
    std::vector<RedrawList> moved = lists;
    moved[1].rect.y += 10;
    moved[1].rect.h -= 10;
    EXPECT_TRUE(r.plan(moved, 1600, 1000, false).whole);
    EXPECT_FALSE(r.plan(moved, 1600, 1000, false).whole);
    // A changed window over a kept one (by more than the shared edge).
    std::vector<RedrawList> over = moved;
    over[0].rect.h = 60;
    over[0].hash = 77;
    EXPECT_TRUE(r.plan(over, 1600, 1000, false).whole);
    EXPECT_TRUE(r.plan(moved, 1600, 1000, false).whole); // and back
    EXPECT_FALSE(r.plan(moved, 1600, 1000, false).whole);
    // The framebuffer's size changes: whole again, twice.
    EXPECT_TRUE(r.plan(moved, 1200, 800, false).whole);
    EXPECT_TRUE(r.plan(moved, 1200, 800, false).whole);
    EXPECT_FALSE(r.plan(moved, 1200, 800, false).whole);
    // invalidate(): a texture in a kept window was replaced.
    r.invalidate();
    EXPECT_TRUE(r.plan(moved, 1200, 800, false).whole);
}

TEST(PartialRedraw, SharedEdgesAreNotOverlaps) {
    // Side by side, sharing up to two pixels (antialiased borders): apart.
    EXPECT_FALSE((RedrawRect{0, 0, 100, 50}).overlaps({98, 0, 100, 50}));
    EXPECT_FALSE((RedrawRect{0, 0, 100, 27}).overlaps({0, 25, 100, 50}));
    EXPECT_TRUE((RedrawRect{0, 0, 100, 50}).overlaps({97, 0, 100, 50}));
    EXPECT_TRUE((RedrawRect{10, 10, 20, 20}).overlaps({0, 0, 100, 100}));
}

TEST(PartialRedraw, SometimesDrawsWholeAnyway) {
    // A texture may change under a kept window's vertices without anyone
    // calling invalidate(): every 120th frame is whole.
    PartialRedraw r = designerRedraw();
    const std::vector<RedrawList> lists = layout();
    int whole = 0;
    for (int i = 0; i < 242; ++i)
        whole += r.plan(lists, 1600, 1000, false).whole;
    EXPECT_EQ(whole, 2 + 2);
}
