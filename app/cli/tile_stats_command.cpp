// `morphogen tile-stats` (hidden, for development): where a surface's explicit
// step limit comes from. Builds a preset's surface on a mesh as a run would
// and reports the distribution of per-texel weight sums (the largest sets the
// substeps) and what the worst texels have in common: which simplified
// triangles (angles, area, valence) and where in their quads they lie.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "cli/commands.hpp"
#include "core/mesh/edge_table.hpp"
#include "core/session/session.hpp"
#include "core/surface/surface_setup.hpp"
#include "core/surface/surface_weights.hpp"
#include "core/surface/tile_diagnostics.hpp"

namespace morphogen::cli {

namespace {

struct TileStatsFlags {
    std::string mesh;
    std::string preset = "turk_large_spots";
    int tileSize = 0;
    int tiles = 0;
    double worst = 0.01;
    int list = 12;
};

double angleAt(const TriangleMesh& m, std::uint32_t t, int k) {
    const auto& tri = m.triangles[t];
    const Eigen::Vector3d p = m.positions[tri[k]].cast<double>();
    const Eigen::Vector3d u = m.positions[tri[(k + 1) % 3]].cast<double>() - p;
    const Eigen::Vector3d v = m.positions[tri[(k + 2) % 3]].cast<double>() - p;
    const double d = u.norm() * v.norm();
    return d > 0 ? std::acos(std::clamp(u.dot(v) / d, -1.0, 1.0)) * 180.0 / M_PI : 0.0;
}

double median(std::vector<double> v) {
    if (v.empty())
        return 0;
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return v[v.size() / 2];
}

// Per texel: what might explain its weight sum.
struct TexelInfo {
    std::uint32_t cell;
    double sum;
    int tile, u, v;
    std::uint32_t triangle;
    int corner;         // of the triangle, = the tile's quad corner 0
    int quadrant;       // nearest quad corner: 0 vertex, 1 leaving midpoint, 2 centroid, 3 arriving
    double cornerAngle; // the triangle's angle at its corner
    double minAngle, maxAngle;
    double triArea; // / median triangle area
    double area;    // texel area / median texel area
    double lu, lv;  // |Ju|, |Jv| / sqrt(median texel area)
    double shear;   // angle between Ju and Jv, degrees
    int valence;
    bool floored;
};

struct Histogram {
    std::vector<double> edges;
    std::vector<std::size_t> counts;
    explicit Histogram(std::vector<double> e) : edges(std::move(e)), counts(edges.size() + 1, 0) {}
    void add(double x) {
        std::size_t b = 0;
        while (b < edges.size() && x >= edges[b])
            ++b;
        ++counts[b];
    }
    std::string text(std::size_t total) const {
        std::string s;
        for (std::size_t b = 0; b < counts.size(); ++b) {
            char buf[64];
            const std::string lo = b == 0 ? "" : std::to_string(int(edges[b - 1]));
            const std::string hi = b == edges.size() ? "" : std::to_string(int(edges[b]));
            std::snprintf(buf, sizeof buf, " [%s,%s) %4.1f%%", lo.c_str(), hi.c_str(),
                          total ? 100.0 * double(counts[b]) / double(total) : 0.0);
            s += buf;
        }
        return s;
    }
};

void summarise(const char* title, const std::vector<const TexelInfo*>& set) {
    const std::size_t n = set.size();
    std::size_t quadrant[4] = {0, 0, 0, 0}, floored = 0;
    Histogram minAngle({10, 20, 30, 40}), corner({20, 40, 60, 90, 120}), maxAngle({90, 120, 150}),
        valence({4, 5, 6, 7, 8});
    std::vector<double> areas, luv, shear, tri;
    for (const TexelInfo* t : set) {
        ++quadrant[t->quadrant];
        floored += t->floored;
        minAngle.add(t->minAngle);
        corner.add(t->cornerAngle);
        maxAngle.add(t->maxAngle);
        valence.add(t->valence);
        areas.push_back(t->area);
        luv.push_back(std::min(t->lu, t->lv));
        shear.push_back(t->shear);
        tri.push_back(t->triArea);
    }
    std::printf("%s: %zu texels\n", title, n);
    std::printf("  nearest quad corner: vertex %.1f%%, leaving mid %.1f%%, centroid %.1f%%, "
                "arriving mid %.1f%%; floored %.1f%%\n",
                100.0 * quadrant[0] / n, 100.0 * quadrant[1] / n, 100.0 * quadrant[2] / n,
                100.0 * quadrant[3] / n, 100.0 * floored / n);
    std::printf("  triangle min angle:%s\n", minAngle.text(n).c_str());
    std::printf("  triangle max angle:%s\n", maxAngle.text(n).c_str());
    std::printf("  angle at the tile's corner:%s\n", corner.text(n).c_str());
    std::printf("  valence of the tile's vertex:%s\n", valence.text(n).c_str());
    std::printf("  median: texel area %.3f, shorter side %.3f, shear %.0f deg, triangle area %.3f "
                "(of the medians)\n",
                median(areas), median(luv), median(shear), median(tri));
}

void tileStats(const TileStatsFlags& f) {
    Session s = loadPreset(f.preset);
    s.surface.mesh = f.mesh;
    s.surface.tileSize = f.tileSize;
    s.surface.tiles = f.tiles;
    const SurfaceSetup setup = setUpSurface(s);
    const SurfaceTiles& tiles = setup.tiles;
    const Atlas& atlas = *tiles.atlas;
    const TriangleMesh& m = tiles.simplified;
    const int n = atlas.tileSize();

    const WeightSumStats st = weightSumStats(atlas, *setup.weights);
    std::printf("%s, preset %s: %zu triangles -> %d tiles of %dx%d, %zu texels; set up in %.2f s\n",
                f.mesh.c_str(), f.preset.c_str(), m.triangles.size(), atlas.tileCount(), n, n,
                st.texels, setup.seconds);
    std::printf("weight sum: max %.4g p99 %.4g p90 %.4g median %.4g; max/median %.2f, "
                "p99/median %.2f; substeps %d\n",
                st.max, st.p99, st.p90, st.median, st.max / st.median, st.p99 / st.median,
                weightedSubsteps(*setup.weights));
    const SurfaceGap gap = tiledSurfaceGap(tiles, setup.mesh.mesh);
    std::printf("tiled surface to the model's %zu vertices: max %.3g%% p99 %.3g%% of the diagonal, "
                "%zu farther than 1%% (the worst at %g, %g, %g)\n",
                gap.vertices, 100 * gap.max, 100 * gap.p99, gap.overOnePercent,
                double(gap.worst.x()), double(gap.worst.y()), double(gap.worst.z()));
    const SurfaceGap simplifiedGap = surfaceGap(m, setup.mesh.mesh);
    std::printf("simplified mesh to the model's vertices: max %.3g%% p99 %.3g%%, %zu farther than "
                "1%% (the worst at %g, %g, %g)\n",
                100 * simplifiedGap.max, 100 * simplifiedGap.p99, simplifiedGap.overOnePercent,
                double(simplifiedGap.worst.x()), double(simplifiedGap.worst.y()),
                double(simplifiedGap.worst.z()));
    const std::vector<double> angles = triangleAngles(m);
    const auto at = [&](double q) { return angles[std::size_t(q * double(angles.size() - 1))]; };
    std::printf("simplified angles: min %.1f p1 %.1f p5 %.1f median %.1f p99 %.1f max %.1f\n",
                angles.front(), at(0.01), at(0.05), at(0.5), at(0.99), angles.back());

    std::vector<double> triAreas;
    for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
        const auto& tr = m.triangles[t];
        triAreas.push_back(0.5 * double((m.positions[tr[1]] - m.positions[tr[0]])
                                            .cross(m.positions[tr[2]] - m.positions[tr[0]])
                                            .norm()));
    }
    const double medTri = median(triAreas);
    std::vector<double> sortedTri = triAreas;
    std::sort(sortedTri.begin(), sortedTri.end());
    std::printf("simplified triangle area / median: min %.3f p1 %.3f p99 %.2f max %.2f\n",
                sortedTri.front() / medTri, sortedTri[sortedTri.size() / 100] / medTri,
                sortedTri[sortedTri.size() * 99 / 100] / medTri, sortedTri.back() / medTri);
    std::vector<int> valence(m.positions.size(), 0);
    for (const auto& tr : m.triangles)
        for (auto v : tr)
            ++valence[v];

    std::vector<double> texelAreas;
    for (std::uint32_t c = 0; c < atlas.cellCount(); ++c)
        if (atlas.used(c))
            texelAreas.push_back(double(tiles.texelArea[c]));
    const double medArea = median(texelAreas), medLen = std::sqrt(medArea);
    const std::vector<double> sums = texelWeightSums(atlas, *setup.weights);
    std::vector<TexelInfo> info;
    for (int t = 0; t < atlas.tileCount(); ++t)
        for (int v = 0; v < n; ++v)
            for (int u = 0; u < n; ++u) {
                TexelInfo x{};
                x.cell = atlas.tileCell(t, u, v);
                x.sum = sums[x.cell];
                x.tile = t;
                x.u = u;
                x.v = v;
                x.triangle = tiles.tileTriangle[std::size_t(t)];
                x.corner = t % 3;
                const bool hu = 2 * u + 1 > n, hv = 2 * v + 1 > n;
                x.quadrant = !hu && !hv ? 0 : hu && !hv ? 1 : hu && hv ? 2 : 3;
                x.cornerAngle = angleAt(m, x.triangle, x.corner);
                double a0 = angleAt(m, x.triangle, 0), a1 = angleAt(m, x.triangle, 1),
                       a2 = angleAt(m, x.triangle, 2);
                x.minAngle = std::min({a0, a1, a2});
                x.maxAngle = std::max({a0, a1, a2});
                x.triArea = triAreas[x.triangle] / medTri;
                x.area = double(tiles.texelArea[x.cell]) / medArea;
                x.lu = double(tiles.jacobianU[x.cell].norm()) / medLen;
                x.lv = double(tiles.jacobianV[x.cell].norm()) / medLen;
                const double d =
                    double(tiles.jacobianU[x.cell].norm() * tiles.jacobianV[x.cell].norm());
                x.shear =
                    d > 0 ? std::acos(std::clamp(
                                double(tiles.jacobianU[x.cell].dot(tiles.jacobianV[x.cell])) / d,
                                -1.0, 1.0)) *
                                180 / M_PI
                          : 0;
                x.valence = valence[m.triangles[x.triangle][std::size_t(x.corner)]];
                x.floored = x.area < kFloorArea || x.lu < kFloorDistance || x.lv < kFloorDistance;
                info.push_back(x);
            }
    std::sort(info.begin(), info.end(),
              [](const TexelInfo& a, const TexelInfo& b) { return a.sum > b.sum; });
    std::vector<const TexelInfo*> all, worst;
    for (const TexelInfo& x : info)
        all.push_back(&x);
    const std::size_t k = std::max<std::size_t>(1, std::size_t(f.worst * double(info.size())));
    worst.assign(all.begin(), all.begin() + std::ptrdiff_t(std::min(k, all.size())));
    std::map<std::uint32_t, int> triangles;
    for (const TexelInfo* x : worst)
        ++triangles[x->triangle];
    char title[128];
    std::snprintf(title, sizeof title, "worst %.1f%% (sum >= %.3g median, %zu triangles)",
                  100 * f.worst, worst.back()->sum / st.median, triangles.size());
    summarise(title, worst);
    summarise("all", all);
    std::printf("the %d worst: sum/median tri corner (u,v) angles[corner,min,max] triArea "
                "texelArea lu lv shear valence\n",
                f.list);
    for (int i = 0; i < f.list && i < int(info.size()); ++i) {
        const TexelInfo& x = info[std::size_t(i)];
        std::printf(
            "  %6.2f %5u %d (%2d,%2d) %5.1f %5.1f %5.1f  %6.3f %6.3f %5.2f %5.2f %4.0f %d%s\n",
            x.sum / st.median, x.triangle, x.corner, x.u, x.v, x.cornerAngle, x.minAngle,
            x.maxAngle, x.triArea, x.area, x.lu, x.lv, x.shear, x.valence,
            x.floored ? " floored" : "");
    }
}

} // namespace

void addTileStatsCommand(CLI::App& app) {
    auto f = std::make_shared<TileStatsFlags>();
    CLI::App* cmd = app.add_subcommand(
        "tile-stats", "Where a surface's step limit comes from: per-texel weight sums and the "
                      "simplified triangles of the worst texels");
    cmd->group(""); // a development tool: not listed in --help
    cmd->add_option("mesh", f->mesh, "mesh file or sample:NAME")->required();
    cmd->add_option("--preset", f->preset, "the preset whose pattern scale sets the tiles");
    cmd->add_option("--tile-size", f->tileSize, "texels per tile side (0: automatic)");
    cmd->add_option("--tiles", f->tiles, "tile budget (0: automatic)");
    cmd->add_option("--worst", f->worst, "the fraction of texels summarised as the worst");
    cmd->add_option("--list", f->list, "how many of the worst texels to list");
    cmd->callback([f] { tileStats(*f); });
}

} // namespace morphogen::cli
