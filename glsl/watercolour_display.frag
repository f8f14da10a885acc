// The "watercolour" colour map on the GPU: the watercolour model's pigments
// painted on its paper, the twin of paintWatercolourRow
// (app/core/output/watercolour_paint.cpp) line for line.
// uState0 = (w, p1, p2, s), uState1 = (d1, d2, g); uNear and uWide the
// wet-area mask's two blurs (glsl/wet_edge_blur.frag): deposits are darkened
// by 1 + uEdgeDarkening max(0, near - wide), uEdgeDarkening the map's
// edge_darkening over WatercolourEdges::crispPeak.

uniform sampler2D uState0;
uniform sampler2D uState1;
uniform vec3 uPaper;
uniform vec3 uAbsorbance[2];
uniform float uWetShare;
uniform float uSheen;
uniform float uGrain;
uniform sampler2D uNear;
uniform sampler2D uWide;
uniform float uEdgeDarkening;

layout(location = 0) out vec4 outColour;

void main() {
    vec4 a = texelFetch(uState0, ivec2(gl_FragCoord.xy), 0);
    vec4 b = texelFetch(uState1, ivec2(gl_FragCoord.xy), 0);
    float band = max(0.0, texelFetch(uNear, ivec2(gl_FragCoord.xy), 0).x -
                          texelFetch(uWide, ivec2(gl_FragCoord.xy), 0).x);
    float rim = 1.0 + uEdgeDarkening * band;
    float tint = 1.0 - uGrain * (a.w - 0.5) - uSheen * clamp(a.x, 0.0, 1.0);
    vec3 optical = uAbsorbance[0] * max(0.0, b.x * rim + uWetShare * a.y) +
                   uAbsorbance[1] * max(0.0, b.y * rim + uWetShare * a.z);
    vec3 v = uPaper * tint * exp(-optical);
    bvec3 bad = bvec3(isnan(v.x) || isinf(v.x), isnan(v.y) || isinf(v.y), isnan(v.z) || isinf(v.z));
    outColour = vec4(mix(clamp(v, 0.0, 1.0), vec3(0.0), bad), 1.0);
}
