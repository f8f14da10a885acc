// Turing activator-substrate as McGraw writes it (eq. 2). c.x = u, c.y = v.
// Mirrors app/core/models/turing_mcgraw.cpp.
vec4 react(vec4 c) {
    float uv = c.x * c.y;
    return vec4(uv - c.x - p_alpha, p_beta - uv, 0.0, 0.0);
}
