#!/bin/sh
# Error against a converged reference versus render time, per sampler: the Cornell box at
# 64x64, 64 spp, 8 bounces, rendered RUNS times (seeds 1..RUNS) with each sampler.
# Prints one CSV row per render (sampler, seed, render seconds, RMSE over all channels,
# RMSE per channel), then per sampler the mean RMSE and min/median/max render time.
#   tools/measure_samplers.sh REFERENCE.exr [build-dir] [runs]
# Make the reference once (a few minutes on 2 cores):
#   build/pathcl render scenes/cornell-box.gltf -o ref.exr --width 64 --height 64 \
#       --spp 16384 --max-bounces 8 --seed 12345 --sampler independent
set -eu
cd "$(dirname "$0")/.."
REF=$1
BUILD=${2:-build}
RUNS=${3:-5}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
SAMPLERS="independent jittered multi-jittered n-rooks sobol halton hammersley"
echo "sampler,seed,render_s,rmse,rmse_r,rmse_g,rmse_b"
# Samplers interleaved within each seed, so that other load on the machine affects all
# of them alike.
seed=1
while [ "$seed" -le "$RUNS" ]; do
    for sampler in $SAMPLERS; do
        line=$("$BUILD/pathcl" render scenes/cornell-box.gltf -o "$TMP/img.exr" --width 64 --height 64 \
            --spp 64 --max-bounces 8 --seed "$seed" --sampler "$sampler")
        secs=$(echo "$line" | sed -n 's/.*| render \([0-9.]*\) s |.*/\1/p')
        rmse=$("$BUILD/pathcl" compare "$TMP/img.exr" "$REF" | sed -n \
            's/^RMSE of A against B (\([^ ]*\) \([^ ]*\) \([^ ]*\)), all channels \(.*\)$/\4,\1,\2,\3/p' || true)
        echo "$sampler,$seed,$secs,$rmse"
    done
    seed=$((seed + 1))
done | tee "$TMP/rows.csv"
echo
echo "sampler,mean_rmse,render_s_min,render_s_median,render_s_max"
for sampler in $SAMPLERS; do
    grep "^$sampler," "$TMP/rows.csv" | sort -t, -k3 -g | awk -F, -v s="$sampler" '
        { t[NR] = $3; r += $4 }
        END { printf "%s,%.6f,%.3f,%.3f,%.3f\n", s, r / NR, t[1], t[int((NR + 1) / 2)], t[NR] }'
done
