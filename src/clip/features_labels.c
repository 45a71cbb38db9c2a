/* The `labels` feature source: labels.json (id -> class) and the label images that `semsplat
 * synth` writes, read as per-cell class weights. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cJSON.h>

#include "features_internal.h"
#include "semsplat/io.h"

void label_table_free(label_table *t)
{
    free(t->cls);
    free(t->class_names);
    free(t->class_of);
    memset(t, 0, sizeof *t);
}

int label_table_read(const char *path, label_table *t, sp_error *err)
{
    memset(t, 0, sizeof *t);
    cJSON *root = NULL;
    int rc = sp_json_read_file(path, &root, err);
    if (rc) return rc;
    const cJSON *labs = cJSON_GetObjectItemCaseSensitive(root, "labels"), *it;
    if (!cJSON_IsObject(labs) && !cJSON_IsArray(labs)) {
        cJSON_Delete(root);
        return sp_error_set(err, SP_E_FORMAT, "%s: missing \"labels\"", path);
    }
    int max_id = 0;
    cJSON_ArrayForEach(it, labs) {
        const cJSON *idv = cJSON_GetObjectItemCaseSensitive(it, "id");
        long id = cJSON_IsNumber(idv) ? (long)idv->valuedouble : (it->string ? strtol(it->string, NULL, 10) : -1);
        if (id < 1 || id > 65535) {
            cJSON_Delete(root);
            return sp_error_set(err, SP_E_FORMAT, "%s: label id %ld outside 1..65535", path, id);
        }
        if (id > max_id) max_id = (int)id;
    }
    t->n = max_id + 1;
    t->cls = calloc((size_t)t->n, sizeof *t->cls);
    t->class_names = calloc((size_t)t->n, sizeof *t->class_names);
    t->class_of = calloc((size_t)t->n, sizeof *t->class_of);
    if (!t->cls || !t->class_names || !t->class_of) {
        cJSON_Delete(root);
        label_table_free(t);
        return sp_error_set(err, SP_E_NOMEM, "out of memory");
    }
    /* id 0 (background, sky) is its own class */
    snprintf(t->cls[0], sizeof t->cls[0], "background");
    cJSON_ArrayForEach(it, labs) {
        const cJSON *idv = cJSON_GetObjectItemCaseSensitive(it, "id");
        long id = cJSON_IsNumber(idv) ? (long)idv->valuedouble : strtol(it->string, NULL, 10);
        const cJSON *c = cJSON_GetObjectItemCaseSensitive(it, "class");
        const cJSON *nm = cJSON_GetObjectItemCaseSensitive(it, "name");
        if (!cJSON_IsString(c)) c = cJSON_GetObjectItemCaseSensitive(it, "model");
        const char *s = cJSON_IsString(c) ? c->valuestring : cJSON_IsString(nm) ? nm->valuestring : NULL;
        if (!s) {
            cJSON_Delete(root);
            label_table_free(t);
            return sp_error_set(err, SP_E_FORMAT, "%s: label %ld has no \"class\"", path, id);
        }
        snprintf(t->cls[id], sizeof t->cls[id], "%s", s);
    }
    cJSON_Delete(root);
    for (int i = 0; i < t->n; i++) {
        if (!t->cls[i][0]) snprintf(t->cls[i], sizeof t->cls[i], "background");
        int k = 0;
        while (k < t->n_classes && strcmp(t->class_names[k], t->cls[i])) k++;
        if (k == t->n_classes) memcpy(t->class_names[t->n_classes++], t->cls[i], sizeof t->cls[i]);
        t->class_of[i] = k;
    }
    return 0;
}


int label_weights(const char *path, const label_table *t, int factor, float **w, int *mw, int *mh, sp_error *err)
{
    *w = NULL;
    sp_image img;
    int rc = sp_image_read(path, &img, err);
    if (rc) return rc;
    int W = img.width, H = img.height, nc = t->n_classes;
    *mw = (W + factor - 1) / factor;
    *mh = (H + factor - 1) / factor;
    size_t cells = (size_t)*mw * *mh;
    if ((double)cells * nc > (double)(1 << 28)) {
        sp_image_free(&img);
        return sp_error_set(err, SP_E_NOMEM, "%s: %zu cells x %d classes is too large a weight map", path, cells, nc);
    }
    float *m = calloc(cells * nc, sizeof *m);
    if (!m) {
        sp_image_free(&img);
        return sp_error_set(err, SP_E_NOMEM, "out of memory");
    }
    for (int y = 0; y < H && !rc; y++) {
        float *row = m + (size_t)(y / factor) * *mw * nc;
        for (int x = 0; x < W; x++) {
            size_t at = ((size_t)y * W + x) * img.channels;
            int id = img.bit_depth == 16 ? ((uint16_t *)img.data)[at] : ((uint8_t *)img.data)[at];
            if (id >= t->n) {
                rc = sp_error_set(err, SP_E_FORMAT, "%s: pixel (%d, %d) has label %d, labels.json knows ids up to %d",
                                  path, x, y, id, t->n - 1);
                break;
            }
            row[(size_t)(x / factor) * nc + t->class_of[id]] += 1.f;
        }
    }
    sp_image_free(&img);
    if (rc) {
        free(m);
        return rc;
    }
    for (size_t c = 0; c < cells; c++) {
        float *r = m + c * nc, n = 0;
        for (int k = 0; k < nc; k++) n += r[k];
        for (int k = 0; k < nc; k++) r[k] /= n;
    }
    *w = m;
    return 0;
}
