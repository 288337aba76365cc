#!/usr/bin/env python3
"""Writes the instancing memory scene: one smooth sphere of 10,000 triangles drawn 10,000
times by EXT_mesh_gpu_instancing (10^8 triangles drawn) on a 100 x 100 grid over a grey
ground, under a sun (a directional light), seen from above one corner.
docs/gltf.md's figure for a two-level BVH's memory is measured on it:

    python3 tools/make_instance_field.py /tmp/field.gltf
    /usr/bin/time -v build/pathcl render /tmp/field.gltf -o /tmp/field.png --spp 16 --background 0.3,0.4,0.5

Usage: python3 tools/make_instance_field.py OUT.gltf
"""
import base64, json, math, struct, sys

STACKS, SLICES = 51, 100  # 2 x 100 + 49 x 100 x 2 = 10,000 triangles
GRID, SPACING, RADIUS = 100, 0.5, 0.2


def sphere():
    positions, normals, indices = [], [], []
    for i in range(STACKS + 1):
        th = math.pi * i / STACKS
        for j in range(SLICES + 1):
            ph = 2 * math.pi * j / SLICES
            n = (math.sin(th) * math.cos(ph), math.cos(th), math.sin(th) * math.sin(ph))
            normals.append(n)
            positions.append(tuple(RADIUS * c for c in n))
    row = SLICES + 1
    for i in range(STACKS):
        for j in range(SLICES):
            a, b, c, d = i * row + j, i * row + j + 1, (i + 1) * row + j + 1, (i + 1) * row + j
            if i > 0:
                indices += [a, b, c]
            if i < STACKS - 1:
                indices += [a, c, d]
    return positions, normals, indices


def look_at(eye, target):
    """The rotation (x, y, z, w) that turns a glTF camera (looking along -Z, +Y up) at target."""
    f = [t - e for t, e in zip(target, eye)]
    n = math.sqrt(sum(c * c for c in f))
    back = [-c / n for c in f]
    right = [back[2], 0.0, -back[0]]  # cross(up, back) with up = +Y
    n = math.sqrt(sum(c * c for c in right))
    right = [c / n for c in right]
    up = [back[1] * right[2] - back[2] * right[1], back[2] * right[0] - back[0] * right[2],
          back[0] * right[1] - back[1] * right[0]]
    m = [[right[0], up[0], back[0]], [right[1], up[1], back[1]], [right[2], up[2], back[2]]]
    w = math.sqrt(max(0.0, 1.0 + m[0][0] + m[1][1] + m[2][2])) / 2
    return [(m[2][1] - m[1][2]) / (4 * w), (m[0][2] - m[2][0]) / (4 * w), (m[1][0] - m[0][1]) / (4 * w), w]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.strip().splitlines()[-1])
    blob, views, accessors = bytearray(), [], []

    def add(data, count, kind, component=5126, target=None, bounds=None):
        while len(blob) % 4:
            blob.append(0)
        view = {"buffer": 0, "byteOffset": len(blob), "byteLength": len(data)}
        if target:
            view["target"] = target
        views.append(view)
        blob.extend(data)
        accessor = {"bufferView": len(views) - 1, "componentType": component, "count": count, "type": kind}
        if bounds:
            accessor["min"], accessor["max"] = bounds
        accessors.append(accessor)
        return len(accessors) - 1

    positions, normals, indices = sphere()
    f32 = lambda x: struct.unpack("<f", struct.pack("<f", x))[0]
    lo = [f32(min(p[k] for p in positions)) for k in range(3)]
    hi = [f32(max(p[k] for p in positions)) for k in range(3)]
    pos = add(b"".join(struct.pack("<3f", *p) for p in positions), len(positions), "VEC3", target=34962,
              bounds=(lo, hi))
    nrm = add(b"".join(struct.pack("<3f", *n) for n in normals), len(normals), "VEC3", target=34962)
    idx = add(b"".join(struct.pack("<I", i) for i in indices), len(indices), "SCALAR", 5125, 34963)
    translations = [((i - GRID / 2) * SPACING, RADIUS, (j - GRID / 2) * SPACING) for i in range(GRID)
                    for j in range(GRID)]
    tra = add(b"".join(struct.pack("<3f", *t) for t in translations), len(translations), "VEC3")
    half = GRID * SPACING
    ground = [(-half, 0, -half), (-half, 0, half), (half, 0, half), (half, 0, -half)]
    gpos = add(b"".join(struct.pack("<3f", *p) for p in ground), 4, "VEC3", target=34962,
               bounds=([-half, 0, -half], [half, 0, half]))
    gidx = add(struct.pack("<6H", 0, 1, 2, 0, 2, 3), 6, "SCALAR", 5123, 34963)
    sun = [-0.3535534, 0.3535534, 0.1464466, 0.8535534]  # node -Z tilted down, turned
    doc = {
        "asset": {"version": "2.0", "generator": "pathcl tools/make_instance_field.py"},
        "extensionsUsed": ["EXT_mesh_gpu_instancing", "KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 3.0}]}},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2, 3]}],
        "nodes": [
            {"name": "spheres", "mesh": 0, "extensions": {"EXT_mesh_gpu_instancing": {"attributes": {
                "TRANSLATION": tra}}}},
            {"name": "ground", "mesh": 1},
            {"name": "sun", "rotation": sun, "extensions": {"KHR_lights_punctual": {"light": 0}}},
            {"name": "camera", "camera": 0, "translation": [-28.0, 6.0, -28.0],
             "rotation": look_at((-28.0, 6.0, -28.0), (0.0, 0.0, 0.0))},
        ],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.01}}],
        "meshes": [
            {"name": "sphere", "primitives": [{"attributes": {"POSITION": pos, "NORMAL": nrm}, "indices": idx,
                                               "material": 0}]},
            {"name": "ground", "primitives": [{"attributes": {"POSITION": gpos}, "indices": gidx, "material": 1}]},
        ],
        "materials": [
            {"name": "sphere", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.3, 0.2, 1.0],
                                                        "metallicFactor": 0.0, "roughnessFactor": 0.5}},
            {"name": "ground", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1.0],
                                                        "metallicFactor": 0.0, "roughnessFactor": 1.0}},
        ],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(blob)).decode("ascii")}],
    }
    with open(sys.argv[1], "w") as f:
        json.dump(doc, f)


if __name__ == "__main__":
    main()
