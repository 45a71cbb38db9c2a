/* CLIP towers on the GPU. Per block: LayerNorm, the fused QKV product with its bias in the
 * epilogue, fused attention reading q/k/v in place, the output product with bias + residual in
 * its epilogue, LayerNorm, fc1 with its bias, QuickGELU in place, fc2 with bias + residual.
 * Weights and activations in fp16 (fp32 accumulation, statistics in fp32) or all fp32. Inputs
 * come up through pinned staging. Mirrors src/clip/cpu.c. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "clip_gpu.cuh"

static size_t off_of(const sp_clip *c, const float *p) { return (size_t)(p - c->blob); }

static int dev_alloc(sp_clip_gpu *g, void **p, size_t bytes, const char *what, sp_error *err)
{
    *p = sp_device_alloc_scratch(g->dev, bytes, err);
    return *p ? 0 : sp_error_prefix(err, "CLIP GPU: %s: ", what);
}

int clip_arena_grow(sp_clip_gpu *g, size_t need, sp_error *err)
{
    sp_device_release(g->dev, g->arena);
    g->arena = NULL;
    g->arena_cap = 0;
    int rc = dev_alloc(g, &g->arena, need, "scratch", err);
    if (!rc) g->arena_cap = need;
    return rc;
}

/* the fused [3w][w] QKV weight and [3w] bias of every layer, after the blob (16-float aligned) */
static size_t fused_floats(size_t w) { return (3 * w * w + 3 * w + 15) & ~(size_t)15; }

static int fuse_qkv(sp_clip *c, sp_clip_gpu *g, size_t *at, sp_error *err)
{
    cudaStream_t st = g->stream;
    for (int tower = 0; tower < 2; tower++) {
        const clip_tower *tw = tower ? &c->vision : &c->text;
        gpu_layer *gl = tower ? g->vision : g->text;
        size_t w = (size_t)tw->cfg.width;
        for (int l = 0; l < tw->cfg.layers; l++) {
            const clip_layer *L = &tw->layers[l];
            gpu_layer *o = &gl[l];
            o->ln1_w = off_of(c, L->ln1_w); o->ln1_b = off_of(c, L->ln1_b);
            o->o_w = off_of(c, L->o_w); o->o_b = off_of(c, L->o_b);
            o->ln2_w = off_of(c, L->ln2_w); o->ln2_b = off_of(c, L->ln2_b);
            o->fc1_w = off_of(c, L->fc1_w); o->fc1_b = off_of(c, L->fc1_b);
            o->fc2_w = off_of(c, L->fc2_w); o->fc2_b = off_of(c, L->fc2_b);
            o->qkv_w = *at;
            o->qkv_b = *at + 3 * w * w;
            const float *sw[3] = {L->q_w, L->k_w, L->v_w}, *sb[3] = {L->q_b, L->k_b, L->v_b};
            for (int k = 0; k < 3; k++) {
                CK(cudaMemcpyAsync(g->w32 + o->qkv_w + k * w * w, g->w32 + off_of(c, sw[k]), w * w * sizeof(float),
                                   cudaMemcpyDeviceToDevice, st), "qkv weights");
                CK(cudaMemcpyAsync(g->w32 + o->qkv_b + k * w, g->w32 + off_of(c, sb[k]), w * sizeof(float),
                                   cudaMemcpyDeviceToDevice, st), "qkv bias");
            }
            *at += fused_floats(w);
        }
    }
    return 0;
}

extern "C" int clip_gpu_init(sp_clip *c, sp_error *err)
{
    sp_clip_gpu *g = (sp_clip_gpu *)calloc(1, sizeof *g);
    if (!g) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    c->gpu = g;
    g->dev = c->dev;
    g->stream = sp_cuda_stream(c->dev);
    if (!(g->blas = sp_cuda_blas(c->dev, err))) return sp_error_prefix(err, "CLIP GPU: ");
    /* without cuBLASLt the plain products still run (lin falls back) */
    if (cublasLtCreate(&g->lt) != CUBLAS_STATUS_SUCCESS) g->lt = NULL;
    g->lt_ws_size = (size_t)32 << 20;
    int rc = dev_alloc(g, &g->lt_ws, g->lt_ws_size, "cuBLASLt workspace", err);
    if (rc) return rc;
    g->text = (gpu_layer *)calloc((size_t)c->cfg.text.layers, sizeof(gpu_layer));
    g->vision = (gpu_layer *)calloc((size_t)c->cfg.vision.layers, sizeof(gpu_layer));
    if (!g->text || !g->vision) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    size_t extra = (size_t)c->cfg.text.layers * fused_floats((size_t)c->cfg.text.width) +
                   (size_t)c->cfg.vision.layers * fused_floats((size_t)c->cfg.vision.width);
    g->n_floats = c->blob_floats + extra;
    if ((rc = dev_alloc(g, (void **)&g->w32, g->n_floats * sizeof(float), "weights", err))) return rc;
    CK(cudaMemsetAsync(g->w32 + c->blob_floats, 0, extra * sizeof(float), g->stream), "weights");
    CK(cudaMemcpyAsync(g->w32, c->blob, c->blob_floats * sizeof(float), cudaMemcpyHostToDevice, g->stream),
       "weights upload");
    size_t at = c->blob_floats;
    if ((rc = fuse_qkv(c, g, &at, err))) return rc;
    CK(cudaStreamSynchronize(g->stream), "weights upload");
    return 0;
}

extern "C" void clip_gpu_free(sp_clip *c)
{
    sp_clip_gpu *g = c->gpu;
    if (!g) return;
    cudaStreamSynchronize(g->stream);
    clip_lt_free(g);
    for (int i = 0; i < g->prof.made; i++) cudaEventDestroy(g->prof.ev[i]);
    for (int i = 0; i < 2; i++) {
        if (g->pin.buf[i]) cudaFreeHost(g->pin.buf[i]);
        if (g->pin.done[i]) cudaEventDestroy(g->pin.done[i]);
    }
    sp_device_release(g->dev, g->w32);
    sp_device_release(g->dev, g->w16);
    sp_device_release(g->dev, g->arena);
    sp_device_release(g->dev, g->lt_ws);
    sp_device_scratch_release(g->dev, &g->io_in);
    sp_device_scratch_release(g->dev, &g->io_out);
    sp_device_scratch_release(g->dev, &g->pos);
    for (int i = 0; i < 8; i++) sp_device_scratch_release(g->dev, &g->dense[i]);
    free(g->text);
    free(g->vision);
    free(g);
    c->gpu = NULL;
}

extern "C" int clip_gpu_set_fp16(sp_clip *c, int on, sp_error *err)
{
    sp_clip_gpu *g = c->gpu;
    if (on && !g->w16) {
        int rc = dev_alloc(g, (void **)&g->w16, g->n_floats * sizeof(__half), "fp16 weights", err);
        if (rc) return rc;
        launch_f32_to_f16(g->w32, g->w16, (long)g->n_floats, g->stream);
        CK(cudaStreamSynchronize(g->stream), "fp16 conversion");
    }
    c->fp16 = on;
    return 0;
}

extern "C" void clip_gpu_set_flags(sp_clip *c, int flags)
{
    if (c->gpu) c->gpu->flags = flags;
}

/* ---- uploads through pinned staging ------------------------------------------------------------------ */

struct copy_job {
    char *dst;
    const char *src;
    size_t n, piece; /* elements (bytes when not converting) */
    int to_half;
};

static void copy_piece(void *ctx, long i, int thread_id)
{
    copy_job *j = (copy_job *)ctx;
    size_t at = (size_t)i * j->piece, n = j->n - at < j->piece ? j->n - at : j->piece;
    if (j->to_half) clip_floats_to_half((const float *)j->src + at, (uint16_t *)j->dst + at, n);
    else memcpy(j->dst + at, j->src + at, n);
}

/* bytes of src (or, to_half, bytes / 4 floats becoming halves at dst) through the two pinned
 * slots: pool threads fill one while the copy engine drains the other */
static int upload_staged(sp_clip *c, void *dst, const void *src, size_t bytes, int to_half, sp_error *err)
{
    sp_clip_gpu *g = c->gpu;
    const size_t slot = (size_t)16 << 20, piece = (size_t)1 << 20;
    if (!g->pin.buf[0]) {
        for (int i = 0; i < 2; i++) {
            CK(cudaHostAlloc((void **)&g->pin.buf[i], slot, cudaHostAllocDefault), "pinned staging");
            CK(cudaEventCreateWithFlags(&g->pin.done[i], cudaEventDisableTiming), "staging event");
        }
        g->pin.cap = slot;
    }
    size_t unit = to_half ? 4 : 1, out_unit = to_half ? 2 : 1, per_slot = slot / out_unit, total = bytes / unit;
    int k = 0;
    for (size_t at = 0; at < total; at += per_slot, k ^= 1) {
        size_t n = total - at < per_slot ? total - at : per_slot;
        CK(cudaEventSynchronize(g->pin.done[k]), "staging"); /* that slot's last copy has drained */
        copy_job j = {g->pin.buf[k], (const char *)src + at * unit, n, piece / unit, to_half};
        sp_pool_for(c->pool, (long)((n + j.piece - 1) / j.piece), copy_piece, &j);
        CK(cudaMemcpyAsync((char *)dst + at * out_unit, g->pin.buf[k], n * out_unit, cudaMemcpyHostToDevice, g->stream),
           "upload");
        CK(cudaEventRecord(g->pin.done[k], g->stream), "staging");
    }
    return 0;
}

int clip_upload(sp_clip *c, void *dst, const void *src, size_t bytes, sp_error *err)
{
    if (bytes < ((size_t)2 << 20)) {
        CK(cudaMemcpyAsync(dst, src, bytes, cudaMemcpyHostToDevice, c->gpu->stream), "upload");
        return 0;
    }
    return upload_staged(c, dst, src, bytes, 0, err);
}

int clip_upload_half(sp_clip *c, __half *dst, const float *src, size_t count, sp_error *err)
{
    return upload_staged(c, dst, src, count * sizeof(float), 1, err);
}

/* ---- one transformer block ------------------------------------------------------------------------------ */

struct bufs_t {
    void *h, *qkv, *m, *s;
    void **ptrs;
};

template <typename T>
static void take_bufs(arena *ar, bufs_t *b, const sp_clip_gpu *g, size_t M, int w, int mlp, int B, int H, int Tn)
{
    int fused = attention_fused_ok(g, sizeof(T) == 2, B, w, H);
    b->h = take<T>(ar, M * w);
    b->qkv = take<T>(ar, M * 3 * w);
    b->m = take<T>(ar, M * (size_t)mlp);
    b->s = take<T>(ar, attention_score_count(B, H, Tn, fused));
    b->ptrs = take<void *>(ar, attention_ptr_count(B, H));
}

template <typename T>
static int block(ctx<T> &x, const sp_clip_tower_config *cfg, const gpu_layer *L, T *xb, int B, int Tn, int causal,
                 bufs_t *bf)
{
    int w = cfg->width, M = B * Tn, rc;
    cudaStream_t st = x.g->stream;
    T *h = (T *)bf->h, *qkv = (T *)bf->qkv, *m = (T *)bf->m;
    const T *W = x.W;
    sp_clip_gpu *g = x.g;
    launch_layernorm<T>(xb, h, M, w, W + L->ln1_w, W + L->ln1_b, cfg->eps, ln_plain(), st);
    clip_prof_mark(g, CLIP_STAGE_LN);
    if ((rc = lin(x, h, w, M, w, W + L->qkv_w, 3 * w, W + L->qkv_b, qkv, 0))) return rc;
    clip_prof_mark(g, CLIP_STAGE_QKV);
    if ((rc = attention(x, qkv, B, Tn, cfg->heads, w, causal, 0, h, (T *)bf->s, bf->ptrs))) return rc;
    clip_prof_mark(g, CLIP_STAGE_ATTN);
    if ((rc = lin(x, h, w, M, w, W + L->o_w, w, W + L->o_b, xb, 1))) return rc;
    clip_prof_mark(g, CLIP_STAGE_OPROJ);
    launch_layernorm<T>(xb, h, M, w, W + L->ln2_w, W + L->ln2_b, cfg->eps, ln_plain(), st);
    clip_prof_mark(g, CLIP_STAGE_LN);
    /* the MLP at once, or (CLIP_GPU_MLP_SLABS) in slabs of rows whose fc1 output (slab x mlp)
     * stays in L2 for the activation and fc2 */
    int slab = M, cap = g->flags & CLIP_GPU_SLABS_SMALL ? 16 : MLP_SLAB_ROWS;
    if ((g->flags & CLIP_GPU_MLP_SLABS) && M > cap) { /* even slabs, rows a multiple of 16 */
        int n = (M + cap - 1) / cap;
        slab = ((M + n - 1) / n + 15) & ~15;
    }
    for (int r = 0; r < M; r += slab) {
        int rows = M - r < slab ? M - r : slab;
        T *ms = m + (size_t)r * cfg->mlp;
        if ((rc = lin(x, h + (size_t)r * w, w, rows, w, W + L->fc1_w, cfg->mlp, W + L->fc1_b, ms, 0))) return rc;
        clip_prof_mark(g, CLIP_STAGE_FC1);
        launch_bias_act<T>(ms, rows, cfg->mlp, NULL, cfg->quick_gelu ? 1 : 2, st);
        clip_prof_mark(g, CLIP_STAGE_ACT);
        if ((rc = lin(x, ms, cfg->mlp, rows, cfg->mlp, W + L->fc2_w, w, W + L->fc2_b, xb + (size_t)r * w, 1)))
            return rc;
        clip_prof_mark(g, CLIP_STAGE_FC2);
    }
    return 0;
}

/* The block over B sequences at once, or (CLIP_GPU_BLOCK_SLABS) over slabs of sequences of at most
 * BLOCK_SLAB_ROWS rows, so that a slab's QKV rows are still in L2 for the attention (and its
 * LayerNorm output for the products); the scratch is reused slab after slab. */
template <typename T>
static int block_slabs(ctx<T> &x, const sp_clip_tower_config *cfg, const gpu_layer *L, T *xb, int B, int Tn,
                       int causal, bufs_t *bf)
{
    int per = B, rc = 0;
    if (x.g->flags & CLIP_GPU_BLOCK_SLABS) {
        int cap = x.g->flags & CLIP_GPU_SLABS_SMALL ? 1 : BLOCK_SLAB_ROWS / Tn;
        if (cap < 1) cap = 1;
        if (B > cap) {
            int n = (B + cap - 1) / cap;
            per = (B + n - 1) / n;
        }
    }
    for (int b0 = 0; b0 < B && !rc; b0 += per)
        rc = block(x, cfg, L, xb + (size_t)b0 * Tn * cfg->width, B - b0 < per ? B - b0 : per, Tn, causal, bf);
    return rc;
}

/* ---- stage timing (CLIP_GPU_PROFILE) ------------------------------------------------------------------ */

void clip_prof_begin(sp_clip_gpu *g)
{
    g->prof.n = 0;
    if (!(g->flags & CLIP_GPU_PROFILE)) return;
    for (; g->prof.made < PROF_EVENTS; g->prof.made++)
        if (cudaEventCreate(&g->prof.ev[g->prof.made]) != cudaSuccess) break;
    if (g->prof.made < PROF_EVENTS) return; /* no events: no timing (the forward itself is unaffected) */
    cudaEventRecord(g->prof.ev[0], g->stream);
    g->prof.stage[0] = CLIP_STAGE_OTHER;
    g->prof.n = 1;
}

void clip_prof_mark(sp_clip_gpu *g, int stage)
{
    /* past the last event the time goes into the next stage that gets one (none: lost) */
    if (!g->prof.n || g->prof.n >= PROF_EVENTS) return;
    cudaEventRecord(g->prof.ev[g->prof.n], g->stream);
    g->prof.stage[g->prof.n++] = stage;
}

void clip_prof_collect(sp_clip_gpu *g)
{
    if (g->prof.n < 2) return;
    for (int i = 1; i < g->prof.n; i++) {
        float ms = 0;
        if (cudaEventElapsedTime(&ms, g->prof.ev[i - 1], g->prof.ev[i]) == cudaSuccess)
            g->prof.ms[g->prof.stage[i]] += ms;
    }
    g->prof.forwards++;
    g->prof.n = 0;
}

extern "C" int clip_gpu_stage_ms(sp_clip *c, double ms[CLIP_STAGES])
{
    sp_clip_gpu *g = c->gpu;
    int n = g ? g->prof.forwards : 0;
    for (int i = 0; i < CLIP_STAGES; i++) {
        ms[i] = g ? g->prof.ms[i] : 0;
        if (g) g->prof.ms[i] = 0;
    }
    if (g) g->prof.forwards = 0;
    return n;
}

template <typename T> static ctx<T> ctx_of(sp_clip *c, sp_error *err)
{
    sp_clip_gpu *g = c->gpu;
    ctx<T> x = {c, g, (const T *)(sizeof(T) == 2 ? (void *)g->w16 : (void *)g->w32), err};
    return x;
}

static int finish(sp_clip_gpu *g, float *out, const float *d_out, size_t n, const char *what, sp_error *err)
{
    cudaError_t launch = cudaGetLastError(); /* a refused launch configuration shows only here */
    if (launch != cudaSuccess)
        return sp_error_set(err, SP_E_DEVICE, "CLIP GPU: %s: %s", what, cudaGetErrorString(launch));
    if (cudaMemcpyAsync(out, d_out, n * sizeof(float), cudaMemcpyDeviceToHost, g->stream) != cudaSuccess ||
        cudaStreamSynchronize(g->stream) != cudaSuccess)
        return sp_error_set(err, SP_E_DEVICE, "CLIP GPU: %s failed: %s", what, cudaGetErrorString(cudaGetLastError()));
    clip_prof_collect(g);
    return 0;
}

/* ---- text ------------------------------------------------------------------------------------------------- */

template <typename T>
static int text_forward(sp_clip *c, const int32_t *ids, int n, float *out, sp_error *err)
{
    sp_clip_gpu *g = c->gpu;
    ctx<T> x = ctx_of<T>(c, err);
    const sp_clip_tower_config *cfg = &c->cfg.text;
    int w = cfg->width, P = c->cfg.projection_dim, ctxn = c->cfg.context, L = 1, rc = 0;
    int32_t *rows = (int32_t *)malloc((size_t)n * sizeof *rows);
    if (!rows) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    for (int i = 0; i < n; i++) {
        rows[i] = clip_eos_position(c, ids + (size_t)i * ctxn);
        if (rows[i] + 1 > L) L = rows[i] + 1;
    }
    /* sequences are cut to the longest EOS: causal attention never looks past a row */
    int32_t *hids = (int32_t *)malloc((size_t)n * L * sizeof *hids);
    if (!hids) {
        free(rows);
        return sp_error_set(err, SP_E_NOMEM, "out of memory");
    }
    for (int i = 0; i < n; i++) {
        memcpy(hids + (size_t)i * L, ids + (size_t)i * ctxn, (size_t)L * sizeof *hids);
        rows[i] += i * L;
    }
    size_t M = (size_t)n * L;
    for (int attempt = 0; attempt < 2; attempt++) {
        arena ar = {g, 0, 1};
        int32_t *d_ids = take<int32_t>(&ar, M), *d_rows = take<int32_t>(&ar, (size_t)n);
        T *xb = take<T>(&ar, M * w), *fin = take<T>(&ar, (size_t)n * w), *po = take<T>(&ar, (size_t)n * P);
        float *o32 = take<float>(&ar, (size_t)n * P);
        bufs_t bf;
        take_bufs<T>(&ar, &bf, g, M, w, cfg->mlp, n, cfg->heads, L);
        if (!ar.fits) {
            if ((rc = clip_arena_grow(g, ar.need, err))) break;
            continue;
        }
        cudaStream_t st = g->stream;
        if (cudaMemcpyAsync(d_ids, hids, M * sizeof *hids, cudaMemcpyHostToDevice, st) != cudaSuccess ||
            cudaMemcpyAsync(d_rows, rows, (size_t)n * sizeof *rows, cudaMemcpyHostToDevice, st) != cudaSuccess) {
            rc = sp_error_set(err, SP_E_DEVICE, "CLIP GPU: upload failed");
            break;
        }
        clip_prof_begin(g);
        launch_embed_text<T>(d_ids, x.W + off_of(c, c->tok_emb), x.W + off_of(c, c->txt_pos), xb, (int)M, L, w, st);
        clip_prof_mark(g, CLIP_STAGE_OTHER);
        for (int l = 0; l < cfg->layers && !rc; l++) rc = block_slabs(x, cfg, &g->text[l], xb, n, L, 1, &bf);
        if (rc) break;
        ln_rows eos = {d_rows, 1, 1, 0};
        launch_layernorm<T>(xb, fin, n, w, x.W + off_of(c, c->final_ln_w), x.W + off_of(c, c->final_ln_b), cfg->eps,
                            eos, st);
        if ((rc = lin(x, fin, w, n, w, x.W + off_of(c, c->text_proj), P, (const T *)NULL, po, 0))) break;
        launch_to_float<T>(po, o32, (long)n * P, st);
        clip_prof_mark(g, CLIP_STAGE_OTHER);
        rc = finish(g, out, o32, (size_t)n * P, "text forward", err);
        break;
    }
    free(rows);
    free(hids);
    return rc;
}

/* ---- vision ------------------------------------------------------------------------------------------------ */

/* Position embeddings for a gh x gw grid on the device (kept for the next call of that size). */
static int pos_for(sp_clip *c, int gh, int gw, const float **d_pos, sp_error *err)
{
    sp_clip_gpu *g = c->gpu;
    int w = c->cfg.vision.width;
    size_t bytes = (size_t)(gh * gw + 1) * w * sizeof(float);
    if (!g->pos.ptr || g->pos_gh != gh || g->pos_gw != gw) {
        float *pos = (float *)malloc(bytes);
        if (!pos) return sp_error_set(err, SP_E_NOMEM, "out of memory");
        clip_pos_embed(c, gh, gw, pos);
        int rc = sp_device_scratch_reserve(g->dev, &g->pos, bytes, err);
        if (!rc && cudaMemcpy(g->pos.ptr, pos, bytes, cudaMemcpyHostToDevice) != cudaSuccess)
            rc = sp_error_set(err, SP_E_DEVICE, "CLIP GPU: position embeddings upload failed");
        free(pos);
        if (rc) return rc;
        g->pos_gh = gh;
        g->pos_gw = gw;
    }
    *d_pos = (const float *)g->pos.ptr;
    return 0;
}

/* The last block replaced by the dense head: MaskCLIP's value path or ClearCLIP's q-q attention,
 * no residual or FFN; result (with the CLS rows) in xb. */
template <typename T>
static int dense_head(ctx<T> &x, const sp_clip_tower_config *cfg, const gpu_layer *L, T *xb, int n, int Tn,
                      clip_out_kind kind, bufs_t *bf)
{
    int w = cfg->width, M = n * Tn, rc;
    T *h = (T *)bf->h, *qkv = (T *)bf->qkv;
    launch_layernorm<T>(xb, h, M, w, x.W + L->ln1_w, x.W + L->ln1_b, cfg->eps, ln_plain(), x.g->stream);
    if ((rc = lin(x, h, w, M, w, x.W + L->qkv_w, 3 * w, x.W + L->qkv_b, qkv, 0))) return rc;
    if (kind == CLIP_OUT_DENSE_MASKCLIP) /* out_proj(v): v read in place from the fused rows */
        return lin(x, qkv + 2 * w, 3 * w, M, w, x.W + L->o_w, w, x.W + L->o_b, xb, 0);
    if ((rc = attention(x, qkv, n, Tn, cfg->heads, w, 0, 1, h, (T *)bf->s, bf->ptrs))) return rc;
    return lin(x, h, w, M, w, x.W + L->o_w, w, x.W + L->o_b, xb, 0);
}

template <typename T>
static int vision_run(sp_clip *c, const void *d_px, int px_half, int n, int H, int W, clip_out_kind kind,
                      float *d_out, sp_error *err)
{
    sp_clip_gpu *g = c->gpu;
    ctx<T> x = ctx_of<T>(c, err);
    const sp_clip_tower_config *cfg = &c->cfg.vision;
    int w = cfg->width, P = c->cfg.projection_dim, p = c->cfg.patch_size, rc = 0;
    int gh = H / p, gw = W / p, np = gh * gw, Tn = np + 1, K = 3 * p * p;
    int dense = kind != CLIP_OUT_POOLED, layers = cfg->layers - (dense ? 1 : 0);
    size_t M = (size_t)n * Tn, n_out = dense ? (size_t)n * np : (size_t)n;
    const float *d_pos = NULL;
    if ((rc = pos_for(c, gh, gw, &d_pos, err))) return rc;
    for (int attempt = 0; attempt < 2; attempt++) {
        arena ar = {g, 0, 1};
        T *cols = take<T>(&ar, (size_t)n * np * K), *pe = take<T>(&ar, (size_t)n * np * w);
        T *xb = take<T>(&ar, M * w), *fin = take<T>(&ar, n_out * w);
        T *po = sizeof(T) == 4 ? (T *)d_out : take<T>(&ar, n_out * P);
        bufs_t bf;
        take_bufs<T>(&ar, &bf, g, M, w, cfg->mlp, n, cfg->heads, Tn);
        if (!ar.fits) {
            if ((rc = clip_arena_grow(g, ar.need, err))) break;
            continue;
        }
        cudaStream_t st = g->stream;
        clip_prof_begin(g);
        launch_im2col<T>(d_px, px_half, cols, n, H, W, p, st);
        if ((rc = lin(x, cols, K, n * np, K, x.W + off_of(c, c->patch_w), w, (const T *)NULL, pe, 0))) break;
        launch_assemble<T>(pe, x.W + off_of(c, c->cls), d_pos, xb, n, Tn, w, st);
        launch_layernorm<T>(xb, xb, (int)M, w, x.W + off_of(c, c->pre_ln_w), x.W + off_of(c, c->pre_ln_b), cfg->eps,
                            ln_plain(), st);
        clip_prof_mark(g, CLIP_STAGE_OTHER);
        for (int l = 0; l < layers && !rc; l++) rc = block_slabs(x, cfg, &g->vision[l], xb, n, Tn, 0, &bf);
        if (!rc && dense) rc = dense_head(x, cfg, &g->vision[cfg->layers - 1], xb, n, Tn, kind, &bf);
        if (rc) break;
        /* pooled: the CLS row of each image; dense: every patch row (CLS rows skipped) */
        ln_rows pick = dense ? ln_rows{NULL, Tn - 1, Tn, 1} : ln_rows{NULL, 1, Tn, 0};
        launch_layernorm<T>(xb, fin, (int)n_out, w, x.W + off_of(c, c->post_ln_w), x.W + off_of(c, c->post_ln_b),
                            cfg->eps, pick, st);
        if ((rc = lin(x, fin, w, (int)n_out, w, x.W + off_of(c, c->vis_proj), P, (const T *)NULL, po, 0))) break;
        if (sizeof(T) == 2) launch_to_float<T>(po, d_out, (long)(n_out * P), st);
        clip_prof_mark(g, CLIP_STAGE_OTHER);
        CK(cudaGetLastError(), "vision forward");
        break;
    }
    return rc;
}

int clip_vision_device(sp_clip *c, const void *d_px, int px_half, int n, int H, int W, clip_out_kind kind,
                       float *d_out, sp_error *err)
{
    return c->fp16 ? vision_run<__half>(c, d_px, px_half, n, H, W, kind, d_out, err)
                   : vision_run<float>(c, d_px, px_half, n, H, W, kind, d_out, err);
}

/* ---- entry points ------------------------------------------------------------------------------------------- */

extern "C" int clip_gpu_text(sp_clip *c, const int32_t *ids, int n, float *out, sp_error *err)
{
    return c->fp16 ? text_forward<__half>(c, ids, n, out, err) : text_forward<float>(c, ids, n, out, err);
}

extern "C" int clip_gpu_vision(sp_clip *c, const float *pixels, int n, int H, int W, clip_out_kind kind, float *out,
                               sp_error *err)
{
    sp_clip_gpu *g = c->gpu;
    int p = c->cfg.patch_size, P = c->cfg.projection_dim, half = c->fp16; /* fp16: the pixels go up as fp16 */
    size_t count = (size_t)n * 3 * H * W;
    size_t n_out = kind == CLIP_OUT_POOLED ? (size_t)n : (size_t)n * (H / p) * (W / p);
    int rc;
    if ((rc = sp_device_scratch_reserve(g->dev, &g->io_in, count * (half ? 2 : 4), err)) ||
        (rc = sp_device_scratch_reserve(g->dev, &g->io_out, n_out * P * sizeof(float), err)))
        return rc;
    rc = half ? clip_upload_half(c, (__half *)g->io_in.ptr, pixels, count, err)
              : clip_upload(c, g->io_in.ptr, pixels, count * sizeof(float), err);
    if (rc || (rc = clip_vision_device(c, g->io_in.ptr, half, n, H, W, kind, (float *)g->io_out.ptr, err))) return rc;
    g->io_half = half;
    return finish(g, out, (const float *)g->io_out.ptr, n_out * P, "vision forward", err);
}

/* Benchmarks: the last vision call again on the pixels still on the device (no upload). */
extern "C" int clip_gpu_vision_again(sp_clip *c, int n, int H, int W, float *out, sp_error *err)
{
    sp_clip_gpu *g = c->gpu;
    size_t in = (size_t)n * 3 * H * W * (g && g->io_half ? 2 : 4);
    if (!g || !g->io_in.ptr || g->io_in.cap < in || g->io_half != c->fp16 ||
        g->io_out.cap < (size_t)n * c->cfg.projection_dim * sizeof(float))
        return sp_error_set(err, SP_E_ARG, "CLIP GPU: no %d images of %dx%d on the device", n, W, H);
    int rc = clip_vision_device(c, g->io_in.ptr, g->io_half, n, H, W, CLIP_OUT_POOLED, (float *)g->io_out.ptr, err);
    return rc ? rc : finish(g, out, (const float *)g->io_out.ptr, (size_t)n * c->cfg.projection_dim, "vision forward", err);
}
