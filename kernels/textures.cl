/* Textures and the other per-vertex inputs of a material: texture lookups, vertex colours
 * and normal mapping. Needs: shared_types.h, bvh.cl (Hit), geometry.cl (SurfacePoint).
 *
 * A material's inputs are applied once per shading point, to a private copy of its
 * Material (apply_material_inputs): each texture value multiplies its factor as glTF
 * defines, COLOR_0 multiplies the base colour, and a normal texture replaces the shading
 * normal. bsdf_params and the emission code then read the copy, so they need no texture
 * code of their own. Triangle lights read their emissive texture at the sampled point
 * through the same texture_at, so a light sample and a ray that hits the same point see
 * the same radiance.
 *
 * A lookup (texture_sample): the interpolated (u, v) goes through the view's
 * KHR_texture_transform matrix, is wrapped per axis (repeat, clamp to edge, mirrored
 * repeat), and is filtered bilinearly (or nearest) between texel centres at
 * ((i + 0.5) / width, (j + 0.5) / height). sRGB texels are decoded to linear before
 * filtering: 8-bit ones through an exact 256-entry table, 16-bit ones by the formula.
 * No mipmapping: without ray differentials there is no footprint to choose a level from;
 * supersampling the pixel filters minified textures instead.
 *
 * Scenes without textures, normal maps or vertex colours compile none of this (the
 * PATHCL_HAS_TEXTURES / _NORMAL_MAPS / _VERTEX_COLORS defines), only the buffer struct. */

/* Everything a material reads besides its Material: the texel data and the per-triangle
 * attributes they are looked up with (each buffer a one-element dummy when unused). */
typedef struct {
    __global const uint* texels;
    __global const TextureImage* images;
    __global const TextureView* views;
    __global const TriangleTexcoords* texcoords;
    __global const TriangleTangents* tangents;
    __global const TriangleColors* colors;
} TextureBuffers;

static inline TextureBuffers texture_buffers(__global const uint* texels, __global const TextureImage* images,
                                             __global const TextureView* views,
                                             __global const TriangleTexcoords* texcoords,
                                             __global const TriangleTangents* tangents,
                                             __global const TriangleColors* colors)
{
    TextureBuffers tex;
    tex.texels = texels;
    tex.images = images;
    tex.views = views;
    tex.texcoords = texcoords;
    tex.tangents = tangents;
    tex.colors = colors;
    return tex;
}

#ifdef PATHCL_HAS_TEXTURES

/* sRGB (IEC 61966-2-1) decoding of the 8-bit value i, i / 255 -> linear, each entry the
 * exact value rounded to float (tested against the host's formula for all 256). */
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

static inline float srgb_to_linear(float c)
{
    return c <= 0.04045f ? c * (1.0f / 12.92f) : pow((c + 0.055f) * (1.0f / 1.055f), 2.4f);
}

/* Texel (x, y) of an image (indices already wrapped), RGBA in [0, 1], RGB decoded from
 * sRGB when asked. Alpha is always linear. */
static inline float4 texel_load(const TextureBuffers* tex, const TextureImage* img, int x, int y, bool srgb)
{
    uint index = (uint)y * img->width + (uint)x;
    float4 t;
    if (img->format == TEXTURE_FORMAT_RGBA16) {
        uint2 w = vload2(index, tex->texels + img->offset);
        t = (float4)((float)(w.x & 0xffffu), (float)(w.x >> 16), (float)(w.y & 0xffffu), (float)(w.y >> 16)) *
            (1.0f / 65535.0f);
        if (srgb)
            t.xyz = (float3)(srgb_to_linear(t.x), srgb_to_linear(t.y), srgb_to_linear(t.z));
        return t;
    }
    uint w = tex->texels[img->offset + index];
    uint4 c = (uint4)(w & 0xffu, (w >> 8) & 0xffu, (w >> 16) & 0xffu, w >> 24);
    t = convert_float4(c) * (1.0f / 255.0f);
    if (srgb)
        t.xyz = (float3)(SRGB8_TO_LINEAR[c.x], SRGB8_TO_LINEAR[c.y], SRGB8_TO_LINEAR[c.z]);
    return t;
}

/* A texel index wrapped into [0, n) by the sampler's mode. */
static inline int wrap_texel(int i, int n, uint mode)
{
    if (mode == TEXTURE_WRAP_REPEAT) {
        int r = i % n;
        return r < 0 ? r + n : r;
    }
    if (mode == TEXTURE_WRAP_MIRRORED_REPEAT) {
        int period = 2 * n;
        int r = i % period;
        if (r < 0)
            r += period;
        return r < n ? r : period - 1 - r;
    }
    return clamp(i, 0, n - 1);
}

/* A coordinate moved into one period of its wrap mode before it is scaled to texels, so
 * that large coordinates keep their fraction and texel indices stay small: [0, 1] for
 * repeat, [0, 2] for mirrored repeat, [-1, 2] for clamp (indices are clamped after). */
static inline float wrap_coordinate(float u, uint mode)
{
    if (!isfinite(u))
        return 0.0f;
    if (mode == TEXTURE_WRAP_REPEAT)
        return u - floor(u);
    if (mode == TEXTURE_WRAP_MIRRORED_REPEAT)
        return u - 2.0f * floor(0.5f * u);
    return clamp(u, -1.0f, 2.0f);
}

/* The texture value of view `view_index` at texture coordinate uv (before its
 * transform): RGBA, linear. */
static inline float4 texture_sample(const TextureBuffers* tex, int view_index, float2 uv)
{
    TextureView view = tex->views[view_index];
    TextureImage img = tex->images[view.image];
    bool srgb = (view.flags & TEXTURE_SRGB) != 0u;
    float3 uv1 = (float3)(uv, 1.0f);
    float u = wrap_coordinate(dot(view.transform_u.xyz, uv1), view.wrap_s);
    float v = wrap_coordinate(dot(view.transform_v.xyz, uv1), view.wrap_t);
    int w = (int)img.width, h = (int)img.height;
    if (view.flags & TEXTURE_NEAREST) {
        int x = wrap_texel((int)floor(u * (float)w), w, view.wrap_s);
        int y = wrap_texel((int)floor(v * (float)h), h, view.wrap_t);
        return texel_load(tex, &img, x, y, srgb);
    }
    /* Bilinear between the four texel centres around (u, v). Written as a + f (b - a),
     * which returns a exactly when a == b (a constant texture is its constant). */
    float x = u * (float)w - 0.5f, y = v * (float)h - 0.5f;
    float x0 = floor(x), y0 = floor(y);
    float fx = x - x0, fy = y - y0;
    int xa = wrap_texel((int)x0, w, view.wrap_s), xb = wrap_texel((int)x0 + 1, w, view.wrap_s);
    int ya = wrap_texel((int)y0, h, view.wrap_t), yb = wrap_texel((int)y0 + 1, h, view.wrap_t);
    float4 t00 = texel_load(tex, &img, xa, ya, srgb), t10 = texel_load(tex, &img, xb, ya, srgb);
    float4 t01 = texel_load(tex, &img, xa, yb, srgb), t11 = texel_load(tex, &img, xb, yb, srgb);
    float4 top = t00 + fx * (t10 - t00);
    float4 bottom = t01 + fx * (t11 - t01);
    return top + fy * (bottom - top);
}

/* The view's texture coordinate at barycentrics (b1, b2) of a triangle. */
static inline float2 triangle_texcoord(const TextureBuffers* tex, const TextureView* view, int triangle, float b1,
                                       float b2)
{
    TriangleTexcoords t = tex->texcoords[view->texcoord_base + (uint)triangle];
    float b0 = 1.0f - b1 - b2;
    return b0 * t.uv01.xy + b1 * t.uv01.zw + b2 * t.uv2.xy;
}

/* The texture value of view `view_index` at barycentrics (b1, b2) of a triangle. */
static inline float4 texture_at(const TextureBuffers* tex, int view_index, int triangle, float b1, float b2)
{
    TextureView view = tex->views[view_index];
    return texture_sample(tex, view_index, triangle_texcoord(tex, &view, triangle, b1, b2));
}

#endif /* PATHCL_HAS_TEXTURES */

#ifdef PATHCL_HAS_NORMAL_MAPS

/* The normal-mapped shading normal: n_t = normalize((texel * 2 - 1) * (scale, scale, 1))
 * in the frame T, B = w cross(N, T), N, where N is the interpolated normal and T the
 * interpolated tangent made orthogonal to it. Returns n unchanged where the tangent or the
 * mapped vector is degenerate (a zero or NaN tangent, a texel of (0.5, 0.5, 0.5)). */
static inline float3 normal_from_map(float3 n, TriangleTangents t, float b1, float b2, float3 texel, float scale)
{
    float b0 = 1.0f - b1 - b2;
    float4 tw = b0 * t.t0 + b1 * t.t1 + b2 * t.t2;
    float3 tangent = tw.xyz - dot(tw.xyz, n) * n;
    float len = length(tangent);
    if (!(len > 1.0e-6f) || !isfinite(len))
        return n;
    tangent /= len;
    float3 bitangent = (tw.w < 0.0f ? -1.0f : 1.0f) * cross(n, tangent);
    float3 nt = (2.0f * texel - 1.0f) * (float3)(scale, scale, 1.0f);
    float3 mapped = nt.x * tangent + nt.y * bitangent + nt.z * n;
    float mapped_len = length(mapped);
    if (!(mapped_len > 1.0e-6f) || !isfinite(mapped_len))
        return n;
    return mapped / mapped_len;
}

/* A shading normal that would mirror wo below the geometric surface (or that lies below
 * it) is turned towards ng, in the plane of ng and ns, just far enough that the mirror
 * direction of wo leaves at the height t = min(0.9 cos_o, 0.01) above the surface: the
 * rule of Cycles' ensure_valid_specular_reflection. ng is on wo's side. Solved as a half
 * vector rather than Cycles' quartic: in the frame (x, y, ng), x the part of ns
 * orthogonal to ng, the wanted mirror direction is r = (sqrt(ix^2 + iz^2 - t^2), -wo.y, t)
 * (r.z = t, and wo + r in the plane of x and ng), so the normal is normalize(wo + r) =
 * normalize((ix + sqrt(ix^2 + iz^2 - t^2)) x + (iz + t) ng), its x part computed without
 * cancellation. The result has n.ng > 0 and n.wo > 0: no direction is lost to a normal
 * pointing into the surface, and no NaN comes out of one pointing straight into it. */
static inline float3 keep_reflection_above_surface(float3 ng, float3 wo, float3 ns)
{
    float iz = dot(wo, ng);
    float t = fmin(0.9f * iz, 0.01f);
    float3 r = 2.0f * dot(ns, wo) * ns - wo;
    if (dot(ns, ng) > 0.0f && dot(r, ng) >= t)
        return ns;
    float3 x = ns - dot(ns, ng) * ng;
    float x_len = length(x);
    if (!(x_len > 1.0e-7f) || !(iz > 0.0f))
        return ng; /* ns along -ng (no plane to turn it in), or wo in the surface */
    x /= x_len;
    float ix = dot(wo, x);
    float s = sqrt(fmax(0.0f, ix * ix + (iz - t) * (iz + t)));
    float nx = ix >= 0.0f ? ix + s : (iz - t) * (iz + t) / (s - ix);
    return normalize(nx * x + (iz + t) * ng);
}

#endif /* PATHCL_HAS_NORMAL_MAPS */

/* Applies the material's textures, the vertex colour and the normal map at a hit: `m` is
 * the hit triangle's material (a private copy), `sp` its surface point, wo the direction
 * back along the ray. */
static inline void apply_material_inputs(Material* m, SurfacePoint* sp, float3 wo, Hit hit, const TextureBuffers* tex)
{
#ifdef PATHCL_HAS_VERTEX_COLORS
    {
        TriangleColors c = tex->colors[hit.triangle];
        float b0 = 1.0f - hit.b1 - hit.b2;
        m->base_color.xyz *= b0 * c.c0.xyz + hit.b1 * c.c1.xyz + hit.b2 * c.c2.xyz;
    }
#endif
#ifdef PATHCL_HAS_TEXTURES
    int tri = hit.triangle;
    if (m->base_color_texture != TEXTURE_NONE)
        m->base_color.xyz *= texture_at(tex, m->base_color_texture, tri, hit.b1, hit.b2).xyz;
    if (m->metallic_roughness_texture != TEXTURE_NONE) {
        float4 mr = texture_at(tex, m->metallic_roughness_texture, tri, hit.b1, hit.b2);
        m->roughness *= mr.y;
        m->metallic *= mr.z;
    }
    if (m->emissive_texture != TEXTURE_NONE)
        m->emission.xyz *= texture_at(tex, m->emissive_texture, tri, hit.b1, hit.b2).xyz;
    if (m->specular_texture != TEXTURE_NONE)
        m->specular_color.w *= texture_at(tex, m->specular_texture, tri, hit.b1, hit.b2).w;
    if (m->specular_color_texture != TEXTURE_NONE)
        m->specular_color.xyz *= texture_at(tex, m->specular_color_texture, tri, hit.b1, hit.b2).xyz;
    if (m->transmission_texture != TEXTURE_NONE)
        m->transmission *= texture_at(tex, m->transmission_texture, tri, hit.b1, hit.b2).x;
#ifdef PATHCL_HAS_NORMAL_MAPS
    if (m->normal_texture != TEXTURE_NONE) {
        /* The tangent frame belongs to the front (counter-clockwise) side; map there, then
         * turn the result to wo's side like the interpolated normal. */
        float side = sp->front_face ? 1.0f : -1.0f;
        float3 texel = texture_at(tex, m->normal_texture, tri, hit.b1, hit.b2).xyz;
        float3 mapped = normal_from_map(side * sp->ns, tex->tangents[tri], hit.b1, hit.b2, texel, m->normal_scale);
        sp->ns = keep_reflection_above_surface(sp->ng, wo, side * mapped);
    }
#endif
#endif
}
