/* The surface point at a hit and robust ray spawning, per lane: the arithmetic of
 * geom/surface_point.cl and geom/ray_offset.cl (which say why), component by component.
 * Triangles without instances. */
#include "kernel_data.cl"
#include "util/math.cl"
#include "wavefront/lanes.cl"

typedef struct {
    Lane3 p, p_error, p_smooth, ng, ns;
    LaneI lifted, front_face; /* masks */
    LaneI material, emitter;
} LaneSurfacePoint;

/* b0 v0 + b1 v1 + b2 v2 with b0 = 1 - b1 - b2, and its rounding bound. */
PATHCL_ALWAYS_INLINE static inline Lane3 lane_barycentric_point(Lane3 v0, Lane3 v1, Lane3 v2, LaneF b1, LaneF b2,
                                                                Lane3* error)
{
    LaneF b0 = 1.0f - b1 - b2;
    Lane3 p0 = lane3_scale(v0, b0), p1 = lane3_scale(v1, b1), p2 = lane3_scale(v2, b2);
    *error =
        lane3_scale(lane3_add(lane3_add(lane3_fabs(p0), lane3_fabs(p1)), lane3_fabs(p2)), lane_splat(FLOAT_GAMMA(7)));
    return lane3_add(lane3_add(p0, p1), p2);
}

/* n turned to front's side. */
PATHCL_ALWAYS_INLINE static inline Lane3 lane_toward(Lane3 n, Lane3 front)
{
    return lane3_select(lane3_dot(n, front) < 0.0f, lane3_neg(n), n);
}

/* One vertex's part of Hanika's lift: b fmin(0, side dot(p - v, n)) n. */
PATHCL_ALWAYS_INLINE static inline Lane3 lane_lift_part(LaneF b, LaneF side, Lane3 p, Lane3 v, Lane3 n)
{
    return lane3_scale(n, b * fmin(0.0f, side * lane3_dot(lane3_sub(p, v), n)));
}

/* The surface points of the lanes' hits on `triangle` (lanes in `m`; the others read
 * triangle 0). */
PATHCL_ALWAYS_INLINE static inline LaneSurfacePoint lane_surface_point(const KernelData* kd, LaneI m, LaneI triangle,
                                                                       LaneF b1, LaneF b2, Lane3 wo)
{
    LaneSurfacePoint sp;
    LaneI t = select(lane_splat_i(0), triangle, m);
    Lane3 v0 = LANE3_GATHER(kd->triangles, v0, t), v1 = LANE3_GATHER(kd->triangles, v1, t),
          v2 = LANE3_GATHER(kd->triangles, v2, t);
    Lane3 n0 = LANE3_GATHER(kd->shading, n0, t), n1 = LANE3_GATHER(kd->shading, n1, t),
          n2 = LANE3_GATHER(kd->shading, n2, t);
    sp.p = lane_barycentric_point(v0, v1, v2, b1, b2, &sp.p_error);
    Lane3 c = lane3_cross(lane3_sub(v1, v0), lane3_sub(v2, v0));
    Lane3 front = lane3_div(c, lane3_length(c));
    LaneF b0 = 1.0f - b1 - b2;
    Lane3 ns = lane3_add(lane3_add(lane3_scale(n0, b0), lane3_scale(n1, b1)), lane3_scale(n2, b2));
    LaneF ns_len = lane3_length(ns);
    ns = lane3_select((ns_len > 0.0f) & isfinite(ns_len), lane3_div(ns, ns_len), front);
    ns = lane_toward(ns, front);
    sp.front_face = lane3_dot(front, wo) > 0.0f;
    LaneF side = select(lane_splat(-1.0f), lane_splat(1.0f), sp.front_face);
    sp.ng = lane3_scale(front, side);
    sp.ns = lane3_scale(ns, side);
    /* Hanika's terminator offset, where the vertex normals bend away from the face. */
    sp.p_smooth = sp.p;
    sp.lifted = lane_splat_i(0);
    LaneI curved = m & !(lane3_equal(n0, n1) & lane3_equal(n0, n2) & lane3_equal(n0, front));
    if (LANE_ANY(curved)) {
        n0 = lane_toward(n0, front);
        n1 = lane_toward(n1, front);
        n2 = lane_toward(n2, front);
        Lane3 lift =
            lane3_add(lane3_add(lane_lift_part(b0, side, sp.p, v0, n0), lane_lift_part(b1, side, sp.p, v1, n1)),
                      lane_lift_part(b2, side, sp.p, v2, n2));
        sp.p_smooth = lane3_select(curved, lane3_sub(sp.p, lane3_scale(lift, side)), sp.p);
        sp.lifted = curved & (-side * lane3_dot(lift, sp.ng) > 4.0f * lane3_dot(lane3_fabs(sp.ng), sp.p_error));
    }
    sp.material = lane_gather_i(LANE_FIELD_I(kd->shading, material), t, LANE_STRIDE(kd->shading));
    sp.emitter = lane_gather_i(LANE_FIELD_I(kd->shading, emitter), t, LANE_STRIDE(kd->shading));
    return sp;
}

/* geom/ray_offset.cl's offset_ray_origin. */
PATHCL_ALWAYS_INLINE static inline Lane3 lane_offset_ray_origin(Lane3 p, Lane3 p_error, Lane3 n, Lane3 w)
{
    Lane3 offset = lane3_scale(n, lane3_dot(lane3_fabs(n), p_error));
    offset = lane3_select(lane3_dot(w, n) < 0.0f, lane3_neg(offset), offset);
    Lane3 po = lane3_add(p, offset);
    LaneF up = lane_splat(INFINITY), down = lane_splat(-INFINITY);
    po.x = select(po.x, nextafter(po.x, up), offset.x > 0.0f);
    po.x = select(po.x, nextafter(po.x, down), offset.x < 0.0f);
    po.y = select(po.y, nextafter(po.y, up), offset.y > 0.0f);
    po.y = select(po.y, nextafter(po.y, down), offset.y < 0.0f);
    po.z = select(po.z, nextafter(po.z, up), offset.z > 0.0f);
    po.z = select(po.z, nextafter(po.z, down), offset.z < 0.0f);
    return po;
}

PATHCL_ALWAYS_INLINE static inline LaneI lane_above_surface(const LaneSurfacePoint* sp, LaneF cos_ig)
{
    return (cos_ig > 0.0f) | sp->lifted;
}

/* geom/ray_offset.cl's spawn_ray_origin. */
PATHCL_ALWAYS_INLINE static inline Lane3 lane_spawn_ray_origin(const LaneSurfacePoint* sp, Lane3 w)
{
    LaneI reflected = (lane3_dot(w, sp->ns) > 0.0f) & lane_above_surface(sp, lane3_dot(w, sp->ng));
    return lane_offset_ray_origin(lane3_select(reflected, sp->p_smooth, sp->p), sp->p_error, sp->ng,
                                  lane3_select(reflected, sp->ng, w));
}
