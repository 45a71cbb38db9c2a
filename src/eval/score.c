/* The localization report: every ground-truth class (and absent controls) queried with both
 * methods, instances matched one-to-one to the class's objects, totals with misses counted. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/eval.h"
#include "semsplat/io.h"

const char *const sp_eval_default_absent[] = {"fire extinguisher", "piano", "bicycle", "bathtub",
                                              "car", "toilet", "washing machine", "fire hydrant",
                                              NULL};

static int has_class(const sp_ground_truth *gt, const char *cls)
{
    for (size_t i = 0; i < gt->n; i++)
        if (!strcmp(gt->objects[i].cls, cls)) return 1;
    return 0;
}

static void query_init(sp_eval_query *q, const char *text, int present)
{
    memset(q, 0, sizeof *q);
    snprintf(q->text, sizeof q->text, "%s", text);
    q->present = present;
    for (int m = 0; m < SP_EVAL_METHODS; m++) {
        q->query_error_m[m] = NAN;
        q->position[m][0] = q->position[m][1] = q->position[m][2] = NAN;
    }
}

static void object_init(sp_eval_object *o, const sp_gt_object *g, float radius)
{
    memset(o, 0, sizeof *o);
    snprintf(o->name, sizeof o->name, "%s", g->name);
    snprintf(o->cls, sizeof o->cls, "%s", g->cls);
    memcpy(o->truth, g->center, sizeof o->truth);
    o->miss_penalty_m = sp_eval_miss_penalty(g, radius);
    for (int m = 0; m < SP_EVAL_METHODS; m++) {
        o->instance[m] = -1;
        o->error_m[m] = NAN;
        o->estimate[m][0] = o->estimate[m][1] = o->estimate[m][2] = NAN;
    }
}

int sp_eval_report_init(sp_eval_report *rep, const sp_ground_truth *gt, const char *const *absent,
                        float radius, sp_error *err)
{
    memset(rep, 0, sizeof *rep);
    rep->match_radius_m = radius > 0 ? radius : 0.5f;
    if (!absent) absent = sp_eval_default_absent;
    size_t n_abs = 0;
    while (absent[n_abs]) n_abs++;
    rep->objects = calloc(gt->n ? gt->n : 1, sizeof *rep->objects);
    rep->queries = calloc(gt->n + n_abs + 1, sizeof *rep->queries);
    if (!rep->objects || !rep->queries) {
        sp_eval_report_free(rep);
        return sp_error_set(err, SP_E_NOMEM, "eval: out of memory for %zu objects", gt->n);
    }
    rep->n_objects = gt->n;
    for (size_t i = 0; i < gt->n; i++) {
        object_init(&rep->objects[i], &gt->objects[i], rep->match_radius_m);
        size_t q = 0;
        while (q < rep->n_queries && strcmp(rep->queries[q].text, gt->objects[i].cls)) q++;
        if (q == rep->n_queries) query_init(&rep->queries[rep->n_queries++], gt->objects[i].cls, 1);
        rep->queries[q].n_objects++;
    }
    /* a control the world does contain is not absent: left out */
    for (size_t k = 0; k < n_abs; k++)
        if (!has_class(gt, absent[k])) query_init(&rep->queries[rep->n_queries++], absent[k], 0);
    return 0;
}

void sp_eval_report_free(sp_eval_report *rep)
{
    if (!rep) return;
    for (size_t k = 0; rep->queries && k < rep->n_queries; k++)
        for (int m = 0; m < SP_EVAL_METHODS; m++) free(rep->queries[k].instance_pos[m]);
    free(rep->objects);
    free(rep->queries);
    memset(rep, 0, sizeof *rep);
}

static double dist3(const float *a, const float *b)
{
    double dx = (double)a[0] - b[0], dy = (double)a[1] - b[1], dz = (double)a[2] - b[2];
    return sqrt(dx * dx + dy * dy + dz * dz);
}

/* Matches the result's instances to the class's objects and records both sides. */
static int score_present(sp_eval_report *rep, const sp_ground_truth *gt, sp_eval_query *q, int m,
                         const sp_query_result *res, sp_error *err)
{
    int n_obj = q->n_objects, n_inst = res->valid ? res->n_instances : 0;
    sp_gt_object *objs = malloc(sizeof *objs * (size_t)(n_obj ? n_obj : 1));
    size_t *idx = malloc(sizeof *idx * (size_t)(n_obj ? n_obj : 1));
    float *pos = malloc(sizeof(float) * 3 * (size_t)(n_inst ? n_inst : 1)), *e = malloc(sizeof(float) * (size_t)(n_obj ? n_obj : 1));
    int *inst_of = malloc(sizeof(int) * (size_t)(n_obj ? n_obj : 1));
    int rc = 0, k = 0;
    if (!objs || !idx || !pos || !e || !inst_of) rc = sp_error_set(err, SP_E_NOMEM, "eval: out of memory");
    for (size_t i = 0; !rc && i < gt->n; i++)
        if (!strcmp(gt->objects[i].cls, q->text)) objs[k] = gt->objects[i], idx[k++] = i;
    for (int j = 0; !rc && j < n_inst; j++) memcpy(pos + 3 * j, res->instances[j].position, sizeof(float) * 3);
    int got = rc ? 0 : sp_eval_match(objs, n_obj, pos, n_inst, rep->match_radius_m, inst_of, e, err);
    if (got < 0) rc = got;
    for (int i = 0; !rc && i < n_obj; i++) {
        sp_eval_object *o = &rep->objects[idx[i]];
        o->instance[m] = inst_of[i];
        o->error_m[m] = e[i];
        if (inst_of[i] >= 0) memcpy(o->estimate[m], pos + 3 * inst_of[i], sizeof(float) * 3);
    }
    if (!rc) {
        q->matched[m] = got;
        for (int i = 0; res->valid && i < n_obj; i++) {
            double d = dist3(res->position, objs[i].center);
            if (!(d >= q->query_error_m[m])) q->query_error_m[m] = (float)d;
            q->correct[m] |= sp_eval_admissible(&objs[i], res->position, rep->match_radius_m);
        }
    }
    free(objs), free(idx), free(pos), free(e), free(inst_of);
    return rc;
}

int sp_eval_report_add(sp_eval_report *rep, const sp_ground_truth *gt, size_t query, int m,
                       const sp_query_result *res, sp_error *err)
{
    if (query >= rep->n_queries || m < 0 || m >= SP_EVAL_METHODS)
        return sp_error_set(err, SP_E_ARG, "eval: query %zu / method %d out of range", query, m);
    sp_eval_query *q = &rep->queries[query];
    int n = res->valid ? res->n_instances : 0;
    free(q->instance_pos[m]);
    q->instance_pos[m] = malloc(sizeof(float) * 3 * (size_t)(n ? n : 1));
    if (!q->instance_pos[m]) return sp_error_set(err, SP_E_NOMEM, "eval: out of memory");
    for (int j = 0; j < n; j++) memcpy(q->instance_pos[m] + 3 * j, res->instances[j].position, sizeof(float) * 3);
    q->scored[m] = 1;
    q->found[m] = res->valid;
    q->confidence[m] = res->confidence;
    q->n_instances[m] = n;
    q->ms[m] = res->ms_total - res->ms_heatmap;
    if (res->valid) memcpy(q->position[m], res->position, sizeof q->position[m]);
    if (m == 0 || !rep->source.encoder[0]) rep->source = res->source, rep->frame = res->frame;
    return q->present ? score_present(rep, gt, q, m, res, err) : 0;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double ratio(int a, int b) { return b > 0 ? (double)a / b : NAN; }

static void summarize(const sp_eval_report *rep, int m, sp_eval_summary *s, double *buf)
{
    memset(s, 0, sizeof *s);
    double sum = 0, sum_all = 0, sum_q = 0, sum_ms = 0;
    int n_scored = 0;
    for (size_t i = 0; i < rep->n_objects; i++) {
        const sp_eval_object *o = &rep->objects[i];
        s->objects++;
        if (o->instance[m] >= 0) {
            buf[s->matched++] = o->error_m[m];
            sum += o->error_m[m];
            sum_all += o->error_m[m];
        } else {
            sum_all += o->miss_penalty_m;
        }
    }
    for (size_t k = 0; k < rep->n_queries; k++) {
        const sp_eval_query *q = &rep->queries[k];
        if (!q->scored[m]) continue;
        n_scored++;
        sum_ms += q->ms[m];
        s->instances += q->n_instances[m];
        if (!q->present) {
            s->absent++;
            s->absent_rejected += !q->found[m];
            continue;
        }
        s->true_instances += q->matched[m];
        s->classes++;
        s->classes_found += q->found[m];
        s->classes_correct += q->correct[m];
        if (q->found[m]) sum_q += q->query_error_m[m];
    }
    s->recall = ratio(s->matched, s->objects);
    s->precision = ratio(s->true_instances, s->instances);
    s->mean_error_m = s->matched ? sum / s->matched : NAN;
    s->mean_error_with_misses_m = s->objects ? sum_all / s->objects : NAN;
    s->mean_query_error_m = s->classes_found ? sum_q / s->classes_found : NAN;
    s->mean_ms = n_scored ? sum_ms / n_scored : NAN;
    qsort(buf, (size_t)s->matched, sizeof *buf, cmp_double);
    s->median_error_m = !s->matched ? NAN : s->matched % 2 ? buf[s->matched / 2]
                                                            : 0.5 * (buf[s->matched / 2 - 1] + buf[s->matched / 2]);
}

void sp_eval_report_finish(sp_eval_report *rep)
{
    double *buf = malloc(sizeof(double) * (rep->n_objects ? rep->n_objects : 1));
    for (int m = 0; m < SP_EVAL_METHODS && buf; m++) summarize(rep, m, &rep->summary[m], buf);
    free(buf);
    rep->finished = buf != NULL;
}

/* File name of a class's heatmap: lower-case letters and digits, '_' for the rest. */
static void slug(const char *text, char *out, size_t cap)
{
    size_t j = 0;
    for (size_t i = 0; text[i] && j + 1 < cap; i++) {
        unsigned char c = (unsigned char)text[i];
        out[j++] = isalnum(c) ? (char)tolower(c) : '_';
    }
    out[j] = 0;
}

static int write_heatmap(const sp_query_result *res, const char *dir, sp_eval_query *q, sp_error *err)
{
    if (!res->relevancy_image) return 0;
    char sl[200];
    slug(q->text, sl, sizeof sl);
    snprintf(q->heatmap, sizeof q->heatmap, "%s/%s.png", dir, sl);
    sp_image img = {res->width, res->height, 3, 8, res->relevancy_image};
    int rc = sp_image_write_png(q->heatmap, &img, err);
    if (rc) q->heatmap[0] = 0;
    return rc;
}

int sp_eval_localization(sp_query_engine *e, const sp_ground_truth *gt, const sp_eval_opts *o,
                         sp_eval_report *rep, sp_error *err)
{
    const sp_frame *f = sp_query_engine_frame(e);
    if (!sp_frame_is_world(f))
        return sp_error_set(err, SP_E_ARG, "eval: the model's positions are in the %s frame, the "
                            "ground truth in the world's: align the model first (semsplat align "
                            "--model DIR writes frame.json)", sp_frame_name(f));
    int rc = sp_eval_report_init(rep, gt, o ? o->absent : NULL, o ? o->match_radius_m : 0, err);
    if (rc) return rc;
    if (o && o->heatmap_dir && (rc = sp_mkdirs(o->heatmap_dir, err))) return rc;
    sp_progress prog;
    sp_progress_begin(&prog, o ? o->log : NULL, "queries", (long)rep->n_queries, "query");
    for (size_t k = 0; k < rep->n_queries && !rc; k++) {
        for (int m = 0; m < SP_EVAL_METHODS && !rc; m++) {
            sp_query_opts qo = *sp_query_engine_defaults(e);
            qo.method = m ? SP_QUERY_MULTIVIEW : SP_QUERY_3D;
            qo.heatmap = m == 0 && o && o->heatmap_dir;
            sp_query_result res;
            rc = sp_query_engine_query(e, rep->queries[k].text, &qo, &res, err);
            if (rc) sp_error_prefix(err, "query '%s': ", rep->queries[k].text);
            if (!rc) rc = sp_eval_report_add(rep, gt, k, m, &res, err);
            if (!rc && qo.heatmap) rc = write_heatmap(&res, o->heatmap_dir, &rep->queries[k], err);
            sp_query_result_free(&res);
        }
        sp_progress_update(&prog, (long)k + 1, rep->queries[k].text);
    }
    sp_progress_end(&prog, rc ? "failed" : NULL);
    if (!rc) sp_eval_report_finish(rep);
    else sp_eval_report_free(rep);
    return rc;
}
