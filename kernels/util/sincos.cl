/* Sine and cosine of angles that are known fractions of a turn, by exact argument
 * reduction and polynomials (within 1.5 ulps, tested), for the sampling warps. PoCL's
 * built-in sincos reduces its argument in an out-of-line call first (5 % of a Cornell box
 * render's profile; without it the render is 9 % faster). */

/* sin x (returned) and cos x for |x| <= pi/4, by the minimax polynomials of Cephes'
 * sinf and cosf (within 1 ulp, tested). */
static inline float sin_cos_small(float x, float* c)
{
    float x2 = x * x;
    *c = fma(fma(fma(fma(2.443315711809948e-5f, x2, -1.388731625493765e-3f), x2, 4.166664568298827e-2f), x2, -0.5f), x2,
             1.0f);
    return fma(fma(fma(-1.9515295891e-4f, x2, 8.3321608736e-3f), x2, -1.6666654611e-1f), x2 * x, x);
}

/* sin (returned) and cos of 2 pi t, for t a number of turns (|t| < 2^21): t is split
 * exactly into the nearest quarter turn q and a remainder |r| <= 1/8 turn, and the
 * quarter turn is applied by symmetry. Near every zero of sin and cos the result is then
 * accurate relative to its own size, unlike sincos(2 pi t), whose rounded argument is
 * off by up to half an ulp of 2 pi t. */
static inline float sin_cos_turns(float t, float* c)
{
    float q = rint(4.0f * t);
    float r = 4.0f * t - q; /* exact: 4t and q are within 1/2 of each other */
    /* The angle r pi/2 as a + a_lo, pi/2 split in two floats, and the polynomials
     * corrected to first order in a_lo: only their own error remains. */
    const float pio2_hi = 0x1.921fb6p0f, pio2_lo = -0x1.777a5cp-25f;
    float a = r * pio2_hi, a_lo = fma(r, pio2_hi, -a) + r * pio2_lo;
    float cs0, sn0 = sin_cos_small(a, &cs0);
    float sn = fma(cs0, a_lo, sn0), cs = fma(-sn0, a_lo, cs0);
    int k = (int)q & 3;
    *c = k == 0 ? cs : k == 1 ? -sn : k == 2 ? -cs : sn;
    return k == 0 ? sn : k == 1 ? cs : k == 2 ? -sn : -cs;
}
