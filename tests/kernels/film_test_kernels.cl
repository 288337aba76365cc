/* Accumulates `count` samples of 0.1 + noise into film pixel 0 from one work-item,
 * through the real film code (kernels/film/film.cl), and gives the samples for the host's
 * sums. Noise: uniform in [-0.05, 0.05) from the counter-based hash. */
#include "film/film.cl"
#include "util/hash.cl"

static inline float film_test_sample(uint i)
{
    return 0.1f + (u32_to_unit_float(hash_u32(i * 2654435761u + 1u)) - 0.5f) * 0.1f;
}

PATHCL_KERNEL void test_film_accumulate(__global FilmPixel* film, __global uint* bad, uint count)
{
    for (uint i = 0; i < count; ++i) {
        float v = film_test_sample(i);
        film_add_sample(film, bad, 0u, (float3)(v, v, v));
    }
}

/* The same samples, one per work-item, for an exact host-side sum. */
PATHCL_KERNEL void test_film_samples(__global float* out)
{
    uint i = get_global_id(0);
    out[i] = film_test_sample(i);
}

PATHCL_KERNEL void test_film_rejects_non_finite(__global FilmPixel* film, __global uint* bad)
{
    film_add_sample(film, bad, 0u, (float3)(1.0f, 1.0f, 1.0f));
    film_add_sample(film, bad, 0u, (float3)(NAN, 1.0f, 1.0f));
    film_add_sample(film, bad, 0u, (float3)(1.0f, INFINITY, 1.0f));
    film_add_sample(film, bad, 0u, (float3)(1.0f, 1.0f, -INFINITY));
}
