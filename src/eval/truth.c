/* A capture's ground_truth.json (synth writes it from the world file): each object's name, class
 * and world box. Every field is checked, so a malformed file names the object at fault. */
#include <cjson/cJSON.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/eval.h"
#include "semsplat/io.h"

static int read_vec3(const cJSON *o, const char *key, float out[3], const char *path, int idx,
                     sp_error *err)
{
    const cJSON *a = cJSON_GetObjectItemCaseSensitive(o, key);
    if (!cJSON_IsArray(a) || cJSON_GetArraySize(a) != 3)
        return sp_error_set(err, SP_E_FORMAT, "%s: object %d: \"%s\" is not 3 numbers", path, idx, key);
    for (int k = 0; k < 3; k++) {
        const cJSON *v = cJSON_GetArrayItem(a, k);
        /* finite as a float too: 1e308 is a finite double but an infinite position */
        if (!cJSON_IsNumber(v) || !(fabs(v->valuedouble) <= FLT_MAX))
            return sp_error_set(err, SP_E_FORMAT, "%s: object %d: \"%s\"[%d] is not a finite number "
                                "(within float range)", path, idx, key, k);
        out[k] = (float)v->valuedouble;
    }
    return 0;
}

static int read_object(const cJSON *o, sp_gt_object *g, const char *path, int idx, sp_error *err)
{
    const cJSON *nm = cJSON_GetObjectItemCaseSensitive(o, "name");
    const cJSON *cl = cJSON_GetObjectItemCaseSensitive(o, "class");
    if (!cJSON_IsString(nm) || !nm->valuestring[0] || !cJSON_IsString(cl) || !cl->valuestring[0])
        return sp_error_set(err, SP_E_FORMAT, "%s: object %d lacks a \"name\" or \"class\" string", path, idx);
    snprintf(g->name, sizeof g->name, "%s", nm->valuestring);
    snprintf(g->cls, sizeof g->cls, "%s", cl->valuestring);
    int rc = read_vec3(o, "aabb_min", g->aabb_min, path, idx, err);
    if (!rc) rc = read_vec3(o, "aabb_max", g->aabb_max, path, idx, err);
    if (rc) return rc;
    for (int k = 0; k < 3; k++) {
        if (g->aabb_min[k] > g->aabb_max[k])
            return sp_error_set(err, SP_E_FORMAT, "%s: object %d (%s): aabb_min[%d] > aabb_max[%d]",
                                path, idx, g->name, k, k);
        g->center[k] = (float)(0.5 * ((double)g->aabb_min[k] + g->aabb_max[k])); /* no float overflow */
    }
    if (cJSON_GetObjectItemCaseSensitive(o, "aabb_center"))
        rc = read_vec3(o, "aabb_center", g->center, path, idx, err);
    return rc;
}

int sp_ground_truth_read(const char *path, sp_ground_truth *gt, sp_error *err)
{
    memset(gt, 0, sizeof *gt);
    cJSON *root = NULL;
    int rc = sp_json_read_file(path, &root, err);
    if (rc) return rc;
    const cJSON *arr = cJSON_GetObjectItemCaseSensitive(root, "objects");
    const cJSON *world = cJSON_GetObjectItemCaseSensitive(root, "world");
    int count = cJSON_IsArray(arr) ? cJSON_GetArraySize(arr) : -1;
    if (count < 0) {
        cJSON_Delete(root);
        return sp_error_set(err, SP_E_FORMAT, "%s: no \"objects\" array", path);
    }
    gt->objects = calloc((size_t)(count ? count : 1), sizeof *gt->objects);
    if (!gt->objects) rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    if (cJSON_IsString(world)) snprintf(gt->world, sizeof gt->world, "%s", world->valuestring);
    const cJSON *o;
    int idx = 0;
    cJSON_ArrayForEach(o, arr)
    {
        if (rc || (rc = read_object(o, &gt->objects[idx], path, idx, err))) break;
        idx++;
    }
    gt->n = (size_t)idx;
    cJSON_Delete(root);
    if (rc) sp_ground_truth_free(gt);
    return rc;
}

void sp_ground_truth_free(sp_ground_truth *gt)
{
    if (!gt) return;
    free(gt->objects);
    memset(gt, 0, sizeof *gt);
}
