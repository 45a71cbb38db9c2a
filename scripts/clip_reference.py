#!/usr/bin/env python3
"""Reference outputs for semsplat's C CLIP, made with torch + Hugging Face transformers on the
GPU machine (nothing is downloaded: random weights with the real shapes, the shipped vocabulary).

  clip_reference.py model --config data/clip/config-vit-base-patch16.json --out DIR [--seed 0]
      a randomly initialised CLIPModel (LayerNorm weights and every bias perturbed so that bugs
      in them show), saved with save_pretrained (model.safetensors + config.json), plus inputs
      and reference outputs as .npy:
        ids.npy [n][77] int32, texts.json         text_embeds.npy [n][P]   (transformers)
        pixels.npy [m][3][S][S]                   image_embeds.npy [m][P]  (transformers)
        pixels_wide.npy [1][3][S][S*3/2]          image_wide.npy [1][P]    (interpolated positions)
        dense_{maskclip,clearclip}.npy [gh*gw][P] dense_wide_{...}.npy     (torch re-implementation
                                                  of the dense head, written here from the weights)
  clip_reference.py tiny --out DIR
      the same for a reduced model (text 32 wide, vision 64 wide, 2 layers, patch 16, 64 px;
      fp16 weights, about 3 MB) kept in tests/fixtures/clip/tiny for CI.
  clip_reference.py bench
      transformers' ViT-B/16 throughput as shared/bench/anchors/bench_clip.py measures it (JSON lines).
  clip_reference.py tokenizer --vocab data/clip --out DIR [--n 12000]
      varied strings (Unicode, punctuation, numbers, empty, very long) and their ids from
      transformers' CLIPTokenizer (add_special_tokens=False) -> tokenizer_pairs_all.json, and a
      few hundred of them -> tokenizer_pairs.json. Ids from other variants available (slow Python
      / fast Rust) are written beside for comparison.
All embeddings are L2-normalised; dense features are L2-normalised per patch."""
import argparse, json, math, os, random, sys

import numpy as np


def log(*a):
    print("[clip_reference]", *a, file=sys.stderr, flush=True)


# ---- model references ---------------------------------------------------------------------------

def interp_pos(pos, g, gh, gw):
    """Position embeddings for a gh x gw grid as transformers' interpolate_pos_encoding does."""
    import torch
    import torch.nn.functional as F
    if gh == g and gw == g:
        return pos
    cls, patch = pos[:1], pos[1:]
    w = pos.shape[-1]
    patch = patch.reshape(1, g, g, w).permute(0, 3, 1, 2)
    patch = F.interpolate(patch, size=(gh, gw), mode="bicubic", align_corners=False)
    patch = patch.permute(0, 2, 3, 1).reshape(gh * gw, w)
    return torch.cat([cls, patch], 0)


def block(L, x, heads, causal=False, mode=0):
    """One CLIP encoder layer from its weights; mode 1 = MaskCLIP (value path), 2 = ClearCLIP
    (q-q attention); both without residual and FFN."""
    import torch
    B, T, w = x.shape
    d = w // heads
    a = L.self_attn
    h = L.layer_norm1(x)
    split = lambda t: t.view(B, T, heads, d).transpose(1, 2)
    q, k, v = split(a.q_proj(h)), split(a.k_proj(h)), split(a.v_proj(h))
    if mode == 1:
        o = v
    else:
        kk = q if mode == 2 else k
        s = q @ kk.transpose(-1, -2) / math.sqrt(d)
        if causal:
            s = s + torch.full((T, T), float("-inf"), device=x.device).triu(1)
        o = s.softmax(-1) @ v
    o = a.out_proj(o.transpose(1, 2).reshape(B, T, w))
    if mode:
        return o
    x = x + o
    return x + L.mlp(L.layer_norm2(x))


def vision_ref(model, px, mode):
    """mode 0: pooled projected embedding [B][P]; 1/2: dense [B][np][P]; all normalised."""
    import torch
    cfg = model.config.vision_config
    vm = model.vision_model
    B, _, H, W = px.shape
    p = cfg.patch_size
    gh, gw, g = H // p, W // p, cfg.image_size // p
    x = vm.embeddings.patch_embedding(px).flatten(2).transpose(1, 2)
    cls = vm.embeddings.class_embedding.expand(B, 1, -1)
    x = torch.cat([cls, x], 1) + interp_pos(vm.embeddings.position_embedding.weight, g, gh, gw)
    x = vm.pre_layrnorm(x)
    layers = vm.encoder.layers
    for L in layers[:-1]:
        x = block(L, x, cfg.num_attention_heads)
    x = block(layers[-1], x, cfg.num_attention_heads, mode=mode)
    if mode == 0:
        e = model.visual_projection(vm.post_layernorm(x[:, 0]))
    else:
        e = model.visual_projection(vm.post_layernorm(x[:, 1:]))
    return torch.nn.functional.normalize(e, dim=-1)


def text_ref(model, ids):
    import torch
    cfg = model.config.text_config
    tm = model.text_model
    T = ids.shape[1]
    x = tm.embeddings.token_embedding(ids) + tm.embeddings.position_embedding.weight[:T]
    for L in tm.encoder.layers:
        x = block(L, x, cfg.num_attention_heads, causal=True)
    x = tm.final_layer_norm(x)
    eos = ids.argmax(-1)
    e = model.text_projection(x[torch.arange(ids.shape[0]), eos])
    return torch.nn.functional.normalize(e, dim=-1)


TEXTS = ["a photo of a cat", "", "A RED mug on the kitchen table, next to 2 chairs!",
         "refrigerator", "the robot's charging dock", "café naïve résumé — 東京 🚀",
         "x " * 60, "bookshelf with books"]


def make_model(cfg_dict, out, seed, dtype_save):
    import torch
    from transformers import CLIPConfig, CLIPModel
    torch.manual_seed(seed)
    cfg = CLIPConfig.from_dict(cfg_dict)
    model = CLIPModel(cfg).eval()
    g = torch.Generator().manual_seed(seed + 1)
    with torch.no_grad():
        for name, p in model.named_parameters():
            if name.endswith("bias"):
                p.copy_(torch.randn(p.shape, generator=g) * 0.02)
            elif "norm" in name and name.endswith("weight"):
                p.copy_(1 + torch.randn(p.shape, generator=g) * 0.1)
            elif "class_embedding" in name:
                p.copy_(torch.randn(p.shape, generator=g) * 0.5)
        if dtype_save == "fp16":  # the references use exactly the stored (rounded) weights
            for p in model.parameters():
                p.copy_(p.half().float())
    os.makedirs(out, exist_ok=True)
    if dtype_save == "fp16":
        model.half().save_pretrained(out)
        model.float()
    else:
        model.save_pretrained(out)
    if not os.path.exists(os.path.join(out, "model.safetensors")):
        log("save_pretrained did not write model.safetensors:", os.listdir(out))
    return model


def references(model, out, tok, dev):
    import torch
    model = model.to(dev)
    cfg = model.config
    S, p = cfg.vision_config.image_size, cfg.vision_config.patch_size
    ids = np.array([tok(t) for t in TEXTS], dtype=np.int32)
    np.save(os.path.join(out, "ids.npy"), ids)
    json.dump(TEXTS, open(os.path.join(out, "texts.json"), "w"), ensure_ascii=False)
    g = torch.Generator().manual_seed(1234)
    px = torch.randn(3, 3, S, S, generator=g)
    wide = torch.randn(1, 3, S, S * 3 // 2 // p * p, generator=g)
    np.save(os.path.join(out, "pixels.npy"), px.numpy())
    np.save(os.path.join(out, "pixels_wide.npy"), wide.numpy())
    res = {}
    with torch.no_grad():
        tid = torch.from_numpy(ids).long().to(dev)
        t_hf = model.text_projection(model.text_model(input_ids=tid).pooler_output)
        t_hf = torch.nn.functional.normalize(t_hf, dim=-1)
        t_me = text_ref(model, tid)
        res["text_hf_vs_reimpl"] = float((t_hf - t_me).abs().max())
        np.save(os.path.join(out, "text_embeds.npy"), t_hf.float().cpu().numpy())
        pxd = px.to(dev)
        i_hf = model.visual_projection(model.vision_model(pixel_values=pxd).pooler_output)
        i_hf = torch.nn.functional.normalize(i_hf, dim=-1)
        i_me = vision_ref(model, pxd, 0)
        res["image_hf_vs_reimpl"] = float((i_hf - i_me).abs().max())
        np.save(os.path.join(out, "image_embeds.npy"), i_hf.float().cpu().numpy())
        wd = wide.to(dev)
        w_me = vision_ref(model, wd, 0)
        try:
            w_hf = model.visual_projection(model.vision_model(pixel_values=wd, interpolate_pos_encoding=True).pooler_output)
            w_hf = torch.nn.functional.normalize(w_hf, dim=-1)
            res["wide_hf_vs_reimpl"] = float((w_hf - w_me).abs().max())
        except Exception as e:  # older/newer transformers without the flag
            res["wide_hf_error"] = str(e)[:200]
            w_hf = w_me
        np.save(os.path.join(out, "image_wide.npy"), w_hf.float().cpu().numpy())
        for mode, name in ((1, "maskclip"), (2, "clearclip")):
            np.save(os.path.join(out, f"dense_{name}.npy"), vision_ref(model, pxd[:1], mode)[0].float().cpu().numpy())
            np.save(os.path.join(out, f"dense_wide_{name}.npy"), vision_ref(model, wd, mode)[0].float().cpu().numpy())
    json.dump(res, open(os.path.join(out, "checks.json"), "w"), indent=1)
    log("reference checks", res)
    return res


def make_clip_tokenizer(vocab_dir, cls=None):
    if cls is None:
        from transformers import CLIPTokenizer as cls
    try:
        return cls(os.path.join(vocab_dir, "vocab.json"), os.path.join(vocab_dir, "merges.txt"))
    except Exception as e:
        log(cls.__name__, "from files failed:", str(e)[:200], "- trying from_pretrained")
        return cls.from_pretrained(vocab_dir)


def load_tokenizer(vocab_dir):
    """transformers' CLIPTokenizer on the shipped vocabulary, with padding to 77."""
    t = make_clip_tokenizer(vocab_dir)
    def enc(text):
        ids = t(text, padding="max_length", max_length=77, truncation=True)["input_ids"]
        return ids
    return t, enc


# ---- tokenizer strings --------------------------------------------------------------------------

def varied_strings(n, seed, vocab_words):
    r = random.Random(seed)
    fixed = ["", " ", "   ", "\t\n", "a", "A", "a photo of a cat", "A PHOTO OF A CAT", "don't", "DON'T",
             "I'm we'll they've she'd it's you're", "''s", "'S'T", "hello, world!", "!!!???...",
             "3.14159", "1,000,000", "12345678901234567890", "4th 2nd 1st", "x²", "Ⅻ", "½", "٣",
             "<|startoftext|>", "<|endoftext|>", "a<|endoftext|>b", "<|ENDOFTEXT|>", "<|endof text|>",
             "café", "cafe\u0301", "naïve", "Ångström", "ΟΔΟΣ ΣΑΣ", "ὈΔΥΣΣΕΎΣ", "İstanbul", "ß", "ǅ", "ﬁne",
             "ＡＢＣ１２３", "東京タワー", "你好世界", "한국어", "\u1100\u1161\u11a8", "Привет мир", "مرحبا",
             "नमस्ते", "🚀🚀 rocket", "👨‍👩‍👧", "zero\u200bwidth", "bom\ufeff", "nbsp\u00a0here",
             "ideo\u3000space", "line\u2028sep", "tab\there", "ctrl\x07bell\x00nul\x1b", "\x85next",
             "\ufffdreplacement", "a\u0301\u0327", "q\u0307\u0323", "e\u0328\u0301", "\u212b", "\u2126",
             "https://example.com/path?q=1&x=2", "def f(x): return x**2  # code", "C++ and C#",
             "email@example.org", "#hashtag @user", "$100.00 €50 £20 ¥1000", "50% off!!",
             "(parentheses) [brackets] {braces}", "\"quoted\" 'single'", "— – - ‐", "…", "¿Qué?", "¡Hola!",
             "a" * 300, "ab " * 200, "🙂" * 50, "Ω" * 100, "1" * 120, "word" * 80]
    out = list(fixed)
    pools = [
        lambda: " ".join(r.choice(vocab_words) for _ in range(r.randint(1, 12))),
        lambda: "".join(r.choice(vocab_words) for _ in range(r.randint(1, 6))),
        lambda: "".join(chr(r.randint(0x20, 0x7e)) for _ in range(r.randint(1, 40))),
        lambda: "".join(chr(r.randint(0xa0, 0x24f)) for _ in range(r.randint(1, 20))),
        lambda: "".join(chr(r.choice([r.randint(0x370, 0x3ff), r.randint(0x400, 0x4ff), r.randint(0x590, 0x6ff),
                                      r.randint(0x900, 0x97f), r.randint(0x3040, 0x30ff), r.randint(0x4e00, 0x9fff),
                                      r.randint(0xac00, 0xd7a3), r.randint(0x1f300, 0x1faff), r.randint(0x2000, 0x206f),
                                      r.randint(0x300, 0x36f), r.randint(0xff00, 0xffef), r.randint(0x2460, 0x24ff)]))
                        for _ in range(r.randint(1, 25))),
        lambda: "".join(chr(c) for c in (r.randint(1, 0x2ffff) for _ in range(r.randint(1, 30)))
                        if not 0xd800 <= c <= 0xdfff),
        lambda: " ".join(str(r.randint(0, 10 ** r.randint(1, 12))) + r.choice(["", ".", ",", "%", "th", "kg", "m²"])
                         for _ in range(r.randint(1, 6))),
        lambda: r.choice(vocab_words).upper() + r.choice(["'s", "'T", "'re", "'VE", "'m", "'ll", "'d", "'x"]) +
                r.choice(["", " ", "!", "?"]) + r.choice(vocab_words),
        lambda: r.choice(["\t", "\n", "  ", "\r\n", "\u00a0", "\u3000", "\u2009", "\x0b", "\x0c"]).join(
            r.choice(vocab_words).capitalize() for _ in range(r.randint(1, 8))),
        lambda: " ".join(r.choice(vocab_words) for _ in range(r.randint(60, 200))),
    ]
    while len(out) < n:
        out.append(r.choice(pools)())
    return out


def tokenizer_pairs(vocab_dir, out, n, keep):
    os.makedirs(out, exist_ok=True)
    vocab = json.load(open(os.path.join(vocab_dir, "vocab.json"), encoding="utf-8"))
    # words: vocabulary entries that end a word, mapped back from the byte alphabet
    bs = list(range(ord("!"), ord("~") + 1)) + list(range(ord("¡"), ord("¬") + 1)) + list(range(ord("®"), ord("ÿ") + 1))
    cs = bs[:]
    k = 0
    for b in range(256):
        if b not in bs:
            bs.append(b); cs.append(256 + k); k += 1
    dec = {chr(c): b for b, c in zip(bs, cs)}
    words = []
    for tkn in vocab:
        if tkn.endswith("</w>") and len(tkn) > 4:
            try:
                words.append(bytes(dec[ch] for ch in tkn[:-4]).decode("utf-8"))
            except Exception:
                pass
    strings = varied_strings(n, 7, words)
    variants = {}
    t = make_clip_tokenizer(vocab_dir)
    variants["CLIPTokenizer"] = (type(t).__module__ + "." + type(t).__name__,
                                 lambda s: t(s, add_special_tokens=False)["input_ids"])
    try:
        from transformers import CLIPTokenizerFast
        tf = make_clip_tokenizer(vocab_dir, CLIPTokenizerFast)
        variants["CLIPTokenizerFast"] = (type(tf).__module__, lambda s: tf(s, add_special_tokens=False)["input_ids"])
    except Exception as e:
        log("no CLIPTokenizerFast:", str(e)[:200])
    try:
        from transformers.models.clip import tokenization_clip as tc
        from transformers.models.bert.tokenization_bert import BasicTokenizer
        ts = make_clip_tokenizer(vocab_dir, tc.CLIPTokenizer)
        if not hasattr(ts, "nlp") and not hasattr(ts, "fix_text"):
            raise RuntimeError("tokenization_clip.CLIPTokenizer is not the Python one here")
        if getattr(ts, "fix_text", None) is not None:  # ftfy installed: use the documented fallback
            ts.nlp = BasicTokenizer(strip_accents=False, do_split_on_punc=False)
            ts.fix_text = None
        variants["slow_basic"] = (type(ts).__module__, lambda s: ts(s, add_special_tokens=False)["input_ids"])
    except Exception as e:
        log("no slow tokenizer:", str(e)[:200])
    meta = {}
    for name, (cls, fn) in variants.items():
        ids = []
        for s in strings:
            try:
                ids.append(fn(s))
            except Exception as e:
                ids.append(None)
        pairs = [[s, i] for s, i in zip(strings, ids) if i is not None]
        json.dump(pairs, open(os.path.join(out, f"tokenizer_pairs_all_{name}.json"), "w"), ensure_ascii=False)
        meta[name] = {"class": cls, "pairs": len(pairs)}
        if name == "CLIPTokenizer":
            json.dump(pairs, open(os.path.join(out, "tokenizer_pairs_all.json"), "w"), ensure_ascii=False)
            step = max(1, len(pairs) // keep)
            ok = [p for p in pairs if "\x00" not in p[0]]  # C strings cannot carry U+0000
            sub = ok[:90] + [p for p in ok[90::step] if len(p[0]) < 400][: keep - 90]
            json.dump(sub, open(os.path.join(out, "tokenizer_pairs.json"), "w"), ensure_ascii=False, indent=0)
    # how the variants differ from each other
    names = list(variants)
    for a in names:
        for b in names:
            if a < b:
                pa = json.load(open(os.path.join(out, f"tokenizer_pairs_all_{a}.json")))
                pb = json.load(open(os.path.join(out, f"tokenizer_pairs_all_{b}.json")))
                db = {s: i for s, i in pb}
                meta[f"{a}_vs_{b}_differ"] = sum(1 for s, i in pa if s in db and db[s] != i)
    json.dump(meta, open(os.path.join(out, "tokenizer_meta.json"), "w"), indent=1)
    log("tokenizer", meta)


def bench_transformers():
    """transformers CLIPModel ViT-B/16 throughput, exactly as shared/bench/anchors/bench_clip.py
    measures it (that file does not travel to the GPU machine): random weights, get_image_features
    / get_text_features under no_grad, median of 10 after 3 warm-ups. Prints JSON lines."""
    import time
    import torch
    from transformers import CLIPConfig, CLIPModel
    cfg = CLIPConfig(
        text_config=dict(hidden_size=512, intermediate_size=2048, num_attention_heads=8, num_hidden_layers=12,
                         max_position_embeddings=77, vocab_size=49408),
        vision_config=dict(hidden_size=768, intermediate_size=3072, num_attention_heads=12, num_hidden_layers=12,
                           image_size=224, patch_size=16),
        projection_dim=512)
    torch.manual_seed(0)
    base = CLIPModel(cfg).cuda().eval()

    def timeit(fn, warm=3, reps=10):
        for _ in range(warm): fn()
        torch.cuda.synchronize(); ts = []
        for _ in range(reps):
            t = time.perf_counter(); fn(); torch.cuda.synchronize(); ts.append(time.perf_counter() - t)
        ts.sort(); return ts[len(ts) // 2]

    print(json.dumps(dict(what="env", torch=torch.__version__, gpu=torch.cuda.get_device_name())), flush=True)
    for dtype in (torch.float32, torch.float16):
        m = base.to(dtype)
        for b in (1, 32, 128):
            x = torch.randn(b, 3, 224, 224, device="cuda", dtype=dtype)
            with torch.no_grad():
                s = timeit(lambda: m.get_image_features(pixel_values=x))
            print(json.dumps(dict(what="clip_image", dtype=str(dtype), batch=b, ms=round(s * 1e3, 3), img_per_s=round(b / s, 1))), flush=True)
        ids = torch.randint(0, 49406, (256, 77), device="cuda")
        with torch.no_grad():
            s = timeit(lambda: m.get_text_features(input_ids=ids))
        print(json.dumps(dict(what="clip_text", dtype=str(dtype), batch=256, ms=round(s * 1e3, 3), text_per_s=round(256 / s, 1))), flush=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("what", choices=["model", "tiny", "tokenizer", "bench"])
    ap.add_argument("--config", default="data/clip/config-vit-base-patch16.json")
    ap.add_argument("--vocab", default="data/clip")
    ap.add_argument("--out", default="")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--n", type=int, default=12000)
    ap.add_argument("--keep", type=int, default=300)
    ap.add_argument("--device", default="cuda")
    a = ap.parse_args()
    if a.what == "bench":
        return bench_transformers()
    if not a.out:
        ap.error("--out is required for " + a.what)
    if a.what == "tokenizer":
        return tokenizer_pairs(a.vocab, a.out, a.n, a.keep)
    import torch
    dev = a.device if (a.device != "cuda" or torch.cuda.is_available()) else "cpu"
    torch.backends.cuda.matmul.allow_tf32 = False
    torch.backends.cudnn.allow_tf32 = False
    if a.what == "model":
        cfg = json.load(open(a.config))
        model = make_model(cfg, a.out, a.seed, "fp32")
    else:
        cfg = {"model_type": "clip", "projection_dim": 32,
               "text_config": {"hidden_size": 32, "intermediate_size": 64, "num_attention_heads": 2,
                               "num_hidden_layers": 2, "max_position_embeddings": 77, "vocab_size": 49408,
                               "hidden_act": "quick_gelu", "eos_token_id": 2, "bos_token_id": 0},
               "vision_config": {"hidden_size": 64, "intermediate_size": 128, "num_attention_heads": 2,
                                 "num_hidden_layers": 2, "image_size": 64, "patch_size": 16,
                                 "hidden_act": "quick_gelu"}}
        model = make_model(cfg, a.out, a.seed + 100, "fp16")
    try:
        _, enc = load_tokenizer(a.vocab)
    except Exception as e:
        log("tokenizer unavailable, ids from the shipped fallback:", str(e)[:200])
        enc = None
    if enc is None:
        raise SystemExit(1)
    references(model, a.out, enc, dev)


if __name__ == "__main__":
    main()
