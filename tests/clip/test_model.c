/* CLIP towers against an independent naive double-precision forward written here, on a tiny
 * random model saved as safetensors (text 32 wide, vision 48 wide, 2 layers each, patch 8), plus
 * the loader's errors: missing file, missing tensor, config that does not match, truncation. */
#include <stdint.h>
#include <unistd.h>

#include "semsplat/clip.h"
#include "semsplat/io.h"
#include "semsplat/device.h"
#include "clip/clip_internal.h"
#include "test.h"

enum { TW = 32, TH = 2, TL = 2, TM = 64, VOCAB = 49408, CTX = 77,
       VW = 48, VH = 3, VL = 2, VM = 96, PS = 8, IMG = 32, PROJ = 24 };

typedef struct { char name[128]; int ndim; size_t shape[4]; float *data; } wt;
static wt W[128];
static int n_w;
static test_rng rng = {12345};

static float *add(const char *name, int ndim, size_t d0, size_t d1, size_t d2, size_t d3, double sd,
                  double mean)
{
    wt *w = &W[n_w++];
    snprintf(w->name, sizeof w->name, "%s", name);
    w->ndim = ndim;
    size_t s[4] = {d0, d1, d2, d3}, n = 1;
    for (int i = 0; i < ndim; i++) n *= (w->shape[i] = s[i]);
    w->data = malloc(n * sizeof(float));
    for (size_t i = 0; i < n; i++) w->data[i] = (float)(mean + sd * (2 * test_uniform(&rng) - 1) * 1.7320508);
    return w->data;
}

static const float *get(const char *name)
{
    for (int i = 0; i < n_w; i++)
        if (!strcmp(W[i].name, name)) return W[i].data;
    return NULL;
}

static void add_tower(const char *pre, int w, int m, int layers)
{
    char n[160];
    for (int l = 0; l < layers; l++) {
#define A1(s, d, sd, mu) (snprintf(n, sizeof n, "%s.encoder.layers.%d.%s", pre, l, s), add(n, 1, d, 0, 0, 0, sd, mu))
#define A2(s, a, b) (snprintf(n, sizeof n, "%s.encoder.layers.%d.%s", pre, l, s), add(n, 2, a, b, 0, 0, 1.0 / sqrt(b), 0))
        A1("layer_norm1.weight", w, 0.1, 1); A1("layer_norm1.bias", w, 0.1, 0);
        A2("self_attn.q_proj.weight", w, w); A1("self_attn.q_proj.bias", w, 0.1, 0);
        A2("self_attn.k_proj.weight", w, w); A1("self_attn.k_proj.bias", w, 0.1, 0);
        A2("self_attn.v_proj.weight", w, w); A1("self_attn.v_proj.bias", w, 0.1, 0);
        A2("self_attn.out_proj.weight", w, w); A1("self_attn.out_proj.bias", w, 0.1, 0);
        A1("layer_norm2.weight", w, 0.1, 1); A1("layer_norm2.bias", w, 0.1, 0);
        A2("mlp.fc1.weight", m, w); A1("mlp.fc1.bias", m, 0.1, 0);
        A2("mlp.fc2.weight", w, m); A1("mlp.fc2.bias", w, 0.1, 0);
#undef A1
#undef A2
    }
}

static void make_model(void)
{
    add("text_model.embeddings.token_embedding.weight", 2, VOCAB, TW, 0, 0, 0.5, 0);
    add("text_model.embeddings.position_embedding.weight", 2, CTX, TW, 0, 0, 0.2, 0);
    add_tower("text_model", TW, TM, TL);
    add("text_model.final_layer_norm.weight", 1, TW, 0, 0, 0, 0.1, 1);
    add("text_model.final_layer_norm.bias", 1, TW, 0, 0, 0, 0.1, 0);
    add("text_projection.weight", 2, PROJ, TW, 0, 0, 0.2, 0);
    add("vision_model.embeddings.class_embedding", 1, VW, 0, 0, 0, 0.5, 0);
    add("vision_model.embeddings.patch_embedding.weight", 4, VW, 3, PS, PS, 0.05, 0);
    add("vision_model.embeddings.position_embedding.weight", 2, (IMG / PS) * (IMG / PS) + 1, VW, 0, 0, 0.3, 0);
    add("vision_model.pre_layrnorm.weight", 1, VW, 0, 0, 0, 0.1, 1);
    add("vision_model.pre_layrnorm.bias", 1, VW, 0, 0, 0, 0.1, 0);
    add_tower("vision_model", VW, VM, VL);
    add("vision_model.post_layernorm.weight", 1, VW, 0, 0, 0, 0.1, 1);
    add("vision_model.post_layernorm.bias", 1, VW, 0, 0, 0, 0.1, 0);
    add("visual_projection.weight", 2, PROJ, VW, 0, 0, 0.2, 0);
}

static uint16_t to_bf16(float f)
{
    uint32_t u;
    memcpy(&u, &f, 4);
    return (uint16_t)((u + 0x7FFF + ((u >> 16) & 1)) >> 16); /* round to nearest even */
}

/* dtype: SP_DTYPE_F32, F16 or BF16 */
static int save_as(const char *path, int skip, int truncate_bytes, sp_dtype dtype);

static int save(const char *path, int skip, int truncate_bytes)
{
    return save_as(path, skip, truncate_bytes, SP_DTYPE_F32);
}

static int save_as(const char *path, int skip, int truncate_bytes, sp_dtype dtype)
{
    sp_tensor_info *t = calloc((size_t)n_w, sizeof *t);
    size_t k = 0;
    for (int i = 0; i < n_w; i++) {
        if (i == skip) continue;
        snprintf(t[k].name, sizeof t[k].name, "%s", W[i].name);
        t[k].dtype = dtype;
        t[k].ndim = W[i].ndim;
        size_t n = 1;
        for (int d = 0; d < W[i].ndim; d++) n *= (t[k].shape[d] = W[i].shape[d]);
        if (dtype == SP_DTYPE_F32) {
            t[k].data = W[i].data;
            t[k].nbytes = n * 4;
        } else {
            uint16_t *h = malloc(n * 2);
            for (size_t j = 0; j < n; j++)
                h[j] = dtype == SP_DTYPE_F16 ? sp_float_to_half(W[i].data[j]) : to_bf16(W[i].data[j]);
            t[k].data = h;
            t[k].nbytes = n * 2;
        }
        k++;
    }
    sp_error err = {0};
    int rc = sp_safetensors_write(path, t, k, &err);
    if (dtype != SP_DTYPE_F32)
        for (size_t i = 0; i < k; i++) free((void *)t[i].data);
    free(t);
    if (rc) fprintf(stderr, "%s\n", err.msg);
    if (!rc && truncate_bytes) {
        FILE *f = fopen(path, "rb+");
        fseek(f, 0, SEEK_END);
        long sz = ftell(f);
        fclose(f);
        if (truncate(path, sz - truncate_bytes)) rc = -1;
    }
    return rc;
}

static void write_text(const char *path, const char *s)
{
    FILE *f = fopen(path, "w");
    fputs(s, f);
    fclose(f);
}

static char config_json[2048];

/* ---- naive reference (double) ----------------------------------------------------------------- */

static void ref_ln(double *x, int n, const float *g, const float *b)
{
    double m = 0, v = 0;
    for (int i = 0; i < n; i++) m += x[i];
    m /= n;
    for (int i = 0; i < n; i++) v += (x[i] - m) * (x[i] - m);
    v /= n;
    for (int i = 0; i < n; i++) x[i] = (x[i] - m) / sqrt(v + 1e-5) * g[i] + b[i];
}

static void ref_lin(const double *x, const float *w, const float *b, int in, int out, double *y)
{
    for (int o = 0; o < out; o++) {
        double s = b ? b[o] : 0;
        for (int i = 0; i < in; i++) s += w[(size_t)o * in + i] * x[i];
        y[o] = s;
    }
}

#define P(fmt) (snprintf(nm, sizeof nm, "%s.encoder.layers.%d." fmt, pre, l), get(nm))

/* x [T][w] in place through `layers` blocks; last_mode: 0 normal, 1 MaskCLIP, 2 ClearCLIP for
 * the last block. */
static void ref_tower(double *x, int T, const char *pre, int w, int heads, int m, int layers,
                      int causal, int last_mode)
{
    char nm[160];
    int d = w / heads;
    double *h = malloc(sizeof(double) * T * w), *q = malloc(sizeof(double) * T * w);
    double *k = malloc(sizeof(double) * T * w), *v = malloc(sizeof(double) * T * w);
    double *o = malloc(sizeof(double) * T * w), *mm = malloc(sizeof(double) * m), *s = malloc(sizeof(double) * T);
    for (int l = 0; l < layers; l++) {
        int mode = l == layers - 1 ? last_mode : 0;
        for (int t = 0; t < T; t++) {
            memcpy(h + t * w, x + t * w, sizeof(double) * w);
            ref_ln(h + t * w, w, P("layer_norm1.weight"), P("layer_norm1.bias"));
            ref_lin(h + t * w, P("self_attn.q_proj.weight"), P("self_attn.q_proj.bias"), w, w, q + t * w);
            ref_lin(h + t * w, P("self_attn.k_proj.weight"), P("self_attn.k_proj.bias"), w, w, k + t * w);
            ref_lin(h + t * w, P("self_attn.v_proj.weight"), P("self_attn.v_proj.bias"), w, w, v + t * w);
        }
        const double *kk = mode == 2 ? q : k;
        for (int hd = 0; hd < heads; hd++)
            for (int i = 0; i < T; i++) {
                int n = causal ? i + 1 : T;
                double mx = -1e300, sum = 0;
                for (int j = 0; j < n; j++) {
                    double a = 0;
                    for (int c = 0; c < d; c++) a += q[i * w + hd * d + c] * kk[j * w + hd * d + c];
                    s[j] = a / sqrt(d);
                    if (s[j] > mx) mx = s[j];
                }
                for (int j = 0; j < n; j++) sum += (s[j] = exp(s[j] - mx));
                for (int c = 0; c < d; c++) {
                    double a = 0;
                    for (int j = 0; j < n; j++) a += s[j] / sum * v[j * w + hd * d + c];
                    o[i * w + hd * d + c] = mode == 1 ? v[i * w + hd * d + c] : a;
                }
            }
        for (int t = 0; t < T; t++) {
            double y[256];
            ref_lin(o + t * w, P("self_attn.out_proj.weight"), P("self_attn.out_proj.bias"), w, w, y);
            if (mode) { /* dense head: no residual, no FFN */
                memcpy(x + t * w, y, sizeof(double) * w);
                continue;
            }
            for (int c = 0; c < w; c++) x[t * w + c] += y[c];
            memcpy(h, x + t * w, sizeof(double) * w);
            ref_ln(h, w, P("layer_norm2.weight"), P("layer_norm2.bias"));
            ref_lin(h, P("mlp.fc1.weight"), P("mlp.fc1.bias"), w, m, mm);
            for (int c = 0; c < m; c++) mm[c] = mm[c] / (1 + exp(-1.702 * mm[c]));
            ref_lin(mm, P("mlp.fc2.weight"), P("mlp.fc2.bias"), m, w, y);
            for (int c = 0; c < w; c++) x[t * w + c] += y[c];
        }
    }
    free(h); free(q); free(k); free(v); free(o); free(mm); free(s);
}

static void normalize(double *v, int n)
{
    double s = 0;
    for (int i = 0; i < n; i++) s += v[i] * v[i];
    for (int i = 0; i < n; i++) v[i] /= sqrt(s);
}

static void ref_text(const int32_t *ids, double *out)
{
    int L = 0;
    for (int i = 1; i < CTX; i++) if (ids[i] > ids[L]) L = i;
    L++;
    double *x = malloc(sizeof(double) * L * TW);
    const float *te = get("text_model.embeddings.token_embedding.weight");
    const float *pe = get("text_model.embeddings.position_embedding.weight");
    for (int t = 0; t < L; t++)
        for (int c = 0; c < TW; c++) x[t * TW + c] = te[(size_t)ids[t] * TW + c] + pe[t * TW + c];
    ref_tower(x, L, "text_model", TW, TH, TM, TL, 1, 0);
    double *e = x + (L - 1) * TW;
    ref_ln(e, TW, get("text_model.final_layer_norm.weight"), get("text_model.final_layer_norm.bias"));
    ref_lin(e, get("text_projection.weight"), NULL, TW, PROJ, out);
    normalize(out, PROJ);
    free(x);
}

/* pixels [3][IMG][IMG]; mode 0: pooled embedding -> out[PROJ]; 1/2: dense -> out[np][PROJ] */
static void ref_vision(const float *px, int mode, double *out)
{
    int g = IMG / PS, np = g * g, T = np + 1;
    double *x = malloc(sizeof(double) * T * VW);
    const float *pw = get("vision_model.embeddings.patch_embedding.weight");
    const float *pos = get("vision_model.embeddings.position_embedding.weight");
    const float *cls = get("vision_model.embeddings.class_embedding");
    for (int c = 0; c < VW; c++) x[c] = cls[c] + pos[c];
    for (int p = 0; p < np; p++)
        for (int c = 0; c < VW; c++) {
            double s = 0;
            for (int ch = 0; ch < 3; ch++)
                for (int ky = 0; ky < PS; ky++)
                    for (int kx = 0; kx < PS; kx++)
                        s += pw[((c * 3 + ch) * PS + ky) * PS + kx] *
                             px[(ch * IMG + (p / g) * PS + ky) * IMG + (p % g) * PS + kx];
            x[(1 + p) * VW + c] = s + pos[(1 + p) * VW + c];
        }
    for (int t = 0; t < T; t++) ref_ln(x + t * VW, VW, get("vision_model.pre_layrnorm.weight"), get("vision_model.pre_layrnorm.bias"));
    ref_tower(x, T, "vision_model", VW, VH, VM, VL, 0, mode);
    for (int t = mode ? 1 : 0; t < (mode ? T : 1); t++) {
        double *e = x + t * VW, *o = out + (mode ? (t - 1) * PROJ : 0);
        ref_ln(e, VW, get("vision_model.post_layernorm.weight"), get("vision_model.post_layernorm.bias"));
        ref_lin(e, get("visual_projection.weight"), NULL, VW, PROJ, o);
        normalize(o, PROJ);
    }
    free(x);
}

/* ---- tests --------------------------------------------------------------------------------------- */

static char dir[1024], wpath[1200];

static void test_text(void)
{
    sp_clip *c = NULL;
    sp_error err = {0};
    CHECK_OK(sp_clip_load(&c, wpath, NULL, NULL, &err), &err);
    if (!c) return;
    CHECK(sp_clip_embed_dim(c) == PROJ);
    const char *texts[] = {"a photo of a cat", "", "refrigerator in the kitchen, next to a chair!"};
    float got[3 * PROJ];
    CHECK_OK(sp_clip_encode_text(c, texts, 3, got, &err), &err);
    sp_clip_tokenizer *tok;
    CHECK_OK(sp_clip_tokenizer_load(&tok, NULL, &err), &err);
    double worst = 0;
    for (int i = 0; i < 3; i++) {
        int32_t ids[CTX];
        sp_clip_tokenize_context(tok, texts[i], ids, NULL, &err);
        double ref[PROJ];
        ref_text(ids, ref);
        for (int k = 0; k < PROJ; k++) worst = fmax(worst, fabs(ref[k] - got[i * PROJ + k]));
    }
    CHECK_MSG(worst < 1e-5, "text max abs diff %g", worst);
    sp_clip_tokenizer_free(tok);
    sp_clip_free(c);
}

static void test_vision(void)
{
    sp_clip *c = NULL;
    sp_error err = {0};
    CHECK_OK(sp_clip_load(&c, wpath, NULL, NULL, &err), &err);
    if (!c) return;
    float px[2 * 3 * IMG * IMG];
    for (int i = 0; i < 2 * 3 * IMG * IMG; i++) px[i] = (float)test_range(&rng, -2, 2);
    float got[2 * PROJ];
    CHECK_OK(sp_clip_encode_pixels(c, px, 2, IMG, IMG, got, &err), &err);
    double worst = 0, ref[16 * PROJ];
    for (int i = 0; i < 2; i++) {
        ref_vision(px + i * 3 * IMG * IMG, 0, ref);
        for (int k = 0; k < PROJ; k++) worst = fmax(worst, fabs(ref[k] - got[i * PROJ + k]));
    }
    CHECK_MSG(worst < 1e-5, "image max abs diff %g", worst);
    for (int mode = 1; mode <= 2; mode++) {
        float dense[16 * PROJ];
        CHECK_OK(sp_clip_dense_pixels(c, px, IMG, IMG, mode == 1 ? SP_CLIP_HEAD_MASKCLIP : SP_CLIP_HEAD_CLEARCLIP, dense, &err), &err);
        ref_vision(px, mode, ref);
        worst = 0;
        for (int k = 0; k < 16 * PROJ; k++) worst = fmax(worst, fabs(ref[k] - dense[k]));
        CHECK_MSG(worst < 1e-5, "dense mode %d max abs diff %g", mode, worst);
    }
    /* a non-square input interpolates the position embeddings and still runs */
    float wide[3 * IMG * 2 * IMG], e[PROJ];
    for (int i = 0; i < 3 * IMG * 2 * IMG; i++) wide[i] = (float)test_range(&rng, -2, 2);
    CHECK_OK(sp_clip_encode_pixels(c, wide, 1, IMG, 2 * IMG, e, &err), &err);
    CHECK_FAILS(sp_clip_encode_pixels(c, wide, 1, IMG + 3, IMG, e, &err), SP_E_ARG, &err, "patch size");
    CHECK_FAILS(sp_clip_set_fp16(c, 1, &err), SP_E_UNSUPPORTED, &err, "GPU");
    /* dense features of a whole image: grid at patch/scale pixels, unit vectors */
    int gw, gh;
    sp_clip_dense_opts o = sp_clip_dense_opts_default();
    o.scales[1] = 1.0f;
    o.n_scales = 2;
    sp_clip_dense_grid(c, &o, 50, 37, &gw, &gh);
    CHECK(gw == 13 && gh == 10); /* 100x74 at scale 2, patch 8 */
    float *rgb = malloc(sizeof(float) * 50 * 37 * 3), *map = malloc(sizeof(float) * gw * gh * PROJ);
    for (int i = 0; i < 50 * 37 * 3; i++) rgb[i] = (float)test_uniform(&rng);
    CHECK_OK(sp_clip_dense_features(c, rgb, 50, 37, &o, map, &err), &err);
    double n0 = 0;
    for (int k = 0; k < PROJ; k++) n0 += map[k] * map[k];
    CHECK_NEAR(n0, 1.0, 1e-4);
    float emb[PROJ];
    CHECK_OK(sp_clip_encode_image(c, rgb, 1, 50, 37, emb, &err), &err);
    free(rgb);
    free(map);
    sp_clip_free(c);
}

/* The same model stored as F16 and BF16 loads and gives nearly the same embeddings. */
static void test_half_files(void)
{
    sp_error err = {0};
    sp_clip *ref = NULL;
    CHECK_OK(sp_clip_load(&ref, wpath, NULL, NULL, &err), &err);
    const char *texts[] = {"a photo of a cat"};
    float a[PROJ], b[PROJ];
    if (ref) CHECK_OK(sp_clip_encode_text(ref, texts, 1, a, &err), &err);
    for (int k = 0; k < 2 && ref; k++) {
        char p[1400], cfg[1400];
        snprintf(p, sizeof p, "%s/half%d", dir, k);
        sp_mkdirs(p, &err);
        snprintf(cfg, sizeof cfg, "%s/config.json", p);
        write_text(cfg, config_json);
        snprintf(p, sizeof p, "%s/half%d/model.safetensors", dir, k);
        CHECK(save_as(p, -1, 0, k ? SP_DTYPE_BF16 : SP_DTYPE_F16) == 0);
        sp_clip *c = NULL;
        CHECK_OK(sp_clip_load(&c, p, NULL, NULL, &err), &err);
        if (!c) continue;
        CHECK_OK(sp_clip_encode_text(c, texts, 1, b, &err), &err);
        double d = 0;
        for (int i = 0; i < PROJ; i++) d = fmax(d, fabs(a[i] - b[i]));
        CHECK_MSG(d < (k ? 0.05 : 0.01), "%s weights: max diff %g", k ? "bf16" : "f16", d);
        sp_clip_free(c);
    }
    sp_clip_free(ref);
}

/* The GPU path (fp32 and fp16) against the CPU path on the same model. */
static void test_gpu(void)
{
    sp_error err = {0};
    sp_device *dev = NULL;
    sp_clip *cpu = NULL, *gpu = NULL;
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CUDA, 0, &err), &err);
    CHECK_OK(sp_clip_load(&cpu, wpath, NULL, NULL, &err), &err);
    CHECK_OK(sp_clip_load(&gpu, wpath, NULL, dev, &err), &err);
    if (!cpu || !gpu) goto done;
    CHECK(sp_clip_on_gpu(gpu) && !sp_clip_on_gpu(cpu));
    const char *texts[] = {"a photo of a cat", "", "a much longer text about a red refrigerator"};
    enum { NP = 3 * (2 * IMG) * IMG };
    static float px[2 * NP], a[64 * PROJ], b[64 * PROJ];
    for (int i = 0; i < 2 * NP; i++) px[i] = (float)test_range(&rng, -2, 2);
    /* then with the MLP in slabs of 16 rows and the blocks over one sequence at a time (the slab
     * variants at sizes these shapes reach) */
    for (int pass = 0; pass < 6; pass++) {
        int fp16 = pass & 1, slabs = pass >> 1;
        double tol = fp16 ? 3e-2 : 1e-5, wt = 0, wi = 0, wd = 0, ww = 0;
        CHECK_OK(sp_clip_set_fp16(gpu, fp16, &err), &err);
        clip_gpu_set_flags(gpu, slabs ? CLIP_GPU_SLABS_SMALL | (slabs == 1 ? CLIP_GPU_MLP_SLABS : CLIP_GPU_BLOCK_SLABS) : 0);
        CHECK_OK(sp_clip_encode_text(cpu, texts, 3, a, &err), &err);
        CHECK_OK(sp_clip_encode_text(gpu, texts, 3, b, &err), &err);
        for (int k = 0; k < 3 * PROJ; k++) wt = fmax(wt, fabs(a[k] - b[k]));
        CHECK_OK(sp_clip_encode_pixels(cpu, px, 2, IMG, IMG, a, &err), &err);
        CHECK_OK(sp_clip_encode_pixels(gpu, px, 2, IMG, IMG, b, &err), &err);
        for (int k = 0; k < 2 * PROJ; k++) wi = fmax(wi, fabs(a[k] - b[k]));
        CHECK_OK(sp_clip_encode_pixels(cpu, px, 1, IMG, 2 * IMG, a, &err), &err);
        CHECK_OK(sp_clip_encode_pixels(gpu, px, 1, IMG, 2 * IMG, b, &err), &err);
        for (int k = 0; k < PROJ; k++) ww = fmax(ww, fabs(a[k] - b[k]));
        for (int head = 0; head <= 1; head++) {
            CHECK_OK(sp_clip_dense_pixels(cpu, px, IMG, IMG, (sp_clip_head)head, a, &err), &err);
            CHECK_OK(sp_clip_dense_pixels(gpu, px, IMG, IMG, (sp_clip_head)head, b, &err), &err);
            for (int k = 0; k < 16 * PROJ; k++) wd = fmax(wd, fabs(a[k] - b[k]));
        }
        fprintf(stderr, "GPU %s%s vs CPU: text %.3g image %.3g wide %.3g dense %.3g\n", fp16 ? "fp16" : "fp32",
                slabs == 1 ? " (MLP in slabs)" : slabs ? " (blocks in slabs)" : "", wt, wi, ww, wd);
        CHECK(wt < tol && wi < tol && ww < tol && wd < tol);
    }
    clip_gpu_set_flags(gpu, 0);
done:
    sp_clip_free(cpu);
    sp_clip_free(gpu);
    sp_device_free(dev);
}

/* The host fp32 -> fp16 conversion of the GPU uploads (F16C where the CPU has it) rounds as
 * sp_float_to_half: to nearest even, denormals, overflow to infinity, signed zeros. */
static void test_half_host(void)
{
    enum { N = 4099 };
    static float x[N];
    static uint16_t a[N];
    for (int i = 0; i < N; i++) {
        double mag = pow(2.0, test_range(&rng, -26, 17)); /* underflow to overflow */
        x[i] = (float)((i & 1 ? -1 : 1) * mag);
    }
    x[0] = 0.f; x[1] = -0.f; x[2] = 65504.f; x[3] = 65520.f; x[4] = 1.0009765625f + 0.00048828125f; /* a tie */
    x[5] = INFINITY; x[6] = -INFINITY; x[7] = 5.96e-8f; x[8] = 2.98e-8f;
    clip_floats_to_half(x, a, N);
    int bad = 0;
    for (int i = 0; i < N; i++) bad += a[i] != sp_float_to_half(x[i]);
    CHECK_MSG(bad == 0, "%d of %d conversions differ from sp_float_to_half", bad, N);
}

/* The fused fp16 attention kernel alone against a double reference on the same fp16-rounded
 * inputs: head widths 16/32/64, sequence lengths around the 64-row tiles and the 16-row chunks
 * (1, 63, 64, 65, 77, 197, 200, 300, 800: 1 to 8 warps per block, 1 to 3 rounds of chunks in the
 * resident kernel), causal and not, q-q (ClearCLIP) and q-k, 8 kernel modes, ViT-B/16's shape (12 heads
 * of 64, 197 tokens, 3 images); every output element written and finite. */
static void ref_attention(const float *qkv, int B, int T, int H, int w, int causal, int qq, double *out)
{
    int d = w / H;
    double *p = malloc(sizeof(double) * T);
    for (int b = 0; b < B; b++)
        for (int h = 0; h < H; h++)
            for (int q = 0; q < T; q++) {
                const float *qr = qkv + ((size_t)b * T + q) * 3 * w + h * d;
                double m = -1e300, sum = 0;
                int n = causal ? q + 1 : T;
                for (int k = 0; k < n; k++) {
                    const float *kr = qkv + ((size_t)b * T + k) * 3 * w + (qq ? 0 : w) + h * d;
                    double s = 0;
                    for (int c = 0; c < d; c++) s += (double)qr[c] * kr[c];
                    p[k] = s / sqrt((double)d);
                    if (p[k] > m) m = p[k];
                }
                for (int k = 0; k < n; k++) sum += (p[k] = exp(p[k] - m));
                for (int c = 0; c < d; c++) {
                    double o = 0;
                    for (int k = 0; k < n; k++) o += p[k] * qkv[((size_t)b * T + k) * 3 * w + 2 * w + h * d + c];
                    out[((size_t)b * T + q) * w + h * d + c] = o / sum;
                }
            }
    free(p);
}

static void test_gpu_attention(void)
{
    sp_error err = {0};
    sp_device *dev = NULL;
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CUDA, 0, &err), &err);
    if (!dev) return;
    /* 800 keys of width 64 do not fit in shared memory: the sequence-resident kernel hands over
     * to the tiled one */
    const int Ts[] = {1, 63, 64, 65, 77, 197, 200, 300, 800}, ds[] = {16, 32, 64};
    double worst[2] = {0, 0};
    int cases = 0;
    for (int ti = 0; ti <= 9; ti++)
        for (int di = 0; di < 3; di++)
            for (int mode = 0; mode < 3; mode++) {
                int vit = ti == 9; /* the last case: ViT-B/16 */
                int T = vit ? 197 : Ts[ti], d = vit ? 64 : ds[di], H = vit ? 12 : 2, w = H * d, B = vit ? 3 : 2;
                int causal = mode == 1, qq = mode == 2;
                if ((T == 800 && d != 64) || (vit && (di || mode == 1))) continue;
                size_t nin = (size_t)B * T * 3 * w, nout = (size_t)B * T * w;
                float *qkv = malloc(sizeof(float) * nin), *got = malloc(sizeof(float) * nout);
                double *ref = malloc(sizeof(double) * nout);
                /* scores up to a few units (softmax neither flat nor one-hot), rounded to fp16 */
                for (size_t i = 0; i < nin; i++)
                    qkv[i] = sp_half_to_float(sp_float_to_half((float)test_range(&rng, -1.5, 1.5)));
                ref_attention(qkv, B, T, H, w, causal, qq, ref);
                /* the towers' choice, the tiled kernel, the resident one with 1 block of 1 and of
                 * 7 warps, 2 of 4 and 3 of 2 per head, and with the queries through shared
                 * memory (1 block of 7, 2 of 4) */
                static const int modes[] = {0, 1, 101, 107, 204, 302, 1107, 1204};
                for (int mi = 0; mi < 8; mi++) {
                    int tiled = modes[mi] == 1;
                    CHECK_OK(clip_gpu_attention_check(dev, qkv, B, T, H, w, causal, qq, modes[mi], got, &err), &err);
                    double e = 0;
                    for (size_t i = 0; i < nout; i++) e = isfinite(got[i]) ? fmax(e, fabs(got[i] - ref[i])) : 1e9;
                    CHECK_MSG(e < 4e-3, "fused attention mode %d T=%d d=%d causal=%d qq=%d: max abs %g", modes[mi], T, d,
                              causal, qq, e);
                    worst[tiled] = fmax(worst[tiled], e);
                    cases++;
                }
                free(qkv); free(got); free(ref);
            }
    fprintf(stderr, "fused attention vs double: %d cases, max abs %.3g (resident K/V), %.3g (tiled)\n", cases,
            worst[0], worst[1]);
    /* a head width the kernel does not take is refused, not miscomputed */
    float one[3 * 24] = {0}, o1[24];
    CHECK_FAILS(clip_gpu_attention_check(dev, one, 1, 1, 1, 24, 0, 0, 0, o1, &err), SP_E_UNSUPPORTED, &err, "width");
    sp_device_free(dev);
}

static void test_errors(void)
{
    sp_clip *c = NULL;
    sp_error err = {0};
    char p[1400], cfg[1400];
    snprintf(p, sizeof p, "%s/none.safetensors", dir);
    CHECK_FAILS(sp_clip_load(&c, p, NULL, NULL, &err), SP_E_NOTFOUND, &err, "none.safetensors");
    CHECK(c == NULL);
    /* config saying 3 layers for a 2-layer checkpoint */
    snprintf(cfg, sizeof cfg, "%s/wrong.json", dir);
    char bad[2048];
    snprintf(bad, sizeof bad, "%s", config_json);
    char *at = strstr(bad, "\"num_hidden_layers\": 2");
    at[21] = '3';
    write_text(cfg, bad);
    CHECK_FAILS(sp_clip_load(&c, wpath, cfg, NULL, &err), SP_E_NOTFOUND, &err, "layers.2");
    /* config with another width */
    snprintf(bad, sizeof bad, "%s", config_json);
    at = strstr(bad, "\"hidden_size\": 32");
    memcpy(at, "\"hidden_size\": 64", 17);
    write_text(cfg, bad);
    CHECK_FAILS(sp_clip_load(&c, wpath, cfg, NULL, &err), SP_E_FORMAT, &err, "expected [");
    write_text(cfg, "{\"text_config\": {\"hidden_size\": \"wide\"}, \"vision_config\": {}}");
    CHECK_FAILS(sp_clip_load(&c, wpath, cfg, NULL, &err), SP_E_FORMAT, &err, "hidden_size");
    write_text(cfg, "{\"text_config\": {}}");
    CHECK_FAILS(sp_clip_load(&c, wpath, cfg, NULL, &err), SP_E_FORMAT, &err, "vision_config");
    /* a missing tensor, named */
    snprintf(p, sizeof p, "%s/sub", dir);
    sp_mkdirs(p, &err);
    snprintf(p, sizeof p, "%s/sub/model.safetensors", dir);
    CHECK(save(p, 7, 0) == 0);
    CHECK_FAILS(sp_clip_load(&c, p, NULL, NULL, &err), SP_E_NOTFOUND, &err, W[7].name);
    /* truncated file */
    CHECK(save(p, -1, 1000) == 0);
    CHECK(sp_clip_load(&c, p, NULL, NULL, &err) != 0);
    CHECK(strstr(err.msg, "model.safetensors") != NULL);
    fprintf(stderr, "truncated: %s\n", err.msg);
    /* shapes inferred without config.json give the same model */
    CHECK(save(p, -1, 0) == 0);
    CHECK_OK(sp_clip_load(&c, p, NULL, NULL, &err), &err);
    if (c) {
        const sp_clip_config *g = sp_clip_get_config(c);
        CHECK(g->text.width == TW && g->text.layers == TL && g->vision.width == VW && g->patch_size == PS &&
              g->image_size == IMG && g->projection_dim == PROJ && g->text.mlp == TM);
    }
    sp_clip_free(c);
}

int main(int argc, char **argv)
{
    TEST_ARGS(argc, argv);
    snprintf(dir, sizeof dir, "%s", test_tmpdir(t_gpu_mode ? "clip_model_gpu" : "clip_model"));
    snprintf(wpath, sizeof wpath, "%s/model.safetensors", dir);
    make_model();
    if (save(wpath, -1, 0)) return 1;
    snprintf(config_json, sizeof config_json,
             "{\"model_type\": \"clip\", \"projection_dim\": %d,\n"
             " \"text_config\": {\"hidden_size\": %d, \"num_hidden_layers\": %d, \"num_attention_heads\": %d, "
             "\"intermediate_size\": %d, \"hidden_act\": \"quick_gelu\", \"eos_token_id\": 2},\n"
             " \"vision_config\": {\"hidden_size\": %d, \"num_hidden_layers\": %d, \"num_attention_heads\": %d, "
             "\"intermediate_size\": %d, \"patch_size\": %d, \"image_size\": %d}}\n",
             PROJ, TW, TL, TH, TM, VW, VL, VH, VM, PS, IMG);
    char cpath[1200];
    snprintf(cpath, sizeof cpath, "%s/config.json", dir);
    write_text(cpath, config_json);
    RUN(test_text);
    RUN(test_vision);
    RUN(test_half_files);
    RUN(test_half_host);
    RUN_GPU(test_gpu);
    RUN_GPU(test_gpu_attention);
    RUN(test_errors);
    for (int i = 0; i < n_w; i++) free(W[i].data);
    return TEST_EXIT();
}
