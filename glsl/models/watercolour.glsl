#define REACT_ARRAYS
// Watercolour (Lo et al. 5.6). c[0] = (w, p1, p2, s): water, the two
// suspended pigments, the paper's stickiness; c[1] = (d1, d2, g): deposited
// pigments, water gone. Mirrors app/core/models/watercolour.hpp (the
// equations and their reasons are there).
void react(vec4 c[STATE_TEXTURES], out vec4 dcdt[STATE_TEXTURES]) {
    float w = c[0].x;
    float s = c[0].w;
    float r = 1.0 / (w + p_film);
    float leave = (p_evaporation + p_absorption * s) * w * r;
    float q = p_dry / (w + p_dry);
    float settleRate = s * (p_settle + p_trap * q * q);
    vec2 dep = c[0].yz * settleRate;
    dcdt[0] = vec4(-leave, -dep, 0.0);
    dcdt[1] = vec4(dep, leave, 0.0);
    for (int i = 2; i < STATE_TEXTURES; ++i)
        dcdt[i] = vec4(0.0);
}
