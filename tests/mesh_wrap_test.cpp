// The alpha-wrap fallback (core/mesh/mesh_wrap.hpp): a soup of pieces is
// wrapped into one closed surface near the model; clean models, a scan's few
// parts and far-apart shells are left alone; the mode is a session field.

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/base/errors.hpp"
#include "core/mesh/mesh_check.hpp"
#include "core/mesh/mesh_io.hpp"
#include "core/mesh/mesh_report.hpp"
#include "core/mesh/mesh_samples.hpp"
#include "core/mesh/mesh_wrap.hpp"
#include "core/session/session.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A unit sphere of 2 n^2 triangles as a soup: every triangle its own three
// vertices, each jittered off the sphere by up to `jitter`, so no two share a
// position and welding joins nothing.
TriangleMesh sphereSoup(int n, double jitter) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> off(-jitter, jitter);
    TriangleMesh soup;
    const auto point = [&](double theta, double phi) {
        const double r = 1.0 + off(rng);
        return Eigen::Vector3f(float(r * std::sin(theta) * std::cos(phi)),
                               float(r * std::sin(theta) * std::sin(phi)),
                               float(r * std::cos(theta)));
    };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < 2 * n; ++j) {
            const double t0 = kPi * i / n, t1 = kPi * (i + 1) / n;
            const double p0 = kPi * j / n, p1 = kPi * (j + 1) / n;
            const std::array<std::array<double, 2>, 6> corners = {
                {{t0, p0}, {t1, p0}, {t1, p1}, {t0, p0}, {t1, p1}, {t0, p1}}};
            for (int k = 0; k < 6; k += 3) {
                const auto base = std::uint32_t(soup.positions.size());
                for (int c = 0; c < 3; ++c)
                    soup.positions.push_back(
                        point(corners[std::size_t(k + c)][0], corners[std::size_t(k + c)][1]));
                soup.triangles.push_back({base, base + 1, base + 2});
            }
        }
    return soup;
}

std::string written(const TriangleMesh& mesh, const std::string& name) {
    const std::string path =
        (test::scratchDir("morphogen_mesh_wrap_test") / (name + ".obj")).string();
    writeObj(mesh, path);
    return path;
}

} // namespace

TEST(MeshWrap, ASoupIsWrappedIntoOneClosedSurfaceNearTheModel) {
    const TriangleMesh soup = sphereSoup(40, 0.002);
    EXPECT_TRUE(looksLikeSoup(soup));
    const LoadedMesh loaded = loadMesh(written(soup, "soup"));
    ASSERT_TRUE(loaded.wrap.wrapped);
    EXPECT_GT(loaded.wrap.componentsBefore,
              soup.triangles.size() * 9 / 10); // less the poles' slivers
    const MeshReport report = checkMesh(loaded.mesh);
    ASSERT_EQ(report.components.size(), 1u);
    EXPECT_EQ(report.boundaryEdges, 0u);
    EXPECT_TRUE(report.usableForTiles()) << whyNotUsableForTiles(report);
    EXPECT_EQ(report.components[0].genus, 0);
    // Within the offset and the alpha's reach of the sphere, and about its area.
    const double diagonal = report.bounds.diagonal();
    double worst = 0;
    for (const Eigen::Vector3f& p : loaded.mesh.positions)
        worst = std::max(worst, std::abs(double(p.norm()) - 1.0));
    EXPECT_LT(worst, 0.01 * diagonal);
    EXPECT_NEAR(report.area, 4 * kPi, 0.1 * 4 * kPi);
    // The same soup left alone comes out in thousands of pieces, specks dropped.
    RepairOptions never;
    never.wrap = WrapMode::Never;
    const LoadedMesh shards = loadMesh(written(soup, "soup"), never);
    EXPECT_FALSE(shards.wrap.wrapped);
    EXPECT_GT(checkMesh(shards.mesh).components.size(), 1000u);
}

TEST(MeshWrap, ModelsThatAreNotSoupsAreLeftAlone) {
    const TriangleMesh torus = sampleMesh("torus", 0);
    EXPECT_FALSE(looksLikeSoup(torus));
    EXPECT_FALSE(loadMesh(written(torus, "torus")).wrap.wrapped);
    // Two shells far apart, and 31 loose triangles: a few pieces, not a soup.
    TriangleMesh two = sampleMesh("sphere", 0);
    const std::size_t n = two.positions.size();
    for (std::size_t i = 0; i < n; ++i)
        two.positions.push_back(two.positions[i] + Eigen::Vector3f(1e4f, 0, 0));
    const std::size_t t = two.triangles.size();
    for (std::size_t i = 0; i < t; ++i) {
        const auto& tri = two.triangles[i];
        two.triangles.push_back(
            {tri[0] + std::uint32_t(n), tri[1] + std::uint32_t(n), tri[2] + std::uint32_t(n)});
    }
    EXPECT_FALSE(looksLikeSoup(two));
    const auto loose = [](int count) {
        TriangleMesh m;
        for (int i = 0; i < count; ++i) {
            const auto b = std::uint32_t(m.positions.size());
            m.positions.push_back({float(3 * i), 0, 0});
            m.positions.push_back({float(3 * i + 1), 0, 0});
            m.positions.push_back({float(3 * i), 1, 0});
            m.triangles.push_back({b, b + 1, b + 2});
        }
        return m;
    };
    EXPECT_FALSE(looksLikeSoup(loose(int(kSoupComponents) - 1)));
    EXPECT_TRUE(looksLikeSoup(loose(int(kSoupComponents))));
}

TEST(MeshWrap, AlwaysWrapsAndKeepsAHandle) {
    RepairOptions always;
    always.wrap = WrapMode::Always;
    const LoadedMesh loaded = loadMesh(written(sampleMesh("torus", 0), "torus"), always);
    ASSERT_TRUE(loaded.wrap.wrapped);
    const MeshReport report = checkMesh(loaded.mesh);
    ASSERT_EQ(report.components.size(), 1u);
    EXPECT_EQ(report.boundaryEdges, 0u);
    EXPECT_EQ(report.components[0].genus, 1); // the hole is far wider than alpha
}

TEST(MeshWrap, TheModeIsASessionFieldAndAFlagValue) {
    EXPECT_EQ(parseWrapMode("never"), WrapMode::Never);
    EXPECT_EQ(parseWrapMode("auto"), WrapMode::Automatic);
    EXPECT_FALSE(parseWrapMode("sometimes").has_value());
    nlohmann::json j = sessionToJson(loadPreset("surface_stripes_torus"));
    EXPECT_FALSE(j["surface"].contains("wrap")); // the default stays unwritten
    j["surface"]["wrap"] = "always";
    const Session s = sessionFromJson(j, "hand.json");
    EXPECT_EQ(s.surface.wrap, WrapMode::Always);
    EXPECT_EQ(sessionToJson(s)["surface"]["wrap"], "always");
    j["surface"]["wrap"] = "sometimes";
    try {
        sessionFromJson(j, "hand.json");
        FAIL() << "an unknown wrap mode was accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("wrap"), std::string::npos) << what;
        EXPECT_NE(what.find("always"), std::string::npos) << what;
    }
}

// A soup the wrap cannot be made of (coordinates whose extent overflows):
// the pieces are kept, and the report says why, instead of an exception.
TEST(MeshWrap, AWrapThatCannotBeMadeKeepsThePiecesAndSaysWhy) {
    TriangleMesh huge;
    for (int i = 0; i < 40; ++i) {
        const auto b = std::uint32_t(huge.positions.size());
        const float x = float((i % 2 ? 3e38 : -3e38) * (i + 1) / 40.0);
        huge.positions.push_back({x, 0, 0});
        huge.positions.push_back({x, 1e37f, 0});
        huge.positions.push_back({x, 0, 1e37f});
        huge.triangles.push_back({b, b + 1, b + 2});
    }
    ASSERT_TRUE(looksLikeSoup(huge));
    const LoadedMesh loaded = loadMesh(written(huge, "huge"));
    EXPECT_FALSE(loaded.wrap.wrapped);
    EXPECT_FALSE(loaded.wrap.failed.empty());
    EXPECT_EQ(loaded.mesh.triangles.size(), 40u);
    const std::string text = meshReportText(loaded, checkMesh(loaded.mesh));
    EXPECT_NE(text.find("wrap: not made"), std::string::npos) << text;
}
