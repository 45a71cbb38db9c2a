/* CUDA rasterizer vs the CPU backend (itself tested against a naive double reference and finite
 * differences): forward within 1e-4, every gradient group within 1e-3 relative, on random scenes
 * with Gaussians behind the camera, across the border and degenerate, for D in {1, 3, 5, 32, 67}
 * and every specialised width (SP_CHANNEL_WIDTHS), with and without background, depth/alpha
 * gradients and the antialiased mode. Also: repeat runs (forward bit-identical, backward equal to
 * float-atomic reordering), the chunk-width option (same bits), first-surface depth (the same
 * bits on both backends), batches of views (sp_render_views: equal to one view at a time, and to
 * the CPU), SH on both devices, bad input; exact tile culling (the same bits as every
 * bounding-box tile, pair counts as the CPU's), profiling, over 65536 tiles (32-bit tile keys),
 * the backward's four colour-gradient sums (cfg.bwd_gather: product, gather, reduce-scatter,
 * tensor cores; the kernel that ran is printed) and the option's range, and the two-pixels-per-
 * thread and four-pixels-per-thread backward (cfg.bwd_px = 2, 4) with and without depth/alpha
 * gradients, and the forward's (cfg.fwd_px: the same bits as one pixel per thread). Skips (77) without a GPU
 * or without the CUDA build. */
#include "test.h"

#include <stdint.h>

#include "semsplat/render.h"

static sp_device *g_gpu; /* the CUDA device every case uses */

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
    void *d = sp_device_alloc(g_gpu, bytes, err);
    if (d && h) sp_device_upload(g_gpu, d, h, bytes, err);
    return d;
}

static int down(void *h, const void *d, size_t bytes, sp_error *err)
{
    return sp_device_download(g_gpu, h, d, bytes, err);
}

static void dfree(const void *d) { sp_device_release(g_gpu, (void *)d); }

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

static int g_block_sums = 0; /* cfg.bwd_gather of compare_case's renders */
static const char *g_expect_bwd; /* when set: the backward kernel compare_case's widest chunk must take */
static int g_bwd_px = 0;  /* cfg.bwd_px of compare_case's renders */
static int g_fwd_px = 0;  /* cfg.fwd_px of compare_case's renders */
static int g_no_aux = 0;  /* 1: compare_case's backward without depth and alpha gradients */
static int g_warp_cull = 0; /* cfg.warp_cull of compare_case's renders */

static void compare_case(int W, int H, size_t n, int D, int with_bg, int aa)
{
    sp_error err = {0};
    sp_camera cam = make_cam(W, H);
    scene s = make_scene(n, D, &cam);
    sp_raster_cfg cfg = sp_raster_cfg_default();
    cfg.antialiased = aa;
    cfg.bwd_gather = g_block_sums;
    cfg.bwd_px = g_bwd_px;
    cfg.fwd_px = g_fwd_px;
    cfg.warp_cull = g_warp_cull;
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
    sp_raster_out out = {img, dep, alp, NULL};
    CHECK_OK(sp_raster_forward(rc, &cam, &cfg, &in, &out, &err), &err);

    /* upstream gradients */
    float *vi = malloc(npix * D * 4), *vd = malloc(npix * 4), *va = malloc(npix * 4);
    for (size_t i = 0; i < npix * D; i++) vi[i] = frange(-1.f, 1.f);
    for (size_t i = 0; i < npix; i++) vd[i] = frange(-0.3f, 0.3f), va[i] = frange(-1.f, 1.f);
    float *g_cpu = calloc(n * (3 + 4 + 3 + 1 + D + 2), 4);
    sp_raster_grads gc = {g_cpu, g_cpu + 3 * n, g_cpu + 7 * n, g_cpu + 10 * n, g_cpu + 11 * n,
                          g_cpu + (11 + D) * n};
    sp_raster_grad_in gin = {vi, g_no_aux ? NULL : vd, g_no_aux ? NULL : va};
    CHECK_OK(sp_raster_backward(rc, &gin, &gc, &err), &err);

    /* CUDA */
    sp_raster *rg = NULL;
    CHECK_OK(sp_raster_create(&rg, g_gpu, &err), &err);
    sp_raster_in ind = {n, up(s.means, n * 12, &err), up(s.quats, n * 16, &err),
                        up(s.log_scales, n * 12, &err), up(s.opac, n * 4, &err),
                        up(s.colors, n * D * 4, &err), D, bg};
    sp_raster_out outd = {up(NULL, npix * D * 4, &err), up(NULL, npix * 4, &err),
                          up(NULL, npix * 4, &err), NULL};
    CHECK_OK(sp_raster_forward(rg, &cam, &cfg, &ind, &outd, &err), &err);
    float *img_g = malloc(npix * D * 4), *dep_g = malloc(npix * 4), *alp_g = malloc(npix * 4);
    CHECK_OK(down(img_g, outd.image, npix * D * 4, &err), &err);
    CHECK_OK(down(dep_g, outd.depth, npix * 4, &err), &err);
    CHECK_OK(down(alp_g, outd.alpha, npix * 4, &err), &err);
    double e_img = rel_err(img_g, img, npix * D, 1.0), e_dep = rel_err(dep_g, dep, npix, 1.0),
           e_alp = rel_err(alp_g, alp, npix, 1.0);
    fprintf(stderr, "  %dx%d n=%zu D=%d bg=%d aa=%d aux=%d px=%d pairs cpu %zu cuda %zu: fwd err img %.2g "
            "depth %.2g alpha %.2g\n", W, H, n, D, with_bg, aa, !g_no_aux, g_bwd_px, sp_raster_last_pairs(rc),
            sp_raster_last_pairs(rg), e_img, e_dep, e_alp);
    CHECK(e_img <= 1e-4);
    CHECK(e_dep <= 1e-4);
    CHECK(e_alp <= 1e-4);
    /* the same exact tile culling on both (the GPU's cut uses the fast log: a borderline tile
     * may go either way, never one that contributes) */
    size_t pc = sp_raster_last_pairs(rc), pg = sp_raster_last_pairs(rg);
    CHECK((pc > pg ? pc - pg : pg - pc) <= pc / 1000 + 2);

    /* radii: same culling (a ceil at a rounding boundary may differ by one pixel) */
    int32_t *rad_g = malloc(n * 4);
    const int32_t *rad_c = sp_raster_radii(rc);
    CHECK_OK(down(rad_g, sp_raster_radii(rg), n * 4, &err), &err);
    size_t rad_bad = 0;
    for (size_t i = 0; i < n; i++)
        if (abs(rad_g[i] - rad_c[i]) > 1 || ((rad_g[i] > 0) != (rad_c[i] > 0))) rad_bad++;
    CHECK_MSG(rad_bad <= n / 1000, "%zu radii differ", rad_bad);

    /* forward determinism: bit-identical */
    CHECK_OK(sp_raster_forward(rg, &cam, &cfg, &ind, &outd, &err), &err);
    float *img_g2 = malloc(npix * D * 4);
    CHECK_OK(down(img_g2, outd.image, npix * D * 4, &err), &err);
    CHECK(memcmp(img_g2, img_g, npix * D * 4) == 0);

    /* backward */
    size_t ng = n * (3 + 4 + 3 + 1 + D + 2);
    float *g_dev = up(NULL, ng * 4, &err);
    sp_raster_grads gd = {g_dev, g_dev + 3 * n, g_dev + 7 * n, g_dev + 10 * n, g_dev + 11 * n,
                          g_dev + (11 + D) * n};
    float *vd_dev = up(vd, npix * 4, &err), *va_dev = up(va, npix * 4, &err);
    sp_raster_grad_in gind = {up(vi, npix * D * 4, &err), g_no_aux ? NULL : vd_dev,
                              g_no_aux ? NULL : va_dev};
    CHECK_OK(sp_raster_backward(rg, &gind, &gd, &err), &err);
    sp_raster_stages stg;
    CHECK_OK(sp_raster_last_stages(rg, &stg, &err), &err);
    fprintf(stderr, "    backward kernel (widest chunk): %s\n", stg.bwd_kernel ? stg.bwd_kernel : "none");
    CHECK(stg.bwd_kernel != NULL);
    if (g_expect_bwd && stg.bwd_kernel)
        CHECK_MSG(!strcmp(stg.bwd_kernel, g_expect_bwd), "backward ran %s, expected %s", stg.bwd_kernel,
                  g_expect_bwd);
    float *g_gpu = malloc(ng * 4);
    CHECK_OK(down(g_gpu, g_dev, ng * 4, &err), &err);
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
    CHECK_OK(sp_raster_backward(rg, &gind, &gd, &err), &err);
    float *g_gpu2 = malloc(ng * 4);
    CHECK_OK(down(g_gpu2, g_dev, ng * 4, &err), &err);
    for (size_t i = 0; i < ng; i++) g_gpu2[i] *= 0.5f;
    CHECK(rel_err(g_gpu2, g_gpu, ng, 1e-6) <= 1e-5);

    dfree((void *)ind.means), dfree((void *)ind.quats);
    dfree((void *)ind.log_scales), dfree((void *)ind.opacity_logits);
    dfree((void *)ind.colors), dfree(outd.image), dfree(outd.depth);
    dfree(outd.alpha), dfree(g_dev), dfree((void *)gind.v_image);
    dfree(vd_dev), dfree(va_dev);
    sp_raster_free(rg);
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
        CHECK_OK(sp_sh_to_rgb(g_gpu, n, 3, deg, d_sh, d_m, cc, d_rgb, 4, &err), &err);
        CHECK_OK(sp_sh_to_rgb_backward(g_gpu, n, 3, deg, d_sh, d_m, cc, d_rgb, d_vr, 4, d_vsh, d_vm,
                                            &err),
                 &err);
        down(rgb_g, d_rgb, n * 16, &err);
        down(vsh_g, d_vsh, n * K * 12, &err);
        down(vm_g, d_vm, n * 12, &err);
        for (size_t i = 0; i < n; i++) /* channel 3 of the stride is untouched (zero) */
            for (int c = 0; c < 3; c++) CHECK_NEAR(rgb_g[i * 4 + c], rgb[i * 4 + c], 1e-5);
        CHECK(count_bad(vsh_g, vsh, n * K * 3, 1e-4, "v_sh", NULL) == 0);
        CHECK(count_bad(vm_g, vm, n * 3, 1e-3, "v_means", NULL) == 0);
        dfree(d_sh), dfree(d_m), dfree(d_rgb), dfree(d_vr);
        dfree(d_vsh), dfree(d_vm);
        sp_device_free(cpu);
        free(sh), free(means), free(rgb), free(rgb_g), free(vr), free(vsh), free(vm);
        free(vsh_g), free(vm_g);
    }
}

static void test_bad_input(void)
{
    sp_error err = {0};
    sp_raster *rg = NULL;
    CHECK_OK(sp_raster_create(&rg, g_gpu, &err), &err);
    sp_raster_grads gd = {0};
    float dummy = 0;
    sp_raster_grad_in gin = {&dummy, NULL, NULL};
    CHECK_FAILS(sp_raster_backward(rg, &gin, &gd, &err), SP_E_ARG, &err, "no forward");
    sp_camera cam = make_cam(32, 32);
    sp_raster_in in = {0};
    in.D = 0;
    sp_raster_out out = {&dummy, NULL, NULL, NULL};
    sp_raster_cfg cfg = sp_raster_cfg_default();
    CHECK_FAILS(sp_raster_forward(rg, &cam, &cfg, &in, &out, &err), SP_E_ARG, &err, "D=0");
    in.D = 3;
    in.n = 10; /* buffers missing */
    CHECK_FAILS(sp_raster_forward(rg, &cam, &cfg, &in, &out, &err), SP_E_ARG, &err, "NULL");
    cam.width = 0;
    in.n = 0;
    CHECK_FAILS(sp_raster_forward(rg, &cam, &cfg, &in, &out, &err), SP_E_ARG, &err, "0x32");
    /* an empty scene renders the background */
    cam.width = 32;
    float bg[3] = {0.25f, 0.5f, 1.f};
    in.background = bg;
    float *img = up(NULL, 32 * 32 * 12, &err);
    out.image = img;
    CHECK_OK(sp_raster_forward(rg, &cam, &cfg, &in, &out, &err), &err);
    float h[32 * 32 * 3];
    CHECK_OK(down(h, img, sizeof h, &err), &err);
    CHECK(h[0] == 0.25f && h[1] == 0.5f && h[2] == 1.f && h[sizeof h / 4 - 1] == 1.f);
    dfree(img);
    CHECK_FAILS(sp_sh_to_rgb(g_gpu, 1, 2, 3, NULL, NULL, sp_v3(0, 0, 0), NULL, 3, &err), SP_E_ARG,
                &err, "active SH degree 3");
    sp_raster_free(rg);
}

static void test_all_widths(void)
{
#define SP_WIDTH_CASE(w) compare_case(40, 36, 150, w, (w) % 2, 0);
    SP_CHANNEL_WIDTHS(SP_WIDTH_CASE)
#undef SP_WIDTH_CASE
}

/* Renders a random scene on the GPU with cfg; returns host image [npix][D] and surface depth. */
static void gpu_render(const scene *s, const sp_camera *cam, const sp_raster_cfg *cfg, float *img,
                       float *surf)
{
    sp_error err = {0};
    size_t npix = (size_t)cam->width * cam->height, n = s->n;
    int D = s->D;
    sp_raster *rg = NULL;
    CHECK_OK(sp_raster_create(&rg, g_gpu, &err), &err);
    sp_raster_in in = {n, up(s->means, n * 12, &err), up(s->quats, n * 16, &err),
                       up(s->log_scales, n * 12, &err), up(s->opac, n * 4, &err),
                       up(s->colors, n * D * 4, &err), D, NULL};
    sp_raster_out out = {up(NULL, npix * D * 4, &err), NULL, NULL, surf ? up(NULL, npix * 4, &err) : NULL};
    CHECK_OK(sp_raster_forward(rg, cam, cfg, &in, &out, &err), &err);
    CHECK_OK(down(img, out.image, npix * D * 4, &err), &err);
    if (surf) CHECK_OK(down(surf, out.surface_depth, npix * 4, &err), &err);
    const void *all[] = {in.means, in.quats, in.log_scales, in.opacity_logits, in.colors, out.image,
                         out.surface_depth};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; i++) dfree(all[i]);
    sp_raster_free(rg);
}

/* The chunk width is a tuning knob only: every width gives the same bits. */
static void test_chunk_option(void)
{
    sp_camera cam = make_cam(64, 48);
    scene s = make_scene(400, 35, &cam);
    size_t npix = 64 * 48;
    float *a = malloc(npix * 35 * 4), *b = malloc(npix * 35 * 4);
    sp_raster_cfg cfg = sp_raster_cfg_default();
    gpu_render(&s, &cam, &cfg, a, NULL);
    static const int chunks[] = {8, 16, 32, 12};
    for (size_t k = 0; k < sizeof chunks / sizeof chunks[0]; k++) {
        cfg.chunk_fwd = chunks[k];
        gpu_render(&s, &cam, &cfg, b, NULL);
        CHECK_MSG(memcmp(a, b, npix * 35 * 4) == 0, "chunk %d changes the image", chunks[k]);
    }
    cfg.chunk_fwd = 5; /* not a specialised width */
    sp_raster *rg = NULL;
    sp_error err = {0};
    CHECK_OK(sp_raster_create(&rg, g_gpu, &err), &err);
    sp_raster_in in = {0};
    in.D = 3;
    sp_raster_out out = {a, NULL, NULL, NULL};
    CHECK_FAILS(sp_raster_forward(rg, &cam, &cfg, &in, &out, &err), SP_E_ARG, &err, "chunk");
    sp_raster_free(rg);
    free(a), free(b);
    scene_free(&s);
}

/* Exact ellipse-vs-tile culling is an optimisation only: with every bounding-box tile
 * (cfg.box_tiles) the image and surface depth have the same bits; profiling changes nothing and
 * reports every stage. */
static void test_box_tiles(void)
{
    sp_camera cam = make_cam(150, 110);
    scene s = make_scene(3000, 3, &cam);
    size_t npix = 150 * 110;
    float *a = malloc(npix * 3 * 4), *b = malloc(npix * 3 * 4), *sa = malloc(npix * 4),
          *sb = malloc(npix * 4);
    sp_raster_cfg cfg = sp_raster_cfg_default();
    gpu_render(&s, &cam, &cfg, a, sa);
    cfg.box_tiles = 1;
    gpu_render(&s, &cam, &cfg, b, sb);
    CHECK(memcmp(a, b, npix * 3 * 4) == 0);
    CHECK(memcmp(sa, sb, npix * 4) == 0);
    cfg.box_tiles = 0;
    cfg.profile = 1;
    gpu_render(&s, &cam, &cfg, b, NULL);
    CHECK(memcmp(a, b, npix * 3 * 4) == 0);
    free(a), free(b), free(sa), free(sb);
    scene_free(&s);
}

/* The backward's optional colour sums by gather (cfg.bwd_gather = 1) against the CPU. */
static void test_block_sums(void)
{
    g_block_sums = 1;
    compare_case(97, 63, 600, 3, 1, 0);
    compare_case(80, 64, 500, 32, 0, 0);
    compare_case(72, 40, 400, 67, 1, 0);
    g_block_sums = 0;
}

/* Wide chunks by warp reduce-scatter (cfg.bwd_gather = -1; by default chunks of 32 channels and
 * more take the shared-memory product kernel) against the CPU. */
static void test_reduce_scatter_wide(void)
{
    g_block_sums = -1;
    compare_case(80, 64, 500, 32, 0, 0);
    compare_case(72, 40, 400, 67, 1, 0);
    compare_case(40, 36, 150, 48, 1, 0);
    g_block_sums = 0;
}

/* Wide chunks on tensor cores (cfg.bwd_gather = 2: 3xTF32 WMMA for the colour product and the
 * per-pixel colour dot) against the CPU, at every width the kernel takes: 32, 64 (also as the
 * full chunk of 67 beside a reduce-scatter chunk of 3), 48, and 40 (whose product is padded to
 * 48 channels; D=35 also pads the chunk itself). The D=32 case must take that kernel (any GPU
 * this build runs on has TF32 tensor cores and room for its 76,416 bytes of shared memory); the wider ones need more
 * shared memory per block than some GPUs give (then the product kernel runs, and says so). */
static void test_tensor_core_wide(void)
{
    g_block_sums = 2;
    g_expect_bwd = "tensor-core";
    compare_case(80, 64, 500, 32, 0, 0);
    compare_case(97, 63, 600, 32, 1, 1);
    g_expect_bwd = NULL;
    compare_case(72, 40, 400, 64, 1, 0);
    compare_case(72, 40, 400, 67, 1, 0);
    compare_case(40, 36, 150, 48, 1, 0);
    compare_case(64, 48, 300, 40, 0, 0);
    compare_case(50, 70, 400, 35, 1, 0);
    g_block_sums = 0;
}

/* Two and four pixels per thread (cfg.bwd_px = 2, 4) against the CPU at the narrow widths they
 * take (D = 1, 3, 4, 8; 97x63 and 50x70 leave tiles with only the first of a thread's pixels
 * inside), with and without depth/alpha gradients, with background and the antialiased mode;
 * D=67's last chunk of 3 takes the two-pixel one too (beside the 64-wide product chunk, without
 * the aux terms), and D=12 (too wide for it) falls back to the one-pixel kernel. */
static void test_bwd_px(void)
{
    g_bwd_px = 2;
    g_expect_bwd = "reduce-scatter-2px";
    compare_case(97, 63, 600, 3, 1, 0);
    compare_case(64, 48, 300, 1, 0, 0);
    compare_case(50, 70, 400, 4, 1, 1);
    compare_case(80, 64, 500, 8, 0, 0);
    compare_case(320, 240, 20000, 3, 1, 0);
    g_no_aux = 1;
    compare_case(97, 63, 600, 3, 0, 0);
    compare_case(64, 48, 300, 1, 1, 0);
    compare_case(50, 70, 400, 8, 1, 1);
    g_no_aux = 0;
    /* four pixels per thread (64 threads per tile; in 97x63 the last tile column has only the
     * first of a thread's four pixels inside) */
    g_bwd_px = 4;
    g_expect_bwd = "reduce-scatter-4px";
    compare_case(97, 63, 600, 3, 1, 0);
    compare_case(50, 70, 400, 4, 0, 1);
    compare_case(80, 64, 500, 8, 1, 0);
    compare_case(320, 240, 20000, 3, 1, 0);
    g_no_aux = 1;
    compare_case(64, 48, 300, 1, 1, 0);
    compare_case(97, 63, 600, 3, 0, 0);
    g_no_aux = 0;
    g_bwd_px = 2;
    g_expect_bwd = NULL; /* the widest chunk's kernel: the product one where it fits */
    compare_case(72, 40, 400, 67, 1, 0);
    g_expect_bwd = "reduce-scatter";
    compare_case(40, 36, 150, 12, 0, 0);
    /* the default (0) is two pixels per thread; 1 keeps one */
    g_bwd_px = 0;
    g_expect_bwd = "reduce-scatter-2px";
    compare_case(97, 63, 600, 3, 1, 0);
    g_bwd_px = 1;
    g_expect_bwd = "reduce-scatter";
    compare_case(97, 63, 600, 3, 1, 0);
    compare_case(50, 70, 400, 8, 0, 1);
    g_expect_bwd = NULL;
    g_bwd_px = 0;
}

/* A forward with cfg fails with SP_E_ARG, its message naming `what` (the option and value). */
static void check_refused(const sp_raster_cfg *cfg, const char *what)
{
    sp_error err = {0};
    sp_raster *rg = NULL;
    CHECK_OK(sp_raster_create(&rg, g_gpu, &err), &err);
    sp_camera cam = make_cam(32, 32);
    float dummy = 0;
    sp_raster_in in = {0};
    in.D = 3;
    sp_raster_out out = {&dummy, NULL, NULL, NULL};
    CHECK_FAILS(sp_raster_forward(rg, &cam, cfg, &in, &out, &err), SP_E_ARG, &err, what);
    sp_raster_free(rg);
}

/* Image, depth and alpha of one CUDA forward (antialiased aa), and the pixels per thread its
 * widest chunk took. */
static int gpu_render_px(const scene *s, const sp_camera *cam, const sp_raster_cfg *cfg, float *img,
                         float *dep, float *alp)
{
    sp_error err = {0};
    size_t npix = (size_t)cam->width * cam->height, n = s->n;
    int D = s->D;
    sp_raster *rg = NULL;
    CHECK_OK(sp_raster_create(&rg, g_gpu, &err), &err);
    sp_raster_in in = {n, up(s->means, n * 12, &err), up(s->quats, n * 16, &err),
                       up(s->log_scales, n * 12, &err), up(s->opac, n * 4, &err),
                       up(s->colors, n * D * 4, &err), D, NULL};
    sp_raster_out out = {up(NULL, npix * D * 4, &err), up(NULL, npix * 4, &err),
                         up(NULL, npix * 4, &err), NULL};
    CHECK_OK(sp_raster_forward(rg, cam, cfg, &in, &out, &err), &err);
    CHECK_OK(down(img, out.image, npix * D * 4, &err), &err);
    CHECK_OK(down(dep, out.depth, npix * 4, &err), &err);
    CHECK_OK(down(alp, out.alpha, npix * 4, &err), &err);
    sp_raster_stages st;
    CHECK_OK(sp_raster_last_stages(rg, &st, &err), &err);
    const void *all[] = {in.means, in.quats, in.log_scales, in.opacity_logits, in.colors, out.image,
                         out.depth, out.alpha};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; i++) dfree(all[i]);
    sp_raster_free(rg);
    return st.fwd_px;
}

/* Renders s with cfg a and with cfg b (gpu_render_px; the pixels per thread each took in *took_a,
 * *took_b) and returns whether image, depth and alpha have the same bits. */
static int same_forward(const scene *s, const sp_camera *cam, const sp_raster_cfg *a,
                        const sp_raster_cfg *b, int *took_a, int *took_b)
{
    size_t npix = (size_t)cam->width * cam->height, ni = npix * s->D;
    float *ia = malloc(ni * 4), *da = malloc(npix * 4), *aa = malloc(npix * 4);
    float *ib = malloc(ni * 4), *db = malloc(npix * 4), *ab = malloc(npix * 4);
    *took_a = gpu_render_px(s, cam, a, ia, da, aa);
    *took_b = gpu_render_px(s, cam, b, ib, db, ab);
    int same = !memcmp(ia, ib, ni * 4) && !memcmp(da, db, npix * 4) && !memcmp(aa, ab, npix * 4);
    free(ia), free(da), free(aa), free(ib), free(db), free(ab);
    return same;
}

/* Several pixels per thread in the forward (cfg.fwd_px = 2, 4; 0 is 2) give one pixel per
 * thread's bits in image, depth and alpha (97x63 and 50x70 leave tiles with only the first of a
 * thread's pixels inside; 320x240 x 20000 saturates pixels, so the early stop is exercised);
 * chunks wider than 8 take one pixel whatever the option; the per-pixel state backward reads
 * (final transmittance, list end) is checked through the backward against the CPU at 1 and 4;
 * values other than 0, 1, 2, 4 are refused. */
static void test_fwd_px(void)
{
    static const struct { int W, H, n, D, aa; } cases[] = {
        {97, 63, 600, 3, 0}, {64, 48, 300, 1, 1}, {50, 70, 400, 4, 0}, {80, 64, 500, 8, 1},
        {320, 240, 20000, 3, 0}, {40, 36, 150, 12, 0}, {72, 40, 400, 35, 0}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        sp_camera cam = make_cam(cases[k].W, cases[k].H);
        scene s = make_scene((size_t)cases[k].n, cases[k].D, &cam);
        sp_raster_cfg one = sp_raster_cfg_default();
        one.antialiased = cases[k].aa;
        one.fwd_px = 1;
        static const int pxs[] = {2, 4, 0};
        for (int q = 0; q < 3; q++) {
            sp_raster_cfg cfg = one;
            cfg.fwd_px = pxs[q];
            int took_one, took;
            const int same = same_forward(&s, &cam, &one, &cfg, &took_one, &took);
            const int want = cases[k].D > 8 ? 1 : pxs[q] ? pxs[q] : 2;
            CHECK(took_one == 1);
            CHECK_MSG(took == want, "%dx%d D=%d fwd_px %d took %d pixels per thread, not %d",
                      cases[k].W, cases[k].H, cases[k].D, pxs[q], took, want);
            CHECK_MSG(same, "%dx%d D=%d: fwd_px %d differs from one pixel per thread", cases[k].W,
                      cases[k].H, cases[k].D, pxs[q]);
        }
        fprintf(stderr, "  fwd_px %dx%d n=%d D=%d aa=%d: 2, 4 and the default match 1 bit for bit\n",
                cases[k].W, cases[k].H, cases[k].n, cases[k].D, cases[k].aa);
        scene_free(&s);
    }
    g_fwd_px = 1;
    compare_case(97, 63, 600, 3, 1, 0);
    g_fwd_px = 4;
    compare_case(97, 63, 600, 3, 1, 0);
    compare_case(50, 70, 400, 8, 0, 1);
    g_fwd_px = 0;

    sp_raster_cfg cfg = sp_raster_cfg_default();
    cfg.fwd_px = 3;
    check_refused(&cfg, "fwd_px 3");
    cfg.fwd_px = 8;
    check_refused(&cfg, "fwd_px 8");
}

/* Warp culling (cfg.warp_cull) only skips Gaussians no pixel of a warp keeps: with it off the
 * forward's image, depth and alpha have the same bits at one, two and four pixels per thread and
 * at widths taking every forward kernel (97x63 and 50x70 leave bands outside the image; 320x240
 * x 20000 saturates pixels); the backward with it off still matches the CPU through each kernel
 * (two pixels per thread at D=3, one at D=12, the product at D=32; the default, on, is what every
 * other case runs); values other than -1, 0, 1 are refused. */
static void test_warp_cull(void)
{
    static const struct { int W, H, n, D, aa; } cases[] = {
        {97, 63, 600, 3, 0}, {50, 70, 400, 4, 1}, {320, 240, 20000, 3, 0}, {40, 36, 150, 12, 0},
        {72, 40, 400, 35, 0}, {64, 48, 300, 64, 1}};
    static const int pxs[] = {1, 2, 4};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        sp_camera cam = make_cam(cases[k].W, cases[k].H);
        scene s = make_scene((size_t)cases[k].n, cases[k].D, &cam);
        for (int q = 0; q < 3; q++) {
            sp_raster_cfg off = sp_raster_cfg_default();
            off.antialiased = cases[k].aa;
            off.fwd_px = pxs[q];
            off.warp_cull = -1;
            sp_raster_cfg on = off;
            on.warp_cull = 0;
            int took_off, took_on;
            CHECK_MSG(same_forward(&s, &cam, &off, &on, &took_off, &took_on),
                      "%dx%d D=%d fwd_px %d: warp culling changed the forward", cases[k].W,
                      cases[k].H, cases[k].D, pxs[q]);
        }
        fprintf(stderr, "  warp_cull %dx%d n=%d D=%d aa=%d: on and off match bit for bit\n",
                cases[k].W, cases[k].H, cases[k].n, cases[k].D, cases[k].aa);
        scene_free(&s);
    }
    g_warp_cull = -1;
    compare_case(97, 63, 600, 3, 1, 0);
    compare_case(50, 70, 400, 12, 0, 1);
    compare_case(64, 48, 300, 32, 1, 0);
    g_warp_cull = 0;

    sp_raster_cfg cfg = sp_raster_cfg_default();
    cfg.warp_cull = 2;
    check_refused(&cfg, "warp_cull 2");
    cfg.warp_cull = -2;
    check_refused(&cfg, "warp_cull -2");
}

/* bwd_px other than 0, 1, 2, 4 is refused. */
static void test_bwd_px_range(void)
{
    sp_raster_cfg cfg = sp_raster_cfg_default();
    cfg.bwd_px = 3;
    check_refused(&cfg, "bwd_px 3");
    cfg.bwd_px = -1;
    check_refused(&cfg, "bwd_px -1");
}

/* bwd_gather outside -1..2 is refused. */
static void test_bwd_gather_range(void)
{
    sp_raster_cfg cfg = sp_raster_cfg_default();
    cfg.bwd_gather = 3;
    check_refused(&cfg, "bwd_gather 3");
}

/* More than 65536 tiles: the tile sort's 32-bit keys (16-bit below). */
static void test_many_tiles(void) { compare_case(4112, 4112, 3000, 1, 0, 0); }

/* First-surface depth: both backends walk the same lists with the same alpha and transmittance
 * arithmetic, so every pixel has the same bits (no tolerance). */
static void test_surface_depth(void)
{
    sp_error err = {0};
    sp_camera cam = make_cam(120, 90);
    scene s = make_scene(3000, 1, &cam);
    size_t npix = 120 * 90, n = s.n;
    sp_device *cpu = NULL;
    sp_raster *rc = NULL;
    CHECK_OK(sp_device_create(&cpu, SP_DEVICE_CPU, 2, &err), &err);
    CHECK_OK(sp_raster_create(&rc, cpu, &err), &err);
    float *img = malloc(npix * 4), *sc = malloc(npix * 4), *sg = malloc(npix * 4);
    static const float thr[] = {0.5f, 0.2f, 0.95f, 1.0f};
    for (size_t k = 0; k < sizeof thr / sizeof thr[0]; k++) {
        sp_raster_cfg cfg = sp_raster_cfg_default();
        cfg.surface_alpha = thr[k];
        sp_raster_in in = {n, s.means, s.quats, s.log_scales, s.opac, s.colors, 1, NULL};
        sp_raster_out out = {img, NULL, NULL, sc};
        CHECK_OK(sp_raster_forward(rc, &cam, &cfg, &in, &out, &err), &err);
        gpu_render(&s, &cam, &cfg, img, sg);
        size_t diff = 0, hit = 0;
        for (size_t p = 0; p < npix; p++) diff += memcmp(&sc[p], &sg[p], 4) != 0, hit += sc[p] > 0;
        fprintf(stderr, "  surface depth at alpha %.2f: %zu of %zu pixels reach it, %zu differ\n",
                thr[k], hit, npix, diff);
        CHECK_MSG(diff == 0, "%zu pixels' surface depth differs at alpha %g", diff, thr[k]);
        CHECK(thr[k] == 1.0f || hit > npix / 10);
    }
    sp_raster_free(rc);
    sp_device_free(cpu);
    free(img), free(sc), free(sg);
    scene_free(&s);
}

/* A host splat of a random scene: SH degree 1 (view-dependent colour) and F features. */
static void make_splat(const scene *s, int F, sp_splat *out)
{
    sp_error err = {0};
    CHECK_OK(sp_splat_alloc(out, s->n, 1, F, &err), &err);
    memcpy(out->means, s->means, s->n * 12);
    memcpy(out->quats, s->quats, s->n * 16);
    memcpy(out->log_scales, s->log_scales, s->n * 12);
    memcpy(out->opacity_logits, s->opac, s->n * 4);
    for (size_t i = 0; i < s->n * 4 * 3; i++) out->sh[i] = frange(-0.8f, 0.8f);
    for (size_t i = 0; i < s->n * (size_t)F; i++) out->features[i] = frange(-1.f, 1.f);
}

typedef struct {
    float *rgb, *feat, *depth, *alpha;
} host_out;

static void render_all(sp_device *dev, const sp_splat *sp, const sp_camera *cams, size_t nv,
                       const sp_render_request *shape, int one_by_one, host_out *o)
{
    sp_error err = {0};
    sp_raster *r = NULL;
    sp_scene *sc = NULL;
    CHECK_OK(sp_raster_create(&r, dev, &err), &err);
    CHECK_OK(sp_scene_create(&sc, dev, sp, SP_SCENE_RGB | SP_SCENE_FEATURES, &err), &err);
    sp_render_request *q = calloc(nv, sizeof *q);
    for (size_t v = 0; v < nv; v++) {
        size_t np = (size_t)cams[v].width * cams[v].height;
        q[v] = shape[v];
        o[v].rgb = q[v].rgb = shape[v].rgb ? calloc(np * 3, 4) : NULL;
        o[v].feat = q[v].features = shape[v].features ? calloc(np * (size_t)sp->feat_dim, 4) : NULL;
        o[v].depth = q[v].depth = shape[v].depth ? calloc(np, 4) : NULL;
        o[v].alpha = q[v].alpha = shape[v].alpha ? calloc(np, 4) : NULL;
    }
    if (one_by_one)
        for (size_t v = 0; v < nv; v++) CHECK_OK(sp_render_views(r, sc, &cams[v], 1, &q[v], &err), &err);
    else
        CHECK_OK(sp_render_views(r, sc, cams, nv, q, &err), &err);
    free(q);
    sp_scene_free(sc);
    sp_raster_free(r);
}

static double max_diff(const float *a, const float *b, size_t n)
{
    double m = 0;
    for (size_t i = 0; a && b && i < n; i++) m = fmax(m, fabs((double)a[i] - b[i]));
    return m;
}

/* Checks a batch's outputs against one view at a time (the same bits) and the CPU's (within
 * 1e-4; first-surface depth: the same bits), then frees all three. */
static void compare_batch(const sp_camera *cams, const sp_render_request *shape, int nv, size_t F,
                          host_out *batch, host_out *single, host_out *cpu)
{
    for (int v = 0; v < nv; v++) {
        size_t np = (size_t)cams[v].width * cams[v].height;
        float *b[4] = {batch[v].rgb, batch[v].feat, batch[v].depth, batch[v].alpha};
        float *o[4] = {single[v].rgb, single[v].feat, single[v].depth, single[v].alpha};
        float *c[4] = {cpu[v].rgb, cpu[v].feat, cpu[v].depth, cpu[v].alpha};
        size_t len[4] = {np * 3, np * F, np, np};
        for (int k = 0; k < 4; k++) {
            if (!b[k]) continue;
            CHECK_MSG(memcmp(b[k], o[k], len[k] * 4) == 0, "view %d output %d: batch != single", v, k);
            double d = max_diff(b[k], c[k], len[k]);
            int exact = k == 2 && shape[v].depth_mode == SP_DEPTH_SURFACE;
            CHECK_MSG(exact ? memcmp(b[k], c[k], len[k] * 4) == 0 : d <= 1e-4,
                      "view %d output %d: GPU vs CPU %g", v, k, d);
            fprintf(stderr, "  view %d output %d: |GPU - CPU| %.2g\n", v, k, d);
        }
        for (int k = 0; k < 4; k++) free(b[k]), free(o[k]), free(c[k]);
    }
}

/* A batch whose views all ask the same (their passes share colours and background: one
 * compositing launch for all views): the same bits as one view at a time, and the CPU's within
 * 1e-4; views of different sizes, one with no Gaussian in front of it. */
static void test_views_batch_uniform(void)
{
    sp_error err = {0};
    sp_camera base = make_cam(96, 72);
    scene s = make_scene(2500, 1, &base);
    sp_splat sp;
    make_splat(&s, 33, &sp);
    sp_camera cams[5] = {base, make_cam(64, 40), make_cam(33, 50), base, make_cam(50, 20)};
    sp_vec3 eye = {0.3f, -0.2f, -0.5f}, at = {0.f, 0.f, 4.f}, upv = {0.f, -1.f, 0.f};
    sp_camera_look_at(&cams[3], eye, at, upv);
    sp_vec3 away = {0.f, 0.f, -10.f};
    sp_camera_look_at(&cams[4], eye, away, upv);
    float bg[3] = {0.2f, 0.4f, 0.9f};
    for (int twopass = 0; twopass < 2; twopass++) {
        sp_render_request shape[5];
        for (int v = 0; v < 5; v++)
            shape[v] = (sp_render_request){.rgb = twopass ? (float *)1 : NULL, .features = (float *)1,
                                           .depth = (float *)1, .alpha = (float *)1,
                                           .background = twopass ? bg : NULL};
        host_out batch[5], single[5], cpu[5];
        render_all(g_gpu, &sp, cams, 5, shape, 0, batch);
        render_all(g_gpu, &sp, cams, 5, shape, 1, single);
        sp_device *cd = NULL;
        CHECK_OK(sp_device_create(&cd, SP_DEVICE_CPU, 2, &err), &err);
        render_all(cd, &sp, cams, 5, shape, 0, cpu);
        sp_device_free(cd);
        compare_batch(cams, shape, 5, 33, batch, single, cpu);
    }
    sp_splat_free(&sp);
    scene_free(&s);
}

/* A batch of views of different sizes and requests: the same bits as one view at a time on the
 * GPU, and the CPU's renders within 1e-4 (surface depth: the same bits). */
static void test_views_batch(void)
{
    sp_error err = {0};
    sp_camera base = make_cam(96, 72);
    scene s = make_scene(2500, 1, &base);
    sp_splat sp;
    make_splat(&s, 7, &sp);
    sp_camera cams[4] = {base, make_cam(64, 40), make_cam(33, 50), base};
    sp_vec3 eye = {0.3f, -0.2f, -0.5f}, at = {0.f, 0.f, 4.f}, upv = {0.f, -1.f, 0.f};
    sp_camera_look_at(&cams[3], eye, at, upv);
    float bg[3] = {0.2f, 0.4f, 0.9f};
    sp_render_request shape[4] = {
        {.rgb = (float *)1, .features = (float *)1, .depth = (float *)1, .alpha = (float *)1, .background = bg},
        {.rgb = (float *)1, .depth = (float *)1, .depth_mode = SP_DEPTH_SURFACE},
        {.alpha = (float *)1, .depth = (float *)1, .depth_mode = SP_DEPTH_SURFACE, .depth_alpha = 0.8f},
        {.features = (float *)1, .depth = (float *)1}};
    host_out batch[4], single[4], cpu[4];
    render_all(g_gpu, &sp, cams, 4, shape, 0, batch);
    render_all(g_gpu, &sp, cams, 4, shape, 1, single);
    sp_device *cd = NULL;
    CHECK_OK(sp_device_create(&cd, SP_DEVICE_CPU, 2, &err), &err);
    render_all(cd, &sp, cams, 4, shape, 0, cpu);
    compare_batch(cams, shape, 4, 7, batch, single, cpu);
    sp_device_free(cd);
    sp_splat_free(&sp);
    scene_free(&s);
}

int main(void)
{
    sp_error err = {0};
    if (!sp_cuda_available()) TEST_SKIP("no CUDA GPU (or a build without CUDA)");
    if (sp_device_create(&g_gpu, SP_DEVICE_CUDA, 2, &err)) {
        fprintf(stderr, "CUDA device: %s\n", err.msg);
        return 1;
    }
    RUN(test_bad_input);
    RUN(test_rgb);
    RUN(test_one_channel);
    RUN(test_padded_width);
    RUN(test_features32);
    RUN(test_features67);
    RUN(test_antialiased);
    RUN(test_many);
    RUN(test_all_widths);
    RUN(test_chunk_option);
    RUN(test_box_tiles);
    RUN(test_block_sums);
    RUN(test_reduce_scatter_wide);
    RUN(test_tensor_core_wide);
    RUN(test_bwd_gather_range);
    RUN(test_bwd_px);
    RUN(test_bwd_px_range);
    RUN(test_fwd_px);
    RUN(test_warp_cull);
    RUN(test_many_tiles);
    RUN(test_surface_depth);
    RUN(test_views_batch);
    RUN(test_views_batch_uniform);
    RUN(test_sh);
    sp_device_free(g_gpu);
    return TEST_EXIT();
}
