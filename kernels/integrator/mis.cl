/* How the strategies weight their two techniques (frame.strategy; docs/usage.md,
 * "Image and sampling"): emission found by a BSDF-sampled ray and a light sample, each weighted against
 * the other technique's pdf for the same direction.
 *   bsdf:       w_bsdf = 1, no light sampling;
 *   nee:        w_bsdf = 0, w_light = 1 (BSDF rays carry indirect light only);
 *   mis:        power heuristic, w = p^2 / (p_light^2 + p_bsdf^2);
 *   one-sample: a coin picks ONE technique per bounce (probability 1/2 each) and its
 *               sample is divided by the mixture pdf (p_light + p_bsdf) / 2 (Veach's
 *               one-sample model; the coin's probability is inside the mixture). */
#include "types.h"

static inline float power_heuristic(float pdf_a, float pdf_b)
{
    float a = pdf_a * pdf_a, b = pdf_b * pdf_b;
    if (isinf(a))
        return 1.0f;
    return (a + b > 0.0f) ? a / (a + b) : 0.0f;
}

/* Weight of emission found by a BSDF-sampled ray whose pdf was bsdf_pdf, where light
 * sampling would have produced the same direction with light_pdf. */
static inline float bsdf_hit_weight(uint strategy, bool technique_was_bsdf, float bsdf_pdf, float light_pdf)
{
    switch (strategy) {
    case STRATEGY_BSDF:
        return 1.0f;
    case STRATEGY_NEE:
        /* Light sampling carries this light, unless it cannot produce this direction
         * (a zero-width cell of a float CDF, say): then only the BSDF finds it. */
        return light_pdf > 0.0f ? 0.0f : 1.0f;
    case STRATEGY_ONE_SAMPLE:
        /* beta already holds f cos / p_bsdf: this turns it into f cos / p_mixture. */
        return technique_was_bsdf ? bsdf_pdf / (0.5f * (bsdf_pdf + light_pdf)) : 0.0f;
    default:
        return power_heuristic(bsdf_pdf, light_pdf);
    }
}

/* Factor applied to f cos Le of a light sample with pdfs light_pdf and bsdf_pdf
 * (0 when the strategy does not sample lights at this vertex). */
static inline float light_sample_factor(uint strategy, bool technique_is_light, float light_pdf, float bsdf_pdf)
{
    switch (strategy) {
    case STRATEGY_BSDF:
        return 0.0f;
    case STRATEGY_NEE:
        return 1.0f / light_pdf;
    case STRATEGY_ONE_SAMPLE:
        return technique_is_light ? 1.0f / (0.5f * (light_pdf + bsdf_pdf)) : 0.0f;
    default:
        return power_heuristic(light_pdf, bsdf_pdf) / light_pdf;
    }
}
