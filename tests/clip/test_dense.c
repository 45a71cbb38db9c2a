/* Dense features and preprocessing on the tiny reference model (tests/fixtures/clip/tiny):
 * tiling and overlap averaging against per-tile dense-head calls done here, the bicubic resize
 * against a direct double implementation of PIL's antialiased filter, and bilinear upsampling. */
#include "semsplat/clip.h"
#include "semsplat/device.h"
#include "clip/clip_internal.h"
#include "test.h"

static sp_clip *c;

static void normalize(float *v, int n)
{
    double s = 0;
    for (int i = 0; i < n; i++) s += (double)v[i] * v[i];
    for (int i = 0; i < n; i++) v[i] = (float)(v[i] / sqrt(s));
}

/* planar normalised crop [3][S][S] of an interleaved RGB image at (x0, y0) */
static void crop(const sp_clip_config *g, const float *rgb, int W, int x0, int y0, int S, float *px)
{
    for (int ch = 0; ch < 3; ch++)
        for (int y = 0; y < S; y++)
            for (int x = 0; x < S; x++)
                px[(ch * S + y) * S + x] = (rgb[((y0 + y) * W + x0 + x) * 3 + ch] - g->image_mean[ch]) / g->image_std[ch];
}

static void test_tiles(void)
{
    const sp_clip_config *g = sp_clip_get_config(c);
    int S = g->image_size, p = g->patch_size, P = sp_clip_embed_dim(c), gs = S / p;
    int W = S + S / 2, H = S; /* two tiles across, overlapping by half */
    test_rng rng = {99};
    float *rgb = malloc(sizeof(float) * W * H * 3);
    for (int i = 0; i < W * H * 3; i++) rgb[i] = (float)test_uniform(&rng);
    sp_clip_dense_opts o = sp_clip_dense_opts_default();
    o.scales[0] = 1.0f;
    o.stride = S / 2;
    int gw, gh;
    sp_clip_dense_grid(c, &o, W, H, &gw, &gh);
    CHECK(gw == W / p && gh == H / p);
    float *got = malloc(sizeof(float) * gw * gh * P), *ref = calloc((size_t)gw * gh * P, sizeof(float));
    sp_error err = {0};
    CHECK_OK(sp_clip_dense_features(c, rgb, W, H, &o, got, &err), &err);
    float *px = malloc(sizeof(float) * 3 * S * S), *t = malloc(sizeof(float) * gs * gs * P);
    int cnt[64] = {0};
    for (int tx = 0; tx <= S / 2; tx += S / 2) {
        crop(g, rgb, W, tx, 0, S, px);
        CHECK_OK(sp_clip_dense_pixels(c, px, S, S, SP_CLIP_HEAD_CLEARCLIP, t, &err), &err);
        for (int y = 0; y < gs; y++)
            for (int x = 0; x < gs; x++) {
                int gx = tx / p + x;
                for (int k = 0; k < P; k++) ref[((y * gw) + gx) * P + k] += t[(y * gs + x) * P + k];
                cnt[y * gw + gx]++;
            }
    }
    double worst = 0;
    for (int i = 0; i < gw * gh; i++) {
        CHECK(cnt[i] == (i % gw >= 2 && i % gw < 4 ? 2 : 1));
        normalize(ref + i * P, P);
        for (int k = 0; k < P; k++) worst = fmax(worst, fabs(ref[i * P + k] - got[i * P + k]));
    }
    CHECK_MSG(worst < 1e-5, "tiled dense features differ from per-tile calls by %g", worst);
    free(rgb); free(got); free(ref); free(px); free(t);
}

/* PIL ImagingResample with the bicubic filter (a = -0.5), one axis, in double */
static double cubic(double x)
{
    x = fabs(x);
    return x < 1 ? (1.5 * x - 2.5) * x * x + 1 : x < 2 ? ((-0.5 * x + 2.5) * x - 4) * x + 2 : 0;
}

static void ref_axis(const double *in, int n_in, double *out, int n_out)
{
    double scale = (double)n_in / n_out, fs = scale > 1 ? scale : 1;
    for (int i = 0; i < n_out; i++) {
        double center = (i + 0.5) * scale, s = 0, ws = 0;
        int lo = (int)(center - 2 * fs + 0.5), hi = (int)(center + 2 * fs + 0.5);
        if (lo < 0) lo = 0;
        if (hi > n_in) hi = n_in;
        for (int k = lo; k < hi; k++) {
            double w = cubic((k - center + 0.5) / fs);
            s += w * in[k];
            ws += w;
        }
        out[i] = s / ws;
    }
}

static void test_preprocess(void)
{
    const sp_clip_config *g = sp_clip_get_config(c);
    int S = g->image_size, W = 150, H = 100; /* shortest side 100 -> S, width 150*S/100 */
    test_rng rng = {5};
    float *rgb = malloc(sizeof(float) * W * H * 3), *px = malloc(sizeof(float) * 3 * S * S);
    for (int i = 0; i < W * H * 3; i++) rgb[i] = (float)test_uniform(&rng);
    sp_error err = {0};
    CHECK_OK(sp_clip_preprocess(c, rgb, W, H, px, &err), &err);
    int rw = S * W / H, rh = S, left = (rw - S) / 2;
    double *row = malloc(sizeof(double) * W), *tmp = malloc(sizeof(double) * rw * H), *col = malloc(sizeof(double) * H);
    double *colo = malloc(sizeof(double) * rh), worst = 0;
    for (int ch = 0; ch < 3; ch++) {
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) row[x] = rgb[(y * W + x) * 3 + ch];
            ref_axis(row, W, tmp + y * rw, rw);
        }
        for (int x = left; x < left + S; x++) {
            for (int y = 0; y < H; y++) col[y] = tmp[y * rw + x];
            ref_axis(col, H, colo, rh);
            for (int y = 0; y < S; y++) {
                double want = (colo[y] - g->image_mean[ch]) / g->image_std[ch];
                worst = fmax(worst, fabs(want - px[(ch * S + y) * S + x - left]));
            }
        }
    }
    CHECK_MSG(worst < 1e-5, "preprocess differs from the PIL-style reference by %g", worst);
    CHECK_FAILS(sp_clip_preprocess(c, rgb, 0, H, px, &err), SP_E_ARG, &err, "size");
    free(rgb); free(px); free(row); free(tmp); free(col); free(colo);
}

/* Tile origins: the count alone (cap 0, as the GPU path sizes its tables) equals the count
 * written; 640x480 at scale 2 is 11 x 8 tiles of 224 at stride 112, the last flush. */
static void test_tile_starts(void)
{
    int xs[64], ys[64];
    CHECK(clip_tile_starts(1280, 224, 112, NULL, 0) == 11 && clip_tile_starts(1280, 224, 112, xs, 64) == 11);
    CHECK(clip_tile_starts(960, 224, 112, NULL, 0) == 8 && clip_tile_starts(960, 224, 112, ys, 64) == 8);
    CHECK(xs[0] == 0 && xs[9] == 1008 && xs[10] == 1056 && ys[7] == 736);
    CHECK(clip_tile_starts(224, 224, 112, NULL, 0) == 1 && clip_tile_starts(224, 224, 112, xs, 64) == 1 && xs[0] == 0);
    /* more than cap: counted, only cap written */
    CHECK(clip_tile_starts(1280, 224, 16, xs, 3) == 67 && xs[2] == 32);
}

static void test_upsample(void)
{
    /* a linear ramp is reproduced exactly away from the borders */
    enum { GW = 4, GH = 3, D = 2, WW = 16, HH = 12 };
    float grid[GH * GW * D], out[HH * WW * D];
    for (int y = 0; y < GH; y++)
        for (int x = 0; x < GW; x++) {
            grid[(y * GW + x) * D] = (float)x;
            grid[(y * GW + x) * D + 1] = (float)y;
        }
    sp_clip_upsample(grid, GW, GH, D, WW, HH, out);
    for (int y = 2; y < HH - 2; y++)
        for (int x = 2; x < WW - 2; x++) {
            CHECK_NEAR(out[(y * WW + x) * D], (x + 0.5) * GW / WW - 0.5, 1e-5);
            CHECK_NEAR(out[(y * WW + x) * D + 1], (y + 0.5) * GH / HH - 0.5, 1e-5);
        }
}

/* The device-resident dense pipeline against the CPU path on the same model: two scales (the
 * second resampled onto the first's grid), an image that is not a whole number of tiles, both
 * heads, fp32 and fp16. */
static void test_gpu_dense(void)
{
    char w[1024];
    snprintf(w, sizeof w, "%s/tests/fixtures/clip/tiny/model.safetensors", SP_SOURCE_DIR);
    sp_error err = {0};
    sp_device *dev = NULL;
    sp_clip *gpu = NULL;
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CUDA, 0, &err), &err);
    if (dev) CHECK_OK(sp_clip_load(&gpu, w, NULL, dev, &err), &err);
    if (!gpu) {
        sp_device_free(dev);
        return;
    }
    int W = 150, H = 97, P = sp_clip_embed_dim(c);
    test_rng rng = {31};
    float *rgb = malloc(sizeof(float) * W * H * 3);
    for (int i = 0; i < W * H * 3; i++) rgb[i] = (float)test_uniform(&rng);
    sp_clip_dense_opts o = sp_clip_dense_opts_default();
    o.n_scales = 2;
    o.scales[0] = 1.0f;
    o.scales[1] = 0.75f;
    o.batch = 3;
    int gw, gh;
    sp_clip_dense_grid(c, &o, W, H, &gw, &gh);
    float *a = malloc(sizeof(float) * gw * gh * P), *b = malloc(sizeof(float) * gw * gh * P);
    for (int fp16 = 0; fp16 <= 1; fp16++)
        for (int head = 0; head <= 1; head++) {
            o.head = (sp_clip_head)head;
            CHECK_OK(sp_clip_set_fp16(gpu, fp16, &err), &err);
            CHECK_OK(sp_clip_dense_features(c, rgb, W, H, &o, a, &err), &err);
            for (int i = 0; i < gw * gh * P; i++) b[i] = NAN; /* every cell must be written */
            CHECK_OK(sp_clip_dense_features(gpu, rgb, W, H, &o, b, &err), &err);
            double worst = 0;
            for (int i = 0; i < gw * gh * P; i++) worst = isfinite(b[i]) ? fmax(worst, fabs(a[i] - b[i])) : 1e9;
            fprintf(stderr, "dense GPU %s head %d vs CPU (%dx%d grid): max abs %.3g\n", fp16 ? "fp16" : "fp32", head, gw,
                    gh, worst);
            CHECK(worst < (fp16 ? 3e-2 : 1e-4));
        }
    free(rgb); free(a); free(b);
    sp_clip_free(gpu);
    sp_device_free(dev);
}

int main(int argc, char **argv)
{
    TEST_ARGS(argc, argv);
    char w[1024];
    snprintf(w, sizeof w, "%s/tests/fixtures/clip/tiny/model.safetensors", SP_SOURCE_DIR);
    sp_error err = {0};
    if (sp_clip_load(&c, w, NULL, NULL, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    RUN(test_tiles);
    RUN(test_preprocess);
    RUN(test_upsample);
    RUN(test_tile_starts);
    RUN_GPU(test_gpu_dense);
    sp_clip_free(c);
    return TEST_EXIT();
}
