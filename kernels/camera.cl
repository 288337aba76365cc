/* Camera rays: one per pixel per pass. Camera samples fall uniformly inside their own
 * pixel (box filter). Needs: shared_types.h, samplers.cl. */

static inline Ray camera_generate_ray(const Camera* cam, float2 film_uv)
{
    /* film_uv in [0, 1)^2 with v down the image; the sensor maps to [-1, 1]^2, y up. */
    float sx = 2.0f * film_uv.x - 1.0f;
    float sy = 1.0f - 2.0f * film_uv.y;
    Ray ray;
    ray.origin = cam->position;
    float3 d = cam->forward.xyz + sx * cam->right.xyz + sy * cam->up.xyz;
    ray.direction = (float4)(normalize(d), 0.0f);
    return ray;
}

__kernel void generate_camera_rays(__global Ray* rays, Camera camera, FrameParams frame)
{
    uint x = get_global_id(0);
    uint y = get_global_id(1);
    if (x >= frame.width || y >= frame.height)
        return;
    uint pixel = y * frame.width + x;
    SamplerState sampler = sampler_start(pixel, frame.sample_index, frame.seed, DIM_PIXEL);
    float2 offset = sampler_get_2d(&sampler);
    float2 film_uv = (float2)(((float)x + offset.x) / (float)frame.width,
                              ((float)y + offset.y) / (float)frame.height);
    rays[pixel] = camera_generate_ray(&camera, film_uv);
}
