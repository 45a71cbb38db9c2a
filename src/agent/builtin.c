/* The built-in brain: the offline, deterministic backend. It reads the user's command with the
 * built-in parser and drives the same tools an LLM would, one call per turn, through the same
 * validation and commitments (query -> pose -> plan -> goal for "go to"; query -> tool for the
 * others), then words the answer from the tools' results. It asks back when the parser does,
 * when a phrase matches several instances, and resolves the user's choice on the next command. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "agent_internal.h"

typedef enum { ST_START = 0, ST_QUERIED, ST_POSED, ST_PLANNED, ST_DONE } step_t;

typedef struct builtin {
    sp_agent_intent in;      /* the request being served */
    int step, n_calls;
    int instance;            /* 1-based pick */
    double goal[3];          /* the picked instance's position */
    sp_agent_intent pending; /* a request waiting for the user's choice */
    int has_pending;
    char last_target[SP_AGENT_MAX_PHRASE + 1];
} builtin;

static int say(sp_agent_reply *out, const char *text)
{
    memset(out, 0, sizeof *out);
    out->stop = SP_AGENT_STOP_END;
    snprintf(out->stop_raw, sizeof out->stop_raw, "end_turn");
    out->text = agent_strdup(text);
    return out->text ? SP_OK : SP_E_NOMEM;
}

/* One tool call (takes args). */
static int call(builtin *b, sp_agent_reply *out, int tool, cJSON *args)
{
    memset(out, 0, sizeof *out);
    out->stop = SP_AGENT_STOP_TOOL_USE;
    snprintf(out->stop_raw, sizeof out->stop_raw, "tool_use");
    out->calls = calloc(1, sizeof *out->calls);
    char *a = cJSON_PrintUnformatted(args);
    cJSON_Delete(args);
    if (!out->calls || !a) {
        free(out->calls);
        free(a);
        out->calls = NULL;
        return SP_E_NOMEM;
    }
    out->n_calls = 1;
    snprintf(out->calls[0].id, sizeof out->calls[0].id, "builtin_%d", ++b->n_calls);
    snprintf(out->calls[0].name, sizeof out->calls[0].name, "%s", sp_agent_tool_get(tool)->name);
    out->calls[0].arguments = a;
    return SP_OK;
}

static cJSON *obj_str(const char *k, const char *v)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, k, v);
    return o;
}

static double num(const cJSON *o, const char *k)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, k);
    return cJSON_IsNumber(v) ? v->valuedouble : NAN;
}

static const char *str(const cJSON *o, const char *k)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, k);
    return cJSON_IsString(v) ? v->valuestring : "";
}

static void vec(const cJSON *a, double *v, int n)
{
    for (int i = 0; i < n; i++) {
        const cJSON *e = cJSON_GetArrayItem(a, i);
        v[i] = cJSON_IsNumber(e) ? e->valuedouble : NAN;
    }
}

/* The text of a tool's error: "message" (and nearest matches when there are some). */
static void error_text(const cJSON *res, char *out, size_t cap)
{
    const cJSON *e = cJSON_GetObjectItemCaseSensitive(res, "error");
    const cJSON *m = cJSON_GetObjectItemCaseSensitive(cJSON_GetObjectItemCaseSensitive(res, "data"), "nearest_matches");
    size_t j = (size_t)snprintf(out, cap, "%s", str(e, "message"));
    if (cJSON_GetArraySize(m) > 0 && j < cap) {
        j += (size_t)snprintf(out + j, cap - j, ". The nearest matches in this map:");
        int i = 0;
        const cJSON *s;
        cJSON_ArrayForEach(s, m) if (cJSON_IsString(s) && j < cap)
            j += (size_t)snprintf(out + j, cap - j, "%s %s", i++ ? "," : "", s->valuestring);
        if (j < cap) snprintf(out + j, cap - j, ". Did you mean one of them?");
    } else if (j < cap) {
        snprintf(out + j, cap - j, ".");
    }
}

/* The 1-based instance the selector picks among n (0 = none, -1 = out of range). */
static int pick(const sp_agent_intent *in, const cJSON *instances)
{
    int n = cJSON_GetArraySize(instances);
    switch (in->selector) {
    case SP_AGENT_SELECT_NEAREST:
    case SP_AGENT_SELECT_ANY: return 1;
    case SP_AGENT_SELECT_FARTHEST: return n;
    case SP_AGENT_SELECT_INDEX: return in->index <= n ? in->index : -1;
    default: break;
    }
    if (in->anchor[0]) { /* "the one in the kitchen" */
        int i = 1;
        const cJSON *e;
        cJSON_ArrayForEach(e, instances) {
            if (strstr(str(e, "region"), in->anchor)) return i;
            i++;
        }
    }
    return 0;
}

static int after_query(builtin *b, const cJSON *res, sp_agent_reply *out)
{
    char text[2048];
    const cJSON *d = cJSON_GetObjectItemCaseSensitive(res, "data");
    const cJSON *inst = cJSON_GetObjectItemCaseSensitive(d, "instances");
    if (!cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(res, "ok"))) {
        error_text(res, text, sizeof text);
        return say(out, text);
    }
    if (!cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(d, "found"))) {
        size_t j = (size_t)snprintf(text, sizeof text,
                                    "I could not find the %s in this map (best confidence %.2f, a match needs %.2f).",
                                    b->in.target, num(d, "confidence"), num(d, "min_confidence"));
        const cJSON *m = cJSON_GetObjectItemCaseSensitive(d, "nearest_matches"), *s;
        if (cJSON_GetArraySize(m) > 0 && j < sizeof text) {
            j += (size_t)snprintf(text + j, sizeof text - j, " The nearest matches:");
            int i = 0;
            cJSON_ArrayForEach(s, m) if (cJSON_IsString(s) && j < sizeof text)
                j += (size_t)snprintf(text + j, sizeof text - j, "%s %s", i++ ? "," : "", s->valuestring);
            if (j < sizeof text) snprintf(text + j, sizeof text - j, ". Did you mean one of them?");
        }
        return say(out, text);
    }
    int n = cJSON_GetArraySize(inst), k = pick(&b->in, inst);
    if (b->in.kind == SP_AGENT_INTENT_LOCATE) {
        size_t j = (size_t)snprintf(text, sizeof text, "I found %d match%s for the %s (confidence %.2f):",
                                    n, n == 1 ? "" : "es", b->in.target, num(d, "confidence"));
        const cJSON *e;
        int i = 1;
        cJSON_ArrayForEach(e, inst) {
            double p[3];
            vec(cJSON_GetObjectItemCaseSensitive(e, "position"), p, 3);
            if (j < sizeof text)
                j += (size_t)snprintf(text + j, sizeof text - j, " %d) at (%.2f, %.2f, %.2f), %.1f m away, in the %s%s",
                                      i, p[0], p[1], p[2], num(e, "distance_m"), str(e, "region"), i < n ? ";" : ".");
            i++;
        }
        snprintf(b->last_target, sizeof b->last_target, "%s", b->in.target);
        return say(out, text);
    }
    if (k < 0) {
        snprintf(text, sizeof text, "There are only %d %s matches; which one do you mean (1 to %d)?", n,
                 b->in.target, n);
        b->pending = b->in, b->has_pending = 1;
        b->pending.selector = SP_AGENT_SELECT_NONE;
        return say(out, text);
    }
    if (k == 0 && n > 1) {
        snprintf(text, sizeof text, "%s", str(d, "ask_user"));
        b->pending = b->in, b->has_pending = 1;
        return say(out, text);
    }
    b->instance = k ? k : 1;
    const cJSON *chosen = cJSON_GetArrayItem(inst, b->instance - 1);
    vec(cJSON_GetObjectItemCaseSensitive(chosen, "position"), b->goal, 3);
    snprintf(b->last_target, sizeof b->last_target, "%s", b->in.target);
    cJSON *args = obj_str(b->in.kind == SP_AGENT_INTENT_DESCRIBE ? "object_name" : "target", b->in.target);
    if (b->in.kind == SP_AGENT_INTENT_GOTO) {
        cJSON_Delete(args);
        b->step = ST_QUERIED;
        return call(b, out, SP_AGENT_TOOL_GET_POSE, cJSON_CreateObject());
    }
    if (n > 1) cJSON_AddNumberToObject(args, "instance", b->instance);
    b->step = ST_DONE;
    if (b->in.kind == SP_AGENT_INTENT_TRAJECTORIES) {
        cJSON_AddNumberToObject(args, "k", b->in.k);
        return call(b, out, SP_AGENT_TOOL_SHOW_TRAJECTORIES, args);
    }
    cJSON_AddNumberToObject(args, "radius", fmin(fmax(b->in.radius_m, 0.2), 5.0));
    return call(b, out, SP_AGENT_TOOL_DESCRIBE, args);
}

static int plan_call(builtin *b, const cJSON *res, sp_agent_reply *out)
{
    const cJSON *d = cJSON_GetObjectItemCaseSensitive(res, "data");
    char text[1024];
    if (!cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(res, "ok"))) {
        error_text(res, text, sizeof text);
        return say(out, text);
    }
    cJSON *args = cJSON_CreateObject();
    double start[4] = {num(d, "x"), num(d, "y"), num(d, "z"), num(d, "yaw")};
    cJSON_AddItemToObject(args, "start", agent_json_numbers(start, 4));
    cJSON_AddItemToObject(args, "goal", agent_json_numbers(b->goal, 3));
    b->step = ST_POSED;
    return call(b, out, SP_AGENT_TOOL_PLAN_PATH, args);
}

static int goal_call(builtin *b, const cJSON *res, sp_agent_reply *out)
{
    const cJSON *d = cJSON_GetObjectItemCaseSensitive(res, "data");
    char text[1024];
    if (!cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(res, "ok"))) {
        char e[800];
        error_text(res, e, sizeof e);
        snprintf(text, sizeof text, "I cannot plan a path to the %s: %s", b->in.target, e);
        return say(out, text);
    }
    double end[4];
    vec(cJSON_GetObjectItemCaseSensitive(d, "end"), end, 4);
    cJSON *args = cJSON_CreateObject();
    cJSON_AddNumberToObject(args, "x", end[0]);
    cJSON_AddNumberToObject(args, "y", end[1]);
    cJSON_AddNumberToObject(args, "yaw", end[3]);
    cJSON_AddStringToObject(args, "plan_id", str(d, "plan_id"));
    b->step = ST_PLANNED;
    return call(b, out, SP_AGENT_TOOL_SEND_GOAL, args);
}

static int goal_done(builtin *b, const cJSON *res, sp_agent_reply *out)
{
    const cJSON *d = cJSON_GetObjectItemCaseSensitive(res, "data");
    const cJSON *fp = cJSON_GetObjectItemCaseSensitive(d, "final_pose");
    char text[1024], e[800];
    if (!cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(res, "ok")) && !d) {
        error_text(res, e, sizeof e);
        snprintf(text, sizeof text, "I did not move: %s", e);
        return say(out, text);
    }
    const char *status = str(d, "status");
    if (!strcmp(status, "succeeded"))
        snprintf(text, sizeof text,
                 "Arrived at the %s: the robot drove %.1f m along %s in %.0f s and stopped at (%.2f, %.2f) "
                 "facing %.0f deg, %.2f m from the plan's goal; the %s is at (%.2f, %.2f, %.2f).",
                 b->in.target, num(d, "distance_driven_m"), str(d, "plan_id"), num(d, "elapsed_s"),
                 num(fp, "x"), num(fp, "y"), num(fp, "yaw") * 180 / M_PI, num(d, "distance_to_goal_m"),
                 b->in.target, b->goal[0], b->goal[1], b->goal[2]);
    else
        snprintf(text, sizeof text, "The goal to the %s ended %s after %.1f m, at (%.2f, %.2f)%s%s.",
                 b->in.target, status, num(d, "distance_driven_m"), num(fp, "x"), num(fp, "y"),
                 str(d, "message")[0] ? ": " : "", str(d, "message"));
    return say(out, text);
}

static int trajectories_text(builtin *b, const cJSON *d, sp_agent_reply *out)
{
    char text[3072];
    const cJSON *tr = cJSON_GetObjectItemCaseSensitive(d, "trajectories"), *t;
    int n = cJSON_GetArraySize(tr);
    size_t j = (size_t)snprintf(text, sizeof text, "%d trajectories to the %s (asked for %.0f), best first:", n,
                                b->in.target, num(d, "asked"));
    cJSON_ArrayForEach(t, tr) {
        const cJSON *sc = cJSON_GetObjectItemCaseSensitive(t, "score");
        if (j < sizeof text)
            j += (size_t)snprintf(text + j, sizeof text - j, " #%.0f %s: %.1f m, min clearance %.2f m, score %.2f, %d previews;",
                                  num(t, "rank"), str(t, "plan_id"), num(t, "length_m"), num(sc, "min_clearance_m"),
                                  num(sc, "total"), cJSON_GetArraySize(cJSON_GetObjectItemCaseSensitive(t, "previews")));
    }
    if (str(d, "note")[0] && j < sizeof text) j += (size_t)snprintf(text + j, sizeof text - j, " %s.", str(d, "note"));
    if (str(d, "map_image")[0] && j < sizeof text) snprintf(text + j, sizeof text - j, " Map: %s", str(d, "map_image"));
    return say(out, text);
}

static int explore_text(builtin *b, const cJSON *d, sp_agent_reply *out)
{
    char text[2048];
    const cJSON *w = cJSON_GetObjectItemCaseSensitive(d, "waypoints"), *e;
    size_t j = (size_t)snprintf(text, sizeof text, "Exploration tour of the %s: %d waypoints,", str(d, "region"),
                                cJSON_GetArraySize(w));
    cJSON_ArrayForEach(e, w) {
        double p[4];
        vec(e, p, 4);
        if (j < sizeof text) j += (size_t)snprintf(text + j, sizeof text - j, " (%.2f, %.2f)", p[0], p[1]);
    }
    if (j < sizeof text)
        snprintf(text + j, sizeof text - j, "; %.1f m in all as %s. I have not moved.", num(d, "tour_length_m"),
                 str(d, "plan_id"));
    return say(out, text);
}

static int final_text(builtin *b, const cJSON *res, sp_agent_reply *out)
{
    const cJSON *d = cJSON_GetObjectItemCaseSensitive(res, "data");
    const char *tool = str(res, "tool");
    char text[1024];
    if (!cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(res, "ok"))) {
        error_text(res, text, sizeof text);
        return say(out, text);
    }
    if (!strcmp(tool, "show_trajectories")) return trajectories_text(b, d, out);
    if (!strcmp(tool, "describe_surroundings")) return say(out, str(d, "sentence"));
    if (!strcmp(tool, "explore_region")) return explore_text(b, d, out);
    snprintf(text, sizeof text, "Stopped; the goal is now %s.", str(d, "status"));
    return say(out, text);
}

/* Starts serving b->in (already resolved against pending choices and pronouns). */
static int start(builtin *b, sp_agent_reply *out)
{
    b->step = ST_START;
    switch (b->in.kind) {
    case SP_AGENT_INTENT_CANCEL:
        b->step = ST_DONE;
        return call(b, out, SP_AGENT_TOOL_CANCEL, cJSON_CreateObject());
    case SP_AGENT_INTENT_EXPLORE:
        b->step = ST_DONE;
        snprintf(b->last_target, sizeof b->last_target, "%s", b->in.target);
        return call(b, out, SP_AGENT_TOOL_EXPLORE, obj_str("region", b->in.target));
    case SP_AGENT_INTENT_GOTO:
    case SP_AGENT_INTENT_TRAJECTORIES:
    case SP_AGENT_INTENT_DESCRIBE:
    case SP_AGENT_INTENT_LOCATE:
        return call(b, out, SP_AGENT_TOOL_QUERY_OBJECT, obj_str("object_name", b->in.target));
    default:
        return say(out, b->in.question[0] ? b->in.question : "What would you like me to do?");
    }
}

static int on_user(builtin *b, const char *text, sp_agent_reply *out)
{
    sp_agent_intent in;
    sp_agent_parse(text, &in);
    if (in.kind == SP_AGENT_INTENT_SELECT) {
        if (!b->has_pending) return say(out, "I have not asked you to choose anything. What would you like me to do?");
        sp_agent_intent p = b->pending;
        p.selector = in.selector;
        p.index = in.index;
        snprintf(p.anchor, sizeof p.anchor, "%s", in.anchor);
        in = p;
    }
    if (in.kind != SP_AGENT_INTENT_ASK) b->has_pending = 0;
    if (in.pronoun) {
        if (!b->last_target[0])
            return say(out, "I have nothing to refer \"it\" or \"there\" to yet: which object do you mean?");
        snprintf(in.target, sizeof in.target, "%s", b->last_target);
    }
    b->in = in;
    return start(b, out);
}

static int builtin_next(void *ctx, const agent_convo *c, sp_agent_reply *out, agent_stats *st,
                        sp_error *err)
{
    builtin *b = ctx;
    if (c->n == 0) return sp_error_set(err, SP_E_ARG, "builtin: empty conversation");
    const agent_msg *last = &c->m[c->n - 1];
    int rc;
    if (last->role == AGENT_MSG_USER) {
        rc = on_user(b, last->text, out);
    } else {
        cJSON *res = last->role == AGENT_MSG_TOOL ? cJSON_Parse(last->text) : NULL;
        if (!res) return sp_error_set(err, SP_E_FORMAT, "builtin: expected a tool result");
        if (b->step == ST_START) rc = after_query(b, res, out);
        else if (b->step == ST_QUERIED) rc = plan_call(b, res, out);
        else if (b->step == ST_POSED) rc = goal_call(b, res, out);
        else if (b->step == ST_PLANNED) rc = goal_done(b, res, out);
        else rc = final_text(b, res, out);
        cJSON_Delete(res);
    }
    if (rc) sp_error_set(err, rc, "builtin: out of memory");
    return rc;
}

static void builtin_close(void *ctx) { free(ctx); }

int agent_brain_builtin(agent_brain *out, sp_error *err)
{
    builtin *b = calloc(1, sizeof *b);
    if (!b) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    out->name = "builtin";
    out->next = builtin_next;
    out->close = builtin_close;
    out->ctx = b;
    return SP_OK;
}
