/* Film accumulation. Each pixel keeps Neumaier-compensated float sums of L and L^2, so the
 * mean and the variance stay accurate to about one float ulp after millions of samples
 * without needing doubles on the device. A sample with a NaN or Inf component is not
 * added; it is counted in the pixel's bad-sample counter, which every render reports.
 *
 * Contraction is off: the compensation term must be computed from separately rounded
 * operations. */
#include "kernel_data.cl"

#pragma OPENCL FP_CONTRACT OFF

static inline void neumaier_add(float4* sum, float4* compensation, float4 x)
{
    float4 s = *sum;
    float4 t = s + x;
    float4 lost = select((x - t) + s, (s - t) + x, fabs(s) >= fabs(x));
    *compensation += lost;
    *sum = t;
}

static inline void film_add_sample(__global FilmPixel* film, __global uint* bad_samples, uint pixel, float3 radiance)
{
    if (!all(isfinite(radiance))) {
        bad_samples[pixel] += 1u;
        return;
    }
    FilmPixel px = film[pixel];
    float4 l = (float4)(radiance, 1.0f); /* w counts samples */
    neumaier_add(&px.sum, &px.sum_compensation, l);
    neumaier_add(&px.sum_sq, &px.sum_sq_compensation, l * l);
    film[pixel] = px;
}

/* Zeroes the film and the bad-sample counters of every pixel. */
PATHCL_KERNEL void clear_film(PATHCL_KERNEL_PARAMS FrameParams frame)
{
    PATHCL_KERNEL_DATA;
    uint i = get_global_id(0);
    if (i >= frame.width * frame.height)
        return;
    FilmPixel zero;
    zero.sum = zero.sum_compensation = zero.sum_sq = zero.sum_sq_compensation = (float4)(0.0f);
    kd.film[i] = zero;
    kd.bad_samples[i] = 0u;
}

#pragma OPENCL FP_CONTRACT ON
