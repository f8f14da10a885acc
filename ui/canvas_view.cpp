#include "ui/canvas_view.hpp"

#include <algorithm>

namespace morphogen::ui {

void CanvasView::frame(int canvasWidth, int canvasHeight, double viewWidth, double viewHeight) {
    zoom = std::clamp(std::min(viewWidth / canvasWidth, viewHeight / canvasHeight), kMinZoom,
                      kMaxZoom);
    centreX = canvasWidth / 2.0;
    centreY = canvasHeight / 2.0;
}

void CanvasView::zoomAt(double factor, std::array<double, 2> screen, double viewWidth,
                        double viewHeight) {
    const std::array<double, 2> anchor = toCanvas(screen, viewWidth, viewHeight);
    zoom = std::clamp(zoom * factor, kMinZoom, kMaxZoom);
    // The anchor stays under the cursor: solve toScreen(anchor) == screen for the centre.
    centreX = anchor[0] - (screen[0] - viewWidth / 2.0) / zoom;
    centreY = anchor[1] - (screen[1] - viewHeight / 2.0) / zoom;
}

void CanvasView::pan(double dx, double dy) {
    centreX -= dx / zoom;
    centreY -= dy / zoom;
}

std::array<double, 2> CanvasView::toCanvas(std::array<double, 2> screen, double viewWidth,
                                           double viewHeight) const {
    return {centreX + (screen[0] - viewWidth / 2.0) / zoom,
            centreY + (screen[1] - viewHeight / 2.0) / zoom};
}

std::array<double, 2> CanvasView::toScreen(std::array<double, 2> canvas, double viewWidth,
                                           double viewHeight) const {
    return {(canvas[0] - centreX) * zoom + viewWidth / 2.0,
            (canvas[1] - centreY) * zoom + viewHeight / 2.0};
}

} // namespace morphogen::ui
