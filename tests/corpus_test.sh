#!/bin/bash
# Runs pathcl on every case of the hostile-input corpus (tests/corpus/expected.tsv, written
# by tests/corpus/make_corpus.py; `render` on a scene, or a whole command line such as a
# merge or a converge) and checks pathcl's contract for bad input:
#   error   exit 2; stderr exactly one line "pathcl: error: ..." that names the file (or
#           the flag); no output written, no temporary file left, nothing beside the scene
#           changed, an existing output left byte-identical;
#   renders exit 0; every output written, nothing else; no NaN/Inf sample;
#   any     either (for the few inputs that are valid but absurd, where a limit that
#           refuses them is as right as rendering them);
# and for both: no signal, no timeout, within the memory limit.
#
#   tests/corpus_test.sh PATHCL_BINARY CORPUS_DIR [--asan] [--jobs N] [CASE_PATTERN...]
#
# CORPUS_DIR is tests/corpus. Patterns (shell globs) pick cases by name. --asan (or
# CORPUS_ASAN=1): the binary is built with AddressSanitizer, so no address-space limit.
# --jobs N (or CORPUS_JOBS; default: the cores, at most 4): the cases are dealt to N
# shards run at once, each in its own scratch directory (every case makes what it needs,
# so none depends on another), and their reports are printed shard after shard.
# Environment: CORPUS_TIMEOUT (seconds per error case, 60), CORPUS_RENDER_TIMEOUT (per
# renders case, 300: it may build a kernel variant the cache lacks), CORPUS_MEMORY_LIMIT
# (address space, 4G), CORPUS_KEEP=1 keeps the scratch directory. Each case runs in a
# fresh working directory on a scratch copy of CORPUS_DIR/files (FIFOs and the
# 100,000-deep node chain are made there); prints one PASS/FAIL line per case and a
# summary; exits 1 if any case fails.
set -u

if [ $# -lt 2 ]; then
    echo "usage: $0 PATHCL_BINARY CORPUS_DIR [--asan] [CASE_PATTERN...]" >&2
    exit 2
fi
BIN=$(realpath "$1")
CORPUS=$(realpath "$2")
shift 2
ASAN=${CORPUS_ASAN:-0}
JOBS=${CORPUS_JOBS:-$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)}
[ "$JOBS" -gt 4 ] 2>/dev/null && JOBS=4
SHARD= # K/N: run only the cases whose index (among those the patterns pick) is K modulo N
PATTERNS=()
while [ $# -gt 0 ]; do
    case $1 in
    --asan) ASAN=1 ;;
    --jobs) JOBS=${2:-} && shift ;;
    --shard) SHARD=${2:-} && shift ;;
    *) PATTERNS+=("$1") ;;
    esac
    shift
done
case $JOBS in '' | *[!0-9]* | 0) echo "corpus: --jobs wants a positive number, not '$JOBS'" >&2 && exit 2 ;; esac
TIMEOUT=${CORPUS_TIMEOUT:-60}
RENDER_TIMEOUT=${CORPUS_RENDER_TIMEOUT:-300}
MEMORY_LIMIT=${CORPUS_MEMORY_LIMIT:-4G}
MANIFEST=$CORPUS/expected.tsv
[ -x "$BIN" ] || { echo "corpus: $BIN is not an executable" >&2; exit 2; }
[ -f "$MANIFEST" ] || { echo "corpus: no $MANIFEST" >&2; exit 2; }

# The shards: this script again, once per shard, all at once; then their reports in order.
if [ -z "$SHARD" ] && [ "$JOBS" -gt 1 ]; then
    REPORTS=$(mktemp -d "${TMPDIR:-/tmp}/pathcl-corpus-reports.XXXXXX")
    trap 'rm -rf "$REPORTS"' EXIT
    flags=()
    [ "$ASAN" = 1 ] && flags+=(--asan)
    pids=()
    for ((k = 0; k < JOBS; ++k)); do
        bash "$0" "$BIN" "$CORPUS" "${flags[@]}" --shard "$k/$JOBS" "${PATTERNS[@]}" >"$REPORTS/$k" 2>&1 &
        pids+=($!)
    done
    status=0
    for pid in "${pids[@]}"; do
        wait "$pid" || status=1
    done
    total=0 passed=0 failed=0
    for ((k = 0; k < JOBS; ++k)); do
        grep -v '^corpus: [0-9]* cases, ' "$REPORTS/$k"
        read -r t p f < <(sed -n 's/^corpus: \([0-9]*\) cases, \([0-9]*\) passed, \([0-9]*\) failed$/\1 \2 \3/p' "$REPORTS/$k")
        [ -n "${t:-}" ] || { echo "corpus: shard $k/$JOBS ended without its summary" && status=1; }
        total=$((total + ${t:-0})) passed=$((passed + ${p:-0})) failed=$((failed + ${f:-0}))
    done
    if [ $total = 0 ]; then
        echo "corpus: no case matched" >&2
        exit 2
    fi
    echo "corpus: $total cases, $passed passed, $failed failed ($JOBS shards)"
    [ $failed = 0 ] && [ $status = 0 ]
    exit $?
fi
SHARD_INDEX=0 SHARD_COUNT=1
if [ -n "$SHARD" ]; then
    SHARD_INDEX=${SHARD%/*} SHARD_COUNT=${SHARD#*/}
fi

ROOT=$(mktemp -d "${TMPDIR:-/tmp}/pathcl-corpus.XXXXXX")
# shellcheck disable=SC2317 # called by the trap
cleanup()
{
    if [ "${CORPUS_KEEP:-0}" = 1 ]; then
        echo "corpus: scratch directory kept: $ROOT"
    else
        chmod -R u+w "$ROOT" 2>/dev/null
        rm -rf "$ROOT"
    fi
}
trap cleanup EXIT
FILES=$ROOT/files
cp -a "$CORPUS/files" "$FILES"
# A directory nobody may write into. root may write into any mode-0555 directory, so
# root gets /proc, where no regular file can be created.
if [ "$(id -u)" = 0 ]; then
    RO=/proc
else
    RO=$ROOT/read-only
    mkdir "$RO" && chmod 555 "$RO"
fi

# The address-space limit, by prlimit where there is one, else by ulimit -v.
limit_bytes()
{
    local v=$1
    case $v in
    *G) echo $((${v%G} * 1024 * 1024 * 1024)) ;;
    *M) echo $((${v%M} * 1024 * 1024)) ;;
    *) echo "$v" ;;
    esac
}
LIMIT=()
if [ "$ASAN" != 1 ]; then
    if command -v prlimit >/dev/null 2>&1; then
        LIMIT=(prlimit "--as=$(limit_bytes "$MEMORY_LIMIT")")
    else
        # shellcheck disable=SC2016 # expanded by that sh
        LIMIT=(sh -c 'ulimit -v "$0" && exec "$@"' "$(($(limit_bytes "$MEMORY_LIMIT") / 1024))")
    fi
fi

# files/REL: a node chain DEPTH deep ending at the triangle, from the generator's template.
make_chain()
{
    local depth=$1 rel=$2
    mkdir -p "$(dirname "$FILES/$rel")"
    awk -v depth="$depth" '
        {
            i = index($0, "\"@NODES@\"")
            j = index($0, "\"@CAMERA@\"")
            printf "%s", substr($0, 1, j - 1)
            printf "%d", depth
            printf "%s", substr($0, j + 10, i - j - 10)
            printf "["
            for (k = 0; k < depth - 1; ++k)
                printf "{\"children\":[%d]},", k + 1
            printf "{\"mesh\":0},{\"name\":\"camera\",\"camera\":0,\"translation\":[0,0,3]}]"
            print substr($0, i + 9)
        }' "$FILES/generated/chain-template.json" >"$FILES/$rel"
}

# What a case may change: the files (type, size, mtime, inode) under a directory.
snapshot()
{
    find "$1" -mindepth 1 -printf '%P\t%y\t%s\t%T@\t%i\n' 2>/dev/null | sort
}

seconds_since()
{
    awk -v a="$1" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }'
}

EXISTING="the user's earlier render: pathcl must leave this file alone"
total=0
passed=0
failed=()
n=0
picked=0
while IFS=$'\t' read -r name file args expect setup names what; do
    case $name in '' | '#'*) continue ;; esac
    if [ ${#PATTERNS[@]} -gt 0 ]; then
        match=0
        for p in "${PATTERNS[@]}"; do
            # shellcheck disable=SC2053
            [[ $name == $p ]] && match=1
        done
        [ $match = 1 ] || continue
    fi
    picked=$((picked + 1))
    [ $(((picked - 1) % SHARD_COUNT)) = "$SHARD_INDEX" ] || continue
    n=$((n + 1))
    total=$((total + 1))
    CWD=$ROOT/case-$n
    CAP=$ROOT/capture-$n
    mkdir -p "$CWD" "$CAP"
    case $file in
    -) scene= ;; # args is the whole command line
    /*) scene=$file ;;
    *) scene=$FILES/$file ;;
    esac
    [ "$names" = - ] && names=$(basename "$file")
    [ "$args" = - ] && args=

    # Set-up actions.
    fifos=()
    existing=0
    IFS=, read -ra actions <<<"$setup"
    for action in "${actions[@]}"; do
        case $action in
        - | '') ;;
        mkfifo:*)
            mkfifo "$FILES/${action#mkfifo:}"
            fifos+=("$FILES/${action#mkfifo:}")
            ;;
        cwd:*)
            spec=${action#cwd:}
            cp "$FILES/${spec%%=*}" "$CWD/${spec#*=}"
            ;;
        mkdir:*) mkdir -p "$CWD/${action#mkdir:}" ;;
        existing-output) printf '%s\n' "$EXISTING" >"$CWD/out.png" && existing=1 ;;
        chain:*)
            spec=${action#chain:}
            [ -f "$FILES/${spec#*:}" ] || make_chain "${spec%%:*}" "${spec#*:}"
            ;;
        sparse:*)
            spec=${action#sparse:}
            mkdir -p "$(dirname "$FILES/${spec%%:*}")"
            truncate -s "${spec#*:}" "$FILES/${spec%%:*}"
            ;;
        partial:*)
            IFS=: read -r rel first count <<<"${action#partial:}"
            mkdir -p "$(dirname "$FILES/$rel")"
            "$BIN" render "$FILES/valid.gltf" -o "$FILES/$rel" --width 4 --height 4 --spp 32 --batch-spp 16 \
                --sample-range "$first:$count" --quiet >/dev/null 2>&1 ||
                echo "corpus: $name: the partial render $rel failed" >&2
            ;;
        replace:*)
            IFS='|' read -r rel old new <<<"${action#replace:}"
            python3 - "$FILES/$rel" "$old" "$new" <<'PY' || echo "corpus: $name: cannot edit $rel" >&2
import codecs, sys
path, old, new = sys.argv[1], *(codecs.decode(a, "unicode_escape").encode("latin-1") for a in sys.argv[2:])
data = open(path, "rb").read()
assert len(old) == len(new) and data.count(old) == 1, (old, new, data.count(old))
open(path, "wb").write(data.replace(old, new))
PY
            ;;
        *) echo "corpus: $name: unknown set-up action '$action'" >&2 ;;
        esac
    done

    # The arguments: placeholders replaced, split at spaces; default size, spp and output.
    args=${args//\{CWD\}/$CWD}
    args=${args//\{FILES\}/$FILES}
    args=${args//\{SCENE\}/$scene}
    args=${args//\{RO\}/$RO}
    read -ra argv <<<"$args"
    outputs=()
    have_width=0 have_height=0 have_spp=0
    for ((i = 0; i < ${#argv[@]}; ++i)); do
        case ${argv[i]} in
        -o | --output) outputs+=("${argv[i + 1]:-}") ;;
        --width) have_width=1 ;;
        --height) have_height=1 ;;
        --spp) have_spp=1 ;;
        esac
    done
    if [ -n "$scene" ]; then
        if [ ${#outputs[@]} = 0 ]; then
            outputs=("$CWD/out.png")
            argv+=(-o "$CWD/out.png")
        fi
        [ $have_width = 1 ] || argv+=(--width 16)
        [ $have_height = 1 ] || argv+=(--height 16)
        [ $have_spp = 1 ] || argv+=(--spp 1)
        argv=(render "$scene" "${argv[@]}")
    fi

    limit=$TIMEOUT
    [ "$expect" != error ] && limit=$RENDER_TIMEOUT
    before_cwd=$(snapshot "$CWD")
    before_files=$(snapshot "$FILES")
    start=$(date +%s.%N)
    (cd "$CWD" && exec timeout -k 5 "$limit" "${LIMIT[@]}" "$BIN" "${argv[@]}" \
        >"$CAP/stdout" 2>"$CAP/stderr" </dev/null)
    rc=$?
    elapsed=$(seconds_since "$start")
    after_cwd=$(snapshot "$CWD")
    after_files=$(snapshot "$FILES")
    for f in "${fifos[@]}"; do rm -f "$f"; done
    # The FIFOs are gone again: their entries are not changes.
    [ ${#fifos[@]} -gt 0 ] && before_files=$(snapshot "$FILES") && after_files=$before_files

    lines=$(wc -l <"$CAP/stderr")
    bytes=$(wc -c <"$CAP/stderr")
    first=$(head -n 1 "$CAP/stderr" | cut -c 1-300)
    problems=()
    if [ $rc = 124 ] || [ $rc = 137 ]; then
        problems+=("timed out after ${limit} s")
    elif [ $rc -gt 128 ]; then
        problems+=("killed by signal $((rc - 128))")
    fi
    mode=$expect
    if [ "$expect" = any ]; then
        mode=error
        [ $rc = 0 ] && mode=renders
    fi
    if [ "$mode" = error ]; then
        [ $rc = 2 ] || problems+=("exit $rc, expected 2")
        if [ "$lines" != 1 ] || [ "$bytes" = 0 ] || [ "$(tail -c 1 "$CAP/stderr" | od -An -c | tr -d ' ')" != '\n' ]; then
            problems+=("stderr has $lines lines, expected exactly one")
        fi
        case $first in
        "pathcl: error: "*) ;;
        *) problems+=("stderr does not begin 'pathcl: error: '") ;;
        esac
        named=0
        IFS='|' read -ra alternatives <<<"$names"
        for alternative in "${alternatives[@]}"; do
            [[ $first == *"$alternative"* ]] && named=1
        done
        [ $named = 1 ] || problems+=("the error does not name '$names'")
        [ "$after_cwd" = "$before_cwd" ] ||
            problems+=("the working directory changed: $(diff <(echo "$before_cwd") <(echo "$after_cwd") |
                grep '^[<>] .' | cut -f1 | tr '\n' ' ')")
        if [ $existing = 1 ] && [ "$(cat "$CWD/out.png" 2>/dev/null)" != "$EXISTING" ]; then
            problems+=("the existing output was changed")
        fi
    else
        [ $rc = 0 ] || problems+=("exit $rc, expected 0")
        for o in "${outputs[@]}"; do
            [ -s "$o" ] || problems+=("no output $(basename "$o")")
        done
        if [ "${argv[0]}" = render ]; then
            grep -q ' 0 NaN/Inf samples' "$CAP/stdout" || problems+=("the summary does not say 0 NaN/Inf samples")
        fi
        if grep -v '^pathcl: warning: ' "$CAP/stderr" | grep -q .; then
            problems+=("stderr holds more than warnings")
        fi
        expected_cwd=$( (
            [ -n "$before_cwd" ] && echo "$before_cwd" | cut -f1
            for o in "${outputs[@]}"; do
                case $o in "$CWD"/*) echo "${o#"$CWD"/}" ;; esac
            done
        ) | sort -u)
        actual_cwd=$(echo "$after_cwd" | cut -f1 | sed '/^$/d' | sort -u)
        [ "$actual_cwd" = "$expected_cwd" ] ||
            problems+=("the working directory holds: $(echo "$actual_cwd" | tr '\n' ' ')")
    fi
    [ "$after_files" = "$before_files" ] ||
        problems+=("files beside the scene changed: $(diff <(echo "$before_files") <(echo "$after_files") |
            grep '^[<>] .' | cut -f1 | sort -u | tr '\n' ' ')")
    if [ ${#problems[@]} = 0 ]; then
        passed=$((passed + 1))
        if [ "${CORPUS_VERBOSE:-0}" = 1 ]; then
            echo "PASS $name (${elapsed} s) | stderr: ${first:-(empty)}"
        else
            echo "PASS $name (${elapsed} s)"
        fi
    else
        failed+=("$name")
        msg=$(printf '%s; ' "${problems[@]}")
        echo "FAIL $name (${elapsed} s): ${msg%; } | case: $what | stderr: ${first:-(empty)}"
    fi
    chmod -R u+w "$CWD" 2>/dev/null
    rm -rf "$CWD" "$CAP"
done <"$MANIFEST"

if [ $total = 0 ] && [ -z "$SHARD" ]; then
    echo "corpus: no case matched" >&2
    exit 2
fi
echo "corpus: $total cases, $passed passed, ${#failed[@]} failed"
if [ ${#failed[@]} -gt 0 ]; then
    echo "corpus: failed: ${failed[*]}"
    exit 1
fi
exit 0
