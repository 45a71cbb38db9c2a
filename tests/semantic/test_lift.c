/* Lifting: the per-Gaussian average sum_p w_ip t_p / sum_p w_ip taken from the rasterizer's
 * backward must equal a naive double-precision computation of the compositing weights (EWA
 * projection, depth order, 3DGS alpha rules) on a small scene with occlusion; label maps rendered
 * from a labelled scene lift back to the right class features. */
#include <math.h>
#include <stdlib.h>

#include "scene.h"
#include "semsplat/render.h"
#include "semsplat/semantic.h"
#include "test.h"

/* Naive weights: for every pixel, every Gaussian in depth order, w = alpha * T. */
static void naive_accumulate(const sp_splat *s, const sp_camera *cam, const float *target, int D,
                             double *num, double *den)
{
    size_t n = s->n;
    double *z = malloc(sizeof(double) * n), *u = malloc(sizeof(double) * n),
           *v = malloc(sizeof(double) * n), *con = malloc(sizeof(double) * 3 * n),
           *op = malloc(sizeof(double) * n);
    size_t *ord = malloc(sizeof(size_t) * n);
    for (size_t i = 0; i < n; i++) {
        const float *m = s->means + 3 * i;
        double x[3];
        for (int a = 0; a < 3; a++)
            x[a] = cam->R[a * 3] * m[0] + cam->R[a * 3 + 1] * m[1] + cam->R[a * 3 + 2] * m[2] + cam->t[a];
        z[i] = x[2];
        u[i] = cam->fx * x[0] / x[2] + cam->cx;
        v[i] = cam->fy * x[1] / x[2] + cam->cy;
        float Rq[9];
        sp_quat_to_mat3(s->quats + 4 * i, Rq);
        double S[3], Sig[9], W[9], cw[9], J[6];
        for (int a = 0; a < 3; a++) S[a] = exp(2.0 * s->log_scales[3 * i + a]);
        for (int a = 0; a < 3; a++) /* world covariance R S^2 R^T */
            for (int b = 0; b < 3; b++) {
                double acc = 0;
                for (int k = 0; k < 3; k++) acc += Rq[a * 3 + k] * S[k] * Rq[b * 3 + k];
                Sig[a * 3 + b] = acc;
            }
        for (int k = 0; k < 9; k++) W[k] = cam->R[k];
        for (int a = 0; a < 3; a++) /* camera covariance W Sig W^T */
            for (int b = 0; b < 3; b++) {
                double acc = 0;
                for (int k = 0; k < 3; k++)
                    for (int l = 0; l < 3; l++) acc += W[a * 3 + k] * Sig[k * 3 + l] * W[b * 3 + l];
                cw[a * 3 + b] = acc;
            }
        J[0] = cam->fx / x[2], J[1] = 0, J[2] = -cam->fx * x[0] / (x[2] * x[2]);
        J[3] = 0, J[4] = cam->fy / x[2], J[5] = -cam->fy * x[1] / (x[2] * x[2]);
        double c2[4];
        for (int a = 0; a < 2; a++)
            for (int b = 0; b < 2; b++) {
                double acc = 0;
                for (int k = 0; k < 3; k++)
                    for (int l = 0; l < 3; l++) acc += J[a * 3 + k] * cw[k * 3 + l] * J[b * 3 + l];
                c2[a * 2 + b] = acc;
            }
        c2[0] += SP_EPS2D, c2[3] += SP_EPS2D;
        double det = c2[0] * c2[3] - c2[1] * c2[2];
        con[3 * i] = c2[3] / det, con[3 * i + 1] = -c2[1] / det, con[3 * i + 2] = c2[0] / det;
        op[i] = 1.0 / (1.0 + exp(-(double)s->opacity_logits[i]));
        ord[i] = i;
    }
    for (size_t a = 1; a < n; a++) { /* insertion sort by depth (stable) */
        size_t t = ord[a], b = a;
        while (b > 0 && z[ord[b - 1]] > z[t]) ord[b] = ord[b - 1], b--;
        ord[b] = t;
    }
    for (int py = 0; py < cam->height; py++)
        for (int px = 0; px < cam->width; px++) {
            double T = 1;
            const float *tp = target + ((size_t)py * cam->width + px) * D;
            for (size_t k = 0; k < n; k++) {
                size_t i = ord[k];
                if (z[i] < 0.01) continue;
                double dx = u[i] - (px + 0.5), dy = v[i] - (py + 0.5);
                double sig = 0.5 * (con[3 * i] * dx * dx + con[3 * i + 2] * dy * dy) + con[3 * i + 1] * dx * dy;
                if (sig < 0) continue;
                double al = fmin(SP_ALPHA_MAX, op[i] * exp(-sig));
                if (al < SP_ALPHA_MIN) continue;
                double nT = T * (1 - al);
                if (nT < SP_TRANSMITTANCE_MIN) break;
                double w = al * T;
                for (int c = 0; c < D; c++) num[i * D + c] += w * tp[c];
                den[i] += w;
                T = nT;
            }
        }
    free(z), free(u), free(v), free(con), free(op), free(ord);
}

typedef struct {
    const float *maps;
    size_t stride;
} map_ctx;

static int give_map(void *user, size_t view, float *target, uint8_t *mask, sp_error *err)
{
    (void)mask, (void)err;
    map_ctx *c = user;
    memcpy(target, c->maps + view * c->stride, sizeof(float) * c->stride);
    return 0;
}

static void test_lift_matches_naive_weights(void)
{
    test_rng r = {31};
    sp_splat s;
    sp_error err = {0};
    enum { N = 90, D = 5, V = 3, W = 48, H = 40 };
    CHECK_OK(sp_splat_alloc(&s, N, 0, 0, &err), &err);
    for (size_t i = 0; i < N; i++) { /* three overlapping clusters at different depths */
        int c = (int)(i % 3);
        s.means[3 * i] = (float)(c * 0.35 - 0.35 + test_range(&r, -0.25, 0.25));
        s.means[3 * i + 1] = (float)test_range(&r, -0.3, 0.3);
        s.means[3 * i + 2] = (float)(c * 0.3 + test_range(&r, -0.1, 0.1));
        for (int a = 0; a < 3; a++) s.log_scales[3 * i + a] = (float)log(test_range(&r, 0.03, 0.12));
        for (int a = 0; a < 4; a++) s.quats[4 * i + a] = (float)test_range(&r, -1, 1);
        s.opacity_logits[i] = (float)test_range(&r, -1.5, 3);
    }
    sp_camera cams[V];
    for (int v = 0; v < V; v++) {
        memset(&cams[v], 0, sizeof cams[v]);
        cams[v].width = W, cams[v].height = H, cams[v].fx = cams[v].fy = 50, cams[v].cx = 24, cams[v].cy = 20;
        sp_camera_look_at(&cams[v], sp_v3(0.3f * (v - 1), 0.2f * (v - 1), -3.0f), sp_v3(0, 0, 0.3f), sp_v3(0, -1, 0));
    }
    float *maps = malloc(sizeof(float) * V * W * H * D);
    for (size_t k = 0; k < (size_t)V * W * H * D; k++) maps[k] = (float)test_range(&r, -1, 1);
    double *num = calloc(N * D, sizeof(double)), *den = calloc(N, sizeof(double));
    for (int v = 0; v < V; v++) naive_accumulate(&s, &cams[v], maps + (size_t)v * W * H * D, D, num, den);

    sp_device *dev = NULL;
    sp_raster *rast = NULL;
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CPU, 2, &err), &err);
    CHECK_OK(sp_raster_create(&rast, dev, &err), &err);
    float wsum[N];
    map_ctx ctx = {maps, (size_t)W * H * D};
    CHECK_OK(sp_semantic_lift(rast, &s, D, cams, V, give_map, &ctx, NULL, wsum, NULL, &err), &err);
    CHECK(s.feat_dim == D);
    double worst_w = 0, worst_f = 0;
    int seen = 0;
    for (size_t i = 0; i < N; i++) {
        worst_w = fmax(worst_w, fabs(wsum[i] - den[i]) / (1 + den[i]));
        if (den[i] < 1e-3) continue;
        seen++;
        for (int c = 0; c < D; c++) worst_f = fmax(worst_f, fabs(s.features[i * D + c] - num[i * D + c] / den[i]));
    }
    CHECK(seen > N / 2);
    CHECK_NEAR(worst_w, 0, 2e-4);
    CHECK_NEAR(worst_f, 0, 2e-4);

    /* bad input */
    CHECK_FAILS(sp_semantic_lift(rast, &s, 0, cams, V, give_map, &ctx, NULL, NULL, NULL, &err), SP_E_ARG, &err, "dim");
    CHECK_FAILS(sp_semantic_lift(rast, &s, D, cams, 0, give_map, &ctx, NULL, NULL, NULL, &err), SP_E_ARG, &err, "no views");
    sp_raster_free(rast);
    sp_device_free(dev);
    sp_splat_free(&s);
    free(maps), free(num), free(den);
}

/* Renders the labelled scene's features from each camera (the "label maps"), forgets the
 * features, lifts them back: every visible Gaussian gets its class's feature (within blending at
 * boundaries, where coarse maps blend neighbours), so nearly all decode closest to their class. */
static void test_lift_label_maps_roundtrip(void)
{
    float emb[SC_CLASSES][SC_FULL];
    sp_sem_pca pca;
    sc_make_pca(&pca, emb);
    sp_splat s;
    int *cls;
    sc_make_splat(&s, &cls, &pca, emb);
    enum { V = 10, W = 80, H = 60 };
    sp_camera cams[V];
    sc_make_cams(cams, V, W, H);
    sp_device *dev = NULL;
    sp_raster *rast = NULL;
    sp_error err = {0};
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CPU, 2, &err), &err);
    CHECK_OK(sp_raster_create(&rast, dev, &err), &err);
    float *maps = malloc(sizeof(float) * V * W * H * SC_DIM), *alpha = malloc(sizeof(float) * W * H);
    for (int v = 0; v < V; v++) {
        sp_render_request req = {.features = maps + (size_t)v * W * H * SC_DIM, .alpha = alpha};
        CHECK_OK(sp_render_splat(rast, &s, &cams[v], &req, &err), &err);
        for (int p = 0; p < W * H; p++) /* normalise by coverage like a label image would be */
            if (alpha[p] > 1e-3f)
                for (int c = 0; c < SC_DIM; c++) maps[((size_t)v * W * H + p) * SC_DIM + c] /= alpha[p];
    }
    float *truth = malloc(sizeof(float) * s.n * SC_DIM);
    memcpy(truth, s.features, sizeof(float) * s.n * SC_DIM);
    memset(s.features, 0, sizeof(float) * s.n * SC_DIM);
    map_ctx ctx = {maps, (size_t)W * H * SC_DIM};
    float *wsum = malloc(sizeof(float) * s.n);
    CHECK_OK(sp_semantic_lift(rast, &s, SC_DIM, cams, V, give_map, &ctx, NULL, wsum, NULL, &err), &err);
    size_t seen = 0, right = 0;
    for (size_t i = 0; i < s.n; i++) {
        if (wsum[i] < 0.05f) continue;
        seen++;
        double best = 1e30;
        int arg = -1;
        for (int k = 0; k < SC_CLASSES; k++) {
            float fk[SC_DIM];
            sc_encode(&pca, emb[k], fk);
            double d = 0;
            for (int c = 0; c < SC_DIM; c++) d += (s.features[i * SC_DIM + c] - fk[c]) * (s.features[i * SC_DIM + c] - fk[c]);
            if (d < best) best = d, arg = k;
        }
        right += arg == cls[i];
    }
    CHECK(seen > s.n / 3);
    CHECK_MSG(right > 0.93 * seen, "%zu of %zu lifted Gaussians decode to their class", right, seen);
    sp_raster_free(rast);
    sp_device_free(dev);
    sp_splat_free(&s);
    sp_sem_pca_free(&pca);
    free(cls), free(maps), free(alpha), free(truth), free(wsum);
}

int main(void)
{
    RUN(test_lift_matches_naive_weights);
    RUN(test_lift_label_maps_roundtrip);
    return TEST_EXIT();
}
