/* The report's figures, drawn with media's bar charts (Cairo, as the maps are): per-object
 * localization errors for both methods with misses marked and the match radius as a line, and
 * per-query position errors of the semantic splat against the closed-vocabulary baseline. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval/eval_internal.h"
#include "semsplat/media.h"

static int localization_png(const sp_eval_run *r, const char *path, sp_error *err)
{
    const sp_eval_report *rep = &r->loc;
    int n = (int)rep->n_objects;
    char (*names)[160] = calloc((size_t)n + 1, sizeof *names);
    const char **cats = calloc((size_t)n + 1, sizeof *cats);
    double *v = calloc(2 * (size_t)n + 1, sizeof *v);
    uint8_t *miss = calloc(2 * (size_t)n + 1, 1);
    int rc = 0;
    if (!names || !cats || !v || !miss) rc = sp_error_set(err, SP_E_NOMEM, "eval: out of memory");
    for (int i = 0; !rc && i < n; i++) {
        const sp_eval_object *o = &rep->objects[i];
        if (!strcmp(o->name, o->cls)) snprintf(names[i], sizeof names[i], "%s", o->name);
        else snprintf(names[i], sizeof names[i], "%s (%s)", o->name, o->cls);
        cats[i] = names[i];
        for (int m = 0; m < SP_EVAL_METHODS; m++) {
            v[m * n + i] = o->instance[m] >= 0 ? o->error_m[m] : NAN;
            miss[m * n + i] = o->instance[m] < 0;
        }
    }
    sp_plot_series s[2] = {{.name = "3D-native", .values = v, .missed = miss},
                           {.name = "multi-view", .values = v + n, .missed = miss + n}};
    char title[256];
    snprintf(title, sizeof title, "Localization error per object (%s world, %d objects)",
             r->gt.world[0] ? strrchr(r->gt.world, '/') ? strrchr(r->gt.world, '/') + 1 : r->gt.world : "", n);
    sp_plot_bars p = {.title = title, .x_label = "distance from the matched instance to the object's box centre (m)",
                      .n_categories = n, .categories = cats, .n_series = 2, .series = s,
                      .ref_value = rep->match_radius_m, .ref_label = "match radius", .value_format = "%.2f"};
    if (!rc) rc = sp_plot_bars_png(path, 1100, 140 + 34 * n, &p, err);
    free(names);
    free(cats);
    free(v);
    free(miss);
    return rc;
}

static int vocabulary_png(const sp_eval_run *r, const char *path, sp_error *err)
{
    int n = (int)r->n_vocab;
    char (*names)[200] = calloc((size_t)n + 1, sizeof *names);
    const char **cats = calloc((size_t)n + 1, sizeof *cats);
    double *v = calloc(2 * (size_t)n + 1, sizeof *v);
    uint8_t *miss = calloc(2 * (size_t)n + 1, 1);
    int rc = 0;
    if (!names || !cats || !v || !miss) rc = sp_error_set(err, SP_E_NOMEM, "eval: out of memory");
    for (int i = 0; !rc && i < n; i++) {
        const sp_eval_vocab_row *q = &r->vocab[i];
        snprintf(names[i], sizeof names[i], "\"%s\"%s%s", q->spec.text, q->in_coco ? " (COCO)" : "",
                 q->n_targets ? "" : " - not in this world");
        cats[i] = names[i];
        int has = q->n_targets > 0;
        v[i] = q->open_found ? q->open_error_m : NAN;
        miss[i] = has && !q->open_found;
        v[n + i] = q->closed_found ? q->closed_error_m : NAN;
        miss[n + i] = has && !q->closed_found;
    }
    sp_plot_series s[2] = {{.name = "semantic splat (open vocabulary)", .values = v, .missed = miss},
                           {.name = "COCO-80 baseline (closed vocabulary)", .values = v + n, .missed = miss + n}};
    sp_plot_bars p = {.title = "Open vs closed vocabulary: position error when found",
                      .x_label = "answer to the nearest right object's centre (m)", .n_categories = n,
                      .categories = cats, .n_series = 2, .series = s, .value_format = "%.2f"};
    if (!rc) rc = sp_plot_bars_png(path, 1100, 160 + 40 * n, &p, err);
    free(names);
    free(cats);
    free(v);
    free(miss);
    return rc;
}

int ev_figures(const sp_eval_run *r, const char *out_dir, char figs[][1100], int max, sp_error *err)
{
    int n = 0, rc = 0;
    if (max < 2) return 0;
    snprintf(figs[n], 1100, "%s/figures/localization.png", out_dir);
    if (r->loc.n_objects && !(rc = localization_png(r, figs[n], err))) n++;
    if (!rc && r->n_vocab) {
        snprintf(figs[n], 1100, "%s/figures/vocabulary.png", out_dir);
        if (!(rc = vocabulary_png(r, figs[n], err))) n++;
    }
    /* without Cairo the report goes out without figures, saying so */
    if (rc == SP_E_UNSUPPORTED) {
        sp_error_clear(err);
        return n;
    }
    return rc ? rc : n;
}
