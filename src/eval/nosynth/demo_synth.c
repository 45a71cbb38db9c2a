/* Built when synth's dependencies (assimp, libxml2) are missing: the demo needs --capture. */
#include "eval/eval_internal.h"

int ev_demo_synth(const sp_demo_opts *o, const char *capture_dir, int views, int width, int height,
                  sp_error *err)
{
    (void)o, (void)capture_dir, (void)views, (void)width, (void)height;
    return sp_error_set(err, SP_E_UNSUPPORTED, "demo: synth is not built into this library (install "
                        "libassimp-dev and libxml2-dev, or pass an existing capture)");
}
