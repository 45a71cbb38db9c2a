/* CUDA rasterizer vs the CPU backend (itself tested against a naive double reference and finite
 * differences): forward within 1e-4, every gradient group within 1e-3 relative, on random scenes
 * with Gaussians behind the camera, across the border and degenerate, for D in {1, 3, 5, 32, 67},
 * with and without background, depth/alpha gradients and the antialiased mode. Also: repeat
 * runs (forward bit-identical, backward equal to float-atomic reordering), SH on both devices,
 * bad input. Skips (77) without a GPU. The GPU side is driven through cuda_api.h directly so a
 * failure points at the backend, not at the dispatch. */
#include "test.h"

#ifndef SP_HAVE_CUDA
/* Built without the CUDA backend: nothing to compare. */
int main(void) { TEST_SKIP("built without CUDA"); }
#else

#include <stdint.h>

#include "render/cuda_api.h"
#include "semsplat/render.h"

static uint64_t rng_state = 88172645463325252ull;
static float frand(void) /* [0, 1) */
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (float)((rng_state >> 40) & 0xffffff) / 16777216.0f;
}
static float frange(float a, float b) { return a + (b - a) * frand(); }

typedef struct {
    size_t n;
    int D;
    float *means, *quats, *log_scales, *opac, *colors;
} scene;

static void scene_free(scene *s)
{
    free(s->means), free(s->quats), free(s->log_scales), free(s->opac), free(s->colors);
}

/* Gaussians in and around the frustum of a camera at the origin looking down +z. */
static scene make_scene(size_t n, int D, const sp_camera *cam)
{
    scene s = {n, D, malloc(n * 12), malloc(n * 16), malloc(n * 12), malloc(n * 4),
               malloc(n * (size_t)D * 4)};
    for (size_t i = 0; i < n; i++) {
        float z = frange(0.5f, 6.f);
        if (i % 17 == 0) z = -frange(0.1f, 2.f); /* behind the camera */
        float u = frange(-0.2f, 1.2f) * cam->width, v = frange(-0.2f, 1.2f) * cam->height;
        s.means[i * 3] = (u - cam->cx) / cam->fx * z;
        s.means[i * 3 + 1] = (v - cam->cy) / cam->fy * z;
        s.means[i * 3 + 2] = z;
        for (int k = 0; k < 4; k++) s.quats[i * 4 + k] = frange(-1.f, 1.f);
        float px = frange(0.4f, 6.f); /* footprint in pixels */
        for (int k = 0; k < 3; k++)
            s.log_scales[i * 3 + k] = logf(px * fabsf(z) / cam->fx * frange(0.3f, 1.5f));
        if (i % 23 == 0) s.log_scales[i * 3 + 2] = -12.f; /* flat (degenerate) */
        s.opac[i] = frange(-2.f, 4.f);
        for (int c = 0; c < D; c++) s.colors[i * D + c] = frange(-0.2f, 1.f);
    }
    return s;
}

static sp_camera make_cam(int W, int H)
{
    sp_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.width = W, cam.height = H;
    cam.fx = cam.fy = 0.9f * W;
    cam.cx = 0.5f * W + 0.3f, cam.cy = 0.5f * H - 0.2f;
    cam.R[0] = cam.R[4] = cam.R[8] = 1.f;
    return cam;
}

static void *up(const void *h, size_t bytes, sp_error *err)
{
    void *d = sp_cuda_malloc(bytes, err);
    if (d && h) sp_cuda_memcpy_h2d(d, h, bytes, err);
    return d;
}

/* max |a - b| / max(|b|_inf, floor) over the array: a relative error against the array's scale,
 * so near-zero entries (whose error is all rounding) do not dominate. */
static double rel_err(const float *a, const float *b, size_t n, double floor)
{
    double m = floor, e = 0;
    for (size_t i = 0; i < n; i++) m = fmax(m, fabs(b[i]));
    for (size_t i = 0; i < n; i++) e = fmax(e, fabs((double)a[i] - b[i]));
    return e / m;
}

/* Per element: |a - b| <= tol * max(|b|, 1e-2 * |b|_inf) -- the "1e-3 relative where the
 * gradient is not tiny" criterion. Returns the number of violations; *worst gets the largest
 * ratio error / (tol-scaled reference) seen. */
static size_t count_bad(const float *a, const float *b, size_t n, double tol, const char *what,
                        double *worst)
{
    double m = 0;
    for (size_t i = 0; i < n; i++) m = fmax(m, fabs(b[i]));
    size_t bad = 0;
    double w = 0;
    for (size_t i = 0; i < n; i++) {
        double ref = fmax(fabs(b[i]), 1e-2 * m) + 1e-7;
        double e = fabs((double)a[i] - b[i]) / ref;
        w = fmax(w, e);
        if (e > tol) {
            if (bad < 3)
                fprintf(stderr, "  %s[%zu]: cuda %.7g cpu %.7g\n", what, i, a[i], b[i]);
            bad++;
        }
    }
    if (worst) *worst = w;
    return bad;
}

static void compare_case(int W, int H, size_t n, int D, int with_bg, int aa)
{
    sp_error err = {0};
    sp_camera cam = make_cam(W, H);
    scene s = make_scene(n, D, &cam);
    sp_raster_cfg cfg = sp_raster_cfg_default();
    cfg.antialiased = aa;
    float *bg = NULL;
    if (with_bg) {
        bg = malloc(sizeof(float) * D);
        for (int c = 0; c < D; c++) bg[c] = frand();
    }
    size_t npix = (size_t)W * H;

    /* CPU reference */
    sp_device *cpu = NULL;
    sp_raster *rc = NULL;
    CHECK_OK(sp_device_create(&cpu, SP_DEVICE_CPU, 2, &err), &err);
    CHECK_OK(sp_raster_create(&rc, cpu, &err), &err);
    sp_raster_in in = {n, s.means, s.quats, s.log_scales, s.opac, s.colors, D, bg};
    float *img = calloc(npix * D, 4), *dep = calloc(npix, 4), *alp = calloc(npix, 4);
    sp_raster_out out = {img, dep, alp};
    CHECK_OK(sp_raster_forward(rc, &cam, &cfg, &in, &out, &err), &err);

    /* upstream gradients */
    float *vi = malloc(npix * D * 4), *vd = malloc(npix * 4), *va = malloc(npix * 4);
    for (size_t i = 0; i < npix * D; i++) vi[i] = frange(-1.f, 1.f);
    for (size_t i = 0; i < npix; i++) vd[i] = frange(-0.3f, 0.3f), va[i] = frange(-1.f, 1.f);
    float *g_cpu = calloc(n * (3 + 4 + 3 + 1 + D + 2), 4);
    sp_raster_grads gc = {g_cpu, g_cpu + 3 * n, g_cpu + 7 * n, g_cpu + 10 * n, g_cpu + 11 * n,
                          g_cpu + (11 + D) * n};
    sp_raster_grad_in gin = {vi, vd, va};
    CHECK_OK(sp_raster_backward(rc, &gin, &gc, &err), &err);

    /* CUDA */
    sp_cuda_raster *rg = NULL;
    CHECK_OK(sp_cuda_raster_create(&rg, &err), &err);
    sp_raster_in ind = {n, up(s.means, n * 12, &err), up(s.quats, n * 16, &err),
                        up(s.log_scales, n * 12, &err), up(s.opac, n * 4, &err),
                        up(s.colors, n * D * 4, &err), D, bg};
    sp_raster_out outd = {up(NULL, npix * D * 4, &err), up(NULL, npix * 4, &err),
                          up(NULL, npix * 4, &err)};
    CHECK_OK(sp_cuda_raster_forward(rg, &cam, &cfg, &ind, &outd, &err), &err);
    float *img_g = malloc(npix * D * 4), *dep_g = malloc(npix * 4), *alp_g = malloc(npix * 4);
    CHECK_OK(sp_cuda_memcpy_d2h(img_g, outd.image, npix * D * 4, &err), &err);
    CHECK_OK(sp_cuda_memcpy_d2h(dep_g, outd.depth, npix * 4, &err), &err);
    CHECK_OK(sp_cuda_memcpy_d2h(alp_g, outd.alpha, npix * 4, &err), &err);
    double e_img = rel_err(img_g, img, npix * D, 1.0), e_dep = rel_err(dep_g, dep, npix, 1.0),
           e_alp = rel_err(alp_g, alp, npix, 1.0);
    fprintf(stderr, "  %dx%d n=%zu D=%d bg=%d aa=%d pairs cpu %zu cuda %zu: fwd err img %.2g "
            "depth %.2g alpha %.2g\n", W, H, n, D, with_bg, aa, sp_raster_last_pairs(rc),
            sp_cuda_raster_last_pairs(rg), e_img, e_dep, e_alp);
    CHECK(e_img <= 1e-4);
    CHECK(e_dep <= 1e-4);
    CHECK(e_alp <= 1e-4);

    /* radii: same culling (a ceil at a rounding boundary may differ by one pixel) */
    int32_t *rad_g = malloc(n * 4);
    const int32_t *rad_c = sp_raster_radii(rc);
    CHECK_OK(sp_cuda_memcpy_d2h(rad_g, sp_cuda_raster_radii(rg), n * 4, &err), &err);
    size_t rad_bad = 0;
    for (size_t i = 0; i < n; i++)
        if (abs(rad_g[i] - rad_c[i]) > 1 || ((rad_g[i] > 0) != (rad_c[i] > 0))) rad_bad++;
    CHECK_MSG(rad_bad <= n / 1000, "%zu radii differ", rad_bad);

    /* forward determinism: bit-identical */
    CHECK_OK(sp_cuda_raster_forward(rg, &cam, &cfg, &ind, &outd, &err), &err);
    float *img_g2 = malloc(npix * D * 4);
    CHECK_OK(sp_cuda_memcpy_d2h(img_g2, outd.image, npix * D * 4, &err), &err);
    CHECK(memcmp(img_g2, img_g, npix * D * 4) == 0);

    /* backward */
    size_t ng = n * (3 + 4 + 3 + 1 + D + 2);
    float *g_dev = up(NULL, ng * 4, &err);
    sp_raster_grads gd = {g_dev, g_dev + 3 * n, g_dev + 7 * n, g_dev + 10 * n, g_dev + 11 * n,
                          g_dev + (11 + D) * n};
    sp_raster_grad_in gind = {up(vi, npix * D * 4, &err), up(vd, npix * 4, &err),
                              up(va, npix * 4, &err)};
    CHECK_OK(sp_cuda_raster_backward(rg, &gind, &gd, &err), &err);
    float *g_gpu = malloc(ng * 4);
    CHECK_OK(sp_cuda_memcpy_d2h(g_gpu, g_dev, ng * 4, &err), &err);
    static const char *names[] = {"v_means", "v_quats", "v_log_scales", "v_opacity_logits",
                                  "v_colors", "v_means2d"};
    size_t off[7] = {0, 3 * n, 7 * n, 10 * n, 11 * n, (11 + D) * n, ng};
    /* Both backends make the same keep/skip decisions bit for bit (one alpha rule, gauss_math.h;
     * render/test_exact_alpha checks the CPU half), so every entry is within 1e-3 relative. */
    for (int k = 0; k < 6; k++) {
        size_t cnt = off[k + 1] - off[k];
        double worst = 0;
        size_t bad = count_bad(g_gpu + off[k], g_cpu + off[k], cnt, 1e-3, names[k], &worst);
        fprintf(stderr, "    %-17s %zu of %zu beyond 1e-3, worst %.2g\n", names[k], bad, cnt,
                worst);
        CHECK_MSG(bad == 0, "%s: %zu of %zu entries beyond 1e-3 "
                  "relative, worst %.3g", names[k], bad, cnt, worst);
    }

    /* backward accumulates (+=) and is repeatable up to atomic ordering */
    CHECK_OK(sp_cuda_raster_backward(rg, &gind, &gd, &err), &err);
    float *g_gpu2 = malloc(ng * 4);
    CHECK_OK(sp_cuda_memcpy_d2h(g_gpu2, g_dev, ng * 4, &err), &err);
    for (size_t i = 0; i < ng; i++) g_gpu2[i] *= 0.5f;
    CHECK(rel_err(g_gpu2, g_gpu, ng, 1e-6) <= 1e-5);

    sp_cuda_free((void *)ind.means), sp_cuda_free((void *)ind.quats);
    sp_cuda_free((void *)ind.log_scales), sp_cuda_free((void *)ind.opacity_logits);
    sp_cuda_free((void *)ind.colors), sp_cuda_free(outd.image), sp_cuda_free(outd.depth);
    sp_cuda_free(outd.alpha), sp_cuda_free(g_dev), sp_cuda_free((void *)gind.v_image);
    sp_cuda_free((void *)gind.v_depth), sp_cuda_free((void *)gind.v_alpha);
    sp_cuda_raster_free(rg);
    sp_raster_free(rc);
    sp_device_free(cpu);
    free(img), free(dep), free(alp), free(vi), free(vd), free(va), free(g_cpu), free(img_g);
    free(dep_g), free(alp_g), free(img_g2), free(g_gpu), free(g_gpu2), free(rad_g), free(bg);
    scene_free(&s);
}

static void test_rgb(void) { compare_case(97, 63, 600, 3, 1, 0); }
static void test_one_channel(void) { compare_case(64, 48, 300, 1, 0, 0); }
static void test_padded_width(void) { compare_case(50, 70, 400, 5, 1, 1); }
static void test_features32(void) { compare_case(80, 64, 500, 32, 0, 0); }
static void test_features67(void) { compare_case(72, 40, 400, 67, 1, 0); }
static void test_antialiased(void) { compare_case(96, 96, 800, 3, 0, 1); }
static void test_many(void) { compare_case(320, 240, 20000, 3, 1, 0); }

static void test_sh(void)
{
    sp_error err = {0};
    size_t n = 1000;
    for (int deg = 0; deg <= 3; deg++) {
        int K = sp_sh_coeffs(3);
        float *sh = malloc(n * K * 12), *means = malloc(n * 12), *rgb = malloc(n * 16);
        float *rgb_g = malloc(n * 16), *vr = malloc(n * 16);
        float *vsh = calloc(n * K * 3, 4), *vm = calloc(n * 3, 4);
        float *vsh_g = malloc(n * K * 12), *vm_g = malloc(n * 12);
        for (size_t i = 0; i < n * K * 3; i++) sh[i] = frange(-1.f, 1.f);
        for (size_t i = 0; i < n * 3; i++) means[i] = frange(-3.f, 3.f);
        for (size_t i = 0; i < n * 4; i++) vr[i] = frange(-1.f, 1.f);
        sp_vec3 cc = {0.1f, -0.2f, 0.3f};
        sp_device *cpu = NULL;
        CHECK_OK(sp_device_create(&cpu, SP_DEVICE_CPU, 1, &err), &err);
        CHECK_OK(sp_sh_to_rgb(cpu, n, 3, deg, sh, means, cc, rgb, 4, &err), &err);
        CHECK_OK(sp_sh_to_rgb_backward(cpu, n, 3, deg, sh, means, cc, rgb, vr, 4, vsh, vm, &err),
                 &err);
        float *d_sh = up(sh, n * K * 12, &err), *d_m = up(means, n * 12, &err);
        float *d_rgb = up(NULL, n * 16, &err), *d_vr = up(vr, n * 16, &err);
        float *d_vsh = up(NULL, n * K * 12, &err), *d_vm = up(NULL, n * 12, &err);
        CHECK_OK(sp_cuda_sh_to_rgb(n, 3, deg, d_sh, d_m, cc, d_rgb, 4, &err), &err);
        CHECK_OK(sp_cuda_sh_to_rgb_backward(n, 3, deg, d_sh, d_m, cc, d_rgb, d_vr, 4, d_vsh, d_vm,
                                            &err),
                 &err);
        sp_cuda_memcpy_d2h(rgb_g, d_rgb, n * 16, &err);
        sp_cuda_memcpy_d2h(vsh_g, d_vsh, n * K * 12, &err);
        sp_cuda_memcpy_d2h(vm_g, d_vm, n * 12, &err);
        for (size_t i = 0; i < n; i++) /* channel 3 of the stride is untouched (zero) */
            for (int c = 0; c < 3; c++) CHECK_NEAR(rgb_g[i * 4 + c], rgb[i * 4 + c], 1e-5);
        CHECK(count_bad(vsh_g, vsh, n * K * 3, 1e-4, "v_sh", NULL) == 0);
        CHECK(count_bad(vm_g, vm, n * 3, 1e-3, "v_means", NULL) == 0);
        sp_cuda_free(d_sh), sp_cuda_free(d_m), sp_cuda_free(d_rgb), sp_cuda_free(d_vr);
        sp_cuda_free(d_vsh), sp_cuda_free(d_vm);
        sp_device_free(cpu);
        free(sh), free(means), free(rgb), free(rgb_g), free(vr), free(vsh), free(vm);
        free(vsh_g), free(vm_g);
    }
}

static void test_bad_input(void)
{
    sp_error err = {0};
    sp_cuda_raster *rg = NULL;
    CHECK_OK(sp_cuda_raster_create(&rg, &err), &err);
    sp_raster_grads gd = {0};
    float dummy = 0;
    sp_raster_grad_in gin = {&dummy, NULL, NULL};
    CHECK_FAILS(sp_cuda_raster_backward(rg, &gin, &gd, &err), SP_E_ARG, &err, "no forward");
    sp_camera cam = make_cam(32, 32);
    sp_raster_in in = {0};
    in.D = 0;
    sp_raster_out out = {&dummy, NULL, NULL};
    CHECK_FAILS(sp_cuda_raster_forward(rg, &cam, NULL, &in, &out, &err), SP_E_ARG, &err, "D = 0");
    in.D = 3;
    in.n = 10; /* buffers missing */
    CHECK_FAILS(sp_cuda_raster_forward(rg, &cam, NULL, &in, &out, &err), SP_E_ARG, &err, "NULL");
    cam.width = 0;
    in.n = 0;
    CHECK_FAILS(sp_cuda_raster_forward(rg, &cam, NULL, &in, &out, &err), SP_E_ARG, &err, "0x32");
    /* an empty scene renders the background */
    cam.width = 32;
    float bg[3] = {0.25f, 0.5f, 1.f};
    in.background = bg;
    float *img = sp_cuda_malloc(32 * 32 * 12, &err);
    out.image = img;
    CHECK_OK(sp_cuda_raster_forward(rg, &cam, NULL, &in, &out, &err), &err);
    float h[32 * 32 * 3];
    CHECK_OK(sp_cuda_memcpy_d2h(h, img, sizeof h, &err), &err);
    CHECK(h[0] == 0.25f && h[1] == 0.5f && h[2] == 1.f && h[sizeof h / 4 - 1] == 1.f);
    sp_cuda_free(img);
    CHECK_FAILS(sp_cuda_sh_to_rgb(1, 2, 3, NULL, NULL, sp_v3(0, 0, 0), NULL, 3, &err), SP_E_ARG,
                &err, "active SH degree 3");
    sp_cuda_raster_free(rg);
}

int main(void)
{
    if (!sp_cuda_available()) TEST_SKIP("no CUDA GPU");
    RUN(test_bad_input);
    RUN(test_rgb);
    RUN(test_one_channel);
    RUN(test_padded_width);
    RUN(test_features32);
    RUN(test_features67);
    RUN(test_antialiased);
    RUN(test_many);
    RUN(test_sh);
    return TEST_EXIT();
}
#endif /* SP_HAVE_CUDA */
