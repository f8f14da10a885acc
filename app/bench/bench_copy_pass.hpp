#pragma once

#include "gl/gpu_simulator.hpp"
#include "gl/objects.hpp"

namespace morphogen::bench {

// The copy pass the benchmark measures the GPU step against: same format,
// same size, same number of state textures, one fetch per texel, same
// ping-pong.
class CopyPass {
public:
    // The textures a simulation of `chemicals` chemicals steps.
    CopyPass(int width, int height, int chemicals);
    void run(int steps) { m_pingPong.run(m_program, steps); }

private:
    gl::Program m_program;
    gl::PingPong m_pingPong;
};

} // namespace morphogen::bench
