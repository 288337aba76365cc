/* Texture lookups: the interpolated (u, v) goes through the view's KHR_texture_transform
 * matrix, is wrapped per axis (repeat, clamp to edge, mirrored repeat), and is filtered
 * bilinearly (or nearest) between texel centres at ((i + 0.5) / width, (j + 0.5) /
 * height). sRGB texels are decoded to linear before filtering: 8-bit ones through an
 * exact 256-entry table, 16-bit ones by the formula. No mipmapping: without ray
 * differentials there is no footprint to choose a level from; supersampling the pixel
 * filters minified textures instead. Compiled only for scenes with textures
 * (PATHCL_HAS_TEXTURES). */
#include "features.h"
#include "kernel_data.cl"
#include "texture/srgb.h"
#include "texture/wrap.h"

#ifdef PATHCL_HAS_TEXTURES

/* sRGB (IEC 61966-2-1) decoding of the 8-bit value i, i / 255 -> linear, each entry the
 * exact value rounded to float (tested against the host's formula for all 256). */
/* clang-format off */
__constant float SRGB8_TO_LINEAR[256] = {
    0.0f, 0x1.3e4568p-12f, 0x1.3e4568p-11f, 0x1.dd681cp-11f, 0x1.3e4568p-10f, 0x1.8dd6c2p-10f,
    0x1.dd681cp-10f, 0x1.167cbap-9f, 0x1.3e4568p-9f, 0x1.660e14p-9f, 0x1.8dd6c2p-9f, 0x1.b6a31cp-9f,
    0x1.e1e31ep-9f, 0x1.07c38cp-8f, 0x1.1fcc2cp-8f, 0x1.390ffap-8f, 0x1.53936cp-8f, 0x1.6f5adep-8f,
    0x1.8c6a94p-8f, 0x1.aac6cp-8f, 0x1.ca7382p-8f, 0x1.eb74e2p-8f, 0x1.06e76cp-7f, 0x1.18c2a6p-7f,
    0x1.2b4e0ap-7f, 0x1.3e8b7cp-7f, 0x1.527cd6p-7f, 0x1.6723eep-7f, 0x1.7c8292p-7f, 0x1.929a88p-7f,
    0x1.a96d92p-7f, 0x1.c0fd68p-7f, 0x1.d94bbep-7f, 0x1.f25a44p-7f, 0x1.061552p-6f, 0x1.135f3ep-6f,
    0x1.210bb8p-6f, 0x1.2f1b8cp-6f, 0x1.3d8f84p-6f, 0x1.4c6866p-6f, 0x1.5ba6fap-6f, 0x1.6b4c04p-6f,
    0x1.7b5842p-6f, 0x1.8bcc74p-6f, 0x1.9ca958p-6f, 0x1.adefaap-6f, 0x1.bfa02p-6f, 0x1.d1bb74p-6f,
    0x1.e4425ap-6f, 0x1.f73586p-6f, 0x1.054ad4p-5f, 0x1.0f31bap-5f, 0x1.194fccp-5f, 0x1.23a55ep-5f,
    0x1.2e32c8p-5f, 0x1.38f86p-5f, 0x1.43f678p-5f, 0x1.4f2d64p-5f, 0x1.5a9d76p-5f, 0x1.664702p-5f,
    0x1.722a56p-5f, 0x1.7e47c8p-5f, 0x1.8a9fa4p-5f, 0x1.97323ap-5f, 0x1.a3ffd8p-5f, 0x1.b108dp-5f,
    0x1.be4d6cp-5f, 0x1.cbcdfap-5f, 0x1.d98ac6p-5f, 0x1.e7841cp-5f, 0x1.f5ba48p-5f, 0x1.0216cap-4f,
    0x1.096f26p-4f, 0x1.10e65cp-4f, 0x1.187c9p-4f, 0x1.2031e8p-4f, 0x1.280688p-4f, 0x1.2ffa92p-4f,
    0x1.380e2ap-4f, 0x1.404174p-4f, 0x1.489494p-4f, 0x1.5107acp-4f, 0x1.599adep-4f, 0x1.624e4ep-4f,
    0x1.6b221ep-4f, 0x1.74167p-4f, 0x1.7d2b66p-4f, 0x1.86612p-4f, 0x1.8fb7cp-4f, 0x1.992f68p-4f,
    0x1.a2c83ap-4f, 0x1.ac8256p-4f, 0x1.b65ddcp-4f, 0x1.c05aecp-4f, 0x1.ca79a8p-4f, 0x1.d4ba3p-4f,
    0x1.df1ca2p-4f, 0x1.e9a12p-4f, 0x1.f447cap-4f, 0x1.ff10bcp-4f, 0x1.04fe0cp-3f, 0x1.0a84fep-3f,
    0x1.101d44p-3f, 0x1.15c6eep-3f, 0x1.1b8208p-3f, 0x1.214ea6p-3f, 0x1.272cd4p-3f, 0x1.2d1ca2p-3f,
    0x1.331e1ep-3f, 0x1.393158p-3f, 0x1.3f566p-3f, 0x1.458d42p-3f, 0x1.4bd60ep-3f, 0x1.5230d4p-3f,
    0x1.589dap-3f, 0x1.5f1c84p-3f, 0x1.65ad8ap-3f, 0x1.6c50c4p-3f, 0x1.73063ep-3f, 0x1.79ce06p-3f,
    0x1.80a82ep-3f, 0x1.8794cp-3f, 0x1.8e93ccp-3f, 0x1.95a55ep-3f, 0x1.9cc986p-3f, 0x1.a40052p-3f,
    0x1.ab49cep-3f, 0x1.b2a60ap-3f, 0x1.ba1512p-3f, 0x1.c196f4p-3f, 0x1.c92bbep-3f, 0x1.d0d37cp-3f,
    0x1.d88e3ep-3f, 0x1.e05c0ep-3f, 0x1.e83cfcp-3f, 0x1.f03116p-3f, 0x1.f83866p-3f, 0x1.00297ep-2f,
    0x1.044072p-2f, 0x1.086116p-2f, 0x1.0c8b7p-2f, 0x1.10bf86p-2f, 0x1.14fd6p-2f, 0x1.194502p-2f,
    0x1.1d9676p-2f, 0x1.21f1bep-2f, 0x1.2656e4p-2f, 0x1.2ac5ecp-2f, 0x1.2f3edep-2f, 0x1.33c1cp-2f,
    0x1.384e98p-2f, 0x1.3ce56cp-2f, 0x1.418642p-2f, 0x1.46312p-2f, 0x1.4ae60ep-2f, 0x1.4fa51p-2f,
    0x1.546e2cp-2f, 0x1.59416cp-2f, 0x1.5e1edp-2f, 0x1.630664p-2f, 0x1.67f82ap-2f, 0x1.6cf428p-2f,
    0x1.71fa68p-2f, 0x1.770aecp-2f, 0x1.7c25bcp-2f, 0x1.814adcp-2f, 0x1.867a54p-2f, 0x1.8bb428p-2f,
    0x1.90f86p-2f, 0x1.9647p-2f, 0x1.9ba01p-2f, 0x1.a10394p-2f, 0x1.a67192p-2f, 0x1.abea1p-2f,
    0x1.b16d14p-2f, 0x1.b6faa4p-2f, 0x1.bc92c6p-2f, 0x1.c2357ep-2f, 0x1.c7e2d2p-2f, 0x1.cd9acap-2f,
    0x1.d35d6ap-2f, 0x1.d92ab6p-2f, 0x1.df02b8p-2f, 0x1.e4e57p-2f, 0x1.ead2e8p-2f, 0x1.f0cb26p-2f,
    0x1.f6ce2cp-2f, 0x1.fcdcp-2f, 0x1.017a56p-1f, 0x1.048c18p-1f, 0x1.07a34ap-1f, 0x1.0abfeep-1f,
    0x1.0de208p-1f, 0x1.11099ap-1f, 0x1.1436a8p-1f, 0x1.176932p-1f, 0x1.1aa13ep-1f, 0x1.1ddecap-1f,
    0x1.2121dep-1f, 0x1.246a7ap-1f, 0x1.27b8ap-1f, 0x1.2b0c54p-1f, 0x1.2e6598p-1f, 0x1.31c46ep-1f,
    0x1.3528dcp-1f, 0x1.3892ep-1f, 0x1.3c028p-1f, 0x1.3f77bcp-1f, 0x1.42f29ap-1f, 0x1.467318p-1f,
    0x1.49f93ep-1f, 0x1.4d850ap-1f, 0x1.511682p-1f, 0x1.54ada4p-1f, 0x1.584a78p-1f, 0x1.5becfep-1f,
    0x1.5f9538p-1f, 0x1.634328p-1f, 0x1.66f6d4p-1f, 0x1.6ab03ap-1f, 0x1.6e6f6p-1f, 0x1.723448p-1f,
    0x1.75fef4p-1f, 0x1.79cf64p-1f, 0x1.7da59ep-1f, 0x1.8181a4p-1f, 0x1.856378p-1f, 0x1.894b1cp-1f,
    0x1.8d3892p-1f, 0x1.912bdep-1f, 0x1.9525p-1f, 0x1.9923fep-1f, 0x1.9d28d8p-1f, 0x1.a13392p-1f,
    0x1.a5442cp-1f, 0x1.a95aacp-1f, 0x1.ad771p-1f, 0x1.b1995ep-1f, 0x1.b5c198p-1f, 0x1.b9efbep-1f,
    0x1.be23d4p-1f, 0x1.c25ddep-1f, 0x1.c69ddcp-1f, 0x1.cae3d2p-1f, 0x1.cf2fcp-1f, 0x1.d381aap-1f,
    0x1.d7d994p-1f, 0x1.dc377ep-1f, 0x1.e09b6ap-1f, 0x1.e5055cp-1f, 0x1.e97556p-1f, 0x1.edeb5cp-1f,
    0x1.f2676cp-1f, 0x1.f6e98cp-1f, 0x1.fb71bcp-1f, 0x1p+0f
};
/* clang-format on */

/* Texel (x, y) of an image (indices already wrapped), RGBA in [0, 1], RGB decoded from
 * sRGB when asked. Alpha is always linear. */
static inline float4 texel_load(const KernelData* kd, const TextureImage* img, int x, int y, bool srgb)
{
    uint index = (uint)y * img->width + (uint)x;
    float4 t;
    if (img->format == TEXTURE_FORMAT_RGBA16) {
        uint2 w = vload2(index, kd->texels + img->offset);
        t = (float4)((float)(w.x & 0xffffu), (float)(w.x >> 16), (float)(w.y & 0xffffu), (float)(w.y >> 16)) *
            (1.0f / 65535.0f);
        if (srgb)
            t.xyz = (float3)(srgb_to_linear(t.x), srgb_to_linear(t.y), srgb_to_linear(t.z));
        return t;
    }
    uint w = kd->texels[img->offset + index];
    uint4 c = (uint4)(w & 0xffu, (w >> 8) & 0xffu, (w >> 16) & 0xffu, w >> 24);
    t = convert_float4(c) * (1.0f / 255.0f);
    if (srgb)
        t.xyz = (float3)(SRGB8_TO_LINEAR[c.x], SRGB8_TO_LINEAR[c.y], SRGB8_TO_LINEAR[c.z]);
    return t;
}

/* The texture value of view `view_index` at texture coordinate uv (before its
 * transform): RGBA, linear. */
static inline float4 texture_sample(const KernelData* kd, int view_index, float2 uv)
{
    TextureView view = kd->texture_views[view_index];
    TextureImage img = kd->texture_images[view.image];
    bool srgb = (view.flags & TEXTURE_SRGB) != 0u;
    float3 uv1 = (float3)(uv, 1.0f);
    float u = wrap_coordinate(dot(view.transform_u.xyz, uv1), view.wrap_s);
    float v = wrap_coordinate(dot(view.transform_v.xyz, uv1), view.wrap_t);
    int w = (int)img.width, h = (int)img.height;
    if (view.flags & TEXTURE_NEAREST) {
        int x = wrap_texel((int)floor(u * (float)w), w, view.wrap_s);
        int y = wrap_texel((int)floor(v * (float)h), h, view.wrap_t);
        return texel_load(kd, &img, x, y, srgb);
    }
    /* Bilinear between the four texel centres around (u, v). Written as a + f (b - a),
     * which returns a exactly when a == b (a constant texture is its constant). */
    float x = u * (float)w - 0.5f, y = v * (float)h - 0.5f;
    float x0 = floor(x), y0 = floor(y);
    float fx = x - x0, fy = y - y0;
    int xa = wrap_texel((int)x0, w, view.wrap_s), xb = wrap_texel((int)x0 + 1, w, view.wrap_s);
    int ya = wrap_texel((int)y0, h, view.wrap_t), yb = wrap_texel((int)y0 + 1, h, view.wrap_t);
    float4 t00 = texel_load(kd, &img, xa, ya, srgb), t10 = texel_load(kd, &img, xb, ya, srgb);
    float4 t01 = texel_load(kd, &img, xa, yb, srgb), t11 = texel_load(kd, &img, xb, yb, srgb);
    float4 top = t00 + fx * (t10 - t00);
    float4 bottom = t01 + fx * (t11 - t01);
    return top + fy * (bottom - top);
}

/* The view's texture coordinate at barycentrics (b1, b2) of a triangle. */
static inline float2 triangle_texcoord(const KernelData* kd, const TextureView* view, int triangle, float b1, float b2)
{
    TriangleTexcoords t = kd->texcoords[view->texcoord_base + (uint)triangle];
    float b0 = 1.0f - b1 - b2;
    return b0 * t.uv01.xy + b1 * t.uv01.zw + b2 * t.uv2.xy;
}

/* The texture value of view `view_index` at barycentrics (b1, b2) of a triangle. */
static inline float4 texture_at(const KernelData* kd, int view_index, int triangle, float b1, float b2)
{
    TextureView view = kd->texture_views[view_index];
    return texture_sample(kd, view_index, triangle_texcoord(kd, &view, triangle, b1, b2));
}

#endif /* PATHCL_HAS_TEXTURES */
