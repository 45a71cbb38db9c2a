/* The scene tools on top of the world: show_trajectories (k ranked paths with previews, each a
 * plan this session issued), describe_surroundings and explore_region (a tour planned leg by
 * leg). Phrases resolve through resolve.c. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tools_internal.h"

/* Resolves the phrase of a scene tool and picks the instance; on failure *result is set. */
static const agent_instance *resolve_pick(sp_agent_session *s, const sp_agent_args *a,
                                          sp_agent_pose *robot, agent_resolved *r, char **result)
{
    sp_error e = {0};
    *result = NULL;
    if (agent_robot_pose(s, robot, &e)) {
        *result = agent_result_error(a->tool, "ROBOT_ERROR", e.msg, NULL, NULL);
        return NULL;
    }
    if (agent_resolve(s, a->text, robot, r, &e)) {
        *result = agent_result_error(a->tool, "QUERY_FAILED", e.msg, NULL, NULL);
        return NULL;
    }
    if (a->instance > 0 && r->ambiguous && !s->user_chose) { /* a model choosing for the user */
        s->amb_active = 1, s->amb_n = r->found.n;
        snprintf(s->amb_phrase, sizeof s->amb_phrase, "%s", a->text);
        *result = agent_ambiguity_guard(s, a->tool, NAN, NAN);
        return NULL;
    }
    return agent_pick_instance(a->tool, a->text, a->instance, r, result);
}

static void add_images(sp_agent_session *s, const char (*paths)[AGENT_PATH_CAP], int n)
{
    for (int i = 0; i < n; i++)
        if (paths[i][0]) agent_answer_add_image(s->cur, paths[i]);
}

static cJSON *trajectory_json(sp_agent_session *s, const agent_path *p, int rank, const sp_agent_pose *robot)
{
    const agent_plan_rec *rec = agent_commit_register(s, p, robot);
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "rank", rank);
    cJSON_AddStringToObject(o, "plan_id", rec ? rec->id : "");
    cJSON_AddNumberToObject(o, "length_m", agent_round4(agent_path_length(p->wp, p->n)));
    cJSON *sc = cJSON_CreateObject();
    cJSON_AddNumberToObject(sc, "total", agent_round4(isfinite(p->score) ? p->score : 0));
    if (isfinite(p->min_clearance_m)) cJSON_AddNumberToObject(sc, "min_clearance_m", agent_round4(p->min_clearance_m));
    if (isfinite(p->mean_clearance_m)) cJSON_AddNumberToObject(sc, "mean_clearance_m", agent_round4(p->mean_clearance_m));
    if (isfinite(p->localizability)) cJSON_AddNumberToObject(sc, "localizability", agent_round4(p->localizability));
    if (isfinite(p->semantic)) cJSON_AddNumberToObject(sc, "semantic_relevance", agent_round4(p->semantic));
    cJSON_AddItemToObject(o, "score", sc);
    cJSON_AddNumberToObject(o, "n_waypoints", p->n);
    cJSON_AddItemToObject(o, "waypoints", agent_waypoints_json(p->wp, p->n, 12));
    cJSON_AddItemToObject(o, "end", agent_json_numbers(p->wp + (p->n - 1) * 4, 4));
    cJSON *pv = cJSON_CreateArray();
    for (int i = 0; i < p->n_previews; i++) cJSON_AddItemToArray(pv, cJSON_CreateString(p->previews[i]));
    cJSON_AddItemToObject(o, "previews", pv);
    if (p->sheet[0]) cJSON_AddStringToObject(o, "contact_sheet", p->sheet);
    add_images(s, p->previews, p->n_previews);
    if (p->sheet[0]) agent_answer_add_image(s->cur, p->sheet);
    return o;
}

char *agent_tool_show_trajectories(sp_agent_session *s, const sp_agent_args *a)
{
    sp_agent_pose robot;
    agent_resolved *r = malloc(sizeof *r);
    char *result = NULL;
    if (!r) return NULL;
    const agent_instance *goal = resolve_pick(s, a, &robot, r, &result);
    if (!goal) {
        free(r);
        return result;
    }
    agent_goalspec g = {{goal->position[0], goal->position[1], goal->position[2]}, NAN,
                        SP_AGENT_DEFAULT_TOLERANCE_M};
    agent_plans pl;
    memset(&pl, 0, sizeof pl);
    sp_error e = {0};
    if (s->world.ops->plan(s->world.ctx, &robot, &g, a->k, a->text, s->out_dir[0] ? s->out_dir : NULL, &pl, &e)) {
        free(r);
        agent_plans_free(&pl);
        return agent_result_error(a->tool, "PLANNER_FAILED", e.msg, NULL, NULL);
    }
    if (pl.n == 0) {
        result = agent_result_error(a->tool, pl.error[0] ? pl.error : "NO_VALID_PATH",
                                    pl.note[0] ? pl.note : "no path to it", "tell the user", NULL);
    } else {
        cJSON *d = cJSON_CreateObject(), *tr = cJSON_CreateArray();
        cJSON_AddStringToObject(d, "target", a->text);
        cJSON_AddItemToObject(d, "target_position", agent_json_numbers(goal->position, 3));
        cJSON_AddNumberToObject(d, "asked", a->k);
        cJSON_AddNumberToObject(d, "found", pl.n);
        for (int i = 0; i < pl.n; i++) cJSON_AddItemToArray(tr, trajectory_json(s, &pl.paths[i], i + 1, &robot));
        cJSON_AddItemToObject(d, "trajectories", tr);
        if (pl.map_image[0]) {
            cJSON_AddStringToObject(d, "map_image", pl.map_image);
            agent_answer_add_image(s->cur, pl.map_image);
        }
        if (pl.note[0]) cJSON_AddStringToObject(d, "note", pl.note);
        cJSON_AddStringToObject(d, "next", "to drive one: send_nav2_goal with its end and plan_id");
        result = agent_result_ok(a->tool, d);
    }
    agent_plans_free(&pl);
    free(r);
    return result;
}

/* "left of the dining table", as seen from the robot. */
static void relation_seen_from(const sp_agent_pose *robot, const agent_instance *an,
                               const agent_scene_item *it, const char *name, char *out, size_t cap)
{
    double fx = an->position[0] - robot->x, fy = an->position[1] - robot->y;
    double ox = it->position[0] - an->position[0], oy = it->position[1] - an->position[1];
    double f = hypot(fx, fy);
    if (f < 1e-6 || hypot(ox, oy) < 1e-6) {
        snprintf(out, cap, "at the %s", name);
        return;
    }
    if (agent_dist_to_footprint(an, it->position[0], it->position[1]) < 1e-6 && isfinite(an->extent_max[2]) &&
        it->position[2] >= an->extent_max[2] - 0.15) {
        snprintf(out, cap, "on the %s", name);
        return;
    }
    double side = (fx * oy - fy * ox) / f, along = (fx * ox + fy * oy) / f;
    if (fabs(side) >= fabs(along)) snprintf(out, cap, "%s of the %s", side > 0 ? "left" : "right", name);
    else snprintf(out, cap, "%s the %s", along > 0 ? "behind" : "in front of", name);
}

static int by_item_distance(const void *a, const void *b)
{
    double da = ((const agent_scene_item *)a)->distance_m, db = ((const agent_scene_item *)b)->distance_m;
    return da < db ? -1 : da > db;
}

static void scene_sentence(const agent_scene *sc, const char *name, const agent_instance *an,
                           double radius, char *out, size_t cap)
{
    size_t j = (size_t)snprintf(out, cap, "Within %.1f m of the %s%s%s%s: ", radius, name,
                                an->region[0] ? " (in the " : "", an->region, an->region[0] ? ")" : "");
    if (sc->n == 0) {
        snprintf(out, cap, "I recognise nothing within %.1f m of the %s.", radius, name);
        return;
    }
    for (int i = 0; i < sc->n && j < cap; i++)
        j += (size_t)snprintf(out + j, cap - j, "%s%s %.1f m, %s", i ? "; " : "", sc->items[i].name,
                              sc->items[i].distance_m, sc->items[i].relation);
    if (j < cap) snprintf(out + j, cap - j, ".");
}

char *agent_tool_describe(sp_agent_session *s, const sp_agent_args *a)
{
    sp_agent_pose robot;
    agent_resolved *r = malloc(sizeof *r);
    agent_scene *sc = calloc(1, sizeof *sc);
    char *result = NULL;
    const agent_instance *an = r && sc ? resolve_pick(s, a, &robot, r, &result) : NULL;
    sp_error e = {0};
    if (an && s->world.ops->describe(s->world.ctx, an, a->text, a->radius_m, &robot, sc, &e))
        result = agent_result_error(a->tool, "DESCRIBE_FAILED", e.msg, NULL, NULL), an = NULL;
    if (an) {
        sp_agent_intent in;
        agent_parse_phrase(a->text, &in);
        const char *name = in.target[0] ? in.target : a->text;
        int n = 0;
        if (sc->n > AGENT_MAX_SCENE) sc->n = AGENT_MAX_SCENE;
        for (int i = 0; i < sc->n; i++) {
            agent_scene_item *it = &sc->items[i];
            if (!isfinite(it->distance_m)) it->distance_m = agent_dist_to_footprint(an, it->position[0], it->position[1]);
            if (it->distance_m > a->radius_m) continue;
            if (!it->region[0]) s->world.ops->region_of(s->world.ctx, it->position[0], it->position[1], it->region, sizeof it->region);
            if (!it->relation[0]) relation_seen_from(&robot, an, it, name, it->relation, sizeof it->relation);
            sc->items[n++] = *it;
        }
        sc->n = n;
        qsort(sc->items, (size_t)n, sizeof sc->items[0], by_item_distance);
        if (!sc->sentence[0]) scene_sentence(sc, name, an, a->radius_m, sc->sentence, sizeof sc->sentence);
        cJSON *d = cJSON_CreateObject(), *objs = cJSON_CreateArray();
        cJSON_AddStringToObject(d, "anchor", a->text);
        cJSON_AddItemToObject(d, "anchor_position", agent_json_numbers(an->position, 3));
        cJSON_AddStringToObject(d, "anchor_region", an->region[0] ? an->region : "unknown");
        cJSON_AddNumberToObject(d, "radius_m", agent_round4(a->radius_m));
        for (int i = 0; i < n; i++) {
            cJSON *o = cJSON_CreateObject();
            cJSON_AddStringToObject(o, "name", sc->items[i].name);
            cJSON_AddItemToObject(o, "position", agent_json_numbers(sc->items[i].position, 3));
            cJSON_AddNumberToObject(o, "distance_m", agent_round4(sc->items[i].distance_m));
            cJSON_AddStringToObject(o, "relation", sc->items[i].relation);
            cJSON_AddStringToObject(o, "region", sc->items[i].region[0] ? sc->items[i].region : "unknown");
            cJSON_AddNumberToObject(o, "confidence", agent_round4(sc->items[i].confidence));
            cJSON_AddItemToArray(objs, o);
        }
        cJSON_AddItemToObject(d, "objects", objs);
        cJSON_AddStringToObject(d, "sentence", sc->sentence);
        if (sc->source[0]) cJSON_AddStringToObject(d, "source", sc->source);
        result = agent_result_ok(a->tool, d);
    }
    free(r);
    free(sc);
    return result;
}

/* The tour as one drivable path: each leg planned on the map (a waypoint no leg reaches is
 * dropped and counted). */
static int tour_path(sp_agent_session *s, const sp_agent_pose *robot, agent_tour *t, agent_path *out,
                     int *dropped, sp_error *err)
{
    memset(out, 0, sizeof *out);
    *dropped = 0;
    sp_agent_pose from = *robot;
    int cap = 0;
    for (int i = 0; i < t->n; i++) {
        agent_goalspec g = {{t->wp[i][0], t->wp[i][1], t->wp[i][2]}, t->wp[i][3], 0.3};
        agent_plans pl;
        memset(&pl, 0, sizeof pl);
        int rc = s->world.ops->plan(s->world.ctx, &from, &g, 1, NULL, NULL, &pl, err);
        if (rc || pl.n == 0) {
            agent_plans_free(&pl);
            if (rc) return rc;
            (*dropped)++;
            continue;
        }
        const agent_path *leg = &pl.paths[0];
        int skip = out->n > 0; /* the leg starts where the last one ended */
        if (out->n + leg->n > cap) {
            cap = 2 * (out->n + leg->n);
            double *nw = realloc(out->wp, (size_t)cap * 4 * sizeof *nw);
            if (!nw) {
                agent_plans_free(&pl);
                return sp_error_set(err, SP_E_NOMEM, "out of memory");
            }
            out->wp = nw;
        }
        memcpy(out->wp + out->n * 4, leg->wp + skip * 4, (size_t)(leg->n - skip) * 4 * sizeof *out->wp);
        out->n += leg->n - skip;
        const double *e = leg->wp + (leg->n - 1) * 4;
        from = (sp_agent_pose){e[0], e[1], e[2], e[3]};
        agent_plans_free(&pl);
    }
    return SP_OK;
}

char *agent_tool_explore(sp_agent_session *s, const sp_agent_args *a)
{
    sp_error e = {0};
    sp_agent_pose robot;
    if (agent_robot_pose(s, &robot, &e)) return agent_result_error(a->tool, "ROBOT_ERROR", e.msg, NULL, NULL);
    agent_tour *t = calloc(1, sizeof *t);
    if (!t) return NULL;
    int rc = s->world.ops->explore(s->world.ctx, a->text, &robot, a->max_waypoints,
                                   s->out_dir[0] ? s->out_dir : NULL, t, &e);
    agent_path p = {0};
    int dropped = 0;
    if (!rc && t->n > 0) {
        if (t->n > AGENT_MAX_TOUR) t->n = AGENT_MAX_TOUR;
        rc = tour_path(s, &robot, t, &p, &dropped, &e);
    }
    char *result;
    if (rc || t->n == 0 || p.n == 0) {
        result = agent_result_error(a->tool, rc == SP_E_NOTFOUND ? "NOT_FOUND" : "EXPLORE_FAILED",
                                    rc ? e.msg : t->note[0] ? t->note : "no reachable waypoints",
                                    "tell the user; name a room or an object", NULL);
    } else {
        const agent_plan_rec *rec = agent_commit_register(s, &p, &robot);
        cJSON *d = cJSON_CreateObject();
        cJSON_AddStringToObject(d, "region", t->region[0] ? t->region : a->text);
        cJSON_AddNumberToObject(d, "n_waypoints", t->n);
        cJSON_AddItemToObject(d, "waypoints", agent_waypoints_json(&t->wp[0][0], t->n, AGENT_MAX_TOUR));
        if (dropped) cJSON_AddNumberToObject(d, "unreachable_waypoints", dropped);
        cJSON_AddNumberToObject(d, "tour_length_m", agent_round4(agent_path_length(p.wp, p.n)));
        cJSON_AddStringToObject(d, "plan_id", rec ? rec->id : "");
        if (t->note[0]) cJSON_AddStringToObject(d, "note", t->note);
        if (t->map_image[0]) {
            cJSON_AddStringToObject(d, "map_image", t->map_image);
            agent_answer_add_image(s->cur, t->map_image);
        }
        cJSON_AddStringToObject(d, "next", "to drive the tour: send_nav2_goal with the plan's end and plan_id");
        if (rec) cJSON_AddItemToObject(d, "end", agent_json_numbers(rec->wp + (rec->n - 1) * 4, 4));
        result = agent_result_ok(a->tool, d);
    }
    free(p.wp);
    free(t);
    return result;
}

void agent_plans_free(agent_plans *p)
{
    for (int i = 0; i < SP_AGENT_MAX_K; i++) {
        free(p->paths[i].wp);
        p->paths[i].wp = NULL;
    }
}
