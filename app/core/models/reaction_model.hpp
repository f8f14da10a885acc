#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/base/state.hpp"
#include "core/models/diffusion_spec.hpp"
#include "core/models/initial_condition.hpp"

namespace morphogen {

class NoiseField;

struct ParamSpec {
    std::string name;
    float defaultValue = 0.0f;
    float min = 0.0f; // accepted range; values outside are rejected as bad input
    float max = 0.0f;
    std::string description;
};

struct ChemicalSpec {
    std::string name;
    // The parameter holding this chemical's diffusion rate; empty for a
    // per-cell field that neither diffuses nor reacts (Turk's beta).
    std::string diffusionParam;
    // Hard limits applied after every step on both backends (Turk keeps b >= 0).
    float clampMin = -std::numeric_limits<float>::infinity();
    float clampMax = std::numeric_limits<float>::infinity();
    // Values outside this range mean the run has blown up.
    float saneMin = -1e4f;
    float saneMax = 1e4f;
    // The values a settled pattern spans: a texture set's fixed height levels
    // (the same for every render, unlike the colour map's per-image min-max).
    std::array<float, 2> displayRange = {0.0f, 1.0f};
};

// Parameter values by name, complete for a model (defaults filled in).
using ParamValues = std::map<std::string, float>;

// Pointers to one row of every chemical plane, for the CPU reaction loops.
struct RowView {
    const float* c[kMaxChemicals] = {};
    float* dcdt[kMaxChemicals] = {};
    int n = 0;
};

// The C++ reaction of a model, one cell at a time. Each built-in model (listed
// in builtin_models.hpp) defines one (GrayScottModel::Cell, ...) so the CPU
// backend can instantiate a fused step kernel over it, with the reaction
// inlined into the stencil loop; a virtual call per row and the row buffers
// between passes cost ~3x. A Cell has
//   static constexpr int kChemicals;
//   static constexpr bool diffuses(int chemical); // false: no diffusionParam
//   explicit Cell(const float* params);           // packParams() layout
//   void react(const float* c, float* dcdt) const;
// react() must be plain arithmetic, free of branches and calls, so it
// vectorises across cells, and declared MORPHOGEN_CELL_REACT: GCC's inliner
// otherwise declines the larger ones (watercolour's) inside the fused kernel,
// and the call then stops the loop's vectorisation ("statement clobbers
// memory"). models/react_row.hpp turns a Cell into react().
#if defined(__GNUC__)
#define MORPHOGEN_CELL_REACT inline __attribute__((always_inline))
#else
#define MORPHOGEN_CELL_REACT inline
#endif

// A reaction model: its chemicals, its parameters and its reaction function,
// written twice from one description: a GLSL snippet and the C++ Cell above.
// A gltest proves the two agree. The snippet (glslPath(), compiled after
// glslDefines()) reads parameters as globals p_<param> and defines
//   vec4 react(vec4 c)                                          up to 4 chemicals
//   void react(vec4 c[STATE_TEXTURES], out vec4 dcdt[STATE_TEXTURES])  more
// where chemical i is component i % 4 of c[i / 4] (one state texture per four).
class ReactionModel {
public:
    virtual ~ReactionModel() = default;

    const std::string& name() const { return m_name; }
    const std::string& description() const { return m_description; }
    const std::vector<ChemicalSpec>& chemicals() const { return m_chemicals; }
    const std::vector<ParamSpec>& params() const { return m_params; }
    // The chemical shown by default when rendering.
    int displayChemical() const { return m_displayChemical; }
    // The explicit time step the model's presets are tuned for.
    float defaultDt() const { return m_defaultDt; }
    // The start used when a session names none.
    const InitialCondition& defaultInit() const { return m_defaultInit; }
    // The diffusion used when a session has no "diffusion" block (isotropic
    // unless a model needs more to make any pattern, as Witkin-Kass's
    // multi-orientation models do). A session's block replaces it whole.
    const DiffusionSpec& defaultDiffusion() const { return m_defaultDiffusion; }
    std::string glslPath() const {
        return "glsl/models/" + (m_glslFile.empty() ? m_name : m_glslFile) + ".glsl";
    }
    // "NAME VALUE" #defines the snippet is compiled with (one snippet can serve a family of
    // models, such as Witkin-Kass's 2-, 3- and 5-direction systems).
    const std::vector<std::string>& glslDefines() const { return m_glslDefines; }

    int chemicalIndex(const std::string& name) const; // -1 when absent
    const ParamSpec* param(const std::string& name) const;
    // "a, b, beta": for error messages that list what is accepted.
    std::string chemicalNames() const;
    std::string paramNames() const;

    // Parameter values in declaration order, the layout react() reads.
    std::vector<float> packParams(const ParamValues& values) const;

    // dc/dt of the reaction term for one row of cells. The CPU backend's
    // generic path: used for models it has no fused kernel for, and for runs
    // where a chemical that normally diffuses has a diffusion rate of 0.
    virtual void react(const RowView& row, const float* params) const = 0;

    // Fills model-owned per-cell fields after the initial condition (Turk's
    // beta = mean +- noise, from `noise`). The default does nothing.
    virtual void prepareState(State& state, const ParamValues& values,
                              const NoiseField& noise) const;

protected:
    std::string m_name;
    std::string m_glslFile; // empty: m_name
    std::vector<std::string> m_glslDefines;
    std::string m_description;
    std::vector<ChemicalSpec> m_chemicals;
    std::vector<ParamSpec> m_params;
    int m_displayChemical = 0;
    float m_defaultDt = 1.0f;
    InitialCondition m_defaultInit;
    DiffusionSpec m_defaultDiffusion;
};

// All built-in models (builtin_models.hpp lists them), by name.
const ReactionModel* findModel(const std::string& name);
std::vector<const ReactionModel*> allModels();
// "gray_scott, turing_turk, ...": for error messages.
std::string modelNames();

} // namespace morphogen
