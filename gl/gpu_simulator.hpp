#pragma once

#include <array>

#include "core/sim/simulator.hpp"
#include "gl/objects.hpp"

namespace morphogen::gl {

// Texture units of the step programs. State texture t is sampled from
// kStateUnits[t], the semi-implicit right-hand side's from kRhsUnits[t].
constexpr int kStateUnits[] = {0, 5, 6};
constexpr int kRhsUnits[] = {2, 7, 8};
constexpr int kMapUnit = 1;
constexpr int kParamMapUnit = 3;
constexpr int kFrozenUnit = 4;
constexpr int kConnectivityUnit = 9;       // atlas domains: the RGBA32UI connectivity map
constexpr int kDiagonalUnits[] = {10, 11}; // 9-point on an atlas: diagonals, both orders
constexpr int kBrushMaskUnit = 12;         // brush passes: the region's weights and noise
constexpr int kWeightsUnit = 13;           // weighted atlases: 4 coefficients per texel (RGBA32F)
constexpr int kCrossUnit = 14; // weights with diagonals: 4 diagonal coefficients (RGBA32F)
// Anisotropy on an atlas (AtlasTensorWeights: L1's links, diagonals, L2's): the
// units of the diffusion map and the semi-implicit right-hand sides, which an
// atlas never has (StepConstants refuses both there), so the step program stays
// within OpenGL 3.3's 16 units.
constexpr int kTensorUnits[] = {1, 2, 7, 8};
// Drops on a model (AtlasDrift: inflow RGBA32F, outflow R32F): the last free
// unit and the diffusion map's (StepConstants refuses drift with anisotropy).
constexpr int kDriftUnits[] = {15, 1};

// Two sets of `count` same-size float textures, each set behind one
// framebuffer (multiple render targets); each pass samples the current set
// through a program and draws into the other, then swaps.
class PingPong {
public:
    PingPong() = default;
    PingPong(int width, int height, GLenum internalFormat, GLenum wrap, int count = 1);
    void run(const Program& program, int passes);
    // One pass of `program` over rect only (viewport and scissor) into the
    // other set, whose rect is then copied back into the current one: the
    // current set changes in rect alone (gpu_brush.cpp).
    void runRect(const Program& program, const CellRect& rect);
    // `passes` passes of `program` drawing `rects` only (viewport and scissor
    // per rect); outside them both sets keep the current set's values (the
    // other set is made a copy of the current one first when it may differ),
    // so nothing outside changes however many passes run. Localized runs.
    void runRects(const Program& program, int passes, const std::vector<CellRect>& rects);
    int count() const { return int(m_textures[0].size()); }
    Texture2D& current(int t = 0) { return m_textures[std::size_t(m_current)][std::size_t(t)]; }
    const Texture2D& current(int t = 0) const {
        return m_textures[std::size_t(m_current)][std::size_t(t)];
    }
    // Binds the current set to kStateUnits.
    void bindCurrent() const;
    const VertexArray& vertexArray() const { return m_vao; }
    // Call after writing the current set from outside (uploads).
    void currentChanged() { m_otherMatches = false; }

private:
    VertexArray m_vao;
    std::array<std::vector<Texture2D>, 2> m_textures;
    std::array<Framebuffer, 2> m_framebuffers;
    int m_current = 0;
    int m_width = 0, m_height = 0;
    // runRects: whether the other set holds the current set's values (false
    // after any pass or upload that changes the current set alone).
    bool m_otherMatches = false;
};

// The state texture format for a model: RG32F for up to two chemicals (half
// the bandwidth), RGBA32F for more.
GLenum stateFormat(int chemicals);

// State textures a model needs: four chemicals per texture.
int stateTextures(int chemicals);

// A bit per state texture whose step skips the diffusion term (step.frag's
// STILL_TEXTURES): none of its chemicals has a rate or drifts, under a
// Laplacian operator. The watercolour's deposits (texture 1) are the case
// it is for: their neighbours were fetched and multiplied by 0.
int stillTextures(const StepConstants& k);

// The product backend: FBO ping-pong over float state textures (several,
// written together, for models with more than four chemicals). The
// step program is assembled from glsl/fullscreen.vert, the model's reaction
// snippet (glsl/models/NAME.glsl) and glsl/step.frag, with the diffusion
// operator's form as a #define variant; parameters are uniforms and edges are the sampler's wrap
// mode (on a tiled grid each tile wraps on its own: the TILES variant). run() issues
// draws only: nothing is read back until state(). Brush writes draw over the region's rectangles
// (gpu_brush.cpp). Needs a current context for its whole life.
class GpuSimulator : public Simulator {
public:
    explicit GpuSimulator(const Session& session);

    std::string backendName() const override { return "gpu"; }
    void setState(const State& state) override;
    State state() const override; // read back a band of rows at a time
    std::optional<std::string> insaneValue(const ReactionModel& model) const override;
    void run(int steps) override;
    void setFrozen(const std::vector<std::uint8_t>& frozen) override;
    void applyBrush(const Brush& brush) override; // gpu_brush.cpp
    void setActiveTiles(const std::vector<int>& tiles) override;

    // The current state texture t (chemicals 4t..4t+3), for passes that read
    // the state where it lives (display, brushes) instead of reading it back.
    const Texture2D& stateTexture(int t) const { return m_pingPong.current(t); }
    int stateTextureCount() const { return m_pingPong.count(); }

    // Step programs compiled so far (tests check that live changes compile none).
    int programBuilds() const { return m_programBuilds; }

private:
    // Compiles glsl/step.frag with the operator's variant plus `pass`, and
    // sets the uniforms every variant shares.
    Program buildProgram(const char* pass) const;
    void buildPrograms();
    void bindAuxiliaryTextures() const;
    // A semi-implicit step's relaxation passes, after its right-hand side
    // (in the active tiles' rectangles only when `local`), `own[c]` of them
    // for chemical c.
    void relax(bool local, const std::array<int, kMaxChemicals>& own);
    // gpu_brush.cpp: the brush modes by what they write.
    void brushChemical(const Brush& brush);
    void brushFrozen(const Brush& brush);
    void brushParamMap(const Brush& brush);
    // State read-backs a band of rows at a time: readBand fills `band` (full
    // rows from y0) through `texels`; forEachBand calls fn(y0, band) top to
    // bottom.
    void readBand(int y0, State& band, std::vector<float>& texels) const;
    template <class Fn> void forEachBand(const Fn& fn) const;

    Session m_session;
    const ReactionModel* m_model;
    StepConstants m_k;
    Program m_program; // explicit step, or the Jacobi sweep
    PingPong m_pingPong;
    Texture2D m_map; // TensorMap operators only
    // SemiImplicit: the right-hand-side pass and its target.
    Program m_rhsProgram;
    std::vector<Texture2D> m_rhs;
    Framebuffer m_rhsFramebuffer;
    Texture2D m_paramMap;     // param_maps: up to 4 parameters per cell
    Texture2D m_frozen;       // cascades: 255 where a cell is frozen (GL_R8)
    Texture2D m_connectivity; // atlas domains: 4 neighbours per texel, x | y << 16
    Texture2D m_diagonals[2]; // 9-point on an atlas: the diagonals, x then y / y then x
    Texture2D m_weights;      // weighted atlases: +x, +y, -x, -y coefficients per texel
    Texture2D m_cross;        // weights with diagonals: their 4 coefficients per texel
    Texture2D m_tensor[4];    // anisotropy: AtlasTensorWeights as tensorTexels
    Texture2D m_drift[2];     // drops on a model: AtlasDrift's inflow and outflow
    std::vector<std::uint8_t> m_frozenMask;
    Program m_brushProgram; // built on the first chemical brush
    // Localized runs: the active tiles' rectangles (runs of consecutive tiles
    // in a row of the atlas merged); empty: the whole texture.
    std::vector<CellRect> m_activeRects;

    // The uniforms a live change alters (dt, parameters, rates, kernels, map
    // coefficients) on one step program, and the semi-implicit weights.
    void setLiveUniforms(const Program& program) const;
    void updateLiveUniforms();
    const Session& liveSession() const override { return m_session; }
    const StepConstants& stepConstants() const override { return m_k; }
    void applyLiveChange(Session next) override;
    mutable int m_programBuilds = 0;
};

// The shader pieces of a model's step program (also used by the agreement
// test of the GLSL and C++ reactions).
std::vector<ShaderPiece> stepFragmentPieces(const ReactionModel& model, const StepConstants& k);

} // namespace morphogen::gl
