/* What a plan leaves on disk: plan.json (every trajectory's waypoints and score terms), the map
 * as Nav2's map_server reads it (map.pgm + map.yaml), the top-down map.png, and previews/ (the
 * views along each trajectory and its contact sheet). */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "nav_scene.h"
#include "semsplat/io.h"

cJSON *nav_json_floats(const float *v, int n)
{
    cJSON *a = cJSON_CreateArray();
    for (int i = 0; i < n; i++) cJSON_AddItemToArray(a, isfinite(v[i]) ? cJSON_CreateNumber(v[i]) : cJSON_CreateNull());
    return a;
}

static cJSON *box_json(const sp_nav_box *b)
{
    float v[4] = {b->min[0], b->min[1], b->max[0], b->max[1]};
    return nav_json_floats(v, 4);
}

cJSON *nav_json_target(const sp_nav_target *t)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "text", t->text);
    cJSON_AddBoolToObject(o, "found", t->found);
    cJSON_AddNumberToObject(o, "confidence", t->confidence);
    cJSON_AddStringToObject(o, "source", t->source);
    cJSON *arr = cJSON_AddArrayToObject(o, "instances");
    for (int k = 0; k < t->n; k++) {
        cJSON *e = cJSON_CreateObject();
        cJSON_AddStringToObject(e, "label", t->inst[k].label);
        cJSON_AddItemToObject(e, "position", nav_json_floats(t->inst[k].position, 3));
        cJSON_AddItemToObject(e, "footprint_xy", box_json(&t->inst[k].box));
        float z[2] = {t->inst[k].z_min, t->inst[k].z_max};
        cJSON_AddItemToObject(e, "z_range", nav_json_floats(z, 2));
        cJSON_AddNumberToObject(e, "confidence", t->inst[k].confidence);
        cJSON_AddItemToArray(arr, e);
    }
    return o;
}

static cJSON *goal_json(const sp_nav_goal *g)
{
    static const char *kinds[] = {"point", "pose", "region"};
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "kind", kinds[g->kind]);
    if (g->kind == SP_GOAL_REGION) {
        cJSON *arr = cJSON_AddArrayToObject(o, "footprints_xy");
        for (int b = 0; b < g->n_boxes; b++) cJSON_AddItemToArray(arr, box_json(&g->boxes[b]));
        cJSON_AddNumberToObject(o, "approach_m", g->approach_m);
    } else {
        cJSON_AddItemToObject(o, "xy", nav_json_floats(g->xy, 2));
        if (g->kind == SP_GOAL_POSE) cJSON_AddNumberToObject(o, "yaw", g->yaw);
    }
    return o;
}

static cJSON *path_json(const sp_path *p)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "length_m", p->length_m);
    cJSON *wp = cJSON_AddArrayToObject(o, "waypoints");
    for (int i = 0; i < p->n; i++) cJSON_AddItemToArray(wp, nav_json_floats(p->waypoints + 4 * i, 4));
    cJSON *c = cJSON_AddArrayToObject(o, "corners");
    for (int i = 0; i < p->n_corners; i++) cJSON_AddItemToArray(c, nav_json_floats(p->corners + 2 * i, 2));
    return o;
}

static cJSON *score_json(const sp_nav_score *s, const sp_rank_weights *w)
{
    cJSON *o = cJSON_CreateObject();
    struct { const char *name; float raw, term, weight; const char *unit; } rows[] = {
        {"length", s->length_m, s->t_length, w->length, "m"},
        {"clearance_min", s->clearance_min_m, s->t_clearance_min, w->clearance_min, "m"},
        {"clearance_mean", s->clearance_mean_m, s->t_clearance_mean, w->clearance_mean, "m"},
        {"localizability", s->localizability, s->t_localizability, w->localizability, "0..1, worst waypoint"},
        {"semantic", s->semantic, s->t_semantic, w->semantic, "0..1, related concepts in view"},
    };
    for (size_t k = 0; k < sizeof rows / sizeof rows[0]; k++) {
        cJSON *e = cJSON_CreateObject();
        cJSON_AddNumberToObject(e, "value", rows[k].raw);
        cJSON_AddStringToObject(e, "unit", rows[k].unit);
        cJSON_AddNumberToObject(e, "term", rows[k].term);
        cJSON_AddNumberToObject(e, "weight", rows[k].weight);
        cJSON_AddItemToObject(o, rows[k].name, e);
    }
    cJSON_AddNumberToObject(o, "total", s->total);
    cJSON_AddNumberToObject(o, "weakest_waypoint", s->weakest_waypoint);
    return o;
}

static cJSON *previews_json(const sp_nav_preview *pv, int n)
{
    cJSON *arr = cJSON_CreateArray();
    for (int j = 0; j < n; j++) {
        cJSON *e = cJSON_CreateObject();
        if (pv[j].file[0]) cJSON_AddStringToObject(e, "file", pv[j].file);
        else cJSON_AddNullToObject(e, "file");
        cJSON_AddNumberToObject(e, "waypoint", pv[j].waypoint);
        cJSON_AddNumberToObject(e, "distance_m", pv[j].distance_m);
        cJSON_AddNumberToObject(e, "localizability", pv[j].localizability);
        cJSON_AddItemToObject(e, "camera_xyz_yaw_pitch", nav_json_floats(pv[j].pose, 5));
        cJSON_AddItemToArray(arr, e);
    }
    return arr;
}

static cJSON *map_json(const sp_costmap *cm)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "resolution_m", cm->res);
    cJSON_AddItemToObject(o, "origin_xy", nav_json_floats(cm->origin, 2));
    cJSON_AddNumberToObject(o, "width", cm->nx);
    cJSON_AddNumberToObject(o, "height", cm->ny);
    cJSON_AddNumberToObject(o, "floor_z", cm->floor_z);
    cJSON_AddItemToObject(o, "band_z", nav_json_floats(cm->band, 2));
    cJSON_AddNumberToObject(o, "robot_radius_m", cm->opts.robot_radius_m);
    return o;
}

static cJSON *plan_json(const sp_nav *nav, const sp_nav_plan *p)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "id", p->id);
    cJSON_AddStringToObject(o, "frame", "world (the model's frame: z up, metres; yaw about +z from +x)");
    if (p->target.text[0]) cJSON_AddItemToObject(o, "target", nav_json_target(&p->target));
    cJSON_AddItemToObject(o, "goal", goal_json(&p->goal));
    cJSON_AddItemToObject(o, "start", nav_json_floats(p->start, 3));
    cJSON_AddNumberToObject(o, "k_requested", p->k);
    cJSON_AddNumberToObject(o, "k_found", p->n);
    cJSON_AddStringToObject(o, "note", p->note);
    cJSON *rel = cJSON_AddArrayToObject(o, "related_concepts");
    for (int i = 0; i < p->n_related; i++) {
        cJSON *e = cJSON_CreateObject();
        cJSON_AddStringToObject(e, "text", p->related[i]);
        cJSON_AddBoolToObject(e, "found", p->related_found[i]);
        cJSON_AddItemToArray(rel, e);
    }
    const sp_planner_opts *po = &nav->opts.planner;
    cJSON *rules = cJSON_AddObjectToObject(o, "distinctness");
    cJSON_AddNumberToObject(rules, "max_share", po->max_share);
    cJSON_AddNumberToObject(rules, "max_length_ratio", po->max_length_ratio);
    cJSON_AddNumberToObject(rules, "share_radius_m", po->share_radius_m);
    cJSON *arr = cJSON_AddArrayToObject(o, "trajectories");
    for (int i = 0; i < p->n; i++) {
        const sp_nav_trajectory *t = &p->traj[i];
        cJSON *e = cJSON_CreateObject();
        cJSON_AddStringToObject(e, "id", t->id);
        cJSON_AddNumberToObject(e, "rank", t->rank);
        cJSON_AddNumberToObject(e, "share_with_better", t->share);
        cJSON_AddItemToObject(e, "score", score_json(&t->score, &nav->opts.weights));
        cJSON *pj = path_json(&t->path);
        cJSON_AddItemToObject(pj, "localizability", nav_json_floats(t->loc, t->path.n));
        cJSON_AddItemToObject(e, "path", pj);
        cJSON_AddItemToObject(e, "previews", previews_json(t->previews, t->n_previews));
        cJSON_AddItemToArray(arr, e);
    }
    cJSON_AddItemToObject(o, "map", map_json(&nav->cm));
    cJSON *ms = cJSON_AddObjectToObject(o, "timings_ms");
    cJSON_AddNumberToObject(ms, "plan", p->ms_plan);
    cJSON_AddNumberToObject(ms, "rank", p->ms_rank);
    cJSON_AddNumberToObject(ms, "previews", p->ms_previews);
    return o;
}

char *sp_nav_plan_json(const sp_nav *nav, const sp_nav_plan *p)
{
    cJSON *o = plan_json(nav, p);
    char *s = cJSON_Print(o);
    cJSON_Delete(o);
    return s;
}

int nav_write_previews(sp_nav_preview *pv, int n, const char *out_dir, const char *stem, sp_error *err)
{
    for (int j = 0; j < n; j++) {
        if (!pv[j].rgb) continue;
        char path[4096];
        snprintf(pv[j].file, sizeof pv[j].file, "previews/%s_%d.png", stem, j + 1);
        sp_path_join(path, sizeof path, out_dir, pv[j].file);
        sp_image img = {pv[j].width, pv[j].height, 3, 8, pv[j].rgb};
        int rc = sp_image_write_png(path, &img, err);
        if (rc) return rc;
    }
    return SP_OK;
}

/* The objects a plan found: its target's instances and the related concepts' (re-resolved). */
static int plan_objects(sp_nav *nav, const sp_nav_plan *p, sp_nav_box *boxes, char (*labels)[64],
                        int *is_target, int cap, sp_error *err)
{
    int n = 0;
    for (int k = 0; k < p->target.n && n < cap; k++, n++) {
        boxes[n] = p->target.inst[k].box;
        snprintf(labels[n], 64, "%s", p->target.inst[k].label);
        is_target[n] = 1;
    }
    for (int i = 0; i < p->n_related && n < cap; i++) {
        if (!p->related_found[i]) continue;
        sp_nav_target t;
        int rc = sp_nav_resolve(nav, p->related[i], &t, err);
        if (rc) return -1;
        if (!strncmp(t.source, "region", 6)) continue; /* a room: its objects are listed anyway */
        for (int k = 0; k < t.n && n < cap; k++, n++) {
            boxes[n] = t.inst[k].box;
            snprintf(labels[n], 64, "%s", t.inst[k].label);
            is_target[n] = 0;
        }
    }
    return n;
}

static int draw_plan(sp_nav *nav, sp_nav_plan *p, const char *out_dir, sp_error *err)
{
    enum { CAP = 64 };
    sp_nav_box boxes[CAP];
    char labels[CAP][64], path_labels[16][128], title[320], file[4096];
    int is_target[CAP];
    int n_obj = plan_objects(nav, p, boxes, labels, is_target, CAP, err);
    if (n_obj < 0) return err->code;
    const sp_path *paths[16];
    int np = p->n < 16 ? p->n : 16;
    for (int i = 0; i < np; i++) {
        const sp_nav_score *s = &p->traj[i].score;
        paths[i] = &p->traj[i].path;
        snprintf(path_labels[i], sizeof path_labels[i], "#%d  %.1f m  clear %.2f m  loc %.2f  score %.2f",
                 p->traj[i].rank, s->length_m, s->clearance_min_m, s->localizability, s->total);
    }
    snprintf(title, sizeof title, "%s: %d of %d trajectories to %s", p->id, p->n, p->k,
             p->target.text[0] ? p->target.text : "the goal");
    nav_map_layers L = {&nav->cm, title, p->start, np, paths, (const char(*)[128])path_labels, n_obj, boxes,
                        (const char(*)[64])labels, is_target, 0, NULL, NULL};
    sp_path_join(file, sizeof file, out_dir, "map.png");
    int rc = nav_draw_map(&L, file, err);
    for (int i = 0; i < p->n && !rc; i++) {
        const sp_nav_trajectory *t = &p->traj[i];
        char stem[64], rel[96];
        snprintf(stem, sizeof stem, "t%d_sheet.png", t->rank);
        snprintf(rel, sizeof rel, "previews/%s", stem);
        sp_path_join(file, sizeof file, out_dir, rel);
        snprintf(title, sizeof title, "trajectory #%d (%s) to %s: %.1f m, min clearance %.2f m, "
                 "localizability %.2f, score %.2f", t->rank, t->id, p->target.text[0] ? p->target.text : "the goal",
                 t->score.length_m, t->score.clearance_min_m, t->score.localizability, t->score.total);
        if (t->n_previews) rc = nav_draw_sheet(title, t->previews, t->n_previews, file, err);
    }
    return rc;
}

int sp_nav_plan_write(sp_nav *nav, sp_nav_plan *p, const char *out_dir, sp_error *err)
{
    char dir[4096], file[4096];
    sp_path_join(dir, sizeof dir, out_dir, "previews");
    int rc = sp_mkdirs(dir, err);
    if (rc) return rc;
    sp_path_join(file, sizeof file, out_dir, "map.yaml");
    if ((rc = sp_costmap_write_map(&nav->cm, file, err))) return rc;
    for (int i = 0; i < p->n && !rc; i++) {
        char stem[32];
        snprintf(stem, sizeof stem, "t%d", p->traj[i].rank);
        rc = nav_write_previews(p->traj[i].previews, p->traj[i].n_previews, out_dir, stem, err);
    }
    if (rc) return rc;
    const char *why = NULL;
    int drawn = nav_draw_available(&why);
    if (drawn && (rc = draw_plan(nav, p, out_dir, err))) return rc;
    cJSON *o = plan_json(nav, p);
    cJSON *files = cJSON_AddObjectToObject(o, "files");
    cJSON_AddStringToObject(files, "map_yaml", "map.yaml");
    cJSON_AddStringToObject(files, "map_pgm", "map.pgm");
    if (drawn) cJSON_AddStringToObject(files, "map_png", "map.png");
    else cJSON_AddStringToObject(files, "map_png_unavailable", why);
    cJSON *sheets = cJSON_AddArrayToObject(files, "contact_sheets");
    for (int i = 0; i < p->n && drawn; i++) {
        char rel[64];
        snprintf(rel, sizeof rel, "previews/t%d_sheet.png", p->traj[i].rank);
        if (p->traj[i].n_previews) cJSON_AddItemToArray(sheets, cJSON_CreateString(rel));
    }
    sp_path_join(file, sizeof file, out_dir, "plan.json");
    rc = sp_json_write_file(file, o, err);
    cJSON_Delete(o);
    return rc;
}
