#include "cli/plot_frame.hpp"

#include <algorithm>
#include <cstdlib>

namespace morphogen::cli {

namespace {

constexpr int kTickLength = 5;
constexpr int kLabelGap = 7; // from the plot's edge to a tick label
constexpr int kMargin = 8;   // from the canvas's edge to the title and the y name
constexpr int kTop = 28, kBottom = 44, kRight = 24;
const float kInk[3] = {0.1f, 0.1f, 0.1f};

// Every n-th tick, n the least that puts `clearance` pixels between ticks.
int stride(const PlotAxis& axis, int clearance) {
    int closest = 0;
    for (std::size_t i = 1; i < axis.ticks.size(); ++i) {
        const int d = std::abs(axis.ticks[i].first - axis.ticks[i - 1].first);
        closest = i == 1 ? d : std::min(closest, d);
    }
    if (axis.ticks.size() < 2 || closest >= clearance)
        return 1;
    return closest == 0 ? int(axis.ticks.size()) : (clearance + closest - 1) / closest;
}

int widestLabel(const PlotAxis& axis) {
    int widest = 0;
    for (const auto& tick : axis.ticks)
        widest = std::max(widest, textWidth(tick.second));
    return widest;
}

} // namespace

int xLabelStride(const PlotAxis& x) {
    return stride(x, widestLabel(x) + 6);
}

PlotFrame drawPlotFrame(int plotWidth, int plotHeight, const PlotAxis& x, const PlotAxis& y,
                        const std::string& title) {
    // The y name, a gap, the tick labels, the tick marks.
    const int left = std::max(64, kMargin + textWidth(y.name) + 6 + widestLabel(y) + kLabelGap);
    const int top = kTop;
    PlotFrame frame{Canvas(std::max(left + plotWidth, left + textWidth(title)) + kRight,
                           top + plotHeight + kBottom, 1.0f),
                    left, top};
    Canvas& canvas = frame.canvas;
    const int xStride = xLabelStride(x);
    for (std::size_t i = 0; i < x.ticks.size(); i += std::size_t(xStride)) {
        const auto& [position, label] = x.ticks[i];
        const int px = left + position, below = top + plotHeight;
        canvas.fillRect(px, below, px + 1, below + kTickLength, kInk);
        drawText(canvas, px - textWidth(label) / 2, below + kLabelGap, label, kInk);
    }
    const int yStride = stride(y, kTextHeight + 2);
    for (std::size_t i = 0; i < y.ticks.size(); i += std::size_t(yStride)) {
        const auto& [position, label] = y.ticks[i];
        const int py = top + position;
        canvas.fillRect(left - kTickLength, py, left, py + 1, kInk);
        drawText(canvas, left - kLabelGap - textWidth(label), py - kTextHeight / 2, label, kInk);
    }
    drawText(canvas, left + plotWidth / 2 - textWidth(x.name) / 2, top + plotHeight + 24, x.name,
             kInk);
    drawText(canvas, kMargin, top + plotHeight / 2 - kTextHeight / 2, y.name, kInk);
    drawText(canvas, left, kMargin, title, kInk);
    return frame;
}

} // namespace morphogen::cli
