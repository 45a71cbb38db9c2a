/* The evaluation's documents: report.md, report.html and report.json under the output folder,
 * each written atomically; every number in them comes from the run. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval/doc.h"
#include "eval/eval_internal.h"
#include "semsplat/io.h"

static const char *fmt_m(char *b, size_t cap, double v, const char *nan)
{
    if (isfinite(v)) snprintf(b, cap, "%.3f", v);
    else snprintf(b, cap, "%s", nan);
    return b;
}

static const char *fmt_xyz(char *b, size_t cap, const float *p)
{
    if (!isfinite(p[0])) snprintf(b, cap, "-");
    else snprintf(b, cap, "(%.2f, %.2f, %.2f)", p[0], p[1], p[2]);
    return b;
}

static void head(doc *d, const sp_eval_run *r, const char *title)
{
    const sp_query_source *s = &r->loc.source;
    doc_heading(d, 1, title);
    doc_table(d, 2);
    doc_cell(d, "what");
    doc_cell(d, "value");
    doc_cell(d, "model");
    doc_cell(d, "`%s`", r->model_dir);
    doc_cell(d, "world (ground truth)");
    doc_cell(d, "`%s` (%zu objects)", r->gt.world, r->gt.n);
    doc_cell(d, "capture");
    doc_cell(d, "`%s`, plan `%s`", r->capture_dir[0] ? r->capture_dir : "unknown", r->plan);
    doc_cell(d, "poses");
    doc_cell(d, "%s", r->poses);
    doc_cell(d, "features / text encoder");
    doc_cell(d, "`%s` / `%s` (vocabulary comparison: `%s`)%s%s", s->features, s->encoder, r->vocab_encoder,
             sp_query_source_note(s)[0] ? ": " : "", sp_query_source_note(s));
    doc_cell(d, "frame");
    doc_cell(d, "%s (%s, %s, up %s)", r->loc.frame.name, r->loc.frame.source, r->loc.frame.units, r->loc.frame.up);
    doc_cell(d, "matching");
    doc_cell(d, "one-to-one; an instance matches an object inside the object's box grown by %.2f m; "
                "fragments of one object within %.2f m merged first", (double)r->loc.match_radius_m,
             (double)SP_EVAL_MERGE_GAP_M);
    doc_cell(d, "run time");
    doc_cell(d, "%.1f s", r->seconds);
}

static void localization(doc *d, const sp_eval_run *r, char figs[][1100], int n_figs)
{
    static const char *mname[2] = {"3D-native", "multi-view"};
    char a[4][64];
    doc_heading(d, 2, "5.1 Object localization");
    doc_table(d, 8);
    const char *h[8] = {"method", "recall", "precision", "mean error, matched (m)", "median (m)",
                        "mean with misses (m)", "classes found", "absent controls rejected"};
    for (int i = 0; i < 8; i++) doc_cell(d, "%s", h[i]);
    for (int m = 0; m < SP_EVAL_METHODS; m++) {
        const sp_eval_summary *s = &r->loc.summary[m];
        doc_cell(d, "%s", mname[m]);
        doc_cell(d, "%d/%d (%s)", s->matched, s->objects, fmt_m(a[0], 64, s->recall, "-"));
        doc_cell(d, "%d/%d (%s)", s->true_instances, s->instances, fmt_m(a[1], 64, s->precision, "-"));
        doc_cell(d, "%s", fmt_m(a[2], 64, s->mean_error_m, "-"));
        doc_cell(d, "%s", fmt_m(a[3], 64, s->median_error_m, "-"));
        doc_cell(d, "%s", fmt_m(a[0], 64, s->mean_error_with_misses_m, "-"));
        doc_cell(d, "%d/%d", s->classes_found, s->classes);
        doc_cell(d, "%d/%d", s->absent_rejected, s->absent);
    }
    doc_table(d, 7);
    const char *o[7] = {"object", "class", "ground truth (x, y, z)", "3D estimate", "3D error (m)",
                        "multi-view estimate", "multi-view error (m)"};
    for (int i = 0; i < 7; i++) doc_cell(d, "%s", o[i]);
    for (size_t i = 0; i < r->loc.n_objects; i++) {
        const sp_eval_object *ob = &r->loc.objects[i];
        doc_cell(d, "%s", ob->name);
        doc_cell(d, "%s", ob->cls);
        doc_cell(d, "%s", fmt_xyz(a[0], 64, ob->truth));
        doc_cell(d, "%s", fmt_xyz(a[1], 64, ob->estimate[0]));
        doc_cell(d, "%s", ob->instance[0] >= 0 ? fmt_m(a[2], 64, ob->error_m[0], "-") : "**missed**");
        doc_cell(d, "%s", fmt_xyz(a[3], 64, ob->estimate[1]));
        doc_cell(d, "%s", ob->instance[1] >= 0 ? fmt_m(a[2], 64, ob->error_m[1], "-") : "**missed**");
    }
    for (int f = 0; f < n_figs; f++)
        if (strstr(figs[f], "localization.png"))
            doc_figure(d, figs[f], "Per-object localization error, both methods; a cross marks a miss.");
}

static void vocabulary(doc *d, const sp_eval_run *r, char figs[][1100], int n_figs)
{
    char a[3][64];
    doc_heading(d, 2, "5.2 Open vs closed vocabulary");
    doc_para(d, "The closed-vocabulary baseline is the same map restricted to COCO's 80 class names: the "
                "query is replaced by the COCO class WordNet matches best (or none), and found means that "
                "class's answer lies on an object the query means. The semantic splat answers the query "
                "itself. Error: answer to the nearest right object's box centre.");
    doc_table(d, 8);
    const char *h[8] = {"query", "in COCO?", "COCO baseline (class)", "COCO finds it?",
                        "semantic splat finds it?", "splat confidence", "position error (m)",
                        "the text matched"};
    for (int i = 0; i < 8; i++) doc_cell(d, "%s", h[i]);
    for (size_t k = 0; k < r->n_vocab; k++) {
        const sp_eval_vocab_row *q = &r->vocab[k];
        doc_cell(d, "\"%s\"", q->spec.text);
        doc_cell(d, "%s", q->in_coco ? "yes" : "no");
        doc_cell(d, "%s", q->coco_class[0] ? q->coco_class : "(none)");
        if (!q->n_targets) {
            doc_cell(d, "n/a: not in this world");
            doc_cell(d, "n/a: not in this world");
        } else {
            doc_cell(d, "%s", !q->coco_class[0] ? "no (no class)" : q->closed_found ? "yes" : "no");
            doc_cell(d, "%s", q->open_found ? "yes" : "no");
        }
        doc_cell(d, "%.2f", (double)q->open_confidence);
        doc_cell(d, "%s", fmt_m(a[0], 64, q->open_error_m, "-"));
        doc_cell(d, "%s", q->matched[0] ? q->matched : "-");
    }
    for (int f = 0; f < n_figs; f++)
        if (strstr(figs[f], "vocabulary.png"))
            doc_figure(d, figs[f], "Position error when found, semantic splat against the COCO-80 baseline.");
}

static void trajectories(doc *d, const sp_eval_run *r)
{
    doc_heading(d, 2, "5.4 Trajectory quality");
    if (!r->traj_measured) {
        char t[600];
        snprintf(t, sizeof t, "Not measured: %s.", r->traj_note[0] ? r->traj_note : "no plan");
        doc_para(d, t);
        return;
    }
    char t[700];
    snprintf(t, sizeof t, "The top %d trajectories nav ranks to \"%s\". Visual quality (1-5) is measured on each "
             "trajectory's previews: 1 + 4 x the share of the view the splat covers x its sharpness (the "
             "no-reference blur of Crete et al. 2007, anchored on synth's camera images). %s",
             r->n_traj, r->traj_target, r->traj_note);
    doc_para(d, t);
    doc_table(d, 8);
    const char *h[8] = {"trajectory", "path length (m)", "min clearance (m)", "mean clearance (m)",
                        "visual quality (1-5)", "localizability (0-1)", "ranking score", "notes"};
    for (int i = 0; i < 8; i++) doc_cell(d, "%s", h[i]);
    for (int i = 0; i < r->n_traj; i++) {
        const sp_eval_trajectory *e = &r->traj[i];
        doc_cell(d, "#%d", e->rank);
        doc_cell(d, "%.2f", (double)e->length_m);
        doc_cell(d, "%.2f", (double)e->clearance_min_m);
        doc_cell(d, "%.2f", (double)e->clearance_mean_m);
        doc_cell(d, "%d (%.2f)", e->visual_grade, (double)e->visual_score);
        doc_cell(d, "%.2f", (double)e->localizability);
        doc_cell(d, "%.3f", (double)e->total);
        doc_cell(d, "%d previews: %.0f%% covered, sharpness %.2f%s", e->n_previews, 100.0 * e->coverage,
                 (double)e->sharpness, i ? "" : "; the best ranked");
    }
    if (r->traj_map[0]) doc_figure(d, r->traj_map, "Top-down map: costmap, objects found, start and the ranked paths.");
    for (int i = 0; i < r->n_traj; i++)
        if (r->traj[i].sheet[0]) {
            char cap[64];
            snprintf(cap, sizeof cap, "Previews along trajectory #%d.", r->traj[i].rank);
            doc_figure(d, r->traj[i].sheet, cap);
        }
}

static cJSON *traj_json(const sp_eval_run *r)
{
    cJSON *tr = cJSON_CreateObject();
    cJSON_AddBoolToObject(tr, "measured", r->traj_measured);
    cJSON_AddStringToObject(tr, "target", r->traj_target);
    cJSON_AddStringToObject(tr, "note", r->traj_note);
    cJSON_AddStringToObject(tr, "map", r->traj_map);
    cJSON *a = cJSON_AddArrayToObject(tr, "trajectories");
    for (int i = 0; i < r->n_traj; i++) {
        const sp_eval_trajectory *e = &r->traj[i];
        cJSON *o = cJSON_CreateObject();
        cJSON_AddNumberToObject(o, "rank", e->rank);
        cJSON_AddNumberToObject(o, "length_m", e->length_m);
        cJSON_AddNumberToObject(o, "clearance_min_m", e->clearance_min_m);
        cJSON_AddNumberToObject(o, "clearance_mean_m", e->clearance_mean_m);
        cJSON_AddNumberToObject(o, "visual_quality", e->visual_grade);
        cJSON_AddNumberToObject(o, "visual_score", e->visual_score);
        cJSON_AddNumberToObject(o, "preview_coverage", e->coverage);
        cJSON_AddNumberToObject(o, "preview_sharpness", e->sharpness);
        cJSON_AddNumberToObject(o, "localizability", e->localizability);
        cJSON_AddNumberToObject(o, "score", e->total);
        cJSON_AddNumberToObject(o, "share_with_better", e->share);
        cJSON_AddStringToObject(o, "sheet", e->sheet);
        cJSON_AddItemToArray(a, o);
    }
    return tr;
}

static cJSON *vocab_json(const sp_eval_run *r)
{
    cJSON *a = cJSON_CreateArray();
    for (size_t k = 0; k < r->n_vocab; k++) {
        const sp_eval_vocab_row *q = &r->vocab[k];
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "query", q->spec.text);
        cJSON_AddBoolToObject(o, "in_coco", q->in_coco);
        cJSON_AddBoolToObject(o, "region", q->spec.region);
        cJSON_AddNumberToObject(o, "targets_in_world", q->n_targets);
        cJSON_AddStringToObject(o, "coco_class", q->coco_class);
        cJSON_AddBoolToObject(o, "coco_found", q->closed_found);
        if (isfinite(q->closed_error_m)) cJSON_AddNumberToObject(o, "coco_error_m", q->closed_error_m);
        else cJSON_AddNullToObject(o, "coco_error_m");
        cJSON_AddBoolToObject(o, "splat_found", q->open_found);
        cJSON_AddNumberToObject(o, "splat_confidence", q->open_confidence);
        if (isfinite(q->open_error_m)) cJSON_AddNumberToObject(o, "splat_error_m", q->open_error_m);
        else cJSON_AddNullToObject(o, "splat_error_m");
        cJSON_AddStringToObject(o, "matched", q->matched);
        cJSON_AddItemToArray(a, o);
    }
    return a;
}

static int write_json(const sp_eval_run *r, const char *path, const char *title, char figs[][1100], int n)
{
    cJSON *j = cJSON_CreateObject();
    cJSON_AddStringToObject(j, "format", "semsplat-eval-1");
    cJSON_AddStringToObject(j, "title", title);
    cJSON_AddStringToObject(j, "model", r->model_dir);
    cJSON_AddStringToObject(j, "world", r->gt.world);
    cJSON_AddStringToObject(j, "capture", r->capture_dir);
    cJSON_AddStringToObject(j, "capture_plan", r->plan);
    cJSON_AddStringToObject(j, "poses", r->poses);
    if (isfinite(r->sfm_ate_rms_m)) cJSON_AddNumberToObject(j, "colmap_camera_error_rms_m", r->sfm_ate_rms_m);
    if (isfinite(r->train_psnr)) cJSON_AddNumberToObject(j, "train_psnr_db", r->train_psnr);
    cJSON_AddNumberToObject(j, "gaussians", (double)r->n_gaussians);
    cJSON_AddStringToObject(j, "vocabulary_encoder", r->vocab_encoder);
    cJSON_AddItemToObject(j, "localization", sp_eval_report_json(&r->loc));
    cJSON_AddItemToObject(j, "vocabulary", vocab_json(r));
    cJSON *nav = cJSON_AddObjectToObject(j, "query_success");
    cJSON_AddBoolToObject(nav, "measured", 0);
    cJSON_AddStringToObject(nav, "reason", "navigation (nav, agent over the simulated robot) not in this build");
    cJSON_AddItemToObject(j, "trajectories", traj_json(r));
    cJSON_AddStringToObject(j, "analysis", r->analysis);
    cJSON *f = cJSON_AddArrayToObject(j, "figures");
    for (int i = 0; i < n; i++) cJSON_AddItemToArray(f, cJSON_CreateString(figs[i]));
    cJSON_AddNumberToObject(j, "seconds", r->seconds);
    sp_error err = {0};
    int rc = sp_json_write_file(path, j, &err);
    cJSON_Delete(j);
    return rc;
}

static int write_text(const char *dir, const char *name, char *text, sp_error *err)
{
    if (!text) return sp_error_set(err, SP_E_NOMEM, "eval: out of memory writing %s", name);
    char path[1300];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    int rc = sp_write_file_atomic(path, text, strlen(text), err);
    free(text);
    return rc;
}

/* 5.3: a row per command, the rate of each stage, the plot and the graded views. */
static void navigation(doc *d, const sp_eval_run *r)
{
    doc_heading(d, 2, "5.3 Query success rate");
    const sp_nav_success *s = &r->nav;
    if (!r->nav_measured) {
        char t[600];
        snprintf(t, sizeof t, "Not measured: %s.", r->nav_note);
        doc_para(d, t);
        return;
    }
    char t[900];
    snprintf(t, sizeof t, "%d commands through the agent (built-in parser brain) and the %s. Stages: intent "
             "parsed (the parser read a go-to), valid location (the located goal within the match radius of "
             "an object of the class the command means, and a path planned), reached (the robot reported "
             "success within 0.3 m), views useful (mean view-quality score >= 2.5 of 4 views rendered from the "
             "splat along the driven path). Rates: parsed %d/%d, valid %d/%d, reached %d/%d, views useful "
             "%d/%d.", s->n, s->robot, s->count[0], s->n, s->count[1], s->n, s->count[2], s->n, s->count[3], s->n);
    doc_para(d, t);
    doc_table(d, 8);
    static const char *const cols[] = {"command", "class", "parsed", "valid", "error (m)", "reached", "views (score)",
                                       "note"};
    for (int i = 0; i < 8; i++) doc_cell(d, "%s", cols[i]);
    for (int i = 0; i < s->n; i++) {
        const sp_nav_success_row *w = &s->rows[i];
        doc_cell(d, "%s", w->command);
        doc_cell(d, "%s", w->expect);
        doc_cell(d, "%s", w->parsed ? "yes" : "no");
        doc_cell(d, "%s", w->valid ? "yes" : "no");
        if (isfinite(w->error_m)) doc_cell(d, "%.2f", w->error_m);
        else doc_cell(d, "-");
        doc_cell(d, "%s", w->reached ? "yes" : "no");
        doc_cell(d, "%s (%.1f)", w->useful ? "yes" : "no", w->grade);
        doc_cell(d, "%s", w->note);
    }
    doc_figure(d, s->plot, "5.3: success per stage");
    for (int i = 0; i < s->n; i++)
        if (s->rows[i].views[0]) {
            char cap[300];
            snprintf(cap, sizeof cap, "views along \"%s\"", s->rows[i].command);
            doc_figure(d, s->rows[i].views, cap);
        }
}

int ev_write_docs(const sp_eval_run *r, const char *out_dir, char figs[][1100], int n_figs,
                  const char *title, sp_error *err)
{
    doc d = {0};
    head(&d, r, title);
    doc_heading(&d, 2, "Analysis");
    /* the analysis is paragraphs separated by blank lines */
    char *copy = strdup(r->analysis), *save = NULL;
    for (char *p = copy ? strtok_r(copy, "\n", &save) : NULL; p; p = strtok_r(NULL, "\n", &save))
        if (*p) doc_para(&d, p);
    free(copy);
    localization(&d, r, figs, n_figs);
    vocabulary(&d, r, figs, n_figs);
    navigation(&d, r);
    trajectories(&d, r);
    if (!n_figs) doc_para(&d, "(No figures: this build lacks Cairo.)");
    int rc = write_text(out_dir, "report.md", doc_markdown(&d, out_dir), err);
    if (!rc) rc = write_text(out_dir, "report.html", doc_html(&d, title), err);
    doc_free(&d);
    char path[1300];
    snprintf(path, sizeof path, "%s/report.json", out_dir);
    if (!rc && write_json(r, path, title, figs, n_figs))
        rc = sp_error_set(err, SP_E_IO, "%s: could not be written", path);
    return rc;
}
