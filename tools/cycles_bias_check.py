#!/usr/bin/env python3
"""Does Cycles converge to pathcl's image? Compares a pathcl render (with its variance
channels: render it with --sampler independent, whose per-sample variance is the honest
noise of the mean) against K Cycles renders with different seeds (tools/cycles_render.py
--seeds 1,...,K), whose spread gives Cycles' noise.

    cycles_bias_check.py PATHCL.exr CYCLES-1.exr CYCLES-2.exr ... [--block 16]

For example, on a flat-shaded copy (tools/strip_normals.py) of a scene:

    pathcl render flat.gltf -o p.exr --width 128 --height 128 --spp 4096 --max-bounces 5 \
        --sampler independent --seed 7
    $CYCLES_PY tools/cycles_render.py flat.gltf --out c --size 128 --spp 512 \
        --max-bounces 5 --seeds 1,2,3,4,5,6,7,8
    $CYCLES_PY tools/cycles_bias_check.py p.exr c-1.exr c-2.exr ... c-8.exr

Prints, per channel, the image mean ratio Cycles / pathcl with its standard error, and
over blocks of --block x --block pixels the largest |z| of the block mean difference
(z = difference / sqrt(both noise variances)) with the block's ratio. A systematic
mismatch (units, sides, bounces, camera, filter, colour management) shows as a ratio
off 1 by many standard errors, or as blocks with |z| far beyond ~3.5 (the largest of a
few hundred standard normals).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np  # noqa: E402


def read(path):
    """RGB (H, W, 3), the per-sample variance (or None) and spp of an EXR."""
    import OpenEXR
    with OpenEXR.File(path, separate_channels=True) as f:
        ch = f.channels()
        rgb = np.stack([np.asarray(ch[c].pixels, np.float64) for c in "RGB"], -1)
        var = None
        if "variance.R" in ch:
            var = np.stack([np.asarray(ch[f"variance.{c}"].pixels, np.float64) for c in "RGB"], -1)
        return rgb, var, f.header().get("pathcl:spp")


def blocks(a, n):
    h, w = a.shape[:2]
    return a[: h // n * n, : w // n * n].reshape(h // n, n, w // n, n, -1).mean((1, 3))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("pathcl")
    ap.add_argument("cycles", nargs="+")
    ap.add_argument("--block", type=int, default=16)
    args = ap.parse_args()
    if len(args.cycles) < 2:
        ap.error("give at least two Cycles renders (their spread is Cycles' noise)")
    p, pvar, spp = read(args.pathcl)
    if pvar is None or not spp:
        sys.exit("cycles_bias_check.py: the pathcl render has no variance channels or pathcl:spp")
    runs = np.stack([read(c)[0] for c in args.cycles])
    k = len(runs)
    c = runs.mean(0)
    # Noise variance of a mean over pixels: pathcl's per-sample variance / spp summed over
    # the pixels; Cycles' from the spread of the K run means of that same pixel set.
    n = args.block
    h, w = p.shape[:2]
    npx = n * n
    pv_img = (pvar / spp).reshape(-1, 3).sum(0) / (h * w) ** 2
    cr_img = runs.reshape(k, -1, 3).mean(1)
    cv_img = cr_img.var(0, ddof=1) / k
    pm, cm = p.reshape(-1, 3).mean(0), c.reshape(-1, 3).mean(0)
    print(f"pathcl {spp} spp; Cycles {k} runs; {w}x{h}")
    for i, ch in enumerate("RGB"):
        se = np.sqrt(pv_img[i] + cv_img[i])
        print(f"  {ch}: mean pathcl {pm[i]:.6g} Cycles {cm[i]:.6g}  ratio {cm[i] / pm[i]:.5f} "
              f"+- {se / pm[i]:.5f}  z {(cm[i] - pm[i]) / se:+.2f}")
    pb = blocks(p, n)
    pv_b = blocks(pvar / spp, n) / npx
    rb = np.stack([blocks(r, n) for r in runs])
    cb = rb.mean(0)
    cv_b = rb.var(0, ddof=1) / k
    # Blocks without noise in either (all pixels on a directly seen emitter) have no z:
    # their ratio is reported instead.
    noisy = pv_b + cv_b > 0
    z = np.where(noisy, (cb - pb) / np.sqrt(np.where(noisy, pv_b + cv_b, 1.0)), 0.0)
    j = np.unravel_index(np.argmax(np.abs(z)), z.shape)
    print(f"  {n}x{n} blocks: {z[..., 0].size} x 3 channels, largest |z| {abs(z[j]):.2f} at block "
          f"row {j[0]} col {j[1]} {'RGB'[j[2]]} (ratio {cb[j] / pb[j]:.4f}); "
          f"|z| > 3: {int((np.abs(z) > 3).sum())}, RMS z {np.sqrt(np.mean(z[noisy] ** 2)):.2f}")
    if not noisy.all():
        flat = np.abs(cb[~noisy] / pb[~noisy] - 1.0)
        print(f"  {int((~noisy).sum())} noiseless block channels: largest |ratio - 1| {flat.max():.2e}")
    ratio = cb / pb
    print(f"  block ratios: min {ratio.min():.4f} max {ratio.max():.4f} "
          f"(mean {ratio.mean():.4f})")


if __name__ == "__main__":
    main()
