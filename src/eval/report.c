/* The localization report as text: a console table, Markdown (report.md) and JSON. Every line
 * that carries a figure carries what it measures: the source, the frame, the matching rule. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/eval.h"

static const char *method_name[SP_EVAL_METHODS] = {"3D", "multi-view"};
static const char *method_key[SP_EVAL_METHODS] = {"3d", "multiview"};

/* "0.123" or "miss" / "-" for NaN. */
static const char *num(char *buf, size_t cap, double v, const char *nan_text)
{
    if (isfinite(v)) snprintf(buf, cap, "%.3f", v);
    else snprintf(buf, cap, "%s", nan_text);
    return buf;
}

/* The caveats a reader must see before any figure. */
static void provenance(sp_strbuf *b, const sp_eval_report *r, const char *bullet)
{
    const char *note = sp_query_source_note(&r->source);
    sp_strbuf_printf(b, "%ssource: text encoder %s, features %s%s%s\n", bullet, r->source.encoder,
                     r->source.features, note[0] ? ": " : "", note);
    sp_strbuf_printf(b, "%sframe: %s (%s; units %s, up %s)\n", bullet, r->frame.name, r->frame.source,
                     r->frame.units, r->frame.up);
    sp_strbuf_printf(b, "%smatching: one-to-one; an instance matches an object when it lies inside the "
                     "object's box grown by %.2f m; a miss counts in the penalised mean as the largest "
                     "error a match could have had\n", bullet, (double)r->match_radius_m);
    if (!strcmp(r->source.encoder, "exact"))
        sp_strbuf_printf(b, "%sabsent controls: with the exact encoder an absent name is a random "
                         "vector, so rejecting it holds by construction and tests nothing\n", bullet);
}

static void summary_lines(sp_strbuf *b, const sp_eval_report *r, const char *bullet)
{
    char x[5][32];
    for (int m = 0; m < SP_EVAL_METHODS; m++) {
        const sp_eval_summary *s = &r->summary[m];
        sp_strbuf_printf(b, "%s%s: recall %d/%d (%s), precision %d/%d (%s); error over matched objects: "
                         "mean %s m, median %s m; mean with misses counted %s m\n", bullet,
                         method_name[m], s->matched, s->objects, num(x[0], 32, s->recall, "-"),
                         s->true_instances, s->instances, num(x[1], 32, s->precision, "-"),
                         num(x[2], 32, s->mean_error_m, "-"), num(x[3], 32, s->median_error_m, "-"),
                         num(x[4], 32, s->mean_error_with_misses_m, "-"));
    }
    for (int m = 0; m < SP_EVAL_METHODS; m++) {
        const sp_eval_summary *s = &r->summary[m];
        sp_strbuf_printf(b, "%s%s classes: found %d/%d, best answer on an object of its class %d/%d, "
                         "mean error of the best answer to the nearest object of its class %s m; "
                         "absent controls rejected %d/%d; %.1f ms per query\n", bullet,
                         method_name[m], s->classes_found, s->classes, s->classes_correct, s->classes,
                         num(x[0], 32, s->mean_query_error_m, "-"), s->absent_rejected, s->absent,
                         s->mean_ms);
    }
}

char *sp_eval_report_text(const sp_eval_report *r)
{
    sp_strbuf b = {0};
    char e0[32], e1[32];
    sp_strbuf_printf(&b, "%-22s %-24s %6s %8s %8s %5s\n", "query", "object", "conf", "err3d_m", "errmv_m", "inst");
    for (size_t k = 0; k < r->n_queries; k++) {
        const sp_eval_query *q = &r->queries[k];
        if (!q->present) {
            sp_strbuf_printf(&b, "%-22s %-24s %6.3f %8s %8s %5d  (absent: %s)\n", q->text, "-",
                             q->confidence[0], q->found[0] ? "found" : "-", q->found[1] ? "found" : "-",
                             q->n_instances[0], !q->found[0] && !q->found[1] ? "not found, as it should" : "FOUND, wrongly");
            continue;
        }
        for (size_t i = 0; i < r->n_objects; i++) {
            const sp_eval_object *o = &r->objects[i];
            if (strcmp(o->cls, q->text)) continue;
            sp_strbuf_printf(&b, "%-22s %-24s %6.3f %8s %8s %5d\n", q->text, o->name, q->confidence[0],
                             num(e0, 32, o->error_m[0], "miss"), num(e1, 32, o->error_m[1], "miss"),
                             q->n_instances[0]);
        }
    }
    sp_strbuf_printf(&b, "\n");
    provenance(&b, r, "");
    summary_lines(&b, r, "");
    return sp_strbuf_take(&b);
}

char *sp_eval_report_markdown(const sp_eval_report *r, const char *title)
{
    sp_strbuf b = {0};
    char x[6][32];
    sp_strbuf_printf(&b, "# %s\n\n", title ? title : "semsplat localization report");
    provenance(&b, r, "- ");
    sp_strbuf_printf(&b, "\n| method | recall | precision | mean error, matched (m) | median (m) | mean with misses (m) "
                     "| classes found | best answer correct | absent rejected |\n|---|---|---|---|---|---|---|---|---|\n");
    for (int m = 0; m < SP_EVAL_METHODS; m++) {
        const sp_eval_summary *s = &r->summary[m];
        sp_strbuf_printf(&b, "| %s | %d/%d (%s) | %d/%d (%s) | %s | %s | %s | %d/%d | %d/%d | %d/%d |\n",
                         method_name[m], s->matched, s->objects, num(x[0], 32, s->recall, "-"),
                         s->true_instances, s->instances, num(x[1], 32, s->precision, "-"),
                         num(x[2], 32, s->mean_error_m, "-"), num(x[3], 32, s->median_error_m, "-"),
                         num(x[4], 32, s->mean_error_with_misses_m, "-"), s->classes_found, s->classes,
                         s->classes_correct, s->classes, s->absent_rejected, s->absent);
    }
    sp_strbuf_printf(&b, "\n| query | object | confidence | error 3D (m) | error multi-view (m) | instances 3D / mv "
                     "| heatmap |\n|---|---|---|---|---|---|---|\n");
    for (size_t k = 0; k < r->n_queries; k++) {
        const sp_eval_query *q = &r->queries[k];
        for (size_t i = 0; q->present && i < r->n_objects; i++) {
            const sp_eval_object *o = &r->objects[i];
            if (strcmp(o->cls, q->text)) continue;
            sp_strbuf_printf(&b, "| %s | %s | %.3f | %s | %s | %d / %d | %s |\n", q->text, o->name,
                             q->confidence[0], num(x[0], 32, o->error_m[0], "miss"),
                             num(x[1], 32, o->error_m[1], "miss"), q->n_instances[0], q->n_instances[1],
                             q->heatmap);
        }
        if (!q->present)
            sp_strbuf_printf(&b, "| %s | (absent) | %.3f | %s | %s | %d / %d | |\n", q->text, q->confidence[0],
                             q->found[0] ? "FOUND" : "-", q->found[1] ? "FOUND" : "-", q->n_instances[0],
                             q->n_instances[1]);
    }
    sp_strbuf_printf(&b, "\n");
    summary_lines(&b, r, "- ");
    return sp_strbuf_take(&b);
}

static cJSON *vec3_or_null(const float *v)
{
    if (!isfinite(v[0])) return cJSON_CreateNull();
    double d[3] = {v[0], v[1], v[2]};
    return cJSON_CreateDoubleArray(d, 3);
}

static void add_num(cJSON *o, const char *key, double v)
{
    if (isfinite(v)) cJSON_AddNumberToObject(o, key, v);
    else cJSON_AddNullToObject(o, key);
}

static cJSON *summary_json(const sp_eval_summary *s)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "objects", s->objects);
    cJSON_AddNumberToObject(o, "matched", s->matched);
    cJSON_AddNumberToObject(o, "instances", s->instances);
    cJSON_AddNumberToObject(o, "true_instances", s->true_instances);
    add_num(o, "recall", s->recall);
    add_num(o, "precision", s->precision);
    add_num(o, "mean_error_m", s->mean_error_m);
    add_num(o, "median_error_m", s->median_error_m);
    add_num(o, "mean_error_with_misses_m", s->mean_error_with_misses_m);
    cJSON_AddNumberToObject(o, "classes", s->classes);
    cJSON_AddNumberToObject(o, "classes_found", s->classes_found);
    cJSON_AddNumberToObject(o, "classes_correct", s->classes_correct);
    add_num(o, "mean_query_error_m", s->mean_query_error_m);
    cJSON_AddNumberToObject(o, "absent", s->absent);
    cJSON_AddNumberToObject(o, "absent_rejected", s->absent_rejected);
    add_num(o, "mean_ms", s->mean_ms);
    return o;
}

static cJSON *query_json(const sp_eval_query *q)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "query", q->text);
    cJSON_AddBoolToObject(o, "present", q->present);
    cJSON_AddNumberToObject(o, "objects", q->n_objects);
    for (int m = 0; m < SP_EVAL_METHODS; m++) {
        cJSON *r = cJSON_AddObjectToObject(o, method_key[m]);
        cJSON_AddBoolToObject(r, "found", q->found[m]);
        cJSON_AddNumberToObject(r, "confidence", q->confidence[m]);
        cJSON_AddItemToObject(r, "position", vec3_or_null(q->position[m]));
        add_num(r, "query_error_m", q->query_error_m[m]);
        cJSON_AddBoolToObject(r, "correct", q->correct[m]);
        cJSON_AddNumberToObject(r, "matched", q->matched[m]);
        cJSON *inst = cJSON_AddArrayToObject(r, "instances");
        for (int j = 0; j < q->n_instances[m]; j++)
            cJSON_AddItemToArray(inst, vec3_or_null(q->instance_pos[m] + 3 * j));
        cJSON_AddNumberToObject(r, "ms", q->ms[m]);
    }
    cJSON_AddStringToObject(o, "heatmap", q->heatmap);
    return o;
}

static cJSON *object_json(const sp_eval_object *ob)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "name", ob->name);
    cJSON_AddStringToObject(o, "class", ob->cls);
    cJSON_AddItemToObject(o, "truth", vec3_or_null(ob->truth));
    cJSON_AddNumberToObject(o, "miss_penalty_m", ob->miss_penalty_m);
    for (int m = 0; m < SP_EVAL_METHODS; m++) {
        cJSON *r = cJSON_AddObjectToObject(o, method_key[m]);
        cJSON_AddBoolToObject(r, "matched", ob->instance[m] >= 0);
        cJSON_AddNumberToObject(r, "instance", ob->instance[m]);
        add_num(r, "error_m", ob->error_m[m]);
        cJSON_AddItemToObject(r, "estimate", vec3_or_null(ob->estimate[m]));
    }
    return o;
}

cJSON *sp_eval_report_json(const sp_eval_report *r)
{
    cJSON *o = cJSON_CreateObject();
    if (!o) return NULL;
    cJSON *src = cJSON_AddObjectToObject(o, "source");
    cJSON_AddStringToObject(src, "encoder", r->source.encoder);
    cJSON_AddStringToObject(src, "features", r->source.features);
    cJSON_AddBoolToObject(src, "ground_truth", r->source.ground_truth);
    cJSON_AddStringToObject(src, "note", sp_query_source_note(&r->source));
    cJSON *fr = cJSON_AddObjectToObject(o, "frame");
    cJSON_AddStringToObject(fr, "name", r->frame.name);
    cJSON_AddStringToObject(fr, "source", r->frame.source);
    cJSON_AddStringToObject(fr, "units", r->frame.units);
    cJSON_AddStringToObject(fr, "up", r->frame.up);
    cJSON *mt = cJSON_AddObjectToObject(o, "matching");
    cJSON_AddStringToObject(mt, "rule", "one-to-one (Hungarian): an instance inside the object's box grown by radius_m");
    cJSON_AddNumberToObject(mt, "radius_m", r->match_radius_m);
    cJSON *ms = cJSON_AddObjectToObject(o, "methods");
    for (int m = 0; m < SP_EVAL_METHODS; m++) cJSON_AddItemToObject(ms, method_key[m], summary_json(&r->summary[m]));
    cJSON *qa = cJSON_AddArrayToObject(o, "queries");
    for (size_t k = 0; k < r->n_queries; k++) cJSON_AddItemToArray(qa, query_json(&r->queries[k]));
    cJSON *oa = cJSON_AddArrayToObject(o, "objects");
    for (size_t i = 0; i < r->n_objects; i++) cJSON_AddItemToArray(oa, object_json(&r->objects[i]));
    return o;
}
