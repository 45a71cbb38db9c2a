/* Lexical queries grounded in a label-feature scene through the query engine: each matched
 * class is localized by its label embedding (sem_query_embedding, with the engine's lock held and
 * the call's options); regions are the extent of the instances of the classes that define them,
 * clustered in space; relations rank the target's instances by their distance to the anchor. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lexical.h"
#include "sem_internal.h"
#include "semsplat/clip.h"
#include "semsplat/io.h"

#define REGION_GAP_M 2.0f /* the objects of one room stand within 2 m of each other */
#define ON_TOLERANCE_M 0.3f

void sp_lex_answer_free(sp_lex_answer *a)
{
    if (!a) return;
    sp_query_result_free(&a->result);
    free(a->relation_m);
    free(a->instance_class);
    a->relation_m = NULL;
    a->instance_class = NULL;
}

/* Box-to-box distance (0 when they touch or overlap). */
static float box_gap(const float *alo, const float *ahi, const float *blo, const float *bhi)
{
    double d2 = 0;
    for (int k = 0; k < 3; k++) {
        double g = fmax(0.0, fmax((double)blo[k] - ahi[k], (double)alo[k] - bhi[k]));
        d2 += g * g;
    }
    return (float)sqrt(d2);
}

static void extent_of(const sp_query_instance *in, int n, sp_lex_extent *x)
{
    memset(x, 0, sizeof *x);
    for (int k = 0; k < 3; k++) x->extent_min[k] = INFINITY, x->extent_max[k] = -INFINITY;
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) {
            x->extent_min[k] = fminf(x->extent_min[k], in[i].extent_min[k]);
            x->extent_max[k] = fmaxf(x->extent_max[k], in[i].extent_max[k]);
        }
    for (int k = 0; k < 3; k++) x->centre[k] = 0.5f * (x->extent_min[k] + x->extent_max[k]);
    x->n_instances = n;
}

/* An empty answer of the lexical encoder, in the engine's frame. */
static void not_found(const sp_query_engine *e, sp_query_result *res, const char *text)
{
    sp_query_engine_result_init(e, text, res);
    snprintf(res->source.encoder, sizeof res->source.encoder, "lexical");
}

/* Localizes one class (its label embedding) with lexical score `score` as the confidence. A
 * Gaussian of the class has cosine 1 with it; the scene must show at least 0.5, or the class is
 * named but not seen there. Instances are filtered per class (a small dining chair is not
 * dropped because an armchair is big). */
static int localize_class(sp_query_engine *e, const sp_lex_vocab *v, int cls, float score,
                          const char *text, int heatmap, const sp_query_opts *opts,
                          sp_query_result *res, sp_error *err)
{
    int F = sp_query_engine_full_dim(e);
    float *q = malloc(sizeof(float) * (size_t)F);
    if (!q) return sp_error_set(err, SP_E_NOMEM, "lexical query: out of memory");
    sp_label_embedding(sp_lex_vocab_class(v, cls), F, q);
    sp_query_opts o = *opts;
    o.min_confidence = 0.5f;
    o.heatmap = heatmap && o.heatmap;
    int rc = sem_query_embedding(e, q, text, &o, res, err);
    free(q);
    if (!rc) {
        snprintf(res->source.encoder, sizeof res->source.encoder, "lexical");
        res->confidence = score;
        res->threshold = SP_LEX_THRESHOLD;
        if (!res->valid) res->position[0] = res->position[1] = res->position[2] = NAN;
        for (int k = 0; k < res->n_instances; k++)
            snprintf(res->instances[k].label, sizeof res->instances[k].label, "%s", sp_lex_vocab_class(v, cls));
    }
    return rc;
}

/* The target: each class matched at or above the threshold localized alone, their instances
 * together, the best-scoring class's first, heavier first within a class. A text that is a
 * class's own name (kind exact) means that class alone: "couch" is the couch, not also the bed
 * WordNet calls a couch, "dining chair" not the armchair; a general word or a description
 * ("chair", "something to sit on") covers every class it fits. The best class's heatmap. */
static int localize_target(sp_query_engine *e, const sp_lex_vocab *v, const sp_lex_phrase *ph,
                           const sp_query_opts *o, sp_query_result *res, int **classes, sp_error *err)
{
    not_found(e, res, ph->text);
    int rc = 0, have = 0;
    float *cls_score = NULL;
    int *cls = NULL;
    /* ... but "the sofa and the armchair" (a "between" anchor) names two things */
    int named = ph->n_matches > 0 && ph->matches[0].kind == SP_LEX_EXACT && !strstr(ph->text, " and ");
    for (int i = 0; i < ph->n_matches && !rc; i++) {
        const sp_lex_class_match *m = &ph->matches[i];
        if (m->score < SP_LEX_THRESHOLD) break; /* matches are sorted */
        if (named && m->kind != SP_LEX_EXACT) continue;
        sp_query_result r;
        if ((rc = localize_class(e, v, m->class_index, m->score, ph->text, !have, o, &r, err))) break;
        if (!r.valid) {
            sp_query_result_free(&r);
            continue;
        }
        if (!have) {
            *res = r;
            have = 1;
            size_t nb = (size_t)(r.n_instances > 0 ? r.n_instances : 1);
            cls_score = malloc(sizeof(float) * nb);
            cls = malloc(sizeof(int) * nb);
            if (!cls_score || !cls) rc = sp_error_set(err, SP_E_NOMEM, "lexical query: out of memory");
            for (int k = 0; k < r.n_instances && !rc; k++) cls_score[k] = m->score, cls[k] = m->class_index;
            continue;
        }
        size_t n = (size_t)(res->n_instances + r.n_instances);
        sp_query_instance *ni = realloc(res->instances, sizeof *ni * n);
        if (ni) res->instances = ni;
        float *ns = realloc(cls_score, sizeof *ns * n);
        if (ns) cls_score = ns;
        int *nc = realloc(cls, sizeof *nc * n);
        if (nc) cls = nc;
        if (!ni || !ns || !nc) rc = sp_error_set(err, SP_E_NOMEM, "lexical query: out of memory");
        for (int k = 0; k < r.n_instances && !rc; k++) {
            res->instances[res->n_instances] = r.instances[k];
            cls[res->n_instances] = m->class_index;
            cls_score[res->n_instances++] = m->score;
        }
        sp_query_result_free(&r);
    }
    /* stable insertion sort: class score, then mass (each class's instances came sorted) */
    for (int i = 1; i < res->n_instances && !rc; i++)
        for (int j = i; j > 0 && (cls_score[j] > cls_score[j - 1] ||
                                  (cls_score[j] == cls_score[j - 1] && res->instances[j].score > res->instances[j - 1].score)); j--) {
            sp_query_instance t = res->instances[j];
            res->instances[j] = res->instances[j - 1], res->instances[j - 1] = t;
            float c = cls_score[j];
            cls_score[j] = cls_score[j - 1], cls_score[j - 1] = c;
            int q = cls[j];
            cls[j] = cls[j - 1], cls[j - 1] = q;
        }
    if (!rc && have && res->n_instances) memcpy(res->position, res->instances[0].position, sizeof res->position);
    free(cls_score);
    if (rc || !classes) free(cls);
    else *classes = cls;
    return rc;
}

typedef struct {
    sp_query_instance inst;
    int cls;
    float member; /* the class's membership score */
} member_inst;

static int find_root(int *p, int i)
{
    while (p[i] != i) i = p[i] = p[p[i]];
    return i;
}

/* A region: each member class localized alone, its instances clustered in space (boxes within
 * REGION_GAP_M), and the cluster holding the most of the region's kinds (by membership score)
 * taken. res gets that cluster's instances; x its extent. */
static int localize_region(sp_query_engine *e, const sp_lex_vocab *v, const sp_lex_phrase *ph,
                           const sp_query_opts *o, sp_query_result *res, sp_lex_extent *x, int **classes,
                           sp_error *err)
{
    *classes = NULL;
    member_inst *all = NULL;
    int n = 0, cap = 0, rc = 0;
    for (int i = 0; i < ph->n_matches && !rc; i++) {
        const sp_lex_class_match *m = &ph->matches[i];
        if (m->score < SP_LEX_THRESHOLD) continue;
        sp_query_result r;
        if ((rc = localize_class(e, v, m->class_index, m->score, ph->text, 0, o, &r, err))) break;
        for (int k = 0; k < r.n_instances && r.valid; k++) {
            if (n == cap) {
                cap = cap ? 2 * cap : 16;
                member_inst *na = realloc(all, sizeof *na * (size_t)cap);
                if (!na) {
                    rc = sp_error_set(err, SP_E_NOMEM, "lexical query: out of memory");
                    break;
                }
                all = na;
            }
            all[n++] = (member_inst){r.instances[k], m->class_index, m->score};
        }
        sp_query_result_free(&r);
    }
    not_found(e, res, ph->text);
    res->confidence = ph->n_matches ? ph->matches[0].score : 0;
    int *parent = rc || !n ? NULL : malloc(sizeof(int) * (size_t)n);
    if (!rc && n && !parent) rc = sp_error_set(err, SP_E_NOMEM, "lexical query: out of memory");
    if (!rc && n) {
        for (int i = 0; i < n; i++) parent[i] = i;
        for (int i = 0; i < n; i++)
            for (int j = i + 1; j < n; j++)
                if (box_gap(all[i].inst.extent_min, all[i].inst.extent_max, all[j].inst.extent_min,
                            all[j].inst.extent_max) <= REGION_GAP_M)
                    parent[find_root(parent, i)] = find_root(parent, j);
        /* Cluster value: the membership of each kind it holds, once per kind. */
        int best_root = -1;
        float best_value = -1;
        for (int r = 0; r < n; r++) {
            if (find_root(parent, r) != r) continue;
            float value = 0;
            for (int i = 0; i < n; i++) {
                if (find_root(parent, i) != r) continue;
                int first = 1;
                for (int j = 0; j < i; j++) first &= !(find_root(parent, j) == r && all[j].cls == all[i].cls);
                if (first) value += all[i].member;
            }
            if (value > best_value) best_value = value, best_root = r;
        }
        res->instances = malloc(sizeof *res->instances * (size_t)(n > 0 ? n : 1));
        if (!res->instances) rc = sp_error_set(err, SP_E_NOMEM, "lexical query: out of memory");
        *classes = malloc(sizeof(int) * (size_t)(n > 0 ? n : 1));
        if (!*classes) rc = sp_error_set(err, SP_E_NOMEM, "lexical query: out of memory");
        for (int i = 0; i < n && !rc; i++)
            if (find_root(parent, i) == best_root) {
                (*classes)[res->n_instances] = all[i].cls;
                res->instances[res->n_instances++] = all[i].inst;
            }
    }
    if (!rc && res->n_instances) {
        extent_of(res->instances, res->n_instances, x);
        memcpy(res->position, x->centre, sizeof x->centre);
        res->valid = res->confidence >= SP_LEX_THRESHOLD;
    }
    free(parent);
    free(all);
    return rc;
}

/* The relation's distance term of a target instance t to an anchor box. "on"/"above": t stands
 * over the box (horizontal gap, plus how far t's bottom is below the box's top); "under"/"below"
 * the reverse; every other relation: the gap between the boxes ("the doorway to the bedroom": a
 * door bordering the bedroom's extent). */
static float relation_cost(const char *rel, const sp_query_instance *t, const float *lo, const float *hi)
{
    float tlo[3], thi[3], alo[3], ahi[3];
    memcpy(tlo, t->extent_min, sizeof tlo), memcpy(thi, t->extent_max, sizeof thi);
    memcpy(alo, lo, sizeof alo), memcpy(ahi, hi, sizeof ahi);
    int up = !strcmp(rel, "on") || !strcmp(rel, "above");
    int down = !strcmp(rel, "under") || !strcmp(rel, "below");
    if (!up && !down) return box_gap(tlo, thi, alo, ahi);
    tlo[2] = thi[2] = alo[2] = ahi[2] = 0; /* horizontal gap */
    float g = box_gap(tlo, thi, alo, ahi);
    float v = up ? fmaxf(0.0f, hi[2] - ON_TOLERANCE_M - t->extent_min[2])
                 : fmaxf(0.0f, t->extent_max[2] - (lo[2] + ON_TOLERANCE_M));
    return g + v;
}

static float class_score(const sp_lex_phrase *ph, int cls)
{
    for (int i = 0; i < ph->n_matches; i++)
        if (ph->matches[i].class_index == cls) return ph->matches[i].score;
    return 0;
}

/* Orders the target's instances by their class's lexical score, then by their cost to the
 * nearest anchor box ("the doorway to the bedroom": doors before the walls a doorway is part of,
 * then the door nearest the bedroom). */
static int rank_by_relation(sp_lex_answer *a, const sp_query_instance *anchors, int n_anchors,
                            const sp_lex_extent *region, sp_error *err)
{
    sp_query_result *r = &a->result;
    int n = r->n_instances;
    if (n == 0) return 0;
    float *cost = malloc(sizeof(float) * (size_t)n), *score = malloc(sizeof(float) * (size_t)n);
    int *nearest = malloc(sizeof(int) * (size_t)n), *order = malloc(sizeof(int) * (size_t)n);
    int *cls = malloc(sizeof(int) * (size_t)n);
    sp_query_instance *inst = malloc(sizeof *inst * (size_t)n);
    int rc = 0;
    if (!cost || !score || !nearest || !order || !cls || !inst) {
        rc = sp_error_set(err, SP_E_NOMEM, "lexical query: out of memory");
        goto done;
    }
    for (int i = 0; i < n; i++) {
        order[i] = i, nearest[i] = -1;
        score[i] = class_score(&a->lex.target, a->instance_class[i]);
        if (region) {
            cost[i] = relation_cost(a->lex.relation, &r->instances[i], region->extent_min, region->extent_max);
            continue;
        }
        cost[i] = INFINITY;
        float second = INFINITY;
        for (int k = 0; k < n_anchors; k++) {
            float c = relation_cost(a->lex.relation, &r->instances[i], anchors[k].extent_min, anchors[k].extent_max);
            if (c < cost[i]) second = cost[i], cost[i] = c, nearest[i] = k;
            else if (c < second) second = c;
        }
        /* "between": the gaps to the two nearest anchors together (one anchor: its gap) */
        if (!strcmp(a->lex.relation, "between") && n_anchors > 1) cost[i] += second;
    }
    for (int i = 1; i < n; i++) /* insertion sort of the (few) instances, stable */
        for (int j = i; j > 0; j--) {
            int x = order[j], y = order[j - 1];
            if (!(score[x] > score[y] || (score[x] == score[y] && cost[x] < cost[y]))) break;
            order[j] = y, order[j - 1] = x;
        }
    a->relation_m = malloc(sizeof(float) * (size_t)n);
    if (!a->relation_m) {
        rc = sp_error_set(err, SP_E_NOMEM, "lexical query: out of memory");
        goto done;
    }
    for (int i = 0; i < n; i++) {
        inst[i] = r->instances[order[i]];
        cls[i] = a->instance_class[order[i]];
        a->relation_m[i] = cost[order[i]];
    }
    memcpy(r->instances, inst, sizeof *inst * (size_t)n);
    memcpy(a->instance_class, cls, sizeof *cls * (size_t)n);
    memcpy(r->position, r->instances[0].position, sizeof r->position);
    if (region) a->anchor = *region;
    else if (nearest[order[0]] >= 0) extent_of(&anchors[nearest[order[0]]], 1, &a->anchor);
done:
    free(cost), free(score), free(nearest), free(order), free(cls), free(inst);
    return rc;
}

int sem_lex_answer(sp_query_engine *e, const sp_lex_vocab *v, const char *text, const sp_query_opts *o,
                   sp_lex_answer *a, sp_error *err)
{
    memset(a, 0, sizeof *a);
    double t0 = sp_time_now();
    int rc = sp_lex_match(v, text, &a->lex, err);
    if (rc) return rc;
    double t1 = sp_time_now();
    if (a->lex.target.is_region) {
        a->is_region = 1;
        rc = localize_region(e, v, &a->lex.target, o, &a->result, &a->region, &a->instance_class, err);
    } else {
        rc = localize_target(e, v, &a->lex.target, o, &a->result, &a->instance_class, err);
    }
    if (!rc && a->lex.relation[0] && a->result.valid) {
        sp_query_result anchor;
        sp_lex_extent region;
        int *anchor_class = NULL;
        a->has_anchor = 1;
        if (a->lex.anchor.is_region) {
            rc = localize_region(e, v, &a->lex.anchor, o, &anchor, &region, &anchor_class, err);
            if (!rc && anchor.valid) rc = rank_by_relation(a, NULL, 0, &region, err);
        } else {
            rc = localize_target(e, v, &a->lex.anchor, o, &anchor, &anchor_class, err);
            if (!rc && anchor.valid) rc = rank_by_relation(a, anchor.instances, anchor.n_instances, NULL, err);
        }
        if (!rc && !anchor.valid) { /* the anchor is not there: neither is "X near it" */
            a->result.valid = 0;
            a->result.position[0] = a->result.position[1] = a->result.position[2] = NAN;
        }
        free(anchor_class);
        sp_query_result_free(&anchor);
    }
    if (rc) {
        sp_lex_answer_free(a);
        return rc;
    }
    snprintf(a->result.text, sizeof a->result.text, "%s", text);
    a->result.threshold = SP_LEX_THRESHOLD;
    a->result.ms_embed = (t1 - t0) * 1e3;
    a->result.ms_total = (sp_time_now() - t0) * 1e3;
    return 0;
}

int sp_lex_query(sp_query_engine *e, const sp_lex_vocab *v, const char *text, sp_lex_answer *a,
                 sp_error *err)
{
    if (!e || !v || !text || !a) return sp_error_set(err, SP_E_ARG, "lexical query: missing argument");
    pthread_mutex_lock(&e->mu);
    int rc = sem_lex_answer(e, v, text, &e->defaults, a, err);
    pthread_mutex_unlock(&e->mu);
    return rc;
}

static cJSON *extent_json(const sp_lex_extent *x)
{
    cJSON *o = cJSON_CreateObject();
    cJSON *lo = cJSON_AddArrayToObject(o, "extent_min"), *hi = cJSON_AddArrayToObject(o, "extent_max"),
          *c = cJSON_AddArrayToObject(o, "centre");
    for (int k = 0; k < 3; k++) {
        cJSON_AddItemToArray(lo, cJSON_CreateNumber(x->extent_min[k]));
        cJSON_AddItemToArray(hi, cJSON_CreateNumber(x->extent_max[k]));
        cJSON_AddItemToArray(c, cJSON_CreateNumber(x->centre[k]));
    }
    cJSON_AddNumberToObject(o, "instances", x->n_instances);
    return o;
}

char *sp_lex_answer_json(const sp_lex_answer *a, const sp_lex_vocab *v, const char *heatmap_path)
{
    char *rs = sp_query_result_json(&a->result, heatmap_path), *ls = sp_lex_result_json(&a->lex, v, SP_LEX_THRESHOLD);
    cJSON *o = rs ? cJSON_Parse(rs) : NULL, *lex = ls ? cJSON_Parse(ls) : NULL;
    free(rs);
    free(ls);
    if (!o || !lex) {
        cJSON_Delete(o);
        cJSON_Delete(lex);
        return NULL;
    }
    const char *const replaced[] = {"encoder", "region", "anchor"};
    for (size_t k = 0; k < sizeof replaced / sizeof replaced[0]; k++) cJSON_DeleteItemFromObject(o, replaced[k]);
    cJSON_AddStringToObject(o, "encoder", "lexical");
    cJSON_AddStringToObject(o, "note", "lexical: matching against the scene's known class names, not recognition");
    cJSON_AddItemToObject(o, "lexical", lex);
    if (a->is_region) cJSON_AddItemToObject(o, "region", extent_json(&a->region));
    else cJSON_AddNullToObject(o, "region");
    if (a->has_anchor && a->relation_m) {
        cJSON *an = extent_json(&a->anchor);
        cJSON_AddStringToObject(an, "relation", a->lex.relation);
        cJSON *d = cJSON_AddArrayToObject(an, "instance_cost_m");
        for (int i = 0; i < a->result.n_instances; i++) cJSON_AddItemToArray(d, cJSON_CreateNumber(a->relation_m[i]));
        cJSON_AddItemToObject(o, "anchor", an);
    } else {
        cJSON_AddNullToObject(o, "anchor");
    }
    /* the class of each instance, in the order of "instances" */
    const cJSON *insts = cJSON_GetObjectItem(o, "instances"), *it;
    int k = 0;
    cJSON_ArrayForEach(it, insts) {
        if (a->instance_class && k < a->result.n_instances) {
            cJSON_DeleteItemFromObject((cJSON *)it, "class");
            cJSON_AddStringToObject((cJSON *)it, "class", sp_lex_vocab_class(v, a->instance_class[k]));
        }
        k++;
    }
    char *s = cJSON_Print(o);
    cJSON_Delete(o);
    return s;
}
