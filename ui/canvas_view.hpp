#pragma once

#include <array>

namespace morphogen::ui {

// Where the 2D canvas sits in its viewport: zoom (screen pixels per cell)
// and the cell at the viewport's centre. GL-free, so the mapping the brush
// and the readout rely on is tested without a window. Screen points are
// relative to the viewport's top-left corner, y down; canvas points are in
// cells, cell (x, y) covering [x, x+1) x [y, y+1), row 0 at the top as the
// state stores it.
struct CanvasView {
    double zoom = 1.0;
    double centreX = 0.0, centreY = 0.0;

    // The whole canvas, centred, as large as fits.
    void frame(int canvasWidth, int canvasHeight, double viewWidth, double viewHeight);
    // Zooms by `factor` keeping the canvas point under `screen` where it is.
    void zoomAt(double factor, std::array<double, 2> screen, double viewWidth, double viewHeight);
    // Moves the canvas with the cursor by a screen delta.
    void pan(double dx, double dy);

    std::array<double, 2> toCanvas(std::array<double, 2> screen, double viewWidth,
                                   double viewHeight) const;
    std::array<double, 2> toScreen(std::array<double, 2> canvas, double viewWidth,
                                   double viewHeight) const;

    static constexpr double kMinZoom = 1.0 / 64.0;
    static constexpr double kMaxZoom = 256.0;
};

} // namespace morphogen::ui
