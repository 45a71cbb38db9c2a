#!/bin/bash
# Training parity (issue 23) on the GPU machine, in ONE device call: renders walk captures (150
# views, 640x480) of the house and the bookstore (and of any world PLAN names: office, ward, ...
# from data/worlds/), builds gsplat from shared/bench/anchors and trains gsplat's recipe
# (scripts/gsplat_reference.py) and ours (`semsplat train --steps 7000 --device cuda`) on them,
# printing held-out PSNR, Gaussians and seconds per run.
#   here:  cmake -S . -B build-rt -DCMAKE_BUILD_TYPE=Release -DSP_ROUND2_DEPS=OFF &&
#          cmake --build build-rt --target semsplat_cli && scripts/pack_gpu_runtime.sh build-rt
#          (semsplat with synth and CUDA, without the round-2 media/ROS libraries: 7.7 MB)
#          tar -cf - .gpu-shared | xz > .gl/gs.txz   (.gpu-shared/anchors: a copy of shared/bench/anchors)
#   there: scripts/train_parity_gpu.sh [-- EXTRA TRAIN FLAGS]   (carry .gl/rt.txz and .gl/gs.txz)
# PLAN (optional): runs in order, separated by ';': "gs WORLD" (gsplat's recipe) or
# "ours WORLD TAG [FLAGS...]"; default: gsplat and ours (with the EXTRA flags) on the bookstore,
# then on the house. A time guard (LIM seconds, default 560) skips runs that would outlast one
# device call.
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
DEFAULT_PLAN="gs book; ours book book ${EXTRA[*]}; gs house; ours house house ${EXTRA[*]}"
PLAN=${PLAN:-$DEFAULT_PLAN}
gb=
if echo "$PLAN" | grep -qE '(^|;) *gs '; then # gsplat is built only when a run needs it
  ( cd "$A/gsplat" && PATH="$A/bin:$PATH" MAX_JOBS=12 TORCH_CUDA_ARCH_LIST=9.0 \
      python3 setup.py build_ext --inplace > /tmp/gsplat-build.log 2>&1; echo "gsplat built (rc $?) at $(el) s" ) &
  gb=$!
fi
worlds=$(echo "$PLAN" | tr ';' '\n' | awk 'NF >= 2 {print $2}' | sort -u)
sp=()
for w in $worlds; do
  src=(--world "data/worlds/$w.world") # "book": the bookstore, its models beside it, two missing
  [ "$w" = book ] && src=(--world data/worlds/bookstore/worlds/bookstore.world
                          --model-path data/worlds/bookstore/models --skip-missing)
  $S synth "${src[@]}" --out "/tmp/$w" --views 150 --size 640x480 --walk-only --threads 8 --quiet &
  sp+=($!)
done
wait "${sp[@]}"
for w in $worlds; do echo "capture $w at $(el) s: $(ls /tmp/$w/images 2>/dev/null | wc -l) views"; done
[ -n "$gb" ] && wait $gb
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
  python3 -c "import json; d=json.load(open('/tmp/m_$t/train.json')); print('ours $t', {k: d.get(k) for k in ('psnr', 'gaussians', 'seconds', 'seconds_steps')})"
}
est() { case $1 in gs) echo 60 ;; *) echo 45 ;; esac; }
IFS=';' read -ra runs <<< "$PLAN"
for r in "${runs[@]}"; do
  read -ra a <<< "$r"
  [ ${#a[@]} -ge 2 ] || continue
  case ${a[0]} in
    gs) gs "/tmp/${a[1]}" "${a[1]}" "$(est gs)" ;;
    ours) ours "/tmp/${a[1]}" "${a[2]:-${a[1]}}" "$(est ours)" "${a[@]:3}" ;;
    *) echo "PLAN: unknown run '${a[0]}' (gs or ours)" ;;
  esac
done
echo "total $(el) s"
