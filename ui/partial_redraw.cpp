#include "ui/partial_redraw.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <backends/imgui_impl_opengl3.h>
#include <glad/gl.h>
#include <imgui.h>

namespace morphogen::ui {

namespace {

// FNV-1a over a list's vertices, indices and commands: what it draws and where.
std::uint64_t hashOf(const ImDrawList& list) {
    std::uint64_t h = 1469598103934665603ull;
    const auto add = [&h](const void* data, std::size_t bytes) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < bytes; ++i)
            h = (h ^ p[i]) * 1099511628211ull;
    };
    add(list.VtxBuffer.Data, std::size_t(list.VtxBuffer.Size) * sizeof(ImDrawVert));
    add(list.IdxBuffer.Data, std::size_t(list.IdxBuffer.Size) * sizeof(ImDrawIdx));
    for (const ImDrawCmd& c : list.CmdBuffer) {
        add(&c.ClipRect, sizeof(c.ClipRect));
        add(&c.TextureId, sizeof(c.TextureId));
        add(&c.VtxOffset, sizeof(c.VtxOffset));
        add(&c.IdxOffset, sizeof(c.IdxOffset));
        add(&c.ElemCount, sizeof(c.ElemCount));
        const void* callback = reinterpret_cast<const void*>(c.UserCallback);
        add(&callback, sizeof(callback));
    }
    return h;
}

// The framebuffer pixels a list can touch: the union over its commands of
// their triangles' bounds within their clip rectangles (a window's frame is
// drawn under the whole display's clip rectangle).
RedrawRect rectOf(const ImDrawList& list, const ImDrawData& data, int fbWidth, int fbHeight) {
    float x0 = 1e30f, y0 = 1e30f, x1 = -1e30f, y1 = -1e30f;
    for (const ImDrawCmd& c : list.CmdBuffer) {
        if (c.UserCallback != nullptr || c.ElemCount == 0)
            continue;
        float cx0 = 1e30f, cy0 = 1e30f, cx1 = -1e30f, cy1 = -1e30f;
        for (unsigned i = 0; i < c.ElemCount; ++i) {
            const ImVec2 p =
                list.VtxBuffer[int(c.VtxOffset + list.IdxBuffer[int(c.IdxOffset + i)])].pos;
            cx0 = std::min(cx0, p.x);
            cy0 = std::min(cy0, p.y);
            cx1 = std::max(cx1, p.x);
            cy1 = std::max(cy1, p.y);
        }
        x0 = std::min(x0, std::max(cx0, c.ClipRect.x));
        y0 = std::min(y0, std::max(cy0, c.ClipRect.y));
        x1 = std::max(x1, std::min(cx1, c.ClipRect.z));
        y1 = std::max(y1, std::min(cy1, c.ClipRect.w));
    }
    if (x1 <= x0 || y1 <= y0)
        return {};
    const ImVec2 scale = data.FramebufferScale, origin = data.DisplayPos;
    // Outwards to whole pixels. Windows side by side share an edge: what
    // antialiasing draws past it is lost when one is redrawn alone (the
    // redrawn window's own pixels cover it, as they do when drawn last).
    const int left = std::clamp(int(std::floor((x0 - origin.x) * scale.x)), 0, fbWidth);
    const int right = std::clamp(int(std::ceil((x1 - origin.x) * scale.x)), 0, fbWidth);
    const int top = std::clamp(int(std::floor((y0 - origin.y) * scale.y)), 0, fbHeight);
    const int bottom = std::clamp(int(std::ceil((y1 - origin.y) * scale.y)), 0, fbHeight);
    return {left, fbHeight - bottom, right - left, bottom - top};
}

} // namespace

bool RedrawRect::overlaps(const RedrawRect& o) const {
    constexpr int kShared = 2;
    return x + kShared < o.x + o.w && o.x + kShared < x + w && y + kShared < o.y + o.h &&
           o.y + kShared < y + h;
}

PartialRedraw::PartialRedraw(std::vector<std::string> live, std::vector<std::string> opaque)
    : m_live(std::move(live)), m_opaque(std::move(opaque)) {}

void PartialRedraw::invalidate() {
    m_wholeFrames = std::max(m_wholeFrames, 2);
}

RedrawPlan PartialRedraw::plan(const std::vector<RedrawList>& lists, int fbWidth, int fbHeight,
                               bool whole) {
    if (fbWidth != m_width || fbHeight != m_height) {
        m_width = fbWidth;
        m_height = fbHeight;
        m_wholeFrames = 2;
    }
    // And once in a while whole, in case a texture changed under a kept
    // window without its vertices changing (a caller that knows calls
    // invalidate()).
    whole = whole || m_wholeFrames > 0 || lists.size() != m_last.size() ||
            ++m_sinceWhole >= kWholeEvery;
    for (std::size_t i = 0; !whole && i < lists.size(); ++i)
        whole = lists[i].name != m_last[i].name || !(lists[i].rect == m_last[i].rect);
    const auto named = [](const std::vector<std::string>& names, const std::string& name) {
        return std::find(names.begin(), names.end(), name) != names.end();
    };
    RedrawPlan plan;
    std::vector<const RedrawRect*> kept;
    for (std::size_t i = 0; !whole && i < lists.size(); ++i) {
        const RedrawList& l = lists[i];
        if (named(m_live, l.name) || l.hash != m_last[i].hash) {
            plan.redraw.push_back(int(i));
            plan.clear.push_back(!named(m_opaque, l.name));
        } else {
            kept.push_back(&l.rect);
        }
    }
    // A redrawn window over a kept one would paint over (or clear) its pixels.
    for (std::size_t k = 0; !whole && k < plan.redraw.size(); ++k)
        for (const RedrawRect* r : kept)
            whole = whole || lists[std::size_t(plan.redraw[k])].rect.overlaps(*r);
    m_last = lists;
    m_wholeFrames = std::max(0, m_wholeFrames - 1);
    plan.whole = whole;
    if (whole) {
        m_sinceWhole = 0;
        plan.redraw.clear();
        plan.clear.clear();
    }
    return plan;
}

void PartialRedraw::render(ImDrawData* data, const std::array<float, 4>& clear, int fbWidth,
                           int fbHeight, bool whole) {
    std::vector<RedrawList> lists(static_cast<std::size_t>(data->CmdListsCount));
    for (int i = 0; i < data->CmdListsCount; ++i) {
        const ImDrawList& list = *data->CmdLists[i];
        lists[std::size_t(i)] = {list._OwnerName ? list._OwnerName : "", hashOf(list),
                                 rectOf(list, *data, fbWidth, fbHeight)};
    }
    // Did the last frame's marker come back with the buffer?
    if (m_markerLeft && fbWidth > 0 && fbHeight > 0) {
        unsigned char rgba[4] = {0, 0, 0, 0};
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
        if (rgba[0] == m_marker[0] && rgba[1] == m_marker[1] && rgba[2] == m_marker[2]) {
            m_preserved = true;
        } else if (!m_disabled) {
            std::fprintf(stderr, "morphogen design: the window's back buffer does not keep its "
                                 "pixels across a swap here; every frame is drawn whole\n");
            m_disabled = true;
        }
    }
    const RedrawPlan p = plan(lists, fbWidth, fbHeight, whole || !partial());
    glClearColor(clear[0], clear[1], clear[2], clear[3]);
    if (p.whole) {
        glDisable(GL_SCISSOR_TEST);
        glClear(GL_COLOR_BUFFER_BIT);
        ImGui_ImplOpenGL3_RenderDrawData(data);
    } else {
        drawPart(data, p, lists);
    }
    leaveMarker(clear, fbWidth, fbHeight);
}

void PartialRedraw::leaveMarker(const std::array<float, 4>& clear, int fbWidth, int fbHeight) {
    m_markerLeft = false;
    if (m_disabled || fbWidth <= 0 || fbHeight <= 0)
        return;
    // The clear colour in 8 bits (the bottom-left pixel is the status line's
    // background), its blue's lowest bit the frame's parity: a buffer from
    // two frames ago (a rotating swap chain) reads back the other parity.
    m_parity ^= 1;
    for (std::size_t k = 0; k < 3; ++k)
        m_marker[k] =
            static_cast<unsigned char>(std::lround(std::clamp(clear[k], 0.0f, 1.0f) * 255));
    m_marker[2] = static_cast<unsigned char>((m_marker[2] & ~1) | m_parity);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 1, 1);
    glClearColor(m_marker[0] / 255.0f, m_marker[1] / 255.0f, m_marker[2] / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    m_markerLeft = true;
}

void PartialRedraw::drawPart(ImDrawData* data, const RedrawPlan& p,
                             const std::vector<RedrawList>& lists) {
    // An opaque window paints every pixel it owns: clearing it first would
    // rasterize them twice.
    glEnable(GL_SCISSOR_TEST);
    std::vector<ImDrawList*> redraw;
    for (std::size_t k = 0; k < p.redraw.size(); ++k) {
        redraw.push_back(data->CmdLists[p.redraw[k]]);
        if (!p.clear[k])
            continue;
        const RedrawRect& r = lists[std::size_t(p.redraw[k])].rect;
        glScissor(r.x, r.y, r.w, r.h);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    glDisable(GL_SCISSOR_TEST);
    if (redraw.empty())
        return;
    // The same frame with only those lists (the backend reads nothing else).
    ImDrawData part = *data;
    part.CmdLists = redraw.data();
    part.CmdListsCount = int(redraw.size());
    part.TotalVtxCount = part.TotalIdxCount = 0;
    for (const ImDrawList* l : redraw) {
        part.TotalVtxCount += l->VtxBuffer.Size;
        part.TotalIdxCount += l->IdxBuffer.Size;
    }
    ImGui_ImplOpenGL3_RenderDrawData(&part);
}

} // namespace morphogen::ui
