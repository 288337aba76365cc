#!/usr/bin/env python3
"""pathcl against Mitsuba 3 and Blender's Cycles at equal error: render time, RMSE and
relMSE against a converged reference, and efficiency 1 / (error x time), for each renderer
and sampler, in one run on one machine. Run it through tools/compare_mitsuba.sh, which
makes the venv (Mitsuba 3 and Dr.Jit from PyPI) and finds Debian's libLLVM 19 for Dr.Jit's
LLVM backend, and, for Cycles, the bpy venv (tools/cycles_venv.sh).

    compare_mitsuba.py --pathcl BUILD/pathcl --out DIR SCENE.gltf [SCENE.gltf ...]
        [--size 256] [--spp 256] [--max-bounces 7] [--runs 3] [--reference-spp 16384]
        [--mitsuba-samplers independent,stratified,multijitter,ldsampler,orthogonal]
        [--cycles BPY_VENV/bin/python]

Per scene:
  * a flat-shaded copy (tools/strip_normals.py): tools/mitsuba_reference.py reads no
    vertex normals, so both renderers see the same facets;
  * the reference: pathcl, sobol sampler, --reference-spp, seed 1000, cached in DIR
    (its error is about a quarter of a 64 x lower spp render's; an independent reference
    of the same spp would add a quarter of Sobol's 256-spp MSE to Sobol's measured error);
  * pathcl with the sobol and the independent sampler and Mitsuba's llvm_ad_rgb with each
    sampler: one warm-up render (kernel compilation), then --runs renders with seeds
    1..runs, render time only (pathcl's "render" figure; Mitsuba's mi.render to a numpy
    array), errors against the reference;
  * with --cycles: Cycles (CPU) with its light tree and without, through
    tools/cycles_render.py (its docstring says what its seconds include: a warm-up
    render with persistent data, then the render call per seed) run by the given
    python as a subprocess: bpy 4.5 needs numpy < 2 and bundles its own TBB, OpenEXR and
    Embree, so it gets a venv of its own rather than sharing Mitsuba's process.
    Cycles' max_bounces is --max-bounces - 1 (see there), so --max-bounces must be >= 1;
    a scene it does not translate (anything but Lambertian surfaces and emitters) gets
    no Cycles rows.
--mitsuba-samplers '' leaves Mitsuba out (then Mitsuba need not be installed: any python
with numpy and OpenEXR runs this, the bpy venv's too).
Errors: RMSE over all pixels and channels; relMSE = mean((x - r)^2 / (r^2 + 0.01)).
Efficiency: 1 / (RMSE^2 t) and 1 / (relMSE t), t the median render seconds; the last
columns divide each by the best Mitsuba sampler's and by Cycles' with its light tree, on
each metric (> 1: that row better).
"""
import argparse
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mitsuba_reference as mr  # noqa: E402

import numpy as np  # noqa: E402

TOOLS = os.path.dirname(os.path.abspath(__file__))


def read_rgb(path):
    import OpenEXR
    with OpenEXR.File(path, separate_channels=True) as f:
        ch = f.channels()
        return np.stack([np.asarray(ch[c].pixels, np.float64) for c in "RGB"], -1)


def errors(img, ref):
    d2 = (img - ref) ** 2
    return float(np.sqrt(np.mean(d2))), float(np.mean(d2 / (ref * ref + 0.01)))


def pathcl_render(binary, scene, out, size, spp, bounces, sampler, seed, cache, wrapper=()):
    """pathcl's render seconds; wrapper: a command that runs it (tools/profile_split.py's perf)."""
    cmd = list(wrapper) + [binary, "render", scene, "-o", out, "--width", str(size), "--height", str(size),
                           "--spp", str(spp), "--max-bounces", str(bounces), "--sampler", sampler, "--seed", str(seed)]
    env = dict(os.environ, PATHCL_CACHE_DIR=cache)
    text = subprocess.run(cmd, check=True, capture_output=True, text=True, env=env).stdout
    m = re.search(r"render ([0-9.]+) s", text)
    if not m:
        sys.exit(f"compare_mitsuba.py: no render time in: {text}")
    return float(m.group(1))


def flat_copy(scene_path, out):
    """The scene's flat-shaded copy in out (made once): both renderers see the same facets."""
    name = os.path.splitext(os.path.basename(scene_path))[0]
    flat = os.path.join(out, name + "-flat.gltf")
    if not os.path.exists(flat):
        subprocess.run([sys.executable, os.path.join(TOOLS, "strip_normals.py"), scene_path, flat], check=True)
    return flat


def mitsuba_runs(mi, loaded, size, spp, bounces, sampler, runs):
    """Mitsuba's llvm_ad_rgb renders of a scene (mitsuba_reference.load_scene's triple) with
    seeds 1..runs after a warm-up render (Dr.Jit compiles its kernels): the samples per pixel
    it takes (orthogonal rounds up to the square of a prime) and (seconds, RGB) per run."""
    prims, camera, lights = loaded
    scene = mr.build_scene(mi, prims, camera, size, size, spp, bounces, lights, sampler)
    spp = int(scene.sensors()[0].sampler().sample_count())
    np.array(mi.render(scene, spp=spp, seed=0))
    out = []
    for seed in range(1, runs + 1):
        t0 = time.time()
        img = np.array(mi.render(scene, spp=spp, seed=seed), np.float64)[..., :3]
        out.append((time.time() - t0, img))
    return spp, out


def cycles_runs(python, flat, out, size, spp, bounces, runs, light_tree):
    """Cycles' renders (tools/cycles_render.py under the bpy venv's python) with seeds
    1..runs after its warm-up: Blender's version line and (seconds, RGB) per run."""
    prefix = os.path.join(out, "cycles-run" + ("" if light_tree else "-no-tree"))
    cmd = [python, os.path.join(TOOLS, "cycles_render.py"), flat, "--out", prefix, "--size", str(size),
           "--spp", str(spp), "--max-bounces", str(bounces), "--warm-up",
           "--seeds", ",".join(str(s) for s in range(1, runs + 1))] + ([] if light_tree else ["--no-light-tree"])
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode == 3:  # a scene it does not translate (not Lambertian): no rows
        print(f"  cycles: skipped: {proc.stderr.strip()}", flush=True)
        return None, []
    if proc.returncode != 0:
        sys.exit(f"compare_mitsuba.py: cycles_render.py failed:\n{proc.stdout[-3000:]}{proc.stderr[-3000:]}")
    version = next(line for line in proc.stdout.splitlines() if line.startswith("Blender "))
    found = re.findall(r"^seed \d+ render ([0-9.]+) s (.+\.exr)$", proc.stdout, re.M)
    if len(found) != runs:
        sys.exit(f"compare_mitsuba.py: cycles_render.py gave {len(found)} renders, not {runs}")
    return version, [(float(t), read_rgb(path)) for t, path in found]


def summarize(rows, label, secs, errs, spp, pixels):
    secs = sorted(secs)
    t = secs[len(secs) // 2]
    rmse = float(np.mean([e[0] for e in errs]))
    rel = float(np.mean([e[1] for e in errs]))
    rows.append({"label": label, "t": t, "tmin": secs[0], "tmax": secs[-1], "msps": pixels * spp / t / 1e6,
                 "rmse": rmse, "rel": rel, "eff_rmse": 1.0 / (rmse * rmse * t), "eff_rel": 1.0 / (rel * t)})
    r = rows[-1]
    print(f"  {label:32s} render s {r['tmin']:.3f} / {r['t']:.3f} / {r['tmax']:.3f}  RMSE {rmse:.5f}  "
          f"relMSE {rel:.6f}", flush=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("scenes", nargs="+")
    ap.add_argument("--pathcl", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--spp", type=int, default=256)
    ap.add_argument("--max-bounces", type=int, default=7)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--reference-spp", type=int, default=16384)
    ap.add_argument("--mitsuba-samplers", default="independent,stratified,multijitter,ldsampler,orthogonal",
                    help="comma-separated; '' for no Mitsuba rows")
    ap.add_argument("--cycles", metavar="PYTHON", help="the bpy venv's python: adds Cycles rows")
    args = ap.parse_args()
    samplers = [s for s in args.mitsuba_samplers.split(",") if s]
    if args.cycles and args.max_bounces < 1:
        ap.error("Cycles needs --max-bounces >= 1 (its max_bounces 0 is one scattering event)")
    os.makedirs(args.out, exist_ok=True)
    cache = os.path.join(args.out, "kernel-cache")
    mi = None
    if samplers:
        import mitsuba as mi
        import drjit as dr
        mr.pick_variant(mi, "llvm_ad_rgb")
        print(f"Mitsuba {mi.__version__}, Dr.Jit {dr.__version__}; ", end="")
    print(f"pathcl {args.pathcl}; {args.size}x{args.size}, {args.spp} spp, {args.max_bounces} bounces, "
          f"{args.runs} runs; reference {args.reference_spp} spp sobol")
    pixels = args.size * args.size
    tables = []
    for scene_path in args.scenes:
        name = os.path.splitext(os.path.basename(scene_path))[0]
        flat = flat_copy(scene_path, args.out)
        ref_path = os.path.join(args.out, f"{name}-ref-{args.size}-{args.max_bounces}-{args.reference_spp}.exr")
        if not os.path.exists(ref_path):
            print(f"{name}: rendering the reference ({args.reference_spp} spp)", flush=True)
            pathcl_render(args.pathcl, flat, ref_path, args.size, args.reference_spp, args.max_bounces, "sobol",
                          1000, cache)
        ref = read_rgb(ref_path)
        print(f"{name}:", flush=True)
        rows = []
        run_exr = os.path.join(args.out, "run.exr")
        for sampler in ("sobol", "independent"):
            pathcl_render(args.pathcl, flat, run_exr, args.size, args.spp, args.max_bounces, sampler, 0, cache)
            secs, errs = [], []
            for seed in range(1, args.runs + 1):
                secs.append(pathcl_render(args.pathcl, flat, run_exr, args.size, args.spp, args.max_bounces,
                                          sampler, seed, cache))
                errs.append(errors(read_rgb(run_exr), ref))
            summarize(rows, f"pathcl {sampler}", secs, errs, args.spp, pixels)
        loaded = mr.load_scene(flat) if samplers else None
        for sampler in samplers:
            spp, runs = mitsuba_runs(mi, loaded, args.size, args.spp, args.max_bounces, sampler, args.runs)
            secs = [t for t, _ in runs]
            errs = [errors(img, ref) for _, img in runs]
            summarize(rows, f"mitsuba llvm {sampler}" + (f" ({spp} spp)" if spp != args.spp else ""), secs, errs,
                      spp, pixels)
        for light_tree in (True, False) if args.cycles else ():
            version, runs = cycles_runs(args.cycles, flat, args.out, args.size, args.spp, args.max_bounces,
                                        args.runs, light_tree)
            if not runs:
                break
            if light_tree:
                print(f"  ({version})", flush=True)
            summarize(rows, "cycles cpu " + ("light tree" if light_tree else "no light tree"),
                      [t for t, _ in runs], [errors(img, ref) for _, img in runs], args.spp, pixels)
        tables.append((name, rows))

    print()
    for name, rows in tables:
        # Ratio columns: against the best Mitsuba sampler, and against Cycles' light tree.
        bases = []
        mits = [r for r in rows if r["label"].startswith("mitsuba")]
        if mits:
            bases.append(("vs best Mitsuba", max(r["eff_rmse"] for r in mits), max(r["eff_rel"] for r in mits)))
        tree = [r for r in rows if r["label"] == "cycles cpu light tree"]
        if tree:
            bases.append(("vs Cycles light tree", tree[0]["eff_rmse"], tree[0]["eff_rel"]))
        print(f"{name} ({args.size}x{args.size}, {args.spp} spp, {args.max_bounces} bounces; median of {args.runs})")
        print("| renderer, sampler | render s | Msamples/s | RMSE | relMSE | eff. (RMSE²) | eff. (relMSE) |" +
              "".join(f" {b[0]} (RMSE² / relMSE) |" for b in bases))
        print("|---|---|---|---|---|---|---|" + "---|" * len(bases))
        for r in rows:
            print(f"| {r['label']} | {r['t']:.3f} | {r['msps']:.2f} | {r['rmse']:.5f} | {r['rel']:.6f} | "
                  f"{r['eff_rmse']:.0f} | {r['eff_rel']:.1f} |" +
                  "".join(f" {r['eff_rmse'] / b[1]:.2f} / {r['eff_rel'] / b[2]:.2f} |" for b in bases))
        print()

if __name__ == "__main__":
    main()
