#!/bin/bash
# GPU acceptance run (issues 4 and 6), on a machine with a GPU: builds semsplat, then on a house
# capture made by `semsplat synth` trains on the GPU, extracts label features, lifts them,
# queries every ground-truth class with both localization methods (semsplat demo --capture),
# distills, compares the CPU and CUDA backends on the trained splat, and benches queries.
#   bash scripts/gpu_acceptance.sh CAPTURE_DIR OUT_DIR [STEPS]
# Machines without the -dev packages: put cJSON's include/ and lib/ under .gpu-shared/cjson.
set -u
cap=$1 out=$2 steps=${3:-7000}
mkdir -p "$out"
deps=""
[ -f /usr/include/cjson/cJSON.h ] || deps="-DSP_DEPS_ROOT=$PWD/.gpu-shared/cjson"
t0=$(date +%s)
cmake -S . -B build-gpu -DCMAKE_BUILD_TYPE=Release -DSP_WERROR=OFF $deps >"$out/build.log" 2>&1 &&
  cmake --build build-gpu -j"$(nproc)" >>"$out/build.log" 2>&1 || { tail -40 "$out/build.log"; exit 1; }
B=$PWD/build-gpu
echo "build: $(( $(date +%s) - t0 )) s; GPU: $(nvidia-smi --query-gpu=name --format=csv,noheader)"

echo "== demo on the capture (train $steps steps on the GPU, features, lift, queries)"
"$B/semsplat" demo --capture "$cap" --out "$out/demo" --steps "$steps" --device cuda --quiet
echo "== train.json"; cat "$out/demo/model/train.json"; echo

echo "== lift alone on the GPU"
/usr/bin/time -f "lift wall %e s" "$B/semsplat" lift --model "$out/demo/model" --features "$out/demo/features" \
  --colmap "$cap" --device cuda --quiet

echo "== distill (joint RGB + feature training) on the GPU"
rm -rf "$out/distilled"; cp -r "$out/demo/model" "$out/distilled"
"$B/semsplat" distill --model "$out/distilled" --features "$out/demo/features" --colmap "$cap" \
  --steps 3000 --device cuda --quiet

echo "== GPU tests (CPU vs CUDA on random scenes, a splat trained by the test, batches, depth modes)"
(cd "$B" && ctest -R 'cuda|gpu' --output-on-failure 2>&1 | tail -40)
echo "== CPU vs CUDA on the trained house"
SP_TEST_SPLAT="$out/demo/model/splat.ply" SP_TEST_COLMAP="$cap" "$B/render_test_cuda_splat"

echo "== query bench (300k Gaussians)"
"$B/bench/bench_query" 300000
echo "total: $(( $(date +%s) - t0 )) s"
