/* Built when synth's dependencies (assimp, libxml2) are missing: the demo needs --capture. */
#include <string.h>

#include "eval/eval_internal.h"

int ev_demo_synth(const sp_demo_opts *o, const char *capture_dir, int views, int width, int height, int plan,
                  sp_error *err)
{
    (void)o, (void)capture_dir, (void)views, (void)width, (void)height, (void)plan;
    return sp_error_set(err, SP_E_UNSUPPORTED, "demo: synth is not built into this library (install "
                        "libassimp-dev and libxml2-dev, or pass an existing capture)");
}

int sp_ground_truth_from_world(const char *world, const char *model_path, int skip_missing,
                               const sp_log *log, sp_ground_truth *gt, sp_error *err)
{
    (void)model_path, (void)skip_missing, (void)log;
    memset(gt, 0, sizeof *gt);
    return sp_error_set(err, SP_E_UNSUPPORTED, "%s: reading a world needs synth, which this library "
                        "lacks (install libassimp-dev and libxml2-dev); use the capture's "
                        "ground_truth.json", world);
}
