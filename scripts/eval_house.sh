#!/usr/bin/env bash
# End-to-end evaluation of the semantic query engine on the synthetic house at evaluation settings:
#   synth -> train -> features --source labels -> lift -> every ground-truth class queried with
# both localization methods, scored by the eval module (the same code as `semsplat demo`):
# instances matched one-to-one to objects, recall, precision, mean/median error, misses counted.
# Steps whose output exists are reused (delete OUT to redo).
#
#   scripts/eval_house.sh [OUT]        (default OUT = build/eval-house)
# Environment: BUILD (build dir, default build), VIEWS (150), SIZE (640x480), STEPS (train steps,
# 3000), DEPTH_LAMBDA (depth supervision, 0.5; 0 = RGB only), DOWNSCALE (train downscale, 2), DEVICE (auto|cpu|cuda), THREADS, RADIUS (match radius in
# metres, 0.5), WORLD / MODEL_PATH (another world, e.g. the bookstore), MODEL (use this trained
# model folder instead of training; its splat.ply and train.json are copied into OUT/model).
# Writes OUT/demo.json and OUT/report.md (and heatmaps/).
set -euo pipefail
SRC="$(cd "$(dirname "$0")/.." && pwd)"
OUT="${1:-$SRC/build/eval-house}"
BUILD="${BUILD:-$SRC/build}"
SEMSPLAT="$BUILD/semsplat"
[ -x "$SEMSPLAT" ] || { echo "eval_house: $SEMSPLAT not built (set BUILD)" >&2; exit 2; }
mkdir -p "$OUT"
if [ -n "${MODEL:-}" ] && [ ! -f "$OUT/model/splat.ply" ]; then
  mkdir -p "$OUT/model" && cp "$MODEL/splat.ply" "$MODEL/train.json" "$OUT/model/"
fi
args=(demo --out "$OUT" --reuse --depth-lambda "${DEPTH_LAMBDA:-0.5}" --views "${VIEWS:-150}" --size "${SIZE:-640x480}" --steps "${STEPS:-3000}"
      --downscale "${DOWNSCALE:-2}" --device "${DEVICE:-auto}" --threads "${THREADS:-0}"
      --match-radius "${RADIUS:-0.5}")
[ -n "${WORLD:-}" ] && args+=(--world "$WORLD")
[ -n "${MODEL_PATH:-}" ] && args+=(--model-path "$MODEL_PATH" --skip-missing)
exec "$SEMSPLAT" "${args[@]}"
