#!/usr/bin/env bash
# End-to-end evaluation of the semantic query engine on the synthetic house (issue 6):
#   synth -> train -> features --source labels -> lift -> query every ground-truth class
# with both localization methods, then per-object errors against ground_truth.json, absent
# classes, timings and heatmap PNGs. Steps whose output exists are reused (delete OUT to redo).
#
#   scripts/eval_house.sh [OUT]        (default OUT = build/eval-house)
# Environment: BUILD (build dir, default build), VIEWS (150), SIZE (640x480), STEPS (train steps,
# 3000), DOWNSCALE (train downscale, 2), DEVICE (auto|cpu|cuda for train/lift/query), THREADS,
# MODEL (use this trained model folder instead of training; it is copied into OUT/model).
set -euo pipefail
SRC="$(cd "$(dirname "$0")/.." && pwd)"
OUT="${1:-$SRC/build/eval-house}"
BUILD="${BUILD:-$SRC/build}"
VIEWS="${VIEWS:-150}"
SIZE="${SIZE:-640x480}"
STEPS="${STEPS:-3000}"
DOWNSCALE="${DOWNSCALE:-2}"
DEVICE="${DEVICE:-auto}"
THREADS="${THREADS:-0}"
SEMSPLAT="$BUILD/semsplat"
[ -x "$SEMSPLAT" ] || { echo "eval_house: $SEMSPLAT not built (set BUILD)" >&2; exit 2; }
mkdir -p "$OUT"
log() { echo "[eval_house] $*" >&2; }

if [ ! -f "$OUT/capture/ground_truth.json" ]; then
  log "synth: $VIEWS views at $SIZE"
  "$SEMSPLAT" synth --world "$SRC/data/worlds/house.world" --out "$OUT/capture" --views "$VIEWS" --size "$SIZE"
fi
if [ -n "${MODEL:-}" ] && [ ! -f "$OUT/model/splat.ply" ]; then
  mkdir -p "$OUT/model" && cp "$MODEL/splat.ply" "$MODEL/train.json" "$OUT/model/"
fi
if [ ! -f "$OUT/model/splat.ply" ]; then
  log "train: $STEPS steps, downscale $DOWNSCALE, device $DEVICE"
  "$SEMSPLAT" train --colmap "$OUT/capture" --out "$OUT/model" --steps "$STEPS" --downscale "$DOWNSCALE" \
    --device "$DEVICE" --threads "$THREADS"
fi
if [ ! -f "$OUT/features/features.json" ]; then
  log "features: labels"
  "$SEMSPLAT" features --colmap "$OUT/capture" --source labels --out "$OUT/features"
fi
log "lift"
"$SEMSPLAT" lift --model "$OUT/model" --features "$OUT/features" --colmap "$OUT/capture" --device "$DEVICE" \
  --threads "$THREADS" | tee "$OUT/lift.txt"

log "queries"
SRC="$SRC" SEMSPLAT_LIB="$BUILD" OUT="$OUT" DEVICE="$DEVICE" THREADS="$THREADS" /usr/bin/python3 - <<'PY'
import json, os, sys, time
import numpy as np
sys.path.insert(0, os.path.join(os.environ["SRC"], "python"))
import gs_semantic_query as gq

out = os.environ["OUT"]
gt = json.load(open(os.path.join(out, "capture", "ground_truth.json")))
objs = gt["objects"]
classes = sorted(set(o["class"] for o in objs))
absent = ["piano", "bathtub", "car", "toilet", "washing machine", "fire hydrant"]
dev = os.environ.get("DEVICE", "auto")
q = gq.SemanticSplatQuery(model_path=os.path.join(out, "model"), device=dev, threads=int(os.environ.get("THREADS", "0")))
print("device: %s, cameras: %d" % (q.device, q.n_cameras))

def box_dist(p, o):
    lo, hi = np.array(o["aabb_min"]), np.array(o["aabb_max"])
    return float(np.linalg.norm(np.maximum(0, np.maximum(lo - p, p - hi))))

report = {"classes": {}, "absent": {}, "methods": {}}
for method in ("3d", "multiview"):
    hm_dir = os.path.join(out, "heatmaps", method)
    os.makedirs(hm_dir, exist_ok=True)
    per_obj, found, lat, qerr = [], 0, [], []
    print("\n== %s ==" % method)
    print("%-18s %-6s %5s %5s  %-26s %s" % ("class", "found", "conf", "inst", "position", "per-object error to AABB centre (m) [distance to box]"))
    for c in classes:
        r = q.query(c, method=method)
        lat.append(r.timings_ms["total"] - r.timings_ms["heatmap"])
        if r.relevancy_image is not None:
            r.save_heatmap(os.path.join(hm_dir, c.replace(" ", "_") + ".png"))
        gts = [o for o in objs if o["class"] == c]
        found += r.found
        errs = []
        for o in gts:
            ctr = np.array(o["aabb_center"])
            cands = [i["position"] for i in r.instances] if r.found else []
            if not cands:
                errs.append((o["name"], None, None))
                continue
            d = [float(np.linalg.norm(p - ctr)) for p in cands]
            k = int(np.argmin(d))
            errs.append((o["name"], d[k], box_dist(cands[k], o)))
        per_obj += [e for e in errs]
        if r.found:  # the answer a robot would drive to: the best instance vs the nearest object
            qerr.append(min(float(np.linalg.norm(r.position - np.array(o["aabb_center"]))) for o in gts))
        pos = "-" if r.position is None else "(%.2f %.2f %.2f)" % tuple(r.position)
        print("%-18s %-6s %5.3f %5d  %-26s %s" % (c, "yes" if r.found else "NO", r.confidence, len(r.instances), pos,
              ", ".join("%s %s" % (n, "miss" if e is None else "%.3f [%.3f]" % (e, b)) for n, e, b in errs)))
        report["classes"].setdefault(c, {})[method] = {"found": r.found, "confidence": r.confidence,
            "position": None if r.position is None else r.position.tolist(), "instances": len(r.instances),
            "errors": {n: e for n, e, b in errs}}
    errs = [e for _, e, _ in per_obj if e is not None]
    miss = sum(1 for _, e, _ in per_obj if e is None)
    mean = float(np.mean(errs)) if errs else float("nan")
    print("%s: %d/%d classes found; per object (nearest instance): %d objects, %d missed, mean error %.3f m, "
          "median %.3f m, max %.3f m" % (method, found, len(classes), len(per_obj), miss, mean,
          float(np.median(errs)) if errs else float("nan"), max(errs) if errs else float("nan")))
    print("%s: per query (returned position vs nearest object of the class): mean error %.3f m, median %.3f m, "
          "max %.3f m; mean query latency %.1f ms (no heatmap)" % (method, float(np.mean(qerr)),
          float(np.median(qerr)), max(qerr), float(np.mean(lat))))
    report["methods"][method] = {"classes_found": found, "classes": len(classes), "objects": len(per_obj),
                                 "missed": miss, "mean_error_m": mean, "mean_query_error_m": float(np.mean(qerr)),
                                 "latency_ms": float(np.mean(lat))}
    for a in absent:
        r = q.query(a, method=method)
        report["absent"].setdefault(a, {})[method] = {"found": r.found, "confidence": r.confidence}
    print("absent: " + ", ".join("%s %s %.3f" % (a, "FOUND" if report["absent"][a][method]["found"] else "none",
                                                 report["absent"][a][method]["confidence"]) for a in absent))
json.dump(report, open(os.path.join(out, "eval_house.json"), "w"), indent=1)
print("\nwrote %s and heatmaps under %s/heatmaps/" % (os.path.join(out, "eval_house.json"), out))
PY
