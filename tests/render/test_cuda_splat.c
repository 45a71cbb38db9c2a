/* CPU and CUDA backends agree on a trained splat (issue 4): forward within 1e-4, gradients within
 * 1e-3 relative, first-surface depth bit for bit. The splat is made here: a small room of known
 * Gaussians rendered from a ring of cameras, trained on the GPU (SH degree 3, densification), so
 * it has the overlapping, anisotropic, semi-transparent Gaussians of real training. With
 * SP_TEST_SPLAT=splat.ply SP_TEST_COLMAP=capture the comparison runs on that splat instead (the
 * GPU acceptance script passes the trained house). Skips (77) without a GPU. */
#include "test.h"

#include <stdint.h>

#include "semsplat/io.h"
#include "semsplat/render.h"
#include "semsplat/train.h"

typedef struct {
    sp_device *dev;
    float *means, *quats, *scales, *opac, *sh, *rgb, *feat, *img, *depth, *alpha;
    float *v_img, *v_depth, *v_means, *v_quats, *v_scales, *v_opac, *v_colors, *v_m2d;
} dev_bufs;

static float *up(sp_device *d, const float *h, size_t n, sp_error *err)
{
    float *p = sp_device_alloc(d, n * sizeof(float), err);
    if (p && h) sp_device_upload(d, p, h, n * sizeof(float), err);
    return p;
}

static float *down(sp_device *d, const float *p, size_t n, sp_error *err)
{
    float *h = malloc(n * sizeof(float));
    sp_device_download(d, h, p, n * sizeof(float), err);
    return h;
}

/* Renders RGB + F feature channels (features = a fixed function of the Gaussian index) and runs
 * the backward of random image / depth gradients. Returns host copies via out arrays. */
static int run(sp_device *dev, const sp_splat *s, const sp_camera *cam, int F, const float *v_img_h,
               const float *v_depth_h, float **img, float **dep, float **grads, sp_error *err)
{
    size_t n = s->n, K = (size_t)sp_sh_coeffs(s->sh_degree), D = 3 + (size_t)F;
    size_t npix = (size_t)cam->width * cam->height;
    float *colors_h = calloc(n * D, sizeof(float));
    for (size_t i = 0; i < n; i++)
        for (int f = 0; f < F; f++) colors_h[i * D + 3 + f] = (float)((i * 7 + (size_t)f * 13) % 17) / 17.0f;
    float *means = up(dev, s->means, n * 3, err), *quats = up(dev, s->quats, n * 4, err),
          *scales = up(dev, s->log_scales, n * 3, err), *opac = up(dev, s->opacity_logits, n, err),
          *sh = up(dev, s->sh, n * K * 3, err), *colors = up(dev, colors_h, n * D, err),
          *image = up(dev, NULL, npix * D, err), *depth = up(dev, NULL, npix, err),
          *alpha = up(dev, NULL, npix, err), *v_img = up(dev, v_img_h, npix * D, err),
          *v_dep = up(dev, v_depth_h, npix, err), *g = up(dev, NULL, n * 15 + n * D, err);
    sp_raster *r = NULL;
    int rc = sp_raster_create(&r, dev, err);
    sp_vec3 c = sp_camera_center(cam);
    if (!rc) rc = sp_sh_to_rgb(dev, n, s->sh_degree, s->sh_degree, sh, means, c, colors, (int)D, err);
    sp_raster_cfg cfg = sp_raster_cfg_default();
    sp_raster_in in = {n, means, quats, scales, opac, colors, (int)D, NULL};
    sp_raster_out out = {image, depth, alpha, NULL};
    double t0 = sp_time_now();
    if (!rc) rc = sp_raster_forward(r, cam, &cfg, &in, &out, err);
    sp_raster_grad_in gin = {v_img, v_dep, NULL};
    sp_raster_grads gr = {g, g + n * 3, g + n * 7, g + n * 10, g + n * 15, g + n * 11};
    if (!rc) rc = sp_raster_backward(r, &gin, &gr, err);
    if (!rc) rc = sp_device_sync(dev, err);
    fprintf(stderr, "  %s: forward+backward %.1f ms, %zu pairs\n", sp_device_name(dev),
            1e3 * (sp_time_now() - t0), sp_raster_last_pairs(r));
    if (!rc) {
        *img = down(dev, image, npix * D, err);
        *dep = down(dev, depth, npix, err);
        *grads = down(dev, g, n * 15 + n * D, err);
    }
    sp_raster_free(r);
    float *all[] = {means, quats, scales, opac, sh, colors, image, depth, alpha, v_img, v_dep, g};
    for (size_t i = 0; i < sizeof all / sizeof *all; i++) sp_device_release(dev, all[i]);
    free(colors_h);
    return rc;
}

enum { NV = 24, IW = 160, IH = 120 };

/* The known scene: a floor and two walls of flat Gaussians, and coloured blobs in the room. */
static void make_room(sp_splat *gt, size_t n)
{
    sp_error err = {0};
    CHECK_OK(sp_splat_alloc(gt, n, 0, 0, &err), &err);
    test_rng r = {4242};
    for (size_t i = 0; i < n; i++) {
        float *m = gt->means + 3 * i, *ls = gt->log_scales + 3 * i;
        int part = (int)(i % 4);
        double u = test_range(&r, -1.2, 1.2), v = test_range(&r, -1.2, 1.2);
        if (part == 0) m[0] = (float)u, m[1] = (float)v, m[2] = -0.6f;        /* floor */
        else if (part == 1) m[0] = -1.2f, m[1] = (float)u, m[2] = (float)(0.3 + 0.8 * v); /* wall */
        else if (part == 2) m[0] = (float)u, m[1] = 1.2f, m[2] = (float)(0.3 + 0.8 * v); /* wall */
        else m[0] = (float)(0.6 * u), m[1] = (float)(0.6 * v), m[2] = (float)test_range(&r, -0.5, 0.5);
        for (int k = 0; k < 3; k++) ls[k] = logf((float)test_range(&r, 0.05, 0.15));
        if (part == 0) ls[2] = logf(0.01f);
        if (part == 1) ls[0] = logf(0.01f);
        if (part == 2) ls[1] = logf(0.01f);
        for (int k = 0; k < 4; k++) gt->quats[4 * i + k] = part == 3 ? (float)test_range(&r, -1, 1) : (k == 0);
        for (int k = 0; k < 3; k++) gt->sh[3 * i + k] = (float)((test_uniform(&r) - 0.5) / SP_SH_C0);
        gt->opacity_logits[i] = sp_logit((float)test_range(&r, 0.5, 0.95));
    }
}

static sp_camera ring_cam(int k, int scale)
{
    sp_camera c;
    memset(&c, 0, sizeof c);
    sp_camera_intrinsics_fov(&c, IW * scale, IH * scale, 1.2f);
    double a = 6.2831853 * k / NV;
    sp_camera_look_at(&c, sp_v3((float)(2.6 * cos(a)), (float)(2.6 * sin(a)), 0.9f + 0.2f * (k % 3)),
                      sp_v3(0, 0, -0.1f), sp_v3(0, 0, 1));
    return c;
}

/* Renders the room from the ring into training data and trains a splat on the GPU. */
static int train_room(sp_device *gpu, sp_splat *out)
{
    sp_error err = {0};
    sp_splat gt;
    make_room(&gt, 1200);
    sp_train_data d;
    memset(&d, 0, sizeof d);
    d.n_views = NV;
    d.views = calloc(NV, sizeof *d.views);
    d.n_points = gt.n;
    d.points = malloc(gt.n * 3 * sizeof(float));
    d.point_rgb = malloc(gt.n * 3);
    test_rng r = {99};
    for (size_t i = 0; i < gt.n * 3; i++) {
        d.points[i] = gt.means[i] + (float)test_range(&r, -0.04, 0.04);
        d.point_rgb[i] = 128;
    }
    sp_raster *rast = NULL;
    CHECK_OK(sp_raster_create(&rast, gpu, &err), &err);
    float *rgb = malloc(IW * IH * 3 * sizeof(float));
    for (int k = 0; k < NV && !t_failures; k++) {
        sp_train_view *v = &d.views[k];
        snprintf(v->name, sizeof v->name, "%03d.png", k);
        v->cam = ring_cam(k, 1);
        v->is_test = k % 8 == 0;
        v->rgb = malloc(IW * IH * 3);
        sp_render_request req = {.rgb = rgb};
        CHECK_OK(sp_render_splat(rast, &gt, &v->cam, &req, &err), &err);
        for (int p = 0; p < IW * IH * 3; p++) {
            float x = rgb[p] < 0 ? 0 : rgb[p] > 1 ? 1 : rgb[p];
            v->rgb[p] = (uint8_t)lrintf(x * 255.f);
        }
    }
    free(rgb);
    sp_raster_free(rast);
    sp_train_data_update_scene(&d);
    int rc = t_failures ? 1 : sp_train_init_from_points(out, &d, 3, 7, &err);
    sp_train_options o = sp_train_options_default(2000);
    o.refine_start = 100, o.refine_every = 100, o.refine_stop = 1500;
    sp_train_result res;
    double t0 = sp_time_now();
    if (!rc) rc = sp_train_run(gpu, &d, &o, out, &res, NULL, &err);
    CHECK_MSG(rc == 0, "training: %s", err.msg);
    if (!rc)
        fprintf(stderr, "  trained the room on the GPU: %zu Gaussians, held-out PSNR %.2f dB, %.1f s\n",
                res.gaussians, res.psnr, sp_time_now() - t0);
    CHECK(rc || res.psnr > 20.0);
    sp_train_data_free(&d);
    sp_splat_free(&gt);
    return rc;
}

/* The splat and the views to compare on: SP_TEST_SPLAT / SP_TEST_COLMAP when set, else the room. */
static int get_splat(sp_device *gpu, sp_splat *s, sp_camera *cams, int *nc)
{
    const char *splat_path = getenv("SP_TEST_SPLAT"), *colmap = getenv("SP_TEST_COLMAP");
    sp_error err = {0};
    if (splat_path && colmap) {
        sp_colmap_model m;
        CHECK_OK(sp_ply_read_splat(splat_path, s, &err), &err);
        CHECK_OK(sp_colmap_read(colmap, &m, &err), &err);
        if (t_failures) return 1;
        size_t views[] = {0, m.n_images / 3, (2 * m.n_images) / 3};
        for (int k = 0; k < 3; k++) CHECK_OK(sp_colmap_image_camera(&m, views[k], &cams[k], &err), &err);
        sp_colmap_free(&m);
        *nc = 3;
        return t_failures;
    }
    if (train_room(gpu, s)) return 1;
    /* at twice the training resolution, from between the training views */
    for (int k = 0; k < 3; k++) {
        cams[k] = ring_cam(3 + 8 * k, 2);
        sp_camera c = ring_cam(4 + 8 * k, 2);
        sp_vec3 a = sp_camera_center(&cams[k]), b = sp_camera_center(&c);
        sp_camera_look_at(&cams[k], sp_v3_scale(sp_v3_add(a, b), 0.5f), sp_v3(0, 0, -0.1f), sp_v3(0, 0, 1));
    }
    *nc = 3;
    return 0;
}

/* Inference renders through scenes on both devices: RGB and features within 1e-4, first-surface
 * depth (at alpha 0.5) the same bits, expected depth within 1e-4 relative. */
static void surface_check(sp_device *cpu, sp_device *gpu, const sp_splat *s, const sp_camera *cam)
{
    sp_error err = {0};
    size_t np = (size_t)cam->width * cam->height;
    float *out[2][3];
    for (int d = 0; d < 2; d++) {
        sp_device *dev = d ? gpu : cpu;
        sp_raster *r = NULL;
        sp_scene *sc = NULL;
        for (int k = 0; k < 3; k++) out[d][k] = calloc(np * 3, sizeof(float));
        CHECK_OK(sp_raster_create(&r, dev, &err), &err);
        CHECK_OK(sp_scene_create(&sc, dev, s, SP_SCENE_RGB, &err), &err);
        sp_render_request q[2] = {{.rgb = out[d][0], .depth = out[d][1], .depth_mode = SP_DEPTH_SURFACE},
                                  {.depth = out[d][2]}};
        sp_camera cams[2] = {*cam, *cam};
        CHECK_OK(sp_render_views(r, sc, cams, 2, q, &err), &err);
        sp_scene_free(sc);
        sp_raster_free(r);
    }
    double e_rgb = 0, e_exp = 0;
    size_t diff = 0, hit = 0;
    for (size_t p = 0; p < np * 3; p++) e_rgb = fmax(e_rgb, fabs(out[0][0][p] - out[1][0][p]));
    for (size_t p = 0; p < np; p++) {
        diff += memcmp(&out[0][1][p], &out[1][1][p], sizeof(float)) != 0;
        hit += out[0][1][p] > 0;
        e_exp = fmax(e_exp, fabs(out[0][2][p] - out[1][2][p]) / fmax(1.0, fabs(out[0][2][p])));
    }
    fprintf(stderr, "  scene renders: rgb %.2e, expected depth %.2e, surface depth differs at %zu of "
            "%zu pixels (%zu reach alpha 0.5)\n", e_rgb, e_exp, diff, np, hit);
    CHECK(e_rgb <= 1e-4 && e_exp <= 1e-4);
    CHECK_MSG(diff == 0, "surface depth differs at %zu pixels", diff);
    CHECK(hit > np / 4);
    for (int d = 0; d < 2; d++)
        for (int k = 0; k < 3; k++) free(out[d][k]);
}

static void test_trained_splat(void)
{
    sp_error err = {0};
    sp_device *cpu = NULL, *gpu = NULL;
    CHECK_OK(sp_device_create(&cpu, SP_DEVICE_CPU, 0, &err), &err);
    CHECK_OK(sp_device_create(&gpu, SP_DEVICE_CUDA, 0, &err), &err);
    sp_splat s;
    sp_camera cams[3];
    int nc = 0;
    memset(&s, 0, sizeof s);
    if (t_failures || get_splat(gpu, &s, cams, &nc)) goto done;
    const int F = 32;
    for (int vi = 0; vi < nc && !t_failures; vi++) {
        sp_camera cam = cams[vi];
        size_t npix = (size_t)cam.width * cam.height, D = 3 + F, n = s.n;
        test_rng rng = {1234 + (unsigned long long)vi};
        float *v_img = malloc(npix * D * sizeof(float)), *v_dep = malloc(npix * sizeof(float));
        for (size_t i = 0; i < npix * D; i++) v_img[i] = (float)test_range(&rng, -1, 1);
        for (size_t i = 0; i < npix; i++) v_dep[i] = (float)test_range(&rng, -0.1, 0.1);
        float *ic, *dc, *gc, *ig, *dg, *gg;
        int rc1 = run(cpu, &s, &cam, F, v_img, v_dep, &ic, &dc, &gc, &err);
        CHECK_MSG(rc1 == 0, "cpu: %s", err.msg);
        int rc2 = run(gpu, &s, &cam, F, v_img, v_dep, &ig, &dg, &gg, &err);
        CHECK_MSG(rc2 == 0, "cuda: %s", err.msg);
        if (rc1 || rc2) break;
        double e_img = 0, e_dep = 0;
        for (size_t i = 0; i < npix * D; i++) e_img = fmax(e_img, fabs(ic[i] - ig[i]));
        for (size_t i = 0; i < npix; i++) e_dep = fmax(e_dep, fabs(dc[i] - dg[i]) / fmax(1.0, fabs(dc[i])));
        /* Gradients, per group: |cpu - gpu| / max(|cpu|, 1e-3 max|group|), so entries that
         * are sums of many random-signed pixel terms cancelling to almost nothing are judged
         * against the group's scale, not their own. The forward is identical on both backends
         * (same keep/skip decisions, gauss_math.h); what is left is summation order. Before the
         * conic gradient was summed in the conic's frame and the rotation gradient formed from
         * scale differences (gauss_math.h), that order moved 234 of 14.6M entries of this test
         * beyond 1e-3 (quaternions of nearly round Gaussians, scales of needles). */
        size_t total = n * 15 + n * D, bad = 0;
        const struct { const char *name; size_t off, cnt; } grp[] = {
            {"v_means", 0, 3 * n}, {"v_quats", 3 * n, 4 * n}, {"v_log_scales", 7 * n, 3 * n},
            {"v_opacity", 10 * n, n}, {"v_means2d", 11 * n, 2 * n}, {"v_colors", 15 * n, n * D}};
        double worst = 0;
        for (size_t k = 0; k < sizeof grp / sizeof grp[0]; k++) {
            const float *a = gc + grp[k].off, *b = gg + grp[k].off;
            double gmax = 0, gworst = 0;
            size_t gbad = 0, at = 0;
            for (size_t i = 0; i < grp[k].cnt; i++) gmax = fmax(gmax, fabs(a[i]));
            for (size_t i = 0; i < grp[k].cnt; i++) {
                double rel = fabs(a[i] - b[i]) / fmax(fabs(a[i]), 1e-3 * gmax + 1e-30);
                if (rel > gworst) gworst = rel, at = i;
                gbad += rel > 1e-3;
            }
            fprintf(stderr, "    %-13s %zu of %zu beyond 1e-3 (worst %.2e: cpu %.6g gpu %.6g, "
                    "group max %.3g)\n", grp[k].name, gbad, grp[k].cnt, gworst, a[at], b[at], gmax);
            bad += gbad;
            worst = fmax(worst, gworst);
        }
        fprintf(stderr, "  view %d (%dx%d, %zu Gaussians, D=%zu): max |image| diff %.2e, depth "
                "%.2e; gradients beyond 1e-3 rel: %zu of %zu (worst %.2e)\n", vi, cam.width,
                cam.height, n, D, e_img, e_dep, bad, total, worst);
        CHECK_MSG(e_img <= 1e-4, "image differs by %g", e_img);
        CHECK_MSG(e_dep <= 1e-4, "depth differs by %g", e_dep);
        CHECK_MSG(bad == 0, "%zu of %zu gradients beyond 1e-3 (worst %.3g)", bad, total, worst);
        free(v_img); free(v_dep); free(ic); free(dc); free(gc); free(ig); free(dg); free(gg);
        surface_check(cpu, gpu, &s, &cam);
    }
done:
    sp_device_free(cpu);
    sp_device_free(gpu);
    sp_splat_free(&s);
}

int main(void)
{
    if (!sp_cuda_available()) TEST_SKIP("no GPU");
    RUN(test_trained_splat);
    return TEST_EXIT();
}
