#pragma once

#include "core/simulator.hpp"

namespace morphogen {

// The CPU reference backend: the oracle for the GPU path in tests and the
// fallback for batch work where the only GL is a software rasterizer. Rows
// are split across OpenMP threads. Built-in models step through one fused
// loop per row (stencil, reaction, update and clamp per cell, vectorised,
// with an AVX2 clone picked at run time); other models, and runs with a zero
// diffusion rate, take a generic path through ReactionModel::react().
class CpuSimulator : public Simulator {
public:
    explicit CpuSimulator(const Session& session);

    std::string backendName() const override { return "cpu"; }
    void setState(const State& state) override;
    State state() const override { return m_current; }
    void run(int steps) override;

    // Semi-implicit runs: max over cells of |(I - dt A) c' - (c + dt f(c))|
    // for the last step, i.e. how far the Jacobi sweeps left the solve.
    double lastSolveResidual() const;

private:
    // Steps rows [y0, y1) of in into out.
    using FusedKernel = void (*)(const StepConstants& k, const State& in, State& out, int y0,
                                 int y1);

    void step();
    void stepGeneric();
    void stepSemiImplicit();
    // The diffusion term of chemical c on row y, rate included.
    void diffusionRow(int c, const float* plane, int y, float* out) const;

    const ReactionModel& m_model;
    FusedKernel m_fused = nullptr; // null: the generic path
    StepConstants m_k;
    State m_current;
    State m_next;
    State m_rhs; // SemiImplicit: c + dt f(c) of the step being solved
};

} // namespace morphogen
