/* The semantic module's CUDA seam (src/semantic/cuda/): per-Gaussian relevancy, the multi-view
 * stage's per-pixel scoring and back-projection, and heatmap colouring on the GPU, so a GPU query
 * engine works where its features and renders already live and copies back only the compacted
 * points and the final image; src/semantic/nocuda/ stands in when nvcc is absent. Callers ask
 * sp_device_supports(dev, SP_STAGE_SEM_SCORE, dim) first (engines with e->d_feat). */
#ifndef SP_SEM_CUDA_H
#define SP_SEM_CUDA_H

#include "device/device_impl.h"
#include "semsplat/semantic.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Raw cosine and calibrated relevancy of n device features [n][sc->dim] into device raw [n]
 * and rel [n], exactly as sp_sem_score does on the host, on dev's stream. Needs sc->orthonormal
 * (callers fall back to the host otherwise). */
int sem_cuda_score(sp_device *dev, const sp_sem_scorer *sc, size_t n, const float *d_features,
                   float *d_raw, float *d_rel, sp_error *err);

/* Multi-view points of nv rendered views on the device, as sem_localize_multiview's host loop
 * makes them: view q (camera cams[q], its pixels starting at pixel sum_{r<q} W_r H_r of the
 * buffers) has features d_feat [px][sc->dim] (composited, not divided by alpha), expected depth
 * d_depth [px] and alpha d_alpha [px]. Pixels are scored (alpha-normalised, -1 / 0.5 where
 * alpha <= 0.5), kept where raw >= thr_raw, rel >= thr_rel, alpha > 0.9 and depth > 0, eroded by
 * one pixel, back-projected and compacted in view then raster order into host arrays *pts [m][3],
 * *w [m], *cf [m] (malloc'd; NULL when m = 0). work: the caller's device scratch. ms[0] scoring,
 * ms[1] back-projection and compaction with the copy (host clock after a wait). */
int sem_cuda_view_points(sp_device *dev, sp_device_scratch *work, const sp_sem_scorer *sc,
                         float thr_raw, float thr_rel, const sp_camera *cams, int nv,
                         const float *d_feat, const float *d_depth, const float *d_alpha,
                         float **pts, float **w, float **cf, size_t *m, double ms[2], sp_error *err);

/* scores2 [n][2] = (raw[i], rel[i]) interleaved on the device (the heatmap's 2-channel scene). */
int sem_cuda_interleave(sp_device *dev, size_t n, const float *d_raw, const float *d_rel,
                        float *d_scores2, sp_error *err);

/* The heatmap of a view rendered on the device (rgb [np][3], two [np][2] the composited (raw,
 * rel), alpha [np]): rel [np] = two/alpha where alpha > 0.5 else 0.5; the display scale of
 * heatmap.c (found: stretched to the largest rel; else `fade`); img [np][3] the overlay of
 * sp_heatmap_overlay. Device outputs d_img, d_rel; d_max one float of scratch. */
int sem_cuda_heatmap(sp_device *dev, size_t np, const float *d_rgb, const float *d_two,
                     const float *d_alpha, int found, float fade, uint8_t *d_img, float *d_rel,
                     float *d_max, sp_error *err);

#ifdef __cplusplus
}
#endif
#endif
