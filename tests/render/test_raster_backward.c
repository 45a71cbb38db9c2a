/* The CPU rasterizer's backward pass against central finite differences of the double reference
 * (render_ref.h, replaying the contributor set of the unperturbed render so that a threshold
 * crossing inside +-h cannot spoil a difference quotient), for every parameter group: means,
 * quaternions, log-scales, opacity logits, colours/features, the 2D means, through image, depth
 * and alpha outputs, with and without antialiasing and background. Also: gradients are added,
 * and the same bits come out for any thread count. */
#include "scene_util.h"

typedef struct fd_case {
    int W, H;
    size_t n;
    int D;
    int bg, aa, use_depth, use_alpha;
    unsigned long long seed;
    double op_lo, op_hi; /* opacity range (0 = default 0.1..0.85) */
} fd_case;

static double ref_loss(const ref_scene *rs, const sp_camera *cam, const sp_raster_cfg *cfg,
                       const float *vi, const float *vd, const float *va, ref_record *rec, int mode)
{
    size_t npix = (size_t)cam->width * cam->height;
    double *img = malloc(npix * rs->D * sizeof(double)), *dep = malloc(npix * sizeof(double)),
           *alp = malloc(npix * sizeof(double));
    ref_render(rs, cam, cfg, img, dep, alp, mode, rec);
    double L = 0;
    for (size_t p = 0; p < npix; p++) {
        for (int c = 0; c < rs->D; c++) L += vi[p * rs->D + c] * img[p * rs->D + c];
        if (vd) L += vd[p] * dep[p];
        if (va) L += va[p] * alp[p];
    }
    free(img), free(dep), free(alp);
    return L;
}

/* Compares one parameter group: analytic a[k] vs FD of *param(k). Returns the worst relative
 * error, with "tiny" meaning below 1% of the group's largest FD gradient. */
static double check_group(const char *name, ref_scene *rs, double *params, size_t count,
                          const float *analytic, const sp_camera *cam, const sp_raster_cfg *cfg,
                          const float *vi, const float *vd, const float *va, ref_record *rec)
{
    double *fd = malloc(count * sizeof(double));
    double gmax = 0;
    for (size_t k = 0; k < count; k++) {
        double h = 1e-6 * fmax(1.0, fabs(params[k]));
        double keep = params[k];
        params[k] = keep + h;
        double Lp = ref_loss(rs, cam, cfg, vi, vd, va, rec, 2);
        params[k] = keep - h;
        double Lm = ref_loss(rs, cam, cfg, vi, vd, va, rec, 2);
        params[k] = keep;
        fd[k] = (Lp - Lm) / (2 * h);
        gmax = fmax(gmax, fabs(fd[k]));
    }
    double worst = 0;
    size_t wk = 0;
    for (size_t k = 0; k < count; k++) {
        double denom = fmax(fmax(fabs(fd[k]), 1e-2 * gmax), 1e-9);
        double rel = fabs(analytic[k] - fd[k]) / denom;
        if (rel > worst) worst = rel, wk = k;
    }
    fprintf(stderr, "    %-16s max|grad| %.3e  worst rel err %.2e (index %zu: %.6g vs fd %.6g)\n",
            name, gmax, worst, wk, count ? analytic[wk] : 0.0, count ? fd[wk] : 0.0);
    CHECK_MSG(gmax > 0, "%s: all finite-difference gradients are zero", name);
    free(fd);
    return worst;
}

static void run_case(const fd_case *fc)
{
    test_rng rng = {fc->seed};
    sp_camera cam;
    scene_camera(&rng, fc->W, fc->H, &cam);
    test_scene s;
    scene_make(&s, &rng, &cam, fc->n, fc->D, 1.5, 6.0, fc->op_hi > 0 ? fc->op_lo : 0.1,
               fc->op_hi > 0 ? fc->op_hi : 0.85, 0);
    sp_raster_cfg cfg = sp_raster_cfg_default();
    cfg.antialiased = fc->aa;
    size_t npix = (size_t)fc->W * fc->H, n = fc->n;
    int D = fc->D;
    float *vi = malloc(npix * D * sizeof(float)), *vd = NULL, *va = NULL;
    for (size_t k = 0; k < npix * D; k++) vi[k] = (float)test_range(&rng, -1, 1);
    if (fc->use_depth) {
        vd = malloc(npix * sizeof(float));
        for (size_t k = 0; k < npix; k++) vd[k] = (float)test_range(&rng, -0.3, 0.3);
    }
    if (fc->use_alpha) {
        va = malloc(npix * sizeof(float));
        for (size_t k = 0; k < npix; k++) va[k] = (float)test_range(&rng, -1, 1);
    }

    sp_device *dev = NULL;
    sp_error err = {0};
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CPU, 2, &err), &err);
    sp_raster *r = NULL;
    CHECK_OK(sp_raster_create(&r, dev, &err), &err);
    float *img = malloc(npix * D * sizeof(float)), *dep = malloc(npix * sizeof(float)),
          *alp = malloc(npix * sizeof(float));
    sp_raster_in in = scene_input(&s, fc->bg);
    sp_raster_out out = {img, dep, alp, NULL};
    CHECK_OK(sp_raster_forward(r, &cam, &cfg, &in, &out, &err), &err);
    float *g_means = calloc(n * 3, sizeof(float)), *g_quats = calloc(n * 4, sizeof(float)),
          *g_ls = calloc(n * 3, sizeof(float)), *g_op = calloc(n, sizeof(float)),
          *g_col = calloc(n * D, sizeof(float)), *g_m2 = calloc(n * 2, sizeof(float));
    sp_raster_grads g = {g_means, g_quats, g_ls, g_op, g_col, g_m2};
    sp_raster_grad_in gin = {vi, vd, va};
    CHECK_OK(sp_raster_backward(r, &gin, &g, &err), &err);

    ref_scene rs;
    scene_to_ref(&s, &rs, fc->bg);
    rs.mean2d_offset = calloc(n * 2, sizeof(double));
    ref_record rec = {0};
    ref_loss(&rs, &cam, &cfg, vi, vd, va, &rec, 1);
    fprintf(stderr, "  %dx%d n=%zu D=%d bg=%d aa=%d depth=%d alpha=%d: %zu contributions\n", fc->W,
            fc->H, n, D, fc->bg, fc->aa, fc->use_depth, fc->use_alpha, rec.len);
    double tol = 1e-3;
    CHECK(check_group("means", &rs, rs.means, n * 3, g_means, &cam, &cfg, vi, vd, va, &rec) < tol);
    CHECK(check_group("quats", &rs, rs.quats, n * 4, g_quats, &cam, &cfg, vi, vd, va, &rec) < tol);
    CHECK(check_group("log_scales", &rs, rs.log_scales, n * 3, g_ls, &cam, &cfg, vi, vd, va, &rec) < tol);
    CHECK(check_group("opacity_logits", &rs, rs.opacity_logits, n, g_op, &cam, &cfg, vi, vd, va, &rec) < tol);
    CHECK(check_group("colors", &rs, rs.colors, n * D, g_col, &cam, &cfg, vi, vd, va, &rec) < tol);
    CHECK(check_group("means2d", &rs, rs.mean2d_offset, n * 2, g_m2, &cam, &cfg, vi, vd, va, &rec) < tol);

    ref_record_free(&rec);
    ref_scene_free(&rs);
    free(g_means), free(g_quats), free(g_ls), free(g_op), free(g_col), free(g_m2);
    free(img), free(dep), free(alp), free(vi), free(vd), free(va);
    scene_free(&s);
    sp_raster_free(r);
    sp_device_free(dev);
}

static void test_gradients_rgb(void)
{
    fd_case c = {40, 30, 12, 3, 0, 0, 0, 0, 11, 0, 0};
    run_case(&c);
}

static void test_gradients_features_depth_alpha(void)
{
    fd_case c = {36, 28, 10, 5, 1, 0, 1, 1, 12, 0, 0};
    run_case(&c);
}

static void test_gradients_antialiased(void)
{
    fd_case c = {34, 26, 10, 3, 1, 1, 1, 0, 13, 0, 0};
    run_case(&c);
}

static void test_gradients_depth_only_channel(void)
{
    fd_case c = {30, 30, 8, 1, 0, 0, 1, 1, 14, 0, 0};
    run_case(&c);
}

/* Dense, nearly opaque: alphas capped at 0.99 and pixels ending at T < 1e-4. */
static void test_gradients_opaque(void)
{
    fd_case c = {24, 20, 30, 3, 1, 0, 1, 1, 15, 0.9, 0.9999};
    run_case(&c);
}

/* Backward twice = twice the gradient (added, not overwritten), and the same bits whatever the
 * thread count. */
static void test_accumulates_and_deterministic(void)
{
    test_rng rng = {99};
    sp_camera cam;
    scene_camera(&rng, 100, 80, &cam);
    test_scene s;
    scene_make(&s, &rng, &cam, 2000, 4, 0.5, 8.0, 0.05, 0.95, 1);
    size_t npix = 100 * 80, n = s.n;
    float *vi = malloc(npix * 4 * sizeof(float)), *vd = malloc(npix * sizeof(float));
    for (size_t k = 0; k < npix * 4; k++) vi[k] = (float)test_range(&rng, -1, 1);
    for (size_t k = 0; k < npix; k++) vd[k] = (float)test_range(&rng, -1, 1);
    size_t total = n * (3 + 4 + 3 + 1 + 4 + 2);
    float *first = NULL;
    int threads[3] = {1, 3, 4};
    for (int t = 0; t < 3; t++) {
        sp_device *dev = NULL;
        sp_error err = {0};
        CHECK_OK(sp_device_create(&dev, SP_DEVICE_CPU, threads[t], &err), &err);
        sp_raster *r = NULL;
        CHECK_OK(sp_raster_create(&r, dev, &err), &err);
        float *img = malloc(npix * 4 * sizeof(float)), *dep = malloc(npix * sizeof(float));
        sp_raster_in in = scene_input(&s, 1);
        sp_raster_out out = {img, dep, NULL, NULL};
        sp_raster_cfg cfg = sp_raster_cfg_default();
        CHECK_OK(sp_raster_forward(r, &cam, &cfg, &in, &out, &err), &err);
        float *all = calloc(total, sizeof(float));
        sp_raster_grads g = {all, all + 3 * n, all + 7 * n, all + 10 * n, all + 11 * n, all + 15 * n};
        sp_raster_grad_in gin = {vi, vd, NULL};
        CHECK_OK(sp_raster_backward(r, &gin, &g, &err), &err);
        if (!first) {
            first = all;
            float *twice = calloc(total, sizeof(float));
            sp_raster_grads g2 = {twice, twice + 3 * n, twice + 7 * n, twice + 10 * n, twice + 11 * n,
                                  twice + 15 * n};
            CHECK_OK(sp_raster_backward(r, &gin, &g2, &err), &err);
            CHECK_OK(sp_raster_backward(r, &gin, &g2, &err), &err);
            int ok = 1;
            for (size_t k = 0; k < total; k++) ok &= twice[k] == 2.f * first[k];
            CHECK(ok);
            free(twice);
        } else {
            CHECK(memcmp(first, all, total * sizeof(float)) == 0);
            free(all);
        }
        free(img), free(dep);
        sp_raster_free(r);
        sp_device_free(dev);
    }
    free(first), free(vi), free(vd);
    scene_free(&s);
}

int main(void)
{
    RUN(test_gradients_rgb);
    RUN(test_gradients_features_depth_alpha);
    RUN(test_gradients_antialiased);
    RUN(test_gradients_depth_only_channel);
    RUN(test_gradients_opaque);
    RUN(test_accumulates_and_deterministic);
    return TEST_EXIT();
}
