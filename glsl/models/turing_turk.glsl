// Turing spots as Turk 1991 writes them. c.x = a, c.y = b, c.z = beta (a
// per-cell field that never changes). Mirrors app/core/models/turing_turk.cpp.
vec4 react(vec4 c) {
    float ab = c.x * c.y;
    return vec4(p_s * (16.0 - ab), p_s * (ab - c.y - c.z), 0.0, 0.0);
}
