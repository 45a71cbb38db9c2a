"""gs_semantic_query: the Python face of semsplat's query engine (ctypes over libsemsplat.so).

    from gs_semantic_query import SemanticSplatQuery
    q = SemanticSplatQuery(model_path="out/house_model")
    r = q.query("refrigerator")
    r.position          # np.array([x, y, z]) in the world frame, or None when not found
    r.confidence        # largest raw cosine (above ~0.25 a match, below ~0.15 noise)
    r.relevancy_image   # np.ndarray (H, W, 3) uint8: turbo relevancy over the rendered view
    r.instances         # [{"position": np.array, "extent_min", "extent_max", "score", ...}]

The library is found through $SEMSPLAT_LIB (the .so itself or its folder), else ../build/ (and
../build-*/) next to this file. Needs numpy (Debian: python3-numpy). The model folder is what
`semsplat train` made, with the semantic field added by `semsplat lift` or `semsplat distill`.
"""
import ctypes
import ctypes.util
import glob
import json
import os

import numpy as np

__all__ = ["SemanticSplatQuery", "QueryResult", "SemsplatError", "load_library"]


class SemsplatError(RuntimeError):
    """A semsplat call failed; the message names the file, field or value at fault."""


class _Error(ctypes.Structure):
    _fields_ = [("code", ctypes.c_int), ("msg", ctypes.c_char * 1024)]


class _Opts(ctypes.Structure):  # sp_query_opts (include/semsplat/semantic.h)
    _fields_ = [
        ("method", ctypes.c_int),
        ("negatives", ctypes.c_char * 256),
        ("temperature", ctypes.c_float),
        ("min_confidence", ctypes.c_float),
        ("keep_fraction", ctypes.c_float),
        ("min_relevancy", ctypes.c_float),
        ("min_opacity", ctypes.c_float),
        ("voxel_m", ctypes.c_float),
        ("min_instance_fraction", ctypes.c_float),
        ("n_views", ctypes.c_int),
        ("render_downscale", ctypes.c_int),
        ("heatmap", ctypes.c_int),
        ("heatmap_view", ctypes.c_int),
    ]


class _Instance(ctypes.Structure):  # sp_query_instance
    _fields_ = [
        ("position", ctypes.c_float * 3),
        ("extent_min", ctypes.c_float * 3),
        ("extent_max", ctypes.c_float * 3),
        ("score", ctypes.c_float),
        ("confidence", ctypes.c_float),
        ("n_points", ctypes.c_int),
    ]


class _Result(ctypes.Structure):  # sp_query_result
    _fields_ = [
        ("text", ctypes.c_char * 256),
        ("method", ctypes.c_int),
        ("valid", ctypes.c_int),
        ("position", ctypes.c_float * 3),
        ("confidence", ctypes.c_float),
        ("relevancy_max", ctypes.c_float),
        ("view_index", ctypes.c_int),
        ("view_name", ctypes.c_char * 256),
        ("width", ctypes.c_int),
        ("height", ctypes.c_int),
        ("relevancy_image", ctypes.POINTER(ctypes.c_uint8)),
        ("relevancy", ctypes.POINTER(ctypes.c_float)),
        ("n_instances", ctypes.c_int),
        ("instances", ctypes.POINTER(_Instance)),
        ("ms_embed", ctypes.c_double),
        ("ms_relevancy", ctypes.c_double),
        ("ms_localize", ctypes.c_double),
        ("ms_heatmap", ctypes.c_double),
        ("ms_total", ctypes.c_double),
    ]


class _Image(ctypes.Structure):  # sp_image (include/semsplat/io.h)
    _fields_ = [("width", ctypes.c_int), ("height", ctypes.c_int), ("channels", ctypes.c_int),
                ("bit_depth", ctypes.c_int), ("data", ctypes.c_void_p)]


_METHODS = {"3d": 0, "multiview": 1, "multi-view": 1}
_DEVICES = {"cpu": 0, "cuda": 1, "auto": 2}
_lib = None


def _candidates():
    env = os.environ.get("SEMSPLAT_LIB")
    if env:
        yield os.path.join(env, "libsemsplat.so") if os.path.isdir(env) else env
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(here)
    yield os.path.join(root, "build", "libsemsplat.so")
    for p in sorted(glob.glob(os.path.join(root, "build-*", "libsemsplat.so"))):
        yield p
    found = ctypes.util.find_library("semsplat")
    if found:
        yield found


def load_library():
    """Loads libsemsplat once and declares the functions this module calls."""
    global _lib
    if _lib is not None:
        return _lib
    tried = []
    for path in _candidates():
        tried.append(path)
        if path and (os.path.exists(path) or not os.path.dirname(path)):
            try:
                lib = ctypes.CDLL(path)
                break
            except OSError:
                continue
    else:
        raise SemsplatError("libsemsplat.so not found (tried %s); build it or set SEMSPLAT_LIB"
                            % ", ".join(tried))
    P, E = ctypes.c_void_p, ctypes.POINTER(_Error)
    lib.sp_device_create.argtypes = [ctypes.POINTER(P), ctypes.c_int, ctypes.c_int, E]
    lib.sp_device_create.restype = ctypes.c_int
    lib.sp_device_free.argtypes = [P]
    lib.sp_device_free.restype = None
    lib.sp_device_name.argtypes = [P]
    lib.sp_device_name.restype = ctypes.c_char_p
    lib.sp_query_opts_default.argtypes = []
    lib.sp_query_opts_default.restype = _Opts
    lib.sp_query_engine_open.argtypes = [ctypes.POINTER(P), ctypes.c_char_p, ctypes.POINTER(_Opts),
                                         P, P, E]
    lib.sp_query_engine_open.restype = ctypes.c_int
    lib.sp_query_engine_free.argtypes = [P]
    lib.sp_query_engine_free.restype = None
    lib.sp_query_engine_opts.argtypes = [P]
    lib.sp_query_engine_opts.restype = ctypes.POINTER(_Opts)
    lib.sp_query_engine_query.argtypes = [P, ctypes.c_char_p, ctypes.POINTER(_Result), E]
    lib.sp_query_engine_query.restype = ctypes.c_int
    lib.sp_query_engine_query_embedding.argtypes = [P, ctypes.POINTER(ctypes.c_float),
                                                    ctypes.c_char_p, ctypes.POINTER(_Result), E]
    lib.sp_query_engine_query_embedding.restype = ctypes.c_int
    lib.sp_query_engine_embed.argtypes = [P, ctypes.c_char_p, ctypes.POINTER(ctypes.c_float), E]
    lib.sp_query_engine_embed.restype = ctypes.c_int
    lib.sp_query_engine_full_dim.argtypes = [P]
    lib.sp_query_engine_full_dim.restype = ctypes.c_int
    lib.sp_query_engine_n_cameras.argtypes = [P]
    lib.sp_query_engine_n_cameras.restype = ctypes.c_size_t
    lib.sp_query_result_free.argtypes = [ctypes.POINTER(_Result)]
    lib.sp_query_result_free.restype = None
    lib.sp_image_write_png.argtypes = [ctypes.c_char_p, ctypes.POINTER(_Image), E]
    lib.sp_image_write_png.restype = ctypes.c_int
    _lib = lib
    return lib


def _check(rc, err):
    if rc != 0:
        raise SemsplatError(err.msg.decode("utf-8", "replace") or "semsplat error %d" % rc)


def _vec(a):
    return np.array([a[0], a[1], a[2]], dtype=np.float64)


class QueryResult:
    """One query's answer, copied out of the C result (owns numpy arrays, nothing native)."""

    def __init__(self, r):
        self.text = r.text.decode("utf-8", "replace")
        self.method = "multiview" if r.method == 1 else "3d"
        self.found = bool(r.valid)
        self.position = _vec(r.position) if r.valid else None
        self.confidence = float(r.confidence)
        self.relevancy_max = float(r.relevancy_max)
        self.view_index = int(r.view_index) if r.view_index >= 0 else None
        self.view_name = r.view_name.decode("utf-8", "replace") if r.view_index >= 0 else None
        if r.relevancy_image and r.width > 0 and r.height > 0:
            n = r.width * r.height
            self.relevancy_image = np.ctypeslib.as_array(r.relevancy_image, shape=(n * 3,)).reshape(
                r.height, r.width, 3).copy()
            self.relevancy = (np.ctypeslib.as_array(r.relevancy, shape=(n,)).reshape(r.height, r.width).copy()
                              if r.relevancy else None)
        else:
            self.relevancy_image = None
            self.relevancy = None
        self.instances = []
        for k in range(r.n_instances):
            it = r.instances[k]
            self.instances.append({
                "position": _vec(it.position),
                "extent_min": _vec(it.extent_min),
                "extent_max": _vec(it.extent_max),
                "score": float(it.score),
                "confidence": float(it.confidence),
                "points": int(it.n_points),
            })
        self.timings_ms = {"embed": r.ms_embed, "relevancy": r.ms_relevancy, "localize": r.ms_localize,
                           "heatmap": r.ms_heatmap, "total": r.ms_total}

    def save_heatmap(self, path):
        """Writes relevancy_image as a PNG (through the library's writer, atomically)."""
        if self.relevancy_image is None:
            raise SemsplatError("this result has no heatmap (no cameras, or heatmap=False)")
        lib = load_library()
        img = np.ascontiguousarray(self.relevancy_image)
        desc = _Image(img.shape[1], img.shape[0], 3, 8, img.ctypes.data)
        err = _Error()
        _check(lib.sp_image_write_png(os.fsencode(path), ctypes.byref(desc), ctypes.byref(err)), err)

    def to_dict(self):
        """The same keys as `semsplat query --json` (heatmap left out)."""
        return {
            "text": self.text, "method": self.method, "found": self.found,
            "position": None if self.position is None else self.position.tolist(),
            "confidence": self.confidence, "relevancy_max": self.relevancy_max,
            "view": None if self.view_index is None else {"index": self.view_index, "name": self.view_name},
            "instances": [{k: (v.tolist() if isinstance(v, np.ndarray) else v) for k, v in i.items()}
                          for i in self.instances],
            "timings_ms": dict(self.timings_ms),
        }

    def __repr__(self):
        where = "not found" if self.position is None else "at [%.3f, %.3f, %.3f]" % tuple(self.position)
        return "QueryResult(%r %s, confidence %.3f, %d instances)" % (
            self.text, where, self.confidence, len(self.instances))


class SemanticSplatQuery:
    """Opens a language-embedded model folder once; query() as often as needed.

    model_path: folder with splat.ply (f_sem_* fields), semantic.json and the PCA files.
    device: "auto" (GPU when usable), "cpu" or "cuda". method: "3d" or "multiview".
    heatmap: render relevancy_image for each query. threads: CPU threads (0 = all).
    """

    def __init__(self, model_path, device="auto", method="3d", heatmap=True, threads=0,
                 negatives=None, min_confidence=None):
        self._lib = load_library()
        self._dev = ctypes.c_void_p()
        self._eng = ctypes.c_void_p()
        err = _Error()
        if device not in _DEVICES:
            raise ValueError("device must be one of %s" % sorted(_DEVICES))
        if method not in _METHODS:
            raise ValueError("method must be one of %s" % sorted(_METHODS))
        _check(self._lib.sp_device_create(ctypes.byref(self._dev), _DEVICES[device], int(threads),
                                          ctypes.byref(err)), err)
        opts = self._lib.sp_query_opts_default()
        opts.method = _METHODS[method]
        opts.heatmap = 1 if heatmap else 0
        if negatives is not None:
            opts.negatives = ",".join(negatives).encode() if not isinstance(negatives, str) else negatives.encode()
        if min_confidence is not None:
            opts.min_confidence = float(min_confidence)
        rc = self._lib.sp_query_engine_open(ctypes.byref(self._eng), os.fsencode(model_path),
                                            ctypes.byref(opts), self._dev, None, ctypes.byref(err))
        if rc != 0:
            self._lib.sp_device_free(self._dev)
            self._dev = ctypes.c_void_p()
            _check(rc, err)
        self.model_path = model_path

    @property
    def device(self):
        return self._lib.sp_device_name(self._dev).decode()

    @property
    def n_cameras(self):
        return int(self._lib.sp_query_engine_n_cameras(self._eng))

    def _run(self, call, method, heatmap_view):
        opts = self._lib.sp_query_engine_opts(self._eng).contents
        saved = (opts.method, opts.heatmap_view)
        if method is not None:
            if method not in _METHODS:
                raise ValueError("method must be one of %s" % sorted(_METHODS))
            opts.method = _METHODS[method]
        if heatmap_view is not None:
            opts.heatmap_view = int(heatmap_view)
        res, err = _Result(), _Error()
        try:
            _check(call(ctypes.byref(res), ctypes.byref(err)), err)
            return QueryResult(res)
        finally:
            self._lib.sp_query_result_free(ctypes.byref(res))
            opts.method, opts.heatmap_view = saved

    def query(self, text, method=None, heatmap_view=None):
        """Finds `text`; returns a QueryResult (position None when not found)."""
        return self._run(lambda r, e: self._lib.sp_query_engine_query(self._eng, text.encode("utf-8"), r, e),
                         method, heatmap_view)

    def embed(self, text):
        """The engine's text embedding (CLIP text tower or label embedding), np.float32 [full_dim]."""
        out = np.zeros(self._lib.sp_query_engine_full_dim(self._eng), dtype=np.float32)
        err = _Error()
        _check(self._lib.sp_query_engine_embed(self._eng, text.encode("utf-8"),
                                               out.ctypes.data_as(ctypes.POINTER(ctypes.c_float)),
                                               ctypes.byref(err)), err)
        return out

    def query_embedding(self, embedding, label="", method=None, heatmap_view=None):
        """Same as query() with a precomputed full-dimension embedding."""
        emb = np.ascontiguousarray(embedding, dtype=np.float32)
        if emb.shape != (self._lib.sp_query_engine_full_dim(self._eng),):
            raise ValueError("embedding must have shape (%d,)" % self._lib.sp_query_engine_full_dim(self._eng))
        ptr = emb.ctypes.data_as(ctypes.POINTER(ctypes.c_float))
        return self._run(lambda r, e: self._lib.sp_query_engine_query_embedding(
            self._eng, ptr, label.encode("utf-8"), r, e), method, heatmap_view)

    def close(self):
        if self._eng:
            self._lib.sp_query_engine_free(self._eng)
            self._eng = ctypes.c_void_p()
        if self._dev:
            self._lib.sp_device_free(self._dev)
            self._dev = ctypes.c_void_p()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        try:
            self.close()
        except Exception:
            pass


if __name__ == "__main__":
    import sys
    if len(sys.argv) < 3:
        print("usage: gs_semantic_query.py MODEL_DIR TEXT [TEXT ...]")
        sys.exit(2)
    with SemanticSplatQuery(model_path=sys.argv[1]) as q:
        for t in sys.argv[2:]:
            print(json.dumps(q.query(t).to_dict(), indent=2))
