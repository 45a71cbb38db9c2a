/* Robust frame fits for `semsplat align --matches`: camera-centre (or point) matches between the
 * COLMAP frame and the world, of which some may be wrong (images COLMAP registered in the wrong
 * place). Least median of squares (Rousseeuw 1984) over Umeyama similarities of minimal samples
 * of 3 matches picks the fit most matches agree with, without a threshold to tune; its median
 * residual gives a noise scale, matches beyond the 99.9% bound of 3D Gaussian noise at that
 * scale are outliers, and the similarity is refitted on the inliers (twice, so the bound follows
 * the refit). Too few agreeing matches is a refusal, not a fit. */
#include <cjson/cJSON.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/io.h"
#include "semsplat/semantic.h"

/* Minimal samples: all triples when there are at most this many, else this many random ones
 * (with half the matches wrong a random triple is clean with probability 1/8; 20000 draws miss
 * every clean triple with probability (7/8)^20000, nothing). */
#define ALIGN_MAX_SAMPLES 20000

/* The length of a 3D isotropic Gaussian error (per-axis sigma) has median 1.5382 sigma and
 * 99.9% quantile 4.0331 sigma (chi distribution, 3 degrees of freedom): the inlier bound. At
 * 97.5% one good match in 40 would be named an outlier; at 99.9% one in a thousand. */
#define CHI3_MEDIAN 1.5382
#define CHI3_Q999 4.0331

void sp_align_matches_free(sp_align_matches *m)
{
    if (!m) return;
    free(m->src);
    free(m->dst);
    free(m->name);
    memset(m, 0, sizeof *m);
}

void sp_align_fit_free(sp_align_fit *f)
{
    if (!f) return;
    free(f->inlier);
    free(f->residual);
    memset(f, 0, sizeof *f);
}

static int grow(sp_align_matches *m, size_t *cap, const char *path, sp_error *err)
{
    if (m->n < *cap) return 0;
    size_t c = *cap ? *cap * 2 : 16;
    double *s = realloc(m->src, sizeof(double) * 3 * c);
    if (s) m->src = s;
    double *d = s ? realloc(m->dst, sizeof(double) * 3 * c) : NULL;
    if (d) m->dst = d;
    char(*nm)[256] = d ? realloc(m->name, sizeof *m->name * c) : NULL;
    if (nm) m->name = nm;
    if (!nm) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    *cap = c;
    return 0;
}

static long find_image(const sp_colmap_model *m, const char *name)
{
    for (size_t i = 0; m && i < m->n_images; i++)
        if (m->images[i].name && !strcmp(m->images[i].name, name)) return (long)i;
    return -1;
}

int sp_align_read_matches(const char *path, const char *colmap_dir, sp_align_matches *out,
                          sp_error *err)
{
    memset(out, 0, sizeof *out);
    sp_colmap_model m;
    memset(&m, 0, sizeof m);
    int rc = 0, have_model = 0;
    if (colmap_dir) {
        if ((rc = sp_colmap_read(colmap_dir, &m, err))) return rc;
        have_model = 1;
    }
    FILE *f = fopen(path, "r");
    if (!f) {
        sp_colmap_free(&m);
        return sp_error_set(err, SP_E_IO, "%s: cannot open", path);
    }
    char line[1024];
    size_t cap = 0;
    int lineno = 0;
    while (!rc && fgets(line, sizeof line, f)) {
        lineno++;
        char *p = line;
        while (*p == ' ' || *p == '\t') p++;
        if (*p == '#' || *p == '\n' || *p == '\r' || !*p) continue;
        double a[6];
        char name[256] = "";
        if (sscanf(p, "%lf %lf %lf %lf %lf %lf", &a[0], &a[1], &a[2], &a[3], &a[4], &a[5]) != 6) {
            if (sscanf(p, "%255s %lf %lf %lf", name, &a[3], &a[4], &a[5]) != 4) {
                rc = sp_error_set(err, SP_E_FORMAT, "%s:%d: expected 'IMAGE x y z' or 'x y z X Y Z'", path, lineno);
                break;
            }
            long i = find_image(have_model ? &m : NULL, name);
            if (i < 0) {
                rc = sp_error_set(err, SP_E_NOTFOUND, "%s:%d: image '%s' is not in the COLMAP model%s", path,
                                  lineno, name, have_model ? "" : " (pass --colmap)");
                break;
            }
            sp_camera cam;
            if ((rc = sp_colmap_image_camera(&m, (size_t)i, &cam, err))) break;
            sp_vec3 c = sp_camera_center(&cam);
            a[0] = c.x, a[1] = c.y, a[2] = c.z;
        }
        for (int k = 0; k < 6; k++)
            if (!isfinite(a[k])) rc = sp_error_set(err, SP_E_FORMAT, "%s:%d: a coordinate is not finite", path, lineno);
        if (rc || (rc = grow(out, &cap, path, err))) break;
        memcpy(out->src + 3 * out->n, a, sizeof(double) * 3);
        memcpy(out->dst + 3 * out->n, a + 3, sizeof(double) * 3);
        snprintf(out->name[out->n], sizeof out->name[0], "%s", name);
        out->n++;
    }
    fclose(f);
    sp_colmap_free(&m);
    if (rc) sp_align_matches_free(out);
    return rc;
}

static void residuals(const double M[16], const double *src, const double *dst, size_t n, double *r)
{
    for (size_t i = 0; i < n; i++) {
        double e2 = 0;
        for (int a = 0; a < 3; a++) {
            double y = M[a * 4 + 3];
            for (int c = 0; c < 3; c++) y += M[a * 4 + c] * src[3 * i + c];
            e2 += (y - dst[3 * i + a]) * (y - dst[3 * i + a]);
        }
        r[i] = sqrt(e2);
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median_of(const double *r, size_t n, double *tmp)
{
    memcpy(tmp, r, sizeof(double) * n);
    qsort(tmp, n, sizeof(double), cmp_double);
    return n % 2 ? tmp[n / 2] : 0.5 * (tmp[n / 2 - 1] + tmp[n / 2]);
}

static uint64_t next_rand(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return *s;
}

/* Refits on the matches flagged in `in` (copied into sel buffers); 0 or an error. */
static int refit(const double *src, const double *dst, size_t n, const uint8_t *in, int with_scale,
                 double *ss, double *sd, double M[16], sp_error *err)
{
    size_t k = 0;
    for (size_t i = 0; i < n; i++)
        if (in[i]) {
            memcpy(ss + 3 * k, src + 3 * i, sizeof(double) * 3);
            memcpy(sd + 3 * k, dst + 3 * i, sizeof(double) * 3);
            k++;
        }
    return sp_umeyama(ss, sd, k, with_scale, M, NULL, err);
}

/* Least median of squares over minimal samples: the similarity whose median residual is least. */
static int lmeds(const double *src, const double *dst, size_t n, int with_scale, double best_M[16],
                 double *best_med, double *r, double *tmp)
{
    size_t triples = n * (n - 1) * (n - 2) / 6;
    int exhaustive = n <= 64 && triples <= ALIGN_MAX_SAMPLES;
    size_t n_samples = exhaustive ? triples : ALIGN_MAX_SAMPLES;
    uint64_t rng = 0x9E3779B97F4A7C15ULL;
    size_t i = 0, j = 1, k = 2;
    *best_med = DBL_MAX;
    int found = 0;
    for (size_t s = 0; s < n_samples; s++) {
        if (!exhaustive) {
            i = next_rand(&rng) % n;
            do j = next_rand(&rng) % n; while (j == i);
            do k = next_rand(&rng) % n; while (k == i || k == j);
        }
        double ss[9], sd[9], M[16];
        size_t idx[3] = {i, j, k};
        for (int q = 0; q < 3; q++) {
            memcpy(ss + 3 * q, src + 3 * idx[q], sizeof(double) * 3);
            memcpy(sd + 3 * q, dst + 3 * idx[q], sizeof(double) * 3);
        }
        if (!sp_umeyama(ss, sd, 3, with_scale, M, NULL, NULL)) { /* collinear triples are skipped */
            residuals(M, src, dst, n, r);
            double med = median_of(r, n, tmp);
            if (med < *best_med) {
                *best_med = med;
                memcpy(best_M, M, sizeof(double) * 16);
                found = 1;
            }
        }
        if (exhaustive && ++k == n) { /* next triple i < j < k */
            if (++j == n - 1) ++i, j = i + 1;
            k = j + 1;
        }
    }
    return found;
}

/* RMS distance of the world points from their mean: the size the frame must be good at. */
static double world_spread(const double *p, size_t n)
{
    double c[3] = {0, 0, 0}, e2 = 0;
    for (size_t i = 0; i < n; i++)
        for (int a = 0; a < 3; a++) c[a] += p[3 * i + a] / (double)n;
    for (size_t i = 0; i < n; i++)
        for (int a = 0; a < 3; a++) e2 += (p[3 * i + a] - c[a]) * (p[3 * i + a] - c[a]);
    return sqrt(e2 / (double)n);
}

int sp_align_fit_robust(const double *src, const double *dst, size_t n, int with_scale,
                        double threshold, sp_align_fit *fit, sp_error *err)
{
    memset(fit, 0, sizeof *fit);
    if (n < SP_ALIGN_MIN_INLIERS)
        return sp_error_set(err, SP_E_ARG,
                            "align: %zu matches; a robust fit needs at least %d (3 fix a similarity, "
                            "the 4th is the first that can disagree)",
                            n, SP_ALIGN_MIN_INLIERS);
    fit->n = n;
    fit->inlier = calloc(n, 1);
    fit->residual = malloc(sizeof(double) * n);
    double *tmp = malloc(sizeof(double) * n), *ss = malloc(sizeof(double) * 3 * n),
           *sd = malloc(sizeof(double) * 3 * n);
    int rc = 0;
    if (!fit->inlier || !fit->residual || !tmp || !ss || !sd) {
        rc = sp_error_set(err, SP_E_NOMEM, "align: out of memory for %zu matches", n);
        goto done;
    }
    double M[16];
    if ((rc = sp_umeyama(src, dst, n, with_scale, M, &fit->rms_all, err))) goto done;
    double med;
    if (!lmeds(src, dst, n, with_scale, M, &med, fit->residual, tmp)) {
        rc = sp_error_set(err, SP_E_ARG, "align: every triple of the %zu matches is collinear", n);
        goto done;
    }
    fit->median_residual = med;
    /* Noise scale from the median (with Rousseeuw's small-sample factor), then the 97.5% bound;
     * a given threshold replaces it. A floor keeps exact data from rejecting rounding. */
    double sigma = med / CHI3_MEDIAN * (1.0 + 5.0 / (double)(n - 3));
    for (int pass = 0; pass < 3; pass++) {
        residuals(M, src, dst, n, fit->residual);
        double thr = threshold > 0 ? threshold : CHI3_Q999 * sigma;
        double scale = 0;
        for (size_t i = 0; i < 3 * n; i++) scale = fmax(scale, fabs(dst[i]));
        thr = fmax(thr, 1e-9 * (scale > 0 ? scale : 1));
        fit->threshold = thr;
        size_t m = 0;
        for (size_t i = 0; i < n; i++) m += fit->inlier[i] = fit->residual[i] <= thr;
        fit->n_inliers = m;
        if (m < 3 || pass == 2) break;
        if ((rc = refit(src, dst, n, fit->inlier, with_scale, ss, sd, M, err))) goto done;
        /* the inliers' own scale for the next bound (RMS of a 3D error = sqrt(3) sigma) */
        double e2 = 0;
        residuals(M, src, dst, n, fit->residual);
        for (size_t i = 0; i < n; i++) e2 += fit->inlier[i] ? fit->residual[i] * fit->residual[i] : 0;
        sigma = m > 3 ? sqrt(e2 / (double)(m - 3) / 3.0) : sigma;
    }
    memcpy(fit->M, M, sizeof M);
    double e2 = 0;
    for (size_t i = 0; i < n; i++) e2 += fit->inlier[i] ? fit->residual[i] * fit->residual[i] : 0;
    fit->rms_inliers = fit->n_inliers ? sqrt(e2 / (double)fit->n_inliers) : 0;
    size_t need = (n + 1) / 2;
    if (need < SP_ALIGN_MIN_INLIERS) need = SP_ALIGN_MIN_INLIERS;
    double spread = world_spread(dst, n);
    if (threshold <= 0 && fit->threshold > SP_ALIGN_MAX_BOUND_FRACTION * spread)
        rc = sp_error_set(err, SP_E_FORMAT,
                          "align: the %zu matches do not agree on one similarity: half of them are "
                          "off by %.3g or more, so the inlier bound would be %.3g, above %.0f%% of "
                          "the cameras' spread (%.3g); pass --inlier-m to accept a coarser frame",
                          n, fit->median_residual, fit->threshold, 100 * SP_ALIGN_MAX_BOUND_FRACTION,
                          spread);
    else if (fit->n_inliers < need)
        rc = sp_error_set(err, SP_E_FORMAT,
                          "align: only %zu of %zu matches agree on one similarity (within %.4g); "
                          "need at least %zu (half of them: least median of squares cannot tell "
                          "the right fit from a wrong one when most matches are wrong, and at "
                          "least %d)",
                          fit->n_inliers, n, fit->threshold, need, SP_ALIGN_MIN_INLIERS);
done:
    free(tmp), free(ss), free(sd);
    return rc;
}

char *sp_align_fit_json(const sp_align_fit *fit, const sp_align_matches *m, int with_scale)
{
    cJSON *o = cJSON_CreateObject();
    if (!o) return NULL;
    cJSON_AddStringToObject(o, "method", "lmeds+umeyama");
    cJSON_AddBoolToObject(o, "with_scale", with_scale);
    cJSON *M = cJSON_AddArrayToObject(o, "world_from_colmap");
    for (int r = 0; r < 4; r++) cJSON_AddItemToArray(M, cJSON_CreateDoubleArray(fit->M + 4 * r, 4));
    cJSON_AddNumberToObject(o, "matches", (double)fit->n);
    cJSON_AddNumberToObject(o, "inliers", (double)fit->n_inliers);
    cJSON_AddNumberToObject(o, "rms_inliers", fit->rms_inliers);
    cJSON_AddNumberToObject(o, "rms_all_least_squares", fit->rms_all);
    cJSON_AddNumberToObject(o, "median_residual", fit->median_residual);
    cJSON_AddNumberToObject(o, "inlier_threshold", fit->threshold);
    cJSON *out = cJSON_AddArrayToObject(o, "outliers");
    for (size_t i = 0; i < fit->n; i++) {
        if (fit->inlier[i]) continue;
        cJSON *e = cJSON_CreateObject();
        if (m && m->name && m->name[i][0]) cJSON_AddStringToObject(e, "image", m->name[i]);
        else cJSON_AddNumberToObject(e, "match", (double)i);
        cJSON_AddNumberToObject(e, "residual", fit->residual[i]);
        cJSON_AddItemToArray(out, e);
    }
    char *s = cJSON_Print(o);
    cJSON_Delete(o);
    return s;
}
