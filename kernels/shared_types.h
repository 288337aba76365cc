/* Every struct that crosses the host/device boundary, defined once for both sides.
 * (Kernel helper functions are `static inline`: plain `inline` has C99 semantics in
 * OpenCL C and emits no definition, so a call the compiler does not inline fails to link
 * on some drivers; PoCL happens to accept it.)
 *
 * Rules that keep the two compilers in agreement: members are 4-byte scalars or 16-byte
 * vectors, vectors come first, padding is explicit, and every size is a multiple of 16.
 * host/cl/shared_types_check.cpp static_asserts each size and offset on the host.
 * Byte sizes are part of the design (device memory traffic); they are listed per struct. */
#ifndef PATHCL_SHARED_TYPES_H
#define PATHCL_SHARED_TYPES_H

#ifdef __OPENCL_C_VERSION__
typedef float4 pcl_float4;
typedef int pcl_int;
typedef uint pcl_uint;
typedef float pcl_float;
#else
#include <cstdint>
namespace pathcl {
struct alignas(16) pcl_float4 {
    float x, y, z, w;
};
typedef std::int32_t pcl_int;
typedef std::uint32_t pcl_uint;
typedef float pcl_float;
#endif

/* Ray as written by the camera kernel: 32 bytes. */
typedef struct {
    pcl_float4 origin;    /* xyz; w unused */
    pcl_float4 direction; /* xyz normalized; w unused */
} Ray;

/* Two-wide BVH node holding both children's boxes, so one 64-byte fetch decides which
 * children a ray enters. A child is either an inner node (count == 0, index = node) or a
 * leaf (count > 0, index = first triangle, count triangles). An empty child has count
 * 0 and index -1 and an inverted box. 64 bytes. */
typedef struct {
    pcl_float4 left_min;  /* w: as_float(left index) */
    pcl_float4 left_max;  /* w: as_float(left count) */
    pcl_float4 right_min; /* w: as_float(right index) */
    pcl_float4 right_max; /* w: as_float(right count) */
} BvhNode;

/* Triangle positions in BVH leaf order, for intersection only: 48 bytes. */
typedef struct {
    pcl_float4 v0, v1, v2; /* xyz world position; w unused */
} Triangle;

/* What shading needs of a triangle, same order as Triangle: 64 bytes. */
typedef struct {
    pcl_float4 n0, n1, n2; /* world shading normals at the vertices (geometric if absent) */
    pcl_int material;
    pcl_int emitter; /* index into the light array, -1 when the triangle does not emit */
    pcl_int pad0, pad1;
} TriangleShading;

/* Material flags */
#define MATERIAL_DOUBLE_SIDED 1 /* glTF doubleSided: opaque surfaces reflect on both sides */
#define MATERIAL_THIN_WALLED 2  /* transmission without KHR_materials_volume thickness > 0 */

/* No texture (a texture field's value when the material has none). */
#define TEXTURE_NONE (-1)

/* glTF metallic-roughness material with KHR_materials_specular, _transmission, _ior and
 * _volume, as the kernels read it (see kernels/bsdf.cl for the model): 112 bytes.
 * Texture fields index the texture-view array (TEXTURE_NONE when absent); a texture
 * value multiplies its factor, as glTF defines. */
typedef struct {
    pcl_float4 base_color;     /* rgb linear baseColorFactor; a unused */
    pcl_float4 emission;       /* rgb radiance (emissiveFactor x strength), W m^-2 sr^-1 */
    pcl_float4 specular_color; /* rgb specularColorFactor; w specularFactor */
    pcl_float metallic;
    pcl_float roughness;    /* perceptual; GGX alpha = roughness^2 */
    pcl_float transmission; /* transmissionFactor */
    pcl_float ior;          /* KHR_materials_ior, default 1.5 */
    pcl_uint flags;         /* MATERIAL_* */
    pcl_float normal_scale; /* normalTexture.scale */
    pcl_int base_color_texture;
    pcl_int metallic_roughness_texture;
    pcl_int emissive_texture;
    pcl_int normal_texture;
    pcl_int specular_texture;       /* A channel scales specularFactor */
    pcl_int specular_color_texture; /* RGB (sRGB) scales specularColorFactor */
    pcl_int transmission_texture;   /* R channel scales transmissionFactor */
    pcl_int pad0, pad1, pad2;
} Material;

/* Light types */
#define LIGHT_TRIANGLE 0    /* an emissive triangle (area light) */
#define LIGHT_POINT 1       /* KHR_lights_punctual point */
#define LIGHT_SPOT 2        /* KHR_lights_punctual spot: cone with smooth falloff */
#define LIGHT_RECT_SPOT 3   /* spot with extras hfov/vfov: rectangular frustum, hard edges */
#define LIGHT_DIRECTIONAL 4 /* KHR_lights_punctual directional */
#define LIGHT_SPHERE 5      /* point light with extras.radius: uniform outward radiance */
#define LIGHT_ENVIRONMENT 6 /* equirectangular map at infinity (at most one) */

/* A light, with its entry of the power-proportional alias table used to pick lights.
 * 80 bytes. Fields by type:
 *   TRIANGLE:    p0, p1, p2 = vertices (p0.w = area); radiance = emitted radiance
 *   POINT:       p0 = position; radiance = intensity (W/sr)
 *   SPOT:        p0 = position; p1 = axis (unit, the way light travels);
 *                p2.x = cos(outer angle), p2.y = cos(inner angle); radiance = intensity
 *   RECT_SPOT:   p0 = position; p1 = axis, p1.w = tan(vfov / 2);
 *                p2 = right (unit, node +X), p2.w = tan(hfov / 2); radiance = intensity
 *   DIRECTIONAL: p1 = direction light travels (unit); radiance = irradiance (W/m^2)
 *   SPHERE:      p0 = centre, p0.w = radius; radiance = emitted radiance I / (pi r^2)
 *   ENVIRONMENT: p0 = (width, height, cos(rotation), sin(rotation)); texels and the
 *                sampling distribution are in the env_* buffers (environment.cl)
 * Sphere lights come first in the light array (frame.sphere_count of them): rays test
 * them directly, outside the BVH.
 * radiance.w is the light's selection probability (pmf) for every type. */
typedef struct {
    pcl_float4 p0, p1, p2;
    pcl_float4 radiance;
    pcl_int type;
    pcl_float alias_threshold; /* keep this light if u < threshold, else take alias */
    pcl_int alias;
    pcl_int pad0;
} Light;

/* Camera projections */
#define CAMERA_PERSPECTIVE 0  /* pinhole, or a thin lens when lens_radius > 0 */
#define CAMERA_ORTHOGRAPHIC 1 /* parallel rays along forward (thin lens too if lens_radius > 0) */

/* Camera in render space: 80 bytes. A film position (sx, sy) in [-1, 1]^2 (sy up) maps
 *   perspective:  to the ray from position along forward + sx * right + sy * up, so right
 *                 and up carry tan(yfov / 2) (times the aspect ratio for right);
 *   orthographic: to the ray from position + sx * right + sy * up along forward, so right
 *                 and up carry the half-width and half-height (glTF xmag, ymag).
 * Thin lens (lens_radius > 0, compiled in only with PATHCL_HAS_THIN_LENS): the ray starts
 * at a point of the disk of radius lens_radius around that origin in the right/up plane
 * and passes through the point where the pinhole ray meets the plane of focus, at
 * distance focus_distance along forward. */
typedef struct {
    pcl_float4 position;
    pcl_float4 forward; /* unit */
    pcl_float4 right;
    pcl_float4 up;
    pcl_int type;            /* CAMERA_* */
    pcl_float lens_radius;    /* 0: pinhole */
    pcl_float focus_distance; /* > 0 when lens_radius > 0 */
    pcl_int pad0;
} Camera;

/* Samplers (--sampler); see kernels/samplers.cl. */
#define SAMPLER_INDEPENDENT 0
#define SAMPLER_JITTERED 1
#define SAMPLER_MULTI_JITTERED 2
#define SAMPLER_N_ROOKS 3
#define SAMPLER_SOBOL 4
#define SAMPLER_HALTON 5
#define SAMPLER_HAMMERSLEY 6
#define SAMPLER_COUNT 7

/* Light-sampling strategies (--strategy); all converge to the same image. */
#define STRATEGY_BSDF 0       /* BSDF sampling only: lights are found by chance */
#define STRATEGY_NEE 1        /* light sampling for direct light, BSDF rays for indirect */
#define STRATEGY_ONE_SAMPLE 2 /* one of {light, BSDF} per bounce, mixture-pdf weight */
#define STRATEGY_MIS 3        /* both, power heuristic */

/* Per-pass constants: 48 bytes. */
typedef struct {
    pcl_uint width, height;
    pcl_uint sample_index; /* index of this pass's sample within the pixel */
    pcl_uint seed;
    pcl_uint max_bounces;
    pcl_uint light_count;
    pcl_uint strategy;
    pcl_uint sphere_count; /* lights[0 .. sphere_count) are spheres */
    pcl_int environment;   /* index of the environment light, -1 if none */
    pcl_uint sampler;      /* SAMPLER_* */
    pcl_uint spp;          /* samples per pixel of the render (the samplers' set size) */
    pcl_uint pad0;
} FrameParams;

/* Film pixel: Neumaier-compensated float sums of the radiance and of its square, so a
 * pixel's mean and variance stay accurate over millions of samples on devices without
 * doubles. 64 bytes. */
typedef struct {
    pcl_float4 sum, sum_compensation;
    pcl_float4 sum_sq, sum_sq_compensation;
} FilmPixel;

/* Sampler dimensions (kernels/samplers.cl). Every decision of a path has its own: a 1D
 * decision one dimension, a 2D decision the pair (d, d + 1), drawn as one 2D point set.
 * A bounce's decisions sit at fixed offsets, so a path's numbers never depend on which
 * branches earlier bounces took. The camera kernel consumes the first four; the
 * integrator's bounce k starts at DIM_PATH_START + k * DIMS_PER_BOUNCE. */
#define DIM_PIXEL 0
#define DIM_LENS 2
#define DIM_PATH_START 4
#define DIMS_PER_BOUNCE 9 /* technique coin, light pick (2), light point (2), BSDF (2), RR,
                            BSDF lobe */

#ifndef __OPENCL_C_VERSION__
} /* namespace pathcl */
#endif

#endif
