/* The surface point at a ray hit: position with its rounding-error bound, geometric and
 * shading normals turned to the side the ray came from, and the point lifted onto the
 * smooth surface the vertex normals describe (Hanika 2021), from where reflected rays
 * leave so that coarse meshes with smooth normals have no dark terminator band. */
#include "bvh/instance.cl"
#include "bvh/traversal.cl"
#include "features.h"
#include "kernel_data.cl"
#include "types.h"
#include "util/math.cl"

typedef struct {
    float3 p;        /* world position, from barycentrics (more accurate than o + t d) */
    float3 p_error;  /* per-axis bound on |p - exact p| */
    float3 p_smooth; /* p lifted onto the smooth surface the vertex normals describe (Hanika
                      * 2021): where reflected rays start, so that a coarse mesh with
                      * smooth normals has no dark band at the shadow terminator */
    bool lifted;     /* p_smooth is clearly above the triangle (beyond rounding) */
    float3 ng;       /* geometric normal, flipped to the side the ray came from */
    float3 ns;       /* shading normal, in the same hemisphere as ng */
#ifdef PATHCL_HAS_CLEARCOAT
    float3 n_coat; /* the clear coat's normal: the interpolated one, which the base's normal
                    * map does not bend, bent by the coat's own (KHR_materials_clearcoat) */
#endif
#ifdef PATHCL_HAS_ANISOTROPY
    float3 t_aniso; /* the direction of KHR_materials_anisotropy's larger roughness, in the
                     * shading plane (texture/anisotropy.cl); 0 where it has none */
#endif
    bool front_face; /* the ray hit the counter-clockwise (emitting) side */
    float area;
    int material;
    int emitter;
} SurfacePoint;

static inline float3 barycentric_point(float3 v0, float3 v1, float3 v2, float b1, float b2, float3* error)
{
    float b0 = 1.0f - b1 - b2;
    float3 p0 = b0 * v0, p1 = b1 * v1, p2 = b2 * v2;
    *error = FLOAT_GAMMA(7) * (fabs(p0) + fabs(p1) + fabs(p2));
    return p0 + p1 + p2;
}

static inline SurfacePoint surface_point(const KernelData* kd, Hit hit, float3 wo)
{
    SurfacePoint sp;
    Triangle tri = kd->triangles[hit.triangle];
    TriangleShading sh = kd->shading[hit.triangle];
    float3 v0 = tri.v0.xyz, v1 = tri.v1.xyz, v2 = tri.v2.xyz;
    float3 n0 = sh.n0.xyz, n1 = sh.n1.xyz, n2 = sh.n2.xyz;
#ifdef PATHCL_HAS_INSTANCES
    /* An instance's triangle is taken to render space vertex by vertex; the point's error
     * bound grows by the vertices' rounding and by that of the ray's origin mapped into
     * the instance's space, so that a ray spawned from it starts clear of the surface in
     * both spaces. */
    Instance inst = kd->instances[hit.instance];
    bool placed = !(inst.flags & INSTANCE_IDENTITY);
    float3 placement_error = (float3)(0.0f);
    if (placed) {
        placement_error = fmax(affine_point_error(inst.to_render, v0),
                               fmax(affine_point_error(inst.to_render, v1), affine_point_error(inst.to_render, v2)));
        v0 = affine_point(inst.to_render, v0);
        v1 = affine_point(inst.to_render, v1);
        v2 = affine_point(inst.to_render, v2);
        n0 = normalize(instance_normal(&inst, n0));
        n1 = normalize(instance_normal(&inst, n1));
        n2 = normalize(instance_normal(&inst, n2));
    }
#endif
    sp.p = barycentric_point(v0, v1, v2, hit.b1, hit.b2, &sp.p_error);
#ifdef PATHCL_HAS_INSTANCES
    if (placed) {
        float3 back = affine_point_error(inst.to_object, sp.p); /* the spawned origin's, in mesh space */
        sp.p_error +=
            placement_error + (float3)(dot(fabs(inst.to_render[0].xyz), back), dot(fabs(inst.to_render[1].xyz), back),
                                       dot(fabs(inst.to_render[2].xyz), back));
    }
#endif
    float3 c = cross(v1 - v0, v2 - v0);
#ifdef PATHCL_HAS_INSTANCES
    if (inst.flags & INSTANCE_MIRRORED)
        c = -c; /* the front stays where the mesh's own counter-clockwise side maps */
#endif
    float len = length(c);
    sp.area = 0.5f * len;
    float3 ng = c / len;
    float b0 = 1.0f - hit.b1 - hit.b2;
    float3 ns = b0 * n0 + hit.b1 * n1 + hit.b2 * n2;
    float ns_len = length(ns);
    ns = (ns_len > 0.0f && isfinite(ns_len)) ? ns / ns_len : ng;
    if (dot(ns, ng) < 0.0f)
        ns = -ns;
    sp.front_face = dot(ng, wo) > 0.0f;
    if (!sp.front_face) {
        ng = -ng;
        ns = -ns;
    }
    sp.ng = ng;
    sp.ns = ns;
#ifdef PATHCL_HAS_CLEARCOAT
    sp.n_coat = ns;
#endif
#ifdef PATHCL_HAS_ANISOTROPY
    sp.t_aniso = (float3)(0.0f);
#endif
    /* Hanika's terminator offset: for each vertex, the part of p below the plane through
     * that vertex perpendicular to its normal (on wo's side), lifted out of it, weighted
     * by the barycentrics. Zero on flat triangles and wherever the mesh is concave. */
    sp.p_smooth = sp.p;
    sp.lifted = false;
    float3 front = c / len;
    if (any(n0 != n1) || any(n0 != n2) || any(n0 != front)) {
        n0 = dot(n0, front) < 0.0f ? -n0 : n0; /* vertex normals on the front side */
        n1 = dot(n1, front) < 0.0f ? -n1 : n1;
        n2 = dot(n2, front) < 0.0f ? -n2 : n2;
        float side = sp.front_face ? 1.0f : -1.0f;
        float3 lift = b0 * fmin(0.0f, side * dot(sp.p - v0, n0)) * n0 +
                      hit.b1 * fmin(0.0f, side * dot(sp.p - v1, n1)) * n1 +
                      hit.b2 * fmin(0.0f, side * dot(sp.p - v2, n2)) * n2;
        sp.p_smooth = sp.p - side * lift;
        sp.lifted = -side * dot(lift, ng) > 4.0f * dot(fabs(ng), sp.p_error);
    }
    sp.material = sh.material;
    sp.emitter = sh.emitter;
    return sp;
}
