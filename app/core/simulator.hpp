#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/diffusion_operator.hpp"
#include "core/session.hpp"
#include "core/state.hpp"

namespace morphogen {

// What one step needs, derived once from a session; both backends read the
// same values so they share step semantics. Explicit Euler:
//   c' = clamp(c + dt * (react(c) + A c), clampMin, clampMax)
// Semi-implicit: relaxation sweeps on (I - dt A) c' = c + dt react(c),
// starting from c, clamped after every sweep.
struct StepConstants {
    int chemicals = 0;
    float dt = 1.0f;
    std::array<float, 4> diffusion = {};
    std::array<float, 4> clampMin = {};
    std::array<float, 4> clampMax = {};
    std::vector<float> params; // model declaration order
    Stencil stencil = Stencil::FivePoint;
    GridDomain domain;
    DiffusionOperator op;
    Integrator integrator = Integrator::ExplicitEuler;
    int jacobiSweeps = 8;
    // SemiImplicit: each chemical's Richardson weight (stability.hpp); a sweep is
    //   x' = clamp(x + omega (rhs - x + dt A x)),  rhs = c + dt f(c).
    std::array<float, 4> omega = {};
    double contraction = 0; // worst chemical's residual factor per sweep

    static StepConstants fromSession(const Session& session);
};

// One simulation backend. Runs steps without reading back; state() reads back.
class Simulator {
public:
    virtual ~Simulator() = default;
    virtual std::string backendName() const = 0;
    virtual void setState(const State& state) = 0;
    virtual State state() const = 0;
    virtual void run(int steps) = 0;
};

} // namespace morphogen
