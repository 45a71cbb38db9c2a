/* CPU training throughput: steps per second of the full training step (SH -> rasterize ->
 * L1+SSIM -> backward -> Adam) on a 320x240 capture made in memory (random Gaussians seen from a
 * ring of cameras), densification off so the count stays fixed.
 * usage: bench_train_cpu [gaussians (default 50000)] [steps (default 40)] [threads (0 = all)] */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/render.h"
#include "semsplat/train.h"

static double urand(uint64_t *s)
{
    *s ^= *s >> 12, *s ^= *s << 25, *s ^= *s >> 27;
    return (double)((*s * 2685821657736338717ULL) >> 11) * (1.0 / 9007199254740992.0);
}

int main(int argc, char **argv)
{
    size_t n = argc > 1 ? (size_t)atol(argv[1]) : 50000;
    int steps = argc > 2 ? atoi(argv[2]) : 40, threads = argc > 3 ? atoi(argv[3]) : 0;
    enum { W = 320, H = 240, NV = 12 };
    sp_error err = {0};
    sp_device *dev = NULL;
    sp_raster *r = NULL;
    if (sp_device_create(&dev, SP_DEVICE_CPU, threads, &err) || sp_raster_create(&r, dev, &err)) {
        fprintf(stderr, "bench_train_cpu: %s\n", err.msg);
        return 1;
    }
    /* ground truth: Gaussians filling a room-sized box, seen from inside-out ring cameras */
    sp_splat gt, s;
    uint64_t rng = 88172645463325252ULL;
    sp_splat_alloc(&gt, n, 3, 0, &err);
    for (size_t i = 0; i < n; i++) {
        for (int a = 0; a < 3; a++) {
            gt.means[i * 3 + a] = (float)(urand(&rng) * 4 - 2);
            gt.log_scales[i * 3 + a] = logf((float)(0.01 + 0.04 * urand(&rng)));
            gt.sh[i * 48 + a] = (float)((urand(&rng) - 0.5) / SP_SH_C0);
        }
        for (int a = 0; a < 4; a++) gt.quats[i * 4 + a] = (float)(urand(&rng) * 2 - 1);
        gt.opacity_logits[i] = sp_logit(0.2f + 0.6f * (float)urand(&rng));
    }
    sp_train_data d;
    memset(&d, 0, sizeof d);
    d.n_views = NV;
    d.views = calloc(NV, sizeof(sp_train_view));
    float *img = malloc(sizeof(float) * W * H * 3);
    for (int k = 0; k < NV; k++) {
        sp_train_view *v = &d.views[k];
        snprintf(v->name, sizeof v->name, "%02d.png", k);
        v->cam.width = W, v->cam.height = H, v->cam.fx = v->cam.fy = 250, v->cam.cx = W / 2.0f,
        v->cam.cy = H / 2.0f;
        double a = 6.2831853 * k / NV;
        sp_camera_look_at(&v->cam, sp_v3((float)(5 * cos(a)), (float)(5 * sin(a)), 1),
                          sp_v3(0, 0, 0), sp_v3(0, 0, 1));
        sp_render_request req = {.rgb = img};
        if (sp_render_splat(r, &gt, &v->cam, &req, &err)) {
            fprintf(stderr, "bench_train_cpu: %s\n", err.msg);
            return 1;
        }
        v->rgb = malloc(W * H * 3);
        for (int p = 0; p < W * H * 3; p++) {
            float x = img[p] < 0 ? 0 : img[p] > 1 ? 1 : img[p];
            v->rgb[p] = (uint8_t)(x * 255 + 0.5f);
        }
        v->is_test = k == 0;
    }
    free(img);
    sp_train_data_update_scene(&d);
    /* start from perturbed truth so the workload looks like mid-training */
    sp_splat_copy(&s, &gt, &err);
    for (size_t i = 0; i < n * 3; i++) s.means[i] += (float)(urand(&rng) - 0.5) * 0.02f;
    sp_train_options o = sp_train_options_default(steps);
    o.densify = 0;
    o.sh_degree_interval = 1; /* full SH degree from step 3 on, the steady-state cost */
    o.checkpoint_every = 0;
    sp_train_result res;
    double t0 = sp_time_now();
    if (sp_train_run(dev, &d, &o, &s, &res, NULL, &err)) {
        fprintf(stderr, "bench_train_cpu: %s\n", err.msg);
        return 1;
    }
    double dt = sp_time_now() - t0;
    /* res.seconds includes the final held-out evaluation of one view; report the loop rate */
    printf("train_cpu_steps_per_s  %.2f  steps/s  (%dx%d, %zu gaussians, SH 3, %d steps, %s)\n",
           steps / dt, W, H, n, steps, sp_device_name(dev));
    printf("train_cpu_ms_per_step  %.1f  ms  (same)\n", 1000.0 * dt / steps);
    sp_splat_free(&gt);
    sp_splat_free(&s);
    sp_train_data_free(&d);
    sp_raster_free(r);
    sp_device_free(dev);
    return 0;
}
