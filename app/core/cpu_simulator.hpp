#pragma once

#include "core/simulator.hpp"

namespace morphogen {

// The CPU reference backend: the oracle for the GPU path in tests and the
// fallback for batch work where the only GL is a software rasterizer. Rows
// are split across OpenMP threads; the inner loops are unit-stride so the
// compiler vectorises them.
class CpuSimulator : public Simulator {
public:
    explicit CpuSimulator(const Session& session);

    std::string backendName() const override { return "cpu"; }
    void setState(const State& state) override;
    State state() const override { return m_current; }
    void run(int steps) override;

private:
    void step();

    const ReactionModel& m_model;
    StepConstants m_k;
    State m_current;
    State m_next;
};

} // namespace morphogen
