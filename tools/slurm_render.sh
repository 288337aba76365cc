#!/bin/sh
# One frame over a Slurm job array: each array task renders its share of the frame's
# batches (pathcl render --sample-range) and a last job merges them (pathcl merge) into the
# image the uninterrupted render gives, bit for bit (when every task ran on one kind of
# device; docs/scaling-out.md).
#
#   sbatch --array=0-15 tools/slurm_render.sh render SCENE DIR SPP BATCH_SPP [render options...]
#   sbatch --dependency=afterok:JOBID tools/slurm_render.sh merge DIR OUT.exr
#
# Task i of n (SLURM_ARRAY_TASK_ID, SLURM_ARRAY_TASK_COUNT) renders batches
# [i*b/n, (i+1)*b/n) of the b = ceil(SPP / BATCH_SPP) batches into DIR/range-i.exr, with a
# checkpoint beside it: a task that is preempted or requeued resumes where it stopped.
# Tasks beyond the batch count have nothing to do. Every task must see the same scene
# files and options (the merge refuses ranges of different renders), and the options must
# fix the seed if they change it. PATHCL (default: pathcl on PATH) names the binary.
# Without Slurm, the same script runs tasks by hand (tests/slurm_script_test.sh does):
#   SLURM_ARRAY_TASK_ID=3 SLURM_ARRAY_TASK_COUNT=8 sh tools/slurm_render.sh render ...
#
#SBATCH --job-name=pathcl-frame
#SBATCH --requeue
set -eu
PATHCL=${PATHCL:-pathcl}
usage() {
    echo "usage: $0 render SCENE DIR SPP BATCH_SPP [render options...] | merge DIR OUT.exr" >&2
    exit 2
}
[ $# -ge 1 ] || usage
mode=$1
shift
case $mode in
render)
    [ $# -ge 4 ] || usage
    scene=$1 dir=$2 spp=$3 batch=$4
    shift 4
    task=${SLURM_ARRAY_TASK_ID:?not an array task: set SLURM_ARRAY_TASK_ID}
    tasks=${SLURM_ARRAY_TASK_COUNT:?not an array task: set SLURM_ARRAY_TASK_COUNT}
    batches=$(((spp + batch - 1) / batch))
    first_batch=$((task * batches / tasks))
    end_batch=$(((task + 1) * batches / tasks))
    [ "$end_batch" -gt "$first_batch" ] || exit 0 # more tasks than batches
    first=$((first_batch * batch))
    end=$((end_batch * batch))
    [ "$end" -le "$spp" ] || end=$spp # the last batch may be partial
    mkdir -p "$dir"
    checkpoint=$dir/range-$task.checkpoint
    resume=""
    [ -f "$checkpoint" ] && resume="--resume $checkpoint"
    # shellcheck disable=SC2086
    "$PATHCL" render "$scene" -o "$dir/range-$task.exr" --spp "$spp" --batch-spp "$batch" \
        --sample-range "$first:$((end - first))" --checkpoint "$checkpoint" $resume --quiet "$@"
    rm -f "$checkpoint"
    ;;
merge)
    [ $# -eq 2 ] || usage
    dir=$1 out=$2
    "$PATHCL" merge "$dir"/range-*.exr -o "$out"
    ;;
*)
    usage
    ;;
esac
