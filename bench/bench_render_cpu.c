/* CPU rasterizer benchmark: forward and backward milliseconds at 640x480 for 100k Gaussians with
 * D = 3 and D = 32, on the scene of shared/bench/anchors (camera at the origin looking down +z,
 * fx = fy = width, z uniform in [2, 10] m, x and y uniform across the frustum, per-axis sigma
 * log-uniform in [0.5, 8] px, random unit quaternions, opacity 0.5, channels uniform in [0, 1]).
 * Prints `name  value  unit  (settings)` lines; median of --reps runs after one warm-up.
 * usage: bench_render_cpu [--n N] [--width W --height H] [--threads T] [--reps R] [--d 3|32]
 *                        [--device cpu|cuda] [--box-tiles]
 * --box-tiles bins every Gaussian into all tiles of its bounding box (sp_raster_cfg.box_tiles),
 * without the exact ellipse-vs-tile culling, to measure what that culling saves. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "semsplat/render.h"

static unsigned long long rng_state = 0x9E3779B97F4A7C15ULL;
static double uniform(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 2685821657736338717ULL) >> 11) * (1.0 / 9007199254740992.0);
}
static double normal(void)
{
    double u = uniform(), v = uniform();
    return sqrt(-2.0 * log(u + 1e-300)) * cos(6.283185307179586 * v);
}

/* CPU seconds of the whole process (all threads): with other jobs on the machine, wall time is
 * noisy while this is not, and cpu / wall shows how well the threads were used. */
static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static int die(const sp_error *err)
{
    fprintf(stderr, "bench_render_cpu: %s\n", err->msg);
    return 1;
}

int main(int argc, char **argv)
{
    size_t n = 100000;
    int W = 640, H = 480, threads = 0, reps = 5, only_d = 0, box_tiles = 0;
    sp_device_kind kind = SP_DEVICE_CPU;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--n") && i + 1 < argc) n = (size_t)atol(argv[++i]);
        else if (!strcmp(argv[i], "--width") && i + 1 < argc) W = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--height") && i + 1 < argc) H = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--threads") && i + 1 < argc) threads = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--reps") && i + 1 < argc) reps = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--d") && i + 1 < argc) only_d = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--box-tiles")) box_tiles = 1;
        else if (!strcmp(argv[i], "--device") && i + 1 < argc) {
            i++;
            kind = !strcmp(argv[i], "cuda") ? SP_DEVICE_CUDA : SP_DEVICE_CPU;
        } else {
            fprintf(stderr, "usage: %s [--n N] [--width W] [--height H] [--threads T] [--reps R] "
                    "[--d 3|32] [--device cpu|cuda] [--box-tiles]\n", argv[0]);
            return 2;
        }
    }
    if (reps < 1) reps = 1;
    sp_error err = {0};
    sp_device *dev = NULL;
    if (sp_device_create(&dev, kind, threads, &err)) return die(&err);
    sp_raster *r = NULL;
    if (sp_raster_create(&r, dev, &err)) return die(&err);

    sp_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.width = W;
    cam.height = H;
    cam.fx = cam.fy = (float)W;
    cam.cx = 0.5f * W;
    cam.cy = 0.5f * H;
    cam.R[0] = cam.R[4] = cam.R[8] = 1.f;

    const int Ds[2] = {3, 32};
    int Dmax = 32;
    float *means = malloc(n * 3 * sizeof(float)), *quats = malloc(n * 4 * sizeof(float));
    float *ls = malloc(n * 3 * sizeof(float)), *op = malloc(n * sizeof(float));
    float *colors = malloc(n * Dmax * sizeof(float));
    for (size_t i = 0; i < n; i++) {
        double z = 2 + 8 * uniform();
        means[3 * i] = (float)((uniform() * 2 - 1) * z * (W / 2.0) / cam.fx);
        means[3 * i + 1] = (float)((uniform() * 2 - 1) * z * (H / 2.0) / cam.fy);
        means[3 * i + 2] = (float)z;
        for (int k = 0; k < 3; k++)
            ls[3 * i + k] = (float)log(exp(log(0.5) + uniform() * (log(8.0) - log(0.5))) * z / cam.fx);
        double q[4], qn = 0;
        for (int k = 0; k < 4; k++) q[k] = normal(), qn += q[k] * q[k];
        for (int k = 0; k < 4; k++) quats[4 * i + k] = (float)(q[k] / sqrt(qn));
        op[i] = 0.f; /* logit(0.5) */
    }
    for (size_t i = 0; i < n * (size_t)Dmax; i++) colors[i] = (float)uniform();

    size_t npix = (size_t)W * H;
    /* device buffers (plain host memory on the CPU device) */
    float *d_means = sp_device_alloc(dev, n * 3 * sizeof(float), &err);
    float *d_quats = sp_device_alloc(dev, n * 4 * sizeof(float), &err);
    float *d_ls = sp_device_alloc(dev, n * 3 * sizeof(float), &err);
    float *d_op = sp_device_alloc(dev, n * sizeof(float), &err);
    float *d_col = sp_device_alloc(dev, n * Dmax * sizeof(float), &err);
    float *d_img = sp_device_alloc(dev, npix * Dmax * sizeof(float), &err);
    float *d_vimg = sp_device_alloc(dev, npix * Dmax * sizeof(float), &err);
    float *d_grads = sp_device_alloc(dev, n * (3 + 4 + 3 + 1 + 2 + (size_t)Dmax) * sizeof(float), &err);
    if (!d_means || !d_quats || !d_ls || !d_op || !d_col || !d_img || !d_vimg || !d_grads) return die(&err);
    sp_device_upload(dev, d_means, means, n * 3 * sizeof(float), &err);
    sp_device_upload(dev, d_quats, quats, n * 4 * sizeof(float), &err);
    sp_device_upload(dev, d_ls, ls, n * 3 * sizeof(float), &err);
    sp_device_upload(dev, d_op, op, n * sizeof(float), &err);
    sp_device_upload(dev, d_col, colors, n * Dmax * sizeof(float), &err);
    float *ones = malloc(npix * Dmax * sizeof(float));
    for (size_t i = 0; i < npix * (size_t)Dmax; i++) ones[i] = 1.f; /* d(sum image)/d image */
    sp_device_upload(dev, d_vimg, ones, npix * Dmax * sizeof(float), &err);

    const char *devname = sp_device_name(dev);
    for (int t = 0; t < 2; t++) {
        int D = Ds[t];
        if (only_d && D != only_d) continue;
        sp_raster_cfg cfg = sp_raster_cfg_default();
        cfg.box_tiles = box_tiles;
        sp_raster_in in = {n, d_means, d_quats, d_ls, d_op, d_col, D, NULL};
        sp_raster_out out = {d_img, NULL, NULL, NULL};
        sp_raster_grad_in gin = {d_vimg, NULL, NULL};
        sp_raster_grads g = {d_grads, d_grads + 3 * n, d_grads + 7 * n, d_grads + 10 * n,
                             d_grads + 13 * n, d_grads + 11 * n};
        double *tf = malloc(reps * sizeof(double)), *tb = malloc(reps * sizeof(double));
        double *cf = malloc(reps * sizeof(double)), *cb = malloc(reps * sizeof(double));
        for (int rep = -1; rep < reps; rep++) {
            double c0 = cpu_now(), t0 = sp_time_now();
            if (sp_raster_forward(r, &cam, &cfg, &in, &out, &err)) return die(&err);
            if (sp_device_sync(dev, &err)) return die(&err);
            double c1 = cpu_now(), t1 = sp_time_now();
            if (sp_raster_backward(r, &gin, &g, &err)) return die(&err);
            if (sp_device_sync(dev, &err)) return die(&err);
            double c2 = cpu_now(), t2 = sp_time_now();
            if (rep >= 0) {
                tf[rep] = (t1 - t0) * 1e3, tb[rep] = (t2 - t1) * 1e3;
                cf[rep] = (c1 - c0) * 1e3, cb[rep] = (c2 - c1) * 1e3;
            }
        }
        qsort(tf, reps, sizeof *tf, cmp_double);
        qsort(tb, reps, sizeof *tb, cmp_double);
        qsort(cf, reps, sizeof *cf, cmp_double);
        qsort(cb, reps, sizeof *cb, cmp_double);
        printf("render_forward_D%d  %.2f  ms  (%zu Gaussians, %dx%d, %s, %zu tile pairs, median of %d, "
               "cpu time %.0f ms)\n", D, tf[reps / 2], n, W, H, devname, sp_raster_last_pairs(r), reps,
               cf[reps / 2]);
        printf("render_pairs_per_gaussian_D%d  %.3f  pairs  (%zu Gaussians, %dx%d, %s tiles)\n", D,
               (double)sp_raster_last_pairs(r) / (double)n, n, W, H,
               box_tiles ? "every bounding-box" : "ellipse-culled");
        printf("render_backward_D%d  %.2f  ms  (%zu Gaussians, %dx%d, %s, median of %d, cpu time %.0f ms)\n",
               D, tb[reps / 2], n, W, H, devname, reps, cb[reps / 2]);
        fflush(stdout);
        free(tf), free(tb), free(cf), free(cb);
    }
    printf("render_peak_memory  %.1f  MiB  (device allocations + rasterizer scratch, %s)\n",
           sp_device_peak_bytes(dev) / 1048576.0, devname);
    sp_raster_free(r);
    sp_device_release(dev, d_means), sp_device_release(dev, d_quats), sp_device_release(dev, d_ls);
    sp_device_release(dev, d_op), sp_device_release(dev, d_col), sp_device_release(dev, d_img);
    sp_device_release(dev, d_vimg), sp_device_release(dev, d_grads);
    sp_device_free(dev);
    free(means), free(quats), free(ls), free(op), free(colors), free(ones);
    return 0;
}
