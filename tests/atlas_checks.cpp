#include "atlas_checks.hpp"

#include <random>

#include "core/domain/atlas_diagonals.hpp"

namespace morphogen::test {

Session atlasSession(std::shared_ptr<const Atlas> atlas, Stencil stencil) {
    Session s = loadPreset("gs_coral");
    s.diffusion.stencil = stencil;
    useAtlas(s, std::move(atlas));
    return s;
}

Session pureDiffusionSession(std::shared_ptr<const Atlas> atlas, Stencil stencil) {
    Session s = atlasSession(std::move(atlas), stencil);
    s.params["F"] = 0.0f;
    s.params["k"] = 0.0f;
    return s;
}

State randomUsedState(const Atlas& atlas, unsigned seed) {
    State s(atlas.width(), atlas.height(), 2);
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i) {
        s.plane(0)[i] = atlas.used(i) ? uniform(random) : 7.0f;
        s.plane(1)[i] = atlas.used(i) ? 0.0f : 7.0f;
    }
    return s;
}

double usedSum(const State& s, const Atlas& atlas, int c) {
    double sum = 0;
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
        if (atlas.used(i))
            sum += double(s.plane(c)[i]);
    return sum;
}

std::vector<std::uint32_t> cornerTexels(const Atlas& atlas, int tile) {
    const std::uint32_t a = atlas.cornerCell(tile, 0);
    return {a, atlas.step(a, Direction::MinusX).cell, atlas.step(a, Direction::MinusY).cell};
}

AtlasWeights symmetricWeights(const Atlas& atlas, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> areaOf(0.8f, 1.25f), conductance(0.6f, 1.0f);
    AtlasWeights w;
    w.coefficients.assign(atlas.cellCount(), {0.0f, 0.0f, 0.0f, 0.0f});
    w.area.assign(atlas.cellCount(), 0.0f);
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
        if (atlas.used(i))
            w.area[i] = areaOf(random);
    std::vector<std::array<bool, 4>> done(atlas.cellCount(), {false, false, false, false});
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i) {
        if (!atlas.used(i))
            continue;
        for (int d = 0; d < 4; ++d) {
            if (done[i][std::size_t(d)])
                continue;
            const AtlasStep s = atlas.step(i, Direction(d));
            done[i][std::size_t(d)] = true;
            if (s.cell == i) {
                w.coefficients[i][std::size_t(d)] = 1.0f;
                continue;
            }
            const float k = conductance(random);
            w.coefficients[i][std::size_t(d)] = k / w.area[i];
            w.coefficients[s.cell][std::size_t(s.back)] = k / w.area[s.cell];
            done[s.cell][std::size_t(s.back)] = true;
        }
    }
    return w;
}

AtlasWeights symmetricNinePointWeights(const Atlas& atlas, unsigned seed) {
    AtlasWeights w = symmetricWeights(atlas, seed);
    for (auto& c : w.coefficients)
        for (float& v : c)
            v *= 0.5f;
    std::mt19937 random(seed + 1);
    std::uniform_real_distribution<float> conductance(0.3f, 0.5f);
    const auto d = atlasDiagonals(atlas);
    const auto mirror = diagonalMirrors(atlas, d);
    w.diagonal.assign(atlas.cellCount(), {0.0f, 0.0f, 0.0f, 0.0f});
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
        for (std::size_t s = 0; s < 4; ++s) {
            const std::uint32_t j = d[i][s];
            const int back = mirror[i][s];
            if (back < 0 || j <= i)
                continue;
            const float k = conductance(random);
            w.diagonal[i][s] = k / w.area[i];
            w.diagonal[j][std::size_t(back)] = k / w.area[j];
        }
    return w;
}

double areaWeightedSum(const State& s, const Atlas& atlas, const AtlasWeights& weights, int c) {
    double sum = 0;
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
        if (atlas.used(i))
            sum += double(weights.area[i]) * double(s.plane(c)[i]);
    return sum;
}

bool tileEqual(const State& a, const State& b, const Atlas& atlas, int tile) {
    for (int c = 0; c < a.channels(); ++c)
        for (int v = 0; v < atlas.tileSize(); ++v)
            for (int u = 0; u < atlas.tileSize(); ++u) {
                const std::uint32_t i = atlas.tileCell(tile, u, v);
                if (a.plane(c)[i] != b.plane(c)[i])
                    return false;
            }
    return true;
}

} // namespace morphogen::test
