#include "cli/plot_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

namespace morphogen::cli {

void Canvas::blend(int x, int y, const float colour[3], float alpha) {
    if (x < 0 || y < 0 || x >= width || y >= height || alpha <= 0)
        return;
    float* p = &rgb[(std::size_t(y) * width + x) * 3];
    for (int c = 0; c < 3; ++c)
        p[c] = p[c] * (1 - alpha) + colour[c] * alpha;
}

void Canvas::fillRect(int x0, int y0, int x1, int y1, const float colour[3]) {
    for (int y = std::max(0, y0); y < std::min(height, y1); ++y)
        for (int x = std::max(0, x0); x < std::min(width, x1); ++x)
            blend(x, y, colour, 1.0f);
}

void Canvas::paste(const std::vector<float>& image, int w, int h, int x0, int y0) {
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            blend(x0 + x, y0 + y, &image[(std::size_t(y) * w + x) * 3], 1.0f);
}

namespace {

struct Font {
    ImFontAtlas atlas;
    ImFont* font = nullptr;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;

    Font() {
        font = atlas.AddFontDefault();
        atlas.GetTexDataAsAlpha8(&pixels, &width, &height);
    }
};

const Font& font() {
    static const Font instance;
    return instance;
}

} // namespace

void drawText(Canvas& canvas, int x, int y, const std::string& text, const float colour[3]) {
    const Font& f = font();
    float penX = float(x);
    for (unsigned char ch : text) {
        const ImFontGlyph* g = f.font->FindGlyph(ImWchar(ch));
        if (!g)
            continue;
        const int gx0 = int(std::lround(penX + g->X0)), gy0 = int(std::lround(y + g->Y0));
        const int gw = int(std::lround((g->U1 - g->U0) * f.width));
        const int gh = int(std::lround((g->V1 - g->V0) * f.height));
        const int u0 = int(std::lround(g->U0 * f.width)), v0 = int(std::lround(g->V0 * f.height));
        for (int j = 0; j < gh; ++j)
            for (int i = 0; i < gw; ++i)
                canvas.blend(gx0 + i, gy0 + j, colour,
                             f.pixels[std::size_t(v0 + j) * f.width + std::size_t(u0 + i)] /
                                 255.0f);
        penX += g->AdvanceX;
    }
}

int textWidth(const std::string& text) {
    const Font& f = font();
    float w = 0;
    for (unsigned char ch : text)
        if (const ImFontGlyph* g = f.font->FindGlyph(ImWchar(ch)))
            w += g->AdvanceX;
    return int(std::ceil(w));
}

std::vector<std::pair<double, std::string>> axisTicks(double min, double max, int maxTicks) {
    std::vector<std::pair<double, std::string>> ticks;
    if (!(max > min))
        return {{min, [&] {
                     char b[32];
                     std::snprintf(b, sizeof b, "%g", min);
                     return std::string(b);
                 }()}};
    const double raw = (max - min) / std::max(1, maxTicks - 1);
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = magnitude;
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * magnitude >= raw) {
            step = m * magnitude;
            break;
        }
    for (double v = std::ceil(min / step - 1e-9) * step; v <= max + 1e-9 * step; v += step) {
        const double value = std::fabs(v) < 1e-12 * step ? 0.0 : v;
        char label[32];
        std::snprintf(label, sizeof label, "%g", value);
        ticks.emplace_back(value, label);
    }
    return ticks;
}

} // namespace morphogen::cli
