#!/usr/bin/env python3
"""Writes scenes/material-spheres.gltf: a 5 x 3 grid of spheres over glTF's metallic x
roughness (roughness 0, 0.25, 0.5, 0.75, 1 from left to right; metallic 0, 0.5, 1 from
front to back; one copper-coloured base colour), standing on a grey Lambertian ground and
lit only by scenes/sky.hdr (tools/make_sky_scene.py, at strength 0.25) through scene
extras.environment.
The material test scene: smooth and rough conductors, dielectric coats over a diffuse
base, and their mixtures. The spheres share one mesh's vertex data (smooth radial
normals).

Usage: python3 tools/make_material_spheres.py [OUT_DIR]
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_cornell_box as cb  # noqa: E402  (its glTF Builder and sphere helpers)

BASE = [0.9, 0.55, 0.3, 1.0]
ROUGHNESS = [0.0, 0.25, 0.5, 0.75, 1.0]
METALLIC = [0.0, 0.5, 1.0]
R, SPACING = 200.0, 500.0  # mm


def material(metallic, roughness):
    return {"name": f"metallic {metallic} roughness {roughness}",
            "pbrMetallicRoughness": {"baseColorFactor": BASE, "metallicFactor": metallic,
                                     "roughnessFactor": roughness}}


def main():
    out_dir = sys.argv[1] if len(sys.argv) > 1 else "scenes"
    b = cb.Builder()
    mats = [cb.lambertian("ground", (0.5, 0.5, 0.5))]
    size = 6000.0
    b.add_mesh("ground", [[(-size, 0, -size), (-size, 0, size), (size, 0, size), (size, 0, -size)]], 0)
    # One sphere's vertex data, shared by fifteen meshes that differ only in material,
    # each placed by its node.
    quads = cb.sphere_quads(0.0, 0.0, 0.0, R, stacks=24, slices=48)
    b.add_mesh("sphere", quads, 1, normals=cb.sphere_normals(quads, 0.0, 0.0, 0.0))
    sphere_primitive = b.meshes.pop()["primitives"][0]
    b.nodes.pop()
    for row, metallic in enumerate(METALLIC):
        for col, roughness in enumerate(ROUGHNESS):
            mats.append(material(metallic, roughness))
            name = f"sphere metallic {metallic} roughness {roughness}"
            b.meshes.append({"name": name, "primitives": [dict(sphere_primitive, material=len(mats) - 1)]})
            b.nodes.append({"name": name, "mesh": len(b.meshes) - 1,
                            "translation": [(col - 2) * SPACING * cb.MM, R * cb.MM, -row * SPACING * cb.MM]})
    eye, target = (0.0, 1.5, 2.4), (0.0, 0.15, -0.45)
    look = tuple(t - e for t, e in zip(target, eye))
    b.nodes.append({"name": "camera", "camera": 0, "translation": list(eye),
                    "rotation": cb.quat_from_to((0.0, 0.0, -1.0), look)})
    gltf = b.document("pathcl tools/make_material_spheres.py", "material-spheres", mats, 0.75,
                      ["KHR_materials_specular"], {"environment": {"uri": "sky.hdr", "strength": 0.25}})
    cb.write_gltf(os.path.join(out_dir, "material-spheres.gltf"), gltf)


if __name__ == "__main__":
    main()
