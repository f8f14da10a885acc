#include "ui/thumbnails.hpp"

#include <cstdio>

#include <glad/gl.h>
#include <omp.h>

#include "core/sim/cpu_simulator.hpp"
#include "core/sim/runner.hpp"
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
        if (s.surface.active() || s.tiles.active()) {
            ++m_rendered; // no flat picture of a model or a sweep
            continue;
        }
        try {
            resizeSession(s, kSize, kSize);
            RunOptions options;
            options.cancel = &m_stop;
            const RunResult result = runSession(s, cpu, options);
            if (result.cancelled)
                return;
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
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        auto it = m_pending.find(name);
        if (it == m_pending.end())
            return 0;
        rgba = std::move(it->second);
        m_pending.erase(it);
    }
    gl::Texture2D texture(kSize, kSize, GL_RGBA8);
    texture.uploadRgba(rgba);
    const unsigned id = texture.id();
    m_textures.emplace(name, std::move(texture));
    return id;
}

} // namespace morphogen::ui
