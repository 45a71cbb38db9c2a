/* sfm's private parts: alignment (align.c) and the output capture (capture.c). */
#ifndef SP_SFM_INTERNAL_H
#define SP_SFM_INTERNAL_H

#include "semsplat/io.h"
#include "semsplat/sfm.h"

/* Aligns est (COLMAP's model) into ref's frame in place: poses and points; fills res's scale,
 * inliers and the per-camera errors, and *fit_json with the robust fit's report (malloc'd; NULL
 * on error or when out of memory). */
int sfm_align(sp_colmap_model *est, const sp_colmap_model *ref, sp_sfm_result *res,
              char **fit_json, sp_error *err);

/* Writes the output capture: est as sparse/0, est's images and their labels from the input
 * capture (hard links where possible), labels.json and ground_truth.json, and capture.json (the
 * input's, with the poses' source and the sfm figures), and frame.json: source "align", identity
 * (the poses are already in the reference's frame), the fit's residual and report. */
int sfm_write_capture(const sp_sfm_opts *o, const sp_colmap_model *est, const sp_sfm_result *res,
                      const char *fit_json, sp_error *err);

#endif
