#define REACT_ARRAYS
// Witkin-Kass competing orientations (section 6.3): WK_PAIRS antagonistic
// pairs, chemical 2i = C+_(i+1) (p<i+1>), chemical 2i + 1 = C-_(i+1) (m<i+1>).
// With D_i = C+_i - C-_i, every chemical gains the same R and dissipates at b:
//   WK_REACTION 0, M-D (eq. 14): R = k if max D > threshold, else 0
//   WK_REACTION 1, D-A (eq. 15): R = k if |max D| > |min D|, else 0
// WK_PAIRS and WK_REACTION come from the model's defines (one snippet serves
// witkin_kass_md2/3/5 and witkin_kass_da2/3/5).
// Mirrors WitkinKassMultiModel::Cell::react in app/core/models/witkin_kass_multi.hpp.

float wkChemical(vec4 c[STATE_TEXTURES], int i) {
    return c[i / 4][i % 4];
}

void react(vec4 c[STATE_TEXTURES], out vec4 dcdt[STATE_TEXTURES]) {
    float hi = wkChemical(c, 0) - wkChemical(c, 1);
    float lo = hi;
    for (int i = 1; i < WK_PAIRS; ++i) {
        float d = wkChemical(c, 2 * i) - wkChemical(c, 2 * i + 1);
        hi = max(hi, d);
        lo = min(lo, d);
    }
#if WK_REACTION == 0
    float r = hi > p_threshold ? p_k : 0.0;
#else
    float r = abs(hi) > abs(lo) ? p_k : 0.0;
#endif
    for (int t = 0; t < STATE_TEXTURES; ++t) {
        // Channels past the last chemical (2 * WK_PAIRS of them) stay at 0.
        vec4 used = vec4(lessThan(vec4(float(4 * t)) + vec4(0.0, 1.0, 2.0, 3.0),
                                  vec4(float(2 * WK_PAIRS))));
        dcdt[t] = used * (vec4(r) - p_b * c[t]);
    }
}
