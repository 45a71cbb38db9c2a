/* Structure-from-motion with COLMAP as a library call: the three CPU stages spawned with bounded
 * time (feature extraction, sequential matching, mapping), the largest model taken, aligned into
 * the reference capture's frame and written as a capture of its own. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "sfm/sfm_internal.h"

#define SFM_MAX_MODELS 64

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* The reference's image names that exist under capture/images, sorted (the order of the run). */
static int write_image_list(const sp_sfm_opts *o, const sp_colmap_model *ref, const char *list,
                            int *n_out, sp_error *err)
{
    const char **names = malloc((ref->n_images + 1) * sizeof *names);
    if (!names) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    size_t n = 0;
    char path[2400];
    for (size_t i = 0; i < ref->n_images; i++) {
        snprintf(path, sizeof path, "%s/images/%s", o->capture, ref->images[i].name);
        if (sp_file_exists(path)) names[n++] = ref->images[i].name;
    }
    qsort(names, n, sizeof *names, cmp_str);
    FILE *f = fopen(list, "w");
    int rc = f ? 0 : sp_error_set(err, SP_E_IO, "%s: cannot write", list);
    for (size_t i = 0; f && i < n; i++) fprintf(f, "%s\n", names[i]);
    if (f && fclose(f) != 0) rc = sp_error_set(err, SP_E_IO, "%s: write failed", list);
    free(names);
    if (!rc && n < 3)
        rc = sp_error_set(err, SP_E_NOTFOUND, "%s/images: %zu of the %zu images of its model exist; "
                          "structure-from-motion needs at least 3", o->capture, n, ref->n_images);
    *n_out = (int)n;
    return rc;
}

/* Removes what an earlier run left in work (the database and models), nothing else. */
static void clear_previous(const char *work)
{
    static const char *db[] = {"database.db", "database.db-wal", "database.db-shm"};
    static const char *files[] = {"cameras.bin", "images.bin", "points3D.bin", "project.ini"};
    char p[2400];
    for (int i = 0; i < 3; i++) {
        snprintf(p, sizeof p, "%s/%s", work, db[i]);
        unlink(p);
    }
    for (int k = 0; k < SFM_MAX_MODELS; k++) {
        for (int i = 0; i < 4; i++) {
            snprintf(p, sizeof p, "%s/sparse/%d/%s", work, k, files[i]);
            unlink(p);
        }
        snprintf(p, sizeof p, "%s/sparse/%d", work, k);
        rmdir(p);
    }
}

static int stage(const sp_sfm_opts *o, const char *name, char *const argv[], const char *log,
                 double *seconds, sp_error *err)
{
    sp_logf(o->log, SP_LOG_INFO, "sfm: COLMAP %s ...", name);
    double t0 = sp_time_now();
    int rc = sp_sfm_spawn(argv, log, o->nice, o->timeout_s > 0 ? o->timeout_s : 3600, err);
    *seconds = sp_time_now() - t0;
    if (!rc) sp_logf(o->log, SP_LOG_INFO, "sfm: COLMAP %s done in %.1f s", name, *seconds);
    return rc;
}

static int run_colmap(const sp_sfm_opts *o, const char *colmap, const char *work,
                      const sp_colmap_camera *cam, sp_sfm_result *res, sp_error *err)
{
    char db[2400], images[2400], list[2400], sparse[2400], threads[32], feats[32], overlap[32];
    char params[512], peak[32], tri[32], inl[32];
    snprintf(db, sizeof db, "%s/database.db", work);
    snprintf(images, sizeof images, "%s/images", o->capture);
    snprintf(list, sizeof list, "%s/images.txt", work);
    snprintf(sparse, sizeof sparse, "%s/sparse", work);
    snprintf(threads, sizeof threads, "%d", o->threads > 0 ? o->threads : -1);
    snprintf(feats, sizeof feats, "%d", o->max_features > 0 ? o->max_features : 4096);
    snprintf(overlap, sizeof overlap, "%d", o->overlap > 0 ? o->overlap : 10);
    snprintf(tri, sizeof tri, "%g", o->init_min_tri_angle_deg > 0 ? o->init_min_tri_angle_deg : 4);
    snprintf(inl, sizeof inl, "%d", o->abs_pose_min_inliers > 0 ? o->abs_pose_min_inliers : 15);
    snprintf(peak, sizeof peak, "%.6g", o->peak_threshold > 0 ? o->peak_threshold : 0.02 / 3);
    snprintf(params, sizeof params, "%.17g,%.17g,%.17g,%.17g", cam->params[0], cam->params[1],
             cam->params[2], cam->params[3]);
    char *c = (char *)colmap, *fix = o->estimate_intrinsics ? "1" : "0";
    char *extract[] = {c, "feature_extractor", "--database_path", db, "--image_path", images,
                       "--image_list_path", list, "--ImageReader.camera_model", "PINHOLE",
                       "--ImageReader.single_camera", "1", "--SiftExtraction.use_gpu", "0",
                       "--SiftExtraction.num_threads", threads, "--SiftExtraction.max_num_features",
                       feats, "--SiftExtraction.peak_threshold", peak, o->estimate_intrinsics ? NULL : "--ImageReader.camera_params", params, NULL};
    char *match[] = {c, "sequential_matcher", "--database_path", db, "--SiftMatching.use_gpu", "0",
                     "--SiftMatching.num_threads", threads, "--SequentialMatching.overlap", overlap, NULL};
    char *map[] = {c, "mapper", "--database_path", db, "--image_path", images, "--output_path", sparse,
                   "--Mapper.num_threads", threads, "--Mapper.ba_refine_focal_length", fix,
                   "--Mapper.ba_refine_extra_params", "0", "--Mapper.init_min_tri_angle", tri,
                   "--Mapper.abs_pose_min_num_inliers", inl, NULL};
    char log[2400];
    snprintf(log, sizeof log, "%s/colmap.log", work);
    int rc = stage(o, "feature extraction", extract, log, &res->t_extract_s, err);
    if (!rc) rc = stage(o, "sequential matching", match, log, &res->t_match_s, err);
    if (!rc) rc = sp_mkdirs(sparse, err);
    if (!rc) rc = stage(o, "mapping", map, log, &res->t_map_s, err);
    return rc;
}

/* Reads work/sparse/<k> for every k COLMAP wrote; keeps the model with the most images. */
static int pick_model(const char *work, sp_colmap_model *best, sp_sfm_result *res, sp_error *err)
{
    int sizes[SFM_MAX_MODELS], n = 0;
    memset(best, 0, sizeof *best);
    for (int k = 0; k < SFM_MAX_MODELS; k++) {
        char p[2400];
        snprintf(p, sizeof p, "%s/sparse/%d/images.bin", work, k);
        if (!sp_file_exists(p)) continue;
        snprintf(p, sizeof p, "%s/sparse/%d", work, k);
        sp_colmap_model m;
        int rc = sp_colmap_read_bin(p, &m, err);
        if (rc) {
            sp_colmap_free(best);
            return rc;
        }
        sizes[n++] = (int)m.n_images;
        if (m.n_images > best->n_images) {
            sp_colmap_free(best);
            *best = m;
        } else sp_colmap_free(&m);
    }
    for (int i = 1; i < n; i++) /* largest first */
        for (int j = i; j > 0 && sizes[j] > sizes[j - 1]; j--) {
            int t = sizes[j];
            sizes[j] = sizes[j - 1];
            sizes[j - 1] = t;
        }
    res->n_models = n;
    res->model_images = malloc(((size_t)n + 1) * sizeof(int));
    if (!res->model_images) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    memcpy(res->model_images, sizes, (size_t)n * sizeof(int));
    res->n_registered = (int)best->n_images;
    res->n_points = best->n_points;
    if (n == 0) return sp_error_set(err, SP_E_FORMAT, "COLMAP made no model (see %s/colmap.log)", work);
    return 0;
}

int sp_sfm_colmap(const sp_sfm_opts *o, sp_sfm_result *res, sp_error *err)
{
    memset(res, 0, sizeof *res);
    if (!o || !o->capture || !o->out) return sp_error_set(err, SP_E_ARG, "sfm: a capture and an output folder are needed");
    if (o->nice < 0 || o->nice > 19) return sp_error_set(err, SP_E_ARG, "sfm: niceness %d: expected 0..19", o->nice);
    if (o->timeout_s < 0) return sp_error_set(err, SP_E_ARG, "sfm: timeout %g s", o->timeout_s);
    if (!(o->init_min_tri_angle_deg >= 0 && o->init_min_tri_angle_deg < 90) || o->abs_pose_min_inliers < 0)
        return sp_error_set(err, SP_E_ARG, "sfm: mapper settings %g degrees, %d inliers: expected "
                            "0..90 and >= 0", o->init_min_tri_angle_deg, o->abs_pose_min_inliers);
    if (!(o->peak_threshold >= 0 && o->peak_threshold < 1))
        return sp_error_set(err, SP_E_ARG, "sfm: SIFT peak threshold %g: expected 0..1", o->peak_threshold);
    char colmap[4096];
    int rc = sp_sfm_find_colmap(o->colmap, colmap, sizeof colmap, err);
    if (rc) return rc;
    sp_colmap_model ref = {0}, est = {0};
    char *fit_json = NULL;
    if ((rc = sp_colmap_read(o->capture, &ref, err))) return sp_error_prefix(err, "sfm reference: ");
    const sp_colmap_camera *cam = ref.n_cameras ? &ref.cameras[0] : NULL;
    if (!cam || (!o->estimate_intrinsics && (cam->model != SP_COLMAP_PINHOLE || ref.n_cameras != 1))) {
        sp_colmap_free(&ref);
        return sp_error_set(err, SP_E_UNSUPPORTED, "%s: known intrinsics need one PINHOLE camera (the "
                            "model has %zu, the first %s); estimate them instead", o->capture,
                            ref.n_cameras, cam ? sp_colmap_model_name(cam->model) : "none");
    }
    char work[2400], list[2500];
    if (o->work_dir) snprintf(work, sizeof work, "%s", o->work_dir);
    else snprintf(work, sizeof work, "%s/colmap", o->out);
    snprintf(list, sizeof list, "%s/images.txt", work);
    snprintf(res->log_path, sizeof res->log_path, "%s/colmap.log", work);
    rc = sp_mkdirs(work, err);
    if (!rc) {
        clear_previous(work);
        unlink(res->log_path);
        rc = write_image_list(o, &ref, list, &res->n_images, err);
    }
    if (!rc) {
        sp_logf(o->log, SP_LOG_INFO, "sfm: %d images of %s, %s intrinsics, log %s", res->n_images,
                o->capture, o->estimate_intrinsics ? "estimated" : "known", res->log_path);
        rc = run_colmap(o, colmap, work, cam, res, err);
    }
    if (!rc) rc = pick_model(work, &est, res, err);
    if (!rc) {
        sp_logf(o->log, SP_LOG_INFO, "sfm: %d models; the largest registered %d of %d images, %zu points",
                res->n_models, res->n_registered, res->n_images, res->n_points);
        rc = sfm_align(&est, &ref, res, &fit_json, err);
    }
    if (!rc) {
        sp_logf(o->log, SP_LOG_INFO, "sfm: aligned (scale %.4g, %d inliers): camera error RMS %.3f m, "
                "median %.3f m, max %.3f m (%s), rotation %.2f deg mean", res->scale, res->n_inliers,
                res->ate_rms_m, res->ate_median_m, res->ate_max_m, res->worst_image, res->rot_err_mean_deg);
        rc = sfm_write_capture(o, &est, res, fit_json, err);
    }
    free(fit_json);
    sp_colmap_free(&est);
    sp_colmap_free(&ref);
    return rc;
}

void sp_sfm_result_free(sp_sfm_result *res)
{
    if (!res) return;
    free(res->model_images);
    res->model_images = NULL;
}
