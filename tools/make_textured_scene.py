#!/usr/bin/env python3
"""Writes scenes/textured.gltf and its textures (scenes/textures/*.png): the textured,
normal-mapped test scene. Every texture path pathcl has is used at least once:

- floor: sRGB base-colour tiles with KHR_texture_transform (scale, rotation, offset),
  REPEAT, a normal map of grooves between the tiles and a metallic-roughness texture
  (glossier tiles, rough grout); tangents computed by pathcl (no TANGENT attribute);
- back wall: COLOR_0 (a warm-to-cool gradient) times a nearest-filtered 8 x 8 pattern
  with MIRRORED_REPEAT;
- sphere: a hammered normal map (computed tangents, a UV sphere) and a metallic-roughness
  texture of metal and dielectric bands;
- box: TANGENT given in the file, a 16-bit normal map of rivets and a base colour;
- light: the only emitter, a tilted panel (partly in view) whose emissive texture (a warm
  disc on a dim grid) is read through TEXCOORD_1 with CLAMP_TO_EDGE.

No dependencies beyond Python 3 (PNGs are written with zlib). Textures are small (32 to
64 texels a side) so the committed files stay a few KB.

Usage: python3 tools/make_textured_scene.py [OUT_DIR]   (default: scenes)
"""
import base64
import json
import math
import os
import struct
import sys
import zlib


# ---------------------------------------------------------------------------------------
# PNG writing

def write_png(path, width, height, pixels, channels=4, bits=8):
    """pixels: rows (top first) of width tuples of `channels` integers."""
    raw = bytearray()
    fmt = ">" + ("B" if bits == 8 else "H") * channels
    for row in pixels:
        raw.append(0)  # filter: none
        for px in row:
            raw += struct.pack(fmt, *px)
    colour_type = {1: 0, 2: 4, 3: 2, 4: 6}[channels]

    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, bits, colour_type, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(bytes(raw), 9)))
        f.write(chunk(b"IEND", b""))


def clamp01(x):
    return max(0.0, min(1.0, x))


def to8(x):
    return int(round(clamp01(x) * 255.0))


def texels(size, texel):
    """A size x size image, row by row from the top: texel(i, j, u, v) at column i, row j,
    with (u, v) the texel centre in [0, 1]^2."""
    return [[texel(i, j, (i + 0.5) / size, (j + 0.5) / size) for i in range(size)] for j in range(size)]


def srgb8(rgb):
    """Linear colour to opaque 8-bit sRGB-encoded texels (the way images hold colour)."""
    return tuple(to8(c ** (1 / 2.2)) for c in rgb) + (255,)


def normal_map(size, height, scale, bits=8):
    """Tangent-space normals of a height field h(u, v) (u right, v down the image), as glTF
    encodes them: +X along +u, +Y up the image (along -v), +Z out of the surface."""
    top = 255 if bits == 8 else 65535
    d = 1.0 / size

    def texel(i, j, u, v):
        dh_du = (height(u + d, v) - height(u - d, v)) / (2 * d)
        dh_dv = (height(u, v + d) - height(u, v - d)) / (2 * d)
        n = (-scale * dh_du, scale * dh_dv, 1.0)
        length = math.sqrt(sum(c * c for c in n))
        return tuple(int(round((c / length * 0.5 + 0.5) * top)) for c in n) + (top,)
    return texels(size, texel)


def tiles_grout(u, v):
    """Distance to the nearest grout line of the 2 x 2 tiles, in tile widths."""
    tu, tv = (u * 2) % 1.0, (v * 2) % 1.0
    return min(tu, tv, 1 - tu, 1 - tv)


def tiles_base(size):
    """Four tiles per texture (2 x 2) in two terracotta tones, with light grout."""
    def texel(i, j, u, v):
        if tiles_grout(u, v) < 0.06:
            return srgb8((0.82, 0.80, 0.74))
        if (int(u * 2) + int(v * 2)) % 2 == 0:
            return srgb8((0.70, 0.36, 0.22))
        return srgb8((0.52, 0.30, 0.20))
    return texels(size, texel)


def tiles_height(u, v):
    return -0.02 * clamp01(1.0 - tiles_grout(u, v) / 0.06)  # grooves sink towards the grout lines


def tiles_metallic_roughness(size):
    """G = roughness (tiles 0.3, grout 1), B = metallic (0); R unused."""
    return texels(size, lambda i, j, u, v: (0, to8(1.0 if tiles_grout(u, v) < 0.06 else 0.3), 0, 255))


def wall_pattern(size):
    def texel(i, j, u, v):
        dark = (i + j) % 3 == 0 or (i == j)
        return (90, 90, 96, 255) if dark else (235, 230, 220, 255)
    return texels(size, texel)


def hammered_height(u, v):
    # overlapping shallow dimples on a 16 x 8 lattice (u runs around the sphere)
    h = 0.0
    for a in range(-1, 2):
        for b in range(-1, 2):
            cu = (math.floor(u * 16) + 0.5 + a) / 16
            cv = (math.floor(v * 8) + 0.5 + b) / 8
            r2 = ((u - cu) * 16) ** 2 + ((v - cv) * 8) ** 2
            h -= 0.01 * math.exp(-4.0 * r2)
    return h


def sphere_metallic_roughness(size):
    def texel(i, j, u, v):
        band = (j * 6 // size) % 2
        return (0, to8(0.25 if band else 0.5), 255 if band else 0, 255)
    return texels(size, texel)


def rivets_height(u, v):
    h = 0.0
    for cu in (0.15, 0.85):
        for cv in (0.15, 0.85):
            r = math.hypot(u - cu, v - cv)
            h += 0.03 * math.sqrt(max(0.0, 1.0 - (r / 0.08) ** 2))
    edge = min(u, v, 1 - u, 1 - v)
    h -= 0.02 * clamp01(1.0 - edge / 0.05)  # bevelled border
    return h


def box_base(size):
    return texels(size, lambda i, j, u, v: (40, 70, 140, 255) if ((i + j) // 4) % 2 else (60, 110, 190, 255))


def light_emission(size):
    """A warm disc on a dim grid; the edge texels are dark so CLAMP_TO_EDGE shows."""
    def texel(i, j, u, v):
        if math.hypot(u - 0.5, v - 0.5) < 0.3:
            return srgb8((1.0, 0.85, 0.6))
        if i % 8 == 0 or j % 8 == 0:
            return srgb8((0.35, 0.35, 0.4))
        return srgb8((0.12, 0.12, 0.15))
    return texels(size, texel)


# ---------------------------------------------------------------------------------------
# glTF building

class Builder:
    def __init__(self):
        self.blob = bytearray()
        self.accessors, self.views, self.meshes, self.nodes = [], [], [], []

    def accessor(self, values, kind, component=5126, normalized=False, target=34962):
        while len(self.blob) % 4:
            self.blob.append(0)
        n = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}[kind]
        fmt = {5126: "f", 5123: "H", 5121: "B"}[component]
        data = b"".join(struct.pack("<" + fmt * n, *(v if n > 1 else (v,))) for v in values)
        self.views.append({"buffer": 0, "byteOffset": len(self.blob), "byteLength": len(data), "target": target})
        self.blob += data
        acc = {"bufferView": len(self.views) - 1, "componentType": component, "count": len(values), "type": kind}
        if normalized:
            acc["normalized"] = True
        if kind == "VEC3" and component == 5126 and target == 34962:
            f32 = lambda x: struct.unpack("<f", struct.pack("<f", x))[0]
            acc["min"] = [f32(min(v[k] for v in values)) for k in range(3)]
            acc["max"] = [f32(max(v[k] for v in values)) for k in range(3)]
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def mesh(self, name, material, positions, indices, normals=None, uv0=None, uv1=None, tangents=None,
             colors=None, translation=None, rotation=None):
        attributes = {"POSITION": self.accessor(positions, "VEC3")}
        if normals:
            attributes["NORMAL"] = self.accessor(normals, "VEC3")
        if uv0:
            attributes["TEXCOORD_0"] = self.accessor(uv0, "VEC2")
        if uv1:
            attributes["TEXCOORD_1"] = self.accessor(uv1, "VEC2")
        if tangents:
            attributes["TANGENT"] = self.accessor(tangents, "VEC4")
        if colors:  # normalized unsigned bytes, VEC4 (alpha unused by pathcl)
            attributes["COLOR_0"] = self.accessor([tuple(to8(c) for c in col) + (255,) for col in colors], "VEC4",
                                                  component=5121, normalized=True)
        idx = self.accessor(indices, "SCALAR", component=5123, target=34963)
        self.meshes.append({"name": name, "primitives": [
            {"attributes": attributes, "indices": idx, "material": material, "mode": 4}]})
        node = {"name": name, "mesh": len(self.meshes) - 1}
        if translation:
            node["translation"] = translation
        if rotation:
            node["rotation"] = rotation
        self.nodes.append(node)


def quad(corner, edge_u, edge_v, uv_scale=(1.0, 1.0)):
    """A quad corner + s edge_u + t edge_v (s, t in [0, 1]); normal = edge_u x edge_v;
    texture coordinates (s, 1 - t) scaled, so the image stands upright along edge_v."""
    p = [tuple(corner[k] + s * edge_u[k] + t * edge_v[k] for k in range(3)) for s, t in ((0, 0), (1, 0), (1, 1), (0, 1))]
    n = cross(edge_u, edge_v)
    ln = math.sqrt(sum(c * c for c in n))
    n = tuple(c / ln for c in n)
    uv = [(s * uv_scale[0], (1 - t) * uv_scale[1]) for s, t in ((0, 0), (1, 0), (1, 1), (0, 1))]
    return p, [n] * 4, uv, [0, 1, 2, 0, 2, 3]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def uv_sphere(radius, stacks, slices):
    """Positions, normals, uvs (u around from +x towards -z, v from the top) and indices,
    counter-clockwise from outside; a seam column of duplicated vertices."""
    p, n, uv, idx = [], [], [], []
    for i in range(stacks + 1):
        th = math.pi * i / stacks
        for j in range(slices + 1):
            ph = 2 * math.pi * j / slices
            d = (math.sin(th) * math.cos(ph), math.cos(th), -math.sin(th) * math.sin(ph))
            p.append(tuple(radius * c for c in d))
            n.append(d)
            uv.append((j / slices, i / stacks))
    w = slices + 1
    for i in range(stacks):
        for j in range(slices):
            a, b, c, d = i * w + j, (i + 1) * w + j, (i + 1) * w + j + 1, i * w + j + 1
            if i != 0:
                idx += [a, b, d]
            if i != stacks - 1:
                idx += [b, c, d]
    return p, n, uv, idx


def box(size):
    """A cube of edge `size` centred on the origin: 6 faces with their own UVs and the
    tangent (+u direction, w = +1) of each face written out."""
    h = size / 2
    faces = [  # (corner, edge_u, edge_v)
        ((-h, -h, h), (size, 0, 0), (0, size, 0)),     # +z
        ((h, -h, -h), (-size, 0, 0), (0, size, 0)),    # -z
        ((h, -h, h), (0, 0, -size), (0, size, 0)),     # +x
        ((-h, -h, -h), (0, 0, size), (0, size, 0)),    # -x
        ((-h, h, h), (size, 0, 0), (0, 0, -size)),     # +y
        ((-h, -h, -h), (size, 0, 0), (0, 0, size)),    # -y
    ]
    P, N, UV, T, I = [], [], [], [], []
    for corner, eu, ev in faces:
        p, n, uv, idx = quad(corner, eu, ev)
        base = len(P)
        P += p
        N += n
        UV += uv
        t = tuple(c / size for c in eu)
        T += [t + (1.0,)] * 4
        I += [base + k for k in idx]
    return P, N, UV, T, I


def quat_y(deg):
    a = math.radians(deg) / 2
    return [0.0, math.sin(a), 0.0, math.cos(a)]


def main():
    out_dir = sys.argv[1] if len(sys.argv) > 1 else "scenes"
    tex_dir = os.path.join(out_dir, "textures")
    os.makedirs(tex_dir, exist_ok=True)
    write_png(os.path.join(tex_dir, "tiles-base.png"), 64, 64, tiles_base(64))
    write_png(os.path.join(tex_dir, "tiles-normal.png"), 64, 64, normal_map(64, tiles_height, 1.0))
    write_png(os.path.join(tex_dir, "tiles-mr.png"), 64, 64, tiles_metallic_roughness(64))
    write_png(os.path.join(tex_dir, "wall-pattern.png"), 8, 8, wall_pattern(8))
    write_png(os.path.join(tex_dir, "hammered-normal.png"), 64, 64, normal_map(64, hammered_height, 4.0))
    write_png(os.path.join(tex_dir, "sphere-mr.png"), 32, 32, sphere_metallic_roughness(32))
    write_png(os.path.join(tex_dir, "rivets-normal16.png"), 32, 32, normal_map(32, rivets_height, 1.0, bits=16), bits=16)
    write_png(os.path.join(tex_dir, "box-base.png"), 32, 32, box_base(32))
    write_png(os.path.join(tex_dir, "light-emission.png"), 32, 32, light_emission(32))

    images = ["tiles-base", "tiles-normal", "tiles-mr", "wall-pattern", "hammered-normal", "sphere-mr",
              "rivets-normal16", "box-base", "light-emission"]
    NEAREST, LINEAR, REPEAT, CLAMP, MIRROR = 9728, 9729, 10497, 33071, 33648
    samplers = [
        {"magFilter": LINEAR, "wrapS": REPEAT, "wrapT": REPEAT},    # 0
        {"magFilter": NEAREST, "wrapS": MIRROR, "wrapT": MIRROR},   # 1
        {"magFilter": LINEAR, "wrapS": CLAMP, "wrapT": CLAMP},      # 2
    ]
    textures = [{"source": i, "sampler": {3: 1, 8: 2}.get(i, 0)} for i in range(len(images))]
    floor_transform = {"KHR_texture_transform": {"offset": [0.1, 0.25], "rotation": 0.3, "scale": [3.0, 3.0]}}
    no_specular = {"KHR_materials_specular": {"specularFactor": 0.0}}
    materials = [
        {"name": "floor-tiles", "pbrMetallicRoughness": {
            "baseColorTexture": {"index": 0, "extensions": floor_transform},
            "metallicRoughnessTexture": {"index": 2, "extensions": floor_transform},
            "metallicFactor": 1.0, "roughnessFactor": 1.0},
         "normalTexture": {"index": 1, "scale": 1.0, "extensions": floor_transform}},
        {"name": "wall", "pbrMetallicRoughness": {"baseColorTexture": {"index": 3}, "metallicFactor": 0.0},
         "extensions": no_specular},
        {"name": "hammered", "pbrMetallicRoughness": {
            "baseColorFactor": [0.95, 0.75, 0.45, 1.0], "metallicFactor": 1.0, "roughnessFactor": 1.0,
            "metallicRoughnessTexture": {"index": 5}},
         "normalTexture": {"index": 4, "scale": 1.0}},
        {"name": "box", "pbrMetallicRoughness": {"baseColorTexture": {"index": 7}, "metallicFactor": 0.0,
                                                 "roughnessFactor": 0.6},
         "normalTexture": {"index": 6, "scale": 0.8}},
        {"name": "light", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1.0], "metallicFactor": 0.0},
         "emissiveFactor": [1.0, 1.0, 1.0], "emissiveTexture": {"index": 8, "texCoord": 1},
         "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 5.0},
                        "KHR_materials_specular": {"specularFactor": 0.0}}},
    ]
    FLOOR, WALL, HAMMERED, BOX, LIGHT = range(5)

    b = Builder()
    p, n, uv, idx = quad((-2.0, 0.0, 2.0), (4.0, 0.0, 0.0), (0.0, 0.0, -4.0))
    b.mesh("floor", FLOOR, p, idx, normals=n, uv0=uv)
    p, n, uv, idx = quad((-2.0, 0.0, -1.2), (4.0, 0.0, 0.0), (0.0, 2.5, 0.0), uv_scale=(3.0, 1.875))
    colors = [(1.0, 0.75, 0.55) if q[0] < 0 else (0.55, 0.7, 1.0) for q in p]
    b.mesh("back_wall", WALL, p, idx, normals=n, uv0=uv, colors=colors)
    p, n, uv, idx = uv_sphere(0.45, 16, 32)
    b.mesh("sphere", HAMMERED, p, idx, normals=n, uv0=uv, translation=[-0.6, 0.45, -0.25])
    p, n, uv, t, idx = box(0.6)
    b.mesh("box", BOX, p, idx, normals=n, uv0=uv, tangents=t, translation=[0.65, 0.3, 0.05], rotation=quat_y(-30))
    # The light panel rises towards the camera by 30 degrees: it faces down and forward,
    # so the camera sees part of its emissive texture directly.
    p, n, uv, idx = quad((-0.8, 1.8, -0.9), (1.6, 0.0, 0.0), (0.0, 0.6, 1.2 * math.cos(math.radians(30))))
    uv1 = [(s * 1.2 - 0.1, t * 1.2 - 0.1) for s, t in uv]  # a margin of clamped edge texels
    b.mesh("light", LIGHT, p, idx, normals=n, uv0=uv, uv1=uv1)
    look = math.radians(6.0)  # pitched down a little
    b.nodes.append({"name": "camera", "camera": 0, "translation": [0.0, 1.25, 3.4],
                    "rotation": [-math.sin(look / 2), 0.0, 0.0, math.cos(look / 2)]})
    gltf = {
        "asset": {"version": "2.0", "generator": "pathcl tools/make_textured_scene.py"},
        "extensionsUsed": ["KHR_texture_transform", "KHR_materials_emissive_strength", "KHR_materials_specular"],
        "scene": 0,
        "scenes": [{"name": "textured", "nodes": list(range(len(b.nodes)))}],
        "nodes": b.nodes, "meshes": b.meshes, "materials": materials,
        "textures": textures, "samplers": samplers,
        "images": [{"uri": "textures/%s.png" % name} for name in images],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.75, "aspectRatio": 1.0, "znear": 0.01}}],
        "accessors": b.accessors, "bufferViews": b.views,
        "buffers": [{"byteLength": len(b.blob), "uri": "data:application/octet-stream;base64,"
                     + base64.b64encode(bytes(b.blob)).decode("ascii")}],
    }
    with open(os.path.join(out_dir, "textured.gltf"), "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
