/* 5.3 query success rate: navigation commands of varied complexity through the agent and the
 * simulated robot, each scored per stage: intent parsed, a valid location (near an object of the
 * class the command means), the goal reached, views along the drive useful (media's view-quality
 * proxy on the splat rendered at four poses of the driven path, saved as one picture). */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "drive.h"
#include "semsplat/io.h"
#include "semsplat/media.h"

/* Written before anything was run, phrased as users type (synonyms, relations, a follow-up). */
static const char *const default_cmds[] = {
    "go to the refrigerator|refrigerator",
    "take me to the sofa|couch",
    "navigate to the bed in the bedroom|bed",
    "drive the robot to the bookshelf|bookshelf",
    "go find the potted plant and stop next to it|potted plant",
    "I want to go to the dining table|dining table",
    "head over to the stove|stove",
    "go to the nearest dining chair|dining chair",
    "move to the tv in the living room|tv",
    "go to something to sit on|couch,armchair,dining chair",
};

#define VIEW_W 160
#define VIEW_H 120

/* Distance from (x, y) to the nearest ground-truth box of one of the classes ("a,b,c"). */
static double class_distance(const sp_ground_truth *gt, const char *classes, double x, double y, double *centre)
{
    double best = INFINITY;
    *centre = INFINITY;
    for (size_t i = 0; gt && i < gt->n; i++) {
        const sp_gt_object *g = &gt->objects[i];
        char list[200];
        snprintf(list, sizeof list, "%s", classes);
        int match = 0;
        for (char *tok = strtok(list, ","); tok && !match; tok = strtok(NULL, ",")) match = !strcmp(tok, g->cls);
        if (!match) continue;
        double dx = fmax(0, fmax(g->aabb_min[0] - x, x - g->aabb_max[0]));
        double dy = fmax(0, fmax(g->aabb_min[1] - y, y - g->aabb_max[1]));
        if (hypot(dx, dy) < best) best = hypot(dx, dy);
        double c = hypot(g->center[0] - x, g->center[1] - y);
        if (c < *centre) *centre = c;
    }
    return best;
}

/* Four views along the driven path graded, drawn side by side into png. Returns the mean score. */
static int grade_views(ev_drive_env *env, const ev_track *t, const char *png, double *mean, sp_error *err)
{
    *mean = 0;
    if (t->n < 1) return SP_OK;
    float *rgb = malloc(sizeof(float) * 3 * VIEW_W * VIEW_H), *alpha = malloc(sizeof(float) * VIEW_W * VIEW_H);
    sp_canvas *c = NULL;
    int rc = rgb && alpha ? 0 : sp_error_set(err, SP_E_NOMEM, "5.3: out of memory");
    if (!rc) rc = sp_canvas_create(&c, 4 * VIEW_W, VIEW_H + 24, err);
    if (!rc) sp_canvas_clear(c, sp_rgba_of(0.1f, 0.1f, 0.12f, 1));
    for (int k = 0; k < 4 && !rc; k++) {
        const sp_drive_sample *s = &t->s[(t->n - 1) * (k + 1) / 4];
        sp_view_quality q;
        rc = ev_drive_render(env, s->x, s->y, s->yaw, VIEW_W, VIEW_H, rgb, alpha, err);
        if (!rc) rc = sp_media_view_quality(rgb, alpha, VIEW_W, VIEW_H, &q, err);
        if (!rc) rc = sp_canvas_image_f32(c, rgb, VIEW_W, VIEW_H, (float)(k * VIEW_W), 0, VIEW_W, VIEW_H, NULL, err);
        if (rc) break;
        char label[64];
        snprintf(label, sizeof label, "%d/5 cover %.2f sharp %.2f", q.grade, q.coverage, q.sharpness);
        sp_text_style st = {.size_px = 11, .color = sp_rgba_of(1, 1, 1, 1)};
        sp_canvas_text(c, (float)(k * VIEW_W) + 4, VIEW_H + 16, &st, label);
        *mean += q.score / 4;
    }
    if (!rc) rc = sp_canvas_write_png(c, png, err);
    sp_canvas_free(c);
    free(rgb), free(alpha);
    return rc;
}

static int run_one(ev_drive_env *env, const sp_ground_truth *gt, const char *spec, float radius, const char *dir,
                   int idx, sp_nav_success_row *row, sp_error *err)
{
    memset(row, 0, sizeof *row);
    row->error_m = NAN;
    const char *bar = strchr(spec, '|');
    snprintf(row->command, sizeof row->command, "%.*s", bar ? (int)(bar - spec) : (int)strlen(spec), spec);
    snprintf(row->expect, sizeof row->expect, "%s", bar ? bar + 1 : "");
    sp_agent_answer a;
    memset(&a, 0, sizeof a);
    int rc = ev_drive_ask(env, row->command, &a, err);
    if (rc) return rc;
    snprintf(row->intent, sizeof row->intent, "%s", sp_agent_intent_name(a.intent));
    row->parsed = a.intent == SP_AGENT_INTENT_GOTO;
    ev_answer_info ai;
    ev_answer_read(&a, &ai);
    if (a.asked_back && !ai.goal_status[0]) { /* a question back (several instances): the user picks */
        snprintf(row->note, sizeof row->note, "asked back: %.200s; answered \"the nearest one\"", a.text ? a.text : "");
        sp_agent_answer_free(&a);
        memset(&a, 0, sizeof a);
        if ((rc = ev_drive_ask(env, "the nearest one", &a, err))) return rc;
        ev_answer_info more;
        ev_answer_read(&a, &more);
        if (!ai.have_target || more.have_target) ai = more;
        else snprintf(ai.goal_status, sizeof ai.goal_status, "%s", more.goal_status), ai.distance_to_goal_m = more.distance_to_goal_m;
    }
    double centre = INFINITY;
    if (ai.have_target && gt) {
        double d = class_distance(gt, row->expect, ai.target[0], ai.target[1], &centre);
        row->error_m = isfinite(centre) ? centre : NAN;
        row->valid = ai.planned && d <= radius;
    } else if (ai.have_target) {
        row->valid = ai.planned;
    }
    row->reached = !strcmp(ai.goal_status, "succeeded") && ai.distance_to_goal_m < 0.3;
    snprintf(row->views, sizeof row->views, "%s/nav_views_%02d.png", dir, idx + 1);
    rc = grade_views(env, &env->track, row->views, &row->grade, err);
    if (env->track.n < 1) row->views[0] = 0;
    row->useful = row->grade >= 2.5;
    if (!row->note[0] && ai.first_error[0]) snprintf(row->note, sizeof row->note, "%.290s", ai.first_error);
    sp_agent_answer_free(&a);
    return rc;
}

static int write_outputs(const sp_nav_success *s, const char *dir, sp_error *err)
{
    static const char *const stages[4] = {"intent parsed", "valid location", "reached goal", "views useful"};
    double pct[4];
    for (int k = 0; k < 4; k++) pct[k] = s->n ? 100.0 * s->count[k] / s->n : 0;
    sp_plot_series se = {"success (%)", pct, NULL, {0, 0, 0, 0}};
    char title[400];
    snprintf(title, sizeof title, "5.3: %d navigation commands, success per stage", s->n);
    sp_plot_bars p = {.title = title, .x_label = "commands that passed (%)", .n_categories = 4,
                      .categories = stages, .n_series = 1, .series = &se, .x_max = 100, .value_format = "%.0f %%"};
    int rc = sp_plot_bars_png(s->plot, 900, 360, &p, err);
    cJSON *j = cJSON_CreateObject(), *rows = cJSON_AddArrayToObject(j, "commands");
    cJSON_AddStringToObject(j, "robot", s->robot);
    for (int i = 0; i < s->n; i++) {
        const sp_nav_success_row *r = &s->rows[i];
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "command", r->command);
        cJSON_AddStringToObject(o, "class", r->expect);
        cJSON_AddStringToObject(o, "intent", r->intent);
        cJSON_AddBoolToObject(o, "parsed", r->parsed);
        cJSON_AddBoolToObject(o, "valid_location", r->valid);
        cJSON_AddBoolToObject(o, "reached", r->reached);
        cJSON_AddBoolToObject(o, "views_useful", r->useful);
        cJSON_AddNumberToObject(o, "view_grade", r->grade);
        if (isfinite(r->error_m)) cJSON_AddNumberToObject(o, "error_m", r->error_m);
        cJSON_AddStringToObject(o, "views", r->views);
        cJSON_AddStringToObject(o, "note", r->note);
        cJSON_AddItemToArray(rows, o);
    }
    cJSON *rate = cJSON_AddObjectToObject(j, "rate");
    for (int k = 0; k < 4; k++) cJSON_AddNumberToObject(rate, stages[k], s->n ? (double)s->count[k] / s->n : 0);
    char path[1200];
    snprintf(path, sizeof path, "%s/nav_success.json", dir);
    if (!rc) rc = sp_json_write_file(path, j, err);
    cJSON_Delete(j);
    return rc;
}

int sp_eval_nav_success(const sp_drive_opts *o, const sp_ground_truth *gt, const char *const *cmds, int n,
                        float match_radius_m, sp_nav_success *out, sp_error *err)
{
    memset(out, 0, sizeof *out);
    if (!cmds) cmds = default_cmds, n = (int)(sizeof default_cmds / sizeof *default_cmds);
    if (n < 1 || n > 16) return sp_error_set(err, SP_E_ARG, "5.3: %d commands (1..16)", n);
    ev_drive_env env;
    int rc = ev_drive_open(&env, o, err);
    if (rc) return rc;
    snprintf(out->robot, sizeof out->robot, "%s", env.robot_note);
    float radius = match_radius_m > 0 ? match_radius_m : 0.5f;
    for (int i = 0; i < n && !rc; i++) {
        rc = run_one(&env, gt, cmds[i], radius, o->out_dir, i, &out->rows[i], err);
        out->n = i + 1;
        const sp_nav_success_row *r = &out->rows[i];
        out->count[0] += r->parsed, out->count[1] += r->valid, out->count[2] += r->reached, out->count[3] += r->useful;
        sp_logf(o->log, SP_LOG_INFO, "5.3: \"%s\": parsed %d, valid %d, reached %d, views %.1f", r->command, r->parsed,
                r->valid, r->reached, r->grade);
    }
    ev_drive_close(&env);
    snprintf(out->plot, sizeof out->plot, "%s/nav_success.png", o->out_dir);
    if (!rc) rc = write_outputs(out, o->out_dir, err);
    return rc ? sp_error_prefix(err, "5.3: ") : 0;
}
