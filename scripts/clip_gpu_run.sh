#!/usr/bin/env bash
# One GPU-machine call for the clip module's GPU work (issue 23): build, the GPU tests (fused
# attention against a double reference, GPU vs CPU towers and dense pipeline), parity and
# throughput against transformers (tests/clip/device_check.sh, QUICK), the feature-folder and
# SGEMM benchmarks, then optionally compute-sanitizer and Nsight Compute.
#   SP_CJSON=<cJSON copy> [SANITIZE=1] [NCU=1] bash scripts/clip_gpu_run.sh   (from the project root)
# Writes p.txt (this script's log) and ncu.txt under $OUT beside device_check.sh's five files.
set -u
cd "$(dirname "$0")/.."
OUT=${OUT:-/tmp/clip-out}; mkdir -p "$OUT"
exec > >(tee "$OUT/p.txt") 2>&1
t0=$(date +%s); el() { echo "[$(( $(date +%s) - t0 )) s] $*"; }
nvidia-smi --query-gpu=name,memory.total,driver_version,clocks.sm --format=csv,noheader
cmake -S . -B build-gpu -DCMAKE_BUILD_TYPE=Release -DSP_WERROR=OFF ${SP_CJSON:+-DSP_DEPS_ROOT=$PWD/$SP_CJSON} \
  >/tmp/p-configure.log 2>&1 || { echo "configure failed"; tail -20 /tmp/p-configure.log; }
grep -E "semsplat:" /tmp/p-configure.log
cmake --build build-gpu -j16 --target clip_test_model clip_test_dense clip_test_reference clip_test_tokenizer \
  clip_test_sgemm bench_clip bench_features bench_sgemm >/tmp/p-build.log 2>&1 ||
  { echo "build failed:"; grep -E "error" /tmp/p-build.log | head -30; }
el "built"
for t in model dense sgemm; do
  echo "== clip_test_$t"; timeout 300 ./build-gpu/clip_test_$t --gpu 2>&1 | tail -25
done
./build-gpu/clip_test_sgemm 2>&1 | tail -3
el "gpu tests done"
QUICK=1 BENCH_ARGS="${BENCH_ARGS:---variants}" timeout 400 bash tests/clip/device_check.sh >/dev/null 2>&1
sleep 1 # its tee may still be writing
grep -E "parity|GPU fp|fused|FAIL|failed|vs_trans|img/s|texts/s" "$OUT/log.txt" | grep -v "^\[" | head -60
el "device_check done"
timeout 120 ./build-gpu/bench/bench_features --dir /tmp/bf 2>&1 | tail -3
timeout 60 ./build-gpu/bench/bench_features --cpu --dir /tmp/bf2 2>&1 | tail -3
timeout 120 ./build-gpu/bench/bench_sgemm --threads 16 2>&1 | tail -9
el "feature benches done"
left() { [ $(( $(date +%s) - t0 )) -lt "$1" ]; } # still inside a time budget (s)
if [ "${SANITIZE:-0}" = 1 ] && left "${SANITIZE_BY:-200}"; then
  cs=$(command -v compute-sanitizer || ls /opt/nvidia/*/compute-sanitizer /usr/local/cuda/bin/compute-sanitizer 2>/dev/null | head -1)
  for t in ${SANITIZE_TESTS:-model dense}; do
    echo "== memcheck clip_test_$t"
    timeout 60 "$cs" --tool memcheck --print-limit 5 ./build-gpu/clip_test_$t --gpu 2>&1 | grep -E "ERROR SUMMARY|Invalid|at 0x|ok |FAIL" | head -12
  done
  el "sanitizer done"
fi
if [ "${NCU:-0}" = 1 ] && left "${NCU_BY:-220}"; then
  ncu=$(command -v ncu || ls /opt/nvidia/nsight-compute/*/ncu /usr/local/cuda/bin/ncu 2>/dev/null | head -1)
  # NCU_K: kernel-name regex, NCU_SKIP launches of it skipped, NCU_C profiled (defaults: the first
  # block of the b128 image forward after the fp16 conversion)
  timeout "${NCU_S:-60}" "$ncu" --clock-control none --section SpeedOfLight --section Occupancy \
    -k "regex:${NCU_K:-.}" --launch-skip "${NCU_SKIP:-1}" -c "${NCU_C:-13}" \
    ./build-gpu/bench/bench_clip --gpu-only --ncu >"$OUT/ncu.txt" 2>&1
  grep -E "^  [a-zA-Z_].*\(|Duration|Memory Throughput|Compute \(SM\) Throughput|Achieved Occupancy|Registers Per" \
    "$OUT/ncu.txt" | head -90
  el "ncu done"
fi
