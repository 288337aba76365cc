#!/usr/bin/env python3
"""Error against a converged reference versus render time for Mitsuba 3, the counterpart
of tools/measure_samplers.sh for pathcl, so that the two renderers can be compared at
equal error (the mission's speed bar is Mitsuba's LLVM backend):

    DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM-19.so \\
    /tmp/mivenv/bin/python tools/mitsuba_efficiency.py scenes/cornell-box.gltf \\
        docs/measurements/cornell-box-64-16384spp.exr --spp 64 --runs 9 \\
        --variant llvm_ad_rgb --sampler multijitter

Renders the scene once to warm up (Dr.Jit compiles its kernels), then RUNS times with
seeds 1..RUNS at the reference's size; prints per run the render seconds and the RMSE
over all channels, then the mean RMSE and min / median / max seconds. The scene is read
by tools/mitsuba_reference.py (same conventions, same restrictions). Mitsuba's LLVM
backend needs LLVM's shared library (Debian's libllvm19; 14 and 15 crash Dr.Jit).
"""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mitsuba_reference as mr  # noqa: E402

import numpy as np  # noqa: E402  (mitsuba_reference exits with a hint if it is missing)


def read_rgb(path):
    """R, G, B of an EXR as an (h, w, 3) array, through the OpenEXR pip package (3.x)."""
    import OpenEXR
    with OpenEXR.File(path, separate_channels=True) as f:
        ch = f.channels()
        return np.stack([np.asarray(ch[c].pixels, np.float64) for c in "RGB"], -1)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("scene")
    ap.add_argument("reference", help="EXR written by pathcl (R, G, B used)")
    ap.add_argument("--spp", type=int, required=True)
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--max-bounces", type=int, default=8)
    ap.add_argument("--variant", default="llvm_ad_rgb")
    ap.add_argument("--sampler", default="independent",
                    help="Mitsuba sampler plugin: independent, stratified, multijitter, ldsampler, ...")
    args = ap.parse_args()
    import mitsuba as mi
    ref = read_rgb(args.reference)
    h, w = ref.shape[:2]
    mr.pick_variant(mi, args.variant)
    prims, camera, lights = mr.load_scene(args.scene)
    scene = mr.build_scene(mi, prims, camera, w, h, args.spp, args.max_bounces, lights, args.sampler)
    np.array(mi.render(scene, spp=args.spp, seed=0))  # warm-up
    print("sampler,seed,render_s,rmse")
    rmses, secs = [], []
    for seed in range(1, args.runs + 1):
        t0 = time.time()
        img = np.array(mi.render(scene, spp=args.spp, seed=seed), np.float64)[..., :3]
        secs.append(time.time() - t0)
        rmses.append(float(np.sqrt(np.mean((img - ref) ** 2))))
        print(f"{args.sampler},{seed},{secs[-1]:.3f},{rmses[-1]:.6f}", flush=True)
    secs.sort()
    print(f"{args.variant} {args.sampler}: mean RMSE {np.mean(rmses):.6f}, render s min {secs[0]:.3f} "
          f"median {secs[len(secs) // 2]:.3f} max {secs[-1]:.3f}")


if __name__ == "__main__":
    main()
