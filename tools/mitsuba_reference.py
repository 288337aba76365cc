#!/usr/bin/env python3
"""Renders a glTF scene with Mitsuba 3 as an independent reference for pathcl.

    tools/mitsuba_reference.py SCENE.gltf -o OUT.exr --width W --height H --spp N \
        --max-bounces B --runs K [--seed S] [--variant V] [--integrator auto|path|volpath]

Writes OUT.exr with R, G, B = the mean over all K*N samples per pixel,
variance.R/G/B = the estimated variance of ONE sample (variance across the K run means
times N) and the int attribute pathcl:spp = K*N: the layout pathcl writes, so
`pathcl compare OUT.exr PATHCL.exr` tests the two renders statistically.

Install (pip only; the Debian python3 has no numpy):
    python3 -m venv /tmp/mivenv
    /tmp/mivenv/bin/pip install mitsuba numpy OpenEXR     # or openimageio instead of OpenEXR
    /tmp/mivenv/bin/python tools/mitsuba_reference.py scenes/cornell-box.gltf -o ref.exr ...

The glTF reader is our own (numpy only, no pathcl code) and covers what
scenes/cornell-box*.gltf use: node TRS/matrix hierarchy, triangle primitives (mode 4)
with float VEC3 POSITION, TEXCOORD_n (float, or normalized u8/u16 VEC2) and u8/u16/u32
indices, base64 data-URI or external buffers, images from a bufferView, a data URI or a
file (PNG or JPEG, decoded by Mitsuba's Bitmap), baseColorFactor,
emissiveFactor x KHR_materials_emissive_strength, KHR_lights_punctual point (and
sphere) and directional lights, and the first perspective camera. Materials with an
exact Mitsuba equivalent (see material_params, material_texture): Lambertian
(specularFactor 0), optionally with a baseColorTexture and alphaMode MASK; white metals
(smooth or GGX-rough); solid glass (smooth or GGX-rough, KHR_materials_volume
thicknessFactor > 0), optionally absorbing (attenuationColor / attenuationDistance).
Any other material, alphaMode BLEND, COLOR_0, KHR_texture_transform and any texture
but baseColorTexture (occlusionTexture is ignored, as pathcl ignores it) are errors.
Vertex normals are ignored: every surface is flat-shaded, so compare with a pathcl
render of the scene without its NORMAL attributes (see tools/strip_normals.py).

Conventions matched to pathcl:
  * --max-bounces B counts scattering events (B=0: emission only). Mitsuba's path
    integrator max_depth counts path segments, so max_depth = B + 1.
  * Emission leaves the front face only: the side the counter-clockwise winding's
    normal points to. Mitsuba's mesh face normal is cross(v1-v0, v2-v0), the same side,
    and its area emitter is one-sided in that direction. Nodes whose world matrix
    mirrors (negative determinant) get their winding reversed, as glTF requires.
  * glTF cameras look along local -Z with +Y up; the sensor is placed with
    look_at(origin, origin + forward, up) so no handedness flip is needed.
  * Film: box reconstruction filter, so each pixel is the plain mean of its samples.
  * Absorbing glass (KHR_materials_volume): pathcl multiplies the throughput by
    exp(-sigma t) over a length t inside the solid, sigma = -ln(attenuationColor) /
    attenuationDistance per channel, and nothing scatters inside. Mitsuba: the glass
    shape gets an `interior` homogeneous medium with sigma_t = sigma and albedo 0 (the
    faces' normals point out of the solid, so the interior is the solid). Media need
    the volpath integrator, which samples a free-flight distance in the medium: a
    sampled medium event has albedo 0, so it ends the path with weight 0, and reaching
    the surface first carries weight exp(-sigma t) / pdf: Beer-Lambert in expectation.
    volpath's max_depth counts scattering events as path does (same B + 1; checked on
    clear glass: path and volpath agree); media do not nest in either renderer here.
  * Textures: Mitsuba's uv = (0, 0) is the first texel of the image's first row, as
    glTF's. The base colour texture is decoded from sRGB here (exact formula, before
    filtering, as pathcl's 8-bit table) and given to Mitsuba as raw linear floats, times
    baseColorFactor; the sampler's magFilter picks Mitsuba's filter_type (NEAREST:
    nearest, else bilinear between texel centres, as pathcl's) and wrapS (= wrapT) its
    wrap_mode.
  * alphaMode MASK: pathcl has no surface where alpha = baseColorFactor alpha x texel
    alpha < alphaCutoff (default 0.5), for camera, bounce and shadow rays, and an opaque
    one elsewhere. Mitsuba: a `mask` BSDF whose opacity bitmap is exactly 0 or 1 per
    texel, thresholded here in float32, read nearest (so MASK with a texture needs a
    NEAREST magFilter); a constant alpha below the cutoff drops the primitive. The mask's
    null interface needs volpath too: path's shadow rays stop at it, volpath's pass it
    (eval_null_transmission), and volpath does not count a null interaction as a bounce,
    as pathcl does not count a cut-out.
  * --integrator auto (the default) takes volpath for scenes with an absorbing solid or
    an alpha cut-out and path otherwise, as before.
"""
import argparse
import base64
import json
import math
import os
import sys
import time

try:
    import numpy as np
except ImportError:
    sys.exit("mitsuba_reference.py: numpy is missing. Install: python3 -m venv /tmp/mivenv && "
             "/tmp/mivenv/bin/pip install mitsuba numpy OpenEXR")


# ---------------------------------------------------------------------------------------
# EXR I/O: OpenImageIO if importable, else the OpenEXR pip package.

def _backend():
    try:
        import OpenImageIO as oiio
        return "oiio", oiio
    except ImportError:
        pass
    try:
        import OpenEXR
        return "openexr", OpenEXR
    except ImportError:
        pass
    raise ImportError("no EXR library: pip install openimageio  (or)  pip install OpenEXR")


def exr_backend_name():
    return {"oiio": "OpenImageIO", "openexr": "OpenEXR"}[_backend()[0]]


def write_exr(path, channels, int_attrs=None):
    """Writes float32 channels {name: HxW array} plus int header attributes."""
    kind, lib = _backend()
    names = list(channels)
    h, w = next(iter(channels.values())).shape
    if kind == "oiio":
        spec = lib.ImageSpec(w, h, len(names), lib.FLOAT)
        spec.channelnames = tuple(names)
        spec.attribute("compression", "zip")
        for k, v in (int_attrs or {}).items():
            spec.attribute(k, int(v))
        pixels = np.stack([np.asarray(channels[n], np.float32) for n in names], axis=-1)
        out = lib.ImageOutput.create(path)
        if out is None or not out.open(path, spec):
            raise IOError(f"cannot open {path} for writing: {lib.geterror()}")
        ok = out.write_image(np.ascontiguousarray(pixels))
        out.close()
        if not ok:
            raise IOError(f"cannot write {path}: {lib.geterror()}")
    else:
        header = {"compression": lib.ZIP_COMPRESSION, "type": lib.scanlineimage}
        header.update({k: int(v) for k, v in (int_attrs or {}).items()})
        data = {n: np.ascontiguousarray(channels[n], np.float32) for n in names}
        with lib.File(header, data) as f:
            f.write(path)

COMPONENT_DTYPES = {5120: np.int8, 5121: np.uint8, 5122: np.int16, 5123: np.uint16,
                    5125: np.uint32, 5126: np.float32}
TYPE_SIZES = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}


# ---------------------------------------------------------------------------------------
# Images: decoded by Mitsuba's own Bitmap (libpng, libjpeg), as stored: no colour
# conversion (the sRGB decode is done below, as pathcl does it).

def decode_image(data, mime):
    """Image bytes (PNG or JPEG) as an (H, W, C) uint8 / uint16 array, rows top first."""
    import tempfile
    import mitsuba as mi
    suffix = ".jpg" if mime == "image/jpeg" or data[:2] == b"\xff\xd8" else ".png"
    with tempfile.NamedTemporaryFile(suffix=suffix) as f:
        f.write(data)
        f.flush()
        img = np.array(mi.Bitmap(f.name), copy=True)
    return img[..., None] if img.ndim == 2 else img


# ---------------------------------------------------------------------------------------
# Minimal glTF 2.0 reader.

class Gltf:
    def __init__(self, path):
        with open(path, "rb") as f:
            raw = f.read()
        if raw[:4] == b"glTF":
            raise ValueError(f"{path}: binary .glb is not supported, only .gltf json")
        self.doc = json.loads(raw)
        self.dir = os.path.dirname(os.path.abspath(path))
        self.buffers = [self._load_buffer(b) for b in self.doc.get("buffers", [])]

    def _load_buffer(self, buf):
        uri = buf["uri"]
        if uri.startswith("data:"):
            header, _, payload = uri.partition(",")
            if not header.endswith(";base64"):
                raise ValueError("only base64 data URIs are supported")
            data = base64.b64decode(payload)
        else:
            from urllib.parse import unquote  # glTF URIs are percent-encoded
            with open(os.path.join(self.dir, unquote(uri)), "rb") as f:
                data = f.read()
        if len(data) < buf["byteLength"]:
            raise ValueError(f"buffer shorter than its byteLength {buf['byteLength']}")
        return data

    def image(self, index):
        """Image `index` of the document as an (H, W, C) uint8 / uint16 array."""
        img = self.doc["images"][index]
        if "bufferView" in img:
            view = self.doc["bufferViews"][img["bufferView"]]
            start = view.get("byteOffset", 0)
            data = self.buffers[view["buffer"]][start:start + view["byteLength"]]
        elif img["uri"].startswith("data:"):
            data = base64.b64decode(img["uri"].partition(",")[2])
        else:
            from urllib.parse import unquote
            with open(os.path.join(self.dir, unquote(img["uri"])), "rb") as f:
                data = f.read()
        return decode_image(bytes(data), img.get("mimeType"))

    def accessor(self, index):
        """Returns accessor `index` as a (count, components) numpy array."""
        acc = self.doc["accessors"][index]
        if "sparse" in acc:
            raise ValueError("sparse accessors are not supported")
        dtype = np.dtype(COMPONENT_DTYPES[acc["componentType"]]).newbyteorder("<")
        ncomp, count = TYPE_SIZES[acc["type"]], acc["count"]
        if "bufferView" not in acc:  # all zeros by spec
            return np.zeros((count, ncomp), dtype)
        view = self.doc["bufferViews"][acc["bufferView"]]
        data = self.buffers[view["buffer"]]
        start = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
        elem = dtype.itemsize * ncomp
        stride = view.get("byteStride", elem)
        # Strided view over the buffer, copied so it no longer aliases the bytes.
        arr = np.ndarray((count, ncomp), dtype, buffer=data, offset=start,
                         strides=(stride, dtype.itemsize))
        return np.array(arr)


def quat_to_matrix(q):
    x, y, z, w = q  # glTF order is x, y, z, w
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def node_matrix(node):
    if "matrix" in node:
        return np.array(node["matrix"], np.float64).reshape(4, 4).T  # stored column-major
    m = np.eye(4)
    r = quat_to_matrix(node.get("rotation", [0, 0, 0, 1]))
    s = np.diag(node.get("scale", [1, 1, 1]))
    m[:3, :3] = r @ s  # T * R * S
    m[:3, 3] = node.get("translation", [0, 0, 0])
    return m


def walk_nodes(doc):
    """Yields (node, world matrix) depth-first in scene order."""
    scenes = doc.get("scenes")
    if scenes:
        roots = scenes[doc.get("scene", 0)]["nodes"]
    else:  # no scene list: every node that is nobody's child is a root
        children = {c for n in doc.get("nodes", []) for c in n.get("children", [])}
        roots = [i for i in range(len(doc.get("nodes", []))) if i not in children]
    stack = [(i, np.eye(4)) for i in reversed(roots)]
    while stack:
        i, parent = stack.pop()
        node = doc["nodes"][i]
        world = parent @ node_matrix(node)
        yield node, world
        stack.extend((c, world) for c in reversed(node.get("children", [])))


def material_params(doc, index):
    """(base colour rgb, emitted radiance rgb, double sided, kind) of material `index`.
    kind is the Mitsuba BSDF with the same scattering as pathcl's glTF model, where one
    exists: "diffuse" (metallic 0, KHR_materials_specular specularFactor 0, no
    transmission); a white metal (metallic 1, white base: Schlick's F is then 1, Mitsuba's
    conductor / roughconductor with material "none"); solid glass (transmission 1,
    metallic 0, white base, specular 1, KHR_materials_volume: exact Fresnel, Mitsuba's
    dielectric / roughdielectric; KHR_materials_volume thicknessFactor > 0, else pathcl's
    glass is a thin-walled sheet). Rough lobes: GGX with alpha = roughness^2, separable
    Smith G and visible-normal sampling, as in pathcl; below alpha 1e-3 pathcl's lobes are
    delta functions. Glass kind is ("glass", ior, alpha, sigma): sigma the per-channel
    Beer-Lambert coefficient -ln(attenuationColor) / attenuationDistance of the solid's
    interior (None without an attenuationDistance: clear glass). Anything else is an
    error. Textures and alpha are material_texture's."""
    if index is None:  # glTF default material: metallic 1, roughness 1: no equivalent
        raise ValueError("a primitive without a material (glTF default: rough metal) has no Mitsuba equivalent")
    mat = doc["materials"][index]
    pbr = mat.get("pbrMetallicRoughness", {})
    ext = mat.get("extensions", {})
    base = pbr.get("baseColorFactor", [1, 1, 1, 1])[:3]
    strength = ext.get("KHR_materials_emissive_strength", {}).get("emissiveStrength", 1.0)
    emissive = [c * strength for c in mat.get("emissiveFactor", [0, 0, 0])]
    metallic, roughness = pbr.get("metallicFactor", 1.0), pbr.get("roughnessFactor", 1.0)
    specular = ext.get("KHR_materials_specular", {}).get("specularFactor", 1.0)
    transmission = ext.get("KHR_materials_transmission", {}).get("transmissionFactor", 0.0)
    white = all(c == 1.0 for c in base)
    alpha = roughness * roughness
    if metallic == 0.0 and specular == 0.0 and transmission == 0.0:
        kind = "diffuse"
    elif metallic == 1.0 and white:
        kind = ("metal", alpha)
    elif (transmission == 1.0 and metallic == 0.0 and white and specular == 1.0
          and ext.get("KHR_materials_volume", {}).get("thicknessFactor", 0.0) > 0.0):
        volume = ext["KHR_materials_volume"]
        sigma = None
        if "attenuationDistance" in volume:  # glTF default: +infinity, no absorption
            colour = np.array(volume.get("attenuationColor", [1.0, 1.0, 1.0]), np.float64)
            dist = float(volume["attenuationDistance"])
            if not (dist > 0.0) or np.any(colour <= 0.0) or np.any(colour > 1.0):
                raise ValueError(f"material {index}: attenuationDistance must be > 0 and "
                                 "attenuationColor in (0, 1]")
            if np.any(colour < 1.0):
                sigma = tuple(float(x) for x in -np.log(colour) / dist)
        kind = ("glass", ext.get("KHR_materials_ior", {}).get("ior", 1.5), alpha, sigma)
    else:
        raise ValueError(f"material {index} ({mat.get('name', '')}) has no like-for-like Mitsuba BSDF here")
    return tuple(base), tuple(emissive), bool(mat.get("doubleSided", False)), kind


GL_NEAREST = 9728
GL_WRAP = {10497: "repeat", 33071: "clamp", 33648: "mirror"}


def srgb_to_linear(c):
    """The sRGB transfer function's inverse (IEC 61966-2-1), c in [0, 1], float64."""
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def material_texture(g, index, kind):
    """What material `index` needs beyond material_params: None for a plain material, or
    {"rgb": HxWx3 float32 linear base colour (texel x baseColorFactor),
     "opacity": HxWx1 float32 of exactly 0 or 1 or None, "filter": "nearest"|"bilinear",
     "wrap": Mitsuba wrap_mode, "texcoord": set n}; "cut": True when the whole material
    is cut away (MASK with a constant alpha below the cutoff).
    pathcl's model (docs/gltf.md, "Textures"): the base colour is baseColorFactor x the texture's
    RGB decoded from sRGB (8-bit: the exact formula, per texel, before filtering); alpha
    = baseColorFactor's alpha x the texel's (linear) alpha; alphaMode MASK: no surface
    where alpha < alphaCutoff (default 0.5), an opaque one elsewhere. The cutoff is applied
    per texel here, so MASK needs a NEAREST magFilter (pathcl thresholds the bilinearly
    filtered alpha, which no 0/1 Mitsuba opacity map reproduces). BLEND, COLOR_0,
    KHR_texture_transform and the other texture slots are errors (occlusionTexture,
    which pathcl does not read, is ignored)."""
    if index is None:
        return None
    mat = g.doc["materials"][index]
    pbr = mat.get("pbrMetallicRoughness", {})
    name = f"material {index} ({mat.get('name', '')})"
    others = [k for k in ("metallicRoughnessTexture",) if k in pbr]
    others += [k for k in ("normalTexture", "emissiveTexture") if k in mat]
    for ext_name, ext in mat.get("extensions", {}).items():
        others += [f"{ext_name}.{k}" for k in ext if k.endswith("Texture")]
    if others:
        raise ValueError(f"{name}: {', '.join(others)} has no Mitsuba equivalent here")
    mode = mat.get("alphaMode", "OPAQUE")
    if mode not in ("OPAQUE", "MASK"):
        raise ValueError(f"{name}: alphaMode {mode} is not supported here (OPAQUE, MASK)")
    info = pbr.get("baseColorTexture")
    factor = np.array(pbr.get("baseColorFactor", [1, 1, 1, 1]), np.float64)
    cutoff = np.float32(mat.get("alphaCutoff", 0.5))
    if info is None:
        if mode == "MASK":  # a constant alpha: all or nothing
            return {"cut": True} if np.float32(factor[3]) < cutoff else None
        return None
    if kind != "diffuse":
        raise ValueError(f"{name}: a baseColorTexture is supported on Lambertian materials only")
    if "KHR_texture_transform" in info.get("extensions", {}):
        raise ValueError(f"{name}: KHR_texture_transform is not supported here")
    tex = g.doc["textures"][info["index"]]
    if "source" not in tex:
        raise ValueError(f"{name}: texture {info['index']} has no source image")
    sampler = g.doc.get("samplers", [])[tex["sampler"]] if "sampler" in tex else {}
    wrap_s, wrap_t = sampler.get("wrapS", 10497), sampler.get("wrapT", 10497)
    if wrap_s != wrap_t:
        raise ValueError(f"{name}: wrapS != wrapT has no Mitsuba equivalent (one wrap_mode)")
    nearest = sampler.get("magFilter") == GL_NEAREST
    if mode == "MASK" and not nearest:
        raise ValueError(f"{name}: alphaMode MASK with a texture needs a sampler with magFilter "
                         "NEAREST (9728) here: the cutoff of bilinearly filtered alpha has no "
                         "0/1 Mitsuba opacity map")
    img = g.image(tex["source"])
    scale = float(np.iinfo(img.dtype).max)
    texel = img.astype(np.float64) / scale
    chans = img.shape[2]
    rgb = texel[..., :3] if chans >= 3 else np.repeat(texel[..., :1], 3, axis=-1)
    alpha = texel[..., 3] if chans == 4 else texel[..., 1] if chans == 2 else np.ones(img.shape[:2])
    out = {"rgb": (srgb_to_linear(rgb) * factor[:3]).astype(np.float32), "opacity": None,
           "filter": "nearest" if nearest else "bilinear", "wrap": GL_WRAP[wrap_s],
           "texcoord": info.get("texCoord", 0)}
    if mode == "MASK":  # in float32, as pathcl compares
        a = np.float32(factor[3]) * alpha.astype(np.float32)
        out["opacity"] = (a >= cutoff).astype(np.float32)[..., None]
    return out


def texcoords(g, prim, n):
    """TEXCOORD_n of a primitive as (count, 2) float64: float, or normalized u8 / u16."""
    key = f"TEXCOORD_{n}"
    if key not in prim["attributes"]:
        raise ValueError(f"a textured primitive has no {key}")
    acc = g.doc["accessors"][prim["attributes"][key]]
    uv = g.accessor(prim["attributes"][key])
    if acc["type"] != "VEC2":
        raise ValueError(f"{key} must be VEC2")
    if acc["componentType"] == 5126:
        return uv.astype(np.float64)
    if acc.get("normalized") and acc["componentType"] in (5121, 5123):
        return uv.astype(np.float64) / float(np.iinfo(uv.dtype).max)
    raise ValueError(f"{key}: float or normalized unsigned byte / short only")


def load_scene(path):
    """Returns (triangle primitives, camera, punctual lights) in world space."""
    g = Gltf(path)
    doc = g.doc
    prims, camera, lights = [], None, []
    light_defs = doc.get("extensions", {}).get("KHR_lights_punctual", {}).get("lights", [])
    for node, world in walk_nodes(doc):
        light_ref = node.get("extensions", {}).get("KHR_lights_punctual")
        if light_ref is not None:
            ld = light_defs[light_ref["light"]]
            if ld["type"] not in ("point", "directional"):
                # Mitsuba's spot falloff is not glTF's t^2 one: no like-for-like reference.
                raise ValueError(f"{path}: {ld['type']} lights have no Mitsuba equivalent here")
            rgb = np.array(ld.get("color", [1.0, 1.0, 1.0]), np.float64) * ld.get("intensity", 1.0)
            radius = ld.get("extras", {}).get("radius")
            kind = "sphere" if ld["type"] == "point" and radius else ld["type"]
            if radius:  # the radius scales with the node, like pathcl's
                radius *= abs(np.linalg.det(world[:3, :3])) ** (1.0 / 3.0)
            lights.append({"type": kind, "rgb": rgb, "position": world[:3, 3].copy(), "radius": radius,
                           "direction": world[:3, :3] @ np.array([0.0, 0.0, -1.0])})
        if "camera" in node and camera is None:
            cam = doc["cameras"][node["camera"]]
            if cam.get("type") == "perspective":
                camera = {"world": world, **cam["perspective"]}
        if "mesh" not in node:
            continue
        mirrored = np.linalg.det(world[:3, :3]) < 0
        for k, p in enumerate(doc["meshes"][node["mesh"]]["primitives"]):
            if p.get("mode", 4) != 4:
                print(f"warning: skipping non-triangle primitive (mode {p['mode']})",
                      file=sys.stderr)
                continue
            pos = g.accessor(p["attributes"]["POSITION"]).astype(np.float64)
            if pos.shape[1] != 3:
                raise ValueError("POSITION must be VEC3")
            if "indices" in p:
                idx = g.accessor(p["indices"]).reshape(-1).astype(np.uint32)
            else:
                idx = np.arange(len(pos), dtype=np.uint32)
            faces = idx[: len(idx) // 3 * 3].reshape(-1, 3)
            if mirrored:  # a mirroring transform flips which side is counter-clockwise
                faces = faces[:, ::-1]
            pos = pos @ world[:3, :3].T + world[:3, 3]
            if "COLOR_0" in p["attributes"]:
                raise ValueError("COLOR_0 (vertex colours) has no Mitsuba equivalent here")
            base, emit, two_sided, kind = material_params(doc, p.get("material"))
            texture = material_texture(g, p.get("material"), kind)
            if texture is not None and texture.get("cut"):
                continue  # alphaMode MASK, constant alpha below the cutoff: no surface
            uv = texcoords(g, p, texture["texcoord"]) if texture is not None else None
            prims.append({"name": f"{node.get('name', 'node')}_{k}", "positions": pos,
                          "faces": np.ascontiguousarray(faces), "base": base,
                          "emission": emit, "two_sided": two_sided, "kind": kind,
                          "texture": texture, "uv": uv})
    if camera is None:
        raise ValueError(f"{path}: no perspective camera node in the scene")
    return prims, camera, lights


# ---------------------------------------------------------------------------------------
# Mitsuba scene.

def bitmap_texture(mi, data, tex):
    """A Mitsuba bitmap texture of linear float32 data (raw: no sRGB decoding or spectral
    upsampling; pathcl's sRGB decoding is done by material_texture) with the glTF
    sampler's filter and wrap mode. Mitsuba's uv = (0, 0) is the image's first row's first
    texel, as glTF's."""
    return {"type": "bitmap", "bitmap": mi.Bitmap(np.ascontiguousarray(data)), "raw": True,
            "filter_type": tex["filter"], "wrap_mode": tex["wrap"]}


def make_medium(mi, sigma):
    """pathcl's Beer-Lambert absorption inside a solid: a homogeneous medium that only
    absorbs (extinction sigma per channel, albedo 0, so no scattering). Mitsuba takes an
    RGB sigma_t in [0, 1] only, so it gets sigma / max(sigma) and scale max(sigma)."""
    peak = max(float(c) for c in sigma)
    return mi.load_dict({"type": "homogeneous", "scale": peak,
                         "sigma_t": {"type": "rgb", "value": [float(c) / peak for c in sigma]},
                         "albedo": {"type": "rgb", "value": [0.0, 0.0, 0.0]}})


def make_mesh(mi, prim):
    """A Mitsuba mesh without vertex normals (flat shading) with its BSDF/emitter, its
    texture coordinates when textured and, for absorbing glass, its interior medium."""
    props = mi.Properties()
    kind = prim["kind"]
    texture = prim.get("texture")
    glass = isinstance(kind, tuple) and kind[0] == "glass"
    if isinstance(kind, tuple) and kind[0] == "metal":
        alpha = kind[1]
        bsdf = ({"type": "conductor", "material": "none"} if alpha < 1e-3 else
                {"type": "roughconductor", "material": "none", "distribution": "ggx",
                 "alpha": float(alpha), "sample_visible": True})
    elif glass:  # both sides are the interface
        ior, alpha = float(kind[1]), kind[2]
        bsdf = ({"type": "dielectric", "int_ior": ior, "ext_ior": 1.0} if alpha < 1e-3 else
                {"type": "roughdielectric", "int_ior": ior, "ext_ior": 1.0, "distribution": "ggx",
                 "alpha": float(alpha), "sample_visible": True})
    elif texture is not None:
        bsdf = {"type": "diffuse", "reflectance": bitmap_texture(mi, texture["rgb"], texture)}
    else:
        bsdf = {"type": "diffuse", "reflectance": {"type": "rgb", "value": list(prim["base"])}}
    if prim["two_sided"] and not glass:
        bsdf = {"type": "twosided", "material": bsdf}
    if texture is not None and texture["opacity"] is not None:
        # alphaMode MASK: opacity exactly 0 (a null interface: rays and shadow rays pass
        # unchanged) or 1 (the surface) per texel.
        bsdf = {"type": "mask", "opacity": bitmap_texture(mi, texture["opacity"], texture),
                "material": bsdf}
    props["bsdf"] = mi.load_dict(bsdf)
    if glass and kind[3] is not None:
        # The faces' normals point out of the solid: its inside is Mitsuba's interior.
        props["interior"] = make_medium(mi, kind[3])
    if any(c > 0 for c in prim["emission"]):
        # One-sided: radiance leaves along the face normal only.
        props["emitter"] = mi.load_dict(
            {"type": "area", "radiance": {"type": "rgb", "value": list(prim["emission"])}})
    pos, faces = prim["positions"], prim["faces"]
    uv = prim.get("uv")
    mesh = mi.Mesh(prim["name"], len(pos), len(faces), props=props,
                   has_vertex_normals=False, has_vertex_texcoords=uv is not None)
    params = mi.traverse(mesh)
    # Flat buffers of the variant's own array types (dynamic arrays in scalar_* too).
    params["vertex_positions"] = type(params["vertex_positions"])(pos.astype(np.float32).ravel())
    params["faces"] = type(params["faces"])(faces.astype(np.uint32).ravel())
    if uv is not None:
        params["vertex_texcoords"] = type(params["vertex_texcoords"])(uv.astype(np.float32).ravel())
    params.update()  # recomputes bounds/areas the emitter sampling needs
    return mesh


def camera_to_world(mi, camera):
    world = camera["world"]
    origin = world[:3, 3]
    forward = world[:3, :3] @ np.array([0.0, 0.0, -1.0])  # glTF cameras look down -Z
    up = world[:3, :3] @ np.array([0.0, 1.0, 0.0])
    forward /= np.linalg.norm(forward)
    return mi.ScalarTransform4f().look_at(origin=origin.tolist(),
                                          target=(origin + forward).tolist(),
                                          up=up.tolist())


def make_light(mi, light):
    """KHR_lights_punctual point (intensity, W/sr) and directional (irradiance, W/m^2):
    Mitsuba's point and directional emitters take exactly these quantities. A point light
    with extras.radius is pathcl's sphere light."""
    rgb = {"type": "rgb", "value": [float(c) for c in light["rgb"]]}
    if light["type"] == "sphere":
        # pathcl: a sphere of uniform outward radiance I / (pi r^2) that does not reflect.
        r = float(light["radius"])
        radiance = [float(c) / (math.pi * r * r) for c in light["rgb"]]
        return {"type": "sphere", "center": [float(c) for c in light["position"]], "radius": r,
                "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": [0.0, 0.0, 0.0]}},
                "emitter": {"type": "area", "radiance": {"type": "rgb", "value": radiance}}}
    if light["type"] == "point":
        return {"type": "point", "position": [float(c) for c in light["position"]], "intensity": rgb}
    d = light["direction"] / np.linalg.norm(light["direction"])
    return {"type": "directional", "direction": [float(c) for c in d], "irradiance": rgb}


def needs_volpath(prims):
    """Whether a scene needs Mitsuba's volpath: an absorbing solid (a medium) or an alpha
    cut-out (a mask BSDF: the path integrator's shadow rays do not pass null surfaces)."""
    return any((isinstance(p["kind"], tuple) and p["kind"][0] == "glass" and p["kind"][3] is not None)
               or (p.get("texture") is not None and p["texture"]["opacity"] is not None) for p in prims)


def build_scene(mi, prims, camera, width, height, spp, max_bounces, lights=(), sampler="independent",
                integrator=None):
    """integrator: "path", "volpath" or None (volpath where needs_volpath, else path)."""
    integrator = integrator or ("volpath" if needs_volpath(prims) else "path")
    if integrator == "path" and needs_volpath(prims):
        raise ValueError("media and alpha cut-outs need the volpath integrator")
    scene = {
        "type": "scene",
        "integrator": {"type": integrator, "max_depth": max_bounces + 1, "hide_emitters": False},
        "sensor": {
            "type": "perspective",
            "fov": math.degrees(camera["yfov"]),
            "fov_axis": "y",
            "near_clip": float(camera.get("znear", 0.01)),
            "far_clip": float(camera.get("zfar", 1e4)),
            "to_world": camera_to_world(mi, camera),
            # Independent samples (the default) so that separately seeded runs are
            # independent too; tools/compare_mitsuba.py also times Mitsuba's others.
            "sampler": {"type": sampler, "sample_count": spp},
            "film": {"type": "hdrfilm", "width": width, "height": height,
                     "rfilter": {"type": "box"}, "pixel_format": "rgb",
                     "component_format": "float32"},
        },
    }
    for i, prim in enumerate(prims):
        scene[f"shape_{i:03d}"] = make_mesh(mi, prim)
    for i, light in enumerate(lights):
        scene[f"light_{i:03d}"] = make_light(mi, light)
    return mi.load_dict(scene)


def pick_variant(mi, requested):
    """scalar_rgb unless told otherwise.

    llvm_ad_rgb is ~1.6x faster on 2 cores but drjit 1.5 needs a newer libLLVM than
    Debian 12's default 14/15 (those abort inside codegen, uncatchably); point
    DRJIT_LIBLLVM_PATH at e.g. libLLVM.so.19.1 (Debian package libllvm19) to use it.
    """
    variant = requested or "scalar_rgb"
    if variant not in mi.variants():
        sys.exit(f"mitsuba_reference.py: variant {variant} not in {mi.variants()}")
    try:
        mi.set_variant(variant)
        if not variant.startswith("scalar"):
            # JIT variants fail only on first use when libLLVM / CUDA is missing.
            np.array(mi.Float([1.0, 2.0]) * 2)
    except Exception as e:  # noqa: BLE001 - report whatever the backend raised
        sys.exit(f"mitsuba_reference.py: variant {variant} unusable: {e}")
    return variant


def main():
    ap = argparse.ArgumentParser(description="Mitsuba 3 reference render of a glTF scene")
    ap.add_argument("scene")
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--width", type=int, required=True)
    ap.add_argument("--height", type=int, required=True)
    ap.add_argument("--spp", type=int, required=True, help="samples per pixel per run")
    ap.add_argument("--max-bounces", type=int, required=True,
                    help="scattering events (0 = emission only); max_depth = this + 1")
    ap.add_argument("--runs", type=int, required=True,
                    help="independent runs (>= 2) for the variance estimate")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--variant",
                    help="Mitsuba variant (default scalar_rgb; see pick_variant for llvm_ad_rgb)")
    ap.add_argument("--integrator", choices=("auto", "path", "volpath"), default="auto",
                    help="Mitsuba integrator (auto: volpath for media and alpha cut-outs, else path)")
    args = ap.parse_args()
    if args.runs < 2:
        ap.error("--runs must be >= 2 to estimate a variance")

    try:
        import mitsuba as mi
    except ImportError:
        sys.exit("mitsuba_reference.py: Mitsuba 3 is not installed. Install it with\n"
                 "  python3 -m venv /tmp/mivenv && /tmp/mivenv/bin/pip install mitsuba numpy "
                 "OpenEXR\nand run this script with /tmp/mivenv/bin/python")
    try:
        backend = exr_backend_name()
    except ImportError as e:
        sys.exit(f"mitsuba_reference.py: {e}")

    variant = pick_variant(mi, args.variant)
    try:
        prims, camera, lights = load_scene(args.scene)
    except ValueError as e:
        sys.exit(f"mitsuba_reference.py: {e}")
    integrator = None if args.integrator == "auto" else args.integrator
    try:
        scene = build_scene(mi, prims, camera, args.width, args.height, args.spp,
                            args.max_bounces, lights, integrator=integrator)
    except ValueError as e:
        sys.exit(f"mitsuba_reference.py: {e}")
    integrator = integrator or ("volpath" if needs_volpath(prims) else "path")
    print(f"mitsuba {mi.__version__} variant {variant}, EXR via {backend}; "
          f"{len(prims)} primitives, {integrator}, {args.width}x{args.height}, "
          f"{args.runs} runs x {args.spp} spp, max_depth {args.max_bounces + 1}")

    # Welford over run means in float64: mean and spread of the K independent estimates.
    mean = m2 = None
    t0 = time.time()
    for k in range(args.runs):
        # Run seeds S*K .. S*K+K-1: Mitsuba spreads each seed over disjoint per-pixel
        # RNG streams (scalar) or hashes it (LLVM), so these runs do not overlap.
        seed = args.seed * args.runs + k
        img = np.array(mi.render(scene, spp=args.spp, seed=seed), np.float64)[..., :3]
        if mean is None:
            mean, m2 = np.zeros_like(img), np.zeros_like(img)
        d = img - mean
        mean += d / (k + 1)
        m2 += d * (img - mean)
        print(f"  run {k + 1}/{args.runs} seed {seed}: {time.time() - t0:.1f} s", flush=True)

    # Var of one run's mean, times N = var of one sample.
    sample_var = m2 / (args.runs - 1) * args.spp
    total_spp = args.runs * args.spp
    chans = {"R": mean[..., 0], "G": mean[..., 1], "B": mean[..., 2],
             "variance.R": sample_var[..., 0], "variance.G": sample_var[..., 1],
             "variance.B": sample_var[..., 2]}
    write_exr(args.output, chans, {"pathcl:spp": total_spp, "pathcl:runs": args.runs})

    npx = args.width * args.height
    img_mean = mean.reshape(-1, 3).mean(0)
    img_se = np.sqrt((sample_var / total_spp).reshape(-1, 3).sum(0)) / npx
    print(f"wrote {args.output} ({total_spp} spp) in {time.time() - t0:.1f} s")
    print("image mean +- standard error: " + "  ".join(
        f"{c} {m:.6g} +- {s:.2g}" for c, m, s in zip("RGB", img_mean, img_se)))


if __name__ == "__main__":
    main()
