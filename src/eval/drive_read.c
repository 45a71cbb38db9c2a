/* The parts of an agent answer's trace that the demo video and 5.3 show: the tool calls in one
 * line each, the heatmap, the trajectory map, previews and waypoints, the goal's outcome. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "drive.h"
#include "eval_internal.h"
#include "semsplat/io.h"


static int xy_of(const cJSON *p, double out[3])
{
    int n = cJSON_GetArraySize(p);
    if (!cJSON_IsArray(p) || n < 2) return 0;
    for (int i = 0; i < 3; i++) {
        const cJSON *v = cJSON_GetArrayItem(p, i);
        out[i] = i < n && cJSON_IsNumber(v) ? v->valuedouble : 0;
    }
    return 1;
}

static void copy(char *dst, size_t cap, const char *s)
{
    snprintf(dst, cap, "%s", s ? s : "");
}

/* "name(args)" with the arguments' braces and quotes dropped, then the outcome. */
static void tool_line(const sp_agent_trace_item *t, const cJSON *res, char *line, size_t cap)
{
    char args[160] = "";
    size_t k = 0;
    for (const char *p = t->arguments ? t->arguments : ""; *p && k + 1 < sizeof args; p++)
        if (*p != '"' && *p != '{' && *p != '}') args[k++] = *p == ',' ? ' ' : *p == ':' ? '=' : *p;
    args[k] = 0;
    const cJSON *e = cJSON_GetObjectItemCaseSensitive(res, "error");
    const char *code = ev_json_str(e, "code");
    snprintf(line, cap, "%s(%s) -> %s", t->tool ? t->tool : "?", args, code ? code : "ok");
}

static void read_trajectories(const cJSON *d, ev_answer_info *o)
{
    copy(o->map_image, sizeof o->map_image, ev_json_str(d, "map_image"));
    const cJSON *tr;
    int i = 0;
    cJSON_ArrayForEach(tr, cJSON_GetObjectItemCaseSensitive(d, "trajectories"))
    {
        const cJSON *p;
        cJSON_ArrayForEach(p, cJSON_GetObjectItemCaseSensitive(tr, "previews"))
        {
            if (cJSON_IsString(p) && o->n_previews < 12) copy(o->previews[o->n_previews++], sizeof o->previews[0], p->valuestring);
        }
        if (i >= 3) continue;
        o->traj_len[i] = ev_json_num(tr, "length_m");
        o->traj_score[i] = ev_json_num(cJSON_GetObjectItemCaseSensitive(tr, "score"), "total");
        int n = 0;
        cJSON_ArrayForEach(p, cJSON_GetObjectItemCaseSensitive(tr, "waypoints"))
        {
            double xy[3];
            if (n < 12 && xy_of(p, xy)) o->traj[i][n][0] = xy[0], o->traj[i][n][1] = xy[1], n++;
        }
        o->traj_n[i++] = n;
    }
    o->n_traj = i > 3 ? 3 : i;
    if (o->n_traj) o->planned = 1;
}

void ev_answer_read(const sp_agent_answer *a, ev_answer_info *o)
{
    memset(o, 0, sizeof *o);
    o->distance_to_goal_m = NAN;
    size_t used = 0;
    for (int i = 0; i < a->n_trace; i++) {
        const sp_agent_trace_item *t = &a->trace[i];
        cJSON *res = t->result ? cJSON_Parse(t->result) : NULL;
        const cJSON *d = cJSON_GetObjectItemCaseSensitive(res, "data");
        int ok = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(res, "ok"));
        char line[300];
        tool_line(t, res, line, sizeof line);
        if (used + strlen(line) + 2 < sizeof o->tools)
            used += (size_t)snprintf(o->tools + used, sizeof o->tools - used, "%s%s", used ? "\n" : "", line);
        const char *name = t->tool ? t->tool : "";
        if (!ok && !o->first_error[0]) {
            const cJSON *e = cJSON_GetObjectItemCaseSensitive(res, "error");
            snprintf(o->first_error, sizeof o->first_error, "%s: %s", name, ev_json_str(e, "message") ? ev_json_str(e, "message") : "failed");
        }
        if (!strcmp(name, "query_object_location") && ok) {
            o->found = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(d, "found"));
            copy(o->heatmap, sizeof o->heatmap, ev_json_str(d, "heatmap"));
            if (o->found) o->have_target = xy_of(cJSON_GetObjectItemCaseSensitive(d, "position"), o->target);
        } else if (!strcmp(name, "show_trajectories") && ok) {
            read_trajectories(d, o);
        } else if (!strcmp(name, "plan_path") && ok) {
            o->planned = 1;
        } else if (!strcmp(name, "send_nav2_goal")) {
            copy(o->goal_status, sizeof o->goal_status, ev_json_str(d, "status") ? ev_json_str(d, "status") : ok ? "" : "failed");
            o->distance_to_goal_m = ev_json_num(d, "distance_to_goal_m");
        }
        cJSON_Delete(res);
    }
}
