// Cascades (Turk's frozen cells, stages) and per-cell parameter maps on the
// CPU reference backend; cascade_gltest runs the same checks on the GPU.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cascade_checks.hpp"
#include "core/base/errors.hpp"
#include "core/session/param_map.hpp"
#include "core/session/session.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {
SimulatorFactory cpu() {
    return [](const Session& s) { return std::make_unique<CpuSimulator>(s); };
}
} // namespace

TEST(Cascade, FrozenCellsKeepTheirValuesBitForBit) {
    test::checkFrozenCellsExact(cpu());
}

TEST(Cascade, LeopardResetsFrozenCells) {
    test::checkLeopardReset(cpu());
}

TEST(Cascade, ModelChangeFreezesByTheOldModelAndResetsTheNew) {
    test::checkModelChangeFreezesAndResets(cpu());
}

TEST(Cascade, AModelChangingStageStartsFromTheNewModelsDefaults) {
    Session s = loadPreset("turk_giraffe");
    s.width = s.height = 32;
    s.stages[0].steps = 200;
    s.stages[1].steps = 50;
    s.steps = 250;
    auto run = [](const Session& session) { return runSession(session, cpu(), {}).state; };
    // No "dt": the new model's default (1), not the session's 0.18.
    Session noDt = s;
    noDt.stages[1].dt.reset();
    Session dt1 = s;
    dt1.stages[1].dt = 1.0f;
    Session dtHalf = s;
    dtHalf.stages[1].dt = 0.5f;
    EXPECT_EQ(test::maxAbsDifference(run(noDt), run(dt1)), 0.0f);
    EXPECT_GT(test::maxAbsDifference(run(noDt), run(dtHalf)), 1e-4f);
    // Parameters: the new model's defaults plus the stage's, not the session's.
    Session explicitDefaults = s;
    for (const ParamSpec& p : findModel("meinhardt_stripes")->params())
        explicitDefaults.stages[1].params.emplace(p.name, p.defaultValue);
    EXPECT_EQ(test::maxAbsDifference(run(s), run(explicitDefaults)), 0.0f);
    // A stage "init" replaces the new model's default start.
    Session init = s;
    init.stages[1].init = findModel("meinhardt_stripes")->defaultInit();
    init.stages[1].init->base["g1"] = 0.5f;
    EXPECT_GT(test::maxAbsDifference(run(s), run(init)), 1e-4f);
}

TEST(ParamMaps, TheParameterAtACellIsTheMapsValue) {
    test::checkParamMapReadBack(cpu());
}

TEST(ParamMaps, LinearFieldsRunAlongTheirAxes) {
    ParamMapSpec x{ParamMapSpec::Field::LinearX, 0.01f, 0.09f};
    const std::vector<float> vx = evaluateParamMap(x, 9, 5, 1, "");
    EXPECT_FLOAT_EQ(vx[0], 0.01f);
    EXPECT_FLOAT_EQ(vx[8], 0.09f);
    EXPECT_FLOAT_EQ(vx[4 * 9 + 4], 0.05f); // constant down each column
    ParamMapSpec y{ParamMapSpec::Field::LinearY, 0.0f, 1.0f};
    const std::vector<float> vy = evaluateParamMap(y, 3, 5, 1, "");
    EXPECT_FLOAT_EQ(vy[4 * 3], 0.0f); // bottom row: the axis' minimum
    EXPECT_FLOAT_EQ(vy[0], 1.0f);     // top row: its maximum
    ParamMapSpec noise{ParamMapSpec::Field::Noise, 2.0f, 3.0f};
    noise.scale = 4;
    for (float v : evaluateParamMap(noise, 16, 16, 7, "")) {
        EXPECT_GE(v, 2.0f);
        EXPECT_LE(v, 3.0f);
    }
}

TEST(Cascade, BrokenStagesAndMapsAreNamed) {
    auto errorFor = [](const char* text) -> std::string {
        try {
            sessionFromJson(nlohmann::json::parse(text), "cascade.json");
        } catch (const InputError& e) {
            return e.what();
        }
        return "";
    };
    EXPECT_NE(errorFor(R"({"model": "turing_turk", "stages": []})").find("non-empty array"),
              std::string::npos);
    EXPECT_NE(errorFor(R"({"model": "turing_turk", "stages": [{"freeze": {"chemical": "q"}}]})")
                  .find("'stages[0].freeze.chemical' is 'q'"),
              std::string::npos);
    // Nothing to freeze before the first stage has run.
    EXPECT_NE(errorFor(R"({"model": "turing_turk", "stages": [{"freeze": {"chemical": "b"}},
                                                             {"steps": 1}]})")
                  .find("'stages[0].freeze' cannot be on the first stage"),
              std::string::npos);
    EXPECT_NE(errorFor(R"({"model": "turing_turk", "stages": [{"params": {"z": 1}}]})")
                  .find("'stages[0].params.z' is not a parameter"),
              std::string::npos);
    EXPECT_NE(errorFor(R"({"model": "gray_scott", "param_maps": {"F": {"field": "wave"}}})")
                  .find("accepted: linear_x"),
              std::string::npos);
    EXPECT_NE(errorFor(R"({"model": "gray_scott", "param_maps": {"F": {"range": [0, 9]}}})")
                  .find("'param_maps.F.range[1]' is 9"),
              std::string::npos);
    EXPECT_NE(errorFor(R"({"model": "gray_scott", "param_maps": {"F": {"range": [0, 0.1]}},
                           "stages": [{"params": {"F": 0.05}}]})")
                  .find("which param_maps sets per cell"),
              std::string::npos);
    const Session cheetah = loadPreset("turk_cheetah");
    ASSERT_EQ(cheetah.stages.size(), 2u);
    EXPECT_EQ(cheetah.steps, cheetah.stages[0].steps + cheetah.stages[1].steps);
    EXPECT_EQ(sessionToJson(sessionFromJson(sessionToJson(cheetah), "x")), sessionToJson(cheetah));
}
