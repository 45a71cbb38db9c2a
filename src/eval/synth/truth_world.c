/* Ground truth read from the world file itself (not from a capture): every top-level model that
 * is not structure and has geometry, with its class as synth names it and its world box. So a
 * model trained on any capture (COLMAP's poses, a robot's run) is scored against the world, and
 * moving an object in the world file moves its ground truth. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval/eval_internal.h"
#include "semsplat/synth.h"

int sp_ground_truth_from_world(const char *world, const char *model_path, int skip_missing,
                               const sp_log *log, sp_ground_truth *gt, sp_error *err)
{
    memset(gt, 0, sizeof *gt);
    sp_synth_load_opts lo = {.model_path = model_path, .skip_missing = skip_missing, .log = log};
    sp_world w;
    int rc = sp_synth_load_world(world, &lo, &w, err);
    if (rc) return sp_error_prefix(err, "ground truth: ");
    gt->objects = calloc(w.n_objects ? w.n_objects : 1, sizeof *gt->objects);
    if (!gt->objects) rc = sp_error_set(err, SP_E_NOMEM, "ground truth: out of memory");
    for (size_t i = 0; !rc && i < w.n_objects; i++) {
        const sp_synth_object *o = &w.objects[i];
        if (o->is_structure || !o->n_triangles) continue;
        sp_gt_object *g = &gt->objects[gt->n++];
        snprintf(g->name, sizeof g->name, "%s", o->name);
        snprintf(g->cls, sizeof g->cls, "%s", o->class_name);
        for (int k = 0; k < 3; k++) {
            g->aabb_min[k] = o->aabb_min[k];
            g->aabb_max[k] = o->aabb_max[k];
            g->center[k] = 0.5f * (o->aabb_min[k] + o->aabb_max[k]);
        }
    }
    snprintf(gt->world, sizeof gt->world, "%s", w.path);
    sp_world_free(&w);
    if (!rc && gt->n == 0) rc = sp_error_set(err, SP_E_FORMAT, "%s: no objects (only structure)", world);
    if (rc) sp_ground_truth_free(gt);
    return rc;
}
