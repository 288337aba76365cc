/* Test kernels over the real texture code (kernels/texture/), built with the texture,
 * normal map, vertex colour and anisotropy features: raw lookups and the material inputs at a hit
 * exactly as the integrator applies them. They read the scene arrays through the
 * render kernels' own parameter list (kernel_data.cl). */
#include "geom/surface_point.cl"
#include "kernel_data.cl"
#include "texture/anisotropy.cl"
#include "texture/lookup.cl"
#include "texture/material_inputs.cl"

/* One lookup per work-item: query = (u, v, as_float(view index), unused). */
PATHCL_KERNEL void test_texture_sample(PATHCL_KERNEL_PARAMS __global const float4* queries, __global float4* out)
{
    PATHCL_KERNEL_DATA;
    uint i = get_global_id(0);
    float4 q = queries[i];
    out[i] = texture_sample(&kd, as_int(q.z), q.xy);
}

/* The material at a hit, as the integrator sees it: hit = (b1, b2, as_float(triangle),
 * unused) seen along direction -wo. Writes the shading normal, the textured base colour,
 * emission and specular colour, (metallic, roughness, specular, transmission), the clear
 * coat's (factor, roughness, n_coat.ng) and its normal, the sheen (colour, roughness), and
 * the anisotropy direction and strength. */
PATHCL_KERNEL void test_material_inputs(PATHCL_KERNEL_PARAMS __global const float4* hits, __global const float4* wos,
                                        __global float4* out_normal, __global float4* out_base_color,
                                        __global float4* out_emission, __global float4* out_specular_color,
                                        __global float4* out_params, __global float4* out_coat,
                                        __global float4* out_coat_normal, __global float4* out_sheen,
                                        __global float4* out_anisotropy)
{
    PATHCL_KERNEL_DATA;
    uint i = get_global_id(0);
    Hit hit;
    hit.b1 = hits[i].x;
    hit.b2 = hits[i].y;
    hit.triangle = as_int(hits[i].z);
    hit.t = 1.0f;
#ifdef PATHCL_HAS_INSTANCES
    hit.instance = 0; /* a scene without instanced meshes: its one identity instance */
#endif
    float3 wo = wos[i].xyz;
    SurfacePoint sp = surface_point(&kd, hit, wo);
    Material m = kd.materials[sp.material];
    apply_material_inputs(&m, &sp, wo, hit, &kd);
    apply_anisotropy(&m, &sp, hit, &kd);
    out_normal[i] = (float4)(sp.ns, dot(sp.ns, sp.ng));
    out_base_color[i] = m.base_color;
    out_emission[i] = m.emission;
    out_specular_color[i] = m.specular_color;
    out_params[i] = (float4)(m.metallic, m.roughness, m.specular_color.w, m.transmission);
    out_coat[i] = (float4)(m.clearcoat, m.clearcoat_roughness, dot(sp.n_coat, sp.ng), 0.0f);
    out_coat_normal[i] = (float4)(sp.n_coat, 0.0f);
    out_sheen[i] = m.sheen;
    out_anisotropy[i] = (float4)(sp.t_aniso, m.anisotropy.x);
}
