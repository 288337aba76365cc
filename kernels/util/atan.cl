/* The arctangent of y / x in all four quadrants, by reduction to [0, tan(pi/8)] and the
 * minimax polynomial of Cephes' atanf: within 2.5 ulps of the exact angle (tested).
 * PoCL's built-in atan2 is an out-of-line scalar call; the environment lookup needs two
 * per escaped ray. */

/* pi/4, pi/2 and pi as a float and the float nearest its remainder: adding the remainder
 * last keeps the reductions below from costing more than a rounding. */
#define ATAN_PI_4_HI 0x1.921fb6p-1f
#define ATAN_PI_4_LO -0x1.777a5cp-26f
#define ATAN_PI_2_HI 0x1.921fb6p0f
#define ATAN_PI_2_LO -0x1.777a5cp-25f
#define ATAN_PI_HI 0x1.921fb6p1f
#define ATAN_PI_LO -0x1.777a5cp-24f

/* atan(t) for 0 <= t <= 1 (the other octants reduce to it). */
static inline float atan_unit(float t)
{
    const float tan_pi_8 = 0.4142135623730950f;
    float x = t, base_hi = 0.0f, base_lo = 0.0f;
    if (t > tan_pi_8) { /* atan t = pi/4 + atan((t - 1) / (t + 1)) */
        x = (t - 1.0f) / (t + 1.0f);
        base_hi = ATAN_PI_4_HI;
        base_lo = ATAN_PI_4_LO;
    }
    float z = x * x;
    float p = (((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z - 3.33329491539e-1f) * z;
    return base_hi + ((p * x + base_lo) + x);
}

/* The angle of the point (x, y), as atan2(y, x) (signed zeros as IEEE 754 has them). */
static inline float atan2_fast(float y, float x)
{
    float ax = fabs(x), ay = fabs(y);
    float a = 0.0f;
    if (ay <= ax && ax > 0.0f)
        a = atan_unit(ay / ax);
    else if (ay > ax) /* pi/2 - atan(x / y) */
        a = ATAN_PI_2_HI + (ATAN_PI_2_LO - atan_unit(ax / ay));
    if (signbit(x)) /* the left half-plane: pi - a */
        a = ATAN_PI_HI + (ATAN_PI_LO - a);
    return copysign(a, y);
}
