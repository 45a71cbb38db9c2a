/* The d-dim relevancy algebra of sp_sem_score (src/semantic/relevancy.c) for CUDA kernels: the
 * query, mean and negative projections as one __grid_constant__ kernel argument (read in place
 * from the constant bank, no per-thread copy, no global state shared between engines), and the
 * per-vector score that the per-Gaussian and the per-pixel kernels both run. */
#ifndef SP_SEM_SCORE_CUH
#define SP_SEM_SCORE_CUH

#include "device/cuda/device_cuda.h"
#include "semantic/sem_cuda.h"

struct score_params {
    float q0, m2, temperature;
    float n0[SP_SEM_MAX_NEGATIVES];
    int D, NN;
    float qb[SP_FEATURE_DIM_MAX], mb[SP_FEATURE_DIM_MAX], nb[SP_SEM_MAX_NEGATIVES][SP_FEATURE_DIM_MAX];
};

/* The scorer's terms as kernel parameters; SP_E_UNSUPPORTED when the GPU cannot score it. */
static inline int score_params_fill(const sp_sem_scorer *sc, score_params *p, sp_error *err)
{
    if (!sc->orthonormal)
        return sp_error_set(err, SP_E_UNSUPPORTED, "relevancy on the GPU needs an orthonormal PCA basis");
    if (sc->dim < 1 || sc->dim > SP_FEATURE_DIM_MAX)
        return sp_error_set(err, SP_E_UNSUPPORTED, "relevancy on the GPU: feature dim %d not in 1..%d",
                            sc->dim, SP_FEATURE_DIM_MAX);
    p->q0 = sc->q0, p->m2 = sc->m2, p->temperature = sc->temperature, p->D = sc->dim, p->NN = sc->n_neg;
    for (int q = 0; q < SP_SEM_MAX_NEGATIVES; q++) {
        p->n0[q] = q < sc->n_neg ? sc->n0[q] : 0.f;
        for (int k = 0; k < SP_FEATURE_DIM_MAX; k++) p->nb[q][k] = sc->nb[q][k];
    }
    for (int k = 0; k < SP_FEATURE_DIM_MAX; k++) p->qb[k] = sc->qb[k], p->mb[k] = sc->mb[k];
    return 0;
}

/* Raw cosine and relevancy of the features f [D] divided by a (1 for Gaussians; the pixel's
 * alpha for a composited feature image, as sem_score_pixels normalises before scoring). */
__device__ __forceinline__ void score_one(const score_params &p, const float *__restrict__ f, float a,
                                          float *raw, float *rel)
{
    float dq = p.q0, dm = 0.f, ff = 0.f, dn[SP_SEM_MAX_NEGATIVES];
    for (int q = 0; q < p.NN; q++) dn[q] = p.n0[q];
    for (int k = 0; k < p.D; k++) {
        float x = a == 1.f ? f[k] : __fdiv_rn(f[k], a);
        dq += p.qb[k] * x;
        dm += p.mb[k] * x;
        ff += x * x;
        for (int q = 0; q < p.NN; q++) dn[q] += p.nb[q][k] * x;
    }
    float n2 = p.m2 + 2.f * dm + ff;
    float inv = n2 > 1e-20f ? rsqrtf(n2) : 0.f;
    float s = dq * inv;
    *raw = s;
    /* LERF: min over negatives of exp(s/T) / (exp(s/T) + exp(s_k/T)) = 1 / (1 + exp((s_k - s)/T)) */
    float r = p.NN > 0 ? 1.f : 0.5f + 0.5f * s;
    for (int q = 0; q < p.NN; q++) r = fminf(r, 1.f / (1.f + expf((dn[q] * inv - s) / p.temperature)));
    *rel = r;
}

#endif
