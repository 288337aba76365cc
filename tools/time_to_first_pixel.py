#!/usr/bin/env python3
"""Time to first pixel with empty caches (docs/performance.md): runs `pathcl render SCENE
--width 64 --height 64 --spp 1` with a fresh, empty PATHCL_CACHE_DIR and POCL_CACHE_DIR,
and prints when the image appeared on disk and when the process ended, in seconds from
its start. --warm renders once first, so that both caches hold the program;
--no-pocl-cache sets POCL_KERNEL_CACHE=0 as well.

    python3 tools/time_to_first_pixel.py [--runs N] [--warm] [--no-pocl-cache] PATHCL SCENE...
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time


def one_run(pathcl, scene, warm, no_pocl_cache):
    work = tempfile.mkdtemp(prefix="pathcl-ttfp-")
    try:
        env = dict(os.environ, PATHCL_CACHE_DIR=os.path.join(work, "pathcl-cache"),
                   POCL_CACHE_DIR=os.path.join(work, "pocl-cache"))
        if no_pocl_cache:
            env["POCL_KERNEL_CACHE"] = "0"
        image = os.path.join(work, "first.png")
        cmd = [pathcl, "render", scene, "--width", "64", "--height", "64", "--spp", "1", "--quiet", "-o", image]
        if warm:
            subprocess.run(cmd, env=env, check=True, capture_output=True)
            os.remove(image)
        # stderr to a file, not a pipe: nobody reads a pipe while polling, and a full one
        # would stall pathcl.
        with open(os.path.join(work, "stderr.txt"), "w+b") as err:
            start = time.monotonic()
            proc = subprocess.Popen(cmd, env=env, stdout=subprocess.DEVNULL, stderr=err)
            seen = None
            while proc.poll() is None:
                if seen is None and os.path.exists(image):
                    seen = time.monotonic() - start
                time.sleep(0.002)
            ended = time.monotonic() - start
            if proc.returncode != 0:
                err.seek(0)
                sys.exit(f"time_to_first_pixel.py: {scene}: pathcl exited {proc.returncode}: "
                         f"{err.read().decode(errors='replace').strip()}")
        return (seen if seen is not None else ended), ended
    finally:
        shutil.rmtree(work, ignore_errors=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("pathcl")
    ap.add_argument("scenes", nargs="+")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--warm", action="store_true")
    ap.add_argument("--no-pocl-cache", action="store_true")
    a = ap.parse_args()
    for scene in a.scenes:
        runs = [one_run(a.pathcl, scene, a.warm, a.no_pocl_cache) for _ in range(a.runs)]
        image = sorted(r[0] for r in runs)
        ended = sorted(r[1] for r in runs)
        print(f"{os.path.basename(scene)}: image on disk {image[0]:.2f}-{image[-1]:.2f} s, "
              f"process ended {ended[0]:.2f}-{ended[-1]:.2f} s ({a.runs} runs, "
              f"{'warm' if a.warm else 'empty'} caches)")


if __name__ == "__main__":
    main()
