/* The semantic module's CUDA seam: per-Gaussian relevancy on the GPU (src/semantic/cuda/), so a
 * GPU query engine scores its features where they already live. Compiled when SP_HAVE_CUDA. */
#ifndef SP_SEM_CUDA_H
#define SP_SEM_CUDA_H

#include "semsplat/semantic.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Raw cosine and calibrated relevancy of n device features [n][sc->dim] into device raw [n]
 * and rel [n], exactly as sp_sem_score does on the host. Needs sc->orthonormal (callers fall
 * back to the host otherwise). */
int sem_cuda_score(const sp_sem_scorer *sc, size_t n, const float *d_features, float *d_raw,
                   float *d_rel, sp_error *err);

#ifdef __cplusplus
}
#endif
#endif
