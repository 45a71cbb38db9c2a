/* Relevancy of d-dim semantic features against a text embedding, without decoding them to the
 * full space: the PCA decoder is linear, so dot products and norms reduce to d-dim algebra.
 * Used per Gaussian (3D-native localization) and per pixel (multi-view, heatmaps). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/io.h"
#include "semsplat/semantic.h"

void sp_sem_pca_free(sp_sem_pca *pca)
{
    if (!pca) return;
    free(pca->mean);
    free(pca->basis);
    memset(pca, 0, sizeof *pca);
}

int sp_sem_pca_read(const char *mean_path, const char *basis_path, sp_sem_pca *pca, sp_error *err)
{
    sp_npy m = {0}, b = {0};
    float *mean = NULL, *basis = NULL;
    int rc = sp_npy_read(mean_path, &m, err);
    if (rc) return rc;
    rc = sp_npy_read(basis_path, &b, err);
    if (rc) goto done;
    if (b.ndim != 2 || b.shape[1] < 1) {
        rc = sp_error_set(err, SP_E_FORMAT, "%s: PCA basis must be [dim][full_dim], got %d dimensions",
                          basis_path, b.ndim);
        goto done;
    }
    if ((rc = sp_feature_dim_check(b.shape[0] > INT32_MAX ? INT32_MAX : (int)b.shape[0], SP_E_FORMAT,
                                   basis_path, err)))
        goto done;
    if (sp_npy_count(&m) != b.shape[1]) {
        rc = sp_error_set(err, SP_E_FORMAT, "%s: PCA mean has %zu values but the basis has full_dim %zu",
                          mean_path, sp_npy_count(&m), b.shape[1]);
        goto done;
    }
    if ((rc = sp_npy_to_f32(&m, &mean, err)) || (rc = sp_npy_to_f32(&b, &basis, err))) goto done;
    for (size_t i = 0; i < b.shape[0] * b.shape[1]; i++)
        if (!isfinite(basis[i])) {
            rc = sp_error_set(err, SP_E_NUMERIC, "%s: value %zu is not finite", basis_path, i);
            goto done;
        }
    sp_sem_pca_free(pca);
    pca->dim = (int)b.shape[0];
    pca->full_dim = (int)b.shape[1];
    pca->mean = mean;
    pca->basis = basis;
    mean = basis = NULL;
done:
    free(mean);
    free(basis);
    sp_npy_free(&m);
    sp_npy_free(&b);
    return rc;
}

/* Projects a unit vector v [full_dim] onto the decoder: v0 = v.mean, vb = basis v. */
static void project(const sp_sem_pca *pca, const float *v, float *v0, float *vb)
{
    double s = 0;
    for (int j = 0; j < pca->full_dim; j++) s += (double)v[j] * pca->mean[j];
    *v0 = (float)s;
    for (int k = 0; k < pca->dim; k++) {
        const float *row = pca->basis + (size_t)k * pca->full_dim;
        double d = 0;
        for (int j = 0; j < pca->full_dim; j++) d += (double)row[j] * v[j];
        vb[k] = (float)d;
    }
}

static int unit_copy(const float *v, int n, float *out)
{
    double s = 0;
    for (int j = 0; j < n; j++) s += (double)v[j] * v[j];
    if (!(s > 1e-20) || !isfinite(s)) return -1;
    float inv = (float)(1.0 / sqrt(s));
    for (int j = 0; j < n; j++) out[j] = v[j] * inv;
    return 0;
}

int sp_sem_scorer_init(sp_sem_scorer *sc, const sp_sem_pca *pca, const float *query,
                       const float *negatives, int n_neg, float temperature, sp_error *err)
{
    if (!pca || !pca->basis) return sp_error_set(err, SP_E_ARG, "semantic scorer: no PCA");
    int rc = sp_feature_dim_check(pca->dim, SP_E_ARG, "semantic scorer", err);
    if (rc) return rc;
    if (n_neg < 0 || n_neg > SP_SEM_MAX_NEGATIVES)
        return sp_error_set(err, SP_E_ARG, "semantic scorer: %d negatives (at most %d)", n_neg,
                            SP_SEM_MAX_NEGATIVES);
    if (!(temperature > 0))
        return sp_error_set(err, SP_E_ARG, "semantic scorer: temperature %g must be > 0",
                            (double)temperature);
    int D = pca->dim, F = pca->full_dim;
    float *u = malloc(sizeof(float) * (size_t)F);
    if (!u) return sp_error_set(err, SP_E_NOMEM, "semantic scorer: out of memory");
    memset(sc, 0, sizeof *sc);
    sc->dim = D;
    sc->n_neg = n_neg;
    sc->temperature = temperature;
    if (unit_copy(query, F, u)) {
        free(u);
        return sp_error_set(err, SP_E_ARG, "semantic scorer: the query embedding is zero or not finite");
    }
    project(pca, u, &sc->q0, sc->qb);
    for (int k = 0; k < n_neg; k++) {
        if (unit_copy(negatives + (size_t)k * F, F, u)) {
            free(u);
            return sp_error_set(err, SP_E_ARG, "semantic scorer: negative %d is zero or not finite", k);
        }
        project(pca, u, &sc->n0[k], sc->nb[k]);
    }
    free(u);
    double m2 = 0;
    for (int j = 0; j < F; j++) m2 += (double)pca->mean[j] * pca->mean[j];
    float unused;
    project(pca, pca->mean, &unused, sc->mb);
    sc->m2 = (float)m2;
    sc->orthonormal = 1;
    for (int a = 0; a < D; a++) /* symmetric: each pair once (the same sums either way round) */
        for (int b = a; b < D; b++) {
            double g = 0;
            const float *ra = pca->basis + (size_t)a * F, *rb = pca->basis + (size_t)b * F;
            for (int j = 0; j < F; j++) g += (double)ra[j] * rb[j];
            sc->G[a * D + b] = sc->G[b * D + a] = (float)g;
            if (fabs(g - (a == b)) > 1e-4) sc->orthonormal = 0;
        }
    return 0;
}

float sp_sem_relevancy(float s_query, const float *s_neg, int n_neg, float temperature)
{
    /* exp(a)/(exp(a)+exp(b)) = 1/(1+exp(b-a)): no overflow. */
    float rel = 1.0f;
    for (int k = 0; k < n_neg; k++) {
        float r = 1.0f / (1.0f + expf((s_neg[k] - s_query) / temperature));
        if (r < rel) rel = r;
    }
    return n_neg > 0 ? rel : 0.5f + 0.5f * s_query;
}

typedef struct {
    const sp_sem_scorer *sc;
    const float *features;
    float *raw, *rel;
    size_t n;
} score_job;

#define SCORE_CHUNK 4096
#define LANES 16 /* Gaussians scored together: the inner loops run across them and vectorize */

static void score_chunk(void *ctx, long chunk, int tid)
{
    (void)tid;
    const score_job *j = ctx;
    const sp_sem_scorer *sc = j->sc;
    const int D = sc->dim, NN = sc->n_neg;
    size_t i0 = (size_t)chunk * SCORE_CHUNK, i1 = i0 + SCORE_CHUNK;
    if (i1 > j->n) i1 = j->n;
    float ft[SP_FEATURE_DIM_MAX][LANES]; /* a block of features, transposed */
    for (size_t b0 = i0; b0 < i1; b0 += LANES) {
        int L = (int)(i1 - b0 < LANES ? i1 - b0 : LANES);
        for (int g = 0; g < LANES; g++)
            for (int k = 0; k < D; k++) ft[k][g] = g < L ? j->features[(b0 + g) * (size_t)D + k] : 0.0f;
        float dq[LANES], dm[LANES], ff[LANES], dn[SP_SEM_MAX_NEGATIVES][LANES];
        for (int g = 0; g < LANES; g++) dq[g] = sc->q0, dm[g] = 0, ff[g] = 0;
        for (int q = 0; q < NN; q++)
            for (int g = 0; g < LANES; g++) dn[q][g] = sc->n0[q];
        for (int k = 0; k < D; k++) {
            const float a = sc->qb[k], m = sc->mb[k];
            for (int g = 0; g < LANES; g++) {
                dq[g] += a * ft[k][g];
                dm[g] += m * ft[k][g];
            }
            for (int q = 0; q < NN; q++) {
                const float c = sc->nb[q][k];
                for (int g = 0; g < LANES; g++) dn[q][g] += c * ft[k][g];
            }
        }
        if (sc->orthonormal) {
            for (int k = 0; k < D; k++)
                for (int g = 0; g < LANES; g++) ff[g] += ft[k][g] * ft[k][g];
        } else {
            for (int a = 0; a < D; a++) {
                float Gf[LANES] = {0};
                for (int b = 0; b < D; b++) {
                    const float gab = sc->G[a * D + b];
                    for (int g = 0; g < LANES; g++) Gf[g] += gab * ft[b][g];
                }
                for (int g = 0; g < LANES; g++) ff[g] += ft[a][g] * Gf[g];
            }
        }
        for (int g = 0; g < L; g++) {
            float n2 = sc->m2 + 2 * dm[g] + ff[g];
            float inv = n2 > 1e-20f ? 1.0f / sqrtf(n2) : 0.0f;
            float s = dq[g] * inv;
            if (j->raw) j->raw[b0 + g] = s;
            if (j->rel) {
                float sn[SP_SEM_MAX_NEGATIVES];
                for (int q = 0; q < NN; q++) sn[q] = dn[q][g] * inv;
                j->rel[b0 + g] = sp_sem_relevancy(s, sn, NN, sc->temperature);
            }
        }
    }
}

void sp_sem_score(const sp_sem_scorer *sc, sp_pool *pool, size_t n, const float *features,
                  float *raw_cos, float *relevancy)
{
    score_job j = {sc, features, raw_cos, relevancy, n};
    long chunks = (long)((n + SCORE_CHUNK - 1) / SCORE_CHUNK);
    sp_pool_for(pool, chunks, score_chunk, &j);
}
