/* The device arrays as the kernels see them: every render kernel takes the same parameter
 * list, generated from kernels/data_arrays.h, and reads the arrays through one KernelData
 * (Cycles' KernelGlobals), so no function takes a long list of buffers and the host binds
 * every kernel the same way.
 *
 *   PATHCL_KERNEL void k(PATHCL_KERNEL_PARAMS FrameParams frame)
 *   {
 *       PATHCL_KERNEL_DATA; // declares KernelData kd, filled from the parameters
 *       ... kd.lights[i] ...
 */
#include "data_arrays.h"
#include "types.h"

typedef struct {
#define PATHCL_SCENE_MEMBER(type, name) __global const type* name;
#define PATHCL_FILM_MEMBER(type, name) __global type* name;
    PATHCL_SCENE_ARRAYS(PATHCL_SCENE_MEMBER)
    PATHCL_FILM_ARRAYS(PATHCL_FILM_MEMBER)
#undef PATHCL_SCENE_MEMBER
#undef PATHCL_FILM_MEMBER
} KernelData;

/* The parameter list (each entry ends in a comma: the kernel's own parameters follow). */
#define PATHCL_SCENE_PARAM(type, name) __global const type *name,
#define PATHCL_FILM_PARAM(type, name) __global type *name,
#define PATHCL_KERNEL_PARAMS PATHCL_SCENE_ARRAYS(PATHCL_SCENE_PARAM) PATHCL_FILM_ARRAYS(PATHCL_FILM_PARAM)

#define PATHCL_DATA_ASSIGN(type, name) kd.name = name;
#define PATHCL_KERNEL_DATA                                                                                             \
    KernelData kd;                                                                                                     \
    PATHCL_SCENE_ARRAYS(PATHCL_DATA_ASSIGN)                                                                            \
    PATHCL_FILM_ARRAYS(PATHCL_DATA_ASSIGN)
