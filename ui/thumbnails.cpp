#include "ui/thumbnails.hpp"

#include <cstdio>
#include <optional>

#include <glad/gl.h>
#include <omp.h>

#include "core/sim/cpu_simulator.hpp"
#include "core/sim/runner.hpp"
#include "core/surface/surface_colours.hpp"
#include "core/surface/surface_setup.hpp"
#include "gl/surface_view.hpp"
#include "ui/coloured_state.hpp"

namespace morphogen::ui {

Thumbnails::~Thumbnails() {
    m_stop = true;
    if (m_worker.joinable())
        m_worker.join();
}

void Thumbnails::start(std::vector<Session> presets) {
    if (m_worker.joinable())
        return;
    m_total = int(presets.size());
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
        try {
            std::optional<SurfaceSetup> setup;
            if (s.surface.active()) {
                // Few coarse tiles: a thumbnail's worth of texels, so it costs
                // about what a flat one does.
                s.surface.tiles = kSurfaceTiles;
                s.surface.tileSize = 4;
                setup = setUpSurface(s);
            } else {
                resizeSession(s, kSize, kSize);
            }
            RunOptions options;
            options.cancel = &m_stop;
            const RunResult result = runSession(s, cpu, options);
            if (result.cancelled)
                return;
            if (setup) {
                Session shown = s;
                const SurfaceColours c = surfaceColours(result.state, shown, *s.atlas);
                TexturedMesh textured = texturedSurface(setup->tiles, c.height, c.colours);
                std::lock_guard<std::mutex> lock(m_mutex);
                m_pendingModels[s.name] = std::move(textured);
                ++m_rendered;
                continue;
            }
            std::vector<float> rgba = colouredRgba(
                result.state, colormapChemical(s.colormap, s.outputModel()), s.colormap);
            std::lock_guard<std::mutex> lock(m_mutex);
            m_pending[s.name] = std::move(rgba);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "morphogen design: no thumbnail for preset %s: %s\n",
                         s.name.c_str(), e.what());
        }
        ++m_rendered;
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
    }
    gl::Texture2D texture(kSize, kSize, GL_RGBA8);
    texture.uploadRgba(rgba);
    const unsigned id = texture.id();
    m_textures.emplace(name, std::move(texture));
    return id;
}

} // namespace morphogen::ui
