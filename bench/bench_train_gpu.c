/* End-to-end GPU training benchmark: the library's training loop (sp_train_run, CUDA device) on a
 * capture made in memory, so it needs no files: a ground-truth splat (a textured ground plane
 * and a ring of coloured blobs, all opaque) rendered from views orbiting the scene, then trained
 * from a noisy subset of its centres as the "COLMAP points". Prints steps per second, wall time,
 * Gaussian count and held-out PSNR/SSIM (every 8th view held out, as gsplat).
 *
 * Usage: bench_train_gpu [steps (default 3000)] [width (default 640)] [views (default 64)]
 * Prints `name  value  unit  (settings)` lines; exits 0 with a "skipped" line without a GPU. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/render.h"
#include "semsplat/train.h"

static uint64_t rs = 0x2545F4914F6CDD1Dull;
static float frand(void)
{
    rs ^= rs << 13;
    rs ^= rs >> 7;
    rs ^= rs << 17;
    return (float)((rs >> 40) & 0xffffff) / 16777216.0f;
}

#define DIE(...)                                                                              \
    do {                                                                                      \
        fprintf(stderr, "bench_train_gpu: " __VA_ARGS__);                                     \
        fprintf(stderr, "\n");                                                                \
        return 1;                                                                             \
    } while (0)

/* Ground truth: n_plane Gaussians tiling a 6 x 6 m checkered floor (z = 0) and n_blob in 12
 * coloured clusters on a ring of radius 1.5 m, 0.2-0.8 m up. */
static int make_gt(sp_splat *s, size_t n_plane, size_t n_blob, sp_error *err)
{
    int rc = sp_splat_alloc(s, n_plane + n_blob, 0, 0, err);
    if (rc) return rc;
    for (size_t i = 0; i < s->n; i++) {
        float *m = s->means + 3 * i, *ls = s->log_scales + 3 * i, *c = s->sh + 3 * i;
        float rgb[3];
        if (i < n_plane) {
            m[0] = frand() * 6.f - 3.f, m[1] = frand() * 6.f - 3.f, m[2] = 0.f;
            int check = ((int)((m[0] + 3.f) * 2.f) + (int)((m[1] + 3.f) * 2.f)) & 1;
            for (int k = 0; k < 3; k++) rgb[k] = check ? 0.85f : 0.15f + 0.1f * k;
            ls[0] = ls[1] = logf(0.03f), ls[2] = logf(0.004f);
        } else {
            int b = (int)(i % 12);
            float a = 6.2831853f * b / 12.f;
            m[0] = 1.5f * cosf(a) + 0.15f * (frand() - 0.5f);
            m[1] = 1.5f * sinf(a) + 0.15f * (frand() - 0.5f);
            m[2] = 0.2f + 0.6f * frand();
            rgb[0] = 0.5f + 0.45f * cosf(a), rgb[1] = 0.5f + 0.45f * cosf(a + 2.1f);
            rgb[2] = 0.5f + 0.45f * cosf(a + 4.2f);
            for (int k = 0; k < 3; k++) ls[k] = logf(0.02f + 0.03f * frand());
        }
        for (int k = 0; k < 3; k++) c[k] = (rgb[k] - 0.5f) / SP_SH_C0;
        s->opacity_logits[i] = 4.f;
    }
    return 0;
}

int main(int argc, char **argv)
{
    int steps = argc > 1 ? atoi(argv[1]) : 3000;
    int W = argc > 2 ? atoi(argv[2]) : 640, H = W * 3 / 4;
    int n_views = argc > 3 ? atoi(argv[3]) : 64;
    sp_error err = {0};
    if (!sp_cuda_available()) {
        printf("bench_train_gpu  skipped  (no CUDA GPU)\n");
        return 0;
    }
    sp_device *dev = NULL;
    sp_raster *r = NULL;
    if (sp_device_create(&dev, SP_DEVICE_CUDA, 0, &err) || sp_raster_create(&r, dev, &err))
        DIE("%s", err.msg);

    sp_splat gt;
    if (make_gt(&gt, 60000, 24000, &err)) DIE("%s", err.msg);
    sp_train_data d;
    memset(&d, 0, sizeof d);
    d.n_views = (size_t)n_views;
    d.views = calloc(d.n_views, sizeof *d.views);
    float *img = malloc((size_t)W * H * 3 * sizeof(float));
    for (int v = 0; v < n_views; v++) {
        sp_train_view *tv = &d.views[v];
        snprintf(tv->name, sizeof tv->name, "view_%03d.png", v);
        float a = 6.2831853f * v / n_views, h = 1.2f + 0.8f * (float)(v % 3);
        memset(&tv->cam, 0, sizeof tv->cam);
        tv->cam.width = W, tv->cam.height = H;
        tv->cam.fx = tv->cam.fy = 0.8f * W;
        tv->cam.cx = W / 2.f, tv->cam.cy = H / 2.f;
        sp_camera_look_at(&tv->cam, sp_v3(4.f * cosf(a), 4.f * sinf(a), h), sp_v3(0, 0, 0.3f),
                          sp_v3(0, 0, 1));
        tv->is_test = (v % 8) == 0;
        sp_render_request req = {.rgb = img};
        if (sp_render_splat(r, &gt, &tv->cam, &req, &err)) DIE("%s", err.msg);
        tv->rgb = malloc((size_t)W * H * 3);
        for (size_t k = 0; k < (size_t)W * H * 3; k++) {
            float x = img[k] < 0.f ? 0.f : (img[k] > 1.f ? 1.f : img[k]);
            tv->rgb[k] = (uint8_t)(x * 255.f + 0.5f);
        }
    }
    free(img);
    /* "COLMAP points": every 8th ground-truth centre, jittered by 5 cm */
    d.n_points = gt.n / 8;
    d.points = malloc(d.n_points * 3 * sizeof(float));
    d.point_rgb = malloc(d.n_points * 3);
    for (size_t i = 0; i < d.n_points; i++)
        for (int k = 0; k < 3; k++) {
            d.points[i * 3 + k] = gt.means[8 * i * 3 + k] + 0.05f * (frand() - 0.5f);
            d.point_rgb[i * 3 + k] = 128;
        }
    sp_train_data_update_scene(&d);

    sp_splat s;
    if (sp_train_init_from_points(&s, &d, 3, 1, &err)) DIE("%s", err.msg);
    sp_train_options opt = sp_train_options_default(steps);
    opt.eval_every = 0;
    sp_train_result res;
    memset(&res, 0, sizeof res);
    if (sp_train_run(dev, &d, &opt, &s, &res, NULL, &err)) DIE("%s", err.msg);
    char set[200];
    snprintf(set, sizeof set, "(%d views %dx%d, %zu init points, %d steps, %s)", n_views, W, H,
             d.n_points, steps, sp_device_name(dev));
    printf("train_steps_per_s   %8.1f  steps/s  %s\n", res.steps / res.seconds, set);
    printf("train_wall_s        %8.2f  s        %s\n", res.seconds, set);
    printf("train_psnr          %8.2f  dB       %s held-out %d views\n", res.psnr, set,
           res.n_eval_views);
    printf("train_ssim          %8.4f  -        %s\n", res.ssim, set);
    printf("train_gaussians     %8zu  -        %s\n", res.gaussians, set);
    printf("train_peak_gib      %8.3f  GiB      %s\n", sp_device_peak_bytes(dev) / 1073741824.0,
           set);

    for (size_t v = 0; v < d.n_views; v++) free(d.views[v].rgb);
    free(d.views), free(d.points), free(d.point_rgb);
    sp_splat_free(&s);
    sp_splat_free(&gt);
    sp_raster_free(r);
    sp_device_free(dev);
    return 0;
}
