// Witkin-Kass threshold reaction (eq. 1 and 13): both morphogens gain k
// where C+ - C- exceeds the threshold (0 in the paper), and both dissipate at
// rate b. c.x = C+ (p), c.y = C- (m).
// Mirrors app/core/models/witkin_kass.cpp.
vec4 react(vec4 c) {
    float r = c.x - c.y > p_threshold ? p_k : 0.0;
    return vec4(r - p_b * c.x, r - p_b * c.y, 0.0, 0.0);
}
