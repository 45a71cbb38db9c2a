/* The demo's synth stage: the world into a capture with ground truth (synth's defaults, seed 1,
 * as `semsplat synth` runs them). */
#include "eval/eval_internal.h"
#include "semsplat/synth.h"

int ev_demo_synth(const sp_demo_opts *o, const char *capture_dir, int views, int width, int height, int plan,
                  sp_error *err)
{
    sp_synth_load_opts lo = {.model_path = o->model_path, .skip_missing = o->skip_missing, .log = o->log};
    sp_world w;
    int rc = sp_synth_load_world(o->world, &lo, &w, err);
    if (rc) return rc;
    sp_synth_capture_opts co = {.n_views = views, .width = width, .height = height, .n_points = o->points, .seed = 1,
                                .n_threads = o->threads, .log = o->log,
                                .plan = plan == SP_DEMO_PLAN_WALK    ? SP_SYNTH_PLAN_WALK
                                        : plan == SP_DEMO_PLAN_DRIVE ? SP_SYNTH_PLAN_DRIVE
                                                                     : SP_SYNTH_PLAN_MIXED};
    rc = sp_synth_capture(&w, capture_dir, &co, err);
    sp_world_free(&w);
    return rc;
}
