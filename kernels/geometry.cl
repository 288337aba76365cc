/* Surface points, shading frames and robust ray spawning. Needs: shared_types.h, bvh.cl.
 *
 * Spawned rays start at the hit point pushed along the geometric normal by pbrt's
 * conservative bound on the point's rounding error, then rounded one more ulp away. The
 * bound scales with the coordinates, so this stays correct at 1e-6 and at 1e6 from the
 * origin, where any fixed epsilon is either too small (acne) or too big (leaks). */

typedef struct {
    float3 p;       /* world position, from barycentrics (more accurate than o + t d) */
    float3 p_error; /* per-axis bound on |p - exact p| */
    float3 p_smooth; /* p lifted onto the smooth surface the vertex normals describe (Hanika
                      * 2021): where reflected rays start, so that a coarse mesh with
                      * smooth normals has no dark band at the shadow terminator */
    bool lifted;     /* p_smooth is clearly above the triangle (beyond rounding) */
    float3 ng;      /* geometric normal, flipped to the side the ray came from */
    float3 ns;      /* shading normal, in the same hemisphere as ng */
    bool front_face; /* the ray hit the counter-clockwise (emitting) side */
    float area;
    int material;
    int emitter;
} SurfacePoint;

/* Orthonormal basis around a unit vector (Duff et al. 2017, branchless). */
static inline void make_basis(float3 n, float3* t, float3* b)
{
    float sign = copysign(1.0f, n.z);
    float a = -1.0f / (sign + n.z);
    float c = n.x * n.y * a;
    *t = (float3)(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
    *b = (float3)(c, sign + n.y * n.y * a, -n.y);
}

static inline float3 barycentric_point(float3 v0, float3 v1, float3 v2, float b1, float b2,
                                float3* error)
{
    float b0 = 1.0f - b1 - b2;
    float3 p0 = b0 * v0, p1 = b1 * v1, p2 = b2 * v2;
    *error = FLOAT_GAMMA(7) * (fabs(p0) + fabs(p1) + fabs(p2));
    return p0 + p1 + p2;
}

static inline SurfacePoint surface_point(__global const Triangle* triangles,
                                  __global const TriangleShading* shading, Hit hit, float3 wo)
{
    SurfacePoint sp;
    Triangle tri = triangles[hit.triangle];
    TriangleShading sh = shading[hit.triangle];
    float3 v0 = tri.v0.xyz, v1 = tri.v1.xyz, v2 = tri.v2.xyz;
    sp.p = barycentric_point(v0, v1, v2, hit.b1, hit.b2, &sp.p_error);
    float3 c = cross(v1 - v0, v2 - v0);
    float len = length(c);
    sp.area = 0.5f * len;
    float3 ng = c / len;
    float b0 = 1.0f - hit.b1 - hit.b2;
    float3 ns = b0 * sh.n0.xyz + hit.b1 * sh.n1.xyz + hit.b2 * sh.n2.xyz;
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
    /* Hanika's terminator offset: for each vertex, the part of p below the plane through
     * that vertex perpendicular to its normal (on wo's side), lifted out of it, weighted
     * by the barycentrics. Zero on flat triangles and wherever the mesh is concave. */
    sp.p_smooth = sp.p;
    sp.lifted = false;
    float3 n0 = sh.n0.xyz, n1 = sh.n1.xyz, n2 = sh.n2.xyz, front = c / len;
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
#ifdef PATHCL_FAULT_SHADING_NORMAL_ONLY /* a naive renderer, for the thin-gap test: no lift */
    sp.p_smooth = sp.p;
    sp.lifted = false;
#endif
    sp.material = sh.material;
    sp.emitter = sh.emitter;
    return sp;
}

/* Origin for a ray leaving p in direction w (on either side of the surface n). */
static inline float3 offset_ray_origin(float3 p, float3 p_error, float3 n, float3 w)
{
    float d = dot(fabs(n), p_error);
    float3 offset = d * n;
    if (dot(w, n) < 0.0f)
        offset = -offset;
    float3 po = p + offset;
    po = select(po, nextafter(po, (float3)(INFINITY)), offset > 0.0f);
    po = select(po, nextafter(po, (float3)(-INFINITY)), offset < 0.0f);
    return po;
}

/* The part of a shadow ray's segment that is tested, as a fraction of its length. The
 * end point on an area or sphere light is already pushed off its surface by its error
 * bound, and a point light has no surface, so only a few ulps are left out: an occluder
 * 1e-4 of the way from the light (a lamp shade) still casts its shadow. */
#define SHADOW_RAY_EXTENT (1.0f - 8.0f * 0x1.0p-24f)

/* Whether a direction on the shading normal's side (cos_ig = its cosine with ng) counts
 * as leaving on wo's side. Above the geometric surface it does. Below it only where the
 * point is lifted onto the smooth surface: a ray from there towards wi that meets the
 * mesh is shadowed by it, as the coarse mesh would shadow it, and one that clears it is
 * lit, as the smooth surface would be; that is Hanika's terminator fix. Without a lift a
 * ray below the triangle would start behind it and could leak light through it. */
static inline bool above_surface(const SurfacePoint* sp, float cos_ig)
{
#ifdef PATHCL_FAULT_SHADING_NORMAL_ONLY /* the shading normal alone decides */
    return true;
#endif
    return cos_ig > 0.0f || sp->lifted;
}

/* Origin for a ray leaving the surface point in direction w: a reflected ray (on the
 * shading normal's side) from the smooth surface, pushed off wo's side of the triangle;
 * a transmitted one from the triangle, pushed off its far side. */
static inline float3 spawn_ray_origin(const SurfacePoint* sp, float3 w)
{
#ifdef PATHCL_FAULT_SHADING_NORMAL_ONLY /* a naive renderer: no lift, offset to w's side */
    return offset_ray_origin(sp->p, sp->p_error, sp->ng, w);
#endif
    if (dot(w, sp->ns) > 0.0f && above_surface(sp, dot(w, sp->ng)))
        return offset_ray_origin(sp->p_smooth, sp->p_error, sp->ng, sp->ng);
    return offset_ray_origin(sp->p, sp->p_error, sp->ng, w);
}
