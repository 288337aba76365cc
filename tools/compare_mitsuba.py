#!/usr/bin/env python3
"""pathcl against Mitsuba 3 at equal error: render time, RMSE and relMSE against a converged
reference, and efficiency 1 / (error x time), for each renderer and sampler, in one run on
one machine. Run it through tools/compare_mitsuba.sh, which makes the venv (Mitsuba 3 and
Dr.Jit from PyPI) and finds Debian's libLLVM 19 for Dr.Jit's LLVM backend.

    compare_mitsuba.py --pathcl BUILD/pathcl --out DIR SCENE.gltf [SCENE.gltf ...]
        [--size 256] [--spp 256] [--max-bounces 7] [--runs 3] [--reference-spp 16384]
        [--mitsuba-samplers independent,stratified,multijitter,ldsampler,orthogonal]

Per scene:
  * a flat-shaded copy (tools/strip_normals.py): tools/mitsuba_reference.py reads no
    vertex normals, so both renderers see the same facets;
  * the reference: pathcl, sobol sampler, --reference-spp, seed 1000, cached in DIR
    (its error is about a quarter of a 64 x lower spp render's; an independent reference
    of the same spp would add a quarter of Sobol's 256-spp MSE to Sobol's measured error);
  * pathcl with the sobol and the independent sampler and Mitsuba's llvm_ad_rgb with each
    sampler: one warm-up render (kernel compilation), then --runs renders with seeds
    1..runs, render time only (pathcl's "render" figure; Mitsuba's mi.render to a numpy
    array), errors against the reference.
Errors: RMSE over all pixels and channels; relMSE = mean((x - r)^2 / (r^2 + 0.01)).
Efficiency: 1 / (RMSE^2 t) and 1 / (relMSE t), t the median render seconds; the last two
columns divide each by the best Mitsuba sampler's on that metric (> 1: pathcl better).
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
    ap.add_argument("--mitsuba-samplers", default="independent,stratified,multijitter,ldsampler,orthogonal")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    cache = os.path.join(args.out, "kernel-cache")
    import mitsuba as mi
    import drjit as dr
    mr.pick_variant(mi, "llvm_ad_rgb")
    print(f"Mitsuba {mi.__version__}, Dr.Jit {dr.__version__}; pathcl {args.pathcl}; {args.size}x{args.size}, "
          f"{args.spp} spp, {args.max_bounces} bounces, {args.runs} runs; reference {args.reference_spp} spp sobol")
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
        prims, camera, lights = mr.load_scene(flat)
        for sampler in args.mitsuba_samplers.split(","):
            spp, runs = mitsuba_runs(mi, (prims, camera, lights), args.size, args.spp, args.max_bounces, sampler,
                                     args.runs)
            secs = [t for t, _ in runs]
            errs = [errors(img, ref) for _, img in runs]
            summarize(rows, f"mitsuba llvm {sampler}" + (f" ({spp} spp)" if spp != args.spp else ""), secs, errs,
                      spp, pixels)
        tables.append((name, rows))

    print()
    for name, rows in tables:
        mits = [r for r in rows if r["label"].startswith("mitsuba")]
        best_rmse = max(r["eff_rmse"] for r in mits)
        best_rel = max(r["eff_rel"] for r in mits)
        print(f"{name} ({args.size}x{args.size}, {args.spp} spp, {args.max_bounces} bounces; median of {args.runs})")
        print("| renderer, sampler | render s | Msamples/s | RMSE | relMSE | eff. (RMSE²) | eff. (relMSE) | "
              "vs best Mitsuba (RMSE² / relMSE) |")
        print("|---|---|---|---|---|---|---|---|")
        for r in rows:
            print(f"| {r['label']} | {r['t']:.3f} | {r['msps']:.2f} | {r['rmse']:.5f} | {r['rel']:.6f} | "
                  f"{r['eff_rmse']:.0f} | {r['eff_rel']:.1f} | {r['eff_rmse'] / best_rmse:.2f} / "
                  f"{r['eff_rel'] / best_rel:.2f} |")
        print()


if __name__ == "__main__":
    main()
