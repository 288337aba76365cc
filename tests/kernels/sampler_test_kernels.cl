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
__kernel void test_radical_inverse(uint base, uint scramble, uint seed, __global float* out, __global ulong* digits,
                                   __global ulong* scale)
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
__kernel void test_sin_cos(__global const float* in, uint turns, __global float2* out, __global float2* builtin)
{
    uint i = get_global_id(0);
    float x = in[i], c, s = turns ? sin_cos_turns(x, &c) : sin_cos_small(x, &c);
    out[i] = (float2)(s, c);
    float bc, bs = sincos(turns ? 2.0f * PI_F * x : x, &bc);
    builtin[i] = (float2)(bs, bc);
}

/* Sobol' dimension 1 in reversed bit order, for the test against its definition. */
__kernel void test_sobol_dimension1(__global const uint* in, __global uint* out)
{
    uint i = get_global_id(0);
    out[i] = sobol_dimension1_reversed_u32(in[i]);
}

/* The 2D decision at `dim` of every pixel (one work-item each) through frame_sampler, as a
 * render pass draws it. */
__kernel void test_frame_sampler(FrameParams frame, uint dim, __global float2* out)
{
    uint pixel = get_global_id(0);
    SamplerState s = frame_sampler(&frame, pixel, dim);
    out[pixel] = sampler_get_2d(&s);
}
