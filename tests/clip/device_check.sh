#!/usr/bin/env bash
# The clip module's GPU-machine run (one call): reference models and tokenizer ids from
# transformers (scripts/clip_reference.py), parity of our CPU and GPU code against them, and the
# benchmark with transformers' figures from the same run. At most 8 files land in $OUT.
#   bash tests/clip/device_check.sh        (from the project root on the GPU machine)
#   QUICK=1 bash tests/clip/device_check.sh   skips the tokenizer pairs and the tiny model
# Where the machine lacks the -dev packages, a minimal build links only what the clip tests need
# (cJSON carried in .clipdev/, plain-loop GEMMs instead of OpenBLAS: SP_CLIP_NO_BLAS).
set -u
OUT=${OUT:-/tmp/clip-out}
W=/tmp/clipw; mkdir -p "$W/ref" "$W/tiny" "$W/tok" "$OUT"
exec > >(tee "$OUT/log.txt") 2>&1
t0=$(date +%s); el() { echo "[$(( $(date +%s) - t0 )) s] $*"; }
nvidia-smi --query-gpu=name,memory.total --format=csv,noheader
python3 -c "import torch, transformers; print('torch', torch.__version__, 'transformers', transformers.__version__)" 2>&1 | tail -1
python3 -c "import ftfy" 2>/dev/null && echo "ftfy installed" || echo "no ftfy"
TESTS="test_reference test_tokenizer test_model"
min_build() {
  local nv=$(command -v nvcc || echo /usr/local/cuda/bin/nvcc) b=build-gpu/min o objs=()
  mkdir -p $b build-gpu/bench
  local cf=(-O2 -std=c11 -fPIC -ffp-contract=off -D_POSIX_C_SOURCE=200809L -D_DEFAULT_SOURCE -DSP_CLIP_NO_BLAS
            "-DSP_DATA_DIR=\"$PWD/data\"" -Iinclude -Isrc -I.clipdev/include -I.clipdev/include/cjson
            -I"$(dirname "$(dirname "$nv")")/include")
  for f in src/core/*.c src/device/*.c src/io/common.c src/io/json.c src/io/npy.c src/io/safetensors.c \
           src/clip/tokenizer.c src/clip/model.c src/clip/cpu.c src/clip/dense.c src/clip/label.c src/clip/half_host.c; do
    o=$b/$(echo "$f" | tr / _).o; objs+=("$o"); gcc "${cf[@]}" -c "$f" -o "$o" &
  done
  for f in src/device/cuda/*.cu src/clip/cuda/*.cu; do
    o=$b/$(echo "$f" | tr / _).o; objs+=("$o")
    "$nv" -O3 --use_fast_math -arch=sm_90 -Xcompiler -fPIC -Iinclude -Isrc -c "$f" -o "$o" &
  done
  wait
  rm -f $b/libsp.a; ar rcs $b/libsp.a "${objs[@]}" || return 1
  local lk=($b/libsp.a -L.clipdev/lib -lcjson -lcublas -lcublasLt -lcudart -lm -lpthread -Xlinker -rpath="$PWD/.clipdev/lib")
  for t in $TESTS; do
    gcc "${cf[@]}" -Itests "-DSP_SOURCE_DIR=\"$PWD\"" "-DSP_BUILD_DIR=\"$PWD/build-gpu\"" -c tests/clip/$t.c -o $b/$t.o &&
      "$nv" -arch=sm_90 -o build-gpu/clip_$t $b/$t.o "${lk[@]}" || echo "link $t failed"
  done
  gcc "${cf[@]}" -c bench/bench_clip.c -o $b/bench_clip.o && "$nv" -arch=sm_90 -o build-gpu/bench/bench_clip $b/bench_clip.o "${lk[@]}"
}
build() {
  if cmake -S . -B build-gpu -DSP_WERROR=OFF >"$W/build.log" 2>&1; then
    cmake --build build-gpu -j16 --target clip_test_reference clip_test_tokenizer clip_test_model bench_clip >>"$W/build.log" 2>&1
  else
    echo "cmake configure failed (missing -dev packages?): minimal build" >>"$W/build.log"; min_build >>"$W/build.log" 2>&1
  fi
  echo "build done" >>"$W/build.log"
}
build & BPID=$!
QUICK=${QUICK:-0}
if [ "$QUICK" = 1 ]; then
  TPID=""; cp -r tests/fixtures/clip/tiny/. "$W/tiny/"
else
  python3 scripts/clip_reference.py tokenizer --out "$W/tok" >"$W/tok.log" 2>&1 & TPID=$!
  python3 scripts/clip_reference.py tiny --out "$W/tiny" >"$W/tiny.log" 2>&1; el "tiny rc $?"; tail -3 "$W/tiny.log"
fi
python3 scripts/clip_reference.py model --config data/clip/config-vit-base-patch16.json --out "$W/ref" >"$W/ref.log" 2>&1
el "ViT-B/16 reference rc $?"; tail -3 "$W/ref.log"
wait $BPID; el "built"; grep -E "error|failed|done" "$W/build.log" | head -20
SP_CLIP_REF_DIR="$W/ref" ./build-gpu/clip_test_reference 2>&1 | tee "$OUT/parity_vitb16.txt"
SP_CLIP_REF_DIR="$W/tiny" ./build-gpu/clip_test_reference 2>&1 | grep -E "parity|FAIL|failed"
SP_CLIP_REF_DIR="$W/ref" ./build-gpu/clip_test_reference --gpu 2>&1 | tee -a "$OUT/parity_vitb16.txt"
./build-gpu/clip_test_model --gpu 2>&1 | grep -E "GPU|FAIL|failed|SKIP"
el "parity done"
python3 scripts/clip_reference.py bench 2>&1 | grep -v -i warn | tee "$OUT/anchor-clip.jsonl"
el "transformers bench done"
./build-gpu/bench/bench_clip --gpu-only ${BENCH_ARGS:-} --anchor "$OUT/anchor-clip.jsonl" 2>&1 | tee "$OUT/bench_clip.txt"
el "bench done"
[ -n "$TPID" ] && { wait $TPID; el "tokenizer pairs rc $?"; tail -3 "$W/tok.log"; }
for f in "$W"/tok/tokenizer_pairs_all_*.json; do
  echo "== $f"; SP_CLIP_TOKENIZER_PAIRS="$f" ./build-gpu/clip_test_tokenizer 2>&1 | grep -E "differ|checked|mismatch" | head -8
done
rm -f "$W/ref/model.safetensors"
tar -C "$W" -czf "$OUT/results.tgz" ref tiny tok build.log tiny.log ref.log tok.log 2>/dev/null
ls -la "$OUT"; el "all done"
