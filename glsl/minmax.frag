// One level of the display's min-max reduction: each output texel holds the
// (min, max) of a 4 x 4 block of the source, skipping texels past the
// source's edge. FIRST reads component uComponent of a state texture and
// skips non-finite values (as applyColormap does); later levels read the
// previous level's (min, max) pairs. A block with no finite value gives
// (+inf, -inf), which min and max pass over.

uniform sampler2D uSource;
uniform ivec2 uSourceSize;
#ifdef FIRST
uniform int uComponent;
#endif

layout(location = 0) out vec4 outMinMax;

void main() {
    const float infinity = uintBitsToFloat(0x7f800000u);
    float lo = infinity, hi = -infinity;
    ivec2 base = ivec2(gl_FragCoord.xy) * 4;
    for (int dy = 0; dy < 4; ++dy)
        for (int dx = 0; dx < 4; ++dx) {
            ivec2 p = base + ivec2(dx, dy);
            if (p.x >= uSourceSize.x || p.y >= uSourceSize.y)
                continue;
#ifdef FIRST
            float v = texelFetch(uSource, p, 0)[uComponent];
            if (isnan(v) || isinf(v))
                continue;
            lo = min(lo, v);
            hi = max(hi, v);
#else
            vec2 m = texelFetch(uSource, p, 0).xy;
            lo = min(lo, m.x);
            hi = max(hi, m.y);
#endif
        }
    outMinMax = vec4(lo, hi, 0.0, 0.0);
}
