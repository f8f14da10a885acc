#pragma once

#include <string>
#include <utility>
#include <vector>

#include "cli/plot_text.hpp"

namespace morphogen::cli {

// One axis of a plot: its name and its ticks, each a pixel position inside the
// plot area (x from its left edge, y from its top edge) with a label, listed
// in the order they are thinned from (the first is always labelled).
struct PlotAxis {
    std::string name;
    std::vector<std::pair<int, std::string>> ticks;
};

// The least n such that labelling every n-th tick of a horizontal axis keeps
// the labels clear of each other.
int xLabelStride(const PlotAxis& x);

// A white canvas with room for a plotWidth x plotHeight plot at (left, top),
// framed by the labelled y axis on the left, the x axis below and the title
// above; paste the plot there. Crowded ticks are thinned to every n-th.
struct PlotFrame {
    Canvas canvas;
    int left = 0;
    int top = 0;
};
PlotFrame drawPlotFrame(int plotWidth, int plotHeight, const PlotAxis& x, const PlotAxis& y,
                        const std::string& title);

} // namespace morphogen::cli
