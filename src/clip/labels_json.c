/* A capture's labels.json (label id -> class), read by the `labels` feature source. */
#include <cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clip_internal.h"
#include "semsplat/io.h"

void clip_label_table_free(clip_label_table *t)
{
    free(t->cls);
    free(t->class_names);
    free(t->class_of);
    memset(t, 0, sizeof *t);
}

/* The id of one entry: its "id" field, else its key in the object form. */
static int entry_id(const char *path, const cJSON *it, long *id, sp_error *err)
{
    const cJSON *idv = cJSON_GetObjectItemCaseSensitive(it, "id");
    if (idv) {
        if (sp_json_int(idv, 1, 65535, id))
            return sp_error_set(err, SP_E_FORMAT, "%s: label \"id\" must be an integer in 1..65535", path);
        return SP_OK;
    }
    char *end = NULL;
    *id = it->string ? strtol(it->string, &end, 10) : -1;
    if (!it->string || end == it->string || *end || *id < 1 || *id > 65535)
        return sp_error_set(err, SP_E_FORMAT, "%s: label key '%.40s' is not an id in 1..65535 (and there is no \"id\")",
                            path, it->string ? it->string : "");
    return SP_OK;
}

static int fill(const char *path, const cJSON *labs, clip_label_table *t, sp_error *err)
{
    const cJSON *it;
    long max_id = 0, id;
    cJSON_ArrayForEach(it, labs) {
        int rc = entry_id(path, it, &id, err);
        if (rc) return rc;
        if (id > max_id) max_id = id;
    }
    t->n = (int)max_id + 1;
    t->cls = calloc((size_t)t->n, sizeof *t->cls);
    t->class_names = calloc((size_t)t->n, sizeof *t->class_names);
    t->class_of = calloc((size_t)t->n, sizeof *t->class_of);
    if (!t->cls || !t->class_names || !t->class_of) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    cJSON_ArrayForEach(it, labs) {
        entry_id(path, it, &id, err);
        const cJSON *c = cJSON_GetObjectItemCaseSensitive(it, "class");
        const cJSON *nm = cJSON_GetObjectItemCaseSensitive(it, "name");
        if (!cJSON_IsString(c)) c = cJSON_GetObjectItemCaseSensitive(it, "model");
        const char *s = cJSON_IsString(c) ? c->valuestring : cJSON_IsString(nm) ? nm->valuestring : NULL;
        if (!s) return sp_error_set(err, SP_E_FORMAT, "%s: label %ld has no \"class\"", path, id);
        if (t->class_of[id]) return sp_error_set(err, SP_E_FORMAT, "%s: label id %ld appears twice", path, id);
        t->class_of[id] = 1; /* seen; the class index is set below */
        snprintf(t->cls[id], sizeof t->cls[id], "%s", s);
    }
    /* id 0 (background, sky), unlisted ids and empty classes are the background class */
    for (int i = 0; i < t->n; i++) {
        if (!t->cls[i][0]) snprintf(t->cls[i], sizeof t->cls[i], "background");
        int k = 0;
        while (k < t->n_classes && strcmp(t->class_names[k], t->cls[i])) k++;
        if (k == t->n_classes) memcpy(t->class_names[t->n_classes++], t->cls[i], sizeof t->cls[i]);
        t->class_of[i] = k;
    }
    return SP_OK;
}

int clip_label_table_read(const char *path, clip_label_table *t, sp_error *err)
{
    memset(t, 0, sizeof *t);
    cJSON *root = NULL;
    int rc = sp_json_read_file(path, &root, err);
    if (rc) return rc;
    const cJSON *labs = cJSON_GetObjectItemCaseSensitive(root, "labels");
    if (!cJSON_IsObject(labs) && !cJSON_IsArray(labs))
        rc = sp_error_set(err, SP_E_FORMAT, "%s: missing \"labels\" (an object or array)", path);
    else
        rc = fill(path, labs, t, err);
    cJSON_Delete(root);
    if (rc) clip_label_table_free(t);
    return rc;
}
