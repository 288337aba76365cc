/* Kernel features: what a program is compiled for, so that a scene pays only for the
 * effects it uses (docs/architecture.md, "Design notes"). Every feature bit and every
 * guard derived from the bits is defined here and nowhere else.
 *
 * The host computes one mask for a render (host/compile/kernel_features.cpp) and passes it
 * as the one define -DPATHCL_FEATURES=<mask>; this file turns the mask into the
 * PATHCL_HAS_* guards the kernel files test. A program built without the define gets no
 * optional feature (the sample visualizer's). */
#ifndef PATHCL_FEATURES_H
#define PATHCL_FEATURES_H

/* Scene features: the host sets a bit when the scene has the effect. */
#define FEATURE_AREA_LIGHTS (1u << 0)        /* an emissive triangle */
#define FEATURE_POINT_LIGHTS (1u << 1)       /* a KHR_lights_punctual point light */
#define FEATURE_SPOT_LIGHTS (1u << 2)        /* a cone or rectangular spot light */
#define FEATURE_DIRECTIONAL_LIGHTS (1u << 3) /* a directional light */
#define FEATURE_SPHERE_LIGHTS (1u << 4)      /* a point light with a radius */
#define FEATURE_ENVIRONMENT (1u << 5)        /* an environment map or constant background */
#define FEATURE_GLOSSY (1u << 6)             /* a material with a specular lobe (metal or dielectric layer) */
#define FEATURE_TRANSMISSION (1u << 7)       /* a material with KHR_materials_transmission > 0 */
#define FEATURE_TEXTURES (1u << 8)           /* a material with a texture */
#define FEATURE_NORMAL_MAPS (1u << 9)        /* a material with a normal texture */
#define FEATURE_VERTEX_COLORS (1u << 10)     /* a primitive with COLOR_0 */
#define FEATURE_THIN_LENS (1u << 11)         /* the camera has an aperture (depth of field) */
/* Model options: set by a render option, not by the scene. */
#define FEATURE_SINGLE_SCATTERING (1u << 12) /* no multiple-scattering compensation (pbrt's, Mitsuba's model) */
/* Scene features added later (their bits follow the model options). */
#define FEATURE_ALPHA (1u << 13)             /* a triangle whose material's alphaMode MASK or BLEND can cut it */
#define FEATURE_VOLUME_ABSORPTION (1u << 14) /* a solid transmissive material with KHR_materials_volume attenuation */
#define FEATURE_SCHLICK_LAYER (1u << 15)     /* a material with KHR_materials_ior ior 0 (specular-glossiness mode) */
#define FEATURE_UNLIT (1u << 16)             /* a KHR_materials_unlit material */
#define FEATURE_CLEARCOAT (1u << 17)         /* a material with KHR_materials_clearcoat clearcoatFactor > 0 */
#define FEATURE_INSTANCES (1u << 18)         /* a mesh stored once and drawn by instances (two-level BVH) */
#define FEATURE_SHEEN (1u << 19)             /* a material with a KHR_materials_sheen colour above 0 */
#define FEATURE_ANISOTROPY (1u << 20)        /* a material with KHR_materials_anisotropy strength above 0 */
/* Model options added later. */
#define FEATURE_LIGHT_TREE (1u << 21)            /* --light-sampler tree: lights picked by the light tree */
#define FEATURE_SOLID_ANGLE_TRIANGLES (1u << 22) /* --triangle-sampling solid-angle */
#define FEATURE_ALL ((1u << 23) - 1u)

#ifdef __OPENCL_C_VERSION__

#ifndef PATHCL_FEATURES
#define PATHCL_FEATURES 0u
#endif

#if PATHCL_FEATURES & FEATURE_AREA_LIGHTS
#define PATHCL_HAS_AREA_LIGHTS
#endif
#if PATHCL_FEATURES & FEATURE_POINT_LIGHTS
#define PATHCL_HAS_POINT_LIGHTS
#endif
#if PATHCL_FEATURES & FEATURE_SPOT_LIGHTS
#define PATHCL_HAS_SPOT_LIGHTS
#endif
#if PATHCL_FEATURES & FEATURE_DIRECTIONAL_LIGHTS
#define PATHCL_HAS_DIRECTIONAL_LIGHTS
#endif
#if PATHCL_FEATURES & FEATURE_SPHERE_LIGHTS
#define PATHCL_HAS_SPHERE_LIGHTS
#endif
#if PATHCL_FEATURES & FEATURE_ENVIRONMENT
#define PATHCL_HAS_ENVIRONMENT
#endif
#if PATHCL_FEATURES & FEATURE_GLOSSY
#define PATHCL_HAS_GLOSSY
#endif
#if PATHCL_FEATURES & FEATURE_TRANSMISSION
#define PATHCL_HAS_TRANSMISSION
#endif
#if PATHCL_FEATURES & FEATURE_TEXTURES
#define PATHCL_HAS_TEXTURES
#endif
#if PATHCL_FEATURES & FEATURE_NORMAL_MAPS
#define PATHCL_HAS_NORMAL_MAPS
#endif
#if PATHCL_FEATURES & FEATURE_VERTEX_COLORS
#define PATHCL_HAS_VERTEX_COLORS
#endif
#if PATHCL_FEATURES & FEATURE_THIN_LENS
#define PATHCL_HAS_THIN_LENS
#endif
#if PATHCL_FEATURES & FEATURE_SINGLE_SCATTERING
#define PATHCL_SINGLE_SCATTERING
#endif
#if PATHCL_FEATURES & FEATURE_ALPHA
#define PATHCL_HAS_ALPHA
#endif
#if PATHCL_FEATURES & FEATURE_VOLUME_ABSORPTION
#define PATHCL_HAS_VOLUME_ABSORPTION
#endif
#if PATHCL_FEATURES & FEATURE_SCHLICK_LAYER
#define PATHCL_HAS_SCHLICK_LAYER
#endif
#if PATHCL_FEATURES & FEATURE_UNLIT
#define PATHCL_HAS_UNLIT
#endif
#if PATHCL_FEATURES & FEATURE_CLEARCOAT
#define PATHCL_HAS_CLEARCOAT
#endif
#if PATHCL_FEATURES & FEATURE_INSTANCES
#define PATHCL_HAS_INSTANCES
#endif
#if PATHCL_FEATURES & FEATURE_SHEEN
#define PATHCL_HAS_SHEEN
#endif
#if PATHCL_FEATURES & FEATURE_ANISOTROPY
#define PATHCL_HAS_ANISOTROPY
#endif
#if PATHCL_FEATURES & FEATURE_LIGHT_TREE
#define PATHCL_LIGHT_TREE
#endif
#if (PATHCL_FEATURES & FEATURE_SOLID_ANGLE_TRIANGLES) && (PATHCL_FEATURES & FEATURE_AREA_LIGHTS)
#define PATHCL_SOLID_ANGLE_TRIANGLES
#endif

/* Derived guards. */
#if defined(PATHCL_LIGHT_TREE) || defined(PATHCL_SOLID_ANGLE_TRIANGLES)
#define PATHCL_KEEPS_PREV_REF /* a path keeps the point it left from (integrator/path_state.cl) */
#endif
#if PATHCL_FEATURES & (FEATURE_AREA_LIGHTS | FEATURE_POINT_LIGHTS | FEATURE_SPOT_LIGHTS | FEATURE_DIRECTIONAL_LIGHTS | \
                       FEATURE_SPHERE_LIGHTS | FEATURE_ENVIRONMENT)
#define PATHCL_HAS_LIGHTS /* next event estimation */
#endif
#if PATHCL_FEATURES & (FEATURE_GLOSSY | FEATURE_TRANSMISSION | FEATURE_CLEARCOAT | FEATURE_SHEEN | FEATURE_ANISOTROPY)
#define PATHCL_FULL_BSDF /* the whole glTF BSDF; else Lambertian only */
#endif
#if PATHCL_FEATURES & (FEATURE_TEXTURES | FEATURE_VERTEX_COLORS)
#define PATHCL_HAS_MATERIAL_INPUTS /* per-hit material inputs (texels, vertex colours) */
#endif

#endif /* __OPENCL_C_VERSION__ */

#endif
