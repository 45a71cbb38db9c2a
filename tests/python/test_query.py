"""The Python module against the CLI: the same model folder and query must give the same answer
(found, position, confidence, instances, view, source, frame) through gs_semantic_query and
`semsplat query --json`, and positions come out in the folder's frame (frame.json moves the model
into a world frame; expect.json says where the table must be). Run by tests/semantic/test_python.c
with a model folder it builds:
    test_query.py MODEL_DIR SEMSPLAT_BINARY
"""
import json
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import gs_semantic_query as gq  # noqa: E402

import checks  # noqa: E402
from checks import check  # noqa: E402


def cli(binary, model, text, method, *extra):
    out = subprocess.run([binary, "query", "--model", model, "--json", "--device", "cpu", "--method", method,
                          "--heatmap", os.path.join(model, "cli_heatmap.png")] + list(extra) + [text],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def close(a, b, tol=1e-5):
    return a is not None and b is not None and np.allclose(np.asarray(a, float), np.asarray(b, float), atol=tol)


EXPECT_SOURCE = {"encoder": "lexical", "features": "labels", "ground_truth": True}
EXPECT_FRAME = {"name": "world", "source": "align", "units": "m", "up": "+z"}


def check_provenance(r, j, tag):
    """Source and frame: named, the same through Python and the CLI, with the label caveat."""
    for k, v in EXPECT_SOURCE.items():
        check(r.source[k] == v and j["source"][k] == v, tag + ": source %s = %r / CLI %r" % (k, r.source[k], j["source"][k]))
    check(r.source["note"] == j["source"]["note"] and "perfect 2D segmentation" in (r.source["note"] or ""),
          tag + ": source note %r" % r.source["note"])
    check(r.frame == EXPECT_FRAME and j["frame"] == EXPECT_FRAME, tag + ": frame %r / CLI %r" % (r.frame, j["frame"]))
    check(r.to_dict()["source"] == r.source and r.to_dict()["frame"] == r.frame, tag + ": to_dict carries both")


def check_understanding(r, j, tag):
    """What the encoder understood: the same matches and explanation through Python and the CLI."""
    check(r.encoder == j["encoder"] == r.source["encoder"], tag + ": encoder %s / CLI %s" % (r.encoder, j["encoder"]))
    check(abs(r.threshold - j["threshold"]) < 1e-6, tag + ": threshold")
    check([(m["class"], m["kind"], m["role"]) for m in r.matches] ==
          [(m["class"], m["kind"], m["role"]) for m in j["matches"]], tag + ": matches %s / CLI %s" % (r.matches, j["matches"]))
    check(r.explanation == j["explanation"], tag + ": explanation")
    check([i["class"] for i in r.instances] == [i["class"] for i in j["instances"]], tag + ": instance classes")
    d = r.to_dict()
    check(d["matches"] == r.matches and d["explanation"] == r.explanation and d["encoder"] == r.encoder,
          tag + ": to_dict carries the matches")


def main():
    model, binary = sys.argv[1], sys.argv[2]
    table_world = np.array(json.load(open(os.path.join(model, "expect.json")))["table_world"])
    q = gq.SemanticSplatQuery(model_path=model, device="cpu")
    check(q.n_cameras > 0, "cameras loaded")
    for method in ("3d", "multiview"):
        for text in ("table", "chair", "lamp", "refrigerator"):
            r = q.query(text, method=method)
            j = cli(binary, model, text, method)
            tag = "%s/%s" % (text, method)
            check_provenance(r, j, tag)
            check_understanding(r, j, tag)
            check(r.method == method and j["method"] == method, tag + ": method of this call")
            check(r.found == j["found"], tag + ": found %s vs CLI %s" % (r.found, j["found"]))
            check(abs(r.confidence - j["confidence"]) < 1e-6, tag + ": confidence")
            check(len(r.instances) == len(j["instances"]), tag + ": instance count")
            for a, b in zip(r.instances, j["instances"]):
                check(close(a["position"], b["position"]), tag + ": instance position")
                check(a["points"] == b["points"], tag + ": instance points")
            if j["found"]:
                check(isinstance(r.position, np.ndarray) and r.position.shape == (3,), tag + ": position array")
                check(close(r.position, j["position"]), tag + ": position %s vs CLI %s" % (r.position, j["position"]))
                check(j["view"] is not None and r.view_index == j["view"]["index"], tag + ": view")
            else:
                check(r.position is None and j["position"] is None, tag + ": absent has no position")
                check(r.confidence < r.threshold, tag + ": absent confidence %.3f" % r.confidence)
            img = r.relevancy_image
            check(isinstance(img, np.ndarray) and img.dtype == np.uint8 and img.ndim == 3 and img.shape[2] == 3,
                  tag + ": relevancy_image H x W x 3 uint8")
            check(isinstance(r.confidence, float), tag + ": confidence is a float")
            check(j["heatmap"] is not None and os.path.exists(j["heatmap"]), tag + ": CLI heatmap written")
    # lexical: a synonym and a hypernym find what the exact names find, and say why
    r = q.query("desk")
    check(r.found and r.instances[0]["class"] == "table" and r.matches[0]["class"] == "table",
          "desk -> the table: %s" % r.matches[:1])
    check("table" in (r.explanation or "") and r.threshold == 0.5, "desk: explained")
    r = q.query("a red seat")
    check(r.found and r.instances[0]["class"] == "chair" and r.ignored == ["red"], "a red seat -> chair, red ignored: %s %s"
          % (r.matches[:1], r.ignored))
    # exact stays reachable (tests, comparisons): only exact names, the same positions
    with gq.SemanticSplatQuery(model_path=model, device="cpu", encoder="exact") as qe:
        check(qe.encoder == "exact", "encoder='exact' override: %s" % qe.encoder)
        for text in ("table", "lamp"):
            a, b = q.query(text), qe.query(text)
            check(b.encoder == "exact" and close(a.position, b.position, 1e-6), "%s: lexical and exact agree" % text)
            j = cli(binary, model, text, "3d", "--encoder", "exact")
            check(j["encoder"] == "exact" and close(j["position"], b.position), "%s: CLI --encoder exact" % text)
        check(not qe.query("desk").found, "exact: 'desk' is no class name")
    check(q.encoder == "lexical", "the folder's encoder: %s" % q.encoder)
    # the table in the world frame of frame.json (both methods: splat and cameras moved alike)
    for method in ("3d", "multiview"):
        r = q.query("table", method=method)
        check(r.found and np.linalg.norm(r.position - table_world) < (0.1 if method == "3d" else 0.25),
              "table/%s at %s, world truth %s" % (method, r.position, table_world))
    # chairs: two instances; the embedding path gives the same answer as text
    r = q.query("chair")
    check(len(r.instances) == 2, "two chairs")
    r2 = q.query_embedding(q.embed("chair"), label="chair")
    check(close(r.position, r2.position, 1e-6), "embedding query equals text query")
    path = os.path.join(model, "py_heatmap.png")
    r.save_heatmap(path)
    check(os.path.getsize(path) > 100, "save_heatmap wrote a PNG")
    try:
        gq.SemanticSplatQuery(model_path=os.path.join(model, "missing"))
        check(False, "opening a missing folder raises")
    except FileNotFoundError as e:
        check(isinstance(e, gq.SemsplatError) and "semantic.json" in str(e), "error names semantic.json: %s" % e)
    q.close()
    print("python: %d failures" % checks.failures)
    return 1 if checks.failures else 0


if __name__ == "__main__":
    sys.exit(main())
