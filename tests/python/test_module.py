"""The Python module's own promises: safe after close() (ValueError, never a NULL into C), the
library's ABI version and struct sizes checked, error codes mapped to FileNotFoundError /
ValueError subclasses, per-call options that do not leak into the next call, one lock per
instance (threads give the serial answers), per-Gaussian relevancy and heatmaps from any camera.
    test_module.py MODEL_DIR SEMSPLAT_BINARY
"""
import ctypes
import os
import sys
import threading

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import gs_semantic_query as gq  # noqa: E402

import checks  # noqa: E402
from checks import check, raises  # noqa: E402


def test_closed(model):
    q = gq.SemanticSplatQuery(model_path=model, device="cpu")
    q.close()
    q.close()  # twice is fine
    check(q.closed, "closed property")
    for name, fn in [("query", lambda: q.query("table")), ("embed", lambda: q.embed("table")),
                     ("relevancy", lambda: q.relevancy("table")), ("heatmap", lambda: q.heatmap("table", 0)),
                     ("camera", lambda: q.camera(0)), ("n_cameras", lambda: q.n_cameras),
                     ("query_embedding", lambda: q.query_embedding(np.zeros(512, np.float32))),
                     ("gaussian_positions", lambda: q.gaussian_positions()), ("device", lambda: q.device),
                     ("encoder", lambda: q.encoder)]:
        e = raises(ValueError, fn, "after close: " + name)
        check(e is None or "closed" in str(e), "after close: %s says closed: %s" % (name, e))
    with gq.SemanticSplatQuery(model_path=model, device="cpu") as q2:
        check(q2.query("table").found, "context manager works")
    check(q2.closed, "context manager closes")


def test_errors(model):
    e = raises(FileNotFoundError, lambda: gq.SemanticSplatQuery(model_path=os.path.join(model, "nothere")),
               "missing folder")
    check(isinstance(e, gq.SemsplatNotFoundError) and e.code == -8, "SemsplatNotFoundError, code -8: %r" % e)
    with gq.SemanticSplatQuery(model_path=model, device="cpu") as q:
        e = raises(ValueError, lambda: q.query(""), "empty text")
        check(isinstance(e, gq.SemsplatValueError) and e.code == -4, "SemsplatValueError, code -4: %r" % e)
        raises(ValueError, lambda: q.query("table", method="sideways"), "bad method")
        raises(IndexError, lambda: q.query("table", heatmap_view=999), "bad heatmap view")
        raises(ValueError, lambda: q.query_embedding(np.zeros(3, np.float32)), "bad embedding shape")
        raises(IndexError, lambda: q.camera(q.n_cameras), "camera out of range")
    raises(ValueError, lambda: gq.SemanticSplatQuery(model_path=model, device="tpu"), "bad device")
    raises(ValueError, lambda: gq.SemanticSplatQuery(model_path=model, device="cpu", encoder="bert"), "bad encoder")
    e = raises(FileNotFoundError, lambda: gq.SemanticSplatQuery(model_path=model, device="cpu", encoder="lexical",
                                                                wordnet_dir="/nonexistent"), "no WordNet")
    check(e is None or "wordnet" in str(e), "names the missing WordNet: %s" % e)


class FakeLib:
    """A library whose ABI facts can be set, for the load-time checks."""

    def __init__(self, version, sizes):
        self.sp_semantic_abi_version = lambda: version
        self.sp_semantic_abi_sizeof = lambda name: sizes.get(name.decode(), 0)


def test_abi(model):
    lib = gq.load_library()
    check(lib.sp_semantic_abi_version() == gq.ABI_VERSION, "the built library's ABI version")
    for name, struct in gq._STRUCTS.items():
        check(lib.sp_semantic_abi_sizeof(name.encode()) == ctypes.sizeof(struct), "sizeof(%s) agrees" % name)
    good = {n: ctypes.sizeof(s) for n, s in gq._STRUCTS.items()}
    gq._check_abi(FakeLib(gq.ABI_VERSION, good), "fake")  # passes
    e = raises(gq.SemsplatError, lambda: gq._check_abi(FakeLib(gq.ABI_VERSION + 1, good), "fake"), "ABI version")
    check(e is None or "ABI version" in str(e), "names the ABI version: %s" % e)
    bad = dict(good, sp_query_result=good["sp_query_result"] - 8)
    e = raises(gq.SemsplatError, lambda: gq._check_abi(FakeLib(gq.ABI_VERSION, bad), "fake"), "struct size")
    check(e is None or "sp_query_result" in str(e), "names the struct: %s" % e)


def test_per_call_options(model):
    with gq.SemanticSplatQuery(model_path=model, device="cpu", method="3d") as q:
        a = q.query("table", method="multiview")
        b = q.query("table")
        check(a.method == "multiview" and b.method == "3d", "a call's method does not stick: %s %s" % (a.method, b.method))
        d0 = q.query("lamp")
        c = q.query("lamp", heatmap_view=(d0.view_index + 1) % q.n_cameras)
        d = q.query("lamp")
        check(c.view_index == (d0.view_index + 1) % q.n_cameras and d.view_index == d0.view_index,
              "heatmap_view of one call: %s, then %s (default %s)" % (c.view_index, d.view_index, d0.view_index))
        e = q.query("lamp", heatmap=False)
        check(e.relevancy_image is None and q.query("lamp").relevancy_image is not None, "heatmap=False for one call")


def test_threads(model):
    with gq.SemanticSplatQuery(model_path=model, device="cpu", threads=2) as q:
        texts = ["table", "chair", "lamp", "refrigerator"]
        serial = {(t, m): q.query(t, method=m).to_dict() for t in texts for m in ("3d", "multiview")}
        out, errors = {}, []

        def worker(k):
            try:
                for rep in range(3):
                    for t in texts:
                        m = ("3d", "multiview")[(k + rep) % 2]
                        out[(k, rep, t, m)] = q.query(t, method=m).to_dict()
            except Exception as e:  # noqa: BLE001
                errors.append(e)

        th = [threading.Thread(target=worker, args=(k,)) for k in range(4)]
        for t in th:
            t.start()
        for t in th:
            t.join()
        check(not errors, "threads raised %r" % errors)
        for (k, rep, t, m), d in out.items():
            s = serial[(t, m)]
            same = d["found"] == s["found"] and d["confidence"] == s["confidence"] and \
                len(d["instances"]) == len(s["instances"]) and d["position"] == s["position"]
            check(same, "thread %d %s/%s differs from the serial answer" % (k, t, m))


def test_relevancy_and_heatmap(model):
    with gq.SemanticSplatQuery(model_path=model, device="cpu") as q:
        n = q.n_gaussians
        rel, raw = q.relevancy("table", raw=True)
        pos = q.gaussian_positions()
        check(rel.shape == (n,) and raw.shape == (n,) and pos.shape == (n, 3), "shapes %s %s %s" % (rel.shape, raw.shape, pos.shape))
        check(np.all((rel >= 0) & (rel <= 1)) and np.all((raw >= -1.0001) & (raw <= 1.0001)), "ranges")
        r = q.query("table")
        hot = pos[rel > 0.9]
        check(len(hot) > 10 and np.linalg.norm(hot.mean(axis=0) - r.position) < 0.3,
              "relevant Gaussians sit around the found table: %s vs %s" % (hot.mean(axis=0) if len(hot) else None, r.position))
        # the heatmap from the result's own camera equals the query's heatmap
        rgb, hrel = q.heatmap("table", r.view_index)
        check(rgb.shape == r.relevancy_image.shape and np.array_equal(rgb, r.relevancy_image),
              "heatmap(view) == the query's heatmap image")
        check(np.allclose(hrel, r.relevancy), "heatmap relevancy == the query's")
        # any camera: the same view at half resolution, through a Camera built in Python
        cam = q.camera(r.view_index)
        half = gq.Camera(cam.width // 2, cam.height // 2, cam.fx / 2, cam.fy / 2, cam.cx / 2, cam.cy / 2, cam.R, cam.t)
        rgb2, rel2 = q.heatmap("table", half)
        check(rgb2.shape == (cam.height // 2, cam.width // 2, 3) and rel2.max() > 0.9, "a Camera made in Python")
        raises(ValueError, lambda: q.heatmap("table", gq.Camera(0, 10, 1, 1, 0, 0, np.eye(3), [0, 0, 0])), "empty camera")


def main():
    model = sys.argv[1]
    for t in (test_abi, test_closed, test_errors, test_per_call_options, test_threads, test_relevancy_and_heatmap):
        before = checks.failures
        t(model)
        print("%s %s" % ("ok  " if checks.failures == before else "FAIL", t.__name__), file=sys.stderr)
    print("python module: %d failures" % checks.failures)
    return 1 if checks.failures else 0


if __name__ == "__main__":
    sys.exit(main())
