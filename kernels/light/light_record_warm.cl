/* A light's record read ahead of its use (light_record_warm): by the megakernel's power
 * table, which picks before it traces, by the light tree's descent, which reads the
 * records of a node's light lanes while it weighs them, and for the light sample the
 * megakernel defers past the next traversal (integrator/direct_light.cl). */
#include "kernel_data.cl"
#include "util/prefetch.cl"

/* Starts light `light`'s record on its way into the cache, both cache lines it spans (its
 * first and last words), so that its sample, a few hundred instructions later, does not
 * wait on memory (a 96-byte record picked from a hundred thousand is rarely cached). */
static inline void light_record_warm(const KernelData* kd, int light)
{
    __global const int* words = (__global const int*)&kd->lights[light];
    cache_line_warm(words);
    cache_line_warm(words + sizeof(Light) / sizeof(int) - 1);
}
