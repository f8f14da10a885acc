// One explicit Euler step of reaction-diffusion on a grid:
//   c' = clamp(c + dt * (react(c) + D * lap(c)), clampMin, clampMax)
// The neighbours come from textureOffset with nearest filtering, so periodic
// and clamped edges are the sampler's wrap mode (GL_REPEAT / GL_CLAMP_TO_EDGE),
// not index arithmetic. Variant: STENCIL_9 selects the 9-point Laplacian.
// react() comes from the model's snippet, compiled in front of this file.

uniform sampler2D uState;
uniform vec2 uInvSize;
uniform float uDt;
uniform vec4 uDiffusion;
uniform vec4 uClampMin;
uniform vec4 uClampMax;

out vec4 outState;

vec4 react(vec4 c);

void main() {
    vec2 uv = gl_FragCoord.xy * uInvSize;
    vec4 c = texture(uState, uv);
    vec4 sides = textureOffset(uState, uv, ivec2(-1, 0)) + textureOffset(uState, uv, ivec2(1, 0)) +
                 textureOffset(uState, uv, ivec2(0, -1)) + textureOffset(uState, uv, ivec2(0, 1));
#ifdef STENCIL_9
    vec4 corners = textureOffset(uState, uv, ivec2(-1, -1)) + textureOffset(uState, uv, ivec2(1, -1)) +
                   textureOffset(uState, uv, ivec2(-1, 1)) + textureOffset(uState, uv, ivec2(1, 1));
    vec4 lap = (4.0 * sides + corners - 20.0 * c) * (1.0 / 6.0);
#else
    vec4 lap = sides - 4.0 * c;
#endif
    outState = clamp(c + uDt * (react(c) + uDiffusion * lap), uClampMin, uClampMax);
}
