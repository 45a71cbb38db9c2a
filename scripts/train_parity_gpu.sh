#!/bin/bash
# Training parity (issue 23) on the GPU machine, in ONE device call: renders the house and
# bookstore walk captures (150 views, 640x480), builds gsplat from shared/bench/anchors and trains
# gsplat's recipe (scripts/gsplat_reference.py) and ours (`semsplat train --steps 7000 --device
# cuda`) on both, printing held-out PSNR, Gaussians and seconds per run.
#   here:  scripts/pack_gpu_runtime.sh build   (semsplat with synth, built with CUDA, into .gl/rt.txz)
#          tar -cf - .gpu-shared | xz > .gl/gs.txz   (.gpu-shared/anchors: a copy of shared/bench/anchors)
#   there: scripts/train_parity_gpu.sh [-- EXTRA TRAIN FLAGS]   (carry .gl/rt.txz and .gl/gs.txz)
# A time guard (LIM seconds, default 560) skips runs that would outlast one device call.
set -u
cd "$(dirname "$0")/.."
T0=$(date +%s); el() { echo $(( $(date +%s) - T0 )); }
LIM=${LIM:-560}
[ "${1:-}" = "--" ] && shift
EXTRA=("$@")
nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv,noheader
tar -C /tmp -xJf .gl/rt.txz && export LD_LIBRARY_PATH=/tmp/rt/lib || exit 1
S=/tmp/rt/bin/semsplat
ldd $S | grep 'not found' && exit 1
tar -xJf .gl/gs.txz && A=$PWD/.gpu-shared/anchors/vendor || exit 1
( cd "$A/gsplat" && PATH="$A/bin:$PATH" MAX_JOBS=12 TORCH_CUDA_ARCH_LIST=9.0 \
    python3 setup.py build_ext --inplace > /tmp/gsplat-build.log 2>&1; echo "gsplat built (rc $?) at $(el) s" ) &
gb=$!
$S synth --world data/worlds/bookstore/worlds/bookstore.world --model-path data/worlds/bookstore/models \
  --out /tmp/book --views 150 --size 640x480 --walk-only --skip-missing --threads 8 --quiet &
$S synth --world data/worlds/house.world --out /tmp/house --views 150 --size 640x480 --walk-only \
  --threads 8 --quiet &
wait %2 %3
echo "captures at $(el) s: $(ls /tmp/book/images | wc -l) + $(ls /tmp/house/images | wc -l) views"
wait $gb
python3 -c "import rich" 2>/dev/null || export PYTHONPATH="$A/shim"
export PYTHONPATH="$A/gsplat${PYTHONPATH:+:$PYTHONPATH}"
gs() { # capture tag estimated-seconds
  [ $(( $(el) + $3 )) -lt "$LIM" ] || { echo "SKIP gsplat $2 (at $(el) s)"; return; }
  echo "== gsplat $2 at $(el) s"
  python3 scripts/gsplat_reference.py "$1" --steps 7000 2>&1 | grep '"gsplat_train"'
}
ours() { # capture tag estimated-seconds [flags]
  local c=$1 t=$2 e=$3; shift 3
  [ $(( $(el) + e )) -lt "$LIM" ] || { echo "SKIP ours $t (at $(el) s)"; return; }
  echo "== ours $t ($*) at $(el) s"
  $S train --colmap "$c" --out "/tmp/m_$t" --steps 7000 --device cuda --quiet "$@" > "/tmp/tr_$t.log" 2>&1 ||
    { tail -5 "/tmp/tr_$t.log"; return; }
  python3 -c "import json; d=json.load(open('/tmp/m_$t/train.json')); print('ours $t', {k: d.get(k) for k in ('psnr', 'gaussians', 'seconds')})"
}
gs /tmp/book book 60
ours /tmp/book book 40 "${EXTRA[@]}"
gs /tmp/house house 55
ours /tmp/house house 30 "${EXTRA[@]}"
echo "total $(el) s"
