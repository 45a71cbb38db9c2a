/* Feature folders: reading features.json + PCA + maps (what lift/distill/query consume), and the
 * PCA encode/decode between the full CLIP space and the stored D dimensions. */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cJSON.h>

#include "semsplat/clip.h"
#include "semsplat/io.h"

void sp_features_free(sp_features *f)
{
    if (!f) return;
    for (size_t i = 0; i < f->n_images; i++) free(f->images[i].map);
    free(f->images);
    free(f->pca_mean);
    free(f->pca_basis);
    memset(f, 0, sizeof *f);
}

/* An integer field within int's range (other bounds are checked by the caller). */
static int json_int(const cJSON *o, const char *key, int *out)
{
    long v;
    if (sp_json_int(cJSON_GetObjectItemCaseSensitive(o, key), INT_MIN, INT_MAX, &v)) return -1;
    *out = (int)v;
    return 0;
}

static void json_str(const cJSON *o, const char *key, char *out, size_t cap)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    if (cJSON_IsString(v) && v->valuestring) snprintf(out, cap, "%s", v->valuestring);
    else out[0] = 0;
}

/* Reads an .npy of exactly `count` numbers into a new float buffer. */
static int read_npy_f32(const char *path, size_t count, float **out, sp_npy *shape_out,
                        sp_error *err)
{
    sp_npy a;
    int rc = sp_npy_read(path, &a, err);
    if (rc) return rc;
    if (sp_npy_count(&a) != count) {
        size_t n = sp_npy_count(&a);
        sp_npy_free(&a);
        return sp_error_set(err, SP_E_FORMAT, "%s: %zu values, expected %zu", path, n, count);
    }
    rc = sp_npy_to_f32(&a, out, err);
    if (shape_out) {
        shape_out->ndim = a.ndim;
        memcpy(shape_out->shape, a.shape, sizeof a.shape);
    }
    sp_npy_free(&a);
    return rc;
}

int sp_features_open(const char *dir, sp_features *f, sp_error *err)
{
    memset(f, 0, sizeof *f);
    char path[1200];
    snprintf(f->dir, sizeof f->dir, "%s", dir);
    sp_path_join(path, sizeof path, dir, "features.json");
    cJSON *root = NULL;
    int rc = sp_json_read_file(path, &root, err);
    if (rc) return rc;
    json_str(root, "source", f->source, sizeof f->source);
    json_str(root, "model", f->model_path, sizeof f->model_path);
    json_str(root, "label_embedding", f->label_embedding, sizeof f->label_embedding);
    if (!f->source[0]) {
        rc = sp_error_set(err, SP_E_FORMAT, "%s: missing \"source\"", path);
        goto fail;
    }
    if (json_int(root, "dim", &f->dim) || json_int(root, "full_dim", &f->full_dim) ||
        f->dim < 1 || f->full_dim < f->dim || f->full_dim > 65536) {
        rc = sp_error_set(err, SP_E_FORMAT, "%s: \"dim\"/\"full_dim\" missing or invalid (%d, %d)",
                          path, f->dim, f->full_dim);
        goto fail;
    }
    if ((rc = sp_feature_dim_check(f->dim, SP_E_FORMAT, path, err))) goto fail;
    const cJSON *imgs = cJSON_GetObjectItemCaseSensitive(root, "images");
    if (!cJSON_IsArray(imgs)) {
        rc = sp_error_set(err, SP_E_FORMAT, "%s: missing \"images\" array", path);
        goto fail;
    }
    f->n_images = (size_t)cJSON_GetArraySize(imgs);
    f->images = calloc(f->n_images ? f->n_images : 1, sizeof *f->images);
    if (!f->images) {
        rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
        goto fail;
    }
    size_t i = 0;
    const cJSON *it;
    cJSON_ArrayForEach(it, imgs) {
        sp_features_image *im = &f->images[i];
        json_str(it, "name", im->name, sizeof im->name);
        json_str(it, "map", im->map_file, sizeof im->map_file);
        if (!im->name[0] || !im->map_file[0] || json_int(it, "height", &im->h) ||
            json_int(it, "width", &im->w) || im->h < 1 || im->w < 1) {
            rc = sp_error_set(err, SP_E_FORMAT,
                              "%s: images[%zu] needs name, map, height, width", path, i);
            goto fail;
        }
        if (json_int(it, "image_height", &im->image_h)) im->image_h = 0;
        if (json_int(it, "image_width", &im->image_w)) im->image_w = 0;
        i++;
    }
    cJSON_Delete(root);
    root = NULL;
    sp_path_join(path, sizeof path, dir, "pca_mean.npy");
    if ((rc = read_npy_f32(path, (size_t)f->full_dim, &f->pca_mean, NULL, err))) goto fail;
    sp_path_join(path, sizeof path, dir, "pca_basis.npy");
    if ((rc = read_npy_f32(path, (size_t)f->dim * f->full_dim, &f->pca_basis, NULL, err)))
        goto fail;
    return 0;
fail:
    cJSON_Delete(root);
    sp_features_free(f);
    return rc;
}

int sp_features_load_map(sp_features *f, size_t i, sp_error *err)
{
    if (i >= f->n_images)
        return sp_error_set(err, SP_E_ARG, "features %s: image index %zu of %zu", f->dir, i,
                            f->n_images);
    sp_features_image *im = &f->images[i];
    if (im->map) return 0;
    char path[1400];
    sp_path_join(path, sizeof path, f->dir, im->map_file);
    sp_npy shape;
    int rc = read_npy_f32(path, (size_t)im->h * im->w * f->dim, &im->map, &shape, err);
    if (rc) return rc;
    if (shape.ndim != 3 || shape.shape[0] != (size_t)im->h || shape.shape[1] != (size_t)im->w ||
        shape.shape[2] != (size_t)f->dim) {
        free(im->map);
        im->map = NULL;
        return sp_error_set(err, SP_E_FORMAT, "%s: shape is not [%d][%d][%d] as features.json says",
                            path, im->h, im->w, f->dim);
    }
    return 0;
}

int sp_features_load_all(sp_features *f, sp_error *err)
{
    for (size_t i = 0; i < f->n_images; i++) {
        int rc = sp_features_load_map(f, i, err);
        if (rc) return rc;
    }
    return 0;
}

static const char *base_name(const char *p)
{
    const char *s = strrchr(p, '/');
    return s ? s + 1 : p;
}

/* Length of the name without its extension. */
static size_t stem_len(const char *p)
{
    const char *dot = strrchr(p, '.');
    return dot ? (size_t)(dot - p) : strlen(p);
}

long sp_features_find(const sp_features *f, const char *name)
{
    for (size_t i = 0; i < f->n_images; i++)
        if (!strcmp(f->images[i].name, name)) return (long)i;
    const char *b = base_name(name);
    size_t bl = stem_len(b);
    for (size_t i = 0; i < f->n_images; i++) {
        const char *c = base_name(f->images[i].name);
        if (stem_len(c) == bl && !strncmp(c, b, bl)) return (long)i;
    }
    return -1;
}

void sp_features_decode(const sp_features *f, const float *feat, float *full)
{
    int F = f->full_dim;
    memcpy(full, f->pca_mean, (size_t)F * sizeof *full);
    for (int k = 0; k < f->dim; k++) {
        const float *b = f->pca_basis + (size_t)k * F;
        float a = feat[k];
        for (int j = 0; j < F; j++) full[j] += a * b[j];
    }
}

void sp_features_encode(const sp_features *f, const float *full, float *feat)
{
    int F = f->full_dim;
    for (int k = 0; k < f->dim; k++) {
        const float *b = f->pca_basis + (size_t)k * F;
        double s = 0;
        for (int j = 0; j < F; j++) s += (double)b[j] * (full[j] - f->pca_mean[j]);
        feat[k] = (float)s;
    }
}
