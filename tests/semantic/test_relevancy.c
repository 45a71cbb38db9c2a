/* Relevancy math against a naive double-precision decode, the LERF formula, clustering into
 * instances, the Turbo colormap and the heatmap overlay. */
#include <math.h>
#include <stdlib.h>

#include "semsplat/semantic.h"
#include "test.h"
#include "semantic/sem_internal.h"

/* Random PCA with orthonormal rows (Gram-Schmidt) or, when skew, a non-orthonormal one. */
static void make_pca(sp_sem_pca *p, int dim, int full, test_rng *r, int skew)
{
    p->dim = dim;
    p->full_dim = full;
    p->mean = malloc(sizeof(float) * full);
    p->basis = malloc(sizeof(float) * full * dim);
    for (int j = 0; j < full; j++) p->mean[j] = (float)test_range(r, -0.3, 0.3);
    for (int k = 0; k < dim; k++) {
        float *row = p->basis + (size_t)k * full;
        for (int j = 0; j < full; j++) row[j] = (float)test_range(r, -1, 1);
        if (skew) continue;
        for (int q = 0; q < k; q++) {
            const float *o = p->basis + (size_t)q * full;
            double d = 0;
            for (int j = 0; j < full; j++) d += (double)row[j] * o[j];
            for (int j = 0; j < full; j++) row[j] -= (float)(d * o[j]);
        }
        double n = 0;
        for (int j = 0; j < full; j++) n += (double)row[j] * row[j];
        for (int j = 0; j < full; j++) row[j] /= (float)sqrt(n);
    }
}

static double naive_cos(const sp_sem_pca *p, const float *f, const float *q)
{
    double dot = 0, nf = 0, nq = 0;
    for (int j = 0; j < p->full_dim; j++) {
        double x = p->mean[j];
        for (int k = 0; k < p->dim; k++) x += (double)p->basis[(size_t)k * p->full_dim + j] * f[k];
        dot += x * q[j];
        nf += x * x;
        nq += (double)q[j] * q[j];
    }
    return dot / sqrt(nf * nq);
}

static void check_scores(int skew)
{
    test_rng r = {1234 + skew};
    sp_sem_pca p;
    int D = 12, F = 40, NN = 3;
    make_pca(&p, D, F, &r, skew);
    float q[40], neg[3 * 40], feat[50 * 12], raw[50], rel[50];
    for (int j = 0; j < F; j++) q[j] = (float)test_range(&r, -1, 1);
    for (int j = 0; j < NN * F; j++) neg[j] = (float)test_range(&r, -1, 1);
    for (int j = 0; j < 50 * D; j++) feat[j] = (float)test_range(&r, -1, 1);
    sp_sem_scorer sc;
    sp_error err = {0};
    CHECK_OK(sp_sem_scorer_init(&sc, &p, q, neg, NN, 0.1f, &err), &err);
    CHECK(sc.orthonormal == !skew);
    sp_sem_score(&sc, NULL, 50, feat, raw, rel);
    double worst = 0, worst_rel = 0;
    for (int i = 0; i < 50; i++) {
        double s = naive_cos(&p, feat + i * D, q);
        double mr = 1;
        for (int k = 0; k < NN; k++) {
            double sn = naive_cos(&p, feat + i * D, neg + k * F);
            double v = exp(s / 0.1) / (exp(s / 0.1) + exp(sn / 0.1));
            if (v < mr) mr = v;
        }
        worst = fmax(worst, fabs(s - raw[i]));
        worst_rel = fmax(worst_rel, fabs(mr - rel[i]));
    }
    CHECK_NEAR(worst, 0, 2e-5);
    CHECK_NEAR(worst_rel, 0, 2e-4);
    sp_sem_pca_free(&p);
}

static void test_scores_orthonormal(void) { check_scores(0); }
static void test_scores_general_basis(void) { check_scores(1); }

static void test_relevancy_formula(void)
{
    float n1[2] = {0.3f, 0.3f};
    CHECK_NEAR(sp_sem_relevancy(0.3f, n1, 2, 0.1f), 0.5, 1e-6);
    float n2[3] = {0.1f, 0.25f, 0.2f}; /* the closest negative decides */
    double want = 1.0 / (1.0 + exp((0.25 - 0.3) / 0.1));
    CHECK_NEAR(sp_sem_relevancy(0.3f, n2, 3, 0.1f), want, 1e-6);
    CHECK(sp_sem_relevancy(0.9f, n2, 3, 0.1f) > 0.99f);
    /* no overflow for large gaps */
    float n3[1] = {-1.0f};
    CHECK(isfinite(sp_sem_relevancy(1.0f, n3, 1, 0.001f)));
}

static void test_scorer_bad_input(void)
{
    test_rng r = {5};
    sp_sem_pca p;
    make_pca(&p, 4, 8, &r, 0);
    float zero[8] = {0}, q[8] = {1, 0, 0, 0, 0, 0, 0, 0};
    sp_sem_scorer sc;
    sp_error err = {0};
    CHECK_FAILS(sp_sem_scorer_init(&sc, &p, zero, NULL, 0, 0.1f, &err), SP_E_ARG, &err, "query");
    CHECK_FAILS(sp_sem_scorer_init(&sc, &p, q, zero, 1, 0.1f, &err), SP_E_ARG, &err, "negative 0");
    CHECK_FAILS(sp_sem_scorer_init(&sc, &p, q, NULL, 0, 0.0f, &err), SP_E_ARG, &err, "temperature");
    CHECK_FAILS(sp_sem_scorer_init(&sc, &p, q, NULL, 99, 0.1f, &err), SP_E_ARG, &err, "negatives");
    p.dim = 65;
    CHECK_FAILS(sp_sem_scorer_init(&sc, &p, q, NULL, 0, 0.1f, &err), SP_E_ARG, &err, "65");
    p.dim = 4;
    sp_sem_pca_free(&p);
}

static void test_pca_read_errors(void)
{
    sp_sem_pca p = {0};
    sp_error err = {0};
    CHECK(sp_sem_pca_read("/nonexistent/mean.npy", "/nonexistent/basis.npy", &p, &err) != 0);
    CHECK(strstr(err.msg, "mean.npy") != NULL);
}

static void test_cluster_instances(void)
{
    /* three blobs: two heavy (2 m apart), one light (dropped at min_fraction 0.2) */
    test_rng r = {77};
    enum { M = 600 };
    float pts[M * 3], w[M], cf[M];
    const float c[3][3] = {{0, 0, 0}, {2, 0, 0.5f}, {0, 3, 0}};
    for (int i = 0; i < M; i++) {
        int b = i < 280 ? 0 : i < 560 ? 1 : 2;
        for (int a = 0; a < 3; a++) pts[3 * i + a] = c[b][a] + (float)test_range(&r, -0.2, 0.2);
        w[i] = b == 1 ? 1.2f : 1.0f;
        cf[i] = b == 1 ? 0.8f : 0.6f;
    }
    sp_query_instance *inst = NULL;
    int n = 0;
    sp_error err = {0};
    CHECK_OK(sem_cluster(pts, w, cf, M, 0.12f, 0.2f, 0.0f, &inst, &n, &err), &err);
    CHECK(n == 2);
    if (n == 2) {
        /* heaviest first: blob 1 */
        CHECK_NEAR(inst[0].position[0], 2, 0.05);
        CHECK_NEAR(inst[0].position[2], 0.5, 0.05);
        CHECK_NEAR(inst[0].confidence, 0.8, 1e-6);
        CHECK(inst[0].n_points == 280);
        CHECK_NEAR(inst[1].position[0], 0, 0.05);
        CHECK(inst[0].extent_min[0] > 1.7f && inst[0].extent_max[0] < 2.3f);
    }
    free(inst);
    CHECK_OK(sem_cluster(pts, w, cf, 0, 0.12f, 0.2f, 0.0f, &inst, &n, &err), &err);
    CHECK(n == 0 && inst == NULL);
    CHECK_FAILS(sem_cluster(pts, w, cf, M, 0.0f, 0.2f, 0.0f, &inst, &n, &err), SP_E_ARG, &err, "voxel");
}

/* An instance's bounds are the 5% and 95% weighted quantiles of its points per axis (what
 * semantic.h says; it used to say 2%..98%), its position their middle. */
static void test_cluster_extent_quantiles(void)
{
    enum { M = 101 };
    float pts[M * 3], w[M], cf[M];
    for (int i = 0; i < M; i++) {
        pts[3 * i] = 0.01f * i, pts[3 * i + 1] = 0, pts[3 * i + 2] = 0;
        w[i] = 1, cf[i] = 0.5f;
    }
    sp_query_instance *inst = NULL;
    int n = 0;
    sp_error err = {0};
    CHECK_OK(sem_cluster(pts, w, cf, M, 0.12f, 0.1f, 0.0f, &inst, &n, &err), &err);
    CHECK(n == 1);
    if (n == 1) {
        CHECK_NEAR(inst[0].extent_min[0], 0.05, 1e-6);
        CHECK_NEAR(inst[0].extent_max[0], 0.95, 1e-6);
        CHECK_NEAR(inst[0].position[0], 0.5, 1e-6);
    }
    free(inst);
}

static void test_turbo_and_overlay(void)
{
    float lo[3], hi[3], mid[3];
    sp_turbo(0.15f, lo);
    sp_turbo(1.0f, hi);
    sp_turbo(0.5f, mid);
    CHECK(lo[2] > lo[0] && lo[2] > lo[1]);  /* cold end: blue */
    CHECK(hi[0] > 0.4f && hi[0] > 4 * hi[2]); /* hot end: red */
    CHECK(mid[1] > 0.8f);                  /* middle: green/yellow */
    sp_turbo(NAN, lo);
    CHECK(isfinite(lo[0]));
    float rgb[2 * 3] = {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f}, rel[2] = {0.5f, 1.0f};
    uint8_t out[6];
    sp_heatmap_overlay(rgb, rel, 2, 1, out);
    CHECK(out[0] == out[1] && out[1] == out[2] && out[0] < 128); /* neutral: dimmed grey */
    CHECK(out[3] > out[4] + 40 && out[3] > out[5] + 40);          /* relevant: hot */
}

int main(void)
{
    RUN(test_scores_orthonormal);
    RUN(test_scores_general_basis);
    RUN(test_relevancy_formula);
    RUN(test_scorer_bad_input);
    RUN(test_pca_read_errors);
    RUN(test_cluster_instances);
    RUN(test_cluster_extent_quantiles);
    RUN(test_turbo_and_overlay);
    return TEST_EXIT();
}
