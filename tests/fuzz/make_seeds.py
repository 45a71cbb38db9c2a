#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz harnesses into tests/fuzz/corpus/<harness>/seed_*.

Usage: tests/fuzz/make_seeds.py BUILD_DIR
Seeds are small: real files from a tiny synth -> train -> features -> lift run of
tests/fuzz/fixtures/tiny.world (made with BUILD_DIR/semsplat in a temporary folder), the test
fixtures, and hand-made files that reach branches the real ones do not (other camera models,
ascii PLY, Fortran .npy, palette PNGs, progressive JPEGs, ...). Only seed_* files are replaced;
crash regressions (crash-*, regress-*) and merged inputs stay. Needs python3 and, for the JPEG
seeds, ffmpeg (skipped when absent)."""
import json, os, shutil, struct, subprocess, sys, tempfile, zlib

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CORPUS = os.path.join(ROOT, "tests", "fuzz", "corpus")
FIX = os.path.join(ROOT, "tests", "fuzz", "fixtures")


def put(harness, name, data):
    d = os.path.join(CORPUS, harness)
    os.makedirs(d, exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(d, "seed_" + name), "wb") as f:
        f.write(data)


def clear_seeds():
    if not os.path.isdir(CORPUS):
        return
    for h in os.listdir(CORPUS):
        for f in os.listdir(os.path.join(CORPUS, h)):
            if f.startswith("seed_"):
                os.remove(os.path.join(CORPUS, h, f))


def read(path):
    with open(path, "rb") as f:
        return f.read()


# ---- COLMAP ----------------------------------------------------------------------------------
MODELS = {"SIMPLE_PINHOLE": (0, 3), "PINHOLE": (1, 4), "SIMPLE_RADIAL": (2, 4), "RADIAL": (3, 5),
          "OPENCV": (4, 8), "FULL_OPENCV": (6, 12)}
CAMS = [(1, "PINHOLE", 64, 48, [50, 51, 32, 24]), (2, "OPENCV", 640, 480, [500, 501, 320, 240, 0.1, -0.05, 0.001, 0.002]),
        (3, "SIMPLE_RADIAL", 32, 24, [30, 16, 12, 0.01]), (4, "FULL_OPENCV", 8, 8, [5, 5, 4, 4] + [0.0] * 8)]
IMGS = [(1, [1, 0, 0, 0], [0, 0, 0], 1, "a.png", [(1.5, 2.5, 1), (3.0, 4.0, -1)]),
        (2, [0.7071, 0.7071, 0, 0], [1, 2, 3], 2, "dir/b c.jpg", []),
        (3, [0.5, 0.5, 0.5, 0.5], [-1, 0, 2], 3, "c.png", [(0.0, 0.0, 2)])]
PTS = [(1, [0.1, 0.2, 0.3], [255, 0, 10], 0.5, [(1, 0)]), (2, [1, 2, 3], [1, 2, 3], 1.25, [(1, 1), (3, 0)]),
       (3, [-1, 0, 4], [0, 0, 0], 0.0, [])]


def cams_bin(cams):
    b = struct.pack("<Q", len(cams))
    for cid, m, w, h, p in cams:
        b += struct.pack("<iiQQ", cid, MODELS[m][0], w, h) + struct.pack("<%dd" % len(p), *p)
    return b


def imgs_bin(imgs):
    b = struct.pack("<Q", len(imgs))
    for iid, q, t, cid, name, pts in imgs:
        b += struct.pack("<I4d3dI", iid, *q, *t, cid) + name.encode() + b"\0" + struct.pack("<Q", len(pts))
        for x, y, pid in pts:
            b += struct.pack("<ddq", x, y, pid)
    return b


def pts_bin(pts):
    b = struct.pack("<Q", len(pts))
    for pid, xyz, rgb, e, track in pts:
        b += struct.pack("<Q3d3BdQ", pid, *xyz, *rgb, e, len(track))
        for t in track:
            b += struct.pack("<II", *t)
    return b


def cams_txt(cams):
    s = "# Camera list with one line of data per camera:\n#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n"
    return s + "".join("%d %s %d %d %s\n" % (c, m, w, h, " ".join(repr(float(x)) for x in p)) for c, m, w, h, p in cams)


def imgs_txt(imgs):
    s = "# Image list with two lines of data per image:\n"
    for iid, q, t, cid, name, pts in imgs:
        s += "%d %s %s %d %s\n" % (iid, " ".join(map(str, q)), " ".join(map(str, t)), cid, name)
        s += " ".join("%r %r %d" % p for p in pts) + "\n"
    return s


def pts_txt(pts):
    return "# 3D point list\n" + "".join(
        "%d %s %s %r%s\n" % (pid, " ".join(map(str, xyz)), " ".join(map(str, rgb)), e,
                             "".join(" %d %d" % t for t in track)) for pid, xyz, rgb, e, track in pts)


# ---- splat PLY -------------------------------------------------------------------------------
def ply(n, degree=0, sem=0, ascii=False, double=False, extra_before=False, order=None):
    K = (degree + 1) ** 2
    props = ["x", "y", "z", "nx", "ny", "nz", "f_dc_0", "f_dc_1", "f_dc_2"]
    props += ["f_rest_%d" % i for i in range(3 * (K - 1))]
    props += ["opacity", "scale_0", "scale_1", "scale_2", "rot_0", "rot_1", "rot_2", "rot_3"]
    props += ["f_sem_%d" % i for i in range(sem)]
    if order == "reversed":
        props = props[::-1]
    t = "double" if double else "float"
    h = "ply\nformat %s 1.0\ncomment seed\n" % ("ascii" if ascii else "binary_little_endian")
    if extra_before:
        h += "element camera 1\nproperty float fx\nproperty uchar id\n"
    h += "element vertex %d\n" % n + "".join("property %s %s\n" % (t, p) for p in props) + "end_header\n"
    rows = []
    for i in range(n):
        vals = []
        for p in props:
            v = 0.1 * i + 0.01 * len(p)
            if p == "rot_0":
                v = 1.0
            vals.append(v)
        rows.append(vals)
    if ascii:
        body = ("1.5 7\n" if extra_before else "") + "".join(" ".join("%g" % v for v in r) + "\n" for r in rows)
        return h.encode() + body.encode()
    fmt = "<%d%s" % (len(props), "d" if double else "f")
    body = (struct.pack("<fB", 1.5, 7) if extra_before else b"") + b"".join(struct.pack(fmt, *r) for r in rows)
    return h.encode() + body


# ---- images ----------------------------------------------------------------------------------
def png(w, h, ctype, depth, rows, plte=None, trns=None, interlace=0):
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)
    raw = b"".join(b"\0" + r for r in rows)
    out = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, depth, ctype, 0, 0, interlace))
    if plte:
        out += chunk(b"PLTE", plte)
    if trns:
        out += chunk(b"tRNS", trns)
    return out + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")


def npy(descr, shape, data, fortran=False, version=1):
    d = "{'descr': '%s', 'fortran_order': %s, 'shape': (%s), }" % (
        descr, "True" if fortran else "False", "".join("%d," % s for s in shape) if len(shape) == 1 else ", ".join(map(str, shape)))
    pre = 10 if version == 1 else 12
    total = (pre + len(d) + 1 + 63) // 64 * 64
    d = d + " " * (total - pre - len(d) - 1) + "\n"
    head = b"\x93NUMPY" + bytes([version, 0]) + (struct.pack("<H", len(d)) if version == 1 else struct.pack("<I", len(d)))
    return head + d.encode() + data


def safetensors(tensors, meta=None):
    hdr, off, blob = {}, 0, b""
    if meta:
        hdr["__metadata__"] = meta
    for name, dt, shape, data in tensors:
        hdr[name] = {"dtype": dt, "shape": shape, "data_offsets": [off, off + len(data)]}
        off += len(data)
        blob += data
    j = json.dumps(hdr, separators=(",", ":")).encode()
    j += b" " * ((8 - len(j) % 8) % 8)
    return struct.pack("<Q", len(j)) + j + blob


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build")
    cli = os.path.join(os.path.abspath(build), "semsplat")
    clear_seeds()
    tmp = tempfile.mkdtemp(prefix="sp-seeds-")
    try:
        run = lambda *a: subprocess.run([cli, *a, "--quiet"], check=True, cwd=tmp)
        run("synth", "--world", os.path.join(FIX, "tiny.world"), "--model-path", os.path.join(FIX, "models"),
            "--out", "cap", "--views", "4", "--size", "32x24", "--points", "12")
        run("train", "--colmap", "cap", "--out", "model", "--steps", "20", "--sh-degree", "1", "--device", "cpu")
        run("features", "--colmap", "cap", "--out", "feat", "--source", "labels", "--dim", "4")
        run("lift", "--model", "model", "--features", "feat")
        run("train", "--colmap", "cap", "--out", "ck", "--steps", "2", "--init", "random", "--init-points", "3",
            "--sh-degree", "1", "--checkpoint-every", "1", "--no-densify", "--device", "cpu")
        real = lambda p: read(os.path.join(tmp, p))
        put("checkpoint", "real_3_gaussians", real("ck/checkpoints/checkpoint.bin"))
        # COLMAP (binary: the real capture and hand-made models; text: the same as text)
        for i, f in enumerate(["cameras", "images", "points3D"]):
            put("colmap_bin", "real_" + f, bytes([i]) + real("cap/sparse/0/%s.bin" % f))
        put("colmap_bin", "cameras", b"\0" + cams_bin(CAMS))
        put("colmap_bin", "images", b"\1" + imgs_bin(IMGS))
        put("colmap_bin", "points3D", b"\2" + pts_bin(PTS))
        put("colmap_txt", "cameras", b"\0" + cams_txt(CAMS).encode())
        put("colmap_txt", "images", b"\1" + imgs_txt(IMGS).encode())
        put("colmap_txt", "points3D", b"\2" + pts_txt(PTS).encode())
        put("colmap_txt", "images_crlf", b"\1" + imgs_txt(IMGS[:1]).replace("\n", "\r\n").encode())
        # splat PLY
        put("ply", "real_trained", real("model/splat.ply"))
        put("ply", "bin_deg0_sem4", ply(3, 0, 4))
        put("ply", "bin_deg1_double", ply(2, 1, 0, double=True))
        put("ply", "bin_extra_element", ply(2, 0, 0, extra_before=True, order="reversed"))
        put("ply", "ascii_deg0", ply(3, 0, 2, ascii=True))
        put("ply", "ascii_extra_element", ply(2, 1, 0, ascii=True, extra_before=True))
        # PNG: the fixture (Adam7), a real capture image and 16-bit label map, and colour types
        put("png", "adam7", read(os.path.join(ROOT, "tests/fixtures/io/adam7_rgb8_13x11.png")))
        put("png", "real_rgb", real("cap/images/00000.png"))
        put("png", "real_labels16", real("cap/labels/00000.png"))
        put("png", "gray1", png(9, 3, 0, 1, [b"\xa5\x80"] * 3))
        put("png", "gray_alpha", png(2, 2, 4, 8, [b"\x10\xff\x20\x80"] * 2))
        put("png", "palette_trns", png(3, 2, 3, 4, [b"\x01\x20", b"\x12\x00"], plte=b"\xff\0\0\0\xff\0\0\0\xff", trns=b"\x80"))
        put("png", "rgba16", png(1, 2, 6, 16, [bytes(range(8)), bytes(range(8, 16))]))
        # JPEG through ffmpeg's encoder (baseline: 4:2:0, 4:4:4, grey, low quality)
        if shutil.which("ffmpeg"):
            src = os.path.join(tmp, "cap/images/00000.png")
            for name, args in [("yuv420", ["-pix_fmt", "yuvj420p"]), ("yuv444", ["-pix_fmt", "yuvj444p"]),
                               ("gray", ["-pix_fmt", "gray"]), ("q31", ["-pix_fmt", "yuvj422p", "-q:v", "31"])]:
                out = os.path.join(tmp, name + ".jpg")
                subprocess.run(["ffmpeg", "-loglevel", "error", "-y", "-i", src, *args, out], check=True)
                put("jpeg", name, read(out))
        # .npy: fixtures, a real depth map and PCA, and versions 2/3
        for f in sorted(os.listdir(os.path.join(ROOT, "tests/fixtures/io"))):
            if f.endswith(".npy"):
                put("npy", f[:-4], read(os.path.join(ROOT, "tests/fixtures/io", f)))
        put("npy", "real_depth", real("cap/depth/00000.npy"))
        put("npy", "real_map_f16", real("feat/maps/00000.npy"))
        put("npy", "v2_i4", npy("<i4", [2, 2], struct.pack("<4i", 1, -2, 3, -4), version=2))
        put("npy", "v3_u2_fortran", npy("<u2", [2, 3], struct.pack("<6H", *range(6)), fortran=True, version=3))
        put("npy", "empty_dim", npy("<f4", [0, 3], b""))
        # safetensors
        put("safetensors", "small", safetensors([("a", "F32", [2, 2], struct.pack("<4f", 1, 2, 3, 4)),
                                                 ("b.weight", "F16", [3], b"\0\x3c" * 3),
                                                 ("c", "BF16", [1, 1], b"\x80\x3f"), ("d", "I64", [], struct.pack("<q", 7)),
                                                 ("e", "U8", [0], b"")], meta={"format": "pt"}))
        put("safetensors", "all_dtypes", safetensors([(d, d, [2], b"\1" * (2 * s)) for d, s in
                                                      [("F32", 4), ("F16", 2), ("BF16", 2), ("I64", 8), ("I32", 4),
                                                       ("U8", 1), ("F64", 8), ("U16", 2)]]))
        # folder JSON: the real files, and ones sized for tests/fuzz/fuzz_folder.h's folder
        put("features_json", "real", real("feat/features.json"))
        put("features_json", "folder", json.dumps({"format": "semsplat-features-1", "source": "labels", "dim": 4,
                                                  "full_dim": 8, "model": None, "label_embedding": "hash",
                                                  "images": [{"name": "a.png", "map": "maps/a.npy", "height": 2,
                                                              "width": 3, "image_height": 8, "image_width": 12}]}, indent=1))
        put("semantic_json", "real", real("model/semantic.json"))
        put("semantic_json", "folder", json.dumps({"source": "labels", "dim": 4, "full_dim": 8, "pca_mean": "semantic_pca_mean.npy",
                                                  "pca_basis": "semantic_pca_basis.npy", "label_embedding": "hash",
                                                  "model": None, "method": "lift", "colmap": "cap"}, indent=1))
        put("semantic_json", "clip_model", json.dumps({"pca_mean": "pca_mean.npy", "pca_basis": "/nonexistent/b.npy",
                                                      "label_embedding": "clip", "model": "m.safetensors"}))
        put("train_json", "real", real("model/train.json"))
        put("train_json", "top_level", json.dumps({"colmap_dir": "cap", "psnr": 20.5}))
        put("train_json", "settings_data", json.dumps({"settings": {"data": "somewhere", "steps": 10}}))
        put("labels_json", "real", real("cap/labels.json"))
        put("labels_json", "array", json.dumps({"labels": [{"id": 1, "class": "chair"}, {"id": 7, "model": "table_2"},
                                                           {"id": 3, "name": "lamp"}]}))
        # frame.json (real, scaled and rotated align frames), ground_truth.json, the region table
        put("frame_json", "real", real("model/frame.json") if os.path.exists(os.path.join(tmp, "model/frame.json")) else real("cap/frame.json"))
        put("frame_json", "align_fit", json.dumps({"format": "semsplat-frame-1", "source": "align", "frame": "world",
                                                   "world_from_model": [[0, -2, 0, 1.5], [2, 0, 0, -3], [0, 0, 2, 0.25], [0, 0, 0, 1]],
                                                   "up": "+z", "units": "m", "residual_m": 0.02, "note": "semsplat align",
                                                   "fit": {"inliers": 4, "rms_m": 0.02}}))
        put("frame_json", "colmap", json.dumps({"format": "semsplat-frame-1", "source": "colmap", "frame": "colmap",
                                                "world_from_model": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
                                                "up": "unknown", "units": "unknown", "residual_m": None, "note": ""}))
        put("ground_truth_json", "real", real("cap/ground_truth.json"))
        put("ground_truth_json", "centre", json.dumps({"world": "w.world", "objects": [
            {"name": "chair_1", "class": "chair", "aabb_min": [0, 0, 0], "aabb_max": [1, 1, 1], "aabb_center": [0.5, 0.5, 0.5]},
            {"name": "lamp", "class": "lamp", "aabb_min": [-1, 2, 0], "aabb_max": [-0.5, 2.5, 1.8]}]}))
        put("regions_json", "bundled", read(os.path.join(ROOT, "data/semantic/regions.json")))
        put("regions_json", "small", json.dumps({"_comment": "x", "kitchen": ["refrigerator", "oven"], "office": ["desk"]}))
        # CLIP: the tiny fixture config cut to the harness's vocabulary, plus preprocessing keys
        cfg = json.loads(read(os.path.join(ROOT, "tests/fixtures/clip/tiny/config.json")))
        cfg["text_config"]["vocab_size"] = 64
        put("clip_config", "tiny", json.dumps(cfg, indent=1))
        cfg.update({"image_mean": [0.48, 0.45, 0.4], "image_std": [0.26, 0.26, 0.27]})
        cfg["text_config"]["hidden_act"] = "gelu"
        put("clip_config", "tiny_preprocessor", json.dumps(cfg))
        put("clip_config", "real_b16", read(os.path.join(ROOT, "data/clip/config-vit-base-patch16.json")))
        # tokenizer: the fixture texts and hard cases
        texts = json.loads(read(os.path.join(ROOT, "tests/fixtures/clip/tiny/texts.json")))
        if isinstance(texts, dict):
            texts = texts.get("texts", list(texts.values()))
        for i, t in enumerate(texts[:6]):
            put("tokenizer", "text%d" % i, t if isinstance(t, str) else json.dumps(t))
        put("tokenizer", "unicode", "Caf\u00e9 na\u00efve \u00c5ngstr\u00f6m \u6f22\u5b57 \U0001F600 don't  I'M  x\u0301")
        put("tokenizer", "invalid_utf8", b"a \xff\xfe b \xc3 c \xe2\x82 d \xed\xa0\x80")
        put("tokenizer", "long", "a chair next to the table " * 20)
        # SDF: the tiny world, a single-model file, and SDF 1.9 / degrees / quat poses
        put("sdf", "tiny_world", read(os.path.join(FIX, "tiny.world")))
        put("sdf", "model_file", read(os.path.join(FIX, "models/ball/model.sdf")))
        put("sdf", "poses", """<?xml version="1.0"?>
<sdf version="1.9"><world name="w">
 <light name="spot" type="spot"><pose>0 0 2 0 0 0</pose><spot><inner_angle>0.3</inner_angle><outer_angle>0.6</outer_angle><falloff>1</falloff></spot><attenuation><range>10</range><linear>0.1</linear></attenuation></light>
 <model name="a"><pose degrees="true">1 0 0 0 0 90</pose><link name="l"><visual name="v"><pose>0 0 0 0 0 0 1</pose>
  <geometry><plane><normal>0 0 1</normal><size>2 2</size></plane></geometry><transparency>0.5</transparency>
  <material><ambient>0.2 0.3 0.4 1</ambient><emissive>0.1 0 0 1</emissive></material></visual></link>
  <model name="inner"><pose relative_to="l">0 1 0 0 0 0</pose><link name="m"><visual name="c">
  <geometry><capsule><radius>0.1</radius><length>0.3</length></capsule></geometry></visual></link></model></model>
 <include><uri>model://crate</uri><name>c2</name></include>
 <include><uri>model://missing_model</uri></include>
</world></sdf>
""")
        # meshes: the crate OBJ, STL (binary and ascii) and a COLLADA triangle with a texture
        obj = read(os.path.join(FIX, "models/crate/meshes/crate.obj")).replace(b"mtllib crate.mtl\nusemtl crate",
                                                                                b"mtllib m.mtl\nusemtl m")
        put("mesh", "obj_crate", b"o" + obj)
        tri = [((0, 0, 1), (0, 0, 0), (1, 0, 0), (0, 1, 0)), ((0, 0, 1), (1, 0, 0), (1, 1, 0), (0, 1, 0))]
        stl = b"seed".ljust(80, b" ") + struct.pack("<I", len(tri)) + b"".join(
            struct.pack("<12fH", *[c for v in t for c in v], 0) for t in tri)
        put("mesh", "stl_binary", b"s" + stl)
        put("mesh", "stl_ascii", b"s" + ("solid s\n" + "".join(
            "facet normal %g %g %g\n outer loop\n" % t[0] + "".join("  vertex %g %g %g\n" % v for v in t[1:]) +
            " endloop\nendfacet\n" for t in tri) + "endsolid s\n").encode())
        put("mesh", "dae_triangle", b"d" + DAE.encode())
        # LLM bodies (selector byte, tool byte, body) and tool arguments
        oa = {"id": "c1", "object": "chat.completion", "choices": [{"index": 0, "finish_reason": "tool_calls",
              "message": {"role": "assistant", "content": None, "tool_calls": [{"id": "call_1", "type": "function",
              "function": {"name": "query_object_location", "arguments": "{\"object_name\": \"chair\"}"}}]}}],
              "usage": {"prompt_tokens": 10, "completion_tokens": 5}}
        put("agent_llm", "openai_tool_call", b"\0\0" + json.dumps(oa).encode())
        oa2 = {"choices": [{"finish_reason": "stop", "message": {"content": "The chair is in the kitchen."}}]}
        put("agent_llm", "openai_text", b"\0\0" + json.dumps(oa2).encode())
        an = {"id": "m1", "type": "message", "role": "assistant", "stop_reason": "tool_use",
              "content": [{"type": "thinking", "thinking": "...", "signature": "x"}, {"type": "text", "text": "Going."},
                          {"type": "tool_use", "id": "toolu_1", "name": "send_nav2_goal", "input": {"x": 1.5, "y": -2, "yaw": 0.3}}],
              "usage": {"input_tokens": 20, "output_tokens": 7}}
        put("agent_llm", "anthropic_tool_use", b"\1\0" + json.dumps(an).encode())
        put("agent_llm", "error_openai", b"\2\0" + json.dumps({"error": {"message": "Rate limit", "type": "rate_limit_error",
                                                                      "code": "rate_limit_exceeded"}}).encode())
        put("agent_llm", "error_anthropic", b"\2\0" + json.dumps({"type": "error", "error": {"type": "overloaded_error",
                                                                         "message": "Overloaded"}}).encode())
        for tool, args in [(0, {"object_name": "chair"}), (2, {"start": [0, 0], "goal": [1, 2, 0, 1.5], "tolerance_m": 0.5}),
                           (3, {"pose": [1, 2, 0.5, 0.3]}), (4, {"x": 1, "y": 2, "yaw": 0, "plan_id": "p1"}),
                           (5, {"target": "table", "k": 3, "instance": 1}), (6, {"object_name": "sofa", "radius_m": 2}),
                           (7, {"region": "kitchen", "max_waypoints": 4}), (8, {})]:
            put("agent_llm", "args_tool%d" % tool, bytes([3, tool]) + json.dumps(args).encode())
        # Nav2 maps: a map.yaml (selector 0) and a PGM (selector 1)
        put("costmap_yaml", "map_yaml", b"\0image: map.pgm\nresolution: 0.05\norigin: [-1.0, -2.0, 0.0]\nnegate: 0\n"
                                        b"occupied_thresh: 0.65\nfree_thresh: 0.196\nmode: trinary\n")
        put("costmap_yaml", "map_yaml_scale", b"\0image: \"map.pgm\"\nresolution: 0.1\norigin: [0, 0, 1.57]\nnegate: 1\n"
                                              b"occupied_thresh: 0.7\nfree_thresh: 0.2\nmode: scale\n")
        put("costmap_yaml", "pgm_p5", b"\1P5\n# c\n3 2\n255\n" + bytes([0, 128, 255, 254, 10, 205]))
        put("costmap_yaml", "pgm_p2", b"\1P2\n3 2\n15\n0 7 15\n15 3 0\n")
        # ROS samples from the library's own encoders (the harness writes them)
        d = os.path.join(CORPUS, "ros_cdr")
        os.makedirs(d, exist_ok=True)
        subprocess.run([os.path.join(os.path.abspath(build), "fuzz", "fuzz_ros_cdr_replay"), "/dev/null"],
                       env=dict(os.environ, FZ_WRITE_SEEDS=d), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    finally:
        shutil.rmtree(tmp)
    for h in sorted(os.listdir(CORPUS)):
        files = os.listdir(os.path.join(CORPUS, h))
        print("%-16s %3d files, %6d bytes" % (h, len(files), sum(os.path.getsize(os.path.join(CORPUS, h, f)) for f in files)))


DAE = """<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
 <asset><unit name="centimeter" meter="0.01"/><up_axis>Z_UP</up_axis></asset>
 <library_images><image id="img"><init_from>tex.png</init_from></image></library_images>
 <library_effects><effect id="fx"><profile_COMMON>
  <newparam sid="surf"><surface type="2D"><init_from>img</init_from></surface></newparam>
  <newparam sid="samp"><sampler2D><source>surf</source></sampler2D></newparam>
  <technique sid="t"><lambert><diffuse><texture texture="samp" texcoord="uv"/></diffuse></lambert></technique>
 </profile_COMMON></effect></library_effects>
 <library_materials><material id="mat"><instance_effect url="#fx"/></material></library_materials>
 <library_geometries><geometry id="g"><mesh>
  <source id="pos"><float_array id="pa" count="9">0 0 0 100 0 0 0 100 0</float_array>
   <technique_common><accessor source="#pa" count="3" stride="3"><param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>
  <source id="uv"><float_array id="ua" count="6">0 0 1 0 0 1</float_array>
   <technique_common><accessor source="#ua" count="3" stride="2"><param name="S" type="float"/><param name="T" type="float"/></accessor></technique_common></source>
  <vertices id="v"><input semantic="POSITION" source="#pos"/></vertices>
  <triangles material="m" count="1"><input semantic="VERTEX" source="#v" offset="0"/><input semantic="TEXCOORD" source="#uv" offset="1"/><p>0 0 1 1 2 2</p></triangles>
 </mesh></geometry></library_geometries>
 <library_visual_scenes><visual_scene id="s"><node id="n"><matrix>1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1</matrix>
  <instance_geometry url="#g"><bind_material><technique_common><instance_material symbol="m" target="#mat"/></technique_common></bind_material></instance_geometry>
 </node></visual_scene></library_visual_scenes>
 <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
"""

if __name__ == "__main__":
    main()
