/* Per-Gaussian relevancy on the GPU: one thread per Gaussian, the same d-dim algebra as
 * sp_sem_score on the host (score.cuh). */
#include "semantic/cuda/score.cuh"

__global__ void k_score(const __grid_constant__ score_params p, size_t n, const float *__restrict__ f,
                        float *raw, float *rel)
{
    size_t i = (size_t)blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n) score_one(p, f + i * (size_t)p.D, 1.f, raw + i, rel + i);
}

extern "C" int sem_cuda_score(sp_device *dev, const sp_sem_scorer *sc, size_t n,
                              const float *d_features, float *d_raw, float *d_rel, sp_error *err)
{
    score_params p;
    int rc = score_params_fill(sc, &p, err);
    if (rc || n == 0) return rc;
    unsigned blocks = (unsigned)((n + 255) / 256);
    k_score<<<blocks, 256, 0, sp_cuda_stream(dev)>>>(p, n, d_features, d_raw, d_rel);
    SP_CUDA_LAUNCHED(err, "relevancy on the GPU");
    return 0;
}
