/* Test kernels over the real texture code (kernels/textures.cl), built with
 * PATHCL_HAS_TEXTURES, _NORMAL_MAPS, _VERTEX_COLORS and _AREA_LIGHTS: raw lookups, the
 * material inputs at a hit exactly as the integrator applies them, and light samples on
 * textured emitters. */

#define TEXTURE_BUFFER_ARGS                                                                              \
    __global const uint *texels, __global const TextureImage *images, __global const TextureView *views, \
        __global const TriangleTexcoords *texcoords, __global const TriangleTangents *tangents,           \
        __global const TriangleColors *colors

/* One lookup per work-item: query = (u, v, as_float(view index), unused). */
__kernel void test_texture_sample(TEXTURE_BUFFER_ARGS, __global const float4* queries, __global float4* out)
{
    uint i = get_global_id(0);
    TextureBuffers tex = texture_buffers(texels, images, views, texcoords, tangents, colors);
    float4 q = queries[i];
    out[i] = texture_sample(&tex, as_int(q.z), q.xy);
}

/* The material at a hit, as the integrator sees it: hit = (b1, b2, as_float(triangle),
 * unused) seen along direction -wo. Writes the shading normal, the textured base colour,
 * emission and specular colour, and (metallic, roughness, specular, transmission). */
__kernel void test_material_inputs(TEXTURE_BUFFER_ARGS, __global const Triangle* triangles,
                                   __global const TriangleShading* shading, __global const Material* materials,
                                   __global const float4* hits, __global const float4* wos,
                                   __global float4* out_normal, __global float4* out_base_color,
                                   __global float4* out_emission, __global float4* out_specular_color,
                                   __global float4* out_params)
{
    uint i = get_global_id(0);
    TextureBuffers tex = texture_buffers(texels, images, views, texcoords, tangents, colors);
    Hit hit;
    hit.b1 = hits[i].x;
    hit.b2 = hits[i].y;
    hit.triangle = as_int(hits[i].z);
    hit.t = 1.0f;
    float3 wo = wos[i].xyz;
    SurfacePoint sp = surface_point(triangles, shading, hit, wo);
    Material m = materials[sp.material];
    apply_material_inputs(&m, &sp, wo, hit, &tex);
    out_normal[i] = (float4)(sp.ns, dot(sp.ns, sp.ng));
    out_base_color[i] = m.base_color;
    out_emission[i] = m.emission;
    out_specular_color[i] = m.specular_color;
    out_params[i] = (float4)(m.metallic, m.roughness, m.specular_color.w, m.transmission);
}

/* light_sample from `ref` (one sample per work-item): writes (direction, pdf) and the
 * radiance the sample carries, zeros when there is no sample. */
__kernel void test_textured_light_sample(TEXTURE_BUFFER_ARGS, __global const Light* lights, uint count, float4 ref,
                                         uint seed, __global float4* out, __global float4* radiance_out)
{
    uint i = get_global_id(0);
    TextureBuffers tex = texture_buffers(texels, images, views, texcoords, tangents, colors);
    SamplerState s = sampler_start(i, 0u, seed, 0u);
    EnvironmentBuffers env; /* no environment in these tests */
    env.texels = 0;
    env.marginal = 0;
    env.conditional = 0;
    LightSample ls = light_sample(lights, count, &env, &tex, ref.xyz, &s);
    out[i] = (ls.pdf > 0.0f) ? (float4)(ls.wi, ls.pdf) : (float4)(0.0f);
    radiance_out[i] = (ls.pdf > 0.0f) ? (float4)(ls.radiance, 0.0f) : (float4)(0.0f);
}
