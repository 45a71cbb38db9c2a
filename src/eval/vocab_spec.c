/* The queries of the open- versus closed-vocabulary comparison: the task's ten with the classes
 * that answer them, and a reader for users' own lists (the closed baseline's 80 COCO names are
 * nav's, sp_nav_coco_classes). */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/eval.h"
#include "semsplat/io.h"

/* The task's queries (assignment 5.2) and the world classes that are right answers to them. */
static const sp_eval_query_spec default_vocab[] = {
    {"refrigerator", 1, 0, 2, {"refrigerator", "fridge"}, 0, {{0}}, 0},
    {"couch", 1, 0, 3, {"couch", "sofa", "loveseat"}, 0, {{0}}, 0},
    {"dining table", 1, 0, 2, {"dining table", "table"}, 0, {{0}}, 0},
    {"chair", 1, 0, 5, {"chair", "dining chair", "armchair", "office chair", "stool"}, 0, {{0}}, 0},
    {"tv monitor", 1, 0, 4, {"tv", "television", "monitor", "tv monitor"}, 0, {{0}}, 0},
    {"kitchen counter", 0, 0, 2, {"kitchen counter", "counter"}, 0, {{0}}, 0},
    {"the doorway to the bedroom", 0, 0, 2, {"door", "doorway"}, 3, {"bed", "wardrobe", "nightstand"}, 2.5f},
    {"something to sit on", 0, 0, 10,
     {"chair", "dining chair", "armchair", "couch", "sofa", "bench", "stool", "office chair", "loveseat",
      "seat"}, 0, {{0}}, 0},
    {"area with appliances", 0, 1, 7,
     {"refrigerator", "fridge", "stove", "oven", "microwave", "dishwasher", "washing machine"}, 0, {{0}}, 0},
    {"wooden bookshelf", 0, 0, 3, {"bookshelf", "bookcase", "shelf"}, 0, {{0}}, 0},
};

const sp_eval_query_spec *sp_eval_default_vocab(size_t *n)
{
    *n = sizeof default_vocab / sizeof *default_vocab;
    return default_vocab;
}

static int read_names(const cJSON *arr, char (*out)[64], int cap, int *n, const char *path, int idx,
                      const char *key, sp_error *err)
{
    *n = 0;
    if (!arr) return 0;
    if (!cJSON_IsArray(arr) || cJSON_GetArraySize(arr) > cap)
        return sp_error_set(err, SP_E_FORMAT, "%s: vocabulary entry %d: \"%s\" must be an array of at "
                            "most %d class names", path, idx, key, cap);
    const cJSON *c;
    cJSON_ArrayForEach(c, arr)
    {
        if (!cJSON_IsString(c) || !c->valuestring[0] || strlen(c->valuestring) >= 64)
            return sp_error_set(err, SP_E_FORMAT, "%s: vocabulary entry %d: \"%s\" holds something "
                                "other than a class name of 1..63 characters", path, idx, key);
        snprintf(out[(*n)++], 64, "%s", c->valuestring);
    }
    return 0;
}

static int read_spec(const cJSON *e, sp_eval_query_spec *q, const char *path, int idx, sp_error *err)
{
    memset(q, 0, sizeof *q);
    const cJSON *t = cJSON_GetObjectItemCaseSensitive(e, "text");
    if (!cJSON_IsString(t) || !t->valuestring[0] || strlen(t->valuestring) >= sizeof q->text)
        return sp_error_set(err, SP_E_FORMAT, "%s: vocabulary entry %d: no \"text\" (1..127 characters)",
                            path, idx);
    snprintf(q->text, sizeof q->text, "%s", t->valuestring);
    const cJSON *c = cJSON_GetObjectItemCaseSensitive(e, "coco");
    q->coco = cJSON_IsBool(c) ? cJSON_IsTrue(c) : -1;
    q->region = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(e, "region"));
    int rc = read_names(cJSON_GetObjectItemCaseSensitive(e, "targets"), q->targets, SP_EVAL_MAX_TARGETS,
                        &q->n_targets, path, idx, "targets", err);
    if (!rc) rc = read_names(cJSON_GetObjectItemCaseSensitive(e, "near"), q->near, 4, &q->n_near, path, idx,
                             "near", err);
    if (rc) return rc;
    if (!q->n_targets) /* the text itself names the class */
        snprintf(q->targets[q->n_targets++], 64, "%.63s", q->text);
    const cJSON *nm = cJSON_GetObjectItemCaseSensitive(e, "near_m");
    q->near_m = cJSON_IsNumber(nm) ? (float)nm->valuedouble : 2.5f;
    if (!(q->near_m > 0 && q->near_m < 100))
        return sp_error_set(err, SP_E_FORMAT, "%s: vocabulary entry %d: near_m %g: expected 0..100 m",
                            path, idx, q->near_m);
    return 0;
}

int sp_eval_read_queries(const char *path, sp_eval_query_spec **specs, size_t *n, sp_error *err)
{
    *specs = NULL;
    *n = 0;
    cJSON *root = NULL;
    int rc = sp_json_read_file(path, &root, err);
    if (rc) return rc;
    const cJSON *arr = cJSON_GetObjectItemCaseSensitive(root, "vocabulary");
    int count = cJSON_IsArray(arr) ? cJSON_GetArraySize(arr) : -1;
    if (count <= 0) rc = sp_error_set(err, SP_E_FORMAT, "%s: no \"vocabulary\" array of queries", path);
    sp_eval_query_spec *s = rc ? NULL : calloc((size_t)count, sizeof *s);
    if (!rc && !s) rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    int i = 0;
    const cJSON *e;
    cJSON_ArrayForEach(e, arr)
    {
        if (rc) break;
        rc = read_spec(e, &s[i], path, i, err);
        i++;
    }
    cJSON_Delete(root);
    if (rc) {
        free(s);
        return rc;
    }
    *specs = s;
    *n = (size_t)count;
    return 0;
}
