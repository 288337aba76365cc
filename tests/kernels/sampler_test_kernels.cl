/* The Halton sampler's radical inverse (kernels/samplers.cl) for the first points:
 * out[i] = the float value, digits[i] / scale[i] = the exact rational it comes from. */
__kernel void test_radical_inverse(uint base, uint scramble, uint seed, __global float* out,
                                   __global ulong* digits, __global ulong* scale)
{
    uint i = get_global_id(0);
    ulong r, s;
    radical_inverse_digits(base, i, seed, scramble != 0u, &r, &s);
    out[i] = radical_inverse(base, i, seed, scramble != 0u);
    digits[i] = r;
    scale[i] = s;
}
