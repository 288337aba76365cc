/* Camera rays: one per pixel per pass, from a pinhole, a thin lens or an orthographic
 * camera. Camera samples fall uniformly inside their own pixel (box filter); the film
 * position takes the sampler's pair at DIM_PIXEL, the lens position the pair at DIM_LENS. */
#include "features.h"
#include "film/pixel.cl"
#include "kernel_data.cl"
#include "sample/dimensions.h"
#include "sample/sampler.cl"
#include "sample/warp.cl"

/* film_uv in [0, 1)^2 with v down the image; lens_u in [0, 1)^2 (used by a thin lens). */
static inline Ray camera_generate_ray(const Camera* cam, float2 film_uv, float2 lens_u)
{
    /* The sensor maps to [-1, 1]^2, y up. */
    float sx = 2.0f * film_uv.x - 1.0f;
    float sy = 1.0f - 2.0f * film_uv.y;
    /* The pinhole ray: origin o, direction d with unit component along forward. */
    float3 o = cam->position.xyz;
    float3 d = cam->forward.xyz;
    if (cam->type == CAMERA_ORTHOGRAPHIC)
        o = o + sx * cam->right.xyz + sy * cam->up.xyz;
    else
        d = d + sx * cam->right.xyz + sy * cam->up.xyz;
    Ray ray;
#ifdef PATHCL_HAS_THIN_LENS
    if (cam->lens_radius > 0.0f) {
        /* The pinhole ray meets the plane of focus (distance focus_distance along forward)
         * at o + focus_distance d; the lens ray starts on the disk around o and passes
         * through that point. The concentric map keeps stratified lens samples stratified. */
        float3 focus = o + cam->focus_distance * d;
        float2 disk = cam->lens_radius * sample_concentric_disk(lens_u);
        float3 lens = o + disk.x * normalize(cam->right.xyz) + disk.y * normalize(cam->up.xyz);
        ray.origin = (float4)(lens, 0.0f);
        ray.direction = (float4)(normalize(focus - lens), 0.0f);
        return ray;
    }
#endif
    ray.origin = (float4)(o, 0.0f);
    ray.direction = (float4)(normalize(d), 0.0f);
    return ray;
}

/* Writes the camera ray of this pass's sample for every pixel into kd.rays. */
PATHCL_KERNEL void generate_camera_rays(PATHCL_KERNEL_PARAMS FrameParams frame)
{
    PATHCL_KERNEL_DATA;
    uint2 xy;
    uint pixel;
    if (!frame_pixel(&frame, &xy, &pixel) || !pixel_active(&frame, kd.active, pixel))
        return;
    SamplerState sampler = frame_sampler(&frame, pixel, DIM_PIXEL);
    float2 offset = sampler_get_2d(&sampler);
    float2 film_uv =
        (float2)(((float)xy.x + offset.x) / (float)frame.width, ((float)xy.y + offset.y) / (float)frame.height);
    float2 lens_u = (float2)(0.0f);
#ifdef PATHCL_HAS_THIN_LENS
    sampler.dimension = DIM_LENS;
    lens_u = sampler_get_2d(&sampler);
#endif
    Camera cam = kd.camera[0];
    kd.rays[pixel] = camera_generate_ray(&cam, film_uv, lens_u);
}
