"""The CLIP query path end to end: a capture's features from the tiny CLIP fixture (`semsplat
features --source clip`), lifted into a briefly trained splat, queried through `semsplat query
--json` and through the Python module. Run by tests/synth/test_clip_path.c:
    test_clip_path.py MODEL_DIR FEATURES_DIR SEMSPLAT_BINARY
The tiny CLIP has random weights: this checks that the path runs, its shapes and what it records,
not that "a chair" finds a chair.
"""
import json
import math
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import gs_semantic_query as gq  # noqa: E402

import checks  # noqa: E402
from checks import check  # noqa: E402


def vec3(v):
    return v is not None and np.asarray(v).shape == (3,) and np.all(np.isfinite(np.asarray(v, float)))


def main():
    model, features, binary = sys.argv[1], sys.argv[2], sys.argv[3]
    with open(os.path.join(model, "semantic.json")) as f:
        sem = json.load(f)
    with open(os.path.join(features, "features.json")) as f:
        feat = json.load(f)
    # What produced the features is recorded in both folders.
    check(sem["source"] == "clip" and feat["source"] == "clip", "source clip recorded: %s / %s"
          % (sem["source"], feat["source"]))
    check(sem["model"].endswith("tiny/model.safetensors"), "CLIP weights recorded: %s" % sem["model"])
    check(feat["full_dim"] == 32 and feat["dim"] == 16, "tiny CLIP dims 32 -> PCA 16")
    text = "a chair"
    out = subprocess.run([binary, "query", "--model", model, "--json", "--device", "cpu", text],
                         check=True, capture_output=True, text=True).stdout
    j = json.loads(out)
    with gq.SemanticSplatQuery(model_path=model, device="cpu") as q:
        check(q.n_cameras > 0, "cameras loaded")
        e = q.embed(text)
        check(e.shape == (32,) and abs(float(np.linalg.norm(e)) - 1.0) < 1e-4, "text embedding: 32-D unit")
        r = q.query(text)
        check(math.isfinite(r.confidence) and -1.0 <= r.confidence <= 1.0, "confidence is a cosine")
        check(r.found == j["found"], "found: Python %s, CLI %s" % (r.found, j["found"]))
        check(abs(r.confidence - j["confidence"]) < 1e-6, "confidence: Python and CLI agree")
        check((r.position is None) == (j["position"] is None), "position present in both or neither")
        if r.found:
            check(vec3(r.position) and np.allclose(r.position, j["position"], atol=1e-5), "position (3,)")
        check(len(r.instances) == len(j["instances"]), "instance count")
        for a in r.instances:
            check(vec3(a["position"]) and vec3(a["extent_min"]) and vec3(a["extent_max"]), "instance shapes")
        cam_w, cam_h = 64, 48
        check(r.relevancy_image is not None and r.relevancy_image.shape == (cam_h, cam_w, 3)
              and r.relevancy_image.dtype == np.uint8, "heatmap overlay (48, 64, 3) uint8")
        check(r.relevancy is not None and r.relevancy.shape == (cam_h, cam_w), "relevancy (48, 64)")
        check(r.timings_ms["embed"] > 0 and r.timings_ms["total"] >= r.timings_ms["embed"], "timings")
        # what produced it, and where: CLIP text and features, no label caveat, the synth world
        want = {"encoder": "clip", "features": "clip", "ground_truth": False, "note": None}
        check(r.source == want and j["source"] == want, "source: Python %s, CLI %s" % (r.source, j["source"]))
        check(r.frame["name"] == "world" and r.frame == j["frame"], "frame: Python %s, CLI %s" % (r.frame, j["frame"]))
        # the encoder that answered is named at the top of the result too, with what it understood
        check(sem["encoder"] == "clip", "semantic.json records encoder clip: %s" % sem.get("encoder"))
        check(q.encoder == "clip" and r.encoder == "clip" and j["encoder"] == "clip",
              "encoder: engine %s, Python %s, CLI %s" % (q.encoder, r.encoder, j["encoder"]))
        check(r.matches == [] and j["matches"] == [], "clip matches no class list")
        check(abs(r.threshold - 0.2) < 1e-6 and abs(j["threshold"] - 0.2) < 1e-6, "clip threshold = min_confidence")
        check(r.explanation is not None and "CLIP" in r.explanation and r.explanation == j["explanation"],
              "clip explanation: %r" % r.explanation)
    # a CLIP folder refuses the encoders of hashed labels, naming why
    p = subprocess.run([binary, "query", "--model", model, "--device", "cpu", "--encoder", "lexical", text],
                       capture_output=True, text=True)
    check(p.returncode == 1 and "does not fit its features" in p.stderr, "query --encoder lexical on CLIP "
          "features: exit %d, %s" % (p.returncode, p.stderr.strip()))
    try:
        gq.SemanticSplatQuery(model_path=model, device="cpu", encoder="exact")
        check(False, "encoder='exact' on CLIP features raises")
    except ValueError as e:
        check("does not fit" in str(e), "Python names why: %s" % e)
    print("clip path: found %s, confidence %.3f, %d instances (random tiny weights)"
          % (r.found, r.confidence, len(r.instances)))
    return 1 if checks.failures else 0


if __name__ == "__main__":
    sys.exit(main())
