#!/usr/bin/env python3
"""Writes the scenes that measure light selection (docs/accuracy.md, "Light samplers"):

  lamps          an interior of three rooms joined by doorways, lit by 384 small square
                 lamps of varied power (three decades) and colour on the ceilings; most
                 lamps are hidden from most points by the partition walls; the camera
                 sees the lit rooms but no lamp, so that the error measured is the
                 lighting's
  emissive-mesh  a room lit by a glowing finely tessellated sphere (51,200 quads: 102,080
                 emissive triangles) and a dim ceiling panel
  near-light     a large panel light 3 cm in front of a wall and 3 cm above the floor of a
                 room, facing the wall: it lights the wall and the floor at close range,
                 where the camera looks

Every surface is exactly Lambertian. Units: millimetres in the code, metres in the file.
The scenes are written by `sh tools/make_scenes.sh` (lamps and near-light are small;
emissive-mesh is 3.3 MB and written on demand).

Usage: python3 tools/make_many_lights.py lamps|emissive-mesh|near-light [OUT.gltf]
       python3 tools/make_many_lights.py lamps --per-room 1|2|8|32|128 OUT.gltf
"""
import math, os, random, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_cornell_box import Builder, lambertian, sphere_quads, write_gltf  # noqa: E402

USAGE = "python3 tools/make_many_lights.py lamps|emissive-mesh|near-light [--per-room N] [OUT.gltf]"


def emitter(name, rgb, strength):
    """A black Lambertian surface emitting radiance rgb x strength (W m^-2 sr^-1)."""
    return {"name": name, "pbrMetallicRoughness": {"baseColorFactor": [0.0, 0.0, 0.0, 1.0],
            "metallicFactor": 0.0, "roughnessFactor": 1.0},
            "emissiveFactor": list(rgb),
            "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": strength},
                           "KHR_materials_specular": {"specularFactor": 0.0}}}


def box_faces(lo, hi, inward):
    """The six faces of the box lo..hi, wound to face inward (a room) or outward (a block)."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    faces = [
        [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)],  # floor, normal -y
        [(x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)],  # ceiling, +y
        [(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)],  # -x
        [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)],  # +x
        [(x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0)],  # -z
        [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)],  # +z
    ]
    return [list(reversed(f)) for f in faces] if inward else faces


def square(centre, half, axis, facing):
    """A square of half-size `half` around centre, in the plane normal to axis (0, 1, 2),
    facing +axis (facing 1) or -axis (-1): counter-clockwise seen from that side."""
    u, v = [(1, 2), (2, 0), (0, 1)][axis]
    corners = []
    for du, dv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
        p = list(centre)
        p[u] += du * half
        p[v] += dv * half
        corners.append(tuple(p))
    return corners if facing > 0 else list(reversed(corners))


def lamps(b, materials, per_room=128):
    """Three rooms 3 x 2.8 x 4 m side by side along x, joined by 1 m doorways, with
    `per_room` lamps (128; 1, 2, 8 or 32 for the crossover study) on each ceiling; the
    camera looks down across the first room and through a doorway, and sees no lamp."""
    grey = len(materials)
    materials.append(lambertian("plaster", (0.7, 0.68, 0.65)))
    b.add_mesh("rooms", box_faces((0, 0, 0), (9000, 2800, 4000), inward=True), grey)
    for x in (3000, 6000):  # partition walls, both faces, with a doorway at z 1500..2500
        for z0, z1 in ((0, 1500), (2500, 4000)):
            wall = box_faces((x - 50, 0, z0), (x + 50, 2800, z1), inward=False)
            b.add_mesh(f"partition_{x}_{z0}", wall[2:], grey)
    b.add_mesh("block", box_faces((1200, 0, 1200), (2000, 1400, 2200), inward=False)[1:], grey)
    rng = random.Random(47)
    cols = {1: 1, 2: 2, 8: 4, 32: 8, 128: 16}[per_room]
    rows = per_room // cols
    count = 0
    for room in range(3):
        for i in range(cols):
            for j in range(rows):  # a jittered grid on each ceiling
                x = room * 3000 + (i + 0.5) * 3000 / cols + rng.uniform(-40, 40)
                z = (j + 0.5) * 4000 / rows + rng.uniform(-80, 80)
                # Fewer lamps shine brighter: the rooms' light stays about the same.
                add_lamp(b, materials, rng, (x, 2799, z), 1, -1, count, 128.0 / per_room)
                count += 1
    return (1500.0, 1700.0, 3900.0), (4000.0, 0.0, 1500.0)


def add_lamp(b, materials, rng, centre, axis, facing, index, scale=1.0):
    warm = rng.random() < 0.6
    rgb = (1.0, 0.75, 0.45) if warm else (0.6, 0.75, 1.0)
    strength = scale * 10.0 ** rng.uniform(-0.5, 2.5)  # three decades
    materials.append(emitter(f"lamp_{index}", rgb, strength))
    b.add_mesh(f"lamp_{index}", [square(centre, 30, axis, facing)], len(materials) - 1)


def emissive_mesh(b, materials):
    grey = len(materials)
    materials.append(lambertian("plaster", (0.7, 0.68, 0.65)))
    b.add_mesh("room", box_faces((0, 0, 0), (4000, 2800, 4000), inward=True), grey)
    materials.append(emitter("glow", (1.0, 0.6, 0.3), 6.0))
    quads = sphere_quads(2000, 900, 2000, 400, stacks=160, slices=320)
    b.add_mesh("glowing_sphere", quads, len(materials) - 1)
    materials.append(emitter("panel", (0.8, 0.9, 1.0), 2.0))
    b.add_mesh("panel", [square((3000, 2799, 1000), 200, 1, -1)], len(materials) - 1)
    return (3600.0, 1600.0, 300.0), (2000.0, 700.0, 2000.0)


def near_light(b, materials):
    grey = len(materials)
    materials.append(lambertian("plaster", (0.7, 0.68, 0.65)))
    b.add_mesh("room", box_faces((0, 0, 0), (4000, 2800, 4000), inward=True), grey)
    materials.append(emitter("panel", (1.0, 0.9, 0.8), 20.0))
    # 1 m x 0.5 m, upright, 30 mm in front of the back wall (z 4000) and 30 mm above the
    # floor, facing the wall: it washes the wall and the floor at close range.
    panel = [(1500, 30, 3970), (2500, 30, 3970), (2500, 530, 3970), (1500, 530, 3970)]
    b.add_mesh("panel", [panel], len(materials) - 1)
    return (2000.0, 1200.0, 1500.0), (2000.0, 250.0, 4000.0)


def look_at_rotation(eye, target):
    """Rotation (x, y, z, w) turning the camera's -Z towards target, +Y staying up."""
    f = [t - e for t, e in zip(target, eye)]
    n = math.sqrt(sum(c * c for c in f))
    f = [c / n for c in f]
    yaw = math.atan2(-f[0], -f[2])
    pitch = math.asin(f[1])
    cy, sy, cp, sp = math.cos(yaw / 2), math.sin(yaw / 2), math.cos(pitch / 2), math.sin(pitch / 2)
    # yaw about +Y, then pitch about the turned +X
    return [cy * sp, sy * cp, -sy * sp, cy * cp]


def main():
    args = sys.argv[1:]
    if not args or args[0] in ("-h", "--help") or args[0] not in ("lamps", "emissive-mesh", "near-light"):
        sys.exit(f"usage: {USAGE}")
    kind = args.pop(0)
    per_room = 128
    if len(args) >= 2 and args[0] == "--per-room":
        if kind != "lamps" or args[1] not in ("1", "2", "8", "32", "128"):
            sys.exit(f"usage: {USAGE}")
        per_room = int(args[1])
        args = args[2:]
    out = args[0] if args else f"scenes/{kind}.gltf"
    b = Builder()
    materials = []
    if kind == "lamps":
        eye, target = lamps(b, materials, per_room)
    else:
        eye, target = {"emissive-mesh": emissive_mesh, "near-light": near_light}[kind](b, materials)
    b.nodes.append({"name": "camera", "camera": 0, "translation": [c / 1000.0 for c in eye],
                    "rotation": look_at_rotation(eye, target)})
    gltf = b.document("pathcl tools/make_many_lights.py", kind, materials, math.radians(60.0),
                      ["KHR_materials_emissive_strength", "KHR_materials_specular"])
    write_gltf(out, gltf)


if __name__ == "__main__":
    main()
