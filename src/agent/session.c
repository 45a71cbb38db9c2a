/* The session: opens the world, the robot and the brain, and runs the dialogue loop (brain turn
 * -> tool calls validated and executed -> results back -> ... -> an answer), bounded in turns. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "agent_internal.h"

#define AGENT_CONVO_MAX 80 /* messages kept across commands */

sp_agent_config sp_agent_config_default(void)
{
    sp_agent_config c;
    memset(&c, 0, sizeof c);
    c.brain = SP_AGENT_BRAIN_BUILTIN;
    c.llm.timeout_s = 60;
    c.llm.connect_timeout_s = 10;
    c.llm.max_retries = 2;
    c.llm.retry_base_s = 0.5;
    c.llm.retry_max_s = 30;
    c.llm.max_tokens = 1024;
    c.llm.max_steps = 8;
    c.llm.anthropic_version = "2023-06-01";
    c.max_speed_mps = 0.4;
    c.max_goal_distance_m = 30;
    c.goal_match_m = 0.25;
    c.goal_match_rad = 0.35;
    c.plan_start_m = 0.5;
    c.goal_timeout_s = 300;
    sp_ros_options_default(&c.ros);
    c.ros_wait_s = 10;
    return c;
}

static double clampd(double v, double lo, double hi, double dflt)
{
    if (!isfinite(v)) return dflt;
    return v < lo ? lo : v > hi ? hi : v;
}

static void close_parts(agent_world *w, sp_agent_robot *r)
{
    if (w->ops && w->ops->close) w->ops->close(w->ctx);
    memset(w, 0, sizeof *w);
    sp_agent_robot_close(r);
}

int agent_session_open_world(sp_agent_session **out, const sp_agent_config *cfg, agent_world world,
                             sp_agent_robot robot, sp_error *err)
{
    *out = NULL;
    sp_agent_session *s = calloc(1, sizeof *s);
    if (!s) {
        close_parts(&world, &robot);
        return sp_error_set(err, SP_E_NOMEM, "out of memory");
    }
    s->world = world;
    s->robot = robot;
    s->cfg = *cfg;
    s->cfg.max_speed_mps = agent_clamp_speed(cfg->max_speed_mps);
    s->cfg.max_goal_distance_m = clampd(cfg->max_goal_distance_m, 0.1, 100, 30);
    s->cfg.goal_match_m = clampd(cfg->goal_match_m, 0.01, 1.0, 0.25);
    s->cfg.goal_match_rad = clampd(cfg->goal_match_rad, 0.01, M_PI, 0.35);
    s->cfg.plan_start_m = clampd(cfg->plan_start_m, 0.05, 5, 0.5);
    s->cfg.goal_timeout_s = clampd(cfg->goal_timeout_s, 1, 3600, 300);
    if (s->cfg.llm.max_steps <= 0 || s->cfg.llm.max_steps > 32) s->cfg.llm.max_steps = 8;
    snprintf(s->out_dir, sizeof s->out_dir, "%s", cfg->out_dir ? cfg->out_dir : "");
    snprintf(s->model_dir, sizeof s->model_dir, "%s", cfg->model_dir ? cfg->model_dir : "");
    /* the config's strings are the caller's: keep only copies */
    s->cfg.out_dir = s->out_dir[0] ? s->out_dir : NULL;
    s->cfg.model_dir = s->model_dir[0] ? s->model_dir : NULL;
    s->cfg.llm.preset = s->cfg.llm.base_url = s->cfg.llm.model = s->cfg.llm.anthropic_version = NULL;
    sp_ros_options_default(&s->cfg.ros); /* read by the robot at open; no caller strings kept */
    int rc = SP_OK;
    if (!world.ops || !robot.ops)
        rc = sp_error_set(err, SP_E_ARG, "agent: a world and a robot are needed");
    if (!rc && s->out_dir[0]) rc = sp_mkdirs(s->out_dir, err);
    if (!rc)
        rc = cfg->brain == SP_AGENT_BRAIN_BUILTIN ? agent_brain_builtin(&s->brain, err)
                                                  : agent_brain_llm(&s->brain, cfg->brain, &cfg->llm, cfg->log, err);
    if (rc) {
        sp_agent_session_close(s);
        return rc;
    }
    *out = s;
    return SP_OK;
}

static int open_world(const sp_agent_config *cfg, agent_world *w, sp_error *err)
{
    memset(w, 0, sizeof *w);
    if (!cfg->model_dir) return sp_error_set(err, SP_E_ARG, "agent: a model folder is needed (--model DIR)");
    return agent_world_open_model(w, cfg, err);
}

int sp_agent_session_open_with_robot(sp_agent_session **out, const sp_agent_config *cfg,
                                     sp_agent_robot robot, sp_error *err)
{
    sp_error local;
    if (!err) err = &local;
    *out = NULL;
    agent_world w;
    int rc = open_world(cfg, &w, err);
    if (rc) {
        sp_agent_robot_close(&robot);
        return rc;
    }
    return agent_session_open_world(out, cfg, w, robot, err);
}

/* The world first: the offline robot starts where the capture started when no start is given. */
int sp_agent_session_open(sp_agent_session **out, const sp_agent_config *cfg, sp_error *err)
{
    sp_error local;
    if (!err) err = &local;
    *out = NULL;
    agent_world w;
    sp_agent_robot robot;
    int rc = open_world(cfg, &w, err);
    if (rc) return rc;
    if (cfg->use_ros) {
        rc = agent_robot_open_ros(&robot, cfg, err);
    } else {
        sp_agent_offline_opts o = sp_agent_offline_opts_default();
        if (cfg->have_start) o.start = cfg->start;
        else if (w.ops->default_start) rc = w.ops->default_start(w.ctx, &o.start, err);
        if (!rc) rc = sp_agent_robot_offline(&robot, &o, err);
    }
    if (rc) {
        if (w.ops->close) w.ops->close(w.ctx);
        return rc;
    }
    return agent_session_open_world(out, cfg, w, robot, err);
}

void sp_agent_session_close(sp_agent_session *s)
{
    if (!s) return;
    if (s->brain.close) s->brain.close(s->brain.ctx);
    close_parts(&s->world, &s->robot);
    agent_convo_free(&s->convo);
    agent_commit_free(s);
    free(s);
}

void sp_agent_session_cancel(sp_agent_session *s)
{
    if (s) s->cancel_requested = 1;
}

static int trace_add(sp_agent_answer *a, const sp_agent_call *c, const char *result, int is_error, double ms)
{
    sp_agent_trace_item *t = realloc(a->trace, (size_t)(a->n_trace + 1) * sizeof *t);
    if (!t) return SP_E_NOMEM;
    a->trace = t;
    sp_agent_trace_item *it = &t[a->n_trace++];
    char bad[300];
    snprintf(bad, sizeof bad, "(unreadable: %s)", c->args_error);
    it->tool = agent_strdup(c->name);
    it->call_id = agent_strdup(c->id);
    it->arguments = agent_strdup(c->arguments ? c->arguments : bad);
    it->result = agent_strdup(result);
    it->is_error = is_error;
    it->ms = ms;
    return SP_OK;
}

static int ends_with_question(const char *t)
{
    size_t n = t ? strlen(t) : 0;
    while (n > 0 && (t[n - 1] == ' ' || t[n - 1] == '\n' || t[n - 1] == '"')) n--;
    return n > 0 && t[n - 1] == '?';
}

/* Runs the calls of the assistant turn just added to the conversation. */
static int run_calls(sp_agent_session *s, sp_agent_answer *a)
{
    int idx = s->convo.n - 1;
    for (int i = 0; i < s->convo.m[idx].n_calls; i++) {
        const sp_agent_call *c = &s->convo.m[idx].calls[i]; /* stays valid: tool msgs push after */
        double t0 = sp_time_now();
        int is_error = 0;
        char *res = agent_tool_run(s, c, &is_error);
        if (!res) return SP_E_NOMEM;
        sp_logf(s->cfg.log, SP_LOG_DEBUG, "tool %s(%s) -> %.200s", c->name, c->arguments ? c->arguments : "?", res);
        char id[96], name[65];
        snprintf(id, sizeof id, "%s", c->id);
        snprintf(name, sizeof name, "%s", c->name);
        int rc = trace_add(a, c, res, is_error, (sp_time_now() - t0) * 1e3);
        if (!rc) rc = agent_convo_tool(&s->convo, id, name, res, is_error); /* may move convo.m */
        free(res);
        if (rc) return rc;
    }
    return SP_OK;
}

static int write_answer(sp_agent_session *s, sp_agent_answer *a, sp_error *err)
{
    if (!s->out_dir[0]) return SP_OK;
    snprintf(a->json_path, sizeof a->json_path, "%s/answer_%03d.json", s->out_dir, s->n_answers);
    char *j = sp_agent_answer_json(a);
    if (!j) return sp_error_set(err, SP_E_NOMEM, "out of memory writing the answer");
    size_t n = strlen(j);
    char *t = realloc(j, n + 2);
    if (!t) {
        free(j);
        return sp_error_set(err, SP_E_NOMEM, "out of memory writing the answer");
    }
    t[n] = '\n', t[n + 1] = 0;
    int rc = sp_write_file_atomic(a->json_path, t, n + 1, err);
    free(t);
    return rc;
}

int sp_agent_session_ask(sp_agent_session *s, const char *text, sp_agent_answer *a, sp_error *err)
{
    sp_error local;
    if (!err) err = &local;
    memset(a, 0, sizeof *a);
    a->command = agent_strdup(text ? text : "");
    sp_agent_intent in;
    sp_agent_parse(text, &in);
    a->intent = in.kind;
    /* The user chose when the command says nearest / any / which one, narrows by a relation, or
     * answers the question the last answer asked. */
    s->amb_active = 0;
    s->user_chose = in.selector != SP_AGENT_SELECT_NONE || in.kind == SP_AGENT_INTENT_SELECT ||
                    in.anchor[0] || s->last_asked_back;
    s->n_answers++;
    s->cur = a;
    agent_convo_trim(&s->convo, AGENT_CONVO_MAX);
    int rc = agent_convo_user(&s->convo, text);
    int done = 0;
    for (int step = 0; !rc && step < s->cfg.llm.max_steps && !done; step++) {
        sp_agent_reply r;
        agent_stats st = {0};
        rc = s->brain.next(s->brain.ctx, &s->convo, &r, &st, err);
        a->steps++;
        a->llm_requests += st.requests;
        a->llm_retries += st.retries;
        if (rc) break;
        int stop = r.stop, n_calls = r.n_calls;
        char *said = agent_strdup(r.text);
        rc = agent_convo_assistant(&s->convo, &r);
        sp_agent_reply_free(&r);
        if (!rc && n_calls == 0) {
            done = 1;
            if (!said || !said[0]) {
                free(said);
                said = agent_strdup(stop == SP_AGENT_STOP_MAX_TOKENS ? "(the reply was cut off at the token limit)"
                                    : stop == SP_AGENT_STOP_REFUSAL  ? "(the model declined to answer)"
                                                                     : "(the model gave no answer)");
            }
            a->text = said;
            said = NULL;
        } else if (!rc) {
            rc = run_calls(s, a);
        }
        free(said);
    }
    if (!rc && !done)
        rc = sp_error_set(err, SP_E_FORMAT, "the %s brain gave no final answer within %d turns (the tool-call limit)",
                          s->brain.name, s->cfg.llm.max_steps);
    if (rc && !a->text) {
        char t[1200];
        snprintf(t, sizeof t, "I could not complete this: %s", err->msg);
        a->text = agent_strdup(t);
    }
    a->asked_back = !rc && ends_with_question(a->text);
    s->last_asked_back = a->asked_back;
    sp_error werr;
    if (write_answer(s, a, &werr) && !rc) {
        *err = werr;
        rc = werr.code;
    }
    s->cur = NULL;
    return rc;
}
