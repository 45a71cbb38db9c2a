/* Puts COLMAP's reconstruction into the reference frame: images matched by name to the reference
 * capture, a robust similarity fitted on their camera centres (semantic's LMedS fit), every pose
 * and point moved by it, and the error of each camera after alignment measured against its
 * reference pose (position and orientation). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/io.h"
#include "semsplat/semantic.h"
#include "sfm/sfm_internal.h"

static const sp_colmap_image *find_image(const sp_colmap_model *m, const char *name)
{
    for (size_t i = 0; i < m->n_images; i++)
        if (m->images[i].name && !strcmp(m->images[i].name, name)) return &m->images[i];
    return NULL;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* x_cam = R_i x_c + t_i and x_w = s R_a x_c + t_a give, in metric camera units,
 * x_cam' = s x_cam = (R_i R_a^T) x_w + (s t_i - R_i R_a^T t_a). */
static void move_pose(sp_camera *cam, const double M[16], double s)
{
    float Ra[9], R[9], t[3];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) Ra[r * 3 + c] = (float)(M[r * 4 + c] / s);
    float RaT[9];
    sp_mat3_transpose(Ra, RaT);
    sp_mat3_mul(cam->R, RaT, R);
    for (int r = 0; r < 3; r++)
        t[r] = (float)(s * cam->t[r] - (R[r * 3] * M[3] + R[r * 3 + 1] * M[7] + R[r * 3 + 2] * M[11]));
    memcpy(cam->R, R, sizeof R);
    memcpy(cam->t, t, sizeof t);
}

/* The angle of A B^T, from the Frobenius distance (|A - B|_F = 2 sqrt(2) sin(angle / 2)): unlike
 * acos of the trace it stays exact for small angles in float. */
static double rotation_error_deg(const float A[9], const float B[9])
{
    double d2 = 0;
    for (int k = 0; k < 9; k++) d2 += ((double)A[k] - B[k]) * ((double)A[k] - B[k]);
    double s = sqrt(d2) / (2 * sqrt(2.0));
    return 2 * asin(s > 1 ? 1 : s) * 180 / M_PI;
}

/* The fit's report (sp_align_fit_json) with the matched images' names for its outliers. */
static char *fit_report(const sp_align_fit *fit, const sp_colmap_model *est, const size_t *ri, size_t m)
{
    sp_align_matches am = {.n = m, .name = calloc(m + 1, 256)};
    if (!am.name) return NULL;
    for (size_t k = 0; k < m; k++) snprintf(am.name[k], 256, "%s", est->images[ri[k]].name);
    char *j = sp_align_fit_json(fit, &am, 1);
    free(am.name);
    return j;
}

int sfm_align(sp_colmap_model *est, const sp_colmap_model *ref, sp_sfm_result *res,
              char **fit_json, sp_error *err)
{
    *fit_json = NULL;
    size_t n = est->n_images;
    double *src = malloc((n * 6 + 1) * sizeof *src), *dst = src ? src + 3 * n : NULL;
    size_t *ri = malloc((n + 1) * sizeof *ri);
    const sp_colmap_image **refs = malloc((n + 1) * sizeof *refs);
    if (!src || !ri || !refs) {
        free(src);
        free(ri);
        free(refs);
        return sp_error_set(err, SP_E_NOMEM, "out of memory");
    }
    size_t m = 0;
    int rc = 0;
    for (size_t i = 0; i < n && !rc; i++) {
        const sp_colmap_image *r = find_image(ref, est->images[i].name);
        if (!r) continue;
        sp_camera ce, cr;
        if ((rc = sp_colmap_image_camera(est, i, &ce, err))) break;
        if ((rc = sp_colmap_image_camera(ref, (size_t)(r - ref->images), &cr, err))) break;
        sp_vec3 a = sp_camera_center(&ce), b = sp_camera_center(&cr);
        double *s = src + 3 * m, *d = dst + 3 * m;
        s[0] = a.x, s[1] = a.y, s[2] = a.z;
        d[0] = b.x, d[1] = b.y, d[2] = b.z;
        ri[m] = i;
        refs[m] = r;
        m++;
    }
    sp_align_fit fit = {0};
    if (!rc && m < SP_ALIGN_MIN_INLIERS)
        rc = sp_error_set(err, SP_E_FORMAT, "COLMAP registered %zu images the reference capture knows: "
                          "at least %d are needed to align", m, SP_ALIGN_MIN_INLIERS);
    if (!rc && (rc = sp_align_fit_robust(src, dst, m, 1, 0, &fit, err)))
        sp_error_prefix(err, "aligning COLMAP's %zu cameras to the reference: ", m);
    if (!rc) *fit_json = fit_report(&fit, est, ri, m);
    double *resid = rc ? NULL : malloc((m + 1) * sizeof *resid);
    if (!rc && !resid) rc = sp_error_set(err, SP_E_NOMEM, "out of memory");
    if (!rc) {
        double s = sqrt(fit.M[0] * fit.M[0] + fit.M[4] * fit.M[4] + fit.M[8] * fit.M[8]);
        res->scale = s;
        res->n_inliers = (int)fit.n_inliers;
        res->align_rms_inliers_m = fit.rms_inliers;
        res->align_threshold_m = fit.threshold;
        double sum2 = 0, rsum = 0, rmax = 0, worst = -1;
        for (size_t k = 0; k < m; k++) {
            sp_camera ce, cr;
            sp_colmap_image_camera(est, ri[k], &ce, NULL);
            sp_colmap_image_camera(ref, (size_t)(refs[k] - ref->images), &cr, NULL);
            move_pose(&ce, fit.M, s);
            sp_colmap_image_set_pose(&est->images[ri[k]], &ce);
            sp_vec3 a = sp_camera_center(&ce), b = sp_camera_center(&cr);
            double e = sp_v3_norm(sp_v3_sub(a, b)), re = rotation_error_deg(ce.R, cr.R);
            resid[k] = e;
            sum2 += e * e;
            rsum += re;
            if (re > rmax) rmax = re;
            if (e > worst) {
                worst = e;
                snprintf(res->worst_image, sizeof res->worst_image, "%s", est->images[ri[k]].name);
            }
        }
        res->ate_rms_m = sqrt(sum2 / m);
        res->ate_max_m = worst;
        res->rot_err_mean_deg = rsum / m;
        res->rot_err_max_deg = rmax;
        qsort(resid, m, sizeof *resid, cmp_double);
        res->ate_median_m = m % 2 ? resid[m / 2] : 0.5 * (resid[m / 2 - 1] + resid[m / 2]);
        /* images COLMAP registered that the reference lacks keep their moved pose too */
        for (size_t i = 0; i < n; i++) {
            if (find_image(ref, est->images[i].name)) continue;
            sp_camera ce;
            if (sp_colmap_image_camera(est, i, &ce, NULL)) continue;
            move_pose(&ce, fit.M, s);
            sp_colmap_image_set_pose(&est->images[i], &ce);
        }
        for (size_t p = 0; p < est->n_points; p++) {
            double *x = est->points[p].xyz, y[3];
            for (int r = 0; r < 3; r++) y[r] = fit.M[r * 4] * x[0] + fit.M[r * 4 + 1] * x[1] + fit.M[r * 4 + 2] * x[2] + fit.M[r * 4 + 3];
            memcpy(x, y, sizeof y);
        }
    }
    sp_align_fit_free(&fit);
    free(resid);
    free(src);
    free(ri);
    free(refs);
    return rc;
}
