/* A light's record read ahead of its use (light_record_warm): by the megakernel's power
 * table, which picks before it traces, by the light tree's descent, which reads the
 * records of a node's light lanes while it weighs them, and for the light sample the
 * megakernel defers past the next traversal (integrator/direct_light.cl). And the BVH leaf
 * a shadow ray towards an emissive triangle ends in, read ahead of the traversal
 * (light_shadow_leaf_warm). */
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

/* The fewest lights for which light samples warm their shadow rays' leaves: among the 768
 * lamps of tools/make_many_lights.py, and in the Cornell box, the leaves stay cached and
 * warming them made renders 1-2 % slower; among the glowing sphere's 101,762 emitters it
 * made them 8 % faster with the light tree (median of 11 interleaved rounds; 0.87-1.03x
 * the time). The same sphere of 1,600, 6,400 and 25,600 triangles moved
 * between 10 % faster and 5 % slower, the noise of the machine: the crossover lies
 * somewhere there. */
#define LIGHT_SHADOW_LEAF_WARM_MIN_LIGHTS 4096u

/* Starts the BVH leaf that a shadow ray towards a point on light `light`, an emissive
 * triangle, ends in (the node that names the leaf, and its TriangleBlock) on its way into
 * the cache, before the ray is traced: the traversal reaches that leaf last, after a
 * descent of dependent reads, and among a hundred thousand emitters the leaf is rarely
 * cached. Only where a line can be started without waiting for it (PATHCL_PREFETCH):
 * elsewhere a read would wait now instead of during the traversal. */
static inline void light_shadow_leaf_warm(const KernelData* kd, int light)
{
#ifdef PATHCL_PREFETCH
    __global const Light* l = &kd->lights[light];
    if (l->type != LIGHT_TRIANGLE)
        return;
    cache_lines_warm((__global const int*)&kd->nodes[l->leaf_node], (uint)sizeof(BvhNode));
    cache_lines_warm((__global const int*)&kd->triangle_blocks[l->leaf_block], (uint)sizeof(TriangleBlock));
#else
    (void)kd;
    (void)light;
#endif
}
