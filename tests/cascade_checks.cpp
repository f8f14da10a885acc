#include "cascade_checks.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "core/session/cascade.hpp"
#include "core/session/param_map.hpp"
#include "test_support.hpp"

namespace morphogen::test {

namespace {

Session smallCheetah() {
    Session s = loadPreset("turk_cheetah");
    s.width = s.height = 48;
    s.stages[0].steps = 1500;
    s.stages[1].steps = 300;
    s.steps = 1800;
    return s;
}

State runStages(Session s, const SimulatorFactory& make, std::size_t stages) {
    s.stages.resize(stages);
    s.steps = 0;
    for (const Stage& stage : s.stages)
        s.steps += stage.steps;
    return runSession(s, make, RunOptions{}).state;
}

} // namespace

void checkFrozenCellsExact(const SimulatorFactory& make) {
    const Session s = smallCheetah();
    const ReactionModel& model = s.reactionModel();
    const State first = runStages(s, make, 1);
    const State both = runStages(s, make, 2);
    const std::vector<std::uint8_t> frozen = applyFreezeRule(*s.stages[1].freeze, first, model, {});
    int frozenCount = 0, changed = 0;
    for (std::size_t i = 0; i < frozen.size(); ++i) {
        for (int c = 0; c < first.channels(); ++c) {
            if (frozen[i])
                ASSERT_EQ(both.plane(c)[i], first.plane(c)[i]) << "cell " << i << " chemical " << c;
            else
                changed += both.plane(c)[i] != first.plane(c)[i];
        }
        frozenCount += frozen[i];
    }
    // The rule must pick real spots, and the rest must have moved.
    EXPECT_GT(frozenCount, int(frozen.size()) / 50);
    EXPECT_LT(frozenCount, int(frozen.size()) / 2);
    EXPECT_GT(changed, int(frozen.size()) / 2);
}

void checkLeopardReset(const SimulatorFactory& make) {
    Session s = smallCheetah();
    s.stages[1].reset = {{"a", 4.0f}, {"b", 4.0f}};
    const ReactionModel& model = s.reactionModel();
    const State first = runStages(s, make, 1);
    const State both = runStages(s, make, 2);
    const std::vector<std::uint8_t> frozen = applyFreezeRule(*s.stages[1].freeze, first, model, {});
    for (std::size_t i = 0; i < frozen.size(); ++i)
        if (frozen[i]) {
            ASSERT_EQ(both.plane(0)[i], 4.0f);
            ASSERT_EQ(both.plane(1)[i], 4.0f);
            ASSERT_EQ(both.plane(2)[i], first.plane(2)[i]); // beta untouched
        }
}

void checkModelChangeFreezesAndResets(const SimulatorFactory& make) {
    Session s = loadPreset("turk_giraffe");
    s.width = s.height = 48;
    s.stages[0].steps = 1500;
    s.stages[1].steps = 300;
    s.steps = 1800;
    ASSERT_EQ(s.stages[1].model, "meinhardt_stripes");
    const ReactionModel& turing = s.reactionModel();
    const ReactionModel& stripes = s.outputModel();
    ASSERT_EQ(stripes.name(), "meinhardt_stripes");

    const State first = runStages(s, make, 1);
    const RunResult both = runSession(s, make, RunOptions{});
    ASSERT_EQ(first.channels(), int(turing.chemicals().size()));
    ASSERT_EQ(both.state.channels(), int(stripes.chemicals().size()));
    EXPECT_EQ(both.stepsDone, 1800);

    // The rule reads the Turing result with the Turing model's chemicals.
    const std::vector<std::uint8_t> frozen =
        applyFreezeRule(*s.stages[1].freeze, first, turing, {});
    // The new model's start: its default initial condition, same size and seed.
    ParamValues params;
    for (const ParamSpec& p : stripes.params())
        params[p.name] = p.defaultValue;
    const State start =
        makeInitialState(stripes.defaultInit(), stripes, params, s.width, s.height, s.seed);
    int frozenCount = 0, changed = 0;
    for (std::size_t i = 0; i < frozen.size(); ++i) {
        for (int c = 0; c < both.state.channels(); ++c) {
            const std::string& name = stripes.chemicals()[std::size_t(c)].name;
            auto reset = s.stages[1].reset.find(name);
            if (frozen[i])
                ASSERT_EQ(both.state.plane(c)[i],
                          reset != s.stages[1].reset.end() ? reset->second : start.plane(c)[i])
                    << "cell " << i << " chemical " << name;
            else
                changed += both.state.plane(c)[i] != start.plane(c)[i];
        }
        frozenCount += frozen[i];
    }
    EXPECT_GT(frozenCount, int(frozen.size()) / 20);
    EXPECT_LT(frozenCount, int(frozen.size()) * 3 / 4);
    EXPECT_GT(changed, int(frozen.size()) / 2);
}

void checkParamMapReadBack(const SimulatorFactory& make) {
    Session s = loadPreset("gs_coral");
    s.width = 40;
    s.height = 8;
    s.steps = 1;
    s.dt = 0.5f;
    s.params["Du"] = s.params["Dv"] = 0.0f;
    s.init = InitialCondition{}; // u = v = 0 everywhere
    s.paramMaps["F"] = {ParamMapSpec::Field::LinearX, 0.01f, 0.09f};
    const State st = runSession(s, make, RunOptions{}).state;
    const std::vector<float> expected = evaluateParamMap(s.paramMaps["F"], 40, 8, s.seed, "");
    for (std::size_t i = 0; i < st.cellCount(); ++i)
        ASSERT_NEAR(st.plane(0)[i] / s.dt, expected[i], 1e-6f) << "cell " << i;
    // The axis really spans its range.
    EXPECT_NEAR(st.at(0, 0, 3) / s.dt, 0.01f, 1e-6f);
    EXPECT_NEAR(st.at(0, 39, 3) / s.dt, 0.09f, 1e-6f);
}

} // namespace morphogen::test
