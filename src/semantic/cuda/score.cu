/* Per-Gaussian relevancy on the GPU: one thread per Gaussian, the same d-dim algebra as
 * sp_sem_score on the host (src/semantic/relevancy.c). The query, mean and negative projections
 * travel as one __grid_constant__ kernel argument (read in place from the constant bank, no
 * per-thread copy), so no global state is shared between engines or threads. */
#include "device/cuda/device_cuda.h"
#include "semantic/sem_cuda.h"


struct score_params {
    float q0, m2, temperature;
    float n0[SP_SEM_MAX_NEGATIVES];
    int D, NN;
    float qb[SP_FEATURE_DIM_MAX], mb[SP_FEATURE_DIM_MAX], nb[SP_SEM_MAX_NEGATIVES][SP_FEATURE_DIM_MAX];
};

__global__ void k_score(const __grid_constant__ score_params p, size_t n, const float *__restrict__ f,
                        float *raw, float *rel)
{
    size_t i = (size_t)blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    const float *fi = f + i * (size_t)p.D;
    float dq = p.q0, dm = 0.f, ff = 0.f, dn[SP_SEM_MAX_NEGATIVES];
    for (int q = 0; q < p.NN; q++) dn[q] = p.n0[q];
    for (int k = 0; k < p.D; k++) {
        float x = fi[k];
        dq += p.qb[k] * x;
        dm += p.mb[k] * x;
        ff += x * x;
        for (int q = 0; q < p.NN; q++) dn[q] += p.nb[q][k] * x;
    }
    float n2 = p.m2 + 2.f * dm + ff;
    float inv = n2 > 1e-20f ? rsqrtf(n2) : 0.f;
    float s = dq * inv;
    raw[i] = s;
    /* LERF: min over negatives of exp(s/T) / (exp(s/T) + exp(s_k/T)) = 1 / (1 + exp((s_k - s)/T)) */
    float r = p.NN > 0 ? 1.f : 0.5f + 0.5f * s;
    for (int q = 0; q < p.NN; q++) r = fminf(r, 1.f / (1.f + expf((dn[q] * inv - s) / p.temperature)));
    rel[i] = r;
}

extern "C" int sem_cuda_score(sp_device *dev, const sp_sem_scorer *sc, size_t n,
                              const float *d_features, float *d_raw, float *d_rel, sp_error *err)
{
    if (!sc->orthonormal)
        return sp_error_set(err, SP_E_UNSUPPORTED, "relevancy on the GPU needs an orthonormal PCA basis");
    if (sc->dim < 1 || sc->dim > SP_FEATURE_DIM_MAX)
        return sp_error_set(err, SP_E_UNSUPPORTED, "relevancy on the GPU: feature dim %d not in 1..%d",
                            sc->dim, SP_FEATURE_DIM_MAX);
    if (n == 0) return 0;
    score_params p;
    p.q0 = sc->q0, p.m2 = sc->m2, p.temperature = sc->temperature, p.D = sc->dim, p.NN = sc->n_neg;
    for (int q = 0; q < SP_SEM_MAX_NEGATIVES; q++) {
        p.n0[q] = q < sc->n_neg ? sc->n0[q] : 0.f;
        for (int k = 0; k < SP_FEATURE_DIM_MAX; k++) p.nb[q][k] = sc->nb[q][k];
    }
    for (int k = 0; k < SP_FEATURE_DIM_MAX; k++) p.qb[k] = sc->qb[k], p.mb[k] = sc->mb[k];
    unsigned blocks = (unsigned)((n + 255) / 256);
    k_score<<<blocks, 256, 0, sp_cuda_stream(dev)>>>(p, n, d_features, d_raw, d_rel);
    SP_CUDA_LAUNCHED(err, "relevancy on the GPU");
    return 0;
}
