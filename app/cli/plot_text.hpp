#pragma once

#include <string>
#include <utility>
#include <vector>

namespace morphogen::cli {

// An RGB float image (interleaved, row 0 at the top) to annotate.
struct Canvas {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;

    Canvas(int w, int h, float grey) : width(w), height(h), rgb(std::size_t(w) * h * 3, grey) {}
    void blend(int x, int y, const float colour[3], float alpha);
    void fillRect(int x0, int y0, int x1, int y1, const float colour[3]);
    // Copies an RGB image of w x h with its top-left corner at (x, y).
    void paste(const std::vector<float>& image, int w, int h, int x, int y);
};

// Draws text with Dear ImGui's embedded pixel font (ProggyClean, 13 px):
// its font atlas is built on the CPU, so plots get labels without a font
// file or a GL context. `x` is the left edge, `y` the top of the line.
void drawText(Canvas& canvas, int x, int y, const std::string& text, const float colour[3]);
int textWidth(const std::string& text);
constexpr int kTextHeight = 13;

// "Nice" axis ticks (1, 2, 5 x 10^k) between min and max, as (value, label).
std::vector<std::pair<double, std::string>> axisTicks(double min, double max, int maxTicks = 6);

} // namespace morphogen::cli
