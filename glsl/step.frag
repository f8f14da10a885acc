// One explicit Euler step of reaction-diffusion on a grid:
//   c' = clamp(c + dt * (react(c) + diffusion(c)), clampMin, clampMax)
// Neighbours come from textureOffset with nearest filtering, so periodic and
// clamped edges are the sampler's wrap mode (GL_REPEAT / GL_CLAMP_TO_EDGE),
// not index arithmetic. One diffusion variant is defined in C++:
//   (none)      rate * 5-point Laplacian
//   STENCIL_9   rate * 9-point Laplacian
//   KERNEL_3    a 3x3 mask per chemical (constant anisotropic tensor)
//   KERNEL_5    a 5x5 kernel per chemical (generalized diffusion)
//   TENSOR_MAP  div(A(x) grad c), A per texel from uMap, conservative form
// TILES (with any form but TENSOR_MAP) splits the grid into uTile-sized tiles,
// each periodic on its own: neighbours wrap inside the cell's tile, so tiles
// exchange nothing (a parameter sweep batched into one simulation).
// ATLAS (5- or 9-point Laplacian only) is a surface atlas of square tiles (Lo et
// al.): interior texels of a tile read their neighbours by textureOffset,
// tile-border texels read them from the connectivity map (RGBA32UI, the +x,
// +y, -x, -y neighbours packed x | y << 16) with texelFetch, and texels
// outside every tile copy through unchanged. With STENCIL_9 a border texel's
// diagonals come from uDiagonals0/1 (neighbour of neighbour, x then y and y
// then x; see core/domain/atlas_diagonals.hpp) and are averaged.
// ATLAS_WEIGHTS (with ATLAS, 5-point only) weights each texel's four links by
// uWeights (RGBA32F: the +x, +y, -x, -y coefficients, core/domain/
// atlas_weights.hpp): rate * (sum_d c_d u_d - (sum_d c_d) u), interior texels
// too, summed in the CPU's order (StepConstants::weightPlanes).
// ATLAS_CROSS (with ATLAS_WEIGHTS) adds the weights' diagonals: uCross (RGBA32F:
// the (-x,-y), (+x,-y), (-x,+y), (+x,+y) coefficients), interior texels reading
// the grid's diagonals, border texels uDiagonals0 (one order: a non-zero
// coefficient has both orders reach the same texel), in the CPU's order
// (StepConstants::diagonalPlanes).
// ATLAS_TENSOR (with ATLAS_WEIGHTS) adds anisotropy on a surface: uTensor0..3
// hold the two tensor operators' links and diagonals (AtlasTensorWeights),
// summed as the weights are, and chemical i's term is
// (uMixP S + uMixQ1 L1) + uMixQ2 L2 (StepConstants::tensorMixes, rates included).
// ATLAS_DRIFT (with ATLAS_WEIGHTS) adds water drops running down a model
// (AtlasDrift): uDriftIn (RGBA32F: the +x, +y, -x, -y inflow coefficients),
// uDriftOut (R32F: the outflow), and chemical i's term gains uDrifts[i] (1 or
// 0) times ((in-x l + in+x r) + in-y d) + in+y u - out c, after its diffusion,
// in the CPU's order (StepConstants::driftPlanes).
// The integrator is a second variant: (none) explicit Euler; RHS_PASS and
// JACOBI_PASS the two passes of a semi-implicit step.
// react() comes from the model's snippet, compiled in front of this file.
//
// The state is STATE_TEXTURES (1 to 3) RGBA textures written together
// (multiple render targets): chemical i is component i % 4 of texture i / 4.
// Every per-chemical uniform is an array with one vec4 per texture; the
// sampler of texture t is uState<t> (sampler arrays cannot be indexed by a
// loop variable in GLSL 3.30, hence FOR_EACH_STATE).

#ifndef STATE_TEXTURES
#define STATE_TEXTURES 1
#endif

uniform sampler2D uState0;
#if STATE_TEXTURES > 1
uniform sampler2D uState1;
#endif
#if STATE_TEXTURES > 2
uniform sampler2D uState2;
#endif
// FOR_EACH_STATE(X) expands X(t, state sampler, rhs sampler) per texture (the
// rhs samplers exist in JACOBI_PASS only; GLSL has no ## to paste names).
#if STATE_TEXTURES == 1
#define FOR_EACH_STATE(X) X(0, uState0, uRhs0)
#elif STATE_TEXTURES == 2
#define FOR_EACH_STATE(X) X(0, uState0, uRhs0) X(1, uState1, uRhs1)
#elif STATE_TEXTURES == 3
#define FOR_EACH_STATE(X) X(0, uState0, uRhs0) X(1, uState1, uRhs1) X(2, uState2, uRhs2)
#else
#error "STATE_TEXTURES must be 1, 2 or 3"
#endif

// STILL_TEXTURES: a bit per state texture none of whose chemicals diffuses
// or drifts (the watercolour's deposits): its diffusion term is exactly 0,
// as the CPU's fused kernels have it, and its neighbours are not fetched.
#ifndef STILL_TEXTURES
#define STILL_TEXTURES 0
#endif
#define STILL(t) (((STILL_TEXTURES >> (t)) & 1) != 0)

uniform vec2 uInvSize;
uniform float uDt;
uniform vec4 uDiffusion[STATE_TEXTURES]; // per-chemical rate (Laplacian variants)
uniform vec4 uClampMin[STATE_TEXTURES];
uniform vec4 uClampMax[STATE_TEXTURES];

#if defined(KERNEL_3) || defined(KERNEL_5)
// Weight of c(x + dx, y + dy) in texture t at t * 25 + (dy + 2) * 5 + dx + 2.
uniform vec4 uKernel[25 * STATE_TEXTURES];
#endif
#ifdef TENSOR_MAP
uniform sampler2D uMap; // (s, s cos 2theta, s sin 2theta)
// Per chemical: see DiffusionOperator in diffusion_operator.hpp.
uniform vec4 uMapM[STATE_TEXTURES];
uniform vec4 uMapDc[STATE_TEXTURES];
uniform vec4 uMapDs[STATE_TEXTURES];
#endif

#ifdef FROZEN
uniform sampler2D uFrozen; // 1 where a cell keeps its value (cascades)
#endif

layout(location = 0) out vec4 outState[STATE_TEXTURES];

void loadParams(vec2 uv);                       // generated in C++: p_<name> from uniforms or uParamMap
void rateScale(out vec4 scale[STATE_TEXTURES]); // generated: each chemical's mapped rate, or 1

// Snippets for up to four chemicals define vec4 react(vec4); the engine
// works on arrays of textures.
#ifndef REACT_ARRAYS
vec4 react(vec4 c);
void react(vec4 c[STATE_TEXTURES], out vec4 dcdt[STATE_TEXTURES]) {
    dcdt[0] = react(c[0]);
}
#endif

#ifdef TILES
uniform ivec2 uTile; // cells per tile
// The neighbour (dx, dy) of this fragment's cell, wrapped inside its tile.
// |dx|, |dy| <= 2 < uTile, so adding uTile keeps the operands of % positive.
ivec2 tileNeighbour(int dx, int dy) {
    ivec2 cell = ivec2(gl_FragCoord.xy);
    ivec2 local = cell % uTile;
    return cell - local + (local + ivec2(dx, dy) + uTile) % uTile;
}
#define AT(dx, dy) texelFetch(state, tileNeighbour(dx, dy), 0)
#else
#define AT(dx, dy) textureOffset(state, uv, ivec2(dx, dy))
#endif
#ifdef ATLAS
uniform usampler2D uConnectivity;
uniform ivec3 uAtlas; // texels per tile side, tiles per row, tile count
#ifdef ATLAS_WEIGHTS
uniform sampler2D uWeights; // +x, +y, -x, -y coefficients of this texel's links
#endif
#if defined(STENCIL_9) || defined(ATLAS_CROSS) || defined(ATLAS_TENSOR)
uniform usampler2D uDiagonals0; // (-x,-y), (+x,-y), (-x,+y), (+x,+y), reached x then y
#endif
#ifdef STENCIL_9
uniform usampler2D uDiagonals1; // the same, reached y then x
#endif
#ifdef ATLAS_CROSS
uniform sampler2D uCross; // the diagonal coefficients, uDiagonals0's order
#endif
#ifdef ATLAS_TENSOR
uniform sampler2D uTensor0; // L1's links (+x, +y, -x, -y)
uniform sampler2D uTensor1; // L1's diagonals (uDiagonals0's order)
uniform sampler2D uTensor2; // L2's links
uniform sampler2D uTensor3; // L2's diagonals
uniform vec4 uMixP[STATE_TEXTURES];
uniform vec4 uMixQ1[STATE_TEXTURES];
uniform vec4 uMixQ2[STATE_TEXTURES];
#endif
#ifdef ATLAS_DRIFT
uniform sampler2D uDriftIn;
uniform sampler2D uDriftOut;
uniform vec4 uDrifts[STATE_TEXTURES];
#endif
#ifdef DRIFT_CARRIER
// The carrier's channel of the first state texture (one-hot) and its cling
// depth: a texel passes on its amount times m(w) = w / (w + cling), w >= 0
// (StepConstants::driftCarrier; every drifting chemical is in that texture).
uniform vec4 uCarrier;
uniform float uCling;
vec4 carried(vec4 v) {
    float w = max(dot(uCarrier, v), 0.0);
    return (w / (w + uCling)) * v;
}
#endif
bool gAtlasBorder;    // this fragment's texel is on its tile's border ring
ivec2 unpackTexel(uint address) {
    return ivec2(int(address & 0xFFFFu), int(address >> 16));
}
// 0: outside every tile, 1: inside a tile, 2: on a tile's border ring.
int atlasTexel() {
    ivec2 cell = ivec2(gl_FragCoord.xy);
    ivec2 tile = cell / uAtlas.x;
    if (tile.y * uAtlas.y + tile.x >= uAtlas.z)
        return 0;
    ivec2 local = cell - tile * uAtlas.x;
    return all(greaterThan(local, ivec2(0))) && all(lessThan(local, ivec2(uAtlas.x - 1))) ? 1 : 2;
}
#endif
#define TAP(dx, dy) sum += uKernel[t * 25 + (dy + 2) * 5 + dx + 2] * AT(dx, dy)

#ifdef TENSOR_MAP
vec4 axx(int t, vec4 m) { return uMapM[t] * m.x + uMapDc[t] * m.y - uMapDs[t] * m.z; }
vec4 ayy(int t, vec4 m) { return uMapM[t] * m.x - uMapDc[t] * m.y + uMapDs[t] * m.z; }
vec4 axy(int t, vec4 m) { return -(uMapDc[t] * m.z + uMapDs[t] * m.y); }
#endif

// The diffusion term of the four chemicals in texture t (sampled by `state`).
vec4 diffusion(sampler2D state, int t, vec2 uv, vec4 c) {
#if defined(KERNEL_3) || defined(KERNEL_5)
    vec4 sum = uKernel[t * 25 + 12] * c;
    TAP(-1, -1); TAP(0, -1); TAP(1, -1);
    TAP(-1, 0);              TAP(1, 0);
    TAP(-1, 1);  TAP(0, 1);  TAP(1, 1);
#ifdef KERNEL_5
    TAP(-2, -2); TAP(-1, -2); TAP(0, -2); TAP(1, -2); TAP(2, -2);
    TAP(-2, -1);                                     TAP(2, -1);
    TAP(-2, 0);                                      TAP(2, 0);
    TAP(-2, 1);                                      TAP(2, 1);
    TAP(-2, 2);  TAP(-1, 2);  TAP(0, 2);  TAP(1, 2);  TAP(2, 2);
#endif
    return sum;
#elif defined(TENSOR_MAP)
#ifdef TILES
#error "TILES does not support TENSOR_MAP"
#endif
    vec4 l = AT(-1, 0), r = AT(1, 0), d = AT(0, -1), u = AT(0, 1);
    vec4 mc = texture(uMap, uv);
    vec4 ml = textureOffset(uMap, uv, ivec2(-1, 0)), mr = textureOffset(uMap, uv, ivec2(1, 0));
    vec4 md = textureOffset(uMap, uv, ivec2(0, -1)), mu = textureOffset(uMap, uv, ivec2(0, 1));
    // Face-averaged fluxes: the sum over a periodic grid telescopes, so mass is conserved.
    vec4 xx = 0.5 * (axx(t, mc) + axx(t, mr)) * (r - c) - 0.5 * (axx(t, mc) + axx(t, ml)) * (c - l);
    vec4 yy = 0.5 * (ayy(t, mc) + ayy(t, mu)) * (u - c) - 0.5 * (ayy(t, mc) + ayy(t, md)) * (c - d);
    vec4 ru = AT(1, 1), rd = AT(1, -1), lu = AT(-1, 1), ld = AT(-1, -1);
    vec4 xy = 0.25 * (axy(t, mr) * (ru - rd) - axy(t, ml) * (lu - ld)) +
              0.25 * (axy(t, mu) * (ru - lu) - axy(t, md) * (rd - ld));
    return xx + yy + xy;
#else
#ifdef ATLAS_WEIGHTS
    // The CPU's order: -x, +x, -y, +y, each times its link's coefficient.
    vec4 w = texelFetch(uWeights, ivec2(gl_FragCoord.xy), 0);
    vec4 l, r, d, u;
    if (gAtlasBorder) {
        uvec4 n = texelFetch(uConnectivity, ivec2(gl_FragCoord.xy), 0);
        r = texelFetch(state, unpackTexel(n.x), 0);
        u = texelFetch(state, unpackTexel(n.y), 0);
        l = texelFetch(state, unpackTexel(n.z), 0);
        d = texelFetch(state, unpackTexel(n.w), 0);
    } else {
        l = AT(-1, 0);
        r = AT(1, 0);
        d = AT(0, -1);
        u = AT(0, 1);
    }
    float wsum = ((w.z + w.x) + w.w) + w.y;
    vec4 sides = ((w.z * l + w.x * r) + w.w * d) + w.y * u;
#if defined(ATLAS_CROSS) || defined(ATLAS_TENSOR)
    vec4 mm, pm, mp, pp;
    if (gAtlasBorder) {
        uvec4 g = texelFetch(uDiagonals0, ivec2(gl_FragCoord.xy), 0);
        mm = texelFetch(state, unpackTexel(g.x), 0);
        pm = texelFetch(state, unpackTexel(g.y), 0);
        mp = texelFetch(state, unpackTexel(g.z), 0);
        pp = texelFetch(state, unpackTexel(g.w), 0);
    } else {
        mm = AT(-1, -1);
        pm = AT(1, -1);
        mp = AT(-1, 1);
        pp = AT(1, 1);
    }
#endif
#ifdef ATLAS_CROSS
    vec4 k = texelFetch(uCross, ivec2(gl_FragCoord.xy), 0);
    wsum += (k.x + k.y) + (k.z + k.w);
    sides += (k.x * mm + k.y * pm) + (k.z * mp + k.w * pp);
#endif
#ifdef ATLAS_TENSOR
    vec4 tensorTerm[2];
    for (int q = 0; q < 2; ++q) {
        ivec2 at = ivec2(gl_FragCoord.xy);
        vec4 a = q == 0 ? texelFetch(uTensor0, at, 0) : texelFetch(uTensor2, at, 0);
        vec4 b = q == 0 ? texelFetch(uTensor1, at, 0) : texelFetch(uTensor3, at, 0);
        float sum = (((a.z + a.x) + a.w) + a.y) + ((b.x + b.y) + (b.z + b.w));
        vec4 side = (((a.z * l + a.x * r) + a.w * d) + a.y * u) +
                    ((b.x * mm + b.y * pm) + (b.z * mp + b.w * pp));
        tensorTerm[q] = side - sum * c;
    }
#endif
#elif defined(ATLAS)
    // The CPU's order: -x, +x, -y, +y.
    vec4 sides;
    if (gAtlasBorder) {
        uvec4 n = texelFetch(uConnectivity, ivec2(gl_FragCoord.xy), 0);
        sides = texelFetch(state, unpackTexel(n.z), 0) + texelFetch(state, unpackTexel(n.x), 0) +
                texelFetch(state, unpackTexel(n.w), 0) + texelFetch(state, unpackTexel(n.y), 0);
    } else {
        sides = AT(-1, 0) + AT(1, 0) + AT(0, -1) + AT(0, 1);
    }
#else
    vec4 sides = AT(-1, 0) + AT(1, 0) + AT(0, -1) + AT(0, 1);
#endif
#ifdef STENCIL_9
#ifdef ATLAS
    vec4 corners;
    if (gAtlasBorder) {
        ivec2 cell = ivec2(gl_FragCoord.xy);
        uvec4 a = texelFetch(uDiagonals0, cell, 0), b = texelFetch(uDiagonals1, cell, 0);
#define DIAGONAL(i)                                                                                \
    0.5 * (texelFetch(state, unpackTexel(a.i), 0) + texelFetch(state, unpackTexel(b.i), 0))
        corners = DIAGONAL(x) + DIAGONAL(y) + DIAGONAL(z) + DIAGONAL(w);
#undef DIAGONAL
    } else {
        corners = AT(-1, -1) + AT(1, -1) + AT(-1, 1) + AT(1, 1);
    }
#else
    vec4 corners = AT(-1, -1) + AT(1, -1) + AT(-1, 1) + AT(1, 1);
#endif
    return uDiffusion[t] * ((4.0 * sides + corners - 20.0 * c) * (1.0 / 6.0));
#elif defined(ATLAS_TENSOR)
    return (uMixP[t] * (sides - wsum * c) + uMixQ1[t] * tensorTerm[0]) + uMixQ2[t] * tensorTerm[1];
#elif defined(ATLAS_DRIFT)
    vec4 din = texelFetch(uDriftIn, ivec2(gl_FragCoord.xy), 0);
    float dout = texelFetch(uDriftOut, ivec2(gl_FragCoord.xy), 0).x;
#ifdef DRIFT_CARRIER
    // Texture 0 holds the carrier; nothing drifts in the others (uDrifts 0).
    vec4 drift = (((din.z * carried(l) + din.x * carried(r)) + din.w * carried(d)) +
                  din.y * carried(u)) - dout * carried(c);
#else
    vec4 drift = (((din.z * l + din.x * r) + din.w * d) + din.y * u) - dout * c;
#endif
    return uDiffusion[t] * (sides - wsum * c) + uDrifts[t] * drift;
#elif defined(ATLAS_WEIGHTS)
    return uDiffusion[t] * (sides - wsum * c);
#else
    return uDiffusion[t] * (sides - 4.0 * c);
#endif
#endif
}

#define LOAD_STATE(t, state, rhs) c[t] = texture(state, uv);
#define COPY_STATE(t, state, rhs) outState[t] = texture(state, uv);

// Frozen cells copy their value through, bit for bit.
#ifdef FROZEN
#define KEEP_FROZEN(uv)                                                                            \
    if (texture(uFrozen, uv).x > 0.5) {                                                            \
        FOR_EACH_STATE(COPY_STATE)                                                                 \
        return;                                                                                    \
    }
#else
#define KEEP_FROZEN(uv)
#endif

// Atlas texels outside every tile copy through; the rest note whether they are
// on a tile border.
#ifdef ATLAS
#define ATLAS_TEXEL(uv)                                                                            \
    {                                                                                              \
        int kind = atlasTexel();                                                                   \
        if (kind == 0) {                                                                           \
            FOR_EACH_STATE(COPY_STATE)                                                             \
            return;                                                                                \
        }                                                                                          \
        gAtlasBorder = kind == 2;                                                                  \
    }
#else
#define ATLAS_TEXEL(uv)
#endif

#if defined(RHS_PASS)
// Semi-implicit, first pass: the right-hand side c + dt f(c).
void main() {
    vec2 uv = gl_FragCoord.xy * uInvSize;
    loadParams(uv);
    vec4 c[STATE_TEXTURES];
    FOR_EACH_STATE(LOAD_STATE)
    vec4 f[STATE_TEXTURES];
    react(c, f);
#define RHS(t, state, rhs) outState[t] = c[t] + uDt * f[t];
    FOR_EACH_STATE(RHS)
}
#elif defined(JACOBI_PASS)
// Semi-implicit, one relaxation sweep on (I - dt A) x = rhs: uState<t> holds
// the current iterate, uRhs<t> the right-hand side; uOmega is each chemical's
// Richardson weight, chosen from the kernel's symbol (Jacobi's for the
// Laplacians). On a weighted atlas, which has no symbol, each texel takes
// Jacobi's own, 1 / (1 + dt r S) with S its weight sum: the sweep is then the
// CPU's (rhs + dt r sides) / (1 + dt r S), up to rounding.
uniform sampler2D uRhs0;
#if STATE_TEXTURES > 1
uniform sampler2D uRhs1;
#endif
#if STATE_TEXTURES > 2
uniform sampler2D uRhs2;
#endif
uniform vec4 uOmega[STATE_TEXTURES];
// 1 for the chemicals this pass relaxes, 0 for those carried unchanged
// (their passes done: chemicalRelaxationPasses).
uniform vec4 uRelaxing[STATE_TEXTURES];
#ifdef ATLAS_WEIGHTS
// This texel's links and diagonals summed (the diffusion term's S).
float weightSum() {
    vec4 w = texelFetch(uWeights, ivec2(gl_FragCoord.xy), 0);
    float sum = ((w.z + w.x) + w.w) + w.y;
#ifdef ATLAS_CROSS
    vec4 k = texelFetch(uCross, ivec2(gl_FragCoord.xy), 0);
    sum += (k.x + k.y) + (k.z + k.w);
#endif
    return sum;
}
#define OMEGA(t) (1.0 / (1.0 + uDt * scale[t] * uDiffusion[t] * gWeightSum))
#else
#define OMEGA(t) uOmega[t]
#endif
void main() {
    vec2 uv = gl_FragCoord.xy * uInvSize;
    KEEP_FROZEN(uv)
    ATLAS_TEXEL(uv)
    loadParams(uv);
    vec4 scale[STATE_TEXTURES];
    rateScale(scale);
#ifdef ATLAS_WEIGHTS
    float gWeightSum = weightSum();
#endif
#define SWEEP(t, state, rhs)                                                                          \
    {                                                                                              \
        vec4 x = texture(state, uv);                                                               \
        vec4 swept = clamp(x + OMEGA(t) * (texture(rhs, uv) - x +                                   \
                                          uDt * scale[t] *                                         \
                                              (STILL(t) ? vec4(0.0) : diffusion(state, t, uv, x))), \
                           uClampMin[t], uClampMax[t]);                                            \
        outState[t] = mix(x, swept, greaterThan(uRelaxing[t], vec4(0.5)));                         \
    }
    FOR_EACH_STATE(SWEEP)
}
#else
void main() {
    vec2 uv = gl_FragCoord.xy * uInvSize;
    KEEP_FROZEN(uv)
    ATLAS_TEXEL(uv)
    loadParams(uv);
    vec4 c[STATE_TEXTURES];
    FOR_EACH_STATE(LOAD_STATE)
    vec4 f[STATE_TEXTURES];
    react(c, f);
    vec4 scale[STATE_TEXTURES];
    rateScale(scale);
#define STEP(t, state, rhs)                                                                          \
    outState[t] = clamp(c[t] + uDt * (f[t] + scale[t] * (STILL(t) ? vec4(0.0)                     \
                                                                   : diffusion(state, t, uv, c[t]))), \
                        uClampMin[t], uClampMax[t]);
    FOR_EACH_STATE(STEP)
}
#endif
