/* Built when nvcc is absent: no GPU semantic stages (sp_device_supports never sends a query here,
 * as no CUDA device can be made, so an engine never has device features). */
#include "semantic/sem_cuda.h"

#define NO_CUDA(what) sp_error_set(err, SP_E_UNSUPPORTED, "%s on the GPU: semsplat was built without CUDA", what)

int sem_cuda_score(sp_device *dev, const sp_sem_scorer *sc, size_t n, const float *d_features,
                   float *d_raw, float *d_rel, sp_error *err)
{
    return NO_CUDA("relevancy");
}

int sem_cuda_view_points(sp_device *dev, sp_device_scratch *work, const sp_sem_scorer *sc,
                         float thr_raw, float thr_rel, const sp_camera *cams, int nv,
                         const float *d_feat, const float *d_depth, const float *d_alpha,
                         float **pts, float **w, float **cf, size_t *m, double ms[2], sp_error *err)
{
    return NO_CUDA("multi-view points");
}

int sem_cuda_interleave(sp_device *dev, size_t n, const float *d_raw, const float *d_rel,
                        float *d_scores2, sp_error *err)
{
    return NO_CUDA("heatmap scores");
}

int sem_cuda_heatmap(sp_device *dev, size_t np, const float *d_rgb, const float *d_two,
                     const float *d_alpha, int found, float fade, uint8_t *d_img, float *d_rel,
                     float *d_max, sp_error *err)
{
    return NO_CUDA("heatmap");
}
