#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/domain/domain.hpp"
#include "core/session/brush_mode.hpp"
#include "core/session/session.hpp"

namespace morphogen {

struct StepConstants;

// A rectangle of cells, inside the grid.
struct CellRect {
    int x = 0, y = 0, width = 0, height = 0;
};

// The cells one brush stroke touches, each with a weight in (0, 1] (1: the
// full effect). It is a set of cells rather than a shape so that both
// backends loop over exactly the same cells, and so that a set of atlas
// texels can be a region too: the rectangles only bound where the GPU pass
// draws (every cell lies in exactly one of them).
class BrushRegion {
public:
    struct Cell {
        std::uint32_t index; // y * width + x
        float weight;
    };

    BrushRegion() = default;
    // Cells whose distance from (centreX, centreY) (in cells: cell (x, y) is
    // at (x, y)) is at most `radius`. Periodic edges wrap the disc around;
    // clamped edges cut it. falloff in [0, 1]: the outer fraction of the
    // radius ramps the weight linearly down to 0 at the rim (0: a hard disc).
    // Throws InputError for a negative or non-finite radius or falloff.
    static BrushRegion disc(const Domain& domain, float centreX, float centreY, float radius,
                            float falloff = 0.0f);
    // Any set of cells of the grid (weights in (0, 1]; a cell at most once),
    // bounded by one rectangle.
    static BrushRegion fromCells(const Domain& domain, std::vector<Cell> cells);

    const std::vector<Cell>& cells() const { return m_cells; } // ascending index
    const std::vector<CellRect>& rects() const { return m_rects; }
    int gridWidth() const { return m_gridWidth; }
    int gridHeight() const { return m_gridHeight; }
    bool empty() const { return m_cells.empty(); }

private:
    std::vector<Cell> m_cells;
    std::vector<CellRect> m_rects;
    int m_gridWidth = 0, m_gridHeight = 0;
};

// One brush write. Chemical writes are clamped to the chemical's limits, as
// a step would. Add, Remove, Set and Randomise change one chemical; Hold and
// Release change the frozen mask (a cascade stage's setFrozen replaces it);
// Paint creates the parameter's map on first use, filled with its current
// value.
struct Brush {
    BrushMode mode = BrushMode::Add;
    BrushRegion region;
    int chemical = 0;
    float value = 0.0f;
    std::string param;      // Paint
    std::uint64_t seed = 0; // Randomise
};

// Throws InputError naming the field and what is accepted: a chemical or
// parameter the model lacks, a non-finite value, a painted value outside
// the parameter's range, a region for another grid size.
void checkBrush(const Brush& brush, const ReactionModel& model, const Domain& domain);

// Randomise's noise at a cell, in [-1, 1): a pure function of seed and cell.
float brushNoise(std::uint64_t seed, std::uint32_t cell);

// What a chemical brush leaves in a cell holding c (the CPU backend's
// formula; glsl/brush.frag computes the same), clamped to [lo, hi].
float brushChemical(BrushMode mode, float c, float weight, float value, float noise, float lo,
                    float hi);

// A painted parameter's new value at a cell holding v.
inline float blend(float v, float target, float weight) {
    return v * (1.0f - weight) + target * weight; // weight 1 gives target exactly
}

// The step constants once parameter `name` has a map (filled with its value
// in k, which the session records as a constant map); maps k already has
// keep their painted values, and dt and parameter values stay those of k.
// Throws InputError where the backends cannot vary it per cell (a fifth map;
// a diffusion rate under the semi-implicit integrator).
StepConstants withParamMap(Session& session, const StepConstants& k, const std::string& name);

// The index of parameter `name` in k.mappedParams, or -1.
int mappedIndex(const StepConstants& k, const ReactionModel& model, const std::string& name);

} // namespace morphogen
