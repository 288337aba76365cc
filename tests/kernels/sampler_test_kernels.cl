/* Test kernels over the samplers (kernels/sample/) and the warps' sine and cosine; the
 * sampler_points kernel the host reads point sets through comes with its file. */
#include "sample/halton.cl"
#include "sample/sampler_points.cl"
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
