#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

struct ImDrawData;

namespace morphogen::ui {

// Draws a Dear ImGui frame, redrawing only the windows whose draw lists
// changed since the last frame, plus those named "live" (the canvas and the
// model view, whose textures change under unchanged vertices). Redrawn
// windows are cleared first, except "opaque" ones, which paint every pixel
// of theirs (the canvas: its picture and the background round it).
//
// Why: on a software rasterizer (Mesa llvmpipe, the designer's CI kind of
// machine) rasterizing the whole 1600 x 1000 window took some 11.6 ms of CPU
// per frame on 2 cores -- a third of a 30 fps frame, taken from the
// simulation -- although the panels rarely change between two frames.
//
// It relies on the back buffer keeping its pixels across a swap, which
// Mesa's software GLX does (the swap copies it to the window) and which GL
// does not promise in general (a swap chain that rotates buffers, as on
// Wayland), so the designer uses it only on a software renderer, and it
// checks: every frame leaves a marker in the bottom-left pixel (the frame's
// parity in the lowest bit of blue, invisible) and the next frame reads it
// back before drawing; until one has come back, and for good once one does
// not, every frame is drawn whole. A frame is drawn whole when any list is new, gone or moved
// (a tooltip, a popup), when a redrawn window overlaps a kept one, when the
// framebuffer's size changes, for the first frames, after invalidate(), and
// every kWholeEvery frames (plan(), tests/partial_redraw_test.cpp).
//
// Measured (designer, 512 x 512 gs_coral at 323 steps per frame, 1600 x 1000
// under Xvfb on the 2-core CI kind): rasterizing a frame took 6.2 ms (12 ms
// of CPU) whole, 3.7-4.2 ms (7 ms) redrawing the canvas and the status line.
// A framebuffer rectangle, GL's way up (x, y from the bottom left).
struct RedrawRect {
    int x = 0, y = 0, w = 0, h = 0;
    // By more than the two pixels that the antialiased borders and
    // separators of windows side by side share (what a lone redraw of one
    // of them changes there is a line's fringe).
    bool overlaps(const RedrawRect& o) const;
    bool operator==(const RedrawRect& o) const {
        return x == o.x && y == o.y && w == o.w && h == o.h;
    }
};

// One draw list of a frame: its window's name, a hash of what it draws and
// the pixels it can touch.
struct RedrawList {
    std::string name;
    std::uint64_t hash = 0;
    RedrawRect rect;
};

// What a frame draws: whole, or the lists `redraw` (indices, in order),
// each cleared first where `clear` says so.
struct RedrawPlan {
    bool whole = true;
    std::vector<int> redraw;
    std::vector<bool> clear;
};

class PartialRedraw {
public:
    PartialRedraw(std::vector<std::string> live, std::vector<std::string> opaque);

    // Clears (to `clear`) and draws what must be drawn of `data` into the
    // bound framebuffer of fbWidth x fbHeight pixels. `whole` forces a whole
    // frame (a screenshot follows, say).
    void render(ImDrawData* data, const std::array<float, 4>& clear, int fbWidth, int fbHeight,
                bool whole);

    // The decision render() acts on, for this frame's lists (and remembered
    // for the next): GL-free.
    RedrawPlan plan(const std::vector<RedrawList>& lists, int fbWidth, int fbHeight, bool whole);

    // The next frames are drawn whole (a texture shown in a kept window was
    // replaced).
    void invalidate();

    // Whether frames are drawn partially: the back buffer was seen to keep
    // its pixels across a swap, and never seen not to.
    bool partial() const { return m_preserved && !m_disabled; }

private:
    void drawPart(ImDrawData* data, const RedrawPlan& plan, const std::vector<RedrawList>& lists);
    void leaveMarker(const std::array<float, 4>& clear, int fbWidth, int fbHeight);

    static constexpr int kWholeEvery = 120;
    std::vector<std::string> m_live, m_opaque;
    std::vector<RedrawList> m_last;
    int m_width = 0, m_height = 0;
    int m_wholeFrames = 2; // frames still drawn whole (both buffers of a swap chain)
    int m_sinceWhole = 0;
    // The back buffer's marker (see above): the value left, whether one was,
    // and what the readings said.
    std::array<unsigned char, 3> m_marker{};
    bool m_markerLeft = false, m_preserved = false, m_disabled = false;
    int m_parity = 0;
};

} // namespace morphogen::ui
