/* The world on a model folder: the query engine and the navigation module behind the tools'
 * world interface. Navigation (issue 18) and the per-call query options (issue 16) are not on
 * main yet, so this adapter refuses with a clear message until they land; the tools, the
 * commitments and the dialogue loop are tested on a fake world meanwhile (tests/agent/). */
#include "agent_internal.h"

int agent_world_open_model(agent_world *out, const char *model_dir, const sp_log *log,
                           sp_error *err)
{
    out->ops = NULL;
    out->ctx = NULL;
    return sp_error_set(err, SP_E_UNSUPPORTED,
                        "%s: the agent's model-folder world needs the nav module (costmap, "
                        "planner, previews), which this build does not have yet",
                        model_dir ? model_dir : "(no model)");
}
