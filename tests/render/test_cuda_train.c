/* The trainer's GPU kernels (src/train/cuda/, the CUDA table of train_kernels.h) against their CPU
 * references in src/train/loss.c (which have their own finite-difference tests): L1+SSIM loss and
 * gradient, feature MSE, the depth loss, Adam, densification statistics, column copy, the row
 * gather of density control, the NaN guard, bad sizes.
 * Skips (77) without a GPU or without the CUDA build. */
#include "test.h"

#include <stdint.h>

#include "semsplat/render.h"
#include "train/train_internal.h"

static sp_device *g_gpu;
static const tr_kernels *K; /* the CUDA table */

static uint64_t rs = 0x9E3779B97F4A7C15ull;
static float frand(void)
{
    rs ^= rs << 13;
    rs ^= rs >> 7;
    rs ^= rs << 17;
    return (float)((rs >> 40) & 0xffffff) / 16777216.0f;
}

static float *up(const float *h, size_t n, sp_error *err)
{
    float *d = sp_device_alloc(g_gpu, n * 4, err);
    if (d && h) sp_device_upload(g_gpu, d, h, n * 4, err);
    return d;
}
static void down(float *h, const float *d, size_t n, sp_error *err) { sp_device_download(g_gpu, h, d, n * 4, err); }
static void dfree(void *d) { sp_device_release(g_gpu, d); }

static double max_rel(const float *a, const float *b, size_t n)
{
    double m = 1e-12, e = 0;
    for (size_t i = 0; i < n; i++) m = fmax(m, fabs(b[i]));
    for (size_t i = 0; i < n; i++) e = fmax(e, fabs((double)a[i] - b[i]));
    return e / m;
}

static void test_rgb_loss(void)
{
    sp_error err = {0};
    int H = 37, W = 53, C = 3, S = 5;
    size_t np = (size_t)H * W;
    float *pred = malloc(np * S * 4), *tgt = malloc(np * C * 4);
    for (size_t i = 0; i < np * S; i++) pred[i] = frand();
    for (size_t i = 0; i < np * C; i++) tgt[i] = frand();
    float *scr = malloc(SP_LOSS_SCRATCH_FLOATS(H, W, C) * 4);
    float *v = calloc(np * S, 4), *vg = malloc(np * S * 4);
    double st[4], stg[4];
    CHECK_OK(cpu_rgb_loss(NULL, pred, S, tgt, H, W, C, 0.2f, scr, v, st, &err), &err);
    float *dp = up(pred, np * S, &err), *dt = up(tgt, np * C, &err);
    float *ds = up(NULL, SP_LOSS_SCRATCH_FLOATS(H, W, C), &err), *dv = up(NULL, np * S, &err);
    CHECK_OK(K->rgb_loss(g_gpu, dp, S, dt, H, W, C, 0.2f, ds, dv, stg, &err), &err);
    down(vg, dv, np * S, &err);
    for (int k = 0; k < 4; k++) CHECK_NEAR(stg[k], st[k], 1e-5 * fmax(1.0, fabs(st[k])));
    CHECK(max_rel(vg, v, np * S) < 1e-4);
    /* channels beyond C of the stride stay untouched */
    CHECK(vg[3] == 0.f && vg[4] == 0.f);
    /* evaluation only */
    CHECK_OK(K->rgb_loss(g_gpu, dp, S, dt, H, W, C, 0.2f, ds, NULL, stg, &err), &err);
    CHECK_NEAR(stg[2], st[2], 1e-5);
    CHECK_FAILS(K->rgb_loss(g_gpu, dp, S, dt, 10, W, C, 0.2f, ds, dv, stg, &err), SP_E_ARG, &err,
                "needs >= 11x11");
    dfree(dp), dfree(dt), dfree(ds), dfree(dv);
    free(pred), free(tgt), free(scr), free(v), free(vg);
}

static void test_feature_mse(void)
{
    sp_error err = {0};
    int H = 20, W = 31, F = 16, S = 19, off = 3;
    size_t np = (size_t)H * W;
    float *pred = malloc(np * S * 4), *tgt = malloc(np * F * 4);
    for (size_t i = 0; i < np * S; i++) pred[i] = frand();
    for (size_t i = 0; i < np * F; i++) tgt[i] = frand();
    float *v = calloc(np * S, 4), *vg = malloc(np * S * 4);
    double m, mg;
    CHECK_OK(cpu_feature_mse(NULL, pred, S, off, tgt, H, W, F, 0.5f, v, &m, &err), &err);
    float *dp = up(pred, np * S, &err), *dt = up(tgt, np * F, &err), *dv = up(NULL, np * S, &err);
    CHECK_OK(K->feature_mse(g_gpu, dp, S, off, dt, H, W, F, 0.5f, dv, &mg, &err), &err);
    down(vg, dv, np * S, &err);
    CHECK_NEAR(mg, m, 1e-6);
    CHECK(max_rel(vg, v, np * S) < 1e-5);
    CHECK_FAILS(K->feature_mse(g_gpu, dp, S, 4, dt, H, W, F, 0.5f, dv, &mg, &err), SP_E_ARG, &err,
                "stride 19");
    dfree(dp), dfree(dt), dfree(dv);
    free(pred), free(tgt), free(v), free(vg);
}

static void test_depth_loss(void)
{
    sp_error err = {0};
    int H = 37, W = 53;
    size_t np = (size_t)H * W;
    float *S = malloc(np * 4), *A = malloc(np * 4), *t = malloc(np * 4);
    for (size_t i = 0; i < np; i++) {
        A[i] = i % 9 == 0 ? 0.03f * frand() : 0.1f + 0.9f * frand(); /* some below the alpha floor */
        t[i] = i % 11 == 0 ? 0.0f : 0.5f + 5.0f * frand();           /* holes */
        S[i] = A[i] * (0.5f + 5.0f * frand());
    }
    float *vd = malloc(np * 4), *va = malloc(np * 4), *vdg = malloc(np * 4), *vag = malloc(np * 4);
    double st[3], stg[3];
    CHECK_OK(cpu_depth_loss(NULL, S, A, t, H, W, 0.7f, vd, va, st, &err), &err);
    float *dS = up(S, np, &err), *dA = up(A, np, &err), *dt = up(t, np, &err);
    float *dvd = up(NULL, np, &err), *dva = up(NULL, np, &err);
    CHECK_OK(K->depth_loss(g_gpu, dS, dA, dt, H, W, 0.7f, dvd, dva, stg, &err), &err);
    down(vdg, dvd, np, &err);
    down(vag, dva, np, &err);
    CHECK_NEAR(stg[0], st[0], 1e-6 * fmax(1.0, st[0]));
    CHECK_NEAR(stg[1], st[1], 1e-5 * fmax(1.0, st[1]));
    CHECK(stg[2] == st[2]);
    CHECK(max_rel(vdg, vd, np) < 1e-5);
    CHECK(max_rel(vag, va, np) < 1e-5);
    CHECK_OK(K->depth_loss(g_gpu, dS, dA, dt, H, W, 0.7f, NULL, NULL, stg, &err), &err);
    CHECK_NEAR(stg[0], st[0], 1e-6 * fmax(1.0, st[0]));
    CHECK_FAILS(K->depth_loss(g_gpu, dS, dA, dt, H, W, 0.7f, dvd, NULL, stg, &err), SP_E_ARG, &err,
                "together");
    dfree(dS), dfree(dA), dfree(dt), dfree(dvd), dfree(dva);
    free(S), free(A), free(t), free(vd), free(va), free(vdg), free(vag);
}

static void test_adam_and_stats(void)
{
    sp_error err = {0};
    size_t n = 100003;
    float *p = malloc(n * 4), *g = malloc(n * 4), *m = calloc(n, 4), *v = calloc(n, 4);
    for (size_t i = 0; i < n; i++) p[i] = frand() - 0.5f, g[i] = (frand() - 0.5f) * 0.01f;
    float *dp = up(p, n, &err), *dg = up(g, n, &err), *dm = up(NULL, n, &err), *dv = up(NULL, n, &err);
    for (int step = 1; step <= 3; step++) {
        cpu_adam_step(NULL, p, g, m, v, n, 1e-3f, 0.9f, 0.999f, 1e-15f, step);
        CHECK_OK(K->adam_step(g_gpu, dp, dg, dm, dv, n, 1e-3f, 0.9f, 0.999f, 1e-15f, step, &err), &err);
    }
    float *pg = malloc(n * 4), *mg = malloc(n * 4);
    down(pg, dp, n, &err);
    down(mg, dm, n, &err);
    CHECK(max_rel(pg, p, n) < 1e-5);
    CHECK(max_rel(mg, m, n) < 1e-5);
    CHECK_FAILS(K->adam_step(g_gpu, dp, dg, dm, dv, n, 1e-3f, 0.9f, 0.999f, 1e-15f, 0, &err),
                SP_E_ARG, &err, "step 0");

    /* densification statistics */
    int32_t *radii = malloc(n * 4);
    float *v2 = malloc(n * 8), *gs = calloc(n, 4), *cnt = calloc(n, 4);
    for (size_t i = 0; i < n; i++) radii[i] = (i % 3) ? (int32_t)(i % 7) : 0;
    for (size_t i = 0; i < 2 * n; i++) v2[i] = frand() - 0.5f;
    int32_t *dr = (int32_t *)up((const float *)radii, n, &err);
    float *dv2 = up(v2, 2 * n, &err), *dgs = up(NULL, n, &err), *dc = up(NULL, n, &err);
    for (int rep = 0; rep < 2; rep++) {
        cpu_densify_accumulate(v2, radii, n, 320.f, 240.f, gs, cnt);
        CHECK_OK(K->densify_accumulate(g_gpu, dv2, dr, n, 320.f, 240.f, dgs, dc, &err), &err);
    }
    float *gsg = malloc(n * 4), *cg = malloc(n * 4);
    down(gsg, dgs, n, &err);
    down(cg, dc, n, &err);
    CHECK(max_rel(gsg, gs, n) < 1e-6);
    CHECK(memcmp(cg, cnt, n * 4) == 0);

    /* column copy and NaN guard */
    CHECK_OK(K->copy_columns(g_gpu, dp, 10, 2, dg, 7, 1, n / 10, 5, &err), &err);
    cpu_copy_columns(p, 10, 2, g, 7, 1, n / 10, 5);
    down(pg, dp, n, &err);
    for (size_t r = 0; r < n / 10; r++)
        for (int c = 0; c < 5; c++) CHECK(pg[r * 10 + 2 + c] == p[r * 10 + 2 + c]);
    CHECK_FAILS(K->copy_columns(g_gpu, dp, 10, 6, dg, 7, 1, 4, 5, &err), SP_E_ARG, &err, "fit");
    int bad = -1;
    CHECK_OK(K->any_nonfinite(g_gpu, dp, n, &bad, &err), &err);
    CHECK(bad == 0);
    float nan = NAN;
    sp_device_upload(g_gpu, dp + n - 1, &nan, 4, &err);
    CHECK_OK(K->any_nonfinite(g_gpu, dp, n, &bad, &err), &err);
    CHECK(bad == 1);

    dfree(dp), dfree(dg), dfree(dm), dfree(dv), dfree(dr);
    dfree(dv2), dfree(dgs), dfree(dc);
    free(p), free(g), free(m), free(v), free(pg), free(mg), free(radii), free(v2), free(gs);
    free(cnt), free(gsg), free(cg);
}

/* The density-control row gather against the CPU table's: rows copied by index, -1 zeroed. */
static void test_gather_rows(void)
{
    sp_error err = {0};
    const size_t rows_in = 300, rows = 500;
    const int cols = 45;
    float *src = malloc(rows_in * cols * 4), *want = malloc(rows * cols * 4), *got = malloc(rows * cols * 4);
    int32_t *idx = malloc(rows * 4);
    for (size_t i = 0; i < rows_in * cols; i++) src[i] = frand() - 0.5f;
    for (size_t i = 0; i < rows; i++) idx[i] = frand() < 0.2f ? -1 : (int32_t)(frand() * (float)(rows_in - 1));
    float *dsrc = up(src, rows_in * cols, &err), *ddst = up(NULL, rows * cols, &err);
    int32_t *didx = sp_device_alloc(g_gpu, rows * 4, &err);
    sp_device_upload(g_gpu, didx, idx, rows * 4, &err);
    CHECK_OK(K->gather_rows(g_gpu, ddst, dsrc, didx, rows, cols, &err), &err);
    CHECK_OK(tr_cpu_kernels.gather_rows(NULL, want, src, idx, rows, cols, &err), &err);
    down(got, ddst, rows * cols, &err);
    CHECK(memcmp(got, want, rows * cols * 4) == 0);
    CHECK_FAILS(K->gather_rows(g_gpu, ddst, NULL, didx, rows, cols, &err), SP_E_ARG, &err, "NULL");
    dfree(dsrc), dfree(ddst), dfree(didx);
    free(src), free(want), free(got), free(idx);
}

int main(void)
{
    sp_error err = {0};
    K = tr_cuda_kernels();
    if (!K || !sp_cuda_available()) TEST_SKIP("no CUDA GPU (or a build without CUDA)");
    if (sp_device_create(&g_gpu, SP_DEVICE_CUDA, 2, &err)) {
        fprintf(stderr, "CUDA device: %s\n", err.msg);
        return 1;
    }
    RUN(test_rgb_loss);
    RUN(test_feature_mse);
    RUN(test_depth_loss);
    RUN(test_adam_and_stats);
    RUN(test_gather_rows);
    sp_device_free(g_gpu);
    return TEST_EXIT();
}
