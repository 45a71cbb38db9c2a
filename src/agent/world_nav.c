/* The model-folder world's ops that use the map: plans (one path, or k ranked trajectories with
 * previews and the top-down map written under the agent's output folder), views rendered from
 * the splat, descriptions of an object's surroundings, and exploration tours. A goal point that
 * is an instance a query handed out is planned to as that object (its footprint, approached to
 * nav's approach_m and faced), other points within the goal's tolerance. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "world_model.h"
#include "semsplat/io.h"

#define RENDER_W 640
#define RENDER_H 480

static void path_to_agent(const sp_costmap *cm, const sp_path *p, agent_path *ap, sp_error *err)
{
    memset(ap, 0, sizeof *ap);
    ap->wp = malloc(sizeof(double) * 4 * (p->n ? p->n : 1));
    if (!ap->wp) {
        sp_error_set(err, SP_E_NOMEM, "agent world: out of memory");
        return;
    }
    for (int i = 0; i < 4 * p->n; i++) ap->wp[i] = p->waypoints[i];
    ap->n = p->n;
    ap->length_m = p->length_m;
    float mn, mean;
    sp_path_clearance(cm, p, &mn, &mean);
    ap->min_clearance_m = mn, ap->mean_clearance_m = mean;
    ap->localizability = ap->semantic = ap->score = NAN;
}

/* The goal as nav takes it: an object handed out by a query, a pose, or a point. */
static sp_nav_goal nav_goal(const model_world *w, const agent_goalspec *goal, const mw_known *kn)
{
    sp_nav_goal g;
    if (kn) {
        g = sp_nav_goal_point((float)goal->point[0], (float)goal->point[1]);
        g.kind = SP_GOAL_REGION;
        g.approach_m = sp_nav_options(w->nav)->approach_m;
        g.n_boxes = kn->n_boxes;
        memcpy(g.boxes, kn->boxes, sizeof g.boxes);
    } else if (isfinite(goal->yaw)) {
        g = sp_nav_goal_pose((float)goal->point[0], (float)goal->point[1], (float)goal->yaw);
    } else {
        g = sp_nav_goal_point((float)goal->point[0], (float)goal->point[1]);
    }
    g.tolerance_m = isfinite(goal->tolerance_m) && goal->tolerance_m > 0 ? (float)goal->tolerance_m : 0;
    return g;
}

/* Why no path exists, in the tools' vocabulary (the planner's status of a single run). */
static void no_path(const model_world *w, const float s[3], const sp_nav_goal *g, const sp_error *why,
                    agent_plans *out)
{
    sp_path p;
    sp_error e = {0};
    int status = SP_NAV_NO_VALID_PATH;
    if (sp_plan_path(sp_nav_costmap(w->nav), s, g, &sp_nav_options(w->nav)->planner, &p, &e) == 0) sp_path_free(&p);
    else status = p.status;
    snprintf(out->error, sizeof out->error, "%s", mw_status_code(status));
    snprintf(out->note, sizeof out->note, "%s", why->msg[0] ? why->msg : e.msg);
}

/* k paths without ranking or pictures (plan_path, tour legs). */
static int plain_paths(model_world *w, const float s[3], const sp_nav_goal *g, const agent_goalspec *goal,
                       int k, agent_plans *out, sp_error *err)
{
    const sp_costmap *cm = sp_nav_costmap(w->nav);
    sp_path_set set;
    sp_error e = {0};
    int rc = sp_plan_k(cm, s, g, k, &sp_nav_options(w->nav)->planner, &set, &e);
    if (rc == SP_E_NOTFOUND) {
        no_path(w, s, g, &e, out);
        return SP_OK;
    }
    if (rc) {
        *err = e;
        return rc;
    }
    for (int i = 0; i < set.n && out->n < SP_AGENT_MAX_K && !rc; i++) {
        agent_path *ap = &out->paths[out->n];
        path_to_agent(cm, &set.paths[i], ap, err);
        if (!ap->wp) rc = SP_E_NOMEM;
        else out->n++;
        double *e4 = ap->wp ? ap->wp + 4 * (ap->n - 1) : NULL;
        if (e4 && g->kind == SP_GOAL_POINT && agent_dist2d(e4[0], e4[1], goal->point[0], goal->point[1]) > 0.05)
            e4[3] = atan2(goal->point[1] - e4[1], goal->point[0] - e4[0]); /* face the point */
    }
    snprintf(out->note, sizeof out->note, "%s", set.note);
    sp_path_set_free(&set);
    return rc;
}

static void copy_if_exists(char *dst, size_t cap, const char *dir, const char *rel)
{
    char p[2 * AGENT_PATH_CAP];
    snprintf(p, sizeof p, "%s/%s", dir, rel);
    if (sp_file_exists(p) && strlen(p) < cap) snprintf(dst, cap, "%s", p);
}

/* k ranked trajectories with previews, plan.json and the maps in out_dir/trajectories_NNN. */
static int ranked_paths(model_world *w, const float s[3], const sp_nav_goal *g, const mw_known *kn, int k,
                        const char *out_dir, agent_plans *out, sp_error *err)
{
    sp_nav_request req = sp_nav_request_default();
    req.start = s, req.k = k, req.previews = 1;
    if (kn) req.to = kn->phrase, req.instance = kn->index;
    else req.goal = *g;
    sp_nav_plan plan;
    sp_error e = {0};
    int rc = sp_nav_plan_request(w->nav, &req, &plan, &e);
    if (rc == SP_E_NOTFOUND) {
        no_path(w, s, g, &e, out);
        return SP_OK;
    }
    if (rc) {
        *err = e;
        return rc;
    }
    char dir[AGENT_PATH_CAP];
    rc = mw_output_dir(w, out_dir, "trajectories", dir, sizeof dir, err);
    if (!rc) rc = sp_nav_plan_write(w->nav, &plan, dir, err);
    const sp_costmap *cm = sp_nav_costmap(w->nav);
    for (int i = 0; i < plan.n && out->n < SP_AGENT_MAX_K && !rc; i++) {
        const sp_nav_trajectory *t = &plan.traj[i];
        agent_path *ap = &out->paths[out->n];
        path_to_agent(cm, &t->path, ap, err);
        if (!ap->wp) {
            rc = SP_E_NOMEM;
            break;
        }
        out->n++;
        ap->localizability = t->score.localizability;
        ap->semantic = t->score.semantic;
        ap->score = t->score.total;
        for (int j = 0; j < t->n_previews && ap->n_previews < AGENT_MAX_PREVIEWS; j++)
            if (t->previews[j].file[0]) copy_if_exists(ap->previews[ap->n_previews++], AGENT_PATH_CAP, dir, t->previews[j].file);
        char sheet[64];
        snprintf(sheet, sizeof sheet, "previews/t%d_sheet.png", t->rank);
        copy_if_exists(ap->sheet, sizeof ap->sheet, dir, sheet);
    }
    if (!rc) {
        copy_if_exists(out->map_image, sizeof out->map_image, dir, "map.png");
        snprintf(out->note, sizeof out->note, "%s", plan.note);
    }
    sp_nav_plan_free(&plan);
    return rc;
}

int mw_plan(void *ctx, const sp_agent_pose *start, const agent_goalspec *goal, int k,
            const char *target, const char *out_dir, agent_plans *out, sp_error *err)
{
    model_world *w = ctx;
    if (!isfinite(start->x) || !isfinite(start->y) || !isfinite(goal->point[0]) || !isfinite(goal->point[1]))
        return sp_error_set(err, SP_E_ARG, "plan: start (%g, %g) or goal (%g, %g) is not finite", start->x,
                            start->y, goal->point[0], goal->point[1]);
    float s[3] = {(float)start->x, (float)start->y, isfinite(start->yaw) ? (float)start->yaw : 0.0f};
    const mw_known *kn = mw_find_known(w, goal->point[0], goal->point[1]);
    sp_nav_goal g = nav_goal(w, goal, kn);
    k = k < 1 ? 1 : k > SP_AGENT_MAX_K ? SP_AGENT_MAX_K : k;
    if (target && out_dir) return ranked_paths(w, s, &g, kn, k, out_dir, out, err);
    return plain_paths(w, s, &g, goal, k, out, err);
}

int mw_render(void *ctx, const sp_agent_pose *pose, const char *png_path, sp_error *err)
{
    model_world *w = ctx;
    const sp_nav_opts *o = sp_nav_options(w->nav);
    sp_camera cam;
    memset(&cam, 0, sizeof cam);
    float pos[3] = {(float)pose->x, (float)pose->y, (float)pose->z};
    sp_camera_intrinsics_fov(&cam, RENDER_W, RENDER_H, o->preview_hfov_deg * (float)M_PI / 180.0f);
    sp_camera_from_pose(&cam, pos, (float)pose->yaw, -o->camera_pitch_deg * (float)M_PI / 180.0f);
    size_t np = (size_t)RENDER_W * RENDER_H;
    float *rgb = malloc(sizeof(float) * 3 * np);
    uint8_t *px = malloc(3 * np);
    int rc = rgb && px ? 0 : sp_error_set(err, SP_E_NOMEM, "render: out of memory");
    static const float background[3] = {0.12f, 0.12f, 0.14f}; /* unreconstructed space: dark */
    sp_render_request req;
    memset(&req, 0, sizeof req);
    req.rgb = rgb;
    req.background = background;
    if (!rc) rc = sp_render_views(w->raster, w->scene, &cam, 1, &req, err);
    for (size_t i = 0; !rc && i < 3 * np; i++) {
        float v = rgb[i] < 0 ? 0 : rgb[i] > 1 ? 1 : rgb[i];
        px[i] = (uint8_t)(v * 255.0f + 0.5f);
    }
    sp_image img = {RENDER_W, RENDER_H, 3, 8, px};
    if (!rc) rc = sp_image_write_png(png_path, &img, err);
    free(rgb), free(px);
    return rc;
}

/* The instance of t nearest to (x, y). */
static int nearest_instance(const sp_nav_target *t, double x, double y)
{
    int best = 0;
    for (int k = 1; k < t->n; k++)
        if (agent_dist2d(x, y, t->inst[k].position[0], t->inst[k].position[1]) <
            agent_dist2d(x, y, t->inst[best].position[0], t->inst[best].position[1]))
            best = k;
    return best;
}

/* nav's sentence, cut at a clause boundary when it is longer than the agent keeps. */
static void copy_sentence(char *out, size_t cap, const char *s)
{
    snprintf(out, cap, "%s", s ? s : "");
    if (s && strlen(s) >= cap) {
        char *cut = strrchr(out, ';');
        if (cut) snprintf(cut, cap - (size_t)(cut - out), "; ...");
    }
}

int mw_describe(void *ctx, const agent_instance *anchor, const char *anchor_name, double radius_m,
                const sp_agent_pose *robot, agent_scene *out, sp_error *err)
{
    model_world *w = ctx;
    const mw_known *kn = mw_find_known(w, anchor->position[0], anchor->position[1]);
    char phrase[SP_AGENT_MAX_PHRASE + 1];
    int rc = kn ? (snprintf(phrase, sizeof phrase, "%s", kn->phrase), 0) : mw_nav_phrase(w, anchor_name, phrase, sizeof phrase, err);
    if (rc) return rc;
    if (!phrase[0]) return sp_error_set(err, SP_E_NOTFOUND, "describe: nothing in this map matches '%s'", anchor_name);
    sp_nav_target *t = malloc(sizeof *t);
    if (!t) return sp_error_set(err, SP_E_NOMEM, "describe: out of memory");
    sp_nav_description d;
    memset(&d, 0, sizeof d);
    float r[3] = {(float)robot->x, (float)robot->y, (float)robot->yaw};
    rc = sp_nav_resolve(w->nav, phrase, t, err);
    if (!rc) {
        int idx = kn && kn->index >= 0 && kn->index < t->n ? kn->index
                                                           : nearest_instance(t, anchor->position[0], anchor->position[1]);
        rc = sp_nav_describe_target(w->nav, t, idx, (float)radius_m, r, &d, err);
    }
    free(t);
    if (rc) return rc;
    for (int i = 0; i < d.n && out->n < AGENT_MAX_SCENE; i++) {
        const sp_nav_object *o = &d.objects[i];
        agent_scene_item *it = &out->items[out->n++];
        snprintf(it->name, sizeof it->name, "%s", o->name);
        for (int a = 0; a < 3; a++) it->position[a] = o->inst.position[a];
        it->confidence = o->inst.confidence;
        it->distance_m = o->distance_m;
        snprintf(it->region, sizeof it->region, "%s", o->region);
    }
    copy_sentence(out->sentence, sizeof out->sentence, d.sentence);
    snprintf(out->source, sizeof out->source, "%s", w->source);
    sp_nav_description_free(&d);
    return SP_OK;
}

/* Keeps the max views of a tour that add the most, in visiting order, among those whose mask
 * is set. */
static int keep_best_views(const sp_nav_tour *t, const uint8_t *mask, int max, int *keep)
{
    int n = 0;
    for (int i = 0; i < t->n; i++) {
        if (!mask[i]) continue;
        int better = 0;
        for (int j = 0; j < t->n; j++)
            better += mask[j] && (t->gain[j] > t->gain[i] || (t->gain[j] == t->gain[i] && j < i));
        if (better < max) keep[n++] = i;
    }
    return n;
}

/* A room's tour stands in the room: views from beyond its doorways (which see into it) are left
 * out when some view stands inside. Returns how many were left out. */
static int inside_region(model_world *w, const sp_nav_tour *t, uint8_t *mask, sp_error *err)
{
    size_t n = t->n > 0 ? (size_t)t->n : 0;
    memset(mask, 1, n);
    if (strncmp(t->target.source, "region", 6)) return 0;
    int inside = 0;
    for (int i = 0; i < t->n; i++) {
        char r[64];
        if (sp_nav_region_of(w->nav, t->poses[4 * i], t->poses[4 * i + 1], r, sizeof r, err)) return -1;
        mask[i] = !strcmp(r, t->target.text);
        inside += mask[i];
    }
    if (inside == 0) memset(mask, 1, n);
    return inside ? t->n - inside : 0;
}

int mw_explore(void *ctx, const char *region, const sp_agent_pose *robot, int max_waypoints,
               const char *out_dir, agent_tour *out, sp_error *err)
{
    model_world *w = ctx;
    char phrase[SP_AGENT_MAX_PHRASE + 1];
    int rc = mw_nav_phrase(w, region, phrase, sizeof phrase, err);
    if (rc) return rc;
    if (!phrase[0]) return sp_error_set(err, SP_E_NOTFOUND, "explore: no region or object called '%s' on this map", region);
    float s[3] = {(float)robot->x, (float)robot->y, (float)robot->yaw};
    sp_nav_tour t;
    if ((rc = sp_nav_explore(w->nav, phrase, s, &t, err))) return rc;
    int max = max_waypoints < 1 ? 1 : max_waypoints > AGENT_MAX_TOUR ? AGENT_MAX_TOUR : max_waypoints;
    int *keep = malloc(sizeof(int) * (t.n ? t.n : 1));
    uint8_t *mask = malloc(t.n ? (size_t)t.n : 1);
    if (!keep || !mask) rc = sp_error_set(err, SP_E_NOMEM, "explore: out of memory");
    int outside = rc ? 0 : inside_region(w, &t, mask, err);
    if (outside < 0) rc = err->code;
    int n = rc ? 0 : keep_best_views(&t, mask, max, keep);
    for (int i = 0; i < n; i++)
        for (int a = 0; a < 4; a++) out->wp[i][a] = t.poses[4 * keep[i] + a];
    out->n = n;
    out->length_m = t.path.length_m;
    snprintf(out->region, sizeof out->region, "%s", t.target.text);
    snprintf(out->note, sizeof out->note, "%s%s%.0f %% of the area seen", t.note, t.note[0] ? "; " : "",
             100 * t.coverage);
    size_t l = strlen(out->note);
    if (outside > 0)
        l += (size_t)snprintf(out->note + l, sizeof out->note - l, "; %d view%s from outside the %s left out",
                              outside, outside == 1 ? "" : "s", t.target.text);
    if (n < t.n - outside && l < sizeof out->note)
        snprintf(out->note + l, sizeof out->note - l, "; kept the %d of %d views that add the most", n, t.n - outside);
    char dir[AGENT_PATH_CAP];
    if (!rc && out_dir && !(rc = mw_output_dir(w, out_dir, "explore", dir, sizeof dir, err)) &&
        !(rc = sp_nav_tour_write(w->nav, &t, dir, err)))
        copy_if_exists(out->map_image, sizeof out->map_image, dir, "map.png");
    free(keep), free(mask);
    sp_nav_tour_free(&t);
    return rc;
}
