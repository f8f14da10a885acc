#define REACT_ARRAYS
// Meinhardt's five-chemical stripe system (Turk 1991, appendix). Chemical i is
// component i % 4 of c[i / 4]: c[0] = (g1, g2, r, s1), c[1].x = s2,
// c[1].y = substrate (a per-cell field that never changes).
// Mirrors app/core/models/meinhardt_stripes.cpp.
void react(vec4 c[STATE_TEXTURES], out vec4 dcdt[STATE_TEXTURES]) {
    float g1 = c[0].x;
    float g2 = c[0].y;
    float r = c[0].z;
    float s1 = c[0].w;
    float s2 = c[1].x;
    float sub = c[1].y;
    float rSafe = max(r, 1e-4);
    float p1 = p_c * s2 * g1 * g1 * sub;
    float p2 = p_c * s1 * g2 * g2;
    dcdt[0] = vec4(p1 / rSafe - p_alpha * g1 + p_rho0, p2 / rSafe - p_alpha * g2 + p_rho0,
                   p1 + p2 - p_beta * r, p_gamma * (g1 - s1) + p_rho1);
    dcdt[1] = vec4(p_gamma * (g2 - s2) + p_rho1, 0.0, 0.0, 0.0);
    for (int i = 2; i < STATE_TEXTURES; ++i)
        dcdt[i] = vec4(0.0);
}
