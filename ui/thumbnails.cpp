#include "ui/thumbnails.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>

#include <glad/gl.h>
#include <nlohmann/json.hpp>
#include <omp.h>

#include "core/io/image_io.hpp"
#include "core/session/session.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/runner.hpp"
#include "core/surface/surface_colours.hpp"
#include "core/surface/surface_setup.hpp"
#include "gl/surface_view.hpp"
#include "ui/coloured_state.hpp"

namespace morphogen::ui {

namespace {

// FNV-1a: a stable name for a preset's content (std::hash may differ
// between builds).
std::uint64_t fnv1a(const std::string& text) {
    std::uint64_t h = 14695981039346656037ull;
    for (unsigned char c : text) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

std::string cachePath(const std::string& dir, const Session& s) {
    const std::string key =
        sessionToJson(s).dump() + "|v" + std::to_string(Thumbnails::kCacheVersion) + "|" +
        std::to_string(Thumbnails::kSize) + "|" + std::to_string(Thumbnails::kSurfaceTiles);
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a(key)));
    return (std::filesystem::path(dir) / "thumbnails" / (s.name + "-" + hex + ".png")).string();
}

// The cached picture as RGBA rows, or nothing when it is missing or not a
// kSize x kSize RGBA image.
std::optional<std::vector<float>> readCached(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return std::nullopt;
    try {
        const RawImage image = readRawImage(path);
        const State& st = image.state;
        if (st.width() != Thumbnails::kSize || st.height() != Thumbnails::kSize ||
            st.channels() != 4)
            return std::nullopt;
        std::vector<float> rgba(st.cellCount() * 4);
        for (int c = 0; c < 4; ++c)
            for (std::size_t i = 0; i < st.cellCount(); ++i)
                rgba[i * 4 + std::size_t(c)] = st.plane(c)[i];
        return rgba;
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

// The size a preset's thumbnail runs at: kSize, or a multiple of it that
// keeps a cell at most 2 units wide (a 256-unit Gray-Scott coral at 64 cells
// is 4 units a cell and grows dots instead of its labyrinth), up to 4 kSize.
int renderSize(const Session& s) {
    int factor = 1;
    while (factor < 4 && s.length > 0 && s.length / (Thumbnails::kSize * factor) > 2.0)
        factor *= 2;
    return Thumbnails::kSize * factor;
}

// A factor x factor box average of kSize * factor square RGBA rows.
std::vector<float> shrunk(const std::vector<float>& rgba, int factor) {
    if (factor <= 1)
        return rgba;
    const int from = Thumbnails::kSize * factor;
    std::vector<float> out(std::size_t(Thumbnails::kSize) * Thumbnails::kSize * 4, 0.0f);
    const float weight = 1.0f / float(factor * factor);
    for (int y = 0; y < from; ++y)
        for (int x = 0; x < from; ++x)
            for (int c = 0; c < 4; ++c)
                out[(std::size_t(y / factor) * Thumbnails::kSize + std::size_t(x / factor)) * 4 +
                    std::size_t(c)] += weight * rgba[(std::size_t(y) * from + x) * 4 + c];
    return out;
}

} // namespace

Thumbnails::~Thumbnails() {
    m_stop = true;
    if (m_worker.joinable())
        m_worker.join();
}

void Thumbnails::start(std::vector<Session> presets, const std::string& cacheDir) {
    if (m_worker.joinable())
        return;
    m_total = int(presets.size());
    if (!cacheDir.empty())
        for (const Session& s : presets)
            m_cachePaths[s.name] = cachePath(cacheDir, s);
    m_worker = std::thread([this, presets = std::move(presets)]() mutable { work(presets); });
}

void Thumbnails::work(std::vector<Session> presets) {
    omp_set_num_threads(1);
    const SimulatorFactory cpu = [](const Session& s) { return std::make_unique<CpuSimulator>(s); };
    for (Session& s : presets) {
        if (m_stop)
            return;
        if (s.tiles.active()) {
            ++m_rendered; // no one picture of a sweep
            continue;
        }
        const auto cached = m_cachePaths.find(s.name);
        if (cached != m_cachePaths.end())
            if (std::optional<std::vector<float>> rgba = readCached(cached->second)) {
                std::lock_guard<std::mutex> lock(m_mutex);
                m_pending[s.name] = std::move(*rgba);
                ++m_fromCache;
                ++m_rendered;
                continue;
            }
        try {
            std::optional<SurfaceSetup> setup;
            if (s.surface.active()) {
                // Few coarse tiles: a thumbnail's worth of texels, so it costs
                // about what a flat one does.
                s.surface.tiles = kSurfaceTiles;
                s.surface.tileSize = 4;
                setup = setUpSurface(s);
            } else {
                resizeSession(s, renderSize(s), renderSize(s));
            }
            RunOptions options;
            options.cancel = &m_stop;
            const RunResult result = runSession(s, cpu, options);
            if (result.cancelled)
                return;
            if (setup) {
                Session shown = s;
                const SurfaceColours c = surfaceColours(result.state, shown, *s.atlas);
                TexturedMesh textured = texturedSurface(setup->tiles, c);
                std::lock_guard<std::mutex> lock(m_mutex);
                m_pendingModels[s.name] = std::move(textured);
                ++m_rendered;
                continue;
            }
            std::vector<float> rgba =
                shrunk(colouredRgba(result.state, colormapChemical(s.colormap, s.outputModel()),
                                    s.colormap, s.edges),
                       s.width / kSize);
            keep(s.name, rgba);
            std::lock_guard<std::mutex> lock(m_mutex);
            m_pending[s.name] = std::move(rgba);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "morphogen design: no thumbnail for preset %s: %s\n",
                         s.name.c_str(), e.what());
        }
        ++m_rendered;
    }
}

void Thumbnails::keep(const std::string& name, const std::vector<float>& rgba) const {
    const auto it = m_cachePaths.find(name);
    if (it == m_cachePaths.end())
        return;
    try {
        std::filesystem::create_directories(std::filesystem::path(it->second).parent_path());
        writeImageRows(it->second, kSize, kSize, 4, 8, [&](int y, float* row) {
            std::copy_n(rgba.data() + std::size_t(y) * kSize * 4, kSize * 4, row);
        });
    } catch (const std::exception& e) {
        std::fprintf(stderr, "morphogen design: thumbnail of %s not cached: %s\n", name.c_str(),
                     e.what());
    }
}

unsigned Thumbnails::texture(const std::string& name) {
    if (auto it = m_textures.find(name); it != m_textures.end())
        return it->second.id();
    std::vector<float> rgba;
    std::optional<TexturedMesh> model;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        if (auto it = m_pending.find(name); it != m_pending.end()) {
            rgba = std::move(it->second);
            m_pending.erase(it);
        } else if (auto m = m_pendingModels.find(name); m != m_pendingModels.end()) {
            model = std::move(m->second);
            m_pendingModels.erase(m);
        } else {
            return 0;
        }
    }
    if (model) {
        // The model as the 3D view shows it, on the panel's background.
        const gl::SurfaceRenderer renderer(*model);
        gl::ViewOptions view;
        view.width = view.height = kSize;
        view.supersample = 2;
        view.background = {0.09f, 0.09f, 0.1f, 1.0f};
        const gl::SurfaceImage image = renderer.render(view);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        rgba.resize(image.rgba.size());
        for (std::size_t i = 0; i < rgba.size(); ++i)
            rgba[i] = image.rgba[i] / 255.0f;
        keep(name, rgba);
    }
    gl::Texture2D texture(kSize, kSize, GL_RGBA8);
    texture.uploadRgba(rgba);
    const unsigned id = texture.id();
    m_textures.emplace(name, std::move(texture));
    return id;
}

} // namespace morphogen::ui
