/* The capture sfm writes: COLMAP's aligned model as sparse/0, the registered images and their
 * label images from the input capture (hard links, or copies across file systems), the input's
 * labels.json and ground_truth.json, and a capture.json that says the poses are COLMAP's. */
#include <cjson/cJSON.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "sfm/sfm_internal.h"

/* dst becomes src's content: a hard link, else a copy (atomic either way for readers of dst). */
static int link_or_copy(const char *src, const char *dst, sp_error *err)
{
    char tmp[2200];
    if (snprintf(tmp, sizeof tmp, "%s.tmp.%ld", dst, (long)getpid()) >= (int)sizeof tmp)
        return sp_error_set(err, SP_E_ARG, "%s: path too long", dst);
    unlink(tmp);
    if (link(src, tmp) == 0) {
        if (rename(tmp, dst) == 0) return 0;
        int e = errno;
        unlink(tmp);
        return sp_error_set(err, SP_E_IO, "%s: %s", dst, strerror(e));
    }
    char *data = NULL;
    size_t size = 0;
    int rc = sp_read_file(src, &data, &size, err);
    if (!rc) rc = sp_write_file_atomic(dst, data, size, err);
    free(data);
    return rc;
}

static int stem_png(const char *name, char *out, size_t cap)
{
    const char *dot = strrchr(name, '.');
    size_t n = dot ? (size_t)(dot - name) : strlen(name);
    return snprintf(out, cap, "%.*s.png", (int)n, name) >= (int)cap ? -1 : 0;
}

static int copy_views(const sp_sfm_opts *o, const sp_colmap_model *est, sp_error *err)
{
    char a[2400], b[2400], lab[600];
    snprintf(a, sizeof a, "%s/labels", o->capture);
    int labels = sp_file_exists(a);
    const char *dirs[] = {"images", "labels"};
    for (int d = 0; d < 1 + labels; d++) {
        snprintf(b, sizeof b, "%s/%s", o->out, dirs[d]);
        int rc = sp_mkdirs(b, err);
        if (rc) return rc;
    }
    for (size_t i = 0; i < est->n_images; i++) {
        const char *name = est->images[i].name;
        if (strchr(name, '/') || strstr(name, ".."))
            return sp_error_set(err, SP_E_FORMAT, "COLMAP image name '%s': expected a plain file name", name);
        snprintf(a, sizeof a, "%s/images/%s", o->capture, name);
        snprintf(b, sizeof b, "%s/images/%s", o->out, name);
        int rc = link_or_copy(a, b, err);
        if (rc) return rc;
        if (!labels || stem_png(name, lab, sizeof lab)) continue;
        snprintf(a, sizeof a, "%s/labels/%s", o->capture, lab);
        snprintf(b, sizeof b, "%s/labels/%s", o->out, lab);
        if (sp_file_exists(a) && (rc = link_or_copy(a, b, err))) return rc;
    }
    return 0;
}

static cJSON *sfm_json(const sp_sfm_opts *o, const sp_sfm_result *r)
{
    cJSON *s = cJSON_CreateObject();
    cJSON_AddStringToObject(s, "program", "COLMAP 3.8 (CPU: SIFT, sequential matching, incremental mapper)");
    cJSON_AddStringToObject(s, "reference", o->capture);
    cJSON_AddStringToObject(s, "intrinsics", o->estimate_intrinsics ? "estimated by COLMAP (PINHOLE, refined focal)"
                                                                       : "given (the reference's PINHOLE), fixed");
    cJSON *set = cJSON_AddObjectToObject(s, "settings");
    cJSON_AddNumberToObject(set, "max_features", o->max_features > 0 ? o->max_features : 4096);
    cJSON_AddNumberToObject(set, "peak_threshold", o->peak_threshold > 0 ? o->peak_threshold : 0.02 / 3);
    cJSON_AddNumberToObject(set, "overlap", o->overlap > 0 ? o->overlap : 10);
    cJSON_AddNumberToObject(set, "init_min_tri_angle_deg", o->init_min_tri_angle_deg > 0 ? o->init_min_tri_angle_deg : 4);
    cJSON_AddNumberToObject(set, "abs_pose_min_inliers", o->abs_pose_min_inliers > 0 ? o->abs_pose_min_inliers : 15);
    cJSON_AddNumberToObject(s, "images", r->n_images);
    cJSON_AddNumberToObject(s, "models", r->n_models);
    cJSON_AddItemToObject(s, "model_images", cJSON_CreateIntArray(r->model_images, r->n_models));
    cJSON_AddNumberToObject(s, "registered", r->n_registered);
    cJSON_AddNumberToObject(s, "points3D", (double)r->n_points);
    cJSON *a = cJSON_AddObjectToObject(s, "alignment");
    cJSON_AddStringToObject(a, "method", "LMedS similarity on camera centres, refit on inliers (sp_align_fit_robust)");
    cJSON_AddNumberToObject(a, "scale", r->scale);
    cJSON_AddNumberToObject(a, "inliers", r->n_inliers);
    cJSON_AddNumberToObject(a, "rms_inliers_m", r->align_rms_inliers_m);
    cJSON_AddNumberToObject(a, "inlier_threshold_m", r->align_threshold_m);
    cJSON_AddNumberToObject(a, "ate_rms_m", r->ate_rms_m);
    cJSON_AddNumberToObject(a, "ate_median_m", r->ate_median_m);
    cJSON_AddNumberToObject(a, "ate_max_m", r->ate_max_m);
    cJSON_AddStringToObject(a, "worst_image", r->worst_image);
    cJSON_AddNumberToObject(a, "rotation_error_mean_deg", r->rot_err_mean_deg);
    cJSON_AddNumberToObject(a, "rotation_error_max_deg", r->rot_err_max_deg);
    cJSON *t = cJSON_AddObjectToObject(s, "seconds");
    cJSON_AddNumberToObject(t, "features", r->t_extract_s);
    cJSON_AddNumberToObject(t, "matching", r->t_match_s);
    cJSON_AddNumberToObject(t, "mapping", r->t_map_s);
    return s;
}

static int write_capture_json(const sp_sfm_opts *o, const sp_sfm_result *r, sp_error *err)
{
    char path[2400];
    snprintf(path, sizeof path, "%s/capture.json", o->capture);
    cJSON *j = NULL;
    if (sp_file_exists(path)) {
        int rc = sp_json_read_file(path, &j, err);
        if (rc) return rc;
    } else j = cJSON_CreateObject();
    cJSON_DeleteItemFromObject(j, "poses");
    cJSON_DeleteItemFromObject(j, "sfm");
    cJSON_DeleteItemFromObject(j, "views");
    char poses[256];
    snprintf(poses, sizeof poses, "colmap: %d of %d images registered, aligned to the reference at %.3f m RMS",
             r->n_registered, r->n_images, r->ate_rms_m);
    cJSON_AddStringToObject(j, "poses", poses);
    cJSON_AddNumberToObject(j, "views", r->n_registered);
    cJSON_AddItemToObject(j, "sfm", sfm_json(o, r));
    snprintf(path, sizeof path, "%s/capture.json", o->out);
    int rc = sp_json_write_file(path, j, err);
    cJSON_Delete(j);
    return rc;
}

static int write_frame(const sp_sfm_opts *o, const sp_sfm_result *r, const char *fit_json, sp_error *err)
{
    sp_frame ref, f;
    int rc = sp_frame_of_capture(o->capture, &ref, err);
    if (rc) return sp_error_prefix(err, "sfm reference frame: ");
    if (!sp_frame_is_world(&ref))
        return sp_error_set(err, SP_E_ARG, "%s: its frame is '%s', not a world frame: COLMAP's poses "
                            "would be aligned to nothing", o->capture, ref.source);
    sp_frame_init(&f, "align");
    memcpy(f.world_from_model, ref.world_from_model, sizeof f.world_from_model);
    f.residual_m = r->align_rms_inliers_m;
    snprintf(f.note, sizeof f.note, "COLMAP poses of %d/%d images, aligned to %s's cameras by semsplat sfm",
             r->n_registered, r->n_images, o->capture);
    char path[2400];
    snprintf(path, sizeof path, "%s/frame.json", o->out);
    return fit_json ? sp_frame_write_fit(path, &f, fit_json, err) : sp_frame_write(path, &f, err);
}

int sfm_write_capture(const sp_sfm_opts *o, const sp_colmap_model *est, const sp_sfm_result *res,
                      const char *fit_json, sp_error *err)
{
    char path[2400];
    snprintf(path, sizeof path, "%s/sparse/0", o->out);
    int rc = sp_mkdirs(path, err);
    if (!rc) rc = sp_colmap_write_bin(path, est, err);
    if (!rc) rc = copy_views(o, est, err);
    const char *side[] = {"labels.json", "ground_truth.json"};
    for (int k = 0; k < 2 && !rc; k++) {
        char a[2400];
        snprintf(a, sizeof a, "%s/%s", o->capture, side[k]);
        snprintf(path, sizeof path, "%s/%s", o->out, side[k]);
        if (sp_file_exists(a)) rc = link_or_copy(a, path, err);
    }
    if (!rc) rc = write_capture_json(o, res, err);
    if (!rc) rc = write_frame(o, res, fit_json, err);
    return rc;
}
