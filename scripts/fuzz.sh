#!/bin/sh
# Runs the libFuzzer harnesses (tests/fuzz/fuzz_*.c) for a time or an execution count.
#
#   scripts/fuzz.sh [-t SECONDS | -n RUNS] [-s SEED] [-j JOBS] [-B BUILD] [-o OUT] [--merge] [--no-build] [HARNESS...]
#
#   -t SECONDS   run each harness this long (default 10)
#   -n RUNS      stop a harness after this many executions (with -t: whichever comes first)
#   -s SEED      libFuzzer's random seed (default 0: a new one each run); CI passes 1 so that a
#                fault it finds is found again by the same command here
#   -j JOBS      harnesses run at once (default 1; the machine is shared: 2 at most)
#   -B BUILD     build folder (default build-fuzz: CC=clang, -DSP_FUZZ=ON, configured here)
#   -o OUT       output folder (default /tmp/semsplat-fuzz): OUT/corpus/<h> new inputs (the
#                repository's corpus is only read), OUT/crashes/<h>/ crashes, timeouts and
#                out-of-memory inputs, OUT/logs/<h>.log, OUT/summary.txt
#   --merge      afterwards merge OUT/corpus/<h> into tests/fuzz/corpus/<h> (only inputs that add
#                coverage; libFuzzer -merge=1)
#   --no-build   use BUILD as it is
#   HARNESS      names without fuzz_ (colmap_bin, ply, ...); default: every harness built
#
# Prints one line per harness: executions, coverage (cov: edges, ft: features), exec/s and the
# faults found. Exits 1 when any harness found a fault (a crash, a sanitizer report, an input
# running past 10 s or past 2 GB), so CI fails. A fault's input is in OUT/crashes/<h>/; add it to
# tests/fuzz/corpus/<h>/ as crash-<what> once fixed: the CTest test fuzz/<h> replays it in
# every build. Runs under nice -n 10.
set -e
cd "$(dirname "$0")/.."
ROOT=$(pwd)
SECONDS_EACH=10
RUNS=
JOBS=1
SEED=0
BUILD=build-fuzz
OUT=/tmp/semsplat-fuzz
MERGE=0
DO_BUILD=1
TIME_SET=0
while [ $# -gt 0 ]; do
    case "$1" in
    -t) SECONDS_EACH=$2; TIME_SET=1; shift 2 ;;
    -n) RUNS=$2; [ "$TIME_SET" = 1 ] || SECONDS_EACH=2147483; shift 2 ;;
    -s) SEED=$2; shift 2 ;;
    -j) JOBS=$2; shift 2 ;;
    -B) BUILD=$2; shift 2 ;;
    -o) OUT=$2; shift 2 ;;
    --merge) MERGE=1; shift ;;
    --no-build) DO_BUILD=0; shift ;;
    -h|--help) sed -n '2,26p' "$0"; exit 0 ;;
    -*) echo "fuzz.sh: unknown option $1" >&2; exit 2 ;;
    *) break ;;
    esac
done

if [ "$DO_BUILD" = 1 ]; then
    if [ ! -f "$BUILD/CMakeCache.txt" ]; then
        CC=clang cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSP_FUZZ=ON >/dev/null
    fi
    nice -n 10 cmake --build "$BUILD" -j2 --target fuzz >/dev/null
fi
[ -d "$BUILD/fuzz" ] || { echo "fuzz.sh: no harnesses in $BUILD/fuzz (configure with CC=clang -DSP_FUZZ=ON)" >&2; exit 2; }

if [ $# -eq 0 ]; then
    set --
    for f in "$BUILD"/fuzz/fuzz_*; do
        case "$f" in *_replay) continue ;; esac
        [ -x "$f" ] && set -- "$@" "$(basename "$f" | sed 's/^fuzz_//')"
    done
fi
mkdir -p "$OUT/logs"
: >"$OUT/summary.txt"

# The dictionary a harness uses: its own, else the one of its format family.
dict_of() {
    for d in "$1" $(echo "$1" | sed 's/_json$//; s/^colmap_bin$/colmap_txt/'); do
        [ -f "tests/fuzz/dict/$d.dict" ] && { echo "tests/fuzz/dict/$d.dict"; return; }
    done
    case "$1" in *_json) echo tests/fuzz/dict/json.dict ;; esac
}

run_one() {
    h=$1
    bin="$BUILD/fuzz/fuzz_$h"
    [ -x "$bin" ] || { echo "fuzz.sh: no harness $bin" >&2; return 2; }
    mkdir -p "$OUT/corpus/$h" "$OUT/crashes/$h"
    dict=$(dict_of "$h")
    limit="-max_total_time=$SECONDS_EACH"
    [ -n "$RUNS" ] && limit="$limit -runs=$RUNS"
    log="$OUT/logs/$h.log"
    status=0
    # -timeout: an input taking 10 s is a hang; -rss_limit_mb: 2 GB is a memory blow-up.
    nice -n 10 "$bin" $limit -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -seed="$SEED" \
        ${dict:+-dict=$dict} -artifact_prefix="$OUT/crashes/$h/" \
        "$OUT/corpus/$h" "tests/fuzz/corpus/$h" >"$log" 2>&1 || status=$?
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
    cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
    ft=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
    faults=$(ls "$OUT/crashes/$h" | wc -l)
    line=$(printf '%-16s execs %10s  cov %5s  ft %6s  exec/s %6s  faults %s' "$h" "${execs:-?}" "${cov:-?}" \
        "${ft:-?}" "${rate:-?}" "$faults")
    [ "$status" -ne 0 ] && line="$line  FAILED (exit $status, see $log)"
    echo "$line" | tee -a "$OUT/summary.txt"
    if [ "$MERGE" = 1 ] && [ "$status" -eq 0 ]; then
        nice -n 10 "$bin" -merge=1 "tests/fuzz/corpus/$h" "$OUT/corpus/$h" >"$OUT/logs/$h.merge.log" 2>&1 || true
    fi
    [ "$status" -eq 0 ] && [ "$faults" -eq 0 ]
}

# JOBS lanes, each running its share of the harnesses (round robin) one after another.
lane() {
    lane_fail=0
    i=0
    for h in "$@"; do
        [ $((i % JOBS)) -eq "$LANE" ] && { run_one "$h" || lane_fail=1; }
        i=$((i + 1))
    done
    return $lane_fail
}
fail=0
pids=
LANE=0
while [ "$LANE" -lt "$JOBS" ]; do
    ( lane "$@" ) &
    pids="$pids $!"
    LANE=$((LANE + 1))
done
for p in $pids; do wait "$p" || fail=1; done
[ "$fail" = 0 ] || echo "fuzz.sh: faults found; inputs in $OUT/crashes/, logs in $OUT/logs/" >&2
exit $fail
