// Colour-maps one chemical into the display texture, the GPU twin of
// applyColormap (app/core/output/colormap.cpp) line for line: min-max
// normalisation from the reduction's final (min, max) texel, a flat field to
// the low end, the levels window, then the map's anchors interpolated
// piecewise linearly (grey and two-colour are two-anchor maps).

uniform sampler2D uState;
uniform int uComponent;
uniform sampler2D uMinMax;               // 1 x 1: (min, max) of the finite values
uniform vec2 uLevels;                    // (low, 1 / (high - low))
uniform vec3 uAnchors[MAX_ANCHORS];
uniform int uAnchorCount;

layout(location = 0) out vec4 outColour;

void main() {
    float v = texelFetch(uState, ivec2(gl_FragCoord.xy), 0)[uComponent];
    vec2 range = texelFetch(uMinMax, ivec2(0), 0).xy;
    float lo = range.x, hi = range.y;
    float magnitude = max(1.0, max(abs(lo), abs(hi)));
    float scale = hi - lo > 1e-5 * magnitude ? 1.0 / (hi - lo) : 0.0;
    float normalised = (isnan(v) || isinf(v)) ? 0.0 : (v - lo) * scale;
    float t = clamp((normalised - uLevels.x) * uLevels.y, 0.0, 1.0);
    float x = t * float(uAnchorCount - 1);
    int i = min(int(x), uAnchorCount - 2);
    outColour = vec4(uAnchors[i] + (uAnchors[i + 1] - uAnchors[i]) * (x - float(i)), 1.0);
}
