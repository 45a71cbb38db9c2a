/* Private pieces of the eval module. */
#ifndef SP_EVAL_INTERNAL_H
#define SP_EVAL_INTERNAL_H

#include "semsplat/eval.h"

/* The demo's synth stage: o->world rendered into capture_dir with views x width x height
 * (synth/demo_synth.c; without assimp/libxml2 the stub in nosynth/ fails with SP_E_UNSUPPORTED). */
int ev_demo_synth(const sp_demo_opts *o, const char *capture_dir, int views, int width, int height,
                  sp_error *err);

#endif
