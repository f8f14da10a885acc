#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/session/session.hpp"
#include "core/surface/textured_surface.hpp"
#include "gl/objects.hpp"

namespace morphogen::ui {

// The presets browser's thumbnails, rendered by the engine: each preset run
// at kSize x kSize on the CPU backend (the same pattern at a small size: the
// sessions are resolution independent; a preset more than 2 kSize units wide
// runs at 2 or 4 kSize, at most 2 units a cell, and is averaged down) on a worker thread with one
// OpenMP thread, so the window and the live run keep going. A preset on a model runs on the model's
// tiles at a small budget (kSurfaceTiles: the same pattern, coarser), and its picture is the
// textured model rendered on the main thread, which holds the GL context. The textures are made on
// the main thread as the pictures arrive.
//
// Each finished picture is kept as a PNG in the cache folder, named by the
// preset and a hash of its session JSON (with the thumbnail settings and
// kCacheVersion): the next start shows it at once instead of running the
// preset again, and an edited preset gets a new picture. Bump kCacheVersion
// when the engine's look changes. A cache that cannot be read or written
// only costs the re-render.
class Thumbnails {
public:
    static constexpr int kSize = 64;
    static constexpr int kSurfaceTiles = 150;
    static constexpr int kCacheVersion = 2; // 2: presets wider than 128 units at 2 units a cell

    Thumbnails() = default;
    ~Thumbnails(); // stops the worker after the preset it is on
    Thumbnails(const Thumbnails&) = delete;
    Thumbnails& operator=(const Thumbnails&) = delete;

    // cacheDir empty: no cache.
    void start(std::vector<Session> presets, const std::string& cacheDir = "");
    // The GL texture of a preset's thumbnail, 0 until it is rendered (or
    // when it could not be: a batched sweep, a refused session). Main thread.
    unsigned texture(const std::string& name);
    int rendered() const { return m_rendered.load(); }
    int total() const { return m_total; }
    // How many came from the cache rather than a run (for the tests).
    int fromCache() const { return m_fromCache.load(); }

private:
    void work(std::vector<Session> presets);
    void keep(const std::string& name, const std::vector<float>& rgba) const;

    std::thread m_worker;
    std::atomic<bool> m_stop{false};
    std::atomic<int> m_rendered{0};
    std::atomic<int> m_fromCache{0};
    std::map<std::string, std::string> m_cachePaths; // set before the worker starts
    int m_total = 0;
    std::mutex m_mutex;
    std::map<std::string, std::vector<float>> m_pending; // RGBA, rows top first
    std::map<std::string, TexturedMesh> m_pendingModels; // to render on the main thread
    std::map<std::string, gl::Texture2D> m_textures;
};

} // namespace morphogen::ui
