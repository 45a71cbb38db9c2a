/* Tool arguments from untrusted bytes to a typed struct: parsed exactly, validated against the
 * tool's schema, defaults applied. The one door every model-made argument goes through. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "agent_internal.h"

static void get_vec(const cJSON *o, const char *key, double *v, int *n)
{
    for (int i = 0; i < 4; i++) v[i] = NAN;
    *n = 0;
    const cJSON *a = cJSON_GetObjectItemCaseSensitive(o, key), *e;
    cJSON_ArrayForEach(e, a) {
        if (*n < 4) v[(*n)++] = e->valuedouble;
    }
}

static double get_num(const cJSON *o, const char *key, double dflt)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    return cJSON_IsNumber(v) ? v->valuedouble : dflt;
}

static void get_str(const cJSON *o, const char *key, char *out, size_t cap)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    agent_clean_copy(out, cap, cJSON_IsString(v) ? v->valuestring : "");
}

/* The schema lets phrases be non-empty yet blank ("  "); nothing can be found by that. */
static int blank(const char *s)
{
    for (; *s; s++)
        if (*s != ' ') return 0;
    return 1;
}

int sp_agent_decode_tool_args(int tool, const char *bytes, size_t size, sp_agent_args *out,
                              sp_error *err)
{
    sp_error local;
    if (!err) err = &local;
    memset(out, 0, sizeof *out);
    int rc = sp_agent_validate_args(tool, bytes, size, err);
    if (rc) return rc;
    cJSON *o = agent_json_parse(bytes, size, "arguments", err);
    if (!o) return err->code;
    out->tool = tool;
    out->tolerance_m = get_num(o, "tolerance_m", SP_AGENT_DEFAULT_TOLERANCE_M);
    out->k = (int)get_num(o, "k", 3);
    out->instance = (int)get_num(o, "instance", 0);
    out->radius_m = get_num(o, "radius", SP_AGENT_DEFAULT_RADIUS_M);
    out->max_waypoints = (int)get_num(o, "max_waypoints", 8);
    out->x = get_num(o, "x", NAN);
    out->y = get_num(o, "y", NAN);
    out->yaw = get_num(o, "yaw", NAN);
    get_str(o, "plan_id", out->plan_id, sizeof out->plan_id);
    get_vec(o, "start", out->start, &out->start_n);
    get_vec(o, "goal", out->goal, &out->goal_n);
    int pose_n;
    get_vec(o, "pose", out->pose, &pose_n);
    const char *key = tool == SP_AGENT_TOOL_SHOW_TRAJECTORIES ? "target"
                      : tool == SP_AGENT_TOOL_EXPLORE         ? "region"
                                                              : "object_name";
    get_str(o, key, out->text, sizeof out->text);
    cJSON_Delete(o);
    int wants_text = tool == SP_AGENT_TOOL_QUERY_OBJECT || tool == SP_AGENT_TOOL_SHOW_TRAJECTORIES ||
                     tool == SP_AGENT_TOOL_DESCRIBE || tool == SP_AGENT_TOOL_EXPLORE;
    if (wants_text && blank(out->text)) {
        memset(out, 0, sizeof *out);
        return sp_error_set(err, SP_E_ARG, "%s: %s: must name something, not blanks",
                            sp_agent_tool_get(tool)->name, key);
    }
    return SP_OK;
}
