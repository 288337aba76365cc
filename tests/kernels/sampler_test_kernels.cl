/* Test kernels over the samplers (kernels/sample/) and the warps' sine and cosine; the
 * sampler_points kernel the host reads point sets through comes with its file. */
#include "sample/halton.cl"
#include "sample/sampler.cl"
#include "sample/sampler_points.cl"
#include "sample/sobol.cl"
#include "util/math.cl"
#include "util/sincos.cl"

/* The Halton sampler's radical inverse (kernels/sample/halton.cl) for the first n points
 * (n = the global size): out[i] = the float value, digits[i] / scale[i] = the integer
 * digit prefix it comes from (the whole value when unscrambled). */
PATHCL_KERNEL void test_radical_inverse(uint base, uint scramble, uint seed, __global float* out,
                                        __global ulong* digits, __global ulong* scale)
{
    uint i = get_global_id(0), n = (uint)get_global_size(0);
    ulong r, s;
    uint rest;
    radical_inverse_digits(base, i, n, seed, scramble != 0u, &r, &s, &rest);
    out[i] = radical_inverse(base, i, n, seed, scramble != 0u);
    digits[i] = r;
    scale[i] = s;
}

/* The warps' sine and cosine: out[i] = (sin, cos) of in[i] radians (turns == 0, |x| <=
 * pi/4) or of 2 pi in[i] (turns != 0); the built-in sincos alongside for comparison. */
PATHCL_KERNEL void test_sin_cos(__global const float* in, uint turns, __global float2* out, __global float2* builtin)
{
    uint i = get_global_id(0);
    float x = in[i], c, s = turns ? sin_cos_turns(x, &c) : sin_cos_small(x, &c);
    out[i] = (float2)(s, c);
    float bc, bs = sincos(turns ? 2.0f * PI_F * x : x, &bc);
    builtin[i] = (float2)(bs, bc);
}

/* Sobol' dimension 1 in reversed bit order, for the test against its definition. */
PATHCL_KERNEL void test_sobol_dimension1(__global const uint* in, __global uint* out)
{
    uint i = get_global_id(0);
    out[i] = sobol_dimension1_reversed_u32(in[i]);
}

/* The 2D decision at `dim` of every pixel (one work-item each) through frame_sampler, as a
 * render pass draws it. */
PATHCL_KERNEL void test_frame_sampler(FrameParams frame, uint dim, __global float2* out)
{
    uint pixel = get_global_id(0);
    SamplerState s = frame_sampler(&frame, pixel, dim);
    out[pixel] = sampler_get_2d(&s);
}

/* A bounce's numbers drawn at once (sampler_bounce, from the path's sampler made at the
 * path's first dimension, as the path kernel makes it) against the same decisions drawn
 * one by one (frame_sampler), for every pixel (one work-item each), the bounce's decisions
 * starting at `start`. Per pixel, 2 * DIMS_PER_BOUNCE values each way: first the
 * decisions as a path draws them (a 2D pair at each start DIM_PAIRS_IN_BOUNCE names, 1D
 * elsewhere), then a 1D decision at every offset (a pair's second offset included, where
 * the drawn state must fall back to drawing alone); count[pixel] = how many numbers the
 * state drew at once. */
PATHCL_KERNEL void test_sampler_draw_bounce(FrameParams frame, uint start, __global float* at_once,
                                            __global float* one_by_one, __global uint* count)
{
    uint pixel = get_global_id(0);
    const SamplerState path = frame_sampler(&frame, pixel, DIM_PATH_START);
    SamplerState a = sampler_bounce(&path, start);
    SamplerState b = frame_sampler(&frame, pixel, start);
    count[pixel] = a.block_count;
    uint o = pixel * 2u * DIMS_PER_BOUNCE;
    for (uint k = 0u; k < DIMS_PER_BOUNCE; ++k) {
        a.dimension = b.dimension = start + k;
        if (DIM_PAIRS_IN_BOUNCE >> k & 1u) {
            float2 x = sampler_get_2d(&a), y = sampler_get_2d(&b);
            at_once[o + k] = x.x;
            at_once[o + k + 1u] = x.y;
            one_by_one[o + k] = y.x;
            one_by_one[o + k + 1u] = y.y;
            ++k;
        } else {
            at_once[o + k] = sampler_get_1d(&a);
            one_by_one[o + k] = sampler_get_1d(&b);
        }
    }
    for (uint k = 0u; k < DIMS_PER_BOUNCE; ++k) {
        a.dimension = b.dimension = start + k;
        at_once[o + DIMS_PER_BOUNCE + k] = sampler_get_1d(&a);
        one_by_one[o + DIMS_PER_BOUNCE + k] = sampler_get_1d(&b);
    }
}
