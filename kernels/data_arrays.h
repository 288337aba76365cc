/* Every device array a render binds, in kernel-argument order: one list from which both
 * sides are generated, so that no buffer is bound by position anywhere (Cycles'
 * kernel/data_arrays.h). PATHCL_SCENE_ARRAYS(X) calls X(type, name) for each array the
 * host uploads once per scene (read-only on the device); PATHCL_FILM_ARRAYS(X) for each
 * array sized by the image that the kernels write.
 *
 * Device side: kernels/kernel_data.cl makes them the parameter list of every render
 * kernel (PATHCL_KERNEL_PARAMS) and the KernelData struct the code reads them through.
 * Host side: host/compile/device_arrays.h makes them the vectors of a compiled scene, the
 * buffers of a device, and the one bind call; the test fixture uses the same. An array a
 * scene does not use is uploaded as one zeroed element (OpenCL has no null buffer). */
#ifndef PATHCL_DATA_ARRAYS_H
#define PATHCL_DATA_ARRAYS_H

#define PATHCL_SCENE_ARRAYS(X)                                                                                         \
    X(BvhNode, nodes)                 /* eight-wide BVH, root first */                                                 \
    X(Triangle, triangles)            /* positions, BVH leaf order */                                                  \
    X(TriangleBlock, triangle_blocks) /* the leaves' triangles for the traversal, eight lanes */                       \
    X(TriangleShading, shading)       /* normals, material, emitter; leaf order */                                     \
    X(Instance, instances)            /* two-level BVH only: top-level leaf order */                                   \
    X(Material, materials)                                                                                             \
    X(Light, lights)                             /* sphere lights first */                                             \
    X(LightAliasEntry, light_distribution)       /* selection pmf and alias table, one per light */                    \
    X(LightTreeNode, light_tree)                 /* --light-sampler tree: the tree's nodes, root first */              \
    X(LightTreeClusterLight, light_tree_cluster) /* the lights of the tree's cluster leaves */                         \
    X(pcl_ulong, light_tree_trail)               /* per light: its binary path from the root, a bit a step */          \
    X(pcl_int, light_tree_infinite)              /* the infinite lights' indices, which the tree leaves out */         \
    X(pcl_float4, env_texels)                    /* environment radiance, width x height, top row first */             \
    X(pcl_float, env_marginal)                   /* its CDF over rows (height + 1) */                                  \
    X(pcl_float, env_conditional)                /* per row, the CDF over columns (height x (width + 1)) */            \
    X(pcl_float, layer_albedo)                   /* LAYER_* tables (closure/layer_table.h); glossy scenes only */      \
    X(pcl_uint, texels)                          /* every texture image (TEXTURE_FORMAT_*) */                          \
    X(TextureImage, texture_images)                                                                                    \
    X(TextureView, texture_views)                                                                                      \
    X(TriangleTexcoords, texcoords) /* texture-coordinate sets, leaf order */                                          \
    X(TriangleTangents, tangents)   /* normal-mapped scenes only, leaf order */                                        \
    X(TriangleColors, colors)       /* COLOR_0 scenes only, leaf order */                                              \
    X(Camera, camera)               /* one element */

#define PATHCL_FILM_ARRAYS(X)                                                                                          \
    X(Ray, rays)             /* one camera ray per pixel */                                                            \
    X(FilmPixel, film)       /* per pixel */                                                                           \
    X(pcl_uint, bad_samples) /* NaN/Inf samples rejected, per pixel */                                                 \
    X(pcl_uint, active)      /* adaptive sampling: 0 = the pixel has converged (read if frame.adaptive) */

#endif
