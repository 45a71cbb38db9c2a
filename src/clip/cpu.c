/* The CLIP towers on the CPU: matrix products through OpenBLAS (its own threads), row-wise work
 * (LayerNorm, activations, softmax) across the sp_pool. One transformer block code path serves
 * the text tower (causal, variable-length sequences packed row after row) and the vision tower
 * (full attention), and the dense head replaces the vision tower's last block. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "clip_internal.h"

#ifndef SP_CLIP_NO_BLAS
#include <cblas.h>

/* C = alpha op(A) op(B) + beta C, row-major (ta/tb: 1 = transposed) */
static void gemm(sp_pool *pool, int ta, int tb, int M, int N, int K, float alpha, const float *A,
                 int lda, const float *B, int ldb, float beta, float *C, int ldc)
{
    (void)pool; /* OpenBLAS runs its own threads */
    cblas_sgemm(CblasRowMajor, ta ? CblasTrans : CblasNoTrans, tb ? CblasTrans : CblasNoTrans, M, N,
                K, alpha, A, lda, B, ldb, beta, C, ldc);
}
#else
/* Without a BLAS (minimal builds on machines lacking the -dev package): the same product with
 * plain loops, rows spread over the pool. Slow but exact to float rounding. */
typedef struct gemm_job {
    int ta, tb, M, N, K, lda, ldb, ldc;
    float alpha, beta;
    const float *A, *B;
    float *C;
} gemm_job;

static void gemm_rows(void *ctx, long chunk, int tid)
{
    const gemm_job *g = ctx;
    int i1 = (int)((chunk + 1) * 8 < g->M ? (chunk + 1) * 8 : g->M);
    for (int i = (int)chunk * 8; i < i1; i++)
        for (int j = 0; j < g->N; j++) {
            float acc[8] = {0};
            int k = 0;
            if (!g->ta && g->tb) {
                const float *a = g->A + (size_t)i * g->lda, *b = g->B + (size_t)j * g->ldb;
                for (; k + 8 <= g->K; k += 8)
                    for (int u = 0; u < 8; u++) acc[u] += a[k + u] * b[k + u];
            }
            float s = 0;
            for (; k < g->K; k++) {
                float a = g->ta ? g->A[(size_t)k * g->lda + i] : g->A[(size_t)i * g->lda + k];
                float b = g->tb ? g->B[(size_t)j * g->ldb + k] : g->B[(size_t)k * g->ldb + j];
                s += a * b;
            }
            for (int u = 0; u < 8; u++) s += acc[u];
            float *c = g->C + (size_t)i * g->ldc + j;
            *c = g->alpha * s + (g->beta != 0 ? g->beta * *c : 0.f);
        }
}

static void gemm(sp_pool *pool, int ta, int tb, int M, int N, int K, float alpha, const float *A,
                 int lda, const float *B, int ldb, float beta, float *C, int ldc)
{
    gemm_job g = {ta, tb, M, N, K, lda, ldb, ldc, alpha, beta, A, B, C};
    sp_pool_for(pool, (M + 7) / 8, gemm_rows, &g);
}
#endif

/* Y[M][N] = X[M][K] W^T (+ beta*Y) + b: W in PyTorch Linear layout [N][K]. */
static void linear(sp_pool *pool, const float *X, int M, int K, const float *W, const float *b,
                   int N, float *Y, float beta)
{
    gemm(pool, 0, 1, M, N, K, 1.f, X, K, W, K, beta, Y, N);
    if (b)
        for (long i = 0; i < M; i++) {
            float *y = Y + (size_t)i * N;
            for (int j = 0; j < N; j++) y[j] += b[j];
        }
}

typedef struct rows_job {
    const float *x;
    float *y;
    int n, act;            /* row length; activation kind */
    const float *g, *b;    /* LayerNorm weight and bias */
    float eps;
    long rows;
} rows_job;

#define ROW_CHUNK 16

static void ln_rows(void *ctx, long chunk, int tid)
{
    const rows_job *j = ctx;
    long r1 = (chunk + 1) * ROW_CHUNK < j->rows ? (chunk + 1) * ROW_CHUNK : j->rows;
    for (long r = chunk * ROW_CHUNK; r < r1; r++) {
        const float *x = j->x + (size_t)r * j->n;
        float *y = j->y + (size_t)r * j->n;
        double s = 0, s2 = 0;
        for (int i = 0; i < j->n; i++) s += x[i];
        double mean = s / j->n;
        for (int i = 0; i < j->n; i++) {
            double d = x[i] - mean;
            s2 += d * d;
        }
        float inv = (float)(1.0 / sqrt(s2 / j->n + j->eps)), m = (float)mean;
        for (int i = 0; i < j->n; i++) y[i] = (x[i] - m) * inv * j->g[i] + j->b[i];
    }
}

static void layer_norm(sp_pool *pool, const float *x, float *y, long rows, int n, const float *g,
                       const float *b, float eps)
{
    rows_job j = {x, y, n, 0, g, b, eps, rows};
    sp_pool_for(pool, (rows + ROW_CHUNK - 1) / ROW_CHUNK, ln_rows, &j);
}

static void act_rows(void *ctx, long chunk, int tid)
{
    const rows_job *j = ctx;
    long r1 = (chunk + 1) * ROW_CHUNK < j->rows ? (chunk + 1) * ROW_CHUNK : j->rows;
    for (long r = chunk * ROW_CHUNK; r < r1; r++) {
        float *y = j->y + (size_t)r * j->n;
        if (j->act) /* quick_gelu: x * sigmoid(1.702 x) */
            for (int i = 0; i < j->n; i++) y[i] = y[i] / (1.f + expf(-1.702f * y[i]));
        else
            for (int i = 0; i < j->n; i++) y[i] = 0.5f * y[i] * (1.f + erff(y[i] * 0.70710678f));
    }
}

typedef struct softmax_job {
    float *s;
    int T;
    int causal;
    long rows; /* heads * T */
} softmax_job;

static void softmax_rows(void *ctx, long r, int tid)
{
    const softmax_job *j = ctx;
    float *s = j->s + (size_t)r * j->T;
    int q = (int)(r % j->T), n = j->causal ? q + 1 : j->T;
    float m = s[0];
    for (int i = 1; i < n; i++) m = s[i] > m ? s[i] : m;
    double sum = 0;
    for (int i = 0; i < n; i++) {
        s[i] = expf(s[i] - m);
        sum += s[i];
    }
    float inv = (float)(1.0 / sum);
    for (int i = 0; i < n; i++) s[i] *= inv;
    for (int i = n; i < j->T; i++) s[i] = 0;
}

typedef struct work {
    float *h, *q, *k, *v, *o, *m, *s;
} work;

/* Multi-head attention of one sequence of T rows (row stride w): o = softmax(a b^T * scale) v,
 * with a = q, b = k normally, a = b = q for ClearCLIP's self-self attention. */
static void attention(sp_pool *pool, const sp_clip_tower_config *cfg, const float *a,
                      const float *b, const float *v, float *o, int T, int causal, float *s)
{
    int w = cfg->width, H = cfg->heads, d = w / H;
    float scale = 1.f / sqrtf((float)d);
    for (int h = 0; h < H; h++)
        gemm(pool, 0, 1, T, T, d, scale, a + h * d, w, b + h * d, w, 0.f, s + (size_t)h * T * T, T);
    softmax_job sj = {s, T, causal, (long)H * T};
    sp_pool_for(pool, sj.rows, softmax_rows, &sj);
    for (int h = 0; h < H; h++)
        gemm(pool, 0, 0, T, d, T, 1.f, s + (size_t)h * T * T, T, v + h * d, w, 0.f, o + h * d, w);
}

/* One pre-LN block over M rows made of n_seq sequences (offsets/lengths). */
static void block(sp_pool *pool, const sp_clip_tower_config *cfg, const clip_layer *L, float *x,
                  int M, const int *off, const int *len, int n_seq, int causal, work *wk)
{
    int w = cfg->width;
    layer_norm(pool, x, wk->h, M, w, L->ln1_w, L->ln1_b, cfg->eps);
    linear(pool, wk->h, M, w, L->q_w, L->q_b, w, wk->q, 0.f);
    linear(pool, wk->h, M, w, L->k_w, L->k_b, w, wk->k, 0.f);
    linear(pool, wk->h, M, w, L->v_w, L->v_b, w, wk->v, 0.f);
    for (int s = 0; s < n_seq; s++) {
        size_t r = (size_t)off[s] * w;
        attention(pool, cfg, wk->q + r, wk->k + r, wk->v + r, wk->o + r, len[s], causal, wk->s);
    }
    linear(pool, wk->o, M, w, L->o_w, L->o_b, w, x, 1.f);
    layer_norm(pool, x, wk->h, M, w, L->ln2_w, L->ln2_b, cfg->eps);
    linear(pool, wk->h, M, w, L->fc1_w, L->fc1_b, cfg->mlp, wk->m, 0.f);
    rows_job aj = {NULL, wk->m, cfg->mlp, cfg->quick_gelu, NULL, NULL, 0, M};
    sp_pool_for(pool, (M + ROW_CHUNK - 1) / ROW_CHUNK, act_rows, &aj);
    linear(pool, wk->m, M, cfg->mlp, L->fc2_w, L->fc2_b, w, x, 1.f);
}

static int work_alloc(work *wk, size_t M, int w, int mlp, int T, int heads)
{
    memset(wk, 0, sizeof *wk);
    wk->h = sp_alloc(M * w * sizeof(float));
    wk->q = sp_alloc(M * w * sizeof(float));
    wk->k = sp_alloc(M * w * sizeof(float));
    wk->v = sp_alloc(M * w * sizeof(float));
    wk->o = sp_alloc(M * w * sizeof(float));
    wk->m = sp_alloc(M * mlp * sizeof(float));
    wk->s = sp_alloc((size_t)heads * T * T * sizeof(float));
    return wk->h && wk->q && wk->k && wk->v && wk->o && wk->m && wk->s ? 0 : -1;
}

static void work_free(work *wk)
{
    sp_free(wk->h); sp_free(wk->q); sp_free(wk->k); sp_free(wk->v);
    sp_free(wk->o); sp_free(wk->m); sp_free(wk->s);
}

int clip_cpu_text(sp_clip *c, const int32_t *ids, int n, float *out, sp_error *err)
{
    const sp_clip_tower_config *cfg = &c->cfg.text;
    int w = cfg->width, P = c->cfg.projection_dim, ctx = c->cfg.context;
    int *off = malloc((size_t)n * 2 * sizeof(int)), *len = off + n, M = 0;
    if (!off) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    /* causal attention: rows after the EOS token never influence it, so each sequence stops there */
    for (int i = 0; i < n; i++) {
        off[i] = M;
        len[i] = clip_eos_position(c, ids + (size_t)i * ctx) + 1;
        M += len[i];
    }
    float *x = sp_alloc((size_t)M * w * sizeof(float)), *fin = sp_alloc((size_t)n * w * sizeof(float));
    work wk = {0};
    int rc = 0;
    if (!x || !fin || work_alloc(&wk, (size_t)M, w, cfg->mlp, ctx, cfg->heads)) {
        rc = sp_error_set(err, SP_E_NOMEM, "out of memory for %d texts", n);
        goto done;
    }
    for (int i = 0; i < n; i++)
        for (int t = 0; t < len[i]; t++) {
            float *r = x + (size_t)(off[i] + t) * w;
            const float *e = c->tok_emb + (size_t)ids[(size_t)i * ctx + t] * w, *p = c->txt_pos + (size_t)t * w;
            for (int j = 0; j < w; j++) r[j] = e[j] + p[j];
        }
    for (int l = 0; l < cfg->layers; l++) block(c->pool, cfg, &c->text.layers[l], x, M, off, len, n, 1, &wk);
    for (int i = 0; i < n; i++)
        memcpy(fin + (size_t)i * w, x + (size_t)(off[i] + len[i] - 1) * w, (size_t)w * sizeof(float));
    layer_norm(c->pool, fin, fin, n, w, c->final_ln_w, c->final_ln_b, cfg->eps);
    linear(c->pool, fin, n, w, c->text_proj, NULL, P, out, 0.f);
done:
    work_free(&wk);
    sp_free(x);
    sp_free(fin);
    free(off);
    return rc;
}

typedef struct im2col_job {
    const float *pixels;
    float *cols;
    int H, W, p, gw, np;
} im2col_job;

static void im2col_row(void *ctx, long r, int tid)
{
    const im2col_job *j = ctx;
    int img = (int)(r / j->np), pi = (int)(r % j->np), py = pi / j->gw, px = pi % j->gw;
    float *o = j->cols + (size_t)r * 3 * j->p * j->p;
    const float *src = j->pixels + (size_t)img * 3 * j->H * j->W;
    for (int ch = 0; ch < 3; ch++)
        for (int ky = 0; ky < j->p; ky++) {
            const float *s = src + ((size_t)ch * j->H + py * j->p + ky) * j->W + px * j->p;
            memcpy(o, s, (size_t)j->p * sizeof(float));
            o += j->p;
        }
}

int clip_cpu_vision(sp_clip *c, const float *pixels, int n, int H, int W, clip_out_kind kind,
                    float *out, sp_error *err)
{
    const sp_clip_tower_config *cfg = &c->cfg.vision;
    int w = cfg->width, P = c->cfg.projection_dim, p = c->cfg.patch_size;
    int gh = H / p, gw = W / p, np = gh * gw, T = np + 1, M = n * T, K = 3 * p * p;
    int dense = kind != CLIP_OUT_POOLED, layers = cfg->layers - (dense ? 1 : 0);
    float *x = sp_alloc((size_t)M * w * sizeof(float));
    float *cols = sp_alloc((size_t)n * np * (K > w ? K : w) * sizeof(float));
    float *pos = sp_alloc((size_t)T * w * sizeof(float));
    int *off = malloc((size_t)n * 2 * sizeof(int)), *len = off ? off + n : NULL;
    work wk = {0};
    int rc = 0;
    if (!x || !cols || !pos || !off || work_alloc(&wk, (size_t)M, w, cfg->mlp, T, cfg->heads)) {
        rc = sp_error_set(err, SP_E_NOMEM, "out of memory for %d images of %dx%d", n, W, H);
        goto done;
    }
    /* patch embedding (a stride-p convolution without bias) as im2col + one product */
    im2col_job ij = {pixels, cols, H, W, p, gw, np};
    sp_pool_for(c->pool, (long)n * np, im2col_row, &ij);
    clip_pos_embed(c, gh, gw, pos);
    for (int i = 0; i < n; i++) {
        off[i] = i * T;
        len[i] = T;
        float *xi = x + (size_t)i * T * w;
        linear(c->pool, cols + (size_t)i * np * K, np, K, c->patch_w, NULL, w, xi + w, 0.f);
        for (int j = 0; j < w; j++) xi[j] = c->cls[j];
        for (size_t j = 0; j < (size_t)T * w; j++) xi[j] += pos[j];
    }
    layer_norm(c->pool, x, x, M, w, c->pre_ln_w, c->pre_ln_b, cfg->eps);
    for (int l = 0; l < layers; l++) block(c->pool, cfg, &c->vision.layers[l], x, M, off, len, n, 0, &wk);
    if (!dense) {
        float *cls = cols;
        for (int i = 0; i < n; i++) memcpy(cls + (size_t)i * w, x + (size_t)i * T * w, (size_t)w * sizeof(float));
        layer_norm(c->pool, cls, cls, n, w, c->post_ln_w, c->post_ln_b, cfg->eps);
        linear(c->pool, cls, n, w, c->vis_proj, NULL, P, out, 0.f);
        goto done;
    }
    /* dense head: the last block without residual and FFN, attention replaced by the value path
     * (MaskCLIP) or q-q attention (ClearCLIP); then post-LN and the projection on every patch */
    const clip_layer *L = &c->vision.layers[cfg->layers - 1];
    layer_norm(c->pool, x, wk.h, M, w, L->ln1_w, L->ln1_b, cfg->eps);
    linear(c->pool, wk.h, M, w, L->v_w, L->v_b, w, wk.v, 0.f);
    const float *val = wk.v;
    if (kind == CLIP_OUT_DENSE_CLEARCLIP) {
        linear(c->pool, wk.h, M, w, L->q_w, L->q_b, w, wk.q, 0.f);
        for (int i = 0; i < n; i++) {
            size_t r = (size_t)i * T * w;
            attention(c->pool, cfg, wk.q + r, wk.q + r, wk.v + r, wk.o + r, T, 0, wk.s);
        }
        val = wk.o;
    }
    linear(c->pool, val, M, w, L->o_w, L->o_b, w, x, 0.f);
    for (int i = 0; i < n; i++) /* patch rows only */
        memcpy(cols + (size_t)i * np * w, x + ((size_t)i * T + 1) * w, (size_t)np * w * sizeof(float));
    layer_norm(c->pool, cols, cols, (long)n * np, w, c->post_ln_w, c->post_ln_b, cfg->eps);
    linear(c->pool, cols, n * np, w, c->vis_proj, NULL, P, out, 0.f);
done:
    work_free(&wk);
    sp_free(x);
    sp_free(cols);
    sp_free(pos);
    free(off);
    return rc;
}
