// Gray-Scott (McGraw eq. 3-4). c.x = u, c.y = v. Mirrors app/core/models/gray_scott.cpp.
vec4 react(vec4 c) {
    float uvv = c.x * c.y * c.y;
    return vec4(-uvv + p_F * (1.0 - c.x), uvv - (p_F + p_k) * c.y, 0.0, 0.0);
}
