/* CPU training throughput: steps per second of the full training step (SH -> rasterize ->
 * L1+SSIM -> backward -> Adam) on a 320x240 capture made in memory (random Gaussians seen from a
 * ring of cameras), densification off so the count stays fixed.
 * usage: bench_train_cpu [gaussians (default 50000)] [steps (default 40)] [threads (0 = all)] */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

#include "semsplat/render.h"
#include "semsplat/train.h"

static double urand(uint64_t *s)
{
    *s ^= *s >> 12, *s ^= *s << 25, *s ^= *s >> 27;
    return (double)((*s * 2685821657736338717ULL) >> 11) * (1.0 / 9007199254740992.0);
}

/* CPU seconds of this process (all threads), for a figure that load on a shared machine moves
 * less than wall time. */
static double cpu_seconds(void)
{
    struct rusage u;
    getrusage(RUSAGE_SELF, &u);
    return (double)u.ru_utime.tv_sec + 1e-6 * u.ru_utime.tv_usec + (double)u.ru_stime.tv_sec +
           1e-6 * u.ru_stime.tv_usec;
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
    /* the ground truth's views: one scene, all views in one call */
    float *img = malloc(sizeof(float) * W * H * 3 * NV);
    sp_camera cams[NV];
    sp_render_request reqs[NV];
    for (int k = 0; k < NV; k++) {
        sp_camera *c = &cams[k];
        memset(c, 0, sizeof *c);
        c->width = W, c->height = H, c->fx = c->fy = 250, c->cx = W / 2.0f, c->cy = H / 2.0f;
        double a = 6.2831853 * k / NV;
        sp_camera_look_at(c, sp_v3((float)(5 * cos(a)), (float)(5 * sin(a)), 1), sp_v3(0, 0, 0),
                          sp_v3(0, 0, 1));
        reqs[k] = (sp_render_request){.rgb = img + (size_t)k * W * H * 3};
    }
    sp_scene *scene = NULL;
    if (sp_scene_create(&scene, dev, &gt, SP_SCENE_RGB, &err) ||
        sp_render_views(r, scene, cams, NV, reqs, &err)) {
        fprintf(stderr, "bench_train_cpu: %s\n", err.msg);
        return 1;
    }
    sp_scene_free(scene);
    for (int k = 0; k < NV; k++) {
        sp_train_view *v = &d.views[k];
        snprintf(v->name, sizeof v->name, "%02d.png", k);
        v->cam = cams[k];
        v->rgb = malloc(W * H * 3);
        const float *im = reqs[k].rgb;
        for (int p = 0; p < W * H * 3; p++) {
            float x = im[p] < 0 ? 0 : im[p] > 1 ? 1 : im[p];
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
    double t0 = sp_time_now(), c0 = cpu_seconds();
    if (sp_train_run(dev, &d, &o, &s, &res, NULL, &err)) {
        fprintf(stderr, "bench_train_cpu: %s\n", err.msg);
        return 1;
    }
    double dt = sp_time_now() - t0, cpu = cpu_seconds() - c0;
    /* res.seconds includes the final held-out evaluation of one view; report the loop rate */
    printf("train_cpu_steps_per_s  %.2f  steps/s  (%dx%d, %zu gaussians, SH 3, %d steps, %s)\n",
           steps / dt, W, H, n, steps, sp_device_name(dev));
    printf("train_cpu_ms_per_step  %.1f  ms  (same; cpu time %.0f ms per step, all threads)\n",
           1000.0 * dt / steps, 1000.0 * cpu / steps);
    sp_splat_free(&gt);
    sp_splat_free(&s);
    sp_train_data_free(&d);
    sp_raster_free(r);
    sp_device_free(dev);
    return 0;
}
