/* Commitments: the plans this session issued, and the rule that a motion goal must be the end of
 * one of them (planned from where the robot is, ending in a free cell, not too long). A model
 * can propose any coordinates; only these reach the robot. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "agent_internal.h"

double agent_clamp_speed(double mps)
{
    if (!(mps > 0.05)) return 0.05; /* also NaN */
    return mps > SP_AGENT_SPEED_LIMIT ? SP_AGENT_SPEED_LIMIT : mps;
}

const agent_plan_rec *agent_commit_register(sp_agent_session *s, const agent_path *p,
                                            const sp_agent_pose *start)
{
    if (!p || p->n < 1) return NULL;
    double *wp = malloc((size_t)p->n * 4 * sizeof *wp);
    if (!wp) return NULL;
    memcpy(wp, p->wp, (size_t)p->n * 4 * sizeof *wp);
    agent_plan_rec *r = &s->plans[s->n_plans_issued % AGENT_MAX_PLANS];
    free(r->wp);
    s->n_plans_issued++;
    snprintf(r->id, sizeof r->id, "plan_%d", s->n_plans_issued);
    r->wp = wp;
    r->n = p->n;
    r->start = *start;
    r->length_m = agent_path_length(wp, p->n);
    return r;
}

static const agent_plan_rec *find_id(const sp_agent_session *s, const char *id)
{
    for (int i = 0; i < AGENT_MAX_PLANS; i++)
        if (s->plans[i].wp && !strcmp(s->plans[i].id, id)) return &s->plans[i];
    return NULL;
}

static int end_matches(const sp_agent_session *s, const agent_plan_rec *r, const sp_agent_args *a,
                       double *dist, double *dyaw)
{
    const double *e = r->wp + (r->n - 1) * 4;
    *dist = agent_dist2d(a->x, a->y, e[0], e[1]);
    *dyaw = isfinite(e[3]) ? fabs(agent_wrap_angle(a->yaw - e[3])) : 0;
    return *dist <= s->cfg.goal_match_m && *dyaw <= s->cfg.goal_match_rad;
}

#define FAIL(c, ...)                                      \
    do {                                                  \
        snprintf(code, code_cap, "%s", c);                \
        snprintf(msg, msg_cap, __VA_ARGS__);              \
        return NULL;                                      \
    } while (0)

const agent_plan_rec *agent_commit_match(sp_agent_session *s, const sp_agent_args *a,
                                         const sp_agent_pose *robot, char *code, size_t code_cap,
                                         char *msg, size_t msg_cap, char *hint, size_t hint_cap)
{
    snprintf(hint, hint_cap, "call get_robot_pose, then plan_path(start, goal), then send the "
                             "plan's last waypoint [x, y, yaw] with its plan_id");
    const agent_plan_rec *r = NULL;
    double dist, dyaw;
    if (a->plan_id[0]) {
        r = find_id(s, a->plan_id);
        if (!r) FAIL("PLAN_UNKNOWN", "no plan '%s' was issued in this session", a->plan_id);
        if (!end_matches(s, r, a, &dist, &dyaw)) {
            const double *e = r->wp + (r->n - 1) * 4;
            FAIL("GOAL_MISMATCH",
                 "(%.2f, %.2f, yaw %.2f) is not the end of %s, which is (%.2f, %.2f, yaw %.2f): "
                 "%.2f m and %.2f rad away (at most %.2f m and %.2f rad)",
                 a->x, a->y, a->yaw, r->id, e[0], e[1], e[3], dist, dyaw, s->cfg.goal_match_m,
                 s->cfg.goal_match_rad);
        }
    } else {
        for (int k = 0; k < AGENT_MAX_PLANS && !r; k++) { /* newest first */
            int i = ((s->n_plans_issued - 1 - k) % AGENT_MAX_PLANS + AGENT_MAX_PLANS) % AGENT_MAX_PLANS;
            if (s->plans[i].wp && end_matches(s, &s->plans[i], a, &dist, &dyaw)) r = &s->plans[i];
        }
        if (!r) {
            int cell = s->world.ops->cell(s->world.ctx, a->x, a->y);
            FAIL("PLAN_REQUIRED",
                 "no plan issued in this session ends at (%.2f, %.2f, yaw %.2f)%s%s%s; goals are "
                 "accepted only at the end of a plan from plan_path, never as raw coordinates",
                 a->x, a->y, a->yaw, cell != AGENT_CELL_FREE ? " (that point is " : "",
                 cell != AGENT_CELL_FREE ? agent_cell_name(cell) : "",
                 cell != AGENT_CELL_FREE ? ")" : "");
        }
    }
    const double *e = r->wp + (r->n - 1) * 4;
    int cell = s->world.ops->cell(s->world.ctx, e[0], e[1]);
    if (cell != AGENT_CELL_FREE)
        FAIL("GOAL_NOT_FREE", "the end of %s (%.2f, %.2f) is %s on the map", r->id, e[0], e[1],
             agent_cell_name(cell));
    double off = agent_dist2d(robot->x, robot->y, r->start.x, r->start.y);
    if (off > s->cfg.plan_start_m) {
        snprintf(hint, hint_cap, "call get_robot_pose and plan_path again from the current pose");
        FAIL("PLAN_STALE", "%s was planned from (%.2f, %.2f) but the robot is at (%.2f, %.2f), "
                           "%.2f m away (at most %.2f m)",
             r->id, r->start.x, r->start.y, robot->x, robot->y, off, s->cfg.plan_start_m);
    }
    if (r->length_m > s->cfg.max_goal_distance_m) {
        snprintf(hint, hint_cap, "choose a closer goal, or ask the user to raise the limit");
        FAIL("DISTANCE_LIMIT", "%s is %.1f m long; this session drives at most %.1f m per goal",
             r->id, r->length_m, s->cfg.max_goal_distance_m);
    }
    hint[0] = 0;
    return r;
}

void agent_commit_free(sp_agent_session *s)
{
    for (int i = 0; i < AGENT_MAX_PLANS; i++) {
        free(s->plans[i].wp);
        s->plans[i].wp = NULL;
    }
}
