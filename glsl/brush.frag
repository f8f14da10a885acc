// A brush write on the chemicals: drawn over one rectangle of the region
// (viewport and scissor) from the current state into the other ping-pong
// set, whose rectangle is then copied back. Every texel is copied through
// unchanged except chemical uComponent of texture uTexture where the mask's
// weight is positive; there the formula is brushChemical's in
// app/core/sim/brush.cpp, clamped to the chemical's limits.
// The C++ side defines STATE_TEXTURES and the MODE_* numbers (BrushMode).

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

uniform sampler2D uMask; // (weight, noise) per texel of the rectangle
uniform ivec2 uRectOrigin;
uniform int uTexture;
uniform int uComponent;
uniform int uMode;
uniform float uValue;
uniform float uLo;
uniform float uHi;

layout(location = 0) out vec4 outState[STATE_TEXTURES];

float brushed(float c, float w, float noise) {
    float v = c;
    if (uMode == MODE_ADD)
        v = c + uValue * w;
    else if (uMode == MODE_REMOVE)
        v = c - uValue * w;
    else if (uMode == MODE_SET)
        v = c * (1.0 - w) + uValue * w;
    else if (uMode == MODE_RANDOMISE)
        v = c + uValue * w * noise;
    return clamp(v, uLo, uHi);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec2 mask = texelFetch(uMask, p - uRectOrigin, 0).xy;
#define BRUSH(t, state)                                                                            \
    {                                                                                              \
        vec4 s = texelFetch(state, p, 0);                                                          \
        if (t == uTexture && mask.x > 0.0)                                                         \
            s[uComponent] = brushed(s[uComponent], mask.x, mask.y);                                \
        outState[t] = s;                                                                           \
    }
    BRUSH(0, uState0)
#if STATE_TEXTURES > 1
    BRUSH(1, uState1)
#endif
#if STATE_TEXTURES > 2
    BRUSH(2, uState2)
#endif
}
