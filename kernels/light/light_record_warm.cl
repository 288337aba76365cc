/* A light's record read ahead of its use (light_record_warm): by the megakernel's power
 * table, which picks before it traces, and by the light tree's descent, which reads the
 * records of a node's light lanes while it weighs them. */
#include "kernel_data.cl"

/* Starts light `light`'s record on its way into the cache, by reading a word of each of
 * the two cache lines it spans, so that its sample, a few hundred instructions later, does
 * not wait on memory (a 96-byte record picked from a hundred thousand is rarely cached).
 * Volatile, so that the reads stay though nothing uses them: OpenCL's prefetch() is
 * allowed to do nothing, and PoCL's does. */
static inline void light_record_warm(const KernelData* kd, int light)
{
    volatile __global const int* words = (volatile __global const int*)&kd->lights[light];
    (void)words[0];
    (void)words[sizeof(Light) / sizeof(int) - 1];
}
