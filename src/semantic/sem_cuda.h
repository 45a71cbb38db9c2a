/* The semantic module's CUDA seam: per-Gaussian relevancy on the GPU (src/semantic/cuda/), so a
 * GPU query engine scores its features where they already live; src/semantic/nocuda/ stands in
 * when nvcc is absent. Callers ask sp_device_supports(dev, SP_STAGE_SEM_SCORE, dim) first. */
#ifndef SP_SEM_CUDA_H
#define SP_SEM_CUDA_H

#include "semsplat/semantic.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Raw cosine and calibrated relevancy of n device features [n][sc->dim] into device raw [n]
 * and rel [n], exactly as sp_sem_score does on the host, on dev's stream. Needs sc->orthonormal
 * (callers fall back to the host otherwise). */
int sem_cuda_score(sp_device *dev, const sp_sem_scorer *sc, size_t n, const float *d_features,
                   float *d_raw, float *d_rel, sp_error *err);

#ifdef __cplusplus
}
#endif
#endif
