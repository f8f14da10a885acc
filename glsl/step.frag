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
// The integrator is a second variant: (none) explicit Euler; RHS_PASS and
// JACOBI_PASS the two passes of a semi-implicit step.
// react() comes from the model's snippet, compiled in front of this file.
// Every vec4 holds up to four chemicals, one per component.

uniform sampler2D uState;
uniform vec2 uInvSize;
uniform float uDt;
uniform vec4 uDiffusion; // per-chemical rate (Laplacian variants)
uniform vec4 uClampMin;
uniform vec4 uClampMax;

#if defined(KERNEL_3) || defined(KERNEL_5)
uniform vec4 uKernel[25]; // weight of c(x + dx, y + dy) at (dy + 2) * 5 + dx + 2
#endif
#ifdef TENSOR_MAP
uniform sampler2D uMap; // (s, s cos 2theta, s sin 2theta)
uniform vec4 uMapM;     // per chemical: see DiffusionOperator in diffusion_operator.hpp
uniform vec4 uMapDc;
uniform vec4 uMapDs;
#endif

#ifdef FROZEN
uniform sampler2D uFrozen; // 1 where a cell keeps its value (cascades)
#endif

out vec4 outState;

vec4 react(vec4 c);
void loadParams(vec2 uv); // generated in C++: p_<name> from uniforms or uParamMap
vec4 rateScale();         // generated: per-chemical diffusion rate of this cell, or 1

#ifdef TILES
uniform ivec2 uTile; // cells per tile
// The neighbour (dx, dy) of this fragment's cell, wrapped inside its tile.
// |dx|, |dy| <= 2 < uTile, so adding uTile keeps the operands of % positive.
ivec2 tileNeighbour(int dx, int dy) {
    ivec2 cell = ivec2(gl_FragCoord.xy);
    ivec2 local = cell % uTile;
    return cell - local + (local + ivec2(dx, dy) + uTile) % uTile;
}
#define AT(dx, dy) texelFetch(uState, tileNeighbour(dx, dy), 0)
#else
#define AT(dx, dy) textureOffset(uState, uv, ivec2(dx, dy))
#endif
#define TAP(dx, dy) sum += uKernel[(dy + 2) * 5 + dx + 2] * AT(dx, dy)

#ifdef TENSOR_MAP
vec4 axx(vec4 m) { return uMapM * m.x + uMapDc * m.y - uMapDs * m.z; }
vec4 ayy(vec4 m) { return uMapM * m.x - uMapDc * m.y + uMapDs * m.z; }
vec4 axy(vec4 m) { return -(uMapDc * m.z + uMapDs * m.y); }
#endif

vec4 diffusion(vec2 uv, vec4 c) {
#if defined(KERNEL_3) || defined(KERNEL_5)
    vec4 sum = uKernel[12] * c;
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
    vec4 xx = 0.5 * (axx(mc) + axx(mr)) * (r - c) - 0.5 * (axx(mc) + axx(ml)) * (c - l);
    vec4 yy = 0.5 * (ayy(mc) + ayy(mu)) * (u - c) - 0.5 * (ayy(mc) + ayy(md)) * (c - d);
    vec4 ru = AT(1, 1), rd = AT(1, -1), lu = AT(-1, 1), ld = AT(-1, -1);
    vec4 xy = 0.25 * (axy(mr) * (ru - rd) - axy(ml) * (lu - ld)) +
              0.25 * (axy(mu) * (ru - lu) - axy(md) * (rd - ld));
    return xx + yy + xy;
#else
    vec4 sides = AT(-1, 0) + AT(1, 0) + AT(0, -1) + AT(0, 1);
#ifdef STENCIL_9
    vec4 corners = AT(-1, -1) + AT(1, -1) + AT(-1, 1) + AT(1, 1);
    return uDiffusion * ((4.0 * sides + corners - 20.0 * c) * (1.0 / 6.0));
#else
    return uDiffusion * (sides - 4.0 * c);
#endif
#endif
}

// Frozen cells copy their value through, bit for bit.
#ifdef FROZEN
#define KEEP_FROZEN(uv)                                                                            \
    if (texture(uFrozen, uv).x > 0.5) {                                                            \
        outState = texture(uState, uv);                                                            \
        return;                                                                                    \
    }
#else
#define KEEP_FROZEN(uv)
#endif

#if defined(RHS_PASS)
// Semi-implicit, first pass: the right-hand side c + dt f(c).
void main() {
    vec2 uv = gl_FragCoord.xy * uInvSize;
    loadParams(uv);
    vec4 c = texture(uState, uv);
    outState = c + uDt * react(c);
}
#elif defined(JACOBI_PASS)
// Semi-implicit, one relaxation sweep on (I - dt A) x = rhs: uState holds the
// current iterate; uOmega is each chemical's Richardson weight, chosen from
// the kernel's symbol (Jacobi's for the Laplacians).
uniform sampler2D uRhs;
uniform vec4 uOmega;
void main() {
    vec2 uv = gl_FragCoord.xy * uInvSize;
    KEEP_FROZEN(uv)
    loadParams(uv);
    vec4 x = texture(uState, uv);
    outState = clamp(x + uOmega * (texture(uRhs, uv) - x + uDt * rateScale() * diffusion(uv, x)),
                     uClampMin, uClampMax);
}
#else
void main() {
    vec2 uv = gl_FragCoord.xy * uInvSize;
    KEEP_FROZEN(uv)
    loadParams(uv);
    vec4 c = texture(uState, uv);
    outState = clamp(c + uDt * (react(c) + rateScale() * diffusion(uv, c)), uClampMin, uClampMax);
}
#endif
