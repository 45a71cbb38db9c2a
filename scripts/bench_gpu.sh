#!/usr/bin/env bash
# GPU benchmark, run on the GPU machine from the project root (the `run` tool's working tree):
# builds build-gpu, runs the CUDA tests, semsplat's GPU benchmark, then gsplat's anchors
# (shared/bench/anchors/run_device.sh) in the SAME session so both see one machine state, and
# prints semsplat / gsplat time ratios per scene. Results are copied to $OUT when set.
# Usage: scripts/bench_gpu.sh [--no-build] [--no-tests] [--no-anchor] [--min-build]
set -u
cd "$(dirname "$0")/.."
build=1 tests=1 anchor=1
for a in "$@"; do
  case $a in --min-build) build=2 ;; --no-build) build=0 ;; --no-tests) tests=0 ;; --no-anchor) anchor=0 ;; esac
done
out=${OUT:-/tmp}
nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv,noheader
# The GPU machine may lack the -dev packages the full build needs (libcjson, assimp, ...); then
# build only what the CUDA tests and benchmarks link: core, device (CPU + CUDA), render (CPU +
# CUDA), the train kernels and their CPU references, straight with gcc and nvcc into build-gpu/.
min_build() {
  local nvcc=${NVCC:-$(command -v nvcc || echo /usr/local/cuda/bin/nvcc)}
  local b=build-gpu/min f o; mkdir -p "$b" build-gpu/bench
  local cflags=(-O2 -std=c11 -fPIC -ffp-contract=off -D_POSIX_C_SOURCE=200809L -D_DEFAULT_SOURCE
                "-DSP_DATA_DIR=\"$PWD/data\"" -Iinclude -Isrc)
  local objs=()
  for f in src/core/*.c src/device/*.c src/render/*.c src/train/loss.c src/train/cpu_kernels.c; do
    o=$b/$(echo "$f" | tr / _).o; objs+=("$o"); gcc "${cflags[@]}" -c "$f" -o "$o" &
  done
  for f in src/device/cuda/*.cu src/render/cuda/*.cu src/train/cuda/*.cu; do
    o=$b/$(echo "$f" | tr / _).o; objs+=("$o")
    # as CMakeLists.txt: the projection rounds exactly like the CPU backend, the rest is fast math
    local fm=--use_fast_math; [ "$f" = src/render/cuda/project.cu ] && fm=-fmad=false
    "$nvcc" -O3 $fm -lineinfo -arch=sm_90 -Xcompiler -fPIC -Iinclude -Isrc -c "$f" -o "$o" &
  done
  wait
  for o in "${objs[@]}"; do [ -f "$o" ] || { echo "error: $o was not built"; return 1; }; done
  rm -f $b/libsp.a; ar rcs $b/libsp.a "${objs[@]}" || return 1
  for f in tests/render/test_cuda_*.c; do
    o=render_$(basename "$f" .c)
    [ "$o" = render_test_cuda_splat ] && continue # trains a splat: needs io and train (below)
    gcc "${cflags[@]}" -Itests "-DSP_SOURCE_DIR=\"$PWD\"" "-DSP_BUILD_DIR=\"$PWD/build-gpu\"" \
      -c "$f" -o $b/$o.o && "$nvcc" -o build-gpu/$o $b/$o.o $b/libsp.a -lcublas -lm -lpthread || return 1
  done
  for f in bench/bench_render_gpu.c; do
    o=$(basename "$f" .c)
    gcc "${cflags[@]}" -c "$f" -o $b/$o.o &&
      "$nvcc" -o build-gpu/bench/$o $b/$o.o $b/libsp.a -lcublas -lm -lpthread || return 1
  done
  # The trainer benchmark also needs io and train, hence cJSON: from the system, or from a
  # copy of its header and library carried in $SP_CJSON (include/cjson/cJSON.h, lib/).
  local cj=${SP_CJSON:-}
  if [ -f /usr/include/cjson/cJSON.h ] || [ -n "$cj" ]; then
    local tobjs=() jf=()
    [ -n "$cj" ] && jf=(-I"$cj/include")
    for f in src/io/*.c src/train/*.c; do
      case $f in src/train/loss.c|src/train/cpu_kernels.c) continue ;; esac
      o=$b/$(echo "$f" | tr / _).o; tobjs+=("$o"); gcc "${cflags[@]}" "${jf[@]}" -c "$f" -o "$o" &
    done
    wait
    gcc "${cflags[@]}" -c bench/bench_train_gpu.c -o $b/bench_train_gpu.o &&
      "$nvcc" -o build-gpu/bench/bench_train_gpu $b/bench_train_gpu.o "${tobjs[@]}" $b/libsp.a -lcublas \
        ${cj:+-L"$cj/lib" -Xlinker -rpath="$PWD/$cj/lib"} -lcjson -lpng -ljpeg -lz -lm -lpthread ||
      return 1
    gcc "${cflags[@]}" "${jf[@]}" -Itests "-DSP_SOURCE_DIR=\"$PWD\"" "-DSP_BUILD_DIR=\"$PWD/build-gpu\"" \
      -c tests/render/test_cuda_splat.c -o $b/test_cuda_splat.o &&
      "$nvcc" -o build-gpu/render_test_cuda_splat $b/test_cuda_splat.o "${tobjs[@]}" $b/libsp.a -lcublas \
        ${cj:+-L"$cj/lib" -Xlinker -rpath="$PWD/$cj/lib"} -lcjson -lpng -ljpeg -lz -lm -lpthread ||
      return 1
  fi
}
if [ $build = 2 ]; then
  t0=$(date +%s); min_build >"$out/build.log" 2>&1 || { echo "minimal build failed:"; grep -E "error" "$out/build.log" | head -30; }
  echo "build: $(( $(date +%s) - t0 )) s"
elif [ $build = 1 ]; then
  t0=$(date +%s)
  # a cJSON copy carried in $SP_CJSON (include/, lib/) stands in for the -dev package
  if cmake -S . -B build-gpu -DCMAKE_BUILD_TYPE=Release -DSP_WERROR=OFF \
      ${SP_CJSON:+-DSP_DEPS_ROOT=$PWD/$SP_CJSON} >"$out/configure.log" 2>&1; then
    cmake --build build-gpu -j16 >"$out/build.log" 2>&1 ||
      { echo "build failed:"; grep -E "error|Error" "$out/build.log" | head -30; }
  else
    echo "full configure failed ($(grep -m1 -A3 'not found' "$out/configure.log" | tr '\n' ' ')); minimal build"
    min_build >"$out/build.log" 2>&1 || { echo "minimal build failed:"; grep -E "error" "$out/build.log" | head -30; }
  fi
  echo "build: $(( $(date +%s) - t0 )) s"
fi
if [ $tests = 1 ]; then
  if [ -f build-gpu/CTestTestfile.cmake ]; then
    # the full build: every GPU test and GPU case (CTest lists any that skipped)
    (cd build-gpu && timeout 900 ctest -R 'cuda|gpu' --output-on-failure 2>&1 | tail -60)
  else
    for t in build-gpu/render_test_cuda_*; do
      [ -x "$t" ] || continue
      echo "== $t"; timeout 300 "$t" 2>&1 | tail -40
    done
  fi
fi
echo "== semsplat bench"
timeout 400 build-gpu/bench/bench_render_gpu | tee "$out/semsplat-gpu.txt"
if [ -x build-gpu/bench/bench_train_gpu ]; then
  echo "== semsplat training loop on the GPU"
  timeout 300 build-gpu/bench/bench_train_gpu 3000 | tee -a "$out/semsplat-gpu.txt"
fi
if [ $anchor = 1 ]; then
  # shared/ travels to the GPU machine only when it is inside the checkout; otherwise copy it
  # into an ignored folder, carry that, and point SP_ANCHORS at it.
  anchors=${SP_ANCHORS:-shared/bench/anchors}
  [ -d "$anchors" ] || anchors=../shared/bench/anchors
  echo "== gsplat anchors ($anchors)"
  OUT=$out timeout 500 bash "$anchors/run_device.sh" gsplat >"$out/anchor-run.txt" 2>&1
  tail -12 "$out/anchor-run.txt"
  [ -f "$out/anchor-gsplat.jsonl" ] || { echo "no gsplat figures (see $out/anchor-run.txt)"; exit 1; }
  python3 - "$out/semsplat-gpu.txt" "$out/anchor-gsplat.jsonl" <<'EOF'
import json, sys
ours = {}
for line in open(sys.argv[1]):
    if line.startswith("JSON "):
        d = json.loads(line[5:]); ours[(d["n"], d["w"], d["h"], d["d"])] = d
print("%-26s %9s %9s %6s | %9s %9s %6s | %s" % ("scene", "fwd ms", "gsplat", "ratio", "f+b ms", "gsplat", "ratio", "peak GiB ours/gsplat"))
for line in open(sys.argv[2]):
    try: g = json.loads(line)
    except ValueError: continue
    if g.get("what") != "gsplat" or "fwd_ms" not in g: continue
    k = (g["n"], g["w"], g["h"], g["d"]); o = ours.get(k)
    if not o: continue
    print("%-26s %9.3f %9.3f %6.2f | %9.3f %9.3f %6.2f | %.3f / %.3f" % (
        "%d %dx%d D=%d" % k, o["fwd_ms"], g["fwd_ms"], o["fwd_ms"] / g["fwd_ms"],
        o["fwd_bwd_ms"], g["fwd_bwd_ms"], o["fwd_bwd_ms"] / g["fwd_bwd_ms"], o["peak_gib"], g["peak_gib"]))
print("(ratio < 1: semsplat faster)")
EOF
fi
