// One axis of a box blur for the watercolour map's dark edges, the twin of
// WatercolourEdges' row and column passes (app/core/output/
// watercolour_paint.cpp): the mean of the 2 uRadius + 1 texels along uAxis,
// read across the border as the session's edges do (uWrap: periodic, else
// the border texel repeats). With uMask the source is the watercolour
// state's second texture and each texel's value is the wet-area mask,
// smoothstep(uWetEdge.x, uWetEdge.y, water gone); else the source's .x.

uniform sampler2D uSource;
uniform ivec2 uAxis; // (1, 0) or (0, 1)
uniform int uRadius;
uniform int uWrap;
uniform int uMask;
uniform vec2 uWetEdge;

layout(location = 0) out vec4 outValue;

float valueAt(ivec2 q) {
    vec4 t = texelFetch(uSource, q, 0);
    return uMask != 0 ? smoothstep(uWetEdge.x, uWetEdge.y, t.z) : t.x;
}

void main() {
    ivec2 size = textureSize(uSource, 0);
    ivec2 p = ivec2(gl_FragCoord.xy);
    int n = uAxis.x != 0 ? size.x : size.y;
    int at = uAxis.x != 0 ? p.x : p.y;
    float sum = 0.0;
    for (int i = -uRadius; i <= uRadius; ++i) {
        int j = at + i;
        // (GLSL's % is undefined for a negative operand.)
        j = uWrap != 0 ? j - n * int(floor(float(j) / float(n))) : clamp(j, 0, n - 1);
        sum += valueAt(uAxis.x != 0 ? ivec2(j, p.y) : ivec2(p.x, j));
    }
    outValue = vec4(sum / float(2 * uRadius + 1), 0.0, 0.0, 1.0);
}
