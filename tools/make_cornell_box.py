#!/usr/bin/env python3
"""Writes scenes/cornell-box.gltf: the Cornell box from the Cornell University Program of
Computer Graphics' published measurements (https://www.graphics.cornell.edu/online/box/data.html).

Geometry is the measured data in millimetres, converted to metres (glTF units). The light
sits flush in the ceiling: the ceiling is cut into four rectangles around it, so the light
neither z-fights the ceiling nor hangs below it. Reflectances and the light's radiance are
the RGB conversions of the measured spectra used by the pbrt-v4 / Mitsuba 3 / Bitterli
Cornell box scenes. Walls are exactly Lambertian (metallic 0, KHR_materials_specular
specularFactor 0). The camera is the measured pinhole: 35 mm focal length, 25 mm square
film, at (278, 273, -800) looking along +z.

With --light KIND the ceiling light is replaced by a KHR_lights_punctual light of that
kind (point, sphere, spot, rect-spot, directional) and the ceiling is closed: one test scene per
light type (scenes/cornell-box-KIND.gltf, written by tools/make_scenes.sh). With
--variant glass-mirror the tall block is an ideal mirror and the short block gives way
to a solid glass sphere (scenes/cornell-box-glass-mirror.gltf). With --variant features
the short block gives way to a sphere of coloured glass (KHR_materials_volume
attenuation), the tall block is clear-coated red plastic (KHR_materials_clearcoat) and a
leaf cut out of a card by its texture's alpha (alphaMode MASK) hangs in front of the back
wall (scenes/cornell-box-features.gltf). With --variant instanced the short block is
drawn twice by two nodes (the second mirrored, stretched and turned where the tall block
stood) and a row of gold beads is one sphere drawn six times by EXT_mesh_gpu_instancing
(scenes/cornell-box-instanced.gltf). With --variant dense the
short block gives way to a displaced, flat-shaded white blob of 1,048,576 triangles: the
million-triangle scene of the speed comparison (tools/compare_mitsuba.sh writes it; 32 MB,
not committed).

Usage: python3 tools/make_cornell_box.py [--light KIND] [--variant glass-mirror|features|instanced|dense] [OUT.gltf]
"""
import base64, json, math, struct, sys, zlib

MM = 0.001

# Quads as listed by the measurement page (mm). Each quad is oriented below so that its
# geometric (counter-clockwise) normal faces the inside of the box / out of the blocks.
FLOOR = [(552.8, 0, 0), (0, 0, 0), (0, 0, 559.2), (549.6, 0, 559.2)]
LIGHT = [(343, 548.8, 227), (343, 548.8, 332), (213, 548.8, 332), (213, 548.8, 227)]
CEILING_PIECES = [  # the ceiling (0..556 x 0..559.2 at y 548.8) minus the light's rectangle
    [(0, 548.8, 0), (213, 548.8, 0), (213, 548.8, 559.2), (0, 548.8, 559.2)],
    [(343, 548.8, 0), (556, 548.8, 0), (556, 548.8, 559.2), (343, 548.8, 559.2)],
    [(213, 548.8, 0), (343, 548.8, 0), (343, 548.8, 227), (213, 548.8, 227)],
    [(213, 548.8, 332), (343, 548.8, 332), (343, 548.8, 559.2), (213, 548.8, 559.2)],
]
BACK_WALL = [(549.6, 0, 559.2), (0, 0, 559.2), (0, 548.8, 559.2), (556, 548.8, 559.2)]
RIGHT_WALL = [(0, 0, 559.2), (0, 0, 0), (0, 548.8, 0), (0, 548.8, 559.2)]  # green
LEFT_WALL = [(552.8, 0, 0), (549.6, 0, 559.2), (556, 548.8, 559.2), (556, 548.8, 0)]  # red
SHORT_BLOCK = [
    [(130, 165, 65), (82, 165, 225), (240, 165, 272), (290, 165, 114)],
    [(290, 0, 114), (290, 165, 114), (240, 165, 272), (240, 0, 272)],
    [(130, 0, 65), (130, 165, 65), (290, 165, 114), (290, 0, 114)],
    [(82, 0, 225), (82, 165, 225), (130, 165, 65), (130, 0, 65)],
    [(240, 0, 272), (240, 165, 272), (82, 165, 225), (82, 0, 225)],
]
TALL_BLOCK = [
    [(423, 330, 247), (265, 330, 296), (314, 330, 456), (472, 330, 406)],
    [(423, 0, 247), (423, 330, 247), (472, 330, 406), (472, 0, 406)],
    [(472, 0, 406), (472, 330, 406), (314, 330, 456), (314, 0, 456)],
    [(314, 0, 456), (314, 330, 456), (265, 330, 296), (265, 0, 296)],
    [(265, 0, 296), (265, 330, 296), (423, 330, 247), (423, 0, 247)],
]
BOX_CENTRE = (278.0, 274.4, 279.6)

def sub(a, b): return tuple(x - y for x, y in zip(a, b))
def cross(a, b): return (a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0])
def dot(a, b): return sum(x * y for x, y in zip(a, b))
def centroid(q): return tuple(sum(v[i] for v in q) / len(q) for i in range(3))

def oriented(quad, facing):
    """Returns the quad wound so that its normal points towards `facing` (a point)."""
    n = cross(sub(quad[1], quad[0]), sub(quad[2], quad[0]))
    return quad if dot(n, sub(facing, centroid(quad))) > 0 else list(reversed(quad))

def outward(quad, solid_centre):
    n_quad = oriented(quad, solid_centre)
    return list(reversed(n_quad))

def block_centre(faces):
    pts = [v for f in faces for v in f]
    return centroid(pts)

class Builder:
    def __init__(self):
        self.blob = bytearray()
        self.accessors, self.views, self.meshes, self.nodes = [], [], [], []

    def document(self, generator, scene_name, materials, yfov, extensions_used, scene_extras=None):
        """The glTF document: the nodes added so far make up the scene (camera 0 is a
        square perspective camera of vertical field of view yfov); the buffer is embedded."""
        scene = {"name": scene_name, "nodes": list(range(len(self.nodes)))}
        if scene_extras:
            scene["extras"] = scene_extras
        return {
            "asset": {"version": "2.0", "generator": generator},
            "extensionsUsed": extensions_used,
            "scene": 0,
            "scenes": [scene],
            "nodes": self.nodes, "meshes": self.meshes, "materials": materials,
            "cameras": [{"type": "perspective", "perspective": {
                "yfov": yfov, "aspectRatio": 1.0, "znear": 0.01}}],
            "accessors": self.accessors, "bufferViews": self.views,
            "buffers": [{"byteLength": len(self.blob), "uri": "data:application/octet-stream;base64,"
                         + base64.b64encode(bytes(self.blob)).decode("ascii")}],
        }

    def add_view(self, data, target):
        while len(self.blob) % 4:
            self.blob.append(0)
        view = {"buffer": 0, "byteOffset": len(self.blob), "byteLength": len(data)}
        if target is not None:
            view["target"] = target
        self.views.append(view)
        self.blob += data
        return len(self.views) - 1

    def add_mesh(self, name, quads, material, normals=None):
        """Quads in millimetres; normals (optional): one unit vector per quad corner."""
        positions, indices, nrm = [], [], []
        for qi, q in enumerate(quads):
            base = len(positions)
            positions += [tuple(c * MM for c in v) for v in q]
            if normals is not None:
                nrm += normals[qi]
            for tri in ((0, 1, 2), (0, 2, 3)):
                if len({q[k] for k in tri}) == 3:  # a quad collapsed to a triangle (a pole)
                    indices += [base + k for k in tri]
        pos_bytes = b"".join(struct.pack("<3f", *p) for p in positions)
        idx_bytes = b"".join(struct.pack("<H" if len(positions) < 65536 else "<I", i) for i in indices)
        lo = [min(p[i] for p in positions) for i in range(3)]
        hi = [max(p[i] for p in positions) for i in range(3)]
        # glTF requires min/max to match the stored (float32) values exactly.
        f32 = lambda x: struct.unpack("<f", struct.pack("<f", x))[0]
        pv = self.add_view(pos_bytes, 34962)
        self.accessors.append({"bufferView": pv, "componentType": 5126, "count": len(positions),
                               "type": "VEC3", "min": [f32(x) for x in lo],
                               "max": [f32(x) for x in hi]})
        attributes = {"POSITION": len(self.accessors) - 1}
        if normals is not None:
            nv = self.add_view(b"".join(struct.pack("<3f", *n) for n in nrm), 34962)
            self.accessors.append({"bufferView": nv, "componentType": 5126, "count": len(nrm),
                                   "type": "VEC3"})
            attributes["NORMAL"] = len(self.accessors) - 1
        iv = self.add_view(idx_bytes, 34963)
        self.accessors.append({"bufferView": iv, "componentType": 5123 if len(positions) < 65536 else 5125,
                               "count": len(indices), "type": "SCALAR"})
        self.meshes.append({"name": name, "primitives": [{
            "attributes": attributes,
            "indices": len(self.accessors) - 1, "material": material, "mode": 4}]})
        self.nodes.append({"name": name, "mesh": len(self.meshes) - 1})

def write_gltf(path, gltf):
    with open(path, "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


def sphere_quads(cx, cy, cz, r, stacks=12, slices=24):
    """Quads (4 points, counter-clockwise seen from outside) of a UV sphere, in the
    millimetres the Builder converts; the pole rows collapse to triangles."""
    def p(i, j):
        th, ph = math.pi * i / stacks, 2 * math.pi * j / slices
        sin_th = 0.0 if i in (0, stacks) else math.sin(th)  # exact poles: one shared point
        return (cx + r * sin_th * math.cos(ph), cy + r * math.cos(th), cz + r * sin_th * math.sin(ph))
    quads = []
    for i in range(stacks):
        for j in range(slices):
            quads.append([p(i, j), p(i, j + 1), p(i + 1, j + 1), p(i + 1, j)])
    return quads

def sphere_normals(quads, cx, cy, cz):
    """Smooth (radial) vertex normals for sphere_quads."""
    def n(v):
        d = (v[0] - cx, v[1] - cy, v[2] - cz)
        l = math.sqrt(dot(d, d))
        return tuple(x / l for x in d)
    return [[n(v) for v in q] for q in quads]

def lambertian(name, rgb):
    return {"name": name, "pbrMetallicRoughness": {"baseColorFactor": list(rgb) + [1.0],
            "metallicFactor": 0.0, "roughnessFactor": 1.0},
            "extensions": {"KHR_materials_specular": {"specularFactor": 0.0}}}

# Punctual replacements for the ceiling light (radiometric: W/sr, or W/m^2 for directional).
# Each hangs 10 cm below the light's place in the ceiling, pointing down, except the
# directional light, which shines in through the open front at an angle.
PUNCTUAL_LIGHTS = {
    "point": {"type": "point", "color": [1.0, 0.85, 0.6], "intensity": 0.15},
    # A point light with extras.radius is a sphere light (uniform radiance I / (pi r^2)).
    "sphere": {"type": "point", "color": [1.0, 0.85, 0.6], "intensity": 0.15, "extras": {"radius": 0.06}},
    "spot": {"type": "spot", "color": [1.0, 0.85, 0.6], "intensity": 1.5,
             "spot": {"innerConeAngle": math.radians(25.0), "outerConeAngle": math.radians(40.0)}},
    # KHR_lights_punctual requires "spot" for spot lights; pathcl ignores its angles when
    # extras hfov/vfov are present. The outer angle is the frustum's half diagonal, so
    # other viewers show a cone around the frustum.
    "rect-spot": {"type": "spot", "color": [1.0, 0.85, 0.6], "intensity": 1.5,
                  "spot": {"innerConeAngle": 0.0, "outerConeAngle": math.atan(math.hypot(
                      math.tan(math.radians(35.0)), math.tan(math.radians(22.5))))},
                  "extras": {"hfov": 70.0, "vfov": 45.0}},
    "directional": {"type": "directional", "color": [1.0, 0.85, 0.6], "intensity": 3.0},
}
LOOK_DOWN = [-math.sqrt(0.5), 0.0, 0.0, math.sqrt(0.5)]  # node -Z to world -Y

def quat_from_to(a, b):
    """Shortest-arc rotation (x, y, z, w) taking direction a to direction b."""
    na, nb = math.sqrt(dot(a, a)), math.sqrt(dot(b, b))
    a = tuple(x / na for x in a)
    b = tuple(x / nb for x in b)
    axis = cross(a, b)
    w = 1.0 + dot(a, b)
    n = math.sqrt(dot(axis, axis) + w * w)
    return [axis[0] / n, axis[1] / n, axis[2] / n, w / n]

def quat_rotate(q, v):
    x, y, z, w = q
    u = (x, y, z)
    t = tuple(2.0 * c for c in cross(u, v))
    return tuple(v[i] + w * t[i] + cross(u, t)[i] for i in range(3))

# --variant glass-mirror: the tall block becomes an ideal mirror (metallic 1, roughness 0)
# and the short block a solid glass sphere (KHR_materials_transmission 1, ior 1.5,
# KHR_materials_volume thickness > 0, roughness 0) resting on the floor where it stood.
MIRROR = {"name": "mirror", "pbrMetallicRoughness": {"baseColorFactor": [1.0, 1.0, 1.0, 1.0],
          "metallicFactor": 1.0, "roughnessFactor": 0.0}}
GLASS = {"name": "glass", "pbrMetallicRoughness": {"baseColorFactor": [1.0, 1.0, 1.0, 1.0],
         "metallicFactor": 0.0, "roughnessFactor": 0.0},
         "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0},
                        "KHR_materials_ior": {"ior": 1.5},
                        "KHR_materials_volume": {"thicknessFactor": 0.2}}}
GLASS_SPHERE = (185.0, 100.5, 169.0, 100.0)  # centre and radius, mm: 0.5 mm above the floor

# --variant features: glass tinted by absorption (what is left after 10 cm: the
# attenuation colour), a red plastic under a smooth clear coat, and a leaf card.
TINTED_GLASS = {"name": "tinted_glass", "pbrMetallicRoughness": {"baseColorFactor": [1.0, 1.0, 1.0, 1.0],
                "metallicFactor": 0.0, "roughnessFactor": 0.0},
                "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0},
                               "KHR_materials_ior": {"ior": 1.5},
                               "KHR_materials_volume": {"thicknessFactor": 0.2, "attenuationDistance": 0.1,
                                                        "attenuationColor": [0.35, 0.75, 0.95]}}}
COATED = {"name": "coated_red", "pbrMetallicRoughness": {"baseColorFactor": [0.55, 0.08, 0.05, 1.0],
          "metallicFactor": 0.0, "roughnessFactor": 0.6},
          "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1.0, "clearcoatRoughnessFactor": 0.08}}}
# The leaf card (mm): upright, facing the camera (-z), in front of the back wall, above the
# tall block; its texture's alpha cuts the leaf out (alphaCutoff 0.5).
LEAF_CARD = [(320, 300, 500), (520, 300, 500), (520, 520, 500), (320, 520, 500)]

# --variant instanced: meshes stored once and drawn several times. The short block is
# drawn twice: in its place, and by a second node that mirrors it (negative determinant:
# clockwise is its front), stretches it to twice its height and turns it 30 degrees about
# the vertical where the tall block stood. A row of gold beads along the front is one
# smooth sphere drawn by EXT_mesh_gpu_instancing: flattened, tilted and turned per bead
# (non-uniform scales take the normals through the inverse transpose).
GOLD = {"name": "gold", "pbrMetallicRoughness": {"baseColorFactor": [1.0, 0.78, 0.34, 1.0],
        "metallicFactor": 1.0, "roughnessFactor": 0.35}}
BEAD_RADIUS = 40.0  # mm
BEADS = 6

def mat_mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]

def translation(x, y, z):
    return [[1, 0, 0, x], [0, 1, 0, y], [0, 0, 1, z], [0, 0, 0, 1]]

def rotation_y(degrees):
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return [[c, 0, s, 0], [0, 1, 0, 0], [-s, 0, c, 0], [0, 0, 0, 1]]

def scaling(x, y, z):
    return [[x, 0, 0, 0], [0, y, 0, 0], [0, 0, z, 0], [0, 0, 0, 1]]

def column_major(m):
    return [m[r][c] for c in range(4) for r in range(4)]

def add_instanced_meshes(b, white, gold):
    """The short block twice and the row of beads (see above); returns the extensions used."""
    b.add_mesh("short_block", [outward(q, block_centre(SHORT_BLOCK)) for q in SHORT_BLOCK], white)
    c = block_centre(SHORT_BLOCK)
    # In metres: take the block's centre (on the floor) to the origin, mirror x, stretch y,
    # turn, and stand it where the tall block stood.
    t = block_centre(TALL_BLOCK)
    m = mat_mul(translation(t[0] * MM, 0.0, t[2] * MM),
                mat_mul(rotation_y(30.0), mat_mul(scaling(-1.0, 2.0, 1.0), translation(-c[0] * MM, 0.0, -c[2] * MM))))
    b.nodes.append({"name": "short_block_mirrored_tall", "mesh": len(b.meshes) - 1, "matrix": column_major(m)})
    quads = sphere_quads(0.0, 0.0, 0.0, BEAD_RADIUS, stacks=16, slices=32)
    b.add_mesh("bead", quads, gold, normals=sphere_normals(quads, 0.0, 0.0, 0.0))
    translations, rotations, scales = [], [], []
    for i in range(BEADS):
        squash = 0.55 + 0.08 * i
        translations.append((0.07 + 0.083 * i, BEAD_RADIUS * MM * squash, 0.06))
        tilt = math.radians(12.0 * (i - 2.5))  # about z, then turned about y
        turn = math.radians(25.0 * i)
        qz = (0.0, 0.0, math.sin(tilt / 2), math.cos(tilt / 2))
        qy = (0.0, math.sin(turn / 2), 0.0, math.cos(turn / 2))
        x1, y1, z1, w1 = qy
        x2, y2, z2, w2 = qz
        rotations.append((w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2, w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
                          w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2, w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2))
        scales.append((1.0, squash, 1.0 + 0.1 * i))
    attributes = {}
    for name, values, kind in (("TRANSLATION", translations, "VEC3"), ("ROTATION", rotations, "VEC4"),
                               ("SCALE", scales, "VEC3")):
        fmt = "<%df" % len(values[0])
        view = b.add_view(b"".join(struct.pack(fmt, *v) for v in values), None)
        b.accessors.append({"bufferView": view, "componentType": 5126, "count": len(values), "type": kind})
        attributes[name] = len(b.accessors) - 1
    b.nodes[-1]["extensions"] = {"EXT_mesh_gpu_instancing": {"attributes": attributes}}
    return ["EXT_mesh_gpu_instancing"]

def png_bytes(width, height, rgba):
    """An 8-bit RGBA PNG of rows (top first) of (r, g, b, a) tuples."""
    raw = b"".join(b"\x00" + b"".join(struct.pack("4B", *px) for px in row) for row in rgba)
    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))

def leaf_texels(size=64):
    """A leaf along the texture's diagonal: opaque green inside, alpha 0 outside, with a
    lighter midrib. Texel (i, j) is column i from the left, row j from the top."""
    rows = []
    for j in range(size):
        row = []
        for i in range(size):
            u, v = (i + 0.5) / size, 1.0 - (j + 0.5) / size  # v up
            t = (u + v) / 2.0                                  # along the leaf, stem at (0, 0)
            s = (u - v) / math.sqrt(2.0)                       # across it
            half_width = 0.28 * math.sin(math.pi * min(max((t - 0.08) / 0.88, 0.0), 1.0)) ** 0.8
            inside = abs(s) < half_width or (t < 0.1 and abs(s) < 0.015)  # blade, or stem
            rib = abs(s) < 0.012 and t < 0.9
            row.append((120, 200, 90, 255) if inside and rib else (40, 120, 30, 255) if inside else (40, 120, 30, 0))
        rows.append(row)
    return rows

def add_leaf_card(b, material):
    """The leaf card: a quad with texture coordinates, and its PNG in the buffer."""
    corners = [tuple(c * MM for c in v) for v in LEAF_CARD]
    uvs = [(0.0, 1.0), (1.0, 1.0), (1.0, 0.0), (0.0, 0.0)]  # the image upright, seen from -z
    pv = b.add_view(b"".join(struct.pack("<3f", *p) for p in corners), 34962)
    f32 = lambda x: struct.unpack("<f", struct.pack("<f", x))[0]
    b.accessors.append({"bufferView": pv, "componentType": 5126, "count": 4, "type": "VEC3",
                        "min": [f32(min(p[i] for p in corners)) for i in range(3)],
                        "max": [f32(max(p[i] for p in corners)) for i in range(3)]})
    tv = b.add_view(b"".join(struct.pack("<2f", *t) for t in uvs), 34962)
    b.accessors.append({"bufferView": tv, "componentType": 5126, "count": 4, "type": "VEC2"})
    iv = b.add_view(struct.pack("<6H", 0, 2, 1, 0, 3, 2), 34963)  # counter-clockwise from -z
    b.accessors.append({"bufferView": iv, "componentType": 5123, "count": 6, "type": "SCALAR"})
    n = len(b.accessors)
    b.meshes.append({"name": "leaf_card", "primitives": [{
        "attributes": {"POSITION": n - 3, "TEXCOORD_0": n - 2}, "indices": n - 1,
        "material": material, "mode": 4}]})
    b.nodes.append({"name": "leaf_card", "mesh": len(b.meshes) - 1})
    return b.add_view(png_bytes(64, 64, leaf_texels()), None)

def blob_quads(cx, cy, cz, r, stacks=512, slices=1024):
    """A sphere displaced by a few ridges (up to 9 % of r), as sphere_quads: stacks x slices
    quads, 2 * stacks * slices triangles (the displacement keeps the pole rows from
    collapsing). Detail smaller than a pixel at 256 x 256: a dense mesh's cost, not its looks."""
    def p(i, j):
        th, ph = math.pi * i / stacks, 2 * math.pi * j / slices
        sin_th = 0.0 if i in (0, stacks) else math.sin(th)
        rr = r * (1.0 + 0.06 * math.sin(9 * th) * math.cos(7 * ph) + 0.03 * math.sin(23 * th + 3 * ph))
        return (cx + rr * sin_th * math.cos(ph), cy + rr * math.cos(th), cz + rr * sin_th * math.sin(ph))
    row = [[p(i, j) for j in range(slices + 1)] for i in range(stacks + 1)]
    return [[row[i][j], row[i][j + 1], row[i + 1][j + 1], row[i + 1][j]]
            for i in range(stacks) for j in range(slices)]

USAGE = ("usage: make_cornell_box.py [--light point|sphere|spot|rect-spot|directional] "
         "[--variant glass-mirror|features|instanced|dense] [OUT.gltf]")


def main():
    args = sys.argv[1:]
    if any(a in ("-h", "--help") for a in args):
        print(USAGE)
        return
    light_kind, variant = None, None
    while len(args) >= 2 and args[0] in ("--light", "--variant"):
        if args[0] == "--light":
            light_kind = args[1]
            if light_kind not in PUNCTUAL_LIGHTS:
                sys.exit(f"make_cornell_box.py: --light must be one of {', '.join(PUNCTUAL_LIGHTS)}")
        else:
            variant = args[1]
            if variant not in ("glass-mirror", "features", "instanced", "dense"):
                sys.exit("make_cornell_box.py: --variant must be glass-mirror, features, instanced or dense")
        args = args[2:]
    name = "cornell-box" + (f"-{light_kind}" if light_kind else "") + (f"-{variant}" if variant else "")
    if len(args) > 1 or (args and args[0].startswith("-")):
        sys.exit(f"make_cornell_box.py: unexpected argument {args[-1]!r} ({USAGE})")
    out = args[0] if args else f"scenes/{name}.gltf"
    materials = [
        lambertian("white", (0.725, 0.71, 0.68)),
        lambertian("red", (0.63, 0.065, 0.05)),
        lambertian("green", (0.14, 0.45, 0.091)),
        {"name": "light", "pbrMetallicRoughness": {"baseColorFactor": [0.78, 0.78, 0.78, 1.0],
         "metallicFactor": 0.0, "roughnessFactor": 1.0},
         # Radiance (17, 12, 4) W m^-2 sr^-1 = factor x strength.
         "emissiveFactor": [1.0, 12.0 / 17.0, 4.0 / 17.0],
         "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 17.0},
                        "KHR_materials_specular": {"specularFactor": 0.0}}},
    ]
    WHITE, RED, GREEN, LIGHT_M = 0, 1, 2, 3
    b = Builder()
    inside = BOX_CENTRE
    b.add_mesh("floor", [oriented(FLOOR, inside)], WHITE)
    b.add_mesh("ceiling", [oriented(q, inside) for q in CEILING_PIECES], WHITE)
    b.add_mesh("back_wall", [oriented(BACK_WALL, inside)], WHITE)
    b.add_mesh("right_wall_green", [oriented(RIGHT_WALL, inside)], GREEN)
    b.add_mesh("left_wall_red", [oriented(LEFT_WALL, inside)], RED)
    extensions_used = ["KHR_materials_emissive_strength", "KHR_materials_specular"]
    if variant == "glass-mirror":
        materials += [MIRROR, GLASS]
        mirror_m, glass_m = len(materials) - 2, len(materials) - 1
        quads = sphere_quads(*GLASS_SPHERE, stacks=32, slices=64)
        b.add_mesh("glass_sphere", quads, glass_m, normals=sphere_normals(quads, *GLASS_SPHERE[:3]))
        b.add_mesh("tall_block_mirror", [outward(q, block_centre(TALL_BLOCK)) for q in TALL_BLOCK], mirror_m)
        extensions_used += ["KHR_materials_transmission", "KHR_materials_ior", "KHR_materials_volume"]
    elif variant == "features":
        materials += [TINTED_GLASS, COATED, {
            "name": "leaf", "doubleSided": True, "alphaMode": "MASK", "alphaCutoff": 0.5,
            "pbrMetallicRoughness": {"baseColorFactor": [1.0, 1.0, 1.0, 1.0], "baseColorTexture": {"index": 0},
                                     "metallicFactor": 0.0, "roughnessFactor": 1.0},
            "extensions": {"KHR_materials_specular": {"specularFactor": 0.0}}}]
        glass_m, coated_m, leaf_m = len(materials) - 3, len(materials) - 2, len(materials) - 1
        quads = sphere_quads(*GLASS_SPHERE, stacks=32, slices=64)
        b.add_mesh("tinted_glass_sphere", quads, glass_m, normals=sphere_normals(quads, *GLASS_SPHERE[:3]))
        b.add_mesh("tall_block_coated", [outward(q, block_centre(TALL_BLOCK)) for q in TALL_BLOCK], coated_m)
        leaf_image = add_leaf_card(b, leaf_m)
        extensions_used += ["KHR_materials_transmission", "KHR_materials_ior", "KHR_materials_volume",
                            "KHR_materials_clearcoat"]
    elif variant == "instanced":
        materials.append(GOLD)
        extensions_used += add_instanced_meshes(b, WHITE, len(materials) - 1)
    elif variant == "dense":
        b.add_mesh("blob", blob_quads(*GLASS_SPHERE), WHITE)
        b.add_mesh("tall_block", [outward(q, block_centre(TALL_BLOCK)) for q in TALL_BLOCK], WHITE)
    else:
        b.add_mesh("short_block", [outward(q, block_centre(SHORT_BLOCK)) for q in SHORT_BLOCK], WHITE)
        b.add_mesh("tall_block", [outward(q, block_centre(TALL_BLOCK)) for q in TALL_BLOCK], WHITE)
    lights = []
    if light_kind is None:
        b.add_mesh("light", [oriented(LIGHT, (278, 0, 279.5))], LIGHT_M)  # faces down
    else:
        b.add_mesh("ceiling_closed", [oriented(LIGHT, (278, 0, 279.5))], WHITE)
        lights.append(dict(PUNCTUAL_LIGHTS[light_kind], name=light_kind))
        extensions_used.append("KHR_lights_punctual")
        if light_kind == "directional":
            # Into the box (+z) and down, through the open front, slightly sideways.
            rot = quat_from_to((0.0, 0.0, -1.0), (0.15, -0.55, 1.0))
            node = {"name": "light", "translation": [0.278, 0.4, -0.5], "rotation": rot}
        else:
            node = {"name": "light", "translation": [0.278, 0.4488, 0.2795], "rotation": LOOK_DOWN}
        node["extensions"] = {"KHR_lights_punctual": {"light": 0}}
        b.nodes.append(node)

    yfov = 2.0 * math.atan(12.5 / 35.0)
    # glTF cameras look along local -Z; a half turn about +Y makes that world +Z.
    b.nodes.append({"name": "camera", "camera": 0, "translation": [0.278, 0.273, -0.800],
                    "rotation": [0.0, 1.0, 0.0, 0.0]})
    gltf = b.document("pathcl tools/make_cornell_box.py", "cornell-box" + (f"-{variant}" if variant else ""),
                      materials, yfov, extensions_used)
    if lights:
        gltf["extensions"] = {"KHR_lights_punctual": {"lights": lights}}
    if variant == "features":
        gltf["images"] = [{"name": "leaf", "bufferView": leaf_image, "mimeType": "image/png"}]
        gltf["textures"] = [{"source": 0}]
    write_gltf(out, gltf)

if __name__ == "__main__":
    main()
