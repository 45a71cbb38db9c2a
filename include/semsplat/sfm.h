/* semsplat sfm: camera poses from structure-from-motion, as users' splats get them. Runs Debian's
 * COLMAP 3.8 (an external program, spawned; CPU only) on a capture's images: feature extraction,
 * sequential matching (frames in name order, as a recorded run gives), incremental mapping; takes
 * the model with the most registered images, aligns it into a reference frame by a similarity
 * fitted on the camera centres of the images both know, and writes a new capture whose poses and
 * points are COLMAP's (in the reference frame), with the reference capture's images, labels and
 * ground truth beside them. The reference is typically a synth capture (exact poses, the world
 * frame), standing in for what a robot's odometry or a few surveyed positions give.
 *
 * The alignment is semantic's robust similarity (sp_align_fit_robust: least median of squares
 * over the matched camera centres, refitted on the inliers), so a few images COLMAP placed wrongly
 * do not pull it; it refuses when fewer than half agree. The result reports the residual of every
 * image after alignment (RMS, median, max: the absolute trajectory error), the inliers and the
 * rotation error, so a report can say how good the poses were.
 *
 * Ownership: sp_sfm_result owns its arrays (sp_sfm_result_free). Processes are started with
 * their own process group, bounded by opts->timeout_s, and killed (that group only) on timeout;
 * COLMAP's output goes to <work_dir>/colmap.log. */
#ifndef SEMSPLAT_SFM_H
#define SEMSPLAT_SFM_H

#include "semsplat/core.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sp_sfm_opts {
    const char *capture;     /* input: a capture folder (images/, sparse/0 with the reference poses,
                                labels/, labels.json, ground_truth.json, capture.json as present) */
    const char *out;         /* output capture folder */
    const char *work_dir;    /* COLMAP's database, models and log; NULL = <out>/colmap */
    const char *colmap;      /* the program; NULL = "colmap" on PATH */
    int threads;             /* COLMAP's threads; 0 = all CPUs */
    int nice;                /* niceness added to COLMAP's processes (0..19) */
    double timeout_s;        /* per COLMAP stage; 0 = 3600 */
    int estimate_intrinsics; /* 0: the reference camera's PINHOLE intrinsics are given and fixed
                                (a calibrated robot camera); 1: COLMAP estimates the focal length */
    int max_features;        /* SIFT features per image; 0 = 4096 */
    double peak_threshold;   /* SIFT's contrast threshold; 0 = COLMAP's 0.0067 (0.02 / 3 octave
                                layers). Lower finds more features in low-texture images */
    int overlap;             /* sequential matching: each image against the next N; 0 = 10 */
    double init_min_tri_angle_deg; /* mapper: triangulation angle of the initial pair; 0 = 4.
                                      COLMAP's 16 suits photo collections; a drive's
                                      neighbouring frames are 0.1-0.3 m apart and no pair reaches
                                      16 degrees, so the map starts nowhere or in pieces */
    int abs_pose_min_inliers;      /* mapper: 2D-3D inliers to register an image; 0 = 15 (COLMAP's
                                      30 drops low-texture frames a drive passes through) */
    const sp_log *log;       /* progress lines (may be NULL) */
} sp_sfm_opts;

typedef struct sp_sfm_result {
    int n_images;            /* images given to COLMAP */
    int n_models;            /* reconstructions COLMAP made */
    int *model_images;       /* [n_models] registered images per model, largest first */
    int n_registered;        /* images in the model used (the largest) */
    size_t n_points;         /* its 3D points */
    double scale;            /* the similarity's scale (reference units per COLMAP unit) */
    int n_inliers;           /* registered images the robust fit agrees with */
    double align_rms_inliers_m;  /* the fit's RMS over its inliers */
    double align_threshold_m;    /* its inlier bound */
    double ate_rms_m, ate_median_m, ate_max_m; /* camera centre residuals after alignment, over
                                                  every registered image (outliers included) */
    double rot_err_mean_deg, rot_err_max_deg;  /* camera orientation error after alignment */
    char worst_image[256];   /* the image with the largest residual */
    double t_extract_s, t_match_s, t_map_s;
    char log_path[1100];
} sp_sfm_result;

/* Runs the whole thing (see the header comment). Errors: SP_E_NOTFOUND when colmap is not
 * installed (naming the package) or the capture lacks images/sparse; SP_E_IO when a stage fails
 * (its exit status and the log named) or runs past the timeout; SP_E_FORMAT when COLMAP made no
 * model, too few registered images are known to the reference, or too few agree on a frame. */
int sp_sfm_colmap(const sp_sfm_opts *o, sp_sfm_result *res, sp_error *err);
void sp_sfm_result_free(sp_sfm_result *res);

/* Finds the COLMAP program (name or path; NULL = "colmap") on PATH: 0 and its path in out, or
 * SP_E_NOTFOUND with a message saying how to install it. */
int sp_sfm_find_colmap(const char *name, char *out, size_t cap, sp_error *err);

/* Runs argv[0] (a path) with argv, stdout and stderr appended to log_path, in its own process
 * group, niceness raised by nice, killed after timeout_s (that group, SIGTERM then SIGKILL).
 * 0 when it exited with status 0; SP_E_IO naming the program, its status or signal, or the
 * timeout otherwise. */
int sp_sfm_spawn(char *const argv[], const char *log_path, int nice, double timeout_s,
                 sp_error *err);

#ifdef __cplusplus
}
#endif
#endif
