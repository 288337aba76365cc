/* The Halton sampler's radical inverse (kernels/samplers.cl) for the first n points
 * (n = the global size): out[i] = the float value, digits[i] / scale[i] = the integer
 * digit prefix it comes from (the whole value when unscrambled). */
__kernel void test_radical_inverse(uint base, uint scramble, uint seed, __global float* out,
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
