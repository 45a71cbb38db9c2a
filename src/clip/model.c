/* Loading a Hugging Face CLIPModel checkpoint (config.json + model.safetensors) into f32 host
 * arrays, checking every tensor's presence and shape against the config, and the public encode
 * calls, which dispatch to the CPU (cpu.c) or GPU (clip_gpu.c) forward. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cJSON.h>

#include "clip_internal.h"
#include "semsplat/io.h"

/* ---- config ------------------------------------------------------------------------------------ */

static void tower_defaults(sp_clip_tower_config *t, int width, int layers, int heads, int mlp)
{
    t->width = width;
    t->layers = layers;
    t->heads = heads;
    t->mlp = mlp;
    t->quick_gelu = 1;
    t->eps = 1e-5f;
}

static void config_defaults(sp_clip_config *c)
{
    memset(c, 0, sizeof *c);
    tower_defaults(&c->text, 512, 12, 8, 2048);
    tower_defaults(&c->vision, 768, 12, 12, 3072);
    c->vocab_size = 49408;
    c->context = 77;
    c->eos_token_id = 2;
    c->patch_size = 16;
    c->image_size = 224;
    c->projection_dim = 512;
    const float mean[3] = {0.48145466f, 0.4578275f, 0.40821073f};
    const float std[3] = {0.26862954f, 0.26130258f, 0.27577711f};
    memcpy(c->image_mean, mean, sizeof mean);
    memcpy(c->image_std, std, sizeof std);
}

/* Reads an integer field if present; fails on a non-number or a value out of range. */
static int cfg_int(const cJSON *o, const char *key, int *out, int lo, int hi, const char *path,
                   const char *sect, sp_error *err)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    if (!v) return 0;
    long x;
    if (sp_json_int(v, lo, hi, &x))
        return sp_error_set(err, SP_E_FORMAT, "%s: %s%s must be an integer in [%d, %d]", path,
                            sect, key, lo, hi);
    *out = (int)x;
    return 0;
}

static int parse_tower(const cJSON *o, sp_clip_tower_config *t, const char *path,
                       const char *sect, sp_error *err)
{
    int rc;
    if (!o) return 0;
    if (!cJSON_IsObject(o)) return sp_error_set(err, SP_E_FORMAT, "%s: %s is not an object", path, sect);
    if ((rc = cfg_int(o, "hidden_size", &t->width, 8, 16384, path, sect, err)) ||
        (rc = cfg_int(o, "num_hidden_layers", &t->layers, 1, 256, path, sect, err)) ||
        (rc = cfg_int(o, "num_attention_heads", &t->heads, 1, 256, path, sect, err)) ||
        (rc = cfg_int(o, "intermediate_size", &t->mlp, 1, 65536, path, sect, err)))
        return rc;
    const cJSON *act = cJSON_GetObjectItemCaseSensitive(o, "hidden_act");
    if (act) {
        if (cJSON_IsString(act) && !strcmp(act->valuestring, "quick_gelu")) t->quick_gelu = 1;
        else if (cJSON_IsString(act) && !strcmp(act->valuestring, "gelu")) t->quick_gelu = 0;
        else
            return sp_error_set(err, SP_E_UNSUPPORTED, "%s: %shidden_act '%s' (quick_gelu or gelu)",
                                path, sect, cJSON_IsString(act) ? act->valuestring : "?");
    }
    const cJSON *eps = cJSON_GetObjectItemCaseSensitive(o, "layer_norm_eps");
    if (eps) {
        if (!cJSON_IsNumber(eps) || !(eps->valuedouble > 0) || eps->valuedouble > 1)
            return sp_error_set(err, SP_E_FORMAT, "%s: %slayer_norm_eps invalid", path, sect);
        t->eps = (float)eps->valuedouble;
    }
    if (t->width % t->heads)
        return sp_error_set(err, SP_E_FORMAT, "%s: %shidden_size %d not divisible by %d heads",
                            path, sect, t->width, t->heads);
    return 0;
}

static int parse_config(const char *path, sp_clip_config *c, sp_error *err)
{
    cJSON *root = NULL;
    int rc = sp_json_read_file(path, &root, err);
    if (rc) return rc;
    if (!cJSON_IsObject(root)) {
        cJSON_Delete(root);
        return sp_error_set(err, SP_E_FORMAT, "%s: not a JSON object", path);
    }
    const cJSON *tc = cJSON_GetObjectItemCaseSensitive(root, "text_config");
    const cJSON *vc = cJSON_GetObjectItemCaseSensitive(root, "vision_config");
    const cJSON *mt = cJSON_GetObjectItemCaseSensitive(root, "model_type");
    if (!tc || !vc) {
        rc = sp_error_set(err, SP_E_FORMAT, "%s: needs text_config and vision_config (a CLIPModel "
                          "config.json)", path);
    } else if (mt && cJSON_IsString(mt) && strcmp(mt->valuestring, "clip")) {
        rc = sp_error_set(err, SP_E_UNSUPPORTED, "%s: model_type '%s', expected 'clip'", path,
                          mt->valuestring);
    } else if (!(rc = parse_tower(tc, &c->text, path, "text_config.", err)) &&
               !(rc = parse_tower(vc, &c->vision, path, "vision_config.", err)) &&
               !(rc = cfg_int(tc, "vocab_size", &c->vocab_size, 2, 1 << 24, path, "text_config.", err)) &&
               !(rc = cfg_int(tc, "max_position_embeddings", &c->context, 2, 4096, path, "text_config.", err)) &&
               !(rc = cfg_int(tc, "eos_token_id", &c->eos_token_id, 0, 1 << 24, path, "text_config.", err)) &&
               !(rc = cfg_int(vc, "patch_size", &c->patch_size, 1, 1024, path, "vision_config.", err)) &&
               !(rc = cfg_int(vc, "image_size", &c->image_size, 1, 16384, path, "vision_config.", err)) &&
               !(rc = cfg_int(root, "projection_dim", &c->projection_dim, 1, 65536, path, "", err))) {
        int nc = 3;
        if (!(rc = cfg_int(vc, "num_channels", &nc, 1, 16, path, "vision_config.", err)) && nc != 3)
            rc = sp_error_set(err, SP_E_UNSUPPORTED, "%s: vision_config.num_channels %d (3 only)", path, nc);
        if (!rc && c->image_size % c->patch_size)
            rc = sp_error_set(err, SP_E_FORMAT, "%s: image_size %d not a multiple of patch_size %d",
                              path, c->image_size, c->patch_size);
    }
    cJSON_Delete(root);
    return rc;
}

/* image_mean / image_std: absent keeps OpenAI's defaults; present must be 3 finite numbers (std
 * positive: pixels are divided by it). */
static int preprocessor_triple(const char *path, const cJSON *root, const char *key, int positive, float out[3],
                               sp_error *err)
{
    const cJSON *a = cJSON_GetObjectItemCaseSensitive(root, key);
    if (!a) return 0;
    float v[3];
    int ok = cJSON_IsArray(a) && cJSON_GetArraySize(a) == 3;
    for (int i = 0; ok && i < 3; i++) {
        const cJSON *x = cJSON_GetArrayItem(a, i);
        ok = cJSON_IsNumber(x) && fabs(x->valuedouble) < 1e30 && (!positive || x->valuedouble > 1e-30);
        if (ok) v[i] = (float)x->valuedouble;
    }
    if (!ok)
        return sp_error_set(err, SP_E_FORMAT, "%s: %s must be 3 %snumbers", path, key,
                            positive ? "positive " : "");
    memcpy(out, v, sizeof v);
    return 0;
}

/* preprocessor_config.json beside the weights, when there is one. */
static int parse_preprocessor(const char *path, sp_clip_config *c, sp_error *err)
{
    if (!sp_file_exists(path)) return 0;
    cJSON *root = NULL;
    int rc = sp_json_read_file(path, &root, err);
    if (rc) return rc;
    if (!(rc = preprocessor_triple(path, root, "image_mean", 0, c->image_mean, err)))
        rc = preprocessor_triple(path, root, "image_std", 1, c->image_std, err);
    cJSON_Delete(root);
    return rc;
}

/* ---- tensors ------------------------------------------------------------------------------------ */

typedef struct loader {
    const sp_safetensors *st;
    const char *path;
    float *blob;
    size_t used, cap;
    int measuring; /* first pass: only count */
    sp_error *err;
    int rc;
    uint64_t rng;  /* st == NULL: random weights (benchmarks) */
} loader;

/* Random weights with roughly CLIP's scales: LayerNorm weights near 1, the rest small. */
static void fill_random(loader *L, const char *name, float *dst, size_t count, size_t fan_in)
{
    int is_norm_w = strstr(name, "norm") && strstr(name, ".weight");
    float scale = strstr(name, "bias") ? 0.02f : fan_in > 1 ? 1.0f / sqrtf((float)fan_in) : 0.5f;
    for (size_t i = 0; i < count; i++) {
        uint64_t z = (L->rng += 0x9E3779B97F4A7C15ULL);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        z ^= z >> 31;
        float u = (float)((double)(z >> 11) / 9007199254740992.0) * 2.f - 1.f;
        dst[i] = (is_norm_w ? 1.f : 0.f) + scale * u * (is_norm_w ? 0.1f : 1.f);
    }
}

static void fmt_shape(char *out, size_t cap, const size_t *shape, int ndim)
{
    size_t l = 0;
    out[0] = 0;
    for (int i = 0; i < ndim && l + 24 < cap; i++)
        l += (size_t)snprintf(out + l, cap - l, "%s%zu", i ? ", " : "[", shape[i]);
    snprintf(out + l, cap - l, "]");
}

/* Finds tensor `name` with the expected shape (ndim dims, 0 = any) and converts it to f32. */
static const float *take(loader *L, const char *name, int ndim, size_t d0, size_t d1, size_t d2,
                         size_t d3)
{
    if (L->rc) return NULL;
    size_t want[4] = {d0, d1, d2, d3};
    if (!L->st) {
        size_t count = 1;
        for (int i = 0; i < ndim; i++) count *= want[i];
        size_t at = L->used;
        L->used += (count + 15) & ~(size_t)15;
        if (L->measuring) return NULL;
        fill_random(L, name, L->blob + at, count, ndim >= 2 ? count / want[0] : 1);
        return L->blob + at;
    }
    const sp_tensor_info *t = sp_safetensors_find(L->st, name);
    if (!t) {
        L->rc = sp_error_set(L->err, SP_E_NOTFOUND, "%s: tensor '%s' is missing", L->path, name);
        return NULL;
    }
    int ok = t->ndim == ndim;
    for (int i = 0; ok && i < ndim; i++) ok = t->shape[i] == want[i];
    if (!ok) {
        char got[128], exp[128];
        fmt_shape(got, sizeof got, t->shape, t->ndim);
        fmt_shape(exp, sizeof exp, want, ndim);
        L->rc = sp_error_set(L->err, SP_E_FORMAT, "%s: tensor '%s' has shape %s, expected %s "
                             "(does config.json match the weights?)", L->path, name, got, exp);
        return NULL;
    }
    size_t count = 1;
    for (int i = 0; i < ndim; i++) count *= want[i];
    if (t->dtype != SP_DTYPE_F32 && t->dtype != SP_DTYPE_F16 && t->dtype != SP_DTYPE_BF16) {
        L->rc = sp_error_set(L->err, SP_E_UNSUPPORTED, "%s: tensor '%s' dtype is not F32/F16/BF16",
                             L->path, name);
        return NULL;
    }
    if (t->nbytes != count * sp_dtype_size(t->dtype)) {
        L->rc = sp_error_set(L->err, SP_E_FORMAT, "%s: tensor '%s' has %zu bytes for %zu values",
                             L->path, name, t->nbytes, count);
        return NULL;
    }
    size_t at = L->used;
    L->used += (count + 15) & ~(size_t)15; /* keep 64-byte alignment */
    if (L->measuring) return NULL;
    float *dst = L->blob + at;
    const unsigned char *src = t->data;
    for (size_t i = 0; i < count; i++) {
        if (t->dtype == SP_DTYPE_F32) memcpy(dst + i, src + 4 * i, 4);
        else {
            uint16_t h;
            memcpy(&h, src + 2 * i, 2);
            dst[i] = t->dtype == SP_DTYPE_F16 ? sp_half_to_float(h) : sp_bf16_to_float(h);
        }
    }
    return dst;
}

static void take_tower(loader *L, clip_tower *tw, const char *prefix)
{
    size_t w = (size_t)tw->cfg.width, m = (size_t)tw->cfg.mlp;
    char n[256];
#define T1(field, suffix, d0) \
    (snprintf(n, sizeof n, "%s.encoder.layers.%d.%s", prefix, i, suffix), l->field = take(L, n, 1, d0, 0, 0, 0))
#define T2(field, suffix, d0, d1) \
    (snprintf(n, sizeof n, "%s.encoder.layers.%d.%s", prefix, i, suffix), l->field = take(L, n, 2, d0, d1, 0, 0))
    for (int i = 0; i < tw->cfg.layers; i++) {
        clip_layer *l = &tw->layers[i];
        T1(ln1_w, "layer_norm1.weight", w); T1(ln1_b, "layer_norm1.bias", w);
        T2(q_w, "self_attn.q_proj.weight", w, w); T1(q_b, "self_attn.q_proj.bias", w);
        T2(k_w, "self_attn.k_proj.weight", w, w); T1(k_b, "self_attn.k_proj.bias", w);
        T2(v_w, "self_attn.v_proj.weight", w, w); T1(v_b, "self_attn.v_proj.bias", w);
        T2(o_w, "self_attn.out_proj.weight", w, w); T1(o_b, "self_attn.out_proj.bias", w);
        T1(ln2_w, "layer_norm2.weight", w); T1(ln2_b, "layer_norm2.bias", w);
        T2(fc1_w, "mlp.fc1.weight", m, w); T1(fc1_b, "mlp.fc1.bias", m);
        T2(fc2_w, "mlp.fc2.weight", w, m); T1(fc2_b, "mlp.fc2.bias", w);
    }
#undef T1
#undef T2
    /* more layers in the file than the config says is a mismatch too */
    snprintf(n, sizeof n, "%s.encoder.layers.%d.layer_norm1.weight", prefix, tw->cfg.layers);
    if (!L->rc && L->st && sp_safetensors_find(L->st, n))
        L->rc = sp_error_set(L->err, SP_E_FORMAT, "%s: has '%s' but the config says %d layers",
                             L->path, n, tw->cfg.layers);
}

static void take_all(loader *L, sp_clip *c)
{
    const sp_clip_config *g = &c->cfg;
    size_t tw = (size_t)g->text.width, vw = (size_t)g->vision.width, p = (size_t)g->patch_size;
    size_t grid = (size_t)(g->image_size / g->patch_size);
    c->tok_emb = take(L, "text_model.embeddings.token_embedding.weight", 2, (size_t)g->vocab_size, tw, 0, 0);
    c->txt_pos = take(L, "text_model.embeddings.position_embedding.weight", 2, (size_t)g->context, tw, 0, 0);
    take_tower(L, &c->text, "text_model");
    c->final_ln_w = take(L, "text_model.final_layer_norm.weight", 1, tw, 0, 0, 0);
    c->final_ln_b = take(L, "text_model.final_layer_norm.bias", 1, tw, 0, 0, 0);
    c->text_proj = take(L, "text_projection.weight", 2, (size_t)g->projection_dim, tw, 0, 0);
    c->cls = take(L, "vision_model.embeddings.class_embedding", 1, vw, 0, 0, 0);
    c->patch_w = take(L, "vision_model.embeddings.patch_embedding.weight", 4, vw, 3, p, p);
    c->vis_pos = take(L, "vision_model.embeddings.position_embedding.weight", 2, grid * grid + 1, vw, 0, 0);
    c->pre_ln_w = take(L, "vision_model.pre_layrnorm.weight", 1, vw, 0, 0, 0);
    c->pre_ln_b = take(L, "vision_model.pre_layrnorm.bias", 1, vw, 0, 0, 0);
    take_tower(L, &c->vision, "vision_model");
    c->post_ln_w = take(L, "vision_model.post_layernorm.weight", 1, vw, 0, 0, 0);
    c->post_ln_b = take(L, "vision_model.post_layernorm.bias", 1, vw, 0, 0, 0);
    c->vis_proj = take(L, "visual_projection.weight", 2, (size_t)g->projection_dim, vw, 0, 0);
}

static int count_layers(const sp_safetensors *st, const char *prefix)
{
    char n[256];
    int i = 0;
    for (;; i++) {
        snprintf(n, sizeof n, "%s.encoder.layers.%d.layer_norm1.weight", prefix, i);
        if (!sp_safetensors_find(st, n)) return i;
    }
}

/* Shapes from the tensors alone (no config.json): heads = width / 64 as in every OpenAI CLIP. */
static int infer_config(const sp_safetensors *st, const char *path, sp_clip_config *c, sp_error *err)
{
    const sp_tensor_info *te = sp_safetensors_find(st, "text_model.embeddings.token_embedding.weight");
    const sp_tensor_info *tp = sp_safetensors_find(st, "text_model.embeddings.position_embedding.weight");
    const sp_tensor_info *pe = sp_safetensors_find(st, "vision_model.embeddings.patch_embedding.weight");
    const sp_tensor_info *vp = sp_safetensors_find(st, "vision_model.embeddings.position_embedding.weight");
    const sp_tensor_info *pr = sp_safetensors_find(st, "text_projection.weight");
    const sp_tensor_info *f1 = sp_safetensors_find(st, "text_model.encoder.layers.0.mlp.fc1.weight");
    const sp_tensor_info *v1 = sp_safetensors_find(st, "vision_model.encoder.layers.0.mlp.fc1.weight");
    const char *miss = !te ? "text_model.embeddings.token_embedding.weight"
                     : !tp ? "text_model.embeddings.position_embedding.weight"
                     : !pe ? "vision_model.embeddings.patch_embedding.weight"
                     : !vp ? "vision_model.embeddings.position_embedding.weight"
                     : !pr ? "text_projection.weight"
                     : !f1 ? "text_model.encoder.layers.0.mlp.fc1.weight"
                     : !v1 ? "vision_model.encoder.layers.0.mlp.fc1.weight" : NULL;
    if (miss)
        return sp_error_set(err, SP_E_NOTFOUND, "%s: tensor '%s' is missing (not a CLIPModel "
                            "checkpoint?)", path, miss);
    if (te->ndim != 2 || tp->ndim != 2 || pe->ndim != 4 || vp->ndim != 2 || pr->ndim != 2 ||
        f1->ndim != 2 || v1->ndim != 2)
        return sp_error_set(err, SP_E_FORMAT, "%s: embedding tensors have unexpected ranks", path);
    c->vocab_size = (int)te->shape[0];
    c->text.width = (int)te->shape[1];
    c->context = (int)tp->shape[0];
    c->vision.width = (int)pe->shape[0];
    c->patch_size = (int)pe->shape[2];
    size_t npos = vp->shape[0] - 1, g = 0;
    while ((g + 1) * (g + 1) <= npos) g++;
    if (g * g != npos)
        return sp_error_set(err, SP_E_FORMAT, "%s: %zu vision positions is not 1 + a square", path,
                            vp->shape[0]);
    c->image_size = (int)g * c->patch_size;
    c->projection_dim = (int)pr->shape[0];
    c->text.mlp = (int)f1->shape[0];
    c->vision.mlp = (int)v1->shape[0];
    c->text.heads = c->text.width >= 64 ? c->text.width / 64 : 1;
    c->vision.heads = c->vision.width >= 64 ? c->vision.width / 64 : 1;
    c->text.layers = count_layers(st, "text_model");
    c->vision.layers = count_layers(st, "vision_model");
    return 0;
}

/* ---- public ------------------------------------------------------------------------------------- */

static void dir_of(const char *path, char *out, size_t cap)
{
    snprintf(out, cap, "%s", path);
    char *s = strrchr(out, '/');
    if (s) *s = 0;
    else snprintf(out, cap, ".");
}

/* Weights in place: puts them on the GPU when dev is a CUDA device, and takes dev's thread pool
 * (or a pool of its own). */
static int attach_device(sp_clip *c, sp_device *dev, sp_error *err)
{
    int rc;
    c->dev = dev;
    if (dev && sp_device_kind_of(dev) == SP_DEVICE_CUDA && (rc = clip_gpu_init(c, err))) return rc;
    if (dev) c->pool = sp_device_pool(dev);
    if (!c->pool) {
        if ((rc = sp_pool_create(&c->pool, 0, err))) return rc;
        c->own_pool = 1;
    }
    return 0;
}

int sp_clip_load(sp_clip **out, const char *path, const char *config_json, sp_device *dev,
                 sp_error *err)
{
    *out = NULL;
    if (!path) return sp_error_set(err, SP_E_ARG, "sp_clip_load: no weights path");
    sp_clip *c = calloc(1, sizeof *c);
    if (!c) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    snprintf(c->path, sizeof c->path, "%s", path);
    config_defaults(&c->cfg);
    char dir[1024], cpath[1200];
    dir_of(path, dir, sizeof dir);
    sp_safetensors st;
    memset(&st, 0, sizeof st);
    int rc;
    if (!sp_file_exists(path)) {
        rc = sp_error_set(err, SP_E_NOTFOUND, "%s: CLIP weights not found (get model.safetensors "
                          "of openai/clip-vit-base-patch16 from Hugging Face; see docs/clip.md)", path);
        goto fail;
    }
    if ((rc = sp_safetensors_open(path, &st, err))) goto fail;
    if (config_json) {
        if ((rc = parse_config(config_json, &c->cfg, err))) goto fail;
    } else if (sp_path_join(cpath, sizeof cpath, dir, "config.json") == 0 && sp_file_exists(cpath)) {
        if ((rc = parse_config(cpath, &c->cfg, err))) goto fail;
    } else if ((rc = infer_config(&st, path, &c->cfg, err))) {
        goto fail;
    }
    sp_path_join(cpath, sizeof cpath, dir, "preprocessor_config.json");
    if ((rc = parse_preprocessor(cpath, &c->cfg, err))) goto fail;
    c->text.cfg = c->cfg.text;
    c->vision.cfg = c->cfg.vision;
    c->text.layers = calloc((size_t)c->cfg.text.layers, sizeof *c->text.layers);
    c->vision.layers = calloc((size_t)c->cfg.vision.layers, sizeof *c->vision.layers);
    if (!c->text.layers || !c->vision.layers) {
        rc = sp_error_set(err, SP_E_NOMEM, "out of memory");
        goto fail;
    }
    loader L = {&st, path, NULL, 0, 0, 1, err, 0, 0};
    take_all(&L, c);
    if ((rc = L.rc)) goto fail;
    c->blob_floats = L.used;
    c->blob = sp_alloc(L.used * sizeof(float));
    if (!c->blob) {
        rc = sp_error_set(err, SP_E_NOMEM, "%s: cannot allocate %zu MB for the weights", path,
                          L.used * 4 >> 20);
        goto fail;
    }
    L.blob = c->blob;
    L.used = 0;
    L.measuring = 0;
    take_all(&L, c);
    if ((rc = L.rc)) goto fail;
    sp_safetensors_close(&st);
    if ((rc = attach_device(c, dev, err))) goto fail;
    *out = c;
    return 0;
fail:
    sp_safetensors_close(&st);
    sp_clip_free(c);
    return rc;
}

int clip_create_random(sp_clip **out, const sp_clip_config *cfg, uint64_t seed, sp_device *dev,
                       sp_error *err)
{
    *out = NULL;
    sp_clip *c = calloc(1, sizeof *c);
    if (!c) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    snprintf(c->path, sizeof c->path, "(random weights)");
    c->cfg = *cfg;
    c->text.cfg = cfg->text;
    c->vision.cfg = cfg->vision;
    c->text.layers = calloc((size_t)cfg->text.layers, sizeof *c->text.layers);
    c->vision.layers = calloc((size_t)cfg->vision.layers, sizeof *c->vision.layers);
    int rc = 0;
    loader L = {NULL, "(random)", NULL, 0, 0, 1, err, 0, seed};
    if (!c->text.layers || !c->vision.layers) {
        rc = sp_error_set(err, SP_E_NOMEM, "out of memory");
        goto fail;
    }
    take_all(&L, c);
    c->blob_floats = L.used;
    c->blob = sp_alloc(L.used * sizeof(float));
    if (!c->blob) {
        rc = sp_error_set(err, SP_E_NOMEM, "cannot allocate %zu MB for random weights", L.used * 4 >> 20);
        goto fail;
    }
    L.blob = c->blob;
    L.used = 0;
    L.measuring = 0;
    take_all(&L, c);
    if ((rc = attach_device(c, dev, err))) goto fail;
    *out = c;
    return 0;
fail:
    sp_clip_free(c);
    return rc;
}

/* The ViT-B/16 shapes (openai/clip-vit-base-patch16). */
void clip_config_vit_b16(sp_clip_config *c) { config_defaults(c); }

void sp_clip_free(sp_clip *c)
{
    if (!c) return;
    if (c->gpu) clip_gpu_free(c);
    if (c->own_pool) sp_pool_free(c->pool);
    sp_clip_tokenizer_free(c->tok);
    free(c->text.layers);
    free(c->vision.layers);
    sp_free(c->blob);
    free(c);
}

const sp_clip_config *sp_clip_get_config(const sp_clip *c) { return &c->cfg; }
int sp_clip_embed_dim(const sp_clip *c) { return c->cfg.projection_dim; }
int sp_clip_on_gpu(const sp_clip *c) { return c->gpu != NULL; }

int sp_clip_set_fp16(sp_clip *c, int on, sp_error *err)
{
    if (!c->gpu)
        return sp_error_set(err, SP_E_UNSUPPORTED, "CLIP fp16 runs on the GPU only (this model is on the CPU)");
    return clip_gpu_set_fp16(c, on, err);
}

int clip_eos_position(const sp_clip *c, const int32_t *ids)
{
    int n = c->cfg.context, best = 0;
    if (c->cfg.eos_token_id == 2) { /* legacy configs: transformers takes argmax(ids) */
        for (int i = 1; i < n; i++)
            if (ids[i] > ids[best]) best = i;
        return best;
    }
    for (int i = 0; i < n; i++)
        if (ids[i] == c->cfg.eos_token_id) return i;
    return 0;
}

int sp_clip_encode_tokens(sp_clip *c, const int32_t *ids, int n, float *out, sp_error *err)
{
    if (n <= 0) return 0;
    if (c->cfg.context != SP_CLIP_CONTEXT)
        return sp_error_set(err, SP_E_UNSUPPORTED, "%s: text context %d (77 expected)", c->path,
                            c->cfg.context);
    for (long i = 0; i < (long)n * SP_CLIP_CONTEXT; i++)
        if (ids[i] < 0 || ids[i] >= c->cfg.vocab_size)
            return sp_error_set(err, SP_E_ARG, "token id %d at %ld outside the vocabulary (%d)",
                                ids[i], i, c->cfg.vocab_size);
    int rc = c->gpu ? clip_gpu_text(c, ids, n, out, err) : clip_cpu_text(c, ids, n, out, err);
    if (rc) return rc;
    for (int i = 0; i < n; i++) clip_l2_normalize(out + (size_t)i * c->cfg.projection_dim, c->cfg.projection_dim);
    return 0;
}

int sp_clip_encode_text(sp_clip *c, const char *const *texts, int n, float *out, sp_error *err)
{
    if (n <= 0) return 0;
    int rc;
    if (!c->tok && (rc = sp_clip_tokenizer_load(&c->tok, NULL, err))) return rc;
    int32_t *ids = malloc((size_t)n * SP_CLIP_CONTEXT * sizeof *ids);
    if (!ids) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    for (int i = 0; i < n; i++)
        if ((rc = sp_clip_tokenize_context(c->tok, texts[i], ids + (size_t)i * SP_CLIP_CONTEXT, NULL, err))) {
            free(ids);
            return rc;
        }
    rc = sp_clip_encode_tokens(c, ids, n, out, err);
    free(ids);
    return rc;
}

static int check_pixels(const sp_clip *c, int n, int H, int W, sp_error *err)
{
    int p = c->cfg.patch_size;
    if (n <= 0 || H < p || W < p || H % p || W % p)
        return sp_error_set(err, SP_E_ARG, "image input %dx%d (n=%d): sides must be positive "
                            "multiples of the patch size %d", W, H, n, p);
    return 0;
}

int sp_clip_encode_pixels(sp_clip *c, const float *pixels, int n, int H, int W, float *out,
                          sp_error *err)
{
    int rc = check_pixels(c, n, H, W, err);
    if (rc) return rc;
    rc = c->gpu ? clip_gpu_vision(c, pixels, n, H, W, CLIP_OUT_POOLED, out, err)
                : clip_cpu_vision(c, pixels, n, H, W, CLIP_OUT_POOLED, out, err);
    if (rc) return rc;
    for (int i = 0; i < n; i++) clip_l2_normalize(out + (size_t)i * c->cfg.projection_dim, c->cfg.projection_dim);
    return 0;
}

int sp_clip_dense_pixels(sp_clip *c, const float *pixels, int H, int W, sp_clip_head head,
                         float *out, sp_error *err)
{
    int rc = check_pixels(c, 1, H, W, err);
    if (rc) return rc;
    clip_out_kind k = head == SP_CLIP_HEAD_MASKCLIP ? CLIP_OUT_DENSE_MASKCLIP : CLIP_OUT_DENSE_CLEARCLIP;
    rc = c->gpu ? clip_gpu_vision(c, pixels, 1, H, W, k, out, err)
                : clip_cpu_vision(c, pixels, 1, H, W, k, out, err);
    if (rc) return rc;
    int np = (H / c->cfg.patch_size) * (W / c->cfg.patch_size), d = c->cfg.projection_dim;
    for (int i = 0; i < np; i++) clip_l2_normalize(out + (size_t)i * d, d);
    return 0;
}

/* torch bicubic kernel (A = -0.75). */
static void cubic_coeffs(float t, float w[4])
{
    const float A = -0.75f;
    float x1 = t + 1, x2 = t, x3 = 1 - t, x4 = 2 - t;
    w[0] = ((A * x1 - 5 * A) * x1 + 8 * A) * x1 - 4 * A;
    w[1] = ((A + 2) * x2 - (A + 3)) * x2 * x2 + 1;
    w[2] = ((A + 2) * x3 - (A + 3)) * x3 * x3 + 1;
    w[3] = ((A * x4 - 5 * A) * x4 + 8 * A) * x4 - 4 * A;
}

void clip_pos_embed(const sp_clip *c, int gh, int gw, float *out)
{
    int w = c->cfg.vision.width, g = c->cfg.image_size / c->cfg.patch_size;
    if (gh == g && gw == g) {
        memcpy(out, c->vis_pos, (size_t)(g * g + 1) * w * sizeof *out);
        return;
    }
    memcpy(out, c->vis_pos, (size_t)w * sizeof *out);
    /* torch.nn.functional.interpolate(mode="bicubic", align_corners=False): source index
     * (dst + 0.5) * in/out - 0.5 (not clamped for cubic), taps clamped to the border */
    float sy = (float)g / gh, sx = (float)g / gw;
    for (int oy = 0; oy < gh; oy++) {
        float fy = (oy + 0.5f) * sy - 0.5f;
        int iy = (int)floorf(fy);
        float wy[4];
        cubic_coeffs(fy - iy, wy);
        for (int ox = 0; ox < gw; ox++) {
            float fx = (ox + 0.5f) * sx - 0.5f;
            int ix = (int)floorf(fx);
            float wx[4];
            cubic_coeffs(fx - ix, wx);
            float *o = out + (size_t)(1 + oy * gw + ox) * w;
            for (int ch = 0; ch < w; ch++) o[ch] = 0;
            for (int a = 0; a < 4; a++) {
                int yy = iy - 1 + a;
                yy = yy < 0 ? 0 : yy >= g ? g - 1 : yy;
                for (int b = 0; b < 4; b++) {
                    int xx = ix - 1 + b;
                    xx = xx < 0 ? 0 : xx >= g ? g - 1 : xx;
                    const float *s = c->vis_pos + (size_t)(1 + yy * g + xx) * w;
                    float wt = wy[a] * wx[b];
                    for (int ch = 0; ch < w; ch++) o[ch] += wt * s[ch];
                }
            }
        }
    }
}
