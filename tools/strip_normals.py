#!/usr/bin/env python3
"""Writes a copy of a .gltf scene without NORMAL attributes (flat shading), for like-for-
like comparisons with tools/mitsuba_reference.py, which ignores vertex normals. Buffers
stay as they are (the normal data is simply no longer referenced); relative uris keep
working only if OUT is in the same directory as IN.

Usage: python3 tools/strip_normals.py IN.gltf OUT.gltf
"""
import json
import sys

if len(sys.argv) != 3:
    sys.exit(__doc__)
doc = json.load(open(sys.argv[1]))
for mesh in doc.get("meshes", []):
    for prim in mesh.get("primitives", []):
        prim.get("attributes", {}).pop("NORMAL", None)
with open(sys.argv[2], "w") as f:
    json.dump(doc, f, indent=1)
    f.write("\n")
