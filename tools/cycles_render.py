#!/usr/bin/env python3
"""Renders a glTF scene with Blender's Cycles (CPU) for tools/compare_mitsuba.py.

    cycles_render.py SCENE.gltf --out PREFIX --size N --spp S --max-bounces B
        [--seeds 1,2,3] [--warm-up] [--no-light-tree]

Runs under the bpy venv's python (tools/cycles_venv.sh), not Mitsuba's: the two wheels
pin different numpy versions. For each seed it writes PREFIX-SEED.exr (R, G, B, A,
float32, linear) and prints `seed SEED render SECONDS s PATH`.

The scene is tools/mitsuba_reference.py's load_scene parse, built from numpy arrays, so
that Cycles sees the triangles, materials, camera and lights Mitsuba sees (Blender's
glTF importer is not used: its Principled BSDF is not exactly Lambertian). Only what
tools/make_many_lights.py and the Lambertian Cornell box use is supported: Lambertian
materials with a constant base colour and emission, and no punctual lights; anything
else ends it with exit status 3 (tools/compare_mitsuba.py then leaves Cycles out of
that scene's table).

Conventions matched to pathcl:
  * Lambertian: Diffuse BSDF, roughness 0. glTF doubleSided false makes the back side
    black, as pathcl does (Cycles' BSDFs shade both sides): a Mix Shader by
    Geometry.Backfacing with nothing on its back input (no closure: black, opaque).
  * Emission (emissiveFactor x KHR_materials_emissive_strength) is radiance, Cycles'
    Emission shader's strength-1 unit, from the front face only (the counter-clockwise
    side, Blender's face normal too): added to the diffuse part before the backfacing
    mix, and material.cycles.emission_sampling = FRONT so that light sampling and the
    light tree ignore the back (FRONT alone still shows the back's emission to rays
    that hit it). The mix costs Cycles its constant-emission shortcut (the shader is
    evaluated at each light sample): 4 % of its render time on the lamps, measured
    against plain two-sided Emission.
  * --max-bounces B counts scattering events (0: emission only). Cycles' max_bounces
    counts bounces after the first hit: 0 is direct lighting, one scattering event. So
    max_bounces and every per-type limit = B - 1 (B = 0 is refused). Checked with
    tools/cycles_bias_check.py at B = 1, 2, 3 and 5: each matches pathcl's image at the
    same B to 0.2 % in image mean, while pathcl's images one bounce apart differ by 7 %
    (Cornell box, B = 2 and 3) to 60 % (lamps, B = 1 and 2).
  * Camera: Blender's looks down local -Z with +Y up, as glTF's, so the object takes
    the node's world matrix (scale removed); vertical field of view yfov, the image's
    own aspect ratio (as Mitsuba's fov_axis y).
  * Film: box filter 1 px wide (each pixel the plain mean of its samples), opaque,
    black world, float32 linear EXR (EXR is written in scene linear: no view transform;
    Standard, no look, exposure 0 and gamma 1 are set anyway).
  * No clamping, denoising or adaptive sampling; caustics on and filter glossy 0 (no
    effect on Lambertian scenes, set for likeness with pathcl's unbiased paths). Left at
    Blender's defaults, as a user gets them: the sampling pattern (Automatic: tabulated
    Sobol), multiple importance sampling of lights, the light threshold 0.01 (shadow
    rays whose contribution bound is below it are Russian-rouletted with reweighting:
    unbiased) and Russian roulette of paths.

Timing: persistent data is on, so the warm-up render (--warm-up, seed 0, not written)
builds the BVH, syncs the scene and loads the kernels; each timed figure is then the
wall time of bpy.ops.render.render for one seed: Blender's scene update (the seed
change only), Cycles' reset of its renderer and its sample loop, and writing the pixels into
Blender's render result. Writing the EXR comes after the timed call.
"""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mitsuba_reference as mr  # noqa: E402

import numpy as np  # noqa: E402

import bpy  # noqa: E402
from mathutils import Matrix  # noqa: E402


def make_material(prim, index):
    """A node material: Diffuse BSDF (base colour) + front-face Emission, black behind
    unless doubleSided."""
    if prim["kind"] != "diffuse" or prim.get("texture") is not None:
        raise ValueError(f"{prim['name']}: only untextured Lambertian materials are supported")
    mat = bpy.data.materials.new(f"m{index}")
    mat.use_nodes = True
    nt = mat.node_tree
    nt.nodes.clear()
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    out.target = "CYCLES"
    diffuse = nt.nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (*prim["base"], 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0
    shader = diffuse.outputs["BSDF"]
    emitting = any(c > 0 for c in prim["emission"])
    if emitting:
        emission = nt.nodes.new("ShaderNodeEmission")
        emission.inputs["Color"].default_value = (*prim["emission"], 1.0)
        emission.inputs["Strength"].default_value = 1.0
        add = nt.nodes.new("ShaderNodeAddShader")
        nt.links.new(diffuse.outputs["BSDF"], add.inputs[0])
        nt.links.new(emission.outputs["Emission"], add.inputs[1])
        shader = add.outputs["Shader"]
    if emitting or not prim["two_sided"]:
        # Mix fac = Backfacing: shader on the front, no closure (black) on the back. A
        # double-sided emitter would need both; make_many_lights and the boxes have none.
        if prim["two_sided"]:
            raise ValueError(f"{prim['name']}: double-sided emitters are not supported")
        geometry = nt.nodes.new("ShaderNodeNewGeometry")
        mix = nt.nodes.new("ShaderNodeMixShader")
        nt.links.new(geometry.outputs["Backfacing"], mix.inputs["Fac"])
        nt.links.new(shader, mix.inputs[1])
        shader = mix.outputs["Shader"]
    nt.links.new(shader, out.inputs["Surface"])
    mat.cycles.emission_sampling = "FRONT" if emitting else "NONE"
    return mat


def make_mesh(prim, index):
    """A flat-shaded mesh object of the primitive's world-space triangles."""
    pos, faces = prim["positions"], prim["faces"]
    mesh = bpy.data.meshes.new(f"mesh{index}")
    mesh.vertices.add(len(pos))
    mesh.vertices.foreach_set("co", pos.astype(np.float32).ravel())
    mesh.loops.add(faces.size)
    mesh.loops.foreach_set("vertex_index", faces.astype(np.int32).ravel())
    mesh.polygons.add(len(faces))
    mesh.polygons.foreach_set("loop_start", np.arange(0, faces.size, 3, dtype=np.int32))
    mesh.update(calc_edges=True)
    mesh.materials.append(make_material(prim, index))
    obj = bpy.data.objects.new(f"obj{index}", mesh)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def make_camera(camera, size):
    world = np.array(camera["world"], np.float64)
    rot = world[:3, :3] / np.linalg.norm(world[:3, :3], axis=0)  # columns: drop the scale
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = rot, world[:3, 3]
    data = bpy.data.cameras.new("camera")
    data.type = "PERSP"
    data.sensor_fit = "VERTICAL"
    data.angle_y = float(camera["yfov"])
    data.clip_start = float(camera.get("znear", 0.01))
    data.clip_end = float(camera.get("zfar", 1e4))
    obj = bpy.data.objects.new("camera", data)
    obj.matrix_world = Matrix(m.tolist())  # rows (a plain nested list would be read as columns)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def setup(path, size, spp, bounces, light_tree):
    prims, camera, lights = mr.load_scene(path)
    if lights:
        raise ValueError("punctual lights are not supported here")
    if bounces < 1:
        raise ValueError("--max-bounces must be >= 1 (Cycles' max_bounces 0 is one scattering event)")
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    for i, prim in enumerate(prims):
        make_mesh(prim, i)
    scene.camera = make_camera(camera, size)
    world = bpy.data.worlds.new("black")
    world.use_nodes = False
    world.color = (0.0, 0.0, 0.0)
    scene.world = world

    r = scene.render
    r.engine = "CYCLES"
    r.resolution_x = r.resolution_y = size
    r.resolution_percentage = 100
    r.pixel_aspect_x = r.pixel_aspect_y = 1.0
    r.film_transparent = False
    r.use_persistent_data = True
    r.threads_mode = "AUTO"  # all cores
    r.use_motion_blur = False
    r.use_simplify = False
    r.use_compositing = False
    r.use_sequencer = False
    r.dither_intensity = 0.0
    r.image_settings.file_format = "OPEN_EXR"
    r.image_settings.color_depth = "32"
    r.image_settings.color_mode = "RGBA"
    r.image_settings.exr_codec = "ZIP"
    vs = scene.view_settings
    vs.view_transform, vs.look, vs.exposure, vs.gamma = "Standard", "None", 0.0, 1.0

    c = scene.cycles
    c.device = "CPU"
    c.samples = spp
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.use_light_tree = light_tree
    c.sample_clamp_direct = c.sample_clamp_indirect = 0.0
    c.caustics_reflective = c.caustics_refractive = True
    c.blur_glossy = 0.0
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = bounces - 1
    c.transmission_bounces = c.volume_bounces = bounces - 1
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    c.film_exposure = 1.0
    c.use_animated_seed = False
    return scene


def render(scene, seed):
    """Seconds of one render with this seed. Setting scene.cycles.seed alone does not
    reach the depsgraph's copy of the scene, so every seed would render like the first;
    a TIME tag makes the render see it without re-syncing geometry (a plain update_tag
    rebuilds the BVH)."""
    scene.cycles.seed = seed
    scene.update_tag(refresh={"TIME"})
    t0 = time.perf_counter()
    bpy.ops.render.render()
    return time.perf_counter() - t0


def main():
    ap = argparse.ArgumentParser(description="Cycles (CPU) renders of a glTF scene")
    ap.add_argument("scene")
    ap.add_argument("--out", required=True, help="output prefix: PREFIX-SEED.exr")
    ap.add_argument("--size", type=int, required=True)
    ap.add_argument("--spp", type=int, required=True)
    ap.add_argument("--max-bounces", type=int, required=True, help="scattering events (>= 1)")
    ap.add_argument("--seeds", default="1", help="comma-separated seeds, one render each")
    ap.add_argument("--warm-up", action="store_true", help="an untimed seed-0 render first")
    ap.add_argument("--no-light-tree", action="store_true")
    args = ap.parse_args()
    try:
        scene = setup(args.scene, args.size, args.spp, args.max_bounces, not args.no_light_tree)
    except ValueError as e:  # a scene this does not translate: exit status 3
        print(f"cycles_render.py: {e}", file=sys.stderr)
        sys.exit(3)
    print(f"Blender {bpy.app.version_string}, Cycles CPU, light tree "
          f"{'on' if scene.cycles.use_light_tree else 'off'}", flush=True)
    if args.warm_up:
        render(scene, 0)
    for seed in (int(s) for s in args.seeds.split(",")):
        t = render(scene, seed)
        path = os.path.abspath(f"{args.out}-{seed}.exr")
        bpy.data.images["Render Result"].save_render(path)
        print(f"seed {seed} render {t:.6f} s {path}", flush=True)


if __name__ == "__main__":
    main()
