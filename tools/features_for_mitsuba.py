#!/usr/bin/env python3
"""Writes the copy of scenes/cornell-box-features.gltf that tools/mitsuba_reference.py
can render like for like: the clear-coated block gets the plain white Lambertian (Mitsuba
has no KHR_materials_clearcoat equivalent), NORMAL attributes go (the reference is flat
shaded), the leaf texture gets a NEAREST sampler (the reference thresholds alpha per
texel). The output must be written next to nothing else: the buffer is embedded.

Usage: python3 tools/features_for_mitsuba.py IN.gltf OUT.gltf [--no-absorption] [--drop NODE]...
  --no-absorption  the tinted glass loses its attenuation (clear glass: a control)
  --drop NODE      removes the named root node (repeatable), to compare one feature alone
"""
import argparse
import json

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("src")
ap.add_argument("dst")
ap.add_argument("--no-absorption", action="store_true")
ap.add_argument("--drop", action="append", default=[])
args = ap.parse_args()
doc = json.load(open(args.src))
materials = {m["name"]: i for i, m in enumerate(doc["materials"])}
for mesh in doc["meshes"]:
    for prim in mesh["primitives"]:
        prim["attributes"].pop("NORMAL", None)
        if prim.get("material") == materials["coated_red"]:
            prim["material"] = materials["white"]
doc["samplers"] = [{"magFilter": 9728, "minFilter": 9728}]
for texture in doc["textures"]:
    texture["sampler"] = 0
if args.no_absorption:
    volume = doc["materials"][materials["tinted_glass"]]["extensions"]["KHR_materials_volume"]
    volume.pop("attenuationDistance")
    volume.pop("attenuationColor")
names = [n.get("name") for n in doc["nodes"]]
for name in args.drop:
    if name not in names:
        raise SystemExit(f"features_for_mitsuba.py: no node named {name}")
    doc["scenes"][0]["nodes"].remove(names.index(name))
with open(args.dst, "w") as f:
    json.dump(doc, f, indent=1)
    f.write("\n")
