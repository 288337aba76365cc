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
typedef int4 pcl_int4;
typedef int pcl_int;
typedef uint pcl_uint;
typedef float pcl_float;
#else
#include <cstdint>
namespace pathcl {
struct alignas(16) pcl_float4 {
    float x, y, z, w;
};
struct alignas(16) pcl_int4 {
    std::int32_t x, y, z, w;
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

/* Four-wide BVH node: the four children's boxes stored axis by axis, so that one float4
 * operation slab-tests all four (SIMD on CPUs, and one node fetch decides all children).
 * A child is an inner node (count 0, index = node), a leaf (count > 0: triangles index ..
 * index + count - 1) or empty (index -1, count 0, inverted box). 128 bytes. */
typedef struct {
    pcl_float4 lo_x, hi_x, lo_y, hi_y, lo_z, hi_z; /* lane k: child k's box */
    pcl_int4 index;
    pcl_int4 count;
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

/* Optional per-triangle vertex attributes, each in its own buffer in the same (BVH leaf)
 * order as Triangle, uploaded only when the scene uses them (PATHCL_HAS_TEXTURES,
 * _NORMAL_MAPS, _VERTEX_COLORS); vertex 0, 1, 2 as in Triangle. */

/* One texture-coordinate set (TEXCOORD_n) of a triangle: 32 bytes. The texcoord buffer
 * holds every set some texture uses, one after the other (set slot k of triangle i at
 * k * triangle count + i); a TextureView names where its set starts. */
typedef struct {
    pcl_float4 uv01; /* (u, v) of vertex 0, then of vertex 1 */
    pcl_float4 uv2;  /* xy: (u, v) of vertex 2; zw unused */
} TriangleTexcoords;

/* Vertex tangents for normal mapping, world space: 48 bytes. xyz is the unit tangent
 * (the direction of increasing u), w the handedness: bitangent = w * cross(n, t). Zero
 * where the triangle's material has no normal texture. */
typedef struct {
    pcl_float4 t0, t1, t2;
} TriangleTangents;

/* Vertex colours (COLOR_0, linear RGB; alpha is not used): 48 bytes. White where the
 * triangle's primitive has no COLOR_0. */
typedef struct {
    pcl_float4 c0, c1, c2; /* rgb; a unused */
} TriangleColors;

/* Texel storage formats. Texels of every image live in one buffer of 32-bit words,
 * row-major from the top row of the image; channels are unsigned normalized integers
 * (value / 255 or value / 65535), grey and RGB images expanded to RGBA on the host. */
#define TEXTURE_FORMAT_RGBA8 0  /* one word per texel: R | G << 8 | B << 16 | A << 24 */
#define TEXTURE_FORMAT_RGBA16 1 /* two words per texel: R | G << 16, then B | A << 16 */

/* An image in the texel buffer: 16 bytes. */
typedef struct {
    pcl_uint offset; /* index of its first word in the texel buffer */
    pcl_uint width, height;
    pcl_uint format; /* TEXTURE_FORMAT_* */
} TextureImage;

/* glTF sampler wrap modes, per axis. */
#define TEXTURE_WRAP_REPEAT 0
#define TEXTURE_WRAP_CLAMP_TO_EDGE 1
#define TEXTURE_WRAP_MIRRORED_REPEAT 2

/* TextureView flags */
#define TEXTURE_SRGB 1    /* colour texture: texels are sRGB-encoded, decoded before filtering */
#define TEXTURE_NEAREST 2 /* sampler magFilter NEAREST; otherwise bilinear */

/* How one material slot samples an image (a glTF textureInfo with its sampler): 64 bytes.
 * The texture coordinate (u, v) is first transformed by KHR_texture_transform,
 *   u' = dot(transform_u.xyz, (u, v, 1)),  v' = dot(transform_v.xyz, (u, v, 1)),
 * then wrapped and filtered with texel centres at ((i + 0.5) / width, (j + 0.5) / height). */
typedef struct {
    pcl_float4 transform_u; /* w unused */
    pcl_float4 transform_v; /* w unused */
    pcl_int image;          /* index into the TextureImage array */
    pcl_uint texcoord_base; /* where this view's texture-coordinate set starts in the texcoord buffer */
    pcl_uint wrap_s, wrap_t; /* TEXTURE_WRAP_* for u and v */
    pcl_uint flags;          /* TEXTURE_SRGB, TEXTURE_NEAREST */
    pcl_uint pad0, pad1, pad2;
} TextureView;

/* Material flags */
#define MATERIAL_DOUBLE_SIDED 1 /* glTF doubleSided: opaque surfaces reflect on both sides */
#define MATERIAL_THIN_WALLED 2  /* transmission without KHR_materials_volume thickness > 0 */

/* No texture (a texture field's value when the material has none). */
#define TEXTURE_NONE (-1)

/* glTF metallic-roughness material with KHR_materials_specular, _transmission, _ior and
 * _volume, as the kernels read it (see kernels/bsdf.cl for the model): 112 bytes.
 * Texture fields index the TextureView array (TEXTURE_NONE when absent); a texture
 * value multiplies its factor, as glTF defines (kernels/textures.cl applies them). */
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
    pcl_int base_color_texture;         /* RGB (sRGB) scales base_color */
    pcl_int metallic_roughness_texture; /* B scales metallic, G scales roughness */
    pcl_int emissive_texture;           /* RGB (sRGB) scales emission */
    pcl_int normal_texture;         /* tangent space, scaled by normal_scale */
    pcl_int specular_texture;       /* A channel scales specularFactor */
    pcl_int specular_color_texture; /* RGB (sRGB) scales specularColorFactor */
    pcl_int transmission_texture;   /* R channel scales transmissionFactor */
    pcl_float smooth_layer_average; /* 2 int s(mu, ior) mu dmu, see layer_albedo.h */
    pcl_int pad1, pad2;
} Material;

/* Directional albedo tables of the dielectric specular layer, read by kernels/bsdf.cl to
 * weight the diffuse base (albedo scaling) and built by host/render/layer_albedo.cpp.
 * One float array over sqrt(cos theta), roughness r = sqrt(alpha) and x = (eta-1)/(eta+1),
 * each uniform on its grid and interpolated linearly:
 *   E_ss[r][mu]     albedo of the GGX reflection lobe with Fresnel 1
 *   B[x][r][mu]     albedo with the normalized Fresnel curve s(c) of bsdf.cl in place of 1
 *   E_ss_avg[r], B_avg[x][r]   their cosine-weighted hemispherical averages 2 int E mu dmu
 *   G_out[x'][r][mu], G_in[x'][r][mu]   energy albedo (reflection + refraction) of a rough
 *                   dielectric interface seen from outside (eta = ior) and inside (1/ior),
 *                   x' on a 16-point grid
 * Row r = 0 holds the smooth interface (E_ss = 1, B = s(mu), G = 1). 270,464 bytes. */
#define LAYER_MU_RES 32
#define LAYER_ROUGH_RES 32
#define LAYER_ETA_RES 32 /* x in [0, 0.5]: eta in [1, 3] (clamped beyond) */
#define LAYER_X_MAX 0.5f
#define LAYER_TABLE_ESS 0
#define LAYER_TABLE_B (LAYER_TABLE_ESS + LAYER_ROUGH_RES * LAYER_MU_RES)
#define LAYER_TABLE_ESS_AVG (LAYER_TABLE_B + LAYER_ETA_RES * LAYER_ROUGH_RES * LAYER_MU_RES)
#define LAYER_TABLE_B_AVG (LAYER_TABLE_ESS_AVG + LAYER_ROUGH_RES)
#define LAYER_GLASS_ETA_RES 16 /* x in [0, 0.5] for the dielectric interface tables */
#define LAYER_TABLE_GLASS_OUT (LAYER_TABLE_B_AVG + LAYER_ETA_RES * LAYER_ROUGH_RES)
#define LAYER_TABLE_GLASS_IN (LAYER_TABLE_GLASS_OUT + LAYER_GLASS_ETA_RES * LAYER_ROUGH_RES * LAYER_MU_RES)
#define LAYER_TABLE_SIZE (LAYER_TABLE_GLASS_IN + LAYER_GLASS_ETA_RES * LAYER_ROUGH_RES * LAYER_MU_RES)

/* Light picking draws the slot and the alias coin on a grid of 2^24 steps, so that the
 * host can give each light the exact probability the kernel picks it with. */
#define LIGHT_PICK_GRID 16777216u

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
 *   TRIANGLE:    p0, p1, p2 = vertices (p0.w = area, p1.w = as_float(index of the
 *                triangle in the Triangle array)); radiance = emitted radiance
 *                (emissiveFactor x strength), times the texel of `texture` at the
 *                sampled point when that is not TEXTURE_NONE
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
    pcl_uint alias_threshold; /* keep this light if the coin < threshold (of LIGHT_PICK_GRID), else alias */
    pcl_int alias;
    pcl_int texture; /* TRIANGLE: the material's emissive TextureView or TEXTURE_NONE; other types: unused */
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
