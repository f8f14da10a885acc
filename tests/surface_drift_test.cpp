// Water drops running down a model (core/surface/surface_drift.hpp, Lo et al.
// section 5.6) on the CPU backend: the drift's coefficients conserve the
// amount on the surface; a drop on a tilted plane moves along gravity's
// projection at the drift's speed; on a sphere it runs down the meridian it
// started on, monotonically; without gravity it stays where it is and spreads
// evenly; the session's 3D gravity direction and its bad values.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/base/errors.hpp"
#include "core/domain/atlas.hpp"
#include "core/domain/atlas_weights.hpp"
#include "core/mesh/mesh_io.hpp"
#include "core/models/watercolour.hpp"
#include "core/session/session.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/session_run.hpp"
#include "core/surface/surface_setup.hpp"

using namespace morphogen;
using nlohmann::json;
using M = WatercolourModel;

namespace {

// A watercolour session on `mesh` with one wet dab at `at` (mesh coordinates)
// of `radius`; nothing evaporates or soaks in, so all the water stays on the
// surface and only flows.
json dropOnMesh(const std::string& mesh, const std::array<double, 3>& at, double radius,
                double strength, const std::array<double, 3>& direction) {
    json j = {{"model", "watercolour"},
              {"length", 48},
              {"dt", 0.5},
              {"steps", 100000},
              {"init", {{"type", "noise"}}},
              {"params",
               {{"paper_grain", 0}, {"paper_fibres", 0}, {"evaporation", 0}, {"absorption", 0}}},
              {"strokes", json::array({{{"space", "surface"},
                                        {"points", {{at[0], at[1], at[2]}}},
                                        {"radius", radius},
                                        {"water", 2.0},
                                        {"pigment", "p1"},
                                        {"amount", 0.5}}})},
              {"surface", {{"mesh", mesh}}}};
    if (strength > 0)
        j["gravity"] = {{"strength", strength}, {"direction", direction}};
    return j;
}

struct Drop {
    double amount = 0;                                // sum of area * water
    Eigen::Vector3d centre{0, 0, 0};                  // area- and water-weighted mean position
    Eigen::Matrix3d spread = Eigen::Matrix3d::Zero(); // second moments about the centre
};

Drop dropOf(const Session& s, const State& state) {
    const Atlas& atlas = *s.atlas;
    const AtlasWeights& weights = *s.atlasWeights;
    Drop d;
    const float* w = state.plane(M::W);
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i) {
        if (!atlas.used(i))
            continue;
        const double m = double(weights.area[i]) * w[i];
        const auto& p = (*s.atlasPositions)[i];
        d.amount += m;
        d.centre += m * Eigen::Vector3d(p[0], p[1], p[2]);
    }
    d.centre /= d.amount;
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i) {
        if (!atlas.used(i))
            continue;
        const double m = double(weights.area[i]) * w[i];
        const auto& p = (*s.atlasPositions)[i];
        const Eigen::Vector3d r = Eigen::Vector3d(p[0], p[1], p[2]) - d.centre;
        d.spread += m * r * r.transpose();
    }
    d.spread /= d.amount;
    return d;
}

SessionRun cpuRun(const Session& s) {
    return SessionRun(
        s, [](const Session& l) { return std::make_unique<CpuSimulator>(l); }, 0);
}

// A flat square of side 2 (an n x n grid of quads, two triangles each) in the
// plane through the origin tilted `degrees` from the horizontal about x.
TriangleMesh tiltedPlane(int n, double degrees) {
    const double a = degrees * 3.14159265358979323846 / 180.0;
    TriangleMesh mesh;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const double u = -1.0 + 2.0 * i / n, v = -1.0 + 2.0 * j / n;
            mesh.positions.emplace_back(float(u), float(v * std::sin(a)), float(v * std::cos(a)));
        }
    const auto at = [n](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return mesh;
}

} // namespace

// The drift's coefficients: what a texel passes on arrives per its
// neighbour's area, so sum(area * drift(u)) is 0 for any u; no coefficient is
// negative (upwind); and a texel passes on at most what leaves it.
TEST(SurfaceDrift, CoefficientsConserveTheAmount) {
    Session s =
        sessionFromJson(dropOnMesh("sample:sphere", {0, 0, 1}, 0.2, 0.5, {1, -2, 0.5}), "conserve");
    setUpSurface(s);
    const AtlasWeights& weights = *s.atlasWeights;
    ASSERT_TRUE(weights.drift);
    checkAtlasWeights(*s.atlas, weights);
    const Atlas& atlas = *s.atlas;
    // sum_i A_i drift(u)_i = sum_i A_i (sum_d in_id u_n(i,d) - out_i u_i) for u = a
    // texel's indicator: A_j (sum over its neighbours' inflow from j) - A_j out_j.
    double worst = 0, largest = 0;
    for (std::uint32_t j = 0; j < atlas.cellCount(); ++j) {
        if (!atlas.used(j))
            continue;
        double given = 0;
        for (int e = 0; e < 4; ++e) {
            const AtlasStep st = atlas.step(j, Direction(e));
            if (st.cell == j)
                continue;
            given += double(weights.area[st.cell]) *
                     double(weights.drift->inflow[st.cell][std::size_t(st.back)]);
        }
        const double lost = double(weights.area[j]) * double(weights.drift->outflow[j]);
        worst = std::max(worst, std::abs(given - lost));
        largest = std::max(largest, lost);
    }
    std::printf("largest outflow (area x rate) %.4g, worst imbalance %.3g\n", largest, worst);
    EXPECT_GT(largest, 0.0);
    // Each flux is one float, divided by one area and multiplied back: a few ulps.
    EXPECT_LT(worst, 1e-6 * largest);
}

// Lo 5.6 on a tilted plane: the water's centre of mass moves along gravity's
// projection on the plane at the drift's speed, monotonically, and not
// sideways. For a linear operator the centre moves at the texels' drift
// velocity J w = s P g; the plane's kite-shaped texels make J w the texel's
// centre-difference step, so the measured speed is within a few percent (the
// tolerance) rather than exact as on a grid.
TEST(SurfaceDrift, DropOnATiltedPlaneMovesAlongGravitysProjection) {
    const double tilt = 30.0, strength = 0.5;
    const std::string path =
        (std::filesystem::temp_directory_path() / "morphogen_surface_drift_plane.obj").string();
    writeObj(tiltedPlane(8, tilt), path);
    Session s =
        sessionFromJson(dropOnMesh(path, {0, 0.25, 0.433}, 0.2, strength, {0, -1, 0}), "plane");
    setUpSurface(s);
    std::filesystem::remove(path);
    const double unitsPerWorld = s.length / 2.0; // the plane's area is 4
    // Down the plane: -(0, sin, cos) of the tilt; gravity's projection has length sin(tilt).
    const double a = tilt * 3.14159265358979323846 / 180.0;
    const Eigen::Vector3d downhill(0, -std::sin(a), -std::cos(a));
    const double speed = strength * std::sin(a) / unitsPerWorld; // world units per unit time
    SessionRun run = cpuRun(s);
    run.advance(1); // the stroke
    const Drop start = dropOf(s, run.state());
    double last = 0;
    for (int i = 1; i <= 6; ++i) {
        run.advance(20 * run.substeps()); // 10 time units
        const Drop d = dropOf(s, run.state());
        const Eigen::Vector3d moved = d.centre - start.centre;
        const double along = moved.dot(downhill);
        const double across = (moved - along * downhill).norm();
        EXPECT_GT(along, last) << "block " << i;
        last = along;
        EXPECT_NEAR(along / (speed * 10.0 * i), 1.0, 0.05) << "block " << i;
        EXPECT_LT(across, 0.05 * along) << "block " << i;
        EXPECT_NEAR(d.amount / start.amount, 1.0, 1e-5);
    }
    std::printf("tilted plane: moved %.4f world units in 60 time units (drift %.4f)\n", last,
                speed * 60.0);
}

// A carrier (Gravity::carrier): what a texel passes downhill is scaled by its
// water's mobility w / (w + cling), so the drop's deep middle outruns its thin
// edges: its front steepens and a thin film stays behind it (Lo's wet trace).
// Measured along the slope: the water's third moment turns negative (a tail
// upstream) where the carrier-free drop stays symmetric, and more water is
// left behind the starting point; the water is conserved either way.
TEST(SurfaceDrift, ACarrierLeavesATrailBehindASteepFront) {
    const double tilt = 30.0, strength = 0.5;
    const std::string path =
        (std::filesystem::temp_directory_path() / "morphogen_surface_drift_carrier.obj").string();
    writeObj(tiltedPlane(8, tilt), path);
    const double a = tilt * 3.14159265358979323846 / 180.0;
    const Eigen::Vector3d downhill(0, -std::sin(a), -std::cos(a));
    const Eigen::Vector3d start(0, 0.5 * std::sin(a), 0.5 * std::cos(a));
    struct Shape {
        double skew, behind, amount;
    };
    const auto run = [&](const std::string& carrier) {
        json j = dropOnMesh(path, {start.x(), start.y(), start.z()}, 0.2, strength, {0, -1, 0});
        if (!carrier.empty())
            j["gravity"]["carrier"] = carrier;
        j["gravity"]["cling"] = 0.5;
        Session s = sessionFromJson(j, "carrier");
        setUpSurface(s);
        SessionRun r = cpuRun(s);
        r.advance(1);
        const double before = dropOf(s, r.state()).amount;
        r.advance(60 * r.substeps()); // 30 time units
        const State end = r.state();  // a copy: the planes below point into it
        const Drop d = dropOf(s, end);
        // Moments along the slope, water- and area-weighted.
        double m2 = 0, m3 = 0, behind = 0;
        const float* w = end.plane(M::W);
        for (std::uint32_t i = 0; i < s.atlas->cellCount(); ++i) {
            if (!s.atlas->used(i))
                continue;
            const auto& p = (*s.atlasPositions)[i];
            const Eigen::Vector3d x(p[0], p[1], p[2]);
            const double m = double(s.atlasWeights->area[i]) * w[i];
            const double t = (x - d.centre).dot(downhill);
            m2 += m * t * t;
            m3 += m * t * t * t;
            if ((x - start).dot(downhill) < 0)
                behind += m;
        }
        m2 /= d.amount;
        m3 /= d.amount;
        return Shape{m3 / std::pow(m2, 1.5), behind / d.amount, d.amount / before};
    };
    const Shape plain = run(""), clinging = run("w");
    std::filesystem::remove(path);
    std::printf("skew along the slope: plain %.3f, with a carrier %.3f; water behind the start: "
                "%.3f vs %.3f\n",
                plain.skew, clinging.skew, plain.behind, clinging.behind);
    EXPECT_NEAR(plain.amount, 1.0, 1e-5);
    EXPECT_NEAR(clinging.amount, 1.0, 1e-5);
    EXPECT_LT(std::abs(plain.skew), 0.2);
    EXPECT_LT(clinging.skew, -0.3);
    EXPECT_GT(clinging.behind, 1.5 * plain.behind);
}

// On a sphere a drop started on the upper half runs down its meridian: its
// centre of mass falls monotonically, stays in the plane of the meridian
// (the vertical plane through the start point) and the water is all there.
TEST(SurfaceDrift, DropOnASphereRunsDownItsMeridian) {
    const Eigen::Vector3d at = Eigen::Vector3d(0.6, 0.6, 0.3).normalized();
    Session s = sessionFromJson(
        dropOnMesh("sample:sphere", {at.x(), at.y(), at.z()}, 0.25, 0.6, {0, -1, 0}), "sphere");
    setUpSurface(s);
    SessionRun run = cpuRun(s);
    run.advance(1);
    const Drop start = dropOf(s, run.state());
    // The meridian's plane: spanned by the vertical and the start point.
    const Eigen::Vector3d normal = Eigen::Vector3d::UnitY().cross(at).normalized();
    double lastY = start.centre.y(), worstOff = 0;
    std::printf("sphere: %d substeps per session step\n", run.substeps());
    for (int i = 1; i <= 5; ++i) {
        run.advance(10 * run.substeps()); // 5 time units
        const Drop d = dropOf(s, run.state());
        EXPECT_LT(d.centre.y(), lastY) << "block " << i;
        lastY = d.centre.y();
        worstOff = std::max(worstOff, std::abs(d.centre.dot(normal)));
        // Float rounding of some 1,000 steps on 10k texels.
        EXPECT_NEAR(d.amount / start.amount, 1.0, 2e-5);
    }
    std::printf("sphere: centre of mass y %.4f -> %.4f, off the meridian's plane at most %.4f\n",
                start.centre.y(), lastY, worstOff);
    EXPECT_LT(worstOff, 0.02);
    EXPECT_LT(lastY, start.centre.y() - 0.3) << "the drop should have run well down";
}

// Gravity off: the drop stays where it was put (its centre on the ray through
// the start point) and spreads about as much in every tangent direction.
TEST(SurfaceDrift, WithoutGravityADropSpreadsEvenly) {
    const Eigen::Vector3d at = Eigen::Vector3d(0.6, 0.6, 0.3).normalized();
    Session s = sessionFromJson(
        dropOnMesh("sample:sphere", {at.x(), at.y(), at.z()}, 0.25, 0.0, {0, -1, 0}), "still");
    setUpSurface(s);
    ASSERT_FALSE(s.atlasWeights->drift);
    SessionRun run = cpuRun(s);
    run.advance(1);
    const Drop start = dropOf(s, run.state());
    run.advance(100 * run.substeps());
    const Drop d = dropOf(s, run.state());
    const double off = (d.centre.normalized() - at).norm();
    // The spread in the tangent plane at the start point: two orthogonal directions.
    const Eigen::Vector3d t1 = Eigen::Vector3d::UnitY().cross(at).normalized();
    const Eigen::Vector3d t2 = at.cross(t1);
    const double s1 = t1.dot(d.spread * t1), s2 = t2.dot(d.spread * t2);
    const double s0 = t1.dot(start.spread * t1);
    std::printf("no gravity: centre off the start ray %.4f, tangent spreads %.4f %.4f (start "
                "%.4f)\n",
                off, s1, s2, s0);
    EXPECT_GT(s1, 1.5 * s0) << "the drop should have spread";
    EXPECT_LT(off, 0.01);
    EXPECT_NEAR(s1 / s2, 1.0, 0.1);
}

TEST(SurfaceDrift, SessionsRecordTheDirectionAndRefuseBadValues) {
    const json j = dropOnMesh("sample:sphere", {0, 0, 1}, 0.2, 0.5, {1, -2, 0.5});
    const Session s = sessionFromJson(j, "rec");
    EXPECT_EQ(s.gravity.direction, (std::array<double, 3>{1, -2, 0.5}));
    EXPECT_EQ(sessionFromJson(sessionToJson(s), "again").gravity, s.gravity);
    const auto refused = [](json bad, const std::string& expect) {
        try {
            Session b = sessionFromJson(bad, "bad.json");
            validateSession(b, "bad.json");
            ADD_FAILURE() << "accepted: " << bad["gravity"].dump();
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(expect), std::string::npos) << e.what();
        }
    };
    json bad = j;
    bad["gravity"]["direction"] = {0, 0, 0};
    refused(bad, "gravity.direction");
    bad["gravity"]["direction"] = {0, -1};
    refused(bad, "gravity.direction");
    bad["gravity"]["direction"] = "down";
    refused(bad, "gravity.direction");
    bad["gravity"]["direction"] = {0, "x", 1};
    refused(bad, "gravity.direction");
    // A stroke on the surface needs three coordinates.
    bad = j;
    bad["strokes"][0]["points"] = {{0.5, 0.5}};
    refused(bad, "strokes[0].points");
    bad["strokes"][0]["space"] = "paper";
    refused(bad, "strokes[0].space");

    // A carrier: recorded with its cling; a cling of 0, a chemical the model
    // lacks, and a carrier on a flat canvas are refused naming gravity.carrier.
    json carried = j;
    carried["gravity"]["carrier"] = "w";
    carried["gravity"]["cling"] = 0.7;
    const Session c = sessionFromJson(carried, "carrier");
    EXPECT_EQ(c.gravity.carrier, "w");
    EXPECT_EQ(c.gravity.cling, 0.7);
    EXPECT_EQ(sessionFromJson(sessionToJson(c), "again").gravity, c.gravity);
    json clingOnly = j;
    clingOnly["gravity"]["cling"] = 0.9; // kept without a carrier too
    const Session co = sessionFromJson(clingOnly, "cling");
    EXPECT_EQ(sessionFromJson(sessionToJson(co), "again").gravity, co.gravity);
    bad = carried;
    bad["gravity"]["cling"] = 0;
    refused(bad, "gravity.cling");
    const auto refusedToRun = [](json bad, const std::string& expect) {
        try {
            Session b = sessionFromJson(bad, "bad.json");
            if (b.surface.active())
                setUpSurface(b);
            (void)StepConstants::fromSession(b);
            ADD_FAILURE() << "ran: " << bad["gravity"].dump();
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(expect), std::string::npos) << e.what();
        }
    };
    bad = carried;
    bad["gravity"]["carrier"] = "water";
    bad["surface"]["tiles"] = 100;
    refusedToRun(bad, "gravity.carrier: 'water' is not a chemical");
    bad = carried;
    bad.erase("surface");
    bad.erase("strokes");
    refusedToRun(bad, "gravity.carrier");
}
