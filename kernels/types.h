/* Every struct that crosses the host/device boundary, defined once for both sides, with
 * the constants that name its field values.
 *
 * Rules that keep the two compilers in agreement: members are 4-byte scalars or 16-byte
 * vectors, vectors come first, padding is explicit, and every size is a multiple of 16.
 * host/cl/types_check.cpp static_asserts each size and offset on the host.
 * Byte sizes are part of the design (device memory traffic); they are listed per struct. */
#ifndef PATHCL_TYPES_H
#define PATHCL_TYPES_H

#include "texture/texture_slots.h"
#include "util/compat.h"

PATHCL_BEGIN

/* Ray as written by the camera kernel: 32 bytes. */
typedef struct {
    pcl_float4 origin;    /* xyz; w unused */
    pcl_float4 direction; /* xyz normalized; w unused */
} Ray;

/* Eight-wide BVH node: the eight children's boxes stored axis by axis, so that one float8
 * operation slab-tests all eight (SIMD on CPUs, and one node fetch decides all children;
 * an eight-wide tree has fewer levels than a four-wide one, and each level is a dependent
 * memory fetch). A child is an inner node (count 0, index = node), a leaf
 * (count > 0: build_bvh's triangles index .. index + count - 1; on the device, the
 * TriangleBlock that holds them) or empty (index -1, count 0,
 * inverted box). 256 bytes. */
#define BVH_WIDTH 8
typedef struct {
    pcl_float8 lo_x, hi_x, lo_y, hi_y, lo_z, hi_z; /* lane k: child k's box */
    pcl_int8 index;
    pcl_int8 count;
} BvhNode;

/* Entries of the traversal stack (kernels/bvh/traversal.cl); the builder checks that every
 * tree fits. A node of k children spans at least log2(k) binary levels and pushes k - 1
 * entries besides the one taken next: up to seven per three levels. A tree whose nodes
 * would need more than this gets nodes of the grandchildren of a binary node, at most
 * four children and three pushes per two levels (3 x 31 + 1 = 94 at the builder's depth
 * cap; host/bvh/bvh_builder.cpp). */
#define BVH_STACK_SIZE 128
/* The same for a two-level BVH (PATHCL_HAS_INSTANCES): the top level's entries, a leaf's
 * instances and a return mark below the entries of one mesh's tree; compile_geometry
 * checks that the sum fits. */
#define BVH_INSTANCED_STACK_SIZE (2 * BVH_STACK_SIZE)

/* One drawing of a mesh that is stored once (a two-level BVH: instances in a top-level
 * tree whose leaves name them, each mesh in its own tree in its own space), as two affine
 * maps of three rows each, x'_k = dot(row_k.xyz, x) + row_k.w: to_object takes the
 * render-space ray into the mesh's space for traversal, to_render takes the hit back.
 * 112 bytes. */
typedef struct {
    pcl_float4 to_object[3];
    pcl_float4 to_render[3];
    pcl_int root;  /* the mesh's tree: its root node (always an inner node) */
    pcl_int flags; /* INSTANCE_* */
    pcl_int pad0, pad1;
} Instance;
#define INSTANCE_IDENTITY 1 /* both maps are the identity: the triangles are in render space */
#define INSTANCE_MIRRORED 2 /* the map's determinant is negative: clockwise is the front (glTF) */

/* Triangle positions in BVH leaf order (the hit point and geometric normal of shading;
 * the traversal tests the copies in TriangleBlock): 48 bytes. v0.w is
 * TRIANGLE_ALPHA_TESTED when the triangle's material has alphaMode MASK or BLEND and its
 * alpha can fall short of opaque (the traversal then asks texture/alpha.cl whether a hit
 * counts), else 0; every other w is 0. */
typedef struct {
    pcl_float4 v0, v1, v2; /* xyz world position */
} Triangle;
#define TRIANGLE_ALPHA_TESTED 1.0f

/* A leaf's triangles as the traversal tests them: up to eight, one per lane, each
 * coordinate of each vertex a float8 row, so that one pass of float8 arithmetic runs the
 * watertight test for all of them, and the ray's axis permutation picks rows instead of
 * shuffling each vertex. vertex[3 * v + axis], lane k: triangle k's vertex v. A lane
 * without a triangle has triangle -1 and NaN coordinates. The leaf child of a BvhNode
 * names its block (host/bvh/triangle_blocks.cpp). 320 bytes. */
typedef struct {
    pcl_float8 vertex[9];
    pcl_int8 triangle; /* lane k's triangle: its position in the triangles array */
} TriangleBlock;

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

/* Vertex tangents for normal mapping and anisotropy, world space: 48 bytes. xyz is the
 * unit tangent (the direction of increasing u), w the handedness: bitangent = w * cross(n,
 * t). Zero where the triangle's material has neither a normal texture nor anisotropy. */
typedef struct {
    pcl_float4 t0, t1, t2;
} TriangleTangents;

/* Vertex colours (COLOR_0, linear RGB and alpha): 48 bytes. Opaque white where the
 * triangle's primitive has no COLOR_0 (alpha 1 where it is VEC3). */
typedef struct {
    pcl_float4 c0, c1, c2; /* rgba */
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

/* glTF sampler wrap modes, per axis (texture/wrap.h). */
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
    pcl_float4 transform_u;  /* w unused */
    pcl_float4 transform_v;  /* w unused */
    pcl_int image;           /* index into the TextureImage array */
    pcl_uint texcoord_base;  /* where this view's texture-coordinate set starts in the texcoord buffer */
    pcl_uint wrap_s, wrap_t; /* TEXTURE_WRAP_* for u and v */
    pcl_uint flags;          /* TEXTURE_SRGB, TEXTURE_NEAREST */
    pcl_uint pad0, pad1, pad2;
} TextureView;

/* Material flags */
#define MATERIAL_DOUBLE_SIDED 1 /* glTF doubleSided: opaque surfaces reflect on both sides */
#define MATERIAL_THIN_WALLED 2  /* transmission without KHR_materials_volume thickness > 0 */
#define MATERIAL_ALPHA_MASK 4   /* alphaMode MASK: alpha below alpha_cutoff is no surface */
#define MATERIAL_ALPHA_BLEND 8  /* alphaMode BLEND: alpha is the surface's coverage */
/* The roughness slot holds a specularGlossinessTexture: roughness = 1 - roughness x its
 * alpha (roughness holds glossinessFactor). */
#define MATERIAL_GLOSSINESS 16
/* KHR_materials_unlit: the base colour is seen through delta chains; scatters nothing. */
#define MATERIAL_UNLIT 32

/* No texture (a texture field's value when the material has none). */
#define TEXTURE_NONE (-1)

/* glTF metallic-roughness material with KHR_materials_specular, _transmission, _ior,
 * _volume, _clearcoat, _sheen and _anisotropy, as the kernels read it (see
 * kernels/closure/bsdf.cl for the model): 192 bytes.
 * Each texture slot indexes the TextureView array (TEXTURE_NONE when absent); a texture
 * value multiplies its factor, as glTF defines (kernels/texture/material_inputs.cl
 * applies them). */
typedef struct {
    pcl_float4 base_color;     /* linear baseColorFactor: rgb, and alpha (read with MATERIAL_ALPHA_*) */
    pcl_float4 emission;       /* rgb radiance (emissiveFactor x strength), W m^-2 sr^-1 */
    pcl_float4 specular_color; /* rgb specularColorFactor; w specularFactor */
    pcl_float4 absorption;     /* rgb Beer-Lambert coefficient inside a solid, per unit length
                                  (-ln attenuationColor / attenuationDistance); w unused */
    pcl_float metallic;
    pcl_float roughness;                  /* perceptual; GGX alpha = roughness^2 */
    pcl_float transmission;               /* transmissionFactor */
    pcl_float ior;                        /* KHR_materials_ior, default 1.5 */
    pcl_uint flags;                       /* MATERIAL_* */
    pcl_float normal_scale;               /* normalTexture.scale */
    pcl_int textures[TEXTURE_SLOT_COUNT]; /* TextureView per slot (texture/texture_slots.h) */
    pcl_float smooth_layer_average;       /* 2 int s(mu, ior) mu dmu, see layer_albedo.h */
    pcl_float alpha_cutoff;               /* glTF alphaCutoff (MATERIAL_ALPHA_MASK) */
    pcl_float clearcoat;                  /* KHR_materials_clearcoat clearcoatFactor (0: no coat) */
    pcl_float clearcoat_roughness;        /* clearcoatRoughnessFactor, perceptual */
    pcl_float clearcoat_normal_scale;     /* clearcoatNormalTexture.scale */
    pcl_float4 sheen; /* KHR_materials_sheen: rgb sheenColorFactor (0: no sheen), w sheenRoughnessFactor */
    /* KHR_materials_anisotropy: x anisotropyStrength (0: isotropic), (y, z) the direction
     * (cos, sin of anisotropyRotation) in the tangent, bitangent plane; w unused */
    pcl_float4 anisotropy;
} Material;

/* Light types */
#define LIGHT_TRIANGLE 0    /* an emissive triangle (area light) */
#define LIGHT_POINT 1       /* KHR_lights_punctual point */
#define LIGHT_SPOT 2        /* KHR_lights_punctual spot: cone with smooth falloff */
#define LIGHT_RECT_SPOT 3   /* spot with extras hfov/vfov: rectangular frustum, hard edges */
#define LIGHT_DIRECTIONAL 4 /* KHR_lights_punctual directional */
#define LIGHT_SPHERE 5      /* point light with extras.radius: uniform outward radiance */
#define LIGHT_ENVIRONMENT 6 /* equirectangular map at infinity (at most one) */

/* Per-type light data (the union in Light). Positions are in render space; axes and
 * directions are unit vectors; radiant quantities are in Light.radiance. */
typedef struct {
    pcl_float4 v0, v1, v2; /* vertices (xyz), counter-clockwise seen from the emitting side */
    pcl_float area;
    pcl_int triangle; /* its index in the Triangle array (texture coordinates) */
    pcl_int texture;  /* the material's emissive TextureView, or TEXTURE_NONE */
    pcl_int pad0;
} TriangleLight; /* 64 bytes */

typedef struct {
    pcl_float4 position;
} PointLight; /* 16 bytes */

typedef struct {
    pcl_float4 position;
    pcl_float4 axis; /* the way light travels (node -Z) */
    pcl_float cos_outer, cos_inner;
    pcl_int pad0, pad1;
} SpotLight; /* 48 bytes */

typedef struct {
    pcl_float4 position;
    pcl_float4 axis;                  /* the way light travels (node -Z) */
    pcl_float4 right;                 /* node +X */
    pcl_float tan_half_h, tan_half_v; /* tan(hfov / 2), tan(vfov / 2) */
    pcl_int pad0, pad1;
} RectSpotLight; /* 64 bytes */

typedef struct {
    pcl_float4 direction; /* the way light travels */
} DirectionalLight;       /* 16 bytes */

typedef struct {
    pcl_float4 centre;
    pcl_float radius;
    pcl_int pad0, pad1, pad2;
} SphereLight; /* 32 bytes */

typedef struct {
    pcl_uint width, height;               /* of the map; texels and distribution: the env_* arrays */
    pcl_float cos_rotation, sin_rotation; /* turn about +Y (the map's +Z towards +X) */
} EnvironmentLight;                       /* 16 bytes */

/* A light: 96 bytes. `radiance` is what the type emits: TRIANGLE the emitted radiance
 * (emissiveFactor x strength, times the emissive texel at the point when data.triangle has
 * a texture), POINT / SPOT / RECT_SPOT the intensity (W/sr), DIRECTIONAL the irradiance
 * (W/m^2), SPHERE the emitted radiance I / (pi r^2), ENVIRONMENT unused (the texels hold
 * radiance). Sphere lights come first in the light array (FrameParams.sphere_count of
 * them): rays test them directly, outside the BVH. How often each light is picked is in
 * the separate LightAliasEntry array. */
typedef struct {
    union {
        TriangleLight triangle;
        PointLight point;
        SpotLight spot;
        RectSpotLight rect_spot;
        DirectionalLight directional;
        SphereLight sphere;
        EnvironmentLight environment;
    } data;              /* by type */
    pcl_float4 radiance; /* rgb; w unused */
    pcl_int type;        /* LIGHT_* */
    /* An emissive triangle's BVH leaf, where its shadow rays end: the node whose slot names
     * the leaf and the leaf's TriangleBlock (light_shadow_leaf_warm); unused elsewhere. */
    pcl_int leaf_node, leaf_block;
    pcl_int pad0;
} Light;

/* The light distribution: light i's selection probability and its entry of the
 * power-proportional alias table (kernels/light/light_pick.cl): 16 bytes per light. */
typedef struct {
    pcl_float pmf;            /* probability that light_pick returns this light */
    pcl_uint alias_threshold; /* keep this light if the coin < threshold (of LIGHT_PICK_GRID), else alias */
    pcl_int alias;
    pcl_int pad0;
} LightAliasEntry;

/* A node of the light tree (--light-sampler tree; kernels/light/light_tree.cl, built by
 * host/compile/light_tree.cpp): up to eight children, lane k holding child k's bounds, from
 * which one float8 computation weighs all eight at a shading point (Conty Estevez and
 * Kulla 2018): the bounding sphere of its lights' box, their power, and the cone of
 * directions they emit along (normals within theta_o of the axis, emitting up to theta_e
 * past that), and their mean axis, from which an estimate between the bounds is made.
 * Rounded outward: every light lies within its lanes' bounds. Empty lanes have phi 0.
 * 512 bytes: eight cache lines of 64. */
#define LIGHT_TREE_WIDTH 8
typedef struct {
    pcl_float8 centre_x, centre_y, centre_z;
    pcl_float8 radius2; /* the bounding sphere's radius squared */
    pcl_float8 phi;     /* power (luminance, W) */
    pcl_float8 axis_x, axis_y, axis_z;
    pcl_float8 cos_o, sin_o, cos_e;
    /* The power-weighted mean of its lights' axes (a triangle's: its normal; length at
     * most 1), its part along the lane's axis and the length of its part across; both 0
     * where the lane is two-sided or its cone holds every direction. */
    pcl_float8 mean_axis_along, mean_axis_across;
    pcl_int8 child;     /* >= 0: the child node; < 0: -1 - a leaf (LIGHT_TREE_LEAF_*) */
    pcl_int8 two_sided; /* -1: emits on both sides of its normals (0: the front only) */
    pcl_int8 code;      /* the binary path from this node to the lane: LIGHT_TREE_CODE */
} LightTreeNode;
/* A lane's code: its binary path's bits (bit k: the second child at step k) in bits 0-7,
 * their number in bits 8-11. A light's trail (light_tree_trail) is its whole binary path
 * from the root; at each node the lane whose bits it starts with leads on. */
#define LIGHT_TREE_CODE_BITS(code) ((code)&0xff)
#define LIGHT_TREE_CODE_LENGTH(code) ((code) >> 8)
/* A leaf lane's child is -1 - leaf: a light (its index), or with LIGHT_TREE_CLUSTER set a
 * cluster: up to LIGHT_TREE_CLUSTER_MAX neighbouring lights of one surface that face
 * nearly one way, at light_tree_cluster[index] (its header) and after, picked among in
 * proportion to their power, so that the descent stops above them. */
#define LIGHT_TREE_CLUSTER 0x10000000
#define LIGHT_TREE_LEAF_INDEX(leaf) ((leaf)&0x0fffffff)
#define LIGHT_TREE_MAX_LEAF_INDEX 0x0fffffff
#define LIGHT_TREE_CLUSTER_MAX 256
/* The share of a child's importance given by its upper bound alone (light_tree_importance):
 * the rest by an estimate between its bounds. Lower shares bring the picks over a glowing
 * sphere closer to the ideal, higher ones those over randomly turned cubes, whose mean
 * normals say little; 0.2 improves both most together (docs/accuracy.md; the tests
 * LightTreeSampling.Picks*Ideal). */
#define LIGHT_TREE_UPPER_SHARE 0.2f

/* An entry of light_tree_cluster. A cluster is a header (light: the number of its lights)
 * and then its lights in the order of their indices, each with its probability among
 * them (pmf: in proportion to power) and its slot of their alias table: the slot keeps
 * its light where the coin falls below keep, and gives the light of entry alias (from 0,
 * after the header) elsewhere. A pick reads one entry, or two; a light's pmf is a binary
 * search over the indices. 16 bytes. */
typedef struct {
    pcl_int light;
    pcl_float pmf;
    pcl_float keep;
    pcl_int alias;
} LightTreeClusterLight;

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
    pcl_int type;             /* CAMERA_* */
    pcl_float lens_radius;    /* 0: pinhole */
    pcl_float focus_distance; /* > 0 when lens_radius > 0 */
    pcl_int pad0;
} Camera;

/* Samplers (--sampler); see kernels/sample/sampler.cl. */
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

/* Per-pass constants: 64 bytes. */
typedef struct {
    pcl_uint width, height;
    pcl_uint sample_index; /* index of this pass's sample within the pixel */
    pcl_uint seed;
    pcl_uint max_bounces;
    pcl_uint light_count;
    pcl_uint strategy;
    pcl_uint sphere_count;    /* lights[0 .. sphere_count) are spheres */
    pcl_int environment;      /* index of the environment light, -1 if none */
    pcl_uint sampler;         /* SAMPLER_* */
    pcl_uint spp;             /* samples per pixel of the render (the samplers' set size) */
    pcl_uint stratified_dims; /* decisions at dimensions below this use the sampler; above,
                                 independent numbers (sample/sampler.cl) */
    pcl_uint adaptive;        /* 1: pixels whose film array `active` entry is 0 take no sample */
    pcl_uint first_row;       /* image row of work-item row 0: the device's band (render/device_bands.h) */
    pcl_float infinite_pick;  /* light tree: how often next event estimation picks an infinite light */
    pcl_uint infinite_count;  /* light tree: the infinite lights (directional, environment) */
} FrameParams;

/* Film pixel: Neumaier-compensated float sums of the radiance and of its square, so a
 * pixel's mean and variance stay accurate over millions of samples on devices without
 * doubles. 64 bytes. */
typedef struct {
    pcl_float4 sum, sum_compensation;
    pcl_float4 sum_sq, sum_sq_compensation;
} FilmPixel;

PATHCL_END

#endif
