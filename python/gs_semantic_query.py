"""gs_semantic_query: the Python face of semsplat's query engine (ctypes over libsemsplat.so).

    from gs_semantic_query import SemanticSplatQuery
    q = SemanticSplatQuery(model_path="out/house_model")
    r = q.query("refrigerator")
    r.position          # np.array([x, y, z]) in r.frame, or None when not found
    r.frame             # {"name": "world"|"colmap", "source": "synth"|"align"|"colmap", "units", "up"}
    r.source            # {"encoder": "clip"|"lexical"|"exact", "features": "clip"|"npy"|"labels", "note", ...}
    r.encoder           # the text encoder that answered ("lexical" on label scenes without weights)
    r.confidence        # clip/exact: largest raw cosine (above ~0.25 a match); lexical: the calibrated
                        # WordNet score (r.threshold = 0.5 is a match)
    r.explanation       # lexical: which classes matched and why (synonym, hypernym path, definitions)
    r.matches           # [{"class", "role", "score", "kind", "path", "gloss_words", "definition", ...}]
    r.region, r.anchor  # {"name", "extent_min", "extent_max", "centre", "instances"} or None
    r.relevancy_image   # np.ndarray (H, W, 3) uint8: turbo relevancy over the rendered view
    r.instances         # [{"position": np.array, "extent_min", "extent_max", "score", "class", ...}]
    q.relevancy("chair")                 # per-Gaussian relevancy, np.float32 [n]
    rgb, rel = q.heatmap("chair", q.camera(3))   # from any camera (a Camera, or a view index)

The text encoder is the model folder's (semantic.json "encoder"), or SemanticSplatQuery(...,
encoder="clip"|"lexical"|"exact"). The lexical encoder matches text against the scene's known
class names with WordNet: it cannot find what the world file does not name.

Positions, Gaussians and cameras are in the model folder's frame (frame.json: the world frame for
synth captures and aligned models); `source["note"]` says when the features come from
ground-truth labels (the figures then measure localization given a perfect 2D segmentation).

Safety: the library's ABI version and struct sizes are checked at load; every instance has its
own lock (the C engine locks itself too), and after close() every call raises ValueError instead
of reaching C. Errors: SemsplatNotFoundError (a FileNotFoundError), SemsplatValueError (a
ValueError: bad arguments, malformed or unsupported files), SemsplatMemoryError, else
SemsplatError; all derive from SemsplatError.

The library is found through $SEMSPLAT_LIB (the .so itself or its folder), else ../build/ (and
../build-*/) next to this file. Needs numpy (Debian: python3-numpy).
"""
import ctypes
import ctypes.util
import glob
import json
import os
import threading

import numpy as np

__all__ = ["SemanticSplatQuery", "QueryResult", "Camera", "SemsplatError", "SemsplatNotFoundError",
           "SemsplatValueError", "SemsplatMemoryError", "load_library"]

ABI_VERSION = 4  # SP_SEMANTIC_ABI_VERSION in include/semsplat/semantic.h


class SemsplatError(RuntimeError):
    """A semsplat call failed; the message names the file, field or value at fault."""

    def __init__(self, msg, code=None):
        super().__init__(msg)
        self.code = code


class SemsplatNotFoundError(SemsplatError, FileNotFoundError):
    """A named file, model or class does not exist (SP_E_NOTFOUND)."""


class SemsplatValueError(SemsplatError, ValueError):
    """A bad argument, or a malformed / unsupported file (SP_E_ARG, SP_E_FORMAT, SP_E_UNSUPPORTED)."""


class SemsplatMemoryError(SemsplatError, MemoryError):
    """The library ran out of memory (SP_E_NOMEM)."""


_ERRORS = {-8: SemsplatNotFoundError, -4: SemsplatValueError, -2: SemsplatValueError,
           -5: SemsplatValueError, -3: SemsplatMemoryError}


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
        ("host_stages", ctypes.c_int),
    ]


class _Instance(ctypes.Structure):  # sp_query_instance
    _fields_ = [
        ("position", ctypes.c_float * 3),
        ("extent_min", ctypes.c_float * 3),
        ("extent_max", ctypes.c_float * 3),
        ("score", ctypes.c_float),
        ("confidence", ctypes.c_float),
        ("n_points", ctypes.c_int),
        ("label", ctypes.c_char * 128),
        ("relation_m", ctypes.c_float),
    ]


class _Match(ctypes.Structure):  # sp_query_match
    _fields_ = [("label", ctypes.c_char * 128), ("role", ctypes.c_char * 8), ("score", ctypes.c_float),
                ("kind", ctypes.c_char * 16), ("query_sense", ctypes.c_char * 64),
                ("class_sense", ctypes.c_char * 64), ("path", ctypes.c_char * 256),
                ("gloss_words", ctypes.c_char * 192), ("definition", ctypes.c_char * 192)]


class _Region(ctypes.Structure):  # sp_query_region
    _fields_ = [("valid", ctypes.c_int), ("name", ctypes.c_char * 64), ("extent_min", ctypes.c_float * 3),
                ("extent_max", ctypes.c_float * 3), ("centre", ctypes.c_float * 3), ("n_instances", ctypes.c_int)]


class _EncoderOpts(ctypes.Structure):  # sp_encoder_opts
    _fields_ = [("encoder", ctypes.c_char_p), ("wordnet_dir", ctypes.c_char_p), ("regions_path", ctypes.c_char_p)]


class _Source(ctypes.Structure):  # sp_query_source
    _fields_ = [("encoder", ctypes.c_char * 16), ("features", ctypes.c_char * 16),
                ("ground_truth", ctypes.c_int)]


class _Frame(ctypes.Structure):  # sp_query_frame
    _fields_ = [("name", ctypes.c_char * 16), ("source", ctypes.c_char * 16),
                ("units", ctypes.c_char * 16), ("up", ctypes.c_char * 8)]


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
        ("source", _Source),
        ("frame", _Frame),
        ("threshold", ctypes.c_float),
        ("n_matches", ctypes.c_int),
        ("matches", ctypes.POINTER(_Match)),
        ("relation", ctypes.c_char * 24),
        ("region", _Region),
        ("anchor", _Region),
        ("n_ignored", ctypes.c_int),
        ("ignored", (ctypes.c_char * 32) * 8),
        ("explanation", ctypes.c_char_p),
        ("ms_stage", ctypes.c_double * 9),  # sp_query_stages
    ]


class _Camera(ctypes.Structure):  # sp_camera (include/semsplat/core.h)
    _fields_ = [("width", ctypes.c_int), ("height", ctypes.c_int), ("fx", ctypes.c_float),
                ("fy", ctypes.c_float), ("cx", ctypes.c_float), ("cy", ctypes.c_float),
                ("R", ctypes.c_float * 9), ("t", ctypes.c_float * 3), ("distortion", ctypes.c_int),
                ("dist", ctypes.c_float * 4)]


class _Splat(ctypes.Structure):  # sp_splat (include/semsplat/core.h)
    _fields_ = [("n", ctypes.c_size_t), ("sh_degree", ctypes.c_int), ("feat_dim", ctypes.c_int),
                ("means", ctypes.POINTER(ctypes.c_float)), ("quats", ctypes.POINTER(ctypes.c_float)),
                ("log_scales", ctypes.POINTER(ctypes.c_float)),
                ("opacity_logits", ctypes.POINTER(ctypes.c_float)),
                ("sh", ctypes.POINTER(ctypes.c_float)), ("features", ctypes.POINTER(ctypes.c_float))]


class _Image(ctypes.Structure):  # sp_image (include/semsplat/io.h)
    _fields_ = [("width", ctypes.c_int), ("height", ctypes.c_int), ("channels", ctypes.c_int),
                ("bit_depth", ctypes.c_int), ("data", ctypes.c_void_p)]


_STRUCTS = {"sp_query_opts": _Opts, "sp_query_instance": _Instance, "sp_query_source": _Source,
            "sp_query_frame": _Frame, "sp_query_result": _Result, "sp_error": _Error,
            "sp_query_match": _Match, "sp_query_region": _Region, "sp_encoder_opts": _EncoderOpts,
            "sp_camera": _Camera, "sp_splat": _Splat, "sp_image": _Image}
_METHODS = {"3d": 0, "multiview": 1, "multi-view": 1}
ENCODERS = ("clip", "lexical", "exact")
_DEVICES = {"cpu": 0, "cuda": 1, "auto": 2}
_lib = None
_lib_lock = threading.Lock()


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


def _open_library():
    tried = []
    for path in _candidates():
        tried.append(path)
        if path and (os.path.exists(path) or not os.path.dirname(path)):
            try:
                return ctypes.CDLL(path), path
            except OSError:
                continue
    raise SemsplatError("libsemsplat.so not found (tried %s); build it or set SEMSPLAT_LIB" % ", ".join(tried))


def _check_abi(lib, path):
    """Refuses a library whose ABI version or struct layouts differ from this module's."""
    try:
        lib.sp_semantic_abi_version.restype = ctypes.c_int
        lib.sp_semantic_abi_sizeof.argtypes = [ctypes.c_char_p]
        lib.sp_semantic_abi_sizeof.restype = ctypes.c_size_t
    except AttributeError:
        raise SemsplatError("%s has no ABI information (older than this module): rebuild it" % path)
    version = lib.sp_semantic_abi_version()
    if version != ABI_VERSION:
        raise SemsplatError("%s has ABI version %d, this module expects %d" % (path, version, ABI_VERSION))
    for name, struct in _STRUCTS.items():
        size = lib.sp_semantic_abi_sizeof(name.encode())
        if size != ctypes.sizeof(struct):
            raise SemsplatError("%s: sizeof(%s) is %d in the library, %d here" % (
                path, name, size, ctypes.sizeof(struct)))


def _declare(lib):
    P, E, F = ctypes.c_void_p, ctypes.POINTER(_Error), ctypes.POINTER(ctypes.c_float)
    sigs = {
        "sp_device_create": ([ctypes.POINTER(P), ctypes.c_int, ctypes.c_int, E], ctypes.c_int),
        "sp_device_free": ([P], None),
        "sp_device_name": ([P], ctypes.c_char_p),
        "sp_query_opts_default": ([], _Opts),
        "sp_query_engine_open": ([ctypes.POINTER(P), ctypes.c_char_p, ctypes.POINTER(_Opts), P, P, E], ctypes.c_int),
        "sp_query_engine_open_with": ([ctypes.POINTER(P), ctypes.c_char_p, ctypes.POINTER(_EncoderOpts),
                                       ctypes.POINTER(_Opts), P, P, E], ctypes.c_int),
        "sp_query_engine_free": ([P], None),
        "sp_query_engine_defaults": ([P], ctypes.POINTER(_Opts)),
        "sp_query_engine_query": ([P, ctypes.c_char_p, ctypes.POINTER(_Opts), ctypes.POINTER(_Result), E], ctypes.c_int),
        "sp_query_engine_query_embedding": ([P, F, ctypes.c_char_p, ctypes.POINTER(_Opts),
                                             ctypes.POINTER(_Result), E], ctypes.c_int),
        "sp_query_engine_embed": ([P, ctypes.c_char_p, F, E], ctypes.c_int),
        "sp_query_engine_relevancy": ([P, ctypes.c_char_p, F, F, E], ctypes.c_int),
        "sp_query_engine_heatmap": ([P, ctypes.c_char_p, ctypes.POINTER(_Camera), ctypes.POINTER(ctypes.c_uint8),
                                     F, E], ctypes.c_int),
        "sp_query_engine_full_dim": ([P], ctypes.c_int),
        "sp_query_engine_n_cameras": ([P], ctypes.c_size_t),
        "sp_query_engine_camera": ([P, ctypes.c_size_t], ctypes.POINTER(_Camera)),
        "sp_query_engine_camera_name": ([P, ctypes.c_size_t], ctypes.c_char_p),
        "sp_query_engine_splat": ([P], ctypes.POINTER(_Splat)),
        "sp_query_result_free": ([ctypes.POINTER(_Result)], None),
        "sp_query_source_note": ([ctypes.POINTER(_Source)], ctypes.c_char_p),
        "sp_query_engine_source": ([P], ctypes.POINTER(_Source)),
        "sp_image_write_png": ([ctypes.c_char_p, ctypes.POINTER(_Image), E], ctypes.c_int),
    }
    for name, (args, res) in sigs.items():
        fn = getattr(lib, name)
        fn.argtypes = args
        fn.restype = res


def load_library():
    """Loads libsemsplat once, checks its ABI and declares the functions this module calls."""
    global _lib
    with _lib_lock:
        if _lib is None:
            lib, path = _open_library()
            _check_abi(lib, path)
            _declare(lib)
            _lib = lib
        return _lib


def _check(rc, err):
    if rc != 0:
        msg = err.msg.decode("utf-8", "replace") or "semsplat error %d" % rc
        raise _ERRORS.get(rc, SemsplatError)(msg, rc)


def _vec(a):
    return np.array([a[0], a[1], a[2]], dtype=np.float64)


def _str(b):
    return b.decode("utf-8", "replace")


def _source_dict(s):
    note = load_library().sp_query_source_note(ctypes.byref(s))
    return {"encoder": _str(s.encoder), "features": _str(s.features), "ground_truth": bool(s.ground_truth),
            "note": _str(note) or None}


def _frame_dict(f):
    return {"name": _str(f.name), "source": _str(f.source), "units": _str(f.units), "up": _str(f.up)}


def _region_dict(g):
    if not g.valid:
        return None
    return {"name": _str(g.name), "extent_min": _vec(g.extent_min), "extent_max": _vec(g.extent_max),
            "centre": _vec(g.centre), "instances": int(g.n_instances)}


_MATCH_KEYS = ("role", "kind", "query_sense", "class_sense", "path", "gloss_words", "definition")


def _match_dict(m, threshold):
    d = {"class": _str(m.label), "score": float(m.score), "match": float(m.score) >= threshold}
    for k in _MATCH_KEYS:
        d[k] = _str(getattr(m, k))
    return d


def _plain(v):
    if isinstance(v, np.ndarray):
        return v.tolist()
    if isinstance(v, dict):
        return {k: _plain(x) for k, x in v.items()}
    return v


class Camera:
    """A pinhole camera in the engine's frame: intrinsics in pixels, world-to-camera R (3x3), t.
    OpenCV axes (x right, y down, z forward): x_cam = R x_world + t."""

    def __init__(self, width, height, fx, fy, cx, cy, R, t):
        self.width, self.height = int(width), int(height)
        self.fx, self.fy, self.cx, self.cy = float(fx), float(fy), float(cx), float(cy)
        self.R = np.asarray(R, dtype=np.float64).reshape(3, 3)
        self.t = np.asarray(t, dtype=np.float64).reshape(3)

    @property
    def center(self):
        """The camera centre in the engine's frame (-R^T t)."""
        return -self.R.T @ self.t

    def _to_c(self):
        c = _Camera()
        c.width, c.height, c.fx, c.fy, c.cx, c.cy = self.width, self.height, self.fx, self.fy, self.cx, self.cy
        for k in range(9):
            c.R[k] = float(self.R.flat[k])
        for k in range(3):
            c.t[k] = float(self.t[k])
        return c

    @classmethod
    def _from_c(cls, c):
        return cls(c.width, c.height, c.fx, c.fy, c.cx, c.cy, list(c.R), list(c.t))


class QueryResult:
    """One query's answer, copied out of the C result (owns numpy arrays, nothing native)."""

    def __init__(self, r):
        self.text = _str(r.text)
        self.method = "multiview" if r.method == 1 else "3d"
        self.found = bool(r.valid)
        self.position = _vec(r.position) if r.valid else None
        self.confidence = float(r.confidence)
        self.relevancy_max = float(r.relevancy_max)
        self.view_index = int(r.view_index) if r.view_index >= 0 else None
        self.view_name = _str(r.view_name) if r.view_index >= 0 else None
        self.source = _source_dict(r.source)
        self.encoder = self.source["encoder"]
        self.frame = _frame_dict(r.frame)
        self.threshold = float(r.threshold)
        self.matches = [_match_dict(r.matches[k], self.threshold) for k in range(r.n_matches)]
        self.relation = _str(r.relation) or None
        self.region = _region_dict(r.region)
        self.anchor = _region_dict(r.anchor)
        self.ignored = [_str(r.ignored[k].value) for k in range(r.n_ignored)]
        self.explanation = _str(r.explanation) if r.explanation else None
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
                "class": _str(it.label) or None,
                "relation_m": float(it.relation_m) if np.isfinite(it.relation_m) else None,
            })
        self.timings_ms = {"embed": r.ms_embed, "relevancy": r.ms_relevancy, "localize": r.ms_localize,
                           "heatmap": r.ms_heatmap, "total": r.ms_total}

    def save_heatmap(self, path):
        """Writes relevancy_image as a PNG (through the library's writer, atomically)."""
        if self.relevancy_image is None:
            raise SemsplatValueError("this result has no heatmap (no cameras, or heatmap=False)")
        _write_png(path, self.relevancy_image)

    def to_dict(self):
        """The same keys as `semsplat query --json` (heatmap left out)."""
        return {
            "text": self.text, "encoder": self.encoder, "method": self.method, "found": self.found,
            "position": None if self.position is None else self.position.tolist(),
            "confidence": self.confidence, "threshold": self.threshold, "relevancy_max": self.relevancy_max,
            "view": None if self.view_index is None else {"index": self.view_index, "name": self.view_name},
            "instances": [_plain(i) for i in self.instances],
            "source": dict(self.source), "frame": dict(self.frame),
            "timings_ms": dict(self.timings_ms),
            "matches": [dict(m) for m in self.matches], "relation": self.relation,
            "region": _plain(self.region), "anchor": _plain(self.anchor), "ignored": list(self.ignored),
            "explanation": self.explanation,
        }

    def __repr__(self):
        where = "not found" if self.position is None else "at [%.3f, %.3f, %.3f] (%s frame)" % (
            tuple(self.position) + (self.frame["name"],))
        return "QueryResult(%r %s, confidence %.3f, %d instances, encoder %s)" % (
            self.text, where, self.confidence, len(self.instances), self.source["encoder"])


def _write_png(path, rgb):
    lib = load_library()
    img = np.ascontiguousarray(rgb, dtype=np.uint8)
    desc = _Image(img.shape[1], img.shape[0], 3, 8, img.ctypes.data)
    err = _Error()
    _check(lib.sp_image_write_png(os.fsencode(path), ctypes.byref(desc), ctypes.byref(err)), err)


class SemanticSplatQuery:
    """Opens a language-embedded model folder once; query() as often as needed, from any thread.

    model_path: folder with splat.ply (f_sem_* fields), semantic.json and the PCA files.
    device: "auto" (GPU when usable), "cpu" or "cuda". method: "3d" or "multiview" (the default
    of query(); each call may pass its own). heatmap: render relevancy_image for each query.
    threads: CPU threads (0 = all). encoder: "clip", "lexical" or "exact" (None = the folder's,
    semantic.json "encoder"); wordnet_dir, regions: the lexical encoder's WordNet database and
    region table (None = the defaults).
    """

    def __init__(self, model_path, device="auto", method="3d", heatmap=True, threads=0,
                 negatives=None, min_confidence=None, encoder=None, wordnet_dir=None, regions=None):
        self._lock = threading.RLock()
        self._dev = ctypes.c_void_p()
        self._eng = ctypes.c_void_p()
        if device not in _DEVICES:
            raise ValueError("device must be one of %s" % sorted(_DEVICES))
        if method not in _METHODS:
            raise ValueError("method must be one of %s" % sorted(_METHODS))
        if encoder is not None and encoder not in ENCODERS:
            raise ValueError("encoder must be one of %s" % (ENCODERS,))
        self._lib = load_library()
        err = _Error()
        _check(self._lib.sp_device_create(ctypes.byref(self._dev), _DEVICES[device], int(threads),
                                          ctypes.byref(err)), err)
        opts = self._lib.sp_query_opts_default()
        opts.method = _METHODS[method]
        opts.heatmap = 1 if heatmap else 0
        if negatives is not None:
            text = negatives if isinstance(negatives, str) else ",".join(negatives)
            if len(text.encode()) >= 256:
                raise ValueError("negatives: at most 255 bytes")
            opts.negatives = text.encode()
        if min_confidence is not None:
            opts.min_confidence = float(min_confidence)
        enc = _EncoderOpts(encoder.encode() if encoder else None,
                           os.fsencode(wordnet_dir) if wordnet_dir is not None else None,
                           os.fsencode(regions) if regions is not None else None)
        rc = self._lib.sp_query_engine_open_with(ctypes.byref(self._eng), os.fsencode(model_path),
                                                 ctypes.byref(enc), ctypes.byref(opts), self._dev, None,
                                                 ctypes.byref(err))
        if rc != 0:
            self._lib.sp_device_free(self._dev)
            self._dev = ctypes.c_void_p()
            self._eng = ctypes.c_void_p()
            _check(rc, err)
        self.model_path = model_path

    # -- lifetime ------------------------------------------------------------------------------

    def _engine(self):
        """The native engine, or ValueError once closed (never a NULL into C)."""
        if not self._eng:
            raise ValueError("this SemanticSplatQuery is closed")
        return self._eng

    @property
    def closed(self):
        return not self._eng

    def close(self):
        with self._lock:
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

    # -- facts ---------------------------------------------------------------------------------

    @property
    def encoder(self):
        """The text encoder this engine answers with ("clip", "lexical" or "exact")."""
        with self._lock:
            return _source_dict(self._lib.sp_query_engine_source(self._engine()).contents)["encoder"]

    @property
    def device(self):
        with self._lock:
            self._engine()
            return _str(self._lib.sp_device_name(self._dev))

    @property
    def n_cameras(self):
        with self._lock:
            return int(self._lib.sp_query_engine_n_cameras(self._engine()))

    @property
    def n_gaussians(self):
        with self._lock:
            return int(self._lib.sp_query_engine_splat(self._engine()).contents.n)

    def camera(self, index):
        """Training camera `index` in the engine's frame (a Camera)."""
        with self._lock:
            eng = self._engine()
            n = int(self._lib.sp_query_engine_n_cameras(eng))
            if not 0 <= int(index) < n:
                raise IndexError("camera %d not in 0..%d" % (index, n - 1))
            return Camera._from_c(self._lib.sp_query_engine_camera(eng, int(index)).contents)

    def gaussian_positions(self):
        """Gaussian centres [n, 3] (np.float32) in the engine's frame, in the order of relevancy()."""
        with self._lock:
            s = self._lib.sp_query_engine_splat(self._engine()).contents
            if s.n == 0:
                return np.zeros((0, 3), dtype=np.float32)
            return np.ctypeslib.as_array(s.means, shape=(s.n * 3,)).reshape(s.n, 3).copy()

    # -- queries -------------------------------------------------------------------------------

    def _opts(self, method, heatmap_view, heatmap=None):
        opts = _Opts.from_buffer_copy(self._lib.sp_query_engine_defaults(self._engine()).contents)
        if method is not None:
            if method not in _METHODS:
                raise ValueError("method must be one of %s" % sorted(_METHODS))
            opts.method = _METHODS[method]
        if heatmap_view is not None:
            if not 0 <= int(heatmap_view) < int(self._lib.sp_query_engine_n_cameras(self._eng)):
                raise IndexError("heatmap_view %d is not a camera index" % heatmap_view)
            opts.heatmap_view = int(heatmap_view)
        if heatmap is not None:
            opts.heatmap = 1 if heatmap else 0
        return opts

    def _run(self, call, method, heatmap_view, heatmap):
        with self._lock:
            self._engine()
            opts = self._opts(method, heatmap_view, heatmap)
            res, err = _Result(), _Error()
            try:
                _check(call(ctypes.byref(opts), ctypes.byref(res), ctypes.byref(err)), err)
                return QueryResult(res)
            finally:
                self._lib.sp_query_result_free(ctypes.byref(res))

    def query(self, text, method=None, heatmap_view=None, heatmap=None):
        """Finds `text`; returns a QueryResult (position None when not found). The options are
        this call's only: method "3d" / "multiview", heatmap_view (camera index), heatmap."""
        data = text.encode("utf-8")
        return self._run(lambda o, r, e: self._lib.sp_query_engine_query(self._eng, data, o, r, e),
                         method, heatmap_view, heatmap)

    def embed(self, text):
        """The engine's text embedding (its text encoder), np.float32 [full_dim]."""
        with self._lock:
            eng = self._engine()
            out = np.zeros(self._lib.sp_query_engine_full_dim(eng), dtype=np.float32)
            err = _Error()
            _check(self._lib.sp_query_engine_embed(eng, text.encode("utf-8"),
                                                   out.ctypes.data_as(ctypes.POINTER(ctypes.c_float)),
                                                   ctypes.byref(err)), err)
            return out

    def query_embedding(self, embedding, label="", method=None, heatmap_view=None, heatmap=None):
        """Same as query() with a precomputed full-dimension embedding."""
        with self._lock:
            full = self._lib.sp_query_engine_full_dim(self._engine())
            emb = np.ascontiguousarray(embedding, dtype=np.float32)
            if emb.shape != (full,):
                raise ValueError("embedding must have shape (%d,)" % full)
            ptr = emb.ctypes.data_as(ctypes.POINTER(ctypes.c_float))
            data = label.encode("utf-8")
            return self._run(lambda o, r, e: self._lib.sp_query_engine_query_embedding(
                self._eng, ptr, data, o, r, e), method, heatmap_view, heatmap)

    def relevancy(self, text, raw=False):
        """Per-Gaussian calibrated relevancy of `text` (np.float32 [n], 0.5 = no preference), in
        the order of gaussian_positions(); with raw=True also the raw cosines: (relevancy, raw)."""
        with self._lock:
            eng = self._engine()
            n = int(self._lib.sp_query_engine_splat(eng).contents.n)
            rel = np.zeros(max(n, 1), dtype=np.float32)
            cos = np.zeros(max(n, 1), dtype=np.float32) if raw else None
            err = _Error()
            fp = ctypes.POINTER(ctypes.c_float)
            _check(self._lib.sp_query_engine_relevancy(eng, text.encode("utf-8"), rel.ctypes.data_as(fp),
                                                       cos.ctypes.data_as(fp) if raw else None,
                                                       ctypes.byref(err)), err)
            return (rel[:n], cos[:n]) if raw else rel[:n]

    def heatmap(self, text, camera):
        """The heatmap of `text` seen from `camera` (a Camera in the engine's frame, or a camera
        index): (rgb (H, W, 3) uint8, relevancy (H, W) float32)."""
        with self._lock:
            eng = self._engine()
            cam = self.camera(camera) if isinstance(camera, (int, np.integer)) else camera
            if not isinstance(cam, Camera):
                raise TypeError("camera must be a Camera or a camera index")
            if not (0 < cam.width <= 16384 and 0 < cam.height <= 16384):
                raise ValueError("camera size %dx%d out of range" % (cam.width, cam.height))
            c = cam._to_c()
            rgb = np.zeros((cam.height, cam.width, 3), dtype=np.uint8)
            rel = np.zeros((cam.height, cam.width), dtype=np.float32)
            err = _Error()
            _check(self._lib.sp_query_engine_heatmap(
                eng, text.encode("utf-8"), ctypes.byref(c), rgb.ctypes.data_as(ctypes.POINTER(ctypes.c_uint8)),
                rel.ctypes.data_as(ctypes.POINTER(ctypes.c_float)), ctypes.byref(err)), err)
            return rgb, rel


if __name__ == "__main__":
    import sys
    if len(sys.argv) < 3:
        print("usage: gs_semantic_query.py MODEL_DIR TEXT [TEXT ...]")
        sys.exit(2)
    with SemanticSplatQuery(model_path=sys.argv[1]) as q:
        for t in sys.argv[2:]:
            print(json.dumps(q.query(t).to_dict(), indent=2))
