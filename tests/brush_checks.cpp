#include "brush_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <gtest/gtest.h>

#include "core/base/errors.hpp"
#include "core/session/param_map.hpp"
#include "core/sim/brush.hpp"
#include "test_support.hpp"

namespace morphogen::test {

namespace {

struct Disc {
    float x, y, radius, falloff;
};

bool sameBits(float a, float b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// The weight a disc gives cell (x, y), worked out here from the geometry
// (nearest periodic image) rather than from BrushRegion.
float expectedWeight(const Session& s, const Disc& d, int x, int y) {
    float dx = float(x) - d.x, dy = float(y) - d.y;
    if (s.edges == EdgeMode::Periodic) {
        dx -= float(s.width) * std::round(dx / float(s.width));
        dy -= float(s.height) * std::round(dy / float(s.height));
    }
    const float dist = std::sqrt(dx * dx + dy * dy);
    if (dist > d.radius)
        return 0.0f;
    const float inner = d.radius * (1.0f - d.falloff);
    return dist <= inner ? 1.0f : (d.radius - dist) / (d.radius - inner);
}

Brush makeBrush(const Session& s, BrushMode mode, const Disc& d, int chemical, float value) {
    Brush b;
    b.mode = mode;
    b.region = BrushRegion::disc(s.domain(), d.x, d.y, d.radius, d.falloff);
    b.chemical = chemical;
    b.value = value;
    return b;
}

Brush paintBrush(const Session& s, const Disc& d, const std::string& param, float value) {
    Brush b = makeBrush(s, BrushMode::Paint, d, 0, value);
    b.param = param;
    return b;
}

// A simulator of s started from its initial condition and run `steps` steps.
std::unique_ptr<Simulator> started(const SimulatorFactory& make, const Session& s, int steps) {
    auto sim = make(s);
    sim->setState(makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, s.seed));
    sim->run(steps);
    return sim;
}

bool inDisc(const Session& s, const Disc& d, std::size_t i) {
    return expectedWeight(s, d, int(i % std::size_t(s.width)), int(i / std::size_t(s.width))) > 0;
}

void checkOneChemicalBrush(const SimulatorFactory& make, const Session& s, BrushMode mode,
                           const Disc& d, int chemical, float value) {
    SCOPED_TRACE(s.reactionModel().name() + " " + toString(s.edges) + " " + toString(mode) +
                 " chemical " + std::to_string(chemical) + " at (" + std::to_string(d.x) + ", " +
                 std::to_string(d.y) + ")");
    auto sim = started(make, s, 3);
    const State before = sim->state();
    Brush brush = makeBrush(s, mode, d, chemical, value);
    brush.seed = 7;
    sim->applyBrush(brush);
    const State after = sim->state();
    const ChemicalSpec& spec = s.reactionModel().chemicals()[std::size_t(chemical)];
    int inside = 0, changed = 0;
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(s.width) + std::size_t(x);
            const float w = expectedWeight(s, d, x, y);
            for (int c = 0; c < before.channels(); ++c) {
                const float b = before.plane(c)[i], a = after.plane(c)[i];
                if (c != chemical || w == 0.0f) {
                    ASSERT_TRUE(sameBits(a, b)) << "cell (" << x << ", " << y << ") chemical " << c
                                                << ": " << b << " -> " << a;
                    continue;
                }
                float expected = b;
                if (mode == BrushMode::Add)
                    expected = b + value * w;
                else if (mode == BrushMode::Remove)
                    expected = b - value * w;
                else if (mode == BrushMode::Set)
                    expected = b * (1.0f - w) + value * w;
                else
                    expected = b + value * w * brushNoise(brush.seed, std::uint32_t(i));
                expected = std::clamp(expected, spec.clampMin, spec.clampMax);
                // The GPU may fuse a multiply-add: one rounding apart.
                ASSERT_NEAR(a, expected, 1e-6f * std::max(1.0f, std::fabs(expected)))
                    << "cell (" << x << ", " << y << ") weight " << w;
                ++inside;
                changed += !sameBits(a, b);
            }
        }
    EXPECT_EQ(inside, int(brush.region.cells().size()));
    EXPECT_GT(inside, 10);
    EXPECT_GT(changed, inside / 2);
}

} // namespace

void checkChemicalBrushes(const SimulatorFactory& make) {
    Session gs = smallSession("gs_coral", 20, 3);
    gs.width = 24; // non-square catches swapped axes
    using M = BrushMode;
    checkOneChemicalBrush(make, gs, M::Add, {7.25f, 9.5f, 4.3f, 0.5f}, 1, 0.3f);
    checkOneChemicalBrush(make, gs, M::Remove, {0.5f, 0.5f, 3.6f, 0.0f}, 0, 0.2f); // 4 pieces
    checkOneChemicalBrush(make, gs, M::Set, {23.0f, 10.0f, 3.2f, 0.3f}, 1, 0.7f);  // 2 pieces
    checkOneChemicalBrush(make, gs, M::Randomise, {12.0f, 3.0f, 5.0f, 0.0f}, 0, 0.1f);
    gs.edges = EdgeMode::Clamped;
    checkOneChemicalBrush(make, gs, M::Add, {0.5f, 0.5f, 4.6f, 0.0f}, 1, 0.3f); // cut at the edge

    Session mh = smallSession("meinhardt_random_stripes", 16, 3);
    mh.width = 20;
    // s2 (second texture) cleared to its clamp at 0; substrate across a corner.
    checkOneChemicalBrush(make, mh, M::Remove, {10.0f, 8.0f, 4.2f, 0.0f}, 4, 100.0f);
    checkOneChemicalBrush(make, mh, M::Set, {0.0f, 15.0f, 3.3f, 0.0f}, 5, 2.0f);
    checkOneChemicalBrush(make, mh, M::Add, {5.0f, 5.0f, 3.3f, 0.4f}, 1, 0.5f);
}

void checkRandomiseReproducible(const SimulatorFactory& make) {
    Session s = smallSession("gs_coral", 20, 3);
    const Disc d = {9.5f, 10.0f, 5.5f, 0.0f};
    Brush brush = makeBrush(s, BrushMode::Randomise, d, 1, 0.2f);
    brush.seed = 11;
    auto a = started(make, s, 3), b = started(make, s, 3), c = started(make, s, 3);
    const State before = a->state();
    a->applyBrush(brush);
    b->applyBrush(brush);
    brush.seed = 12;
    c->applyBrush(brush);
    EXPECT_TRUE(a->state() == b->state());
    const State sa = a->state(), sc = c->state();
    int differ = 0, inside = 0;
    for (std::size_t i = 0; i < before.cellCount(); ++i) {
        if (!inDisc(s, d, i)) {
            ASSERT_TRUE(sameBits(sa.plane(1)[i], before.plane(1)[i])) << "cell " << i;
            continue;
        }
        ++inside;
        differ += sa.plane(1)[i] != sc.plane(1)[i];
    }
    EXPECT_GT(inside, 50);
    EXPECT_GT(differ, inside * 9 / 10);
}

void checkHoldAndRelease(const SimulatorFactory& make) {
    Session s = smallSession("gs_coral", 20, 3);
    s.width = 24;
    const Disc a = {6.0f, 6.0f, 3.5f, 0.0f}, b = {0.5f, 14.0f, 3.5f, 0.0f}; // b wraps
    auto sim = started(make, s, 5);
    const State start = sim->state();
    sim->applyBrush(makeBrush(s, BrushMode::Hold, a, 0, 0.0f)); // FROZEN comes in
    sim->run(15);
    const State mid = sim->state();
    sim->applyBrush(makeBrush(s, BrushMode::Hold, b, 0, 0.0f)); // the mask grows
    sim->run(15);
    const State late = sim->state();
    int outsideMoved = 0, outside = 0;
    for (std::size_t i = 0; i < start.cellCount(); ++i)
        for (int c = 0; c < start.channels(); ++c) {
            if (inDisc(s, a, i))
                ASSERT_TRUE(sameBits(late.plane(c)[i], start.plane(c)[i])) << "held cell " << i;
            else if (inDisc(s, b, i))
                ASSERT_TRUE(sameBits(late.plane(c)[i], mid.plane(c)[i])) << "held cell " << i;
            else {
                ++outside;
                outsideMoved += late.plane(c)[i] != mid.plane(c)[i];
            }
        }
    EXPECT_GT(outsideMoved, outside / 2);

    // Release a: a moves again, b stays held; release b too: the mask empties.
    sim->applyBrush(makeBrush(s, BrushMode::Release, a, 0, 0.0f));
    sim->run(15);
    const State released = sim->state();
    sim->applyBrush(makeBrush(s, BrushMode::Release, b, 0, 0.0f));
    sim->run(15);
    const State free = sim->state();
    int aMoved = 0, aCells = 0, bMoved = 0, bCells = 0;
    for (std::size_t i = 0; i < start.cellCount(); ++i) {
        if (inDisc(s, a, i)) {
            ++aCells;
            aMoved += released.plane(0)[i] != late.plane(0)[i];
        } else if (inDisc(s, b, i)) {
            ASSERT_TRUE(sameBits(released.plane(0)[i], late.plane(0)[i])) << "held cell " << i;
            ++bCells;
            bMoved += free.plane(0)[i] != released.plane(0)[i];
        }
    }
    EXPECT_GT(aCells, 20);
    EXPECT_GT(aMoved, aCells / 2);
    EXPECT_GT(bMoved, bCells / 2);
}

void checkPaintedParameters(const SimulatorFactory& make) {
    Session s = smallSession("gs_coral", 20, 3);
    s.width = 24;
    const Disc d = {8.0f, 9.0f, 4.5f, 0.5f}, e = {8.0f, 9.0f, 2.2f, 0.0f}; // e inside d
    const State start = started(make, s, 20)->state();
    auto fresh = [&] {
        auto sim = make(s);
        sim->setState(start);
        return sim;
    };
    for (const std::string param : {"F", "Du"}) {
        SCOPED_TRACE(param);
        const float uniform = s.params.at(param), painted = param == "F" ? 0.09f : 1.0f;
        auto reference = fresh(), plain = fresh(), sim = fresh(), twice = fresh();
        reference->applyBrush(paintBrush(s, d, param, uniform)); // a map, all uniform
        sim->applyBrush(paintBrush(s, d, param, painted));
        twice->applyBrush(paintBrush(s, d, param, painted));
        twice->applyBrush(paintBrush(s, e, param, uniform)); // a stroke on the existing map
        for (auto* x : {reference.get(), plain.get(), sim.get(), twice.get()})
            x->run(1);
        const State r = reference->state(), p = sim->state(), t = twice->state();
        EXPECT_LT(maxAbsDifference(r, plain->state()), 1e-5f);
        // F acts on both chemicals' reactions, Du on u's diffusion only.
        const int affected = param == "F" ? 2 : 1;
        int inside = 0, changed = 0;
        for (std::size_t i = 0; i < r.cellCount(); ++i)
            for (int c = 0; c < r.channels(); ++c) {
                const bool mayChange = c < affected && inDisc(s, d, i);
                if (!mayChange) {
                    ASSERT_TRUE(sameBits(p.plane(c)[i], r.plane(c)[i]))
                        << "cell " << i << " chemical " << c;
                    ASSERT_TRUE(sameBits(t.plane(c)[i], r.plane(c)[i]))
                        << "cell " << i << " chemical " << c;
                    continue;
                }
                if (inDisc(s, e, i))
                    ASSERT_TRUE(sameBits(t.plane(c)[i], r.plane(c)[i])) << "repainted cell " << i;
                ++inside;
                changed += p.plane(c)[i] != r.plane(c)[i];
            }
        EXPECT_GT(inside, 40);
        EXPECT_GT(changed, inside / 2);
    }
}

void checkCellParams(const SimulatorFactory& make) {
    Session s = smallSession("gs_coral", 20, 3);
    s.width = 24;
    auto sim = started(make, s, 2);
    const float uniform = s.params.at("F");
    EXPECT_FALSE(sim->cellParam("F", 3, 4));
    EXPECT_FALSE(sim->cellParam("k", 3, 4));

    const Disc d = {8.0f, 9.0f, 3.0f, 0.0f};
    sim->applyBrush(paintBrush(s, d, "F", 0.09f));
    ASSERT_TRUE(sim->cellParam("F", 8, 9));
    EXPECT_NEAR(*sim->cellParam("F", 8, 9), 0.09f, 1e-6f);
    ASSERT_TRUE(sim->cellParam("F", 20, 2));
    EXPECT_FLOAT_EQ(*sim->cellParam("F", 20, 2), uniform);
    EXPECT_FALSE(sim->cellParam("k", 8, 9));
    EXPECT_FALSE(sim->cellParam("F", 24, 0));
    EXPECT_FALSE(sim->cellParam("F", 0, -1));

    Session mapped = s;
    mapped.paramMaps["k"] = {ParamMapSpec::Field::LinearX, 0.05f, 0.07f};
    auto withMap = started(make, mapped, 1);
    const std::vector<float> k =
        evaluateParamMap(mapped.paramMaps.at("k"), mapped.width, mapped.height, mapped.seed,
                         mapped.baseDir, mapped.layoutCellSize());
    for (const auto [x, y] : {std::pair{0, 0}, std::pair{23, 5}, std::pair{11, 19}}) {
        ASSERT_TRUE(withMap->cellParam("k", x, y));
        EXPECT_FLOAT_EQ(*withMap->cellParam("k", x, y), k[std::size_t(y * mapped.width + x)]);
    }
    EXPECT_NEAR(*withMap->cellParam("k", 23, 0), 0.07f, 1e-6f);
}

void checkBadBrushes(const SimulatorFactory& make) {
    Session s = smallSession("gs_coral", 16, 3);
    const Disc d = {8.0f, 8.0f, 3.0f, 0.0f};
    auto sim = started(make, s, 3);
    const State before = sim->state();
    EXPECT_THROW(sim->applyBrush(makeBrush(s, BrushMode::Add, d, 2, 0.1f)), InputError);
    EXPECT_THROW(sim->applyBrush(makeBrush(s, BrushMode::Add, d, -1, 0.1f)), InputError);
    EXPECT_THROW(sim->applyBrush(
                     makeBrush(s, BrushMode::Add, d, 0, std::numeric_limits<float>::quiet_NaN())),
                 InputError);
    EXPECT_THROW(sim->applyBrush(paintBrush(s, d, "Q", 0.1f)), InputError);
    EXPECT_THROW(sim->applyBrush(paintBrush(s, d, "F", 5.0f)), InputError); // range 0 to 0.2
    Brush other = makeBrush(s, BrushMode::Add, d, 0, 0.1f);
    other.region = BrushRegion::disc(GridDomain(10, 10, EdgeMode::Periodic), 5, 5, 2);
    EXPECT_THROW(sim->applyBrush(other), InputError);
    EXPECT_THROW(BrushRegion::disc(s.domain(), 1, 1, -2), InputError);
    EXPECT_THROW(BrushRegion::disc(s.domain(), 1, 1, 2, 1.5f), InputError);
    EXPECT_TRUE(sim->state() == before);

    // The semi-implicit solve needs constant rates: painting one is refused
    // and the simulation carries on as if nothing happened.
    s.integrator = Integrator::SemiImplicit;
    auto implicit = started(make, s, 0), untouched = started(make, s, 0);
    try {
        implicit->applyBrush(paintBrush(s, d, "Du", 0.5f));
        ADD_FAILURE() << "painting Du under semi_implicit was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("semi_implicit"), std::string::npos) << e.what();
    }
    implicit->run(3);
    untouched->run(3);
    EXPECT_TRUE(implicit->state() == untouched->state());
}

} // namespace morphogen::test
