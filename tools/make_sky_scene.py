#!/usr/bin/env python3
"""Writes scenes/sky.hdr (a 64x32 equirectangular sky: a blue gradient, a darker ground
half and a small bright sun), scenes/sky-spheres.gltf (a diffuse ground, two spheres
and a block lit only by that sky through scene extras.environment; the environment
test scene) and scenes/sky-glass.gltf (the same with a glass sphere and a mirror block).
No dependencies beyond Python 3 (Radiance RGBE is written by hand).

Usage: python3 tools/make_sky_scene.py [OUT_DIR]
"""
import math
import os
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_cornell_box as cb  # noqa: E402  (its glTF Builder and material helper)

W, H = 64, 32
SUN_U, SUN_V = 0.30, 0.25  # sun direction in map coordinates (u from -Z towards +X)


def sky(u, v):
    """Radiance of texel centre (u, v): docs/gltf.md's mapping, v = 0 is straight up."""
    if v > 0.5:  # below the horizon: a dim, warm ground colour
        return (0.12, 0.10, 0.08)
    t = v / 0.5
    rgb = (0.25 + 0.5 * t, 0.45 + 0.4 * t, 1.0)
    du = min(abs(u - SUN_U), 1.0 - abs(u - SUN_U))
    if du < 1.5 / W and abs(v - SUN_V) < 1.5 / H:
        rgb = (400.0, 360.0, 300.0)  # the sun: a few texels, far brighter than the sky
    return rgb


def rgbe(r, g, b):
    v = max(r, g, b)
    if v < 1e-32:
        return bytes((0, 0, 0, 0))
    m, e = math.frexp(v)
    scale = m * 256.0 / v
    return bytes((int(r * scale), int(g * scale), int(b * scale), e + 128))


def write_hdr(path):
    with open(path, "wb") as f:
        f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n")
        f.write(f"-Y {H} +X {W}\n".encode())
        for j in range(H):
            f.write(b"".join(rgbe(*sky((i + 0.5) / W, (j + 0.5) / H)) for i in range(W)))


def scene(name, glass):
    """sky-spheres; with glass, the white sphere is solid glass and the block a mirror
    (sky-glass: the glass-and-environment scene of docs/accuracy.md)."""
    b = cb.Builder()
    mats = [cb.lambertian("ground", (0.6, 0.6, 0.6)), cb.lambertian("red", (0.7, 0.2, 0.15)),
            cb.lambertian("white", (0.8, 0.8, 0.8))]
    if glass:
        mats += [cb.GLASS, cb.MIRROR]
    size = 4000.0
    b.add_mesh("ground", [[(-size, 0, -size), (-size, 0, size), (size, 0, size), (size, 0, -size)]], 0)
    b.add_mesh("sphere_red", cb.sphere_quads(-400, 400, 0, 400), 1)
    b.add_mesh("sphere_white", cb.sphere_quads(500, 300, 300, 300), 3 if glass else 2)
    block = [(200, 0, -700), (700, 0, -700), (700, 600, -700), (200, 600, -700)]
    b.add_mesh("block_front", [cb.oriented(block, (450, 300, 0))], 4 if glass else 2)
    b.nodes.append({"name": "camera", "camera": 0, "translation": [0.0, 0.9, 3.2],
                    "rotation": [-math.sin(math.radians(6)), 0.0, 0.0, math.cos(math.radians(6))]})
    extensions = ["KHR_materials_specular"]
    if glass:
        extensions += ["KHR_materials_transmission", "KHR_materials_ior", "KHR_materials_volume"]
    return b.document("pathcl tools/make_sky_scene.py", name, mats, 0.7, extensions,
                      {"environment": {"uri": "sky.hdr", "strength": 1.0}})


def main():
    out_dir = sys.argv[1] if len(sys.argv) > 1 else "scenes"
    write_hdr(os.path.join(out_dir, "sky.hdr"))
    cb.write_gltf(os.path.join(out_dir, "sky-spheres.gltf"), scene("sky-spheres", False))
    cb.write_gltf(os.path.join(out_dir, "sky-glass.gltf"), scene("sky-glass", True))


if __name__ == "__main__":
    main()
