// The benchmark's baseline: one fetch and one write per texel and state
// texture, the floor under any step pass on the same format, size and
// number of state textures (STATE_TEXTURES, 1 to 3, as in step.frag).
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
uniform vec2 uInvSize;
layout(location = 0) out vec4 outState[STATE_TEXTURES];

void main() {
    vec2 uv = gl_FragCoord.xy * uInvSize;
    outState[0] = texture(uState0, uv);
#if STATE_TEXTURES > 1
    outState[1] = texture(uState1, uv);
#endif
#if STATE_TEXTURES > 2
    outState[2] = texture(uState2, uv);
#endif
}
