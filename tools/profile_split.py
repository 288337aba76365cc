#!/usr/bin/env python3
"""Where pathcl's and Mitsuba 3's time per sample goes: ray traversal (closest hits and
shadow rays) against everything else (camera, sampler, shading, light sampling, MIS),
from perf profiles of the same renders that tools/compare_mitsuba.py times. Run it
through tools/profile_split.sh, which builds the pathcl it needs and makes the venv.

    profile_split.py --pathcl PROFILING_BUILD/pathcl --out DIR SCENE.gltf [SCENE.gltf ...]
        [--size 256] [--spp 256] [--max-bounces 7] [--runs 2] [--mitsuba-sampler multijitter]

Per scene (the flat-shaded copy compare_mitsuba.py renders, made in DIR):
  * pathcl (its default Sobol' sampler), built with bvh_closest_hit and bvh_visibility out
    of line so that perf names them: one warm-up render (kernel cache), then one render
    under `perf record`; its render seconds are pathcl's own figure.
  * Mitsuba's llvm_ad_rgb with --mitsuba-sampler (compare_mitsuba.py's best on the
    committed scenes): a warm-up render and --runs timed renders, the whole process under
    `perf record`; its seconds are the median timed render.
perf samples every thread (cpu-clock). A renderer's render samples are pathcl's kernel
code (the work-group functions PoCL builds, in files named KERNEL.so) or Mitsuba's Dr.Jit
code ("[JIT]") and Embree's traversal (its `intersect` and `occluded`); what runs outside
(loading, BVH builds, compilers) is left out. Each class's share of the render samples
times the render seconds, over the samples taken, is its time per sample in
nanoseconds, summed over the cores (so both renderers' figures add up to their own
render seconds per sample, and compare directly).
"""
import argparse
import os
import re
import statistics
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_mitsuba as cm  # noqa: E402
import mitsuba_reference as mr  # noqa: E402

CLASSES = ("closest", "shadow", "rest")


def perf_wrapper(data):
    """The command prefix that profiles a command into data (cpu-clock, every thread)."""
    return ["perf", "record", "-q", "-e", "cpu-clock", "-o", data, "--"]


def perf_record(data, cmd):
    """Runs cmd under perf_wrapper(data); cmd's stdout."""
    proc = subprocess.run(perf_wrapper(data) + cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"profile_split.py: perf record failed ({proc.returncode}): {proc.stderr.strip()[-500:]}")
    return proc.stdout


def perf_rows(data):
    """(percent, dso, symbol) for every line of perf report on data."""
    out = subprocess.run(["perf", "report", "-i", data, "--no-children", "--sort", "dso,sym", "--stdio", "-q",
                          "-t", "|"], check=True, capture_output=True, text=True).stdout
    rows = []
    for line in out.splitlines():
        parts = [p.strip() for p in line.split("|", 2)]
        if len(parts) == 3 and parts[0].endswith("%"):
            rows.append((float(parts[0][:-1]), parts[1], re.sub(r"^\[\.\]\s*", "", parts[2])))
    return rows


def pathcl_class(dso, sym):
    """closest, shadow or rest for pathcl's kernel code; None outside it."""
    if not re.fullmatch(r"[a-z0-9_]+\.so", dso) or dso.startswith("lib"):
        return None  # the host, libraries, PoCL and LLVM (the kernels are KERNEL.so)
    if sym == "bvh_closest_hit":
        return "closest"
    if sym == "bvh_visibility":
        return "shadow"
    return "rest"


def mitsuba_class(dso, sym):
    """closest, shadow or rest for Mitsuba's render code; None outside it."""
    if dso.startswith("[JIT]"):
        return "rest"
    if dso.startswith("libembree"):
        # A hybrid intersector traces a packet in intersect, or where few of its rays
        # are active one ray at a time in intersect1 (most of the closest hits on every
        # scene profiled), and coherent packets in intersectCoherent; occluded likewise.
        name = sym.rsplit("::", 1)[-1]
        if name in ("intersect", "intersect1", "intersectCoherent") or name.startswith("rtcIntersect"):
            return "closest"
        if name in ("occluded", "occluded1", "occludedCoherent") or name.startswith("rtcOccluded"):
            return "shadow"
    return None  # Embree's BVH build, Python, Dr.Jit's compiler, the kernel


def split(rows, classify):
    """Each class's share of the render samples, and the render samples' share of all."""
    total = {c: 0.0 for c in CLASSES}
    for pct, dso, sym in rows:
        c = classify(dso, sym)
        if c:
            total[c] += pct
    render = sum(total.values())
    if render <= 0.0:
        sys.exit("profile_split.py: no samples in the render code (is the profile empty?)")
    return {c: total[c] / render for c in CLASSES}, render / 100.0


def mitsuba_child(args):
    """The process that perf records for Mitsuba: warm-up and timed renders of one scene."""
    import mitsuba as mi
    mr.pick_variant(mi, "llvm_ad_rgb")
    spp, runs = cm.mitsuba_runs(mi, mr.load_scene(args.scenes[0]), args.size, args.spp, args.max_bounces,
                                args.mitsuba_sampler, args.runs)
    print(f"spp {spp} seconds {statistics.median(t for t, _ in runs):.4f}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("scenes", nargs="+")
    ap.add_argument("--pathcl")
    ap.add_argument("--out")
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--spp", type=int, default=256)
    ap.add_argument("--max-bounces", type=int, default=7)
    ap.add_argument("--runs", type=int, default=2)
    ap.add_argument("--mitsuba-sampler", default="multijitter")
    ap.add_argument("--mitsuba-child", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.mitsuba_child:
        return mitsuba_child(args)
    if not args.pathcl or not args.out:
        sys.exit("profile_split.py: --pathcl and --out are required")
    os.makedirs(args.out, exist_ok=True)
    cache = os.path.join(args.out, "kernel-cache")
    run_exr = os.path.join(args.out, "run.exr")
    print(f"{args.size}x{args.size}, {args.spp} spp, {args.max_bounces} bounces; pathcl sobol, "
          f"Mitsuba llvm_ad_rgb {args.mitsuba_sampler} (median of {args.runs})", flush=True)
    table = []
    for scene_path in args.scenes:
        name = os.path.splitext(os.path.basename(scene_path))[0]
        flat = cm.flat_copy(scene_path, args.out)
        cm.pathcl_render(args.pathcl, flat, run_exr, args.size, args.spp, args.max_bounces, "sobol", 0, cache)
        data = os.path.join(args.out, f"{name}-pathcl.perf")
        secs = cm.pathcl_render(args.pathcl, flat, run_exr, args.size, args.spp, args.max_bounces, "sobol", 1,
                                cache, wrapper=perf_wrapper(data))
        shares, covered = split(perf_rows(data), pathcl_class)
        table.append((name, "pathcl sobol", secs, args.spp, shares, covered))

        data = os.path.join(args.out, f"{name}-mitsuba.perf")
        text = perf_record(data, [sys.executable, os.path.abspath(__file__), "--mitsuba-child", flat,
                                  "--size", str(args.size), "--spp", str(args.spp), "--max-bounces",
                                  str(args.max_bounces), "--runs", str(args.runs), "--mitsuba-sampler",
                                  args.mitsuba_sampler])
        m = re.search(r"spp (\d+) seconds ([0-9.]+)", text)
        if not m:
            sys.exit(f"profile_split.py: no render time from the Mitsuba run: {text}")
        shares, covered = split(perf_rows(data), mitsuba_class)
        table.append((name, f"mitsuba llvm {args.mitsuba_sampler}", float(m.group(2)), int(m.group(1)), shares,
                      covered))
        print(f"  {name}: done", flush=True)

    print()
    print("| scene | renderer | render s | closest hits ns/sample | shadow rays ns/sample | everything else "
          "ns/sample | traversal share | render samples of all |")
    print("|---|---|---|---|---|---|---|---|")
    per_scene = {}
    for name, label, secs, spp, shares, covered in table:
        ns = {c: shares[c] * secs / (args.size * args.size * spp) * 1e9 for c in CLASSES}
        per_scene.setdefault(name, []).append(ns)
        print(f"| {name} | {label} | {secs:.3f} | {ns['closest']:.1f} | {ns['shadow']:.1f} | {ns['rest']:.1f} | "
              f"{shares['closest'] + shares['shadow']:.2f} | {covered:.2f} |")
    print()
    print("pathcl's time per sample over Mitsuba's (> 1: pathcl slower):")
    for name, (p, m) in per_scene.items():
        trav = (p["closest"] + p["shadow"]) / (m["closest"] + m["shadow"])
        print(f"  {name}: traversal {trav:.2f}x, everything else {p['rest'] / m['rest']:.2f}x, "
              f"all {sum(p.values()) / sum(m.values()):.2f}x")


if __name__ == "__main__":
    main()
