/* Test kernels over the real BSDF code (kernels/closure/). The shading point has its
 * geometric and shading normal along `normal` (any unit vector: the kernels' own basis
 * code runs) and its anisotropy direction along `tangent` (orthogonal to it); directions
 * are in world space. */
#include "closure/bsdf.cl"
#include "sample/sampler.cl"

static inline SurfacePoint test_surface_point(float3 normal, float3 tangent, uint front_face)
{
    SurfacePoint sp;
    sp.p = (float3)(0.0f);
    sp.p_error = (float3)(0.0f);
    sp.p_smooth = sp.p;
    sp.lifted = false;
    sp.ng = normal;
    sp.ns = normal;
#ifdef PATHCL_HAS_CLEARCOAT
    sp.n_coat = normal;
#endif
#ifdef PATHCL_HAS_ANISOTROPY
    sp.t_aniso = tangent;
#endif
    sp.front_face = front_face != 0u;
    sp.area = 1.0f;
    sp.material = 0;
    sp.emitter = -1;
    return sp;
}

/* One bsdf_sample per work-item from wo, then bsdf_eval at the sampled direction:
 *   dir_pdf = (wi, sample pdf)           (0 when there was no sample)
 *   weight  = (sample weight, 1 if delta)
 *   eval    = (bsdf_eval f_cos at wi, bsdf_eval pdf at wi) */
PATHCL_KERNEL void test_bsdf_sample(Material m, float4 normal, float4 tangent, float4 wo, uint front_face, uint seed,
                                    __global const float* layer, __global float4* dir_pdf, __global float4* weight,
                                    __global float4* eval)
{
    uint i = get_global_id(0);
    SurfacePoint sp = test_surface_point(normal.xyz, tangent.xyz, front_face);
    BsdfParams p = bsdf_params(&m, &sp, wo.xyz, layer);
    SamplerState s = sampler_start(i, 0u, seed, 0u);
    float u_lobe = sampler_get_1d(&s);
    float2 u = sampler_get_2d(&s);
    BsdfSample bs = bsdf_sample(&p, &sp, wo.xyz, u_lobe, u);
    if (!(bs.pdf > 0.0f)) {
        dir_pdf[i] = weight[i] = eval[i] = (float4)(0.0f);
        return;
    }
    dir_pdf[i] = (float4)(bs.wi, bs.pdf);
    weight[i] = (float4)(bs.weight, bs.delta ? 1.0f : 0.0f);
    BsdfEval e = bsdf_eval(&p, &sp, wo.xyz, bs.wi);
    eval[i] = (float4)(e.f_cos, e.pdf);
}

/* bsdf_eval for given pairs: out = (f_cos, pdf). */
PATHCL_KERNEL void test_bsdf_eval(Material m, float4 normal, float4 tangent, uint front_face,
                                  __global const float* layer, __global const float4* wo, __global const float4* wi,
                                  __global float4* out)
{
    uint i = get_global_id(0);
    SurfacePoint sp = test_surface_point(normal.xyz, tangent.xyz, front_face);
    BsdfParams p = bsdf_params(&m, &sp, wo[i].xyz, layer);
    BsdfEval e = bsdf_eval(&p, &sp, wo[i].xyz, wi[i].xyz);
    out[i] = (float4)(e.f_cos, e.pdf);
}

/* Whether NEE is skipped at this material (every lobe a delta function). */
PATHCL_KERNEL void test_bsdf_is_delta(Material m, __global const float* layer, __global int* out)
{
    SurfacePoint sp = test_surface_point((float3)(0.0f, 0.0f, 1.0f), (float3)(1.0f, 0.0f, 0.0f), 1u);
    BsdfParams p = bsdf_params(&m, &sp, (float3)(0.0f, 0.0f, 1.0f), layer);
    out[0] = bsdf_is_delta(&p) ? 1 : 0;
}

#ifdef PATHCL_FULL_BSDF
/* The Lambertian shortcut against every lobe's code, for the same material, numbers and
 * directions, one work-item each (wo and wi pairs as test_bsdf_eval takes them; the
 * sample's numbers from `seed`). Four float4 per work-item each way:
 *   (sample wi, sample pdf), (sample weight, delta), (eval f_cos at wi[i], eval pdf),
 *   (bsdf_lambertian, 0, 0, 0)
 * to `shortcut` from bsdf_sample_lambertian and bsdf_eval_lambertian, to `lobes` from
 * bsdf_sample_lobes and bsdf_eval_lobes. */
PATHCL_KERNEL void test_bsdf_lambertian_shortcut(Material m, uint front_face, uint seed, __global const float* layer,
                                                 __global const float4* wo, __global const float4* wi,
                                                 __global float4* shortcut, __global float4* lobes)
{
    uint i = get_global_id(0);
    SurfacePoint sp = test_surface_point((float3)(0.0f, 0.0f, 1.0f), (float3)(1.0f, 0.0f, 0.0f), front_face);
    BsdfParams p = bsdf_params(&m, &sp, wo[i].xyz, layer);
    SamplerState s = sampler_start(i, 0u, seed, 0u);
    float u_lobe = sampler_get_1d(&s);
    float2 u = sampler_get_2d(&s);
    BsdfSample a = bsdf_sample_lambertian(&p, &sp, u), b = bsdf_sample_lobes(&p, &sp, wo[i].xyz, u_lobe, u);
    BsdfEval ea = bsdf_eval_lambertian(&p, &sp, wi[i].xyz), eb = bsdf_eval_lobes(&p, &sp, wo[i].xyz, wi[i].xyz);
    float flag = bsdf_lambertian(&p) ? 1.0f : 0.0f;
    shortcut[4u * i] = (float4)(a.wi, a.pdf);
    shortcut[4u * i + 1u] = (float4)(a.weight, a.delta ? 1.0f : 0.0f);
    shortcut[4u * i + 2u] = (float4)(ea.f_cos, ea.pdf);
    shortcut[4u * i + 3u] = (float4)(flag, 0.0f, 0.0f, 0.0f);
    lobes[4u * i] = (float4)(b.wi, b.pdf);
    lobes[4u * i + 1u] = (float4)(b.weight, b.delta ? 1.0f : 0.0f);
    lobes[4u * i + 2u] = (float4)(eb.f_cos, eb.pdf);
    lobes[4u * i + 3u] = (float4)(flag, 0.0f, 0.0f, 0.0f);
}

/* A BsdfParams' fields from the dielectric layer's albedo on (what bsdf_params_base sets),
 * in three float4: (layer_o, lobes.diffuse), (diffuse_scale, lobes.conductor),
 * (lobes.interface, lobes.sheen, lobes.coat, 0); a lobe the program lacks is 0. */
static void write_base_fields(const BsdfParams* p, __global float4* out)
{
    float sheen = 0.0f, coat = 0.0f;
#ifdef PATHCL_HAS_SHEEN
    sheen = p->lobes.sheen;
#endif
#ifdef PATHCL_HAS_CLEARCOAT
    coat = p->lobes.coat;
#endif
    out[0] = (float4)(p->layer_o, p->lobes.diffuse);
    out[1] = (float4)(p->diffuse_scale, p->lobes.conductor);
    out[2] = (float4)(p->lobes.interface, sheen, coat, 0.0f);
}

/* A BsdfSample as two float4: (wi, pdf), (weight, eta2, negated when not a delta sample).
 * wi is written as 0 where there is no sample: a sampler may return before setting it. */
static void write_sample(const BsdfSample* s, __global float4* out)
{
    out[0] = (float4)(s->pdf > 0.0f ? s->wi : (float3)(0.0f), s->pdf);
    out[1] = (float4)(s->weight, s->delta ? s->eta2 : -s->eta2);
}

/* A shortcut of bsdf_params against its general part (bsdf_params_base), for one material
 * and each wo, one work-item each: `ideal` 0 takes bsdf_params_base_diffuse and its
 * predicate bsdf_params_diffuse_only, 1 bsdf_params_base_ideal and bsdf_params_ideal_only.
 * Three float4 per wo (the fields of write_base_fields) to `params` as bsdf_params left
 * them, to `shortcut` as the shortcut sets them and to `general` as the general code
 * computes them; the predicate (1 or 0) to `admitted`; to `samples`, bsdf_sample with the
 * numbers u[i] = (u_lobe, u) from the shortcut's fields and from the general ones, two
 * float4 each (write_sample). */
PATHCL_KERNEL void test_bsdf_params_shortcut(Material m, uint front_face, uint ideal, __global const float* layer,
                                             __global const float4* wo, __global const float4* u,
                                             __global float4* params, __global float4* shortcut,
                                             __global float4* general, __global float* admitted,
                                             __global float4* samples)
{
    uint i = get_global_id(0);
    SurfacePoint sp = test_surface_point((float3)(0.0f, 0.0f, 1.0f), (float3)(1.0f, 0.0f, 0.0f), front_face);
    BsdfParams p = bsdf_params(&m, &sp, wo[i].xyz, layer);
    BsdfParams a = p, b = p;
    if (ideal != 0u)
        bsdf_params_base_ideal(&a);
    else
        bsdf_params_base_diffuse(&a);
    bsdf_params_base(&b, &m, bsdf_wo_local(&b, &sp, wo[i].xyz));
    write_base_fields(&p, params + 3u * i);
    write_base_fields(&a, shortcut + 3u * i);
    write_base_fields(&b, general + 3u * i);
    admitted[i] = (ideal != 0u ? bsdf_params_ideal_only(&p) : bsdf_params_diffuse_only(&p)) ? 1.0f : 0.0f;
    BsdfSample sa = bsdf_sample(&a, &sp, wo[i].xyz, u[i].x, u[i].yz);
    BsdfSample sb = bsdf_sample(&b, &sp, wo[i].xyz, u[i].x, u[i].yz);
    write_sample(&sa, samples + 4u * i);
    write_sample(&sb, samples + 4u * i + 2u);
}

#endif
