#!/bin/sh
# tools/slurm_render.sh without Slurm: the array tasks of one frame run as parallel
# processes (1 task, 3, then 7 for 5 batches, so that some have none), and their merge
# must be the whole render bit for bit.
#   sh tests/slurm_script_test.sh PATHCL SOURCE_DIR
set -eu
PATHCL=$1
SRC=$2
export PATHCL
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
SCENE=$SRC/scenes/cornell-box-sphere.gltf
OPTS="--width 24 --height 20 --seed 9"
# shellcheck disable=SC2086
"$PATHCL" render "$SCENE" -o "$WORK/whole.exr" --spp 36 --batch-spp 8 --quiet $OPTS
for tasks in 1 3 7; do
    pids=""
    task=0
    while [ $task -lt $tasks ]; do
        # shellcheck disable=SC2086
        SLURM_ARRAY_TASK_ID=$task SLURM_ARRAY_TASK_COUNT=$tasks \
            sh "$SRC/tools/slurm_render.sh" render "$SCENE" "$WORK/frame$tasks" 36 8 $OPTS &
        pids="$pids $!"
        task=$((task + 1))
    done
    for pid in $pids; do
        wait "$pid"
    done
    sh "$SRC/tools/slurm_render.sh" merge "$WORK/frame$tasks" "$WORK/merged$tasks.exr"
    "$PATHCL" compare --bitwise "$WORK/whole.exr" "$WORK/merged$tasks.exr"
    if ls "$WORK/frame$tasks"/*.checkpoint >/dev/null 2>&1; then
        echo "a finished task left its checkpoint" >&2
        exit 1
    fi
done
echo "slurm script: 1, 3 and 7 tasks merge into the whole render"
