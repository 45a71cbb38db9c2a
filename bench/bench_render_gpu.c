/* GPU rasterizer and training-step benchmark (CUDA backend).
 *
 * Scenes are those of ../shared/bench/anchors/bench_gsplat.py so the figures compare with
 * gsplat's on the same machine: one pinhole camera at the origin looking down +z, fx = fy = W,
 * principal point at the centre; N Gaussians with z uniform in [2, 10] m, x, y uniform across
 * the frustum, per-axis sigma log-uniform in [0.5, 8] px, random unit quaternions, opacity 0.5,
 * D channels uniform in [0, 1].
 *   raster_fwd      projection + binning + sort + forward
 *   raster_fwd_bwd  the above + zeroing the gradients + backward to means, quats, scales,
 *                   opacities and colours with dL/dimage = 1 (gsplat: img.sum().backward())
 *   train_step      one full training step at 1M Gaussians 1920x1080: SH (degree 3) -> RGB,
 *                   [feature columns packed beside RGB], forward, L1+SSIM loss and gradient,
 *                   [feature MSE], backward, SH backward, densification statistics, Adam on
 *                   every parameter group (the loop src/train runs, minus host bookkeeping)
 *   views           inference renders of an uploaded scene (sp_scene, SH degree 1 + 16 features):
 *                   V views (RGB, features, expected depth, downloaded to the host) as one
 *                   sp_render_views batch and one view per call, in ms per view
 *   raster_stages   one extra profiled fwd+bwd (cfg.profile): per-stage device ms from events
 *                   (project, bin = depth order + pair counts + scan, sort = pair-count wait +
 *                   emission + tile sort, fwd, bwd = clearing + backward compositing,
 *                   project_bwd) and pairs per Gaussian
 * Median of 20 runs after 5 warm-ups, synchronised. Peak memory is what semsplat allocated on
 * the GPU (sp_device_peak_bytes of the CUDA device), measured per case in a child process so cases do not mix;
 * "extra" excludes the Gaussian parameters, as gsplat's anchor does.
 *
 * Usage: bench_render_gpu                 all cases (each in a child process)
 *        bench_render_gpu raster N W H D [B [P [F [C]]]]  one rasterizer case (B: cfg.bwd_gather, 0;
 *                                          -1 reduce-scatter, 1 gather, 2 tensor cores; P:
 *                                          cfg.bwd_px, 0; 2 two pixels per thread for chunks
 *                                          up to 8 channels; F: cfg.fwd_px, 0, the same for the
 *                                          forward; C: cfg.warp_cull, 0, -1 off;
 *                                          the lines say which backward kernel ran,
 *                                          bwd=..., and the forward's pixels per thread, fpx=...)
 *        bench_render_gpu step F          one training step case with F feature channels
 *        bench_render_gpu views N W H V   one inference-batch case */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "semsplat/render.h"
#include "train/train_kernels.h"

#define WARM 5
#define REPS 20

static sp_error g_err;
static sp_device *g_dev;     /* the CUDA device */
static const tr_kernels *K; /* its training kernels */
#define OK(call)                                                                            \
    do {                                                                                    \
        if ((call) != 0) {                                                                  \
            fprintf(stderr, "bench_render_gpu: %s failed: %s\n", #call, g_err.msg);        \
            exit(1);                                                                        \
        }                                                                                   \
    } while (0)

static uint64_t rs = 12345;
static float frand(void)
{
    rs ^= rs << 13;
    rs ^= rs >> 7;
    rs ^= rs << 17;
    return (float)((rs >> 40) & 0xffffff) / 16777216.0f;
}
static float nrand(void)
{
    float u = frand() + 1e-7f, v = frand();
    return sqrtf(-2.f * logf(u)) * cosf(6.2831853f * v);
}

static void *dalloc(size_t bytes)
{
    void *p = sp_device_alloc(g_dev, bytes, &g_err);
    if (!p) {
        fprintf(stderr, "bench_render_gpu: %s\n", g_err.msg);
        exit(1);
    }
    return p;
}
static void *dup_host(const void *h, size_t bytes)
{
    void *d = dalloc(bytes);
    OK(sp_device_upload(g_dev, d, h, bytes, &g_err));
    return d;
}

typedef struct {
    size_t n;
    int W, H, D;
    sp_camera cam;
    float *means, *quats, *log_scales, *opac, *colors; /* device */
} bscene;

static bscene make_scene(size_t n, int W, int H, int D)
{
    bscene s;
    memset(&s, 0, sizeof s);
    s.n = n, s.W = W, s.H = H, s.D = D;
    s.cam.width = W, s.cam.height = H;
    s.cam.fx = s.cam.fy = (float)W;
    s.cam.cx = W / 2.f, s.cam.cy = H / 2.f;
    s.cam.R[0] = s.cam.R[4] = s.cam.R[8] = 1.f;
    float *m = malloc(n * 12), *q = malloc(n * 16), *ls = malloc(n * 12), *o = malloc(n * 4);
    float *c = malloc(n * (size_t)D * 4);
    for (size_t i = 0; i < n; i++) {
        float z = 2.f + 8.f * frand();
        m[i * 3] = (frand() * 2 - 1) * z * (W / 2.f) / s.cam.fx;
        m[i * 3 + 1] = (frand() * 2 - 1) * z * (H / 2.f) / s.cam.fy;
        m[i * 3 + 2] = z;
        for (int k = 0; k < 3; k++) {
            float sigma_px = expf(logf(0.5f) + frand() * (logf(8.f) - logf(0.5f)));
            ls[i * 3 + k] = logf(sigma_px * z / s.cam.fx);
        }
        float qq[4], nn = 0;
        for (int k = 0; k < 4; k++) qq[k] = nrand(), nn += qq[k] * qq[k];
        for (int k = 0; k < 4; k++) q[i * 4 + k] = qq[k] / sqrtf(nn);
        o[i] = 0.f; /* sigmoid(0) = 0.5 */
    }
    for (size_t i = 0; i < n * (size_t)D; i++) c[i] = frand();
    s.means = dup_host(m, n * 12), s.quats = dup_host(q, n * 16);
    s.log_scales = dup_host(ls, n * 12), s.opac = dup_host(o, n * 4);
    s.colors = dup_host(c, n * (size_t)D * 4);
    free(m), free(q), free(ls), free(o), free(c);
    return s;
}

static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

typedef void (*bench_fn)(void *ctx);
static double time_ms(bench_fn fn, void *ctx)
{
    double t[REPS];
    for (int i = 0; i < WARM; i++) fn(ctx);
    OK(sp_device_sync(g_dev, &g_err));
    for (int i = 0; i < REPS; i++) {
        double t0 = sp_time_now();
        fn(ctx);
        OK(sp_device_sync(g_dev, &g_err));
        t[i] = (sp_time_now() - t0) * 1e3;
    }
    qsort(t, REPS, sizeof(double), cmp_d);
    return t[REPS / 2];
}

/* ---- rasterizer cases ---------------------------------------------------------------------- */

typedef struct {
    bscene *s;
    sp_raster *r;
    sp_raster_cfg cfg;
    sp_raster_in in;
    sp_raster_out out;
    sp_raster_grad_in gin;
    sp_raster_grads g;
    float *gbuf;
    size_t gbytes;
} rctx;

static void run_fwd(void *p)
{
    rctx *c = p;
    OK(sp_raster_forward(c->r, &c->s->cam, &c->cfg, &c->in, &c->out, &g_err));
}
static void run_fwd_bwd(void *p)
{
    rctx *c = p;
    run_fwd(p);
    OK(sp_device_zero(g_dev, c->gbuf, c->gbytes, &g_err));
    OK(sp_raster_backward(c->r, &c->gin, &c->g, &g_err));
}

static void case_raster(size_t n, int W, int H, int D, int block_sums, int bwd_px, int fwd_px, int cull,
                        const char *gpu)
{
    bscene s = make_scene(n, W, H, D);
    size_t params = sp_device_peak_bytes(g_dev);
    rctx c;
    memset(&c, 0, sizeof c);
    c.s = &s;
    OK(sp_raster_create(&c.r, g_dev, &g_err));
    c.cfg = sp_raster_cfg_default();
    c.cfg.bwd_gather = block_sums;
    c.cfg.bwd_px = bwd_px;
    c.cfg.fwd_px = fwd_px;
    c.cfg.warp_cull = cull;
    c.in = (sp_raster_in){n, s.means, s.quats, s.log_scales, s.opac, s.colors, D, NULL};
    size_t npix = (size_t)W * H;
    c.out.image = dalloc(npix * D * 4);
    float *ones = malloc(npix * D * 4);
    for (size_t i = 0; i < npix * (size_t)D; i++) ones[i] = 1.f;
    c.gin.v_image = dup_host(ones, npix * D * 4);
    free(ones);
    c.gbytes = n * (3 + 4 + 3 + 1 + (size_t)D + 2) * 4;
    c.gbuf = dalloc(c.gbytes);
    c.g = (sp_raster_grads){c.gbuf, c.gbuf + 3 * n, c.gbuf + 7 * n, c.gbuf + 10 * n,
                            c.gbuf + 11 * n, c.gbuf + (11 + D) * n};
    double f = time_ms(run_fwd, &c);
    size_t pairs = sp_raster_last_pairs(c.r);
    double fb = time_ms(run_fwd_bwd, &c);
    double peak = sp_device_peak_bytes(g_dev) / 1073741824.0;
    double extra = (sp_device_peak_bytes(g_dev) - params) / 1073741824.0;
    /* one more profiled forward + backward: where the time goes (events between the stages) */
    sp_raster_stages st;
    c.cfg.profile = 1;
    run_fwd_bwd(&c);
    OK(sp_raster_last_stages(c.r, &st, &g_err));
    c.cfg.profile = 0;
    char set[384], mode[64] = "";
    if (block_sums || bwd_px || fwd_px || cull)
        snprintf(mode, sizeof mode, " bwd_gather=%d bwd_px=%d fwd_px=%d warp_cull=%d", block_sums,
                 bwd_px, fwd_px, cull);
    /* the kernel that ran (a mode falls back where its kernel does not fit the GPU or width) */
    snprintf(set, sizeof set, "(n=%zu %dx%d D=%d pairs=%zu%s bwd=%s fpx=%d, %s)", n, W, H, D, pairs, mode,
             st.bwd_kernel ? st.bwd_kernel : "?", st.fwd_px, gpu);
    printf("raster_fwd_ms       %8.3f  ms   %s\n", f, set);
    printf("raster_fwd_bwd_ms   %8.3f  ms   %s\n", fb, set);
    printf("raster_peak_gib     %8.3f  GiB  %s extra over params %.3f GiB\n", peak, set, extra);
    printf("raster_stages_ms    %8.3f  ms   (D=%d: project %.3f bin %.3f sort %.3f fwd %.3f "
           "bwd %.3f project_bwd %.3f; pairs/Gaussian %.3f)\n",
           st.project + st.bin + st.sort + st.raster_fwd + st.raster_bwd + st.project_bwd, D,
           st.project, st.bin, st.sort, st.raster_fwd, st.raster_bwd, st.project_bwd,
           (double)pairs / (double)n);
    printf("JSON {\"what\":\"semsplat\",\"n\":%zu,\"w\":%d,\"h\":%d,\"d\":%d,\"fwd_ms\":%.3f,"
           "\"fwd_bwd_ms\":%.3f,\"peak_gib\":%.3f}\n", n, W, H, D, f, fb, extra);
    fflush(stdout);
}

/* ---- training step ------------------------------------------------------------------------- */

typedef struct {
    bscene *s;
    sp_raster *r;
    sp_raster_cfg cfg;
    int F, Dt, deg;
    float *sh, *feat;           /* params beside s's */
    float *grad, *m, *v;        /* one block each for every group, same layout as params */
    size_t group_off[7], total; /* means quats scales opac sh feat | end */
    float *params;
    float *colors, *image, *v_image, *target, *ftarget, *scratch;
    float *grad2d, *count;
    int step;
} sctx;

static void run_step(void *p)
{
    sctx *c = p;
    size_t n = c->s->n;
    int W = c->s->W, H = c->s->H;
    sp_vec3 cc = {0, 0, 0};
    float *g = c->grad;
    OK(sp_device_zero(g_dev, g, c->total * 4, &g_err));
    OK(sp_sh_to_rgb(g_dev, n, 3, c->deg, c->sh, c->s->means, cc, c->colors, c->Dt, &g_err));
    if (c->F) OK(K->copy_columns(g_dev, c->colors, c->Dt, 3, c->feat, c->F, 0, n, c->F, &g_err));
    sp_raster_in in = {n, c->s->means, c->s->quats, c->s->log_scales, c->s->opac, c->colors,
                       c->Dt, NULL};
    sp_raster_out out = {c->image, NULL, NULL, NULL};
    OK(sp_raster_forward(c->r, &c->s->cam, &c->cfg, &in, &out, &g_err));
    double st[4], mse;
    OK(K->rgb_loss(g_dev, c->image, c->Dt, c->target, H, W, 3, 0.2f, c->scratch, c->v_image, st,
                        &g_err));
    if (c->F)
        OK(K->feature_mse(g_dev, c->image, c->Dt, 3, c->ftarget, H, W, c->F, 1.f, c->v_image, &mse,
                               &g_err));
    /* v_colors lands in the scratch-free tail of the gradient block (see case_step) */
    float *v_colors = g + c->total;
    float *v_means2d = v_colors + n * (size_t)c->Dt;
    OK(sp_device_zero(g_dev, v_colors, n * ((size_t)c->Dt + 2) * 4, &g_err));
    sp_raster_grads gr = {g + c->group_off[0], g + c->group_off[1], g + c->group_off[2],
                          g + c->group_off[3], v_colors, v_means2d};
    sp_raster_grad_in gin = {c->v_image, NULL, NULL};
    OK(sp_raster_backward(c->r, &gin, &gr, &g_err));
    OK(sp_sh_to_rgb_backward(g_dev, n, 3, c->deg, c->sh, c->s->means, cc, c->colors, v_colors, c->Dt,
                                  g + c->group_off[4], g + c->group_off[0], &g_err));
    if (c->F)
        OK(K->copy_columns(g_dev, g + c->group_off[5], c->F, 0, v_colors, c->Dt, 3, n, c->F, &g_err));
    OK(K->densify_accumulate(g_dev, v_means2d, sp_raster_radii(c->r), n, W / 2.f, H / 2.f,
                                  c->grad2d, c->count, &g_err));
    c->step++;
    static const float lr[6] = {1.6e-4f, 1e-3f, 5e-3f, 5e-2f, 2.5e-3f, 2.5e-3f};
    for (int k = 0; k < 6; k++) {
        size_t a = c->group_off[k], b = c->group_off[k + 1];
        if (b > a)
            OK(K->adam_step(g_dev, c->params + a, g + a, c->m + a, c->v + a, b - a, lr[k], 0.9f,
                                 0.999f, 1e-15f, c->step, &g_err));
    }
}

static void case_step(int F, const char *gpu)
{
    size_t n = 1000000;
    int W = 1920, H = 1080, K = 16;
    /* parameters in one block so Adam can address groups by offset */
    bscene s = make_scene(n, W, H, 1);
    sctx c;
    memset(&c, 0, sizeof c);
    c.s = &s;
    c.F = F, c.Dt = 3 + F, c.deg = 3;
    size_t sz[6] = {3 * n, 4 * n, 3 * n, n, (size_t)K * 3 * n, (size_t)F * n};
    c.group_off[0] = 0;
    for (int k = 0; k < 6; k++) c.group_off[k + 1] = c.group_off[k] + sz[k];
    c.total = c.group_off[6];
    c.params = dalloc(c.total * 4);
    OK(sp_device_copy(g_dev, c.params, s.means, sz[0] * 4, &g_err));
    OK(sp_device_copy(g_dev, c.params + c.group_off[1], s.quats, sz[1] * 4, &g_err));
    OK(sp_device_copy(g_dev, c.params + c.group_off[2], s.log_scales, sz[2] * 4, &g_err));
    OK(sp_device_copy(g_dev, c.params + c.group_off[3], s.opac, sz[3] * 4, &g_err));
    float *h = malloc(((size_t)K * 3 + F) * n * 4);
    for (size_t i = 0; i < (size_t)K * 3 * n; i++) h[i] = (i % (K * 3) < 3) ? nrand() : 0.05f * nrand();
    OK(sp_device_upload(g_dev, c.params + c.group_off[4], h, sz[4] * 4, &g_err));
    for (size_t i = 0; i < (size_t)F * n; i++) h[i] = frand();
    if (F) OK(sp_device_upload(g_dev, c.params + c.group_off[5], h, sz[5] * 4, &g_err));
    free(h);
    sp_device_release(g_dev, s.means), sp_device_release(g_dev, s.quats), sp_device_release(g_dev, s.log_scales);
    sp_device_release(g_dev, s.opac), sp_device_release(g_dev, s.colors);
    s.means = c.params, s.quats = c.params + c.group_off[1];
    s.log_scales = c.params + c.group_off[2], s.opac = c.params + c.group_off[3];
    c.sh = c.params + c.group_off[4], c.feat = c.params + c.group_off[5];
    size_t params = c.total * 4;
    size_t base = sp_device_peak_bytes(g_dev);

    c.grad = dalloc((c.total + n * ((size_t)c.Dt + 2)) * 4);
    c.m = dalloc(c.total * 4), c.v = dalloc(c.total * 4);
    size_t npix = (size_t)W * H;
    c.colors = dalloc(n * c.Dt * 4);
    c.image = dalloc(npix * c.Dt * 4), c.v_image = dalloc(npix * c.Dt * 4);
    float *t = malloc(npix * (size_t)(3 + F) * 4);
    for (size_t i = 0; i < npix * (size_t)(3 + F); i++) t[i] = frand();
    c.target = dup_host(t, npix * 3 * 4);
    if (F) c.ftarget = dup_host(t + npix * 3, npix * (size_t)F * 4);
    free(t);
    c.scratch = dalloc(SP_LOSS_SCRATCH_FLOATS(H, W, 3) * 4);
    c.grad2d = dalloc(n * 4), c.count = dalloc(n * 4);
    OK(sp_raster_create(&c.r, g_dev, &g_err));
    c.cfg = sp_raster_cfg_default();
    double ms = time_ms(run_step, &c);
    double peak = sp_device_peak_bytes(g_dev) / 1073741824.0;
    char set[200];
    snprintf(set, sizeof set,
             "(n=1M 1920x1080 RGB from SH deg 3%s%s, L1+SSIM, Adam on all groups, pairs=%zu, %s)",
             F ? " + features packed, D=" : "", F ? (F == 32 ? "35" : "67") : "",
             sp_raster_last_pairs(c.r), gpu);
    printf("train_step_ms_F%-3d  %8.3f  ms   %s\n", F, ms, set);
    printf("train_step_peak_gib %8.3f  GiB  (F=%d; params %.3f GiB, everything else %.3f GiB)\n",
           peak, F, params / 1073741824.0, (sp_device_peak_bytes(g_dev) - base) / 1073741824.0);
    fflush(stdout);
}

/* ---- inference batches --------------------------------------------------------------------- */

typedef struct {
    sp_raster *r;
    sp_scene *sc;
    const sp_camera *cams;
    const sp_render_request *reqs;
    int nv, batch;
} vctx;

static void run_views(void *p)
{
    vctx *c = p;
    if (c->batch) {
        OK(sp_render_views(c->r, c->sc, c->cams, (size_t)c->nv, c->reqs, &g_err));
        return;
    }
    for (int v = 0; v < c->nv; v++) OK(sp_render_views(c->r, c->sc, &c->cams[v], 1, &c->reqs[v], &g_err));
}

static void case_views(size_t n, int W, int H, int nv, const char *gpu)
{
    enum { F = 16 };
    sp_camera cam;
    memset(&cam, 0, sizeof cam);
    sp_camera_intrinsics_fov(&cam, W, H, 1.0f);
    sp_splat s;
    OK(sp_splat_alloc(&s, n, 1, F, &g_err));
    for (size_t i = 0; i < n; i++) { /* the raster cases' distribution, before the camera */
        float z = 2.f + 8.f * frand();
        s.means[i * 3] = (frand() * 2 - 1) * z * (W / 2.f) / cam.fx;
        s.means[i * 3 + 1] = (frand() * 2 - 1) * z * (H / 2.f) / cam.fy;
        s.means[i * 3 + 2] = z;
        for (int k = 0; k < 3; k++)
            s.log_scales[i * 3 + k] = logf(expf(logf(0.5f) + frand() * (logf(8.f) - logf(0.5f))) * z / cam.fx);
        for (int k = 0; k < 4; k++) s.quats[i * 4 + k] = nrand();
    }
    for (size_t i = 0; i < n * 12; i++) s.sh[i] = 0.3f * nrand();
    for (size_t i = 0; i < n * F; i++) s.features[i] = frand();
    sp_raster *r = NULL;
    sp_scene *sc = NULL;
    OK(sp_raster_create(&r, g_dev, &g_err));
    OK(sp_scene_create(&sc, g_dev, &s, SP_SCENE_RGB | SP_SCENE_FEATURES, &g_err));
    sp_camera *cams = malloc(sizeof *cams * nv);
    sp_render_request *reqs = calloc(nv, sizeof *reqs);
    size_t npix = (size_t)W * H;
    for (int v = 0; v < nv; v++) { /* small turns about the image's y axis */
        cams[v] = cam;
        float a = 0.2f * (v - nv / 2) / (float)nv, ca = cosf(a), sa = sinf(a);
        float R[9] = {ca, 0, -sa, 0, 1, 0, sa, 0, ca};
        memcpy(cams[v].R, R, sizeof R);
        reqs[v].rgb = malloc(npix * 3 * 4);
        reqs[v].features = malloc(npix * F * 4);
        reqs[v].depth = malloc(npix * 4);
    }
    vctx c = {r, sc, cams, reqs, nv, 1};
    double batch = time_ms(run_views, &c);
    c.batch = 0;
    double single = time_ms(run_views, &c);
    char set[200];
    snprintf(set, sizeof set, "(n=%zu %dx%d, %d views, RGB + %d features + depth to the host, %s)", n,
             W, H, nv, F, gpu);
    printf("views_batch_ms      %8.3f  ms/view %s\n", batch / nv, set);
    printf("views_single_ms     %8.3f  ms/view %s\n", single / nv, set);
    fflush(stdout);
    for (int v = 0; v < nv; v++)
        free(reqs[v].rgb), free(reqs[v].features), free(reqs[v].depth);
    free(reqs), free(cams);
    sp_scene_free(sc);
    sp_raster_free(r);
    sp_splat_free(&s);
}

static int run_child(char *const argv[])
{
    pid_t pid = fork();
    if (pid < 0) return -1;
    if (pid == 0) {
        execv("/proc/self/exe", argv);
        _exit(127);
    }
    int st = 0;
    waitpid(pid, &st, 0);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

int main(int argc, char **argv)
{
    K = tr_cuda_kernels();
    if (!K || !sp_cuda_available()) {
        printf("bench_render_gpu  skipped  (no CUDA GPU)\n");
        return 0;
    }
    /* each case in its own process with its own device, so peak memory does not mix */
    int is_raster = argc >= 6 && argc <= 10 && !strcmp(argv[1], "raster"), is_step = argc == 3 && !strcmp(argv[1], "step");
    int is_views = argc == 6 && !strcmp(argv[1], "views");
    if (is_raster || is_step || is_views) {
        OK(sp_device_create(&g_dev, SP_DEVICE_CUDA, 0, &g_err));
        char gpu[256];
        snprintf(gpu, sizeof gpu, "%s", sp_device_name(g_dev));
        if (is_raster)
            case_raster((size_t)atol(argv[2]), atoi(argv[3]), atoi(argv[4]), atoi(argv[5]),
                        argc >= 7 ? atoi(argv[6]) : 0, argc >= 8 ? atoi(argv[7]) : 0,
                        argc >= 9 ? atoi(argv[8]) : 0, argc == 10 ? atoi(argv[9]) : 0, gpu);
        else if (is_views) case_views((size_t)atol(argv[2]), atoi(argv[3]), atoi(argv[4]), atoi(argv[5]), gpu);
        else case_step(atoi(argv[2]), gpu);
        sp_device_free(g_dev);
        return 0;
    }
    static const char *cases[][4] = {{"100000", "640", "480", "3"},   {"100000", "1920", "1080", "3"},
                                     {"1000000", "1920", "1080", "3"}, {"3000000", "1920", "1080", "3"},
                                     {"1000000", "1920", "1080", "16"}, {"1000000", "1920", "1080", "32"},
                                     {"1000000", "1920", "1080", "64"}, {"300000", "640", "480", "32"}};
    int fails = 0;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char *a[] = {argv[0], "raster", (char *)cases[i][0], (char *)cases[i][1],
                     (char *)cases[i][2], (char *)cases[i][3], NULL};
        fails += run_child(a) != 0;
    }
    static const char *views[][4] = {{"300000", "320", "240", "16"}, {"1000000", "640", "480", "8"}};
    for (size_t i = 0; i < sizeof views / sizeof views[0]; i++) {
        char *a[] = {argv[0], "views", (char *)views[i][0], (char *)views[i][1], (char *)views[i][2],
                     (char *)views[i][3], NULL};
        fails += run_child(a) != 0;
    }
    static const char *feats[] = {"0", "32", "64"};
    for (int i = 0; i < 3; i++) {
        char *a[] = {argv[0], "step", (char *)feats[i], NULL};
        fails += run_child(a) != 0;
    }
    return fails ? 1 : 0;
}
