// The watercolour model on the CPU backend (core/models/watercolour.hpp):
// water and pigment are conserved (on the paper + gone, moving + deposited),
// more water bleeds wider, a very wet wash dries darkest at its rim, the paper is
// reproducible noise, strokes expand into edits and bad ones are refused by
// field, and the "watercolour" map paints pigment on paper.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/base/errors.hpp"
#include "core/models/initial_condition.hpp"
#include "core/models/paper_texture.hpp"
#include "core/models/watercolour.hpp"
#include "core/output/colormap.hpp"
#include "core/output/watercolour_paint.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/session_run.hpp"
#include "test_support.hpp"

using namespace morphogen;
using nlohmann::json;
using M = WatercolourModel;

namespace {

json paintingJson(int size, int steps, const json& strokes) {
    return {{"model", "watercolour"},
            {"size", size},
            {"length", size},
            {"steps", steps},
            {"coarse_to_fine", false},
            {"edges", "clamped"},
            {"init", {{"type", "noise"}}},
            {"strokes", strokes}};
}

State paint(const Session& s) {
    SessionRun run(
        s, [](const Session& l) { return std::make_unique<CpuSimulator>(l); }, 0);
    while (!run.finished())
        run.advance(s.steps);
    return run.state();
}

// Radius (cells) of the disc with the area where deposited pigment 1 is
// above `fraction` of its maximum.
double stainRadius(const State& s, float fraction) {
    const float* d = s.plane(M::D1);
    const float top = *std::max_element(d, d + s.cellCount());
    std::size_t cells = 0;
    for (std::size_t i = 0; i < s.cellCount(); ++i)
        cells += d[i] > fraction * top;
    return std::sqrt(double(cells) / 3.14159265358979);
}

} // namespace

// Between strokes, sum(w + g) and sum(p_i + d_i) do not change: every
// reaction term moves an amount from one chemical to its partner and the
// diffusion of w and p_i conserves their totals on both edge modes.
TEST(Watercolour, ConservesWaterAndPigmentOnTheCpu) {
    for (EdgeMode edges : {EdgeMode::Periodic, EdgeMode::Clamped}) {
        SCOPED_TRACE(toString(edges));
        Session s = sessionFromJson({{"model", "watercolour"}}, "conservation");
        s.width = 48;
        s.height = 40;
        s.edges = edges;
        s.init.inside["p2"] = 0.3f;
        const State start =
            makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, s.seed);
        CpuSimulator cpu(s);
        cpu.setState(start);
        cpu.run(150); // mid-wash: water on the paper, in the paper and gone
        const State end = cpu.state();
        const double water0 = test::planeSum(start, M::W) + test::planeSum(start, M::G);
        const double water1 = test::planeSum(end, M::W) + test::planeSum(end, M::G);
        // Float rounding only: each step adds and subtracts the same float
        // amounts in ~2000 cells; 1e-5 relative over 150 steps is ~100x the
        // drift measured and far below any leak (a missing term loses ~1%
        // a step).
        EXPECT_NEAR(water1 / water0, 1.0, 1e-5);
        for (int k = 0; k < 2; ++k) {
            const double p0 = test::planeSum(start, M::P1 + k) + test::planeSum(start, M::D1 + k);
            const double p1 = test::planeSum(end, M::P1 + k) + test::planeSum(end, M::D1 + k);
            EXPECT_NEAR(p1 / p0, 1.0, 1e-5) << "pigment " << k + 1;
        }
        // The run moved: a third of the water is gone, pigment has settled.
        EXPECT_GT(test::planeSum(end, M::G), 0.3 * water0);
        EXPECT_GT(test::planeSum(end, M::D1), 0.3 * test::planeSum(start, M::P1));
        std::printf("%s: water %.9f -> %.9f, gone %.1f%%\n", toString(edges).c_str(), water0,
                    water1, 100 * test::planeSum(end, M::G) / water0);
    }
}

// Lo Fig. 9: the more water in the brush, the further the stroke bleeds.
// One dab of the same pigment with 0.5, 1, 2 and 4 units of water, left to dry.
TEST(Watercolour, MoreWaterBleedsWider) {
    double last = 0;
    for (double water : {0.5, 1.0, 2.0, 4.0}) {
        const json strokes = json::array(
            {{{"points", {{0.5, 0.5}}}, {"radius", 0.06}, {"water", water}, {"amount", 0.5}}});
        const Session s = sessionFromJson(paintingJson(80, 1500, strokes), "bleed");
        const State end = paint(s);
        const double radius = stainRadius(end, 0.1f);
        const float wet = *std::max_element(end.plane(M::W), end.plane(M::W) + end.cellCount());
        std::printf("water %.1f: stain radius %.2f cells (brush radius 4.8), water left %.3g\n",
                    water, radius, wet);
        EXPECT_LT(wet, 0.05f) << "the wash should have dried";
        // Each doubling of water widens the stain by at least a cell.
        EXPECT_GT(radius, last + 1.0) << "water " << water;
        last = radius;
    }
}

// Watercolour's dark edge, as far as this model reaches it (see
// watercolour.hpp): the drying front is a pigment sink, so a very wet dab
// (4 units of water) dries no darker in its middle than at its rim.
// Measured: rim 1.08x the middle; a moist dab (1 unit) is darkest in the middle.
TEST(Watercolour, VeryWetDabDriesWithItsRimDarkest) {
    const json strokes = json::array(
        {{{"points", {{0.5, 0.5}}}, {"radius", 0.15}, {"water", 4.0}, {"amount", 0.5}}});
    json j = paintingJson(80, 1500, strokes);
    j["params"] = {{"paper_grain", 0}, {"paper_fibres", 0}}; // a plain paper: the profile alone
    const State end = paint(sessionFromJson(j, "rim"));
    // Mean deposit by distance from the centre, in one-cell rings.
    std::vector<double> sum(41, 0.0), count(41, 0.0);
    for (int y = 0; y < 80; ++y)
        for (int x = 0; x < 80; ++x) {
            const int r = int(std::hypot(x + 0.5 - 40.0, y + 0.5 - 40.0));
            if (r <= 40) {
                sum[std::size_t(r)] += end.at(M::D1, x, y);
                count[std::size_t(r)] += 1;
            }
        }
    double centre = 0, rim = 0;
    int rimAt = 0;
    for (int r = 0; r <= 40; ++r) {
        const double mean = sum[std::size_t(r)] / count[std::size_t(r)];
        if (r < 3)
            centre += mean / 3;
        if (mean > rim) {
            rim = mean;
            rimAt = r;
        }
    }
    std::printf("deposit: centre %.4f, rim %.4f (%.3fx) at radius %d\n", centre, rim, rim / centre,
                rimAt);
    EXPECT_GT(rimAt, 6);
    // Half the measured margin: a change that loses the sink fails here.
    EXPECT_GT(rim, 1.04 * centre);
}

TEST(Watercolour, PaperIsReproducibleNoiseInRange) {
    PaperSpec spec;
    const std::vector<float> a = makePaper(spec, 64, 48);
    EXPECT_EQ(a, makePaper(spec, 64, 48));
    spec.seed = 2;
    EXPECT_NE(a, makePaper(spec, 64, 48));
    double mean = 0, var = 0;
    for (float v : a) {
        EXPECT_GE(v, 0.02f);
        EXPECT_LE(v, 1.0f);
        mean += v / double(a.size());
    }
    for (float v : a)
        var += (v - mean) * (v - mean) / double(a.size());
    // The defaults: mean stickiness 0.6 with a visible grain.
    EXPECT_NEAR(mean, 0.6, 0.1);
    EXPECT_GT(std::sqrt(var), 0.05);
    PaperSpec smooth;
    smooth.grain = smooth.fibres = 0;
    for (float v : makePaper(smooth, 16, 16))
        EXPECT_NEAR(v, smooth.mean, 1e-6f);
}

TEST(Watercolour, StrokesBecomeWaterAndPigmentEdits) {
    const json strokes = json::array({{{"step", 5},
                                       {"points", {{0.2, 0.3}, {0.6, 0.3}}},
                                       {"radius", 0.05},
                                       {"water", 2.0},
                                       {"pigment", "p2"},
                                       {"amount", 0.7}},
                                      {{"step", 0}, {"points", {{0.5, 0.5}}}, {"radius", 0.1}}});
    const Session s = sessionFromJson(paintingJson(32, 10, strokes), "strokes");
    ASSERT_EQ(s.edits.size(), 4u);
    EXPECT_EQ(s.edits[0].step, 0); // sorted by step
    EXPECT_EQ(s.edits[0].stroke->chemical, "w");
    EXPECT_EQ(s.edits[1].stroke->chemical, "p1"); // the default pigment
    EXPECT_EQ(s.edits[2].step, 5);
    EXPECT_EQ(s.edits[2].stroke->value, 2.0f);
    EXPECT_EQ(s.edits[3].stroke->chemical, "p2");
    EXPECT_EQ(s.edits[3].stroke->value, 0.7f);
    EXPECT_EQ(s.edits[3].stroke->points.size(), 2u);
    // The session written back holds edits and reads back the same.
    EXPECT_EQ(sessionFromJson(sessionToJson(s), "again").edits, s.edits);
}

TEST(Watercolour, BadStrokesAreRefusedByField) {
    const json good = {{"points", {{0.5, 0.5}}}, {"radius", 0.1}, {"water", 1}, {"pigment", "p1"}};
    struct Bad {
        const char* field;
        json value;
        const char* says;
    };
    const Bad cases[] = {{"points", json::array({{1.2, 0.5}}), "strokes[0].points"},
                         {"points", json::array({{0.5, -0.1}}), "outside the canvas"},
                         {"points", json::array(), "strokes[0].points"},
                         {"radius", 0, "strokes[0].radius"},
                         {"radius", -0.1, "strokes[0].radius"},
                         {"water", -1, "strokes[0].water"},
                         {"amount", -0.5, "strokes[0].amount"},
                         {"pigment", "p3", "accepted: p1, p2"},
                         {"colour", "#ff0000", "colour"}};
    for (const Bad& b : cases) {
        json stroke = good;
        stroke[b.field] = b.value;
        SCOPED_TRACE(stroke.dump());
        try {
            sessionFromJson(paintingJson(32, 10, json::array({stroke})), "bad.json");
            ADD_FAILURE() << "accepted";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(b.says), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("bad.json"), std::string::npos) << e.what();
        }
    }
    json other = paintingJson(32, 10, json::array({good}));
    other["model"] = "gray_scott";
    other.erase("init");
    EXPECT_THROW(sessionFromJson(other, "gs.json"), InputError);
}

TEST(Watercolour, MapPaintsPigmentOnPaper) {
    State st(3, 1, M::Cell::kChemicals);
    for (int x = 0; x < 3; ++x)
        st.at(M::S, x, 0) = 0.5f;
    st.at(M::D1, 1, 0) = 1.0f; // blue pigment
    st.at(M::D2, 2, 0) = 1.0f; // sienna
    ColorMapSpec spec;
    spec.name = "watercolour";
    const std::vector<float> rgb = applyColormap(st, M::D1, spec);
    EXPECT_GT(rgb[0], 0.9f); // bare paper: near white
    EXPECT_GT(rgb[1], 0.9f);
    EXPECT_GT(rgb[2], 0.85f);
    EXPECT_GT(rgb[3 + 2], 2 * rgb[3 + 0]); // pigment 1 is blue
    EXPECT_GT(rgb[6 + 0], 2 * rgb[6 + 2]); // pigment 2 is a warm brown
    const State grey(3, 1, 2);
    EXPECT_THROW(applyColormap(grey, 0, spec), InputError);
}

namespace {

// Mean optical density (-log of the painted red, which pigment 1 absorbs)
// by distance from the canvas' centre, in one-cell rings.
std::vector<double> densityRings(const State& end, const ColorMapSpec& spec) {
    const std::vector<float> rgb = applyColormap(end, M::D1, spec);
    const int n = end.width();
    std::vector<double> sum(std::size_t(n / 2 + 1), 0.0), count(sum.size(), 0.0);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const int r = int(std::hypot(x + 0.5 - n / 2.0, y + 0.5 - n / 2.0));
            if (r <= n / 2) {
                sum[std::size_t(r)] -= std::log(rgb[(std::size_t(y) * n + x) * 3]);
                count[std::size_t(r)] += 1;
            }
        }
    for (std::size_t r = 0; r < sum.size(); ++r)
        sum[r] /= count[r];
    return sum;
}

} // namespace

// The map's dark edge where a wash dried (WatercolourEdges): a moist dab,
// which this model alone dries darkest in its middle, is painted darker in
// a band just inside the edge of where the paper was wet, darker there than
// its middle; the middle hardly changes and the dry paper round it not at all.
TEST(Watercolour, DriedWashIsPaintedDarkerAtItsEdge) {
    const json strokes = json::array(
        {{{"points", {{0.5, 0.5}}}, {"radius", 0.15}, {"water", 1.0}, {"amount", 0.5}}});
    json j = paintingJson(80, 1500, strokes);
    j["params"] = {{"paper_grain", 0}, {"paper_fibres", 0}}; // a plain paper: the profile alone
    const State end = paint(sessionFromJson(j, "edge"));
    ColorMapSpec plain, darkened;
    plain.name = darkened.name = "watercolour";
    plain.edgeDarkening = 0.0f;
    darkened.edgeWidth = 0.05f; // 4 cells at 80, as the default is at 256
    const std::vector<double> a = densityRings(end, plain), b = densityRings(end, darkened);
    const auto peak = [](const std::vector<double>& v, int from) {
        int at = from;
        for (int r = from; r < int(v.size()); ++r)
            at = v[std::size_t(r)] > v[std::size_t(at)] ? r : at;
        return at;
    };
    const int rimAt = peak(b, 3);
    std::printf(
        "density: centre %.4f, without edges the densest ring %d (%.4f); with edges ring %d "
        "%.4f (%.2fx the centre)\n",
        b[0], peak(a, 0), a[std::size_t(peak(a, 0))], rimAt, b[std::size_t(rimAt)],
        b[std::size_t(rimAt)] / b[0]);
    EXPECT_LT(peak(a, 0), 3) << "without the effect this dab is darkest in its middle";
    EXPECT_GT(rimAt, 6);
    // Measured 1.47x (at the default strength, 1): half the margin.
    EXPECT_GT(b[std::size_t(rimAt)], 1.25 * b[0]);
    // The band fades inwards over about twice the width (8 of this dab's 12
    // cells): measured 0.5% in its middle.
    EXPECT_NEAR(b[0], a[0], 0.01 * a[0]) << "the middle of the wash is hardly darkened";
    EXPECT_EQ(b.back(), a.back()) << "nor the dry paper round it";
}

// edge_darkening and edge_width belong to the watercolour map, are read
// back as written, and are refused with the field named elsewhere or out of range.
TEST(Watercolour, EdgeFieldsAreTheWatercolourMapsOwn) {
    json j = paintingJson(32, 10, json::array());
    j["colormap"] = {{"name", "watercolour"}, {"edge_darkening", 0.5}, {"edge_width", 0.02}};
    const Session s = sessionFromJson(j, "edges");
    EXPECT_FLOAT_EQ(s.colormap.edgeDarkening, 0.5f);
    EXPECT_FLOAT_EQ(s.colormap.edgeWidth, 0.02f);
    const Session back = sessionFromJson(sessionToJson(s), "back");
    EXPECT_EQ(back.colormap.edgeDarkening, s.colormap.edgeDarkening);
    EXPECT_EQ(back.colormap.edgeWidth, s.colormap.edgeWidth);
    const auto refused = [&](json colormap, const std::string& expected) {
        json k = j;
        k["colormap"] = colormap;
        try {
            sessionFromJson(k, "bad");
            ADD_FAILURE() << "accepted " << colormap.dump();
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        }
    };
    refused({{"name", "grey"}, {"edge_darkening", 1}}, "edge_darkening");
    refused({{"name", "watercolour"}, {"edge_darkening", -1}}, "edge_darkening");
    refused({{"name", "watercolour"}, {"edge_width", 0}}, "edge_width");
    refused({{"name", "watercolour"}, {"edge_width", "wide"}}, "edge_width");
}

// The band on a made-up state: a wash with sharp edges over the left half of
// the canvas. It peaks just inside the wash's edge at crispPeak (what the
// painter scales by) and is 0 deep inside and on dry paper; at the image's
// border the clamped edges see no edge (the wash goes on past it), the
// periodic ones see the wash end there (the right half is dry).
TEST(Watercolour, EdgeBandFollowsTheSessionsEdges) {
    const int w = 64, h = 8;
    State st(w, h, M::Cell::kChemicals);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w / 2; ++x)
            st.at(M::G, x, y) = 1.0f; // water went here: the paper was wet
    const float width = 4.0f / float(w);
    const std::array<int, 2> radii = WatercolourEdges::radii(w, width);
    ASSERT_EQ(radii, (std::array<int, 2>{1, 4}));
    const float crisp = WatercolourEdges::crispPeak(radii);
    for (const EdgeMode edges : {EdgeMode::Clamped, EdgeMode::Periodic}) {
        const WatercolourEdges e(st, width, edges);
        const auto band = [&](int x) { return e.band()[std::size_t(3 * w + x)]; };
        const auto peak = [&](int from, int to) {
            float p = 0.0f;
            for (int x = from; x < to; ++x)
                p = std::max(p, band(x));
            return p;
        };
        const bool wraps = edges == EdgeMode::Periodic;
        SCOPED_TRACE(wraps ? "periodic" : "clamped");
        EXPECT_NEAR(peak(w / 2 - 9, w / 2), crisp, 1e-5f); // just inside the edge
        EXPECT_FLOAT_EQ(e.scale(), 1.0f / crisp);
        EXPECT_EQ(band(w / 2 - 12), 0.0f); // deep inside: further than two wide radii
        EXPECT_EQ(peak(w / 2, w), 0.0f);   // dry paper
        if (wraps)
            EXPECT_NEAR(peak(0, 9), crisp, 1e-5f); // the wash's other edge, across the border
        else
            EXPECT_EQ(peak(0, 9), 0.0f);
    }
}
