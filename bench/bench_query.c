/* Query latency of the semantic engine with the text already embedded and the model loaded:
 * 3D-native and multi-view localization on a synthetic room of N Gaussians (default 300k) with
 * 32-dim features decoding to 512-D, 20 object classes, 24 cameras at 640x480. CPU always; the
 * GPU too when one answers, with the stage breakdown (sp_query_stages) of multi-view queries and
 * heatmaps. Then lift time for the same splat (150 views at 160x120, D = 32).
 * Usage: bench_query [N] [threads] [--no-lift] [--gpu-only] */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/clip.h"
#include "semsplat/render.h"
#include "semsplat/semantic.h"

enum { FULL = 512, DIM = 32, CLASSES = 20, NCAM = 24 };

static uint64_t rng = 0x9E3779B97F4A7C15ull;
static double uni(void)
{
    rng ^= rng >> 12, rng ^= rng << 25, rng ^= rng >> 27;
    return (double)((rng * 2685821657736338717ull) >> 11) / 9007199254740992.0;
}

static void build(size_t n, sp_splat *s, sp_sem_pca *pca, float *emb, sp_camera *cams)
{
    char name[32];
    for (int k = 0; k < CLASSES; k++) {
        snprintf(name, sizeof name, "class %d", k);
        sp_label_embedding(name, FULL, emb + (size_t)k * FULL);
    }
    pca->dim = DIM, pca->full_dim = FULL;
    pca->mean = calloc(FULL, sizeof(float));
    pca->basis = calloc((size_t)DIM * FULL, sizeof(float));
    for (int k = 0; k < CLASSES; k++)
        for (int j = 0; j < FULL; j++) pca->mean[j] += emb[(size_t)k * FULL + j] / CLASSES;
    /* Gram-Schmidt of class differences (the last one depends on the others: skipped), then
     * random rows: an orthonormal basis as sp_clip_pca_fit makes. */
    for (int r = 0, src = 0; r < DIM; src++) {
        float *row = pca->basis + (size_t)r * FULL;
        for (int j = 0; j < FULL; j++)
            row[j] = src < CLASSES ? emb[(size_t)src * FULL + j] - pca->mean[j] : (float)(uni() - 0.5);
        for (int q = 0; q < r; q++) {
            double d = 0;
            for (int j = 0; j < FULL; j++) d += (double)row[j] * pca->basis[(size_t)q * FULL + j];
            for (int j = 0; j < FULL; j++) row[j] -= (float)(d * pca->basis[(size_t)q * FULL + j]);
        }
        double nn = 0;
        for (int j = 0; j < FULL; j++) nn += (double)row[j] * row[j];
        if (nn < 1e-6) continue;
        for (int j = 0; j < FULL; j++) row[j] /= (float)sqrt(nn);
        r++;
    }
    float centers[CLASSES][3];
    for (int k = 0; k < CLASSES; k++)
        centers[k][0] = (float)(uni() * 8 - 4), centers[k][1] = (float)(uni() * 6 - 3), centers[k][2] = (float)(uni() * 1.2);
    sp_error err = {0};
    sp_splat_alloc(s, n, 0, DIM, &err);
    float feat[CLASSES][DIM];
    for (int k = 0; k < CLASSES; k++)
        for (int r = 0; r < DIM; r++) {
            double d = 0;
            for (int j = 0; j < FULL; j++)
                d += (double)pca->basis[(size_t)r * FULL + j] * (emb[(size_t)k * FULL + j] - pca->mean[j]);
            feat[k][r] = (float)d;
        }
    for (size_t i = 0; i < n; i++) {
        /* 60% room shell (class 0: walls/floor), 40% objects */
        int k = uni() < 0.6 ? 0 : 1 + (int)(uni() * (CLASSES - 1));
        float *m = s->means + 3 * i;
        if (k == 0) { /* floor, or one of the four walls */
            double u = uni(), w = uni();
            int side = (int)(uni() * 6);
            if (side < 2) m[0] = (float)(u * 10 - 5), m[1] = (float)(w * 8 - 4), m[2] = 0;
            else if (side < 4) m[0] = side == 2 ? -5.f : 5.f, m[1] = (float)(u * 8 - 4), m[2] = (float)(w * 2.5);
            else m[0] = (float)(u * 10 - 5), m[1] = side == 4 ? -4.f : 4.f, m[2] = (float)(w * 2.5);
        } else {
            for (int a = 0; a < 3; a++) m[a] = centers[k][a] + (float)(uni() - 0.5) * 0.6f;
        }
        for (int a = 0; a < 3; a++) s->log_scales[3 * i + a] = logf(0.01f + 0.03f * (float)uni());
        s->opacity_logits[i] = (float)(uni() * 6 - 2);
        for (int c = 0; c < 3; c++) s->sh[3 * i + c] = (float)(uni() - 0.5);
        for (int r = 0; r < DIM; r++) s->features[i * DIM + r] = feat[k][r] + 0.05f * (float)(uni() - 0.5);
    }
    for (int c = 0; c < NCAM; c++) {
        double a = 2 * M_PI * c / NCAM;
        memset(&cams[c], 0, sizeof cams[c]);
        cams[c].width = 640, cams[c].height = 480, cams[c].fx = cams[c].fy = 500, cams[c].cx = 320, cams[c].cy = 240;
        sp_camera_look_at(&cams[c], sp_v3((float)(3.5 * cos(a)), (float)(2.5 * sin(a)), 1.2f), sp_v3(0, 0, 0.6f),
                          sp_v3(0, 0, 1));
    }
}

static void run(sp_device_kind kind, int threads, size_t n, const sp_splat *s, const sp_sem_pca *pca,
                const float *emb, const sp_camera *cams)
{
    sp_error err = {0};
    sp_device *dev = NULL;
    if (sp_device_create(&dev, kind, threads, &err)) {
        printf("# %s: %s\n", kind == SP_DEVICE_CUDA ? "cuda" : "cpu", err.msg);
        return;
    }
    sp_query_engine *e = NULL;
    sp_query_opts o = sp_query_opts_default();
    o.heatmap = 0;
    sp_query_model qm = {.splat = s, .pca = pca, .cams = cams, .n_cams = NCAM};
    if (sp_query_engine_create(&e, &qm, &o, dev, NULL, &err)) {
        printf("# engine: %s\n", err.msg);
        sp_device_free(dev);
        return;
    }
    const char *dn = sp_device_name(dev), *kn = kind == SP_DEVICE_CUDA ? "gpu" : "cpu";
    const int methods[2] = {SP_QUERY_3D, SP_QUERY_MULTIVIEW};
    for (int mi = 0; mi < 2; mi++) {
        o.method = methods[mi];
        int reps = mi == 0 ? 10 : 5;
        double best = 1e30, sum = 0, rel = 0;
        sp_query_stages st = {0};
        int found = 0, done = 0;
        long points = 0;
        for (int r = -1; r < reps; r++) { /* r = -1: warm-up (scene upload, occupancy grid) */
            sp_query_result res;
            int k = 1 + (r + 1) % (CLASSES - 1);
            if (sp_query_engine_query_embedding(e, emb + (size_t)k * FULL, "bench", &o, &res, &err)) {
                printf("# query: %s\n", err.msg);
                break;
            }
            if (r >= 0) {
                found += res.valid;
                sum += res.ms_total;
                rel += res.ms_relevancy;
                if (res.ms_total < best) best = res.ms_total;
                st.pick += res.ms_stage.pick, st.render += res.ms_stage.render;
                st.score += res.ms_stage.score, st.backproject += res.ms_stage.backproject;
                st.cluster += res.ms_stage.cluster;
                for (int q = 0; q < res.n_instances; q++) points += res.instances[q].n_points;
                done++;
            }
            sp_query_result_free(&res);
        }
        if (!done) continue;
        printf("query_%s_%s  %.1f  ms  (mean of %d after a warm-up; best %.1f ms; relevancy %.1f ms; %zu Gaussians, D=%d->%d, %s, %d/%d found)\n",
               mi == 0 ? "3d" : "multiview", kn, sum / done, done, best, rel / done, n, DIM, FULL, dn, found, done);
        if (mi == 1)
            printf("query_multiview_%s_stages  pick %.2f render %.2f score %.2f backproject %.2f cluster %.2f  ms  (means; %d views max, 1/%d resolution; %ld points in instances per query)\n",
                   kn, st.pick / done, st.render / done, st.score / done, st.backproject / done,
                   st.cluster / done, 3 * o.n_views, o.render_downscale, points / done);
    }
    /* heatmaps: a 640x480 render of RGB + scores, coloured; first through the best view of the
     * best instance (its choice included), then through a given view (the heatmap alone) */
    o.method = SP_QUERY_3D;
    o.heatmap = 1;
    for (int given = 0; given < 2; given++) {
        o.heatmap_view = given ? 0 : -1;
        sp_query_stages st = {0};
        double part = 0;
        int done = 0;
        for (int r = -1; r < 5; r++) {
            sp_query_result res;
            if (sp_query_engine_query_embedding(e, emb + FULL, "bench", &o, &res, &err)) {
                printf("# heatmap: %s\n", err.msg);
                break;
            }
            if (r >= 0) {
                part += res.ms_heatmap;
                st.hm_pick += res.ms_stage.hm_pick, st.hm_render += res.ms_stage.hm_render;
                st.hm_colormap += res.ms_stage.hm_colormap, st.hm_copy += res.ms_stage.hm_copy;
                done++;
            }
            sp_query_result_free(&res);
        }
        if (!done) continue;
        printf("heatmap_%s_%s  %.2f  ms  (mean of %d; pick %.2f render %.2f colourmap %.2f copy %.2f ms; 640x480, %s)\n",
               given ? "view" : "bestview", kn, part / done, done, st.hm_pick / done, st.hm_render / done,
               st.hm_colormap / done, st.hm_copy / done, dn);
    }
    o.heatmap_view = -1;
    sp_query_engine_free(e);
    sp_device_free(dev);
}

typedef struct {
    const float *maps;
    size_t stride;
} lift_maps;

static int lift_target(void *user, size_t view, float *target, uint8_t *mask, sp_error *err)
{
    (void)mask, (void)err;
    const lift_maps *m = user;
    memcpy(target, m->maps + (view % 8) * m->stride, sizeof(float) * m->stride);
    return 0;
}

/* Lift: 150 views at 160x120 (the label maps' resolution for 640x480 captures), D = 32. */
static void run_lift(sp_device_kind kind, int threads, const sp_splat *s0, const sp_camera *cams)
{
    sp_error err = {0};
    sp_device *dev = NULL;
    sp_raster *r = NULL;
    if (sp_device_create(&dev, kind, threads, &err) || sp_raster_create(&r, dev, &err)) {
        printf("# lift: %s\n", err.msg);
        sp_device_free(dev);
        return;
    }
    enum { V = 150, W = 160, H = 120 };
    sp_camera *lc = malloc(sizeof(sp_camera) * V);
    for (int v = 0; v < V; v++) {
        lc[v] = cams[v % NCAM];
        sp_camera_downscale(&lc[v], 4);
    }
    float *maps = malloc(sizeof(float) * 8 * W * H * DIM);
    for (size_t k = 0; k < (size_t)8 * W * H * DIM; k++) maps[k] = (float)(uni() - 0.5);
    lift_maps lm = {maps, (size_t)W * H * DIM};
    sp_splat s;
    sp_splat_copy(&s, s0, &err);
    double t0 = sp_time_now();
    int rc = sp_semantic_lift(r, &s, DIM, lc, V, lift_target, &lm, NULL, NULL, NULL, &err);
    double dt = sp_time_now() - t0;
    if (rc) printf("# lift: %s\n", err.msg);
    else
        printf("lift_%s  %.2f  s  (%zu Gaussians, %d views %dx%d, D=%d, %s)\n",
               kind == SP_DEVICE_CUDA ? "gpu" : "cpu", dt, s.n, V, W, H, DIM, sp_device_name(dev));
    sp_splat_free(&s);
    free(maps), free(lc);
    sp_raster_free(r);
    sp_device_free(dev);
}

int main(int argc, char **argv)
{
    size_t n = argc > 1 ? (size_t)atol(argv[1]) : 300000;
    int threads = argc > 2 ? atoi(argv[2]) : 0;
    sp_splat s;
    sp_sem_pca pca;
    float *emb = malloc(sizeof(float) * CLASSES * FULL);
    sp_camera cams[NCAM];
    build(n, &s, &pca, emb, cams);
    int lift = 1, cpu = 1;
    for (int a = 3; a < argc; a++) {
        if (!strcmp(argv[a], "--no-lift")) lift = 0;
        else if (!strcmp(argv[a], "--gpu-only")) cpu = 0;
    }
    if (cpu) run(SP_DEVICE_CPU, threads, n, &s, &pca, emb, cams);
    if (sp_cuda_available()) run(SP_DEVICE_CUDA, threads, n, &s, &pca, emb, cams);
    else printf("# gpu: no CUDA device, GPU figures skipped\n");
    if (lift && sp_cuda_available()) run_lift(SP_DEVICE_CUDA, threads, &s, cams);
    if (lift && cpu) run_lift(SP_DEVICE_CPU, threads, &s, cams);
    sp_splat_free(&s);
    sp_sem_pca_free(&pca);
    free(emb);
    return 0;
}
