/* Built when nvcc is absent: no GPU scoring (sp_device_supports never sends a query here, as no
 * CUDA device can be made). */
#include "semantic/sem_cuda.h"

int sem_cuda_score(sp_device *dev, const sp_sem_scorer *sc, size_t n, const float *d_features,
                   float *d_raw, float *d_rel, sp_error *err)
{
    return sp_error_set(err, SP_E_UNSUPPORTED, "relevancy on the GPU: semsplat was built without CUDA");
}
