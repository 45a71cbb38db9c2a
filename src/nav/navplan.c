/* A plan request end to end: the start (given, or the capture's first pose), the goal (a point,
 * a pose, or a phrase resolved to footprints), k distinct paths, the concepts related to the goal
 * for the semantic term, the ranking, previews, and the ids the scene keeps. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "nav_scene.h"

void sp_nav_plan_free(sp_nav_plan *p)
{
    if (!p) return;
    for (int i = 0; i < p->n; i++) {
        sp_nav_trajectory *t = &p->traj[i];
        sp_path_free(&t->path);
        free(t->loc);
        for (int j = 0; j < t->n_previews; j++) nav_preview_free(&t->previews[j]);
        free(t->previews);
    }
    free(p->traj);
    memset(p, 0, sizeof *p);
}

static int goal_from_phrase(sp_nav *nav, const sp_nav_request *req, sp_nav_plan *out, sp_error *err)
{
    int rc = sp_nav_resolve(nav, req->to, &out->target, err);
    if (rc) return rc;
    const sp_nav_target *t = &out->target;
    if (!t->found)
        return sp_error_set(err, SP_E_NOTFOUND, "nav: nothing in this model matches '%s' (best "
                            "confidence %.2f, needs %.2f)", t->text, t->confidence, nav->opts.min_confidence);
    if (req->instance >= t->n)
        return sp_error_set(err, SP_E_ARG, "nav: '%s' has %d instance%s, not %d", t->text, t->n,
                            t->n == 1 ? "" : "s", req->instance + 1);
    sp_nav_goal *g = &out->goal;
    *g = sp_nav_goal_point(t->inst[0].position[0], t->inst[0].position[1]);
    g->kind = SP_GOAL_REGION;
    g->approach_m = nav->opts.approach_m;
    for (int k = 0; k < t->n; k++)
        if (req->instance < 0 || k == req->instance) g->boxes[g->n_boxes++] = t->inst[k].box;
    return SP_OK;
}

/* The related concepts the ranking looks for, each resolved; relevance set from the found. */
static int related(sp_nav *nav, sp_nav_plan *p, sp_error *err)
{
    sp_nav_target *found = calloc(8, sizeof *found);
    if (!found) return sp_error_set(err, SP_E_NOMEM, "nav: out of memory");
    int n_found = 0, rc = 0;
    p->n_related = p->target.text[0] && nav->engine ? nav_related_concepts(p->target.text, p->related, 8) : 0;
    for (int i = 0; i < p->n_related && !rc; i++) {
        rc = sp_nav_resolve(nav, p->related[i], &found[n_found], err);
        if (!rc && found[n_found].found) p->related_found[i] = 1, n_found++;
    }
    if (!rc) rc = nav_set_relevance(nav, found, n_found, err);
    free(found);
    return rc;
}

int sp_nav_plan_request(sp_nav *nav, const sp_nav_request *req, sp_nav_plan *out, sp_error *err)
{
    memset(out, 0, sizeof *out);
    if (!nav || !req) return sp_error_set(err, SP_E_ARG, "nav: missing scene or request");
    int rc = 0;
    if (req->start) memcpy(out->start, req->start, sizeof out->start);
    else if ((rc = sp_nav_default_start(nav, out->start, err))) return rc;
    out->k = req->k > 0 ? req->k : nav->opts.k;
    if (req->to) rc = goal_from_phrase(nav, req, out, err);
    else out->goal = req->goal;
    if (rc) return rc;
    snprintf(out->id, sizeof out->id, "plan-%d", ++nav->plan_seq);
    sp_path_set set;
    if ((rc = sp_plan_k(&nav->cm, out->start, &out->goal, out->k, &nav->opts.planner, &set, err))) return rc;
    out->ms_plan = set.ms;
    snprintf(out->note, sizeof out->note, "%s", set.note);
    out->traj = calloc((size_t)set.n, sizeof *out->traj);
    if (!out->traj) {
        sp_path_set_free(&set);
        return sp_error_set(err, SP_E_NOMEM, "nav: out of memory");
    }
    for (int i = 0; i < set.n; i++) {
        out->traj[i].path = set.paths[i];
        out->traj[i].share = set.share[i];
        memset(&set.paths[i], 0, sizeof set.paths[i]);
    }
    out->n = set.n;
    sp_path_set_free(&set);
    double t0 = sp_time_now();
    if (!rc) rc = related(nav, out, err);
    if (!rc) rc = nav_rank(nav, out, err);
    out->ms_rank = 1e3 * (sp_time_now() - t0);
    t0 = sp_time_now();
    for (int i = 0; i < out->n && !rc && req->previews; i++)
        rc = nav_make_previews(nav, &out->traj[i], req->to ? &out->target : NULL, err);
    out->ms_previews = 1e3 * (sp_time_now() - t0);
    for (int i = 0; i < out->n && !rc; i++) rc = nav_issue(nav, out->traj[i].id, &out->traj[i].path, err);
    if (rc) sp_nav_plan_free(out);
    return rc;
}
