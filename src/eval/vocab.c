/* 5.2, open- versus closed-vocabulary: each query answered by the semantic splat, and by a
 * closed-vocabulary baseline that can only say one of COCO's 80 class names: the query replaced by
 * the COCO class WordNet matches best, that class looked up in the same map. Found = the answer
 * lies on an object the query means (grown by the match radius). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "eval/eval_internal.h"

/* Objects of the world that answer q: its target classes, within near_m of a `near` class. */
static int is_target(const sp_ground_truth *gt, const sp_eval_query_spec *q, size_t i)
{
    const sp_gt_object *o = &gt->objects[i];
    int cls = 0;
    for (int t = 0; t < q->n_targets && !cls; t++) cls = !strcasecmp(o->cls, q->targets[t]);
    if (!cls || !q->n_near) return cls;
    for (size_t j = 0; j < gt->n; j++) {
        const sp_gt_object *a = &gt->objects[j];
        int near_cls = 0;
        for (int t = 0; t < q->n_near && !near_cls; t++) near_cls = !strcasecmp(a->cls, q->near[t]);
        if (!near_cls) continue;
        double gap2 = 0;
        for (int k = 0; k < 3; k++) {
            double g = fmax(0, fmax(a->aabb_min[k] - o->aabb_max[k], o->aabb_min[k] - a->aabb_max[k]));
            gap2 += g * g;
        }
        if (sqrt(gap2) <= q->near_m) return 1;
    }
    return 0;
}

/* Whether p answers q (on a target, or inside the box spanning them for a region), and the
 * distance from p to the nearest target's centre. */
static int on_target(const sp_ground_truth *gt, const sp_eval_query_spec *q, const float p[3],
                     float radius, float *err_m)
{
    *err_m = NAN;
    if (!isfinite(p[0])) return 0;
    sp_gt_object span = {.aabb_min = {INFINITY, INFINITY, INFINITY}, .aabb_max = {-INFINITY, -INFINITY, -INFINITY}};
    int hit = 0, n = 0;
    for (size_t i = 0; i < gt->n; i++) {
        if (!is_target(gt, q, i)) continue;
        const sp_gt_object *o = &gt->objects[i];
        n++;
        float d = 0;
        for (int k = 0; k < 3; k++) {
            d += (p[k] - o->center[k]) * (p[k] - o->center[k]);
            span.aabb_min[k] = fminf(span.aabb_min[k], o->aabb_min[k]);
            span.aabb_max[k] = fmaxf(span.aabb_max[k], o->aabb_max[k]);
        }
        d = sqrtf(d);
        if (!(d >= *err_m)) *err_m = d;
        hit |= sp_eval_admissible(o, p, radius);
    }
    if (q->region && n) hit = sp_eval_admissible(&span, p, radius);
    return hit;
}

/* The semantic splat's answer to text: lexically grounded on a label scene, else the engine's. */
static int answer(const ev_vocab_ctx *c, const char *text, float pos[3], float *conf, char *matched,
                  size_t cap, sp_error *err)
{
    pos[0] = pos[1] = pos[2] = NAN;
    *conf = 0;
    if (matched) matched[0] = 0;
    sp_query_result *res;
    sp_lex_answer *a = NULL;
    sp_query_result plain;
    int rc;
    if (c->scene) {
        a = calloc(1, sizeof *a);
        if (!a) return sp_error_set(err, SP_E_NOMEM, "eval: out of memory");
        rc = sp_lex_query(c->engine, c->scene, text, a, err);
        res = &a->result;
        if (!rc && !a->lex.found) res->valid = 0;
        for (int k = 0; !rc && matched && k < a->lex.target.n_matches; k++) {
            const sp_lex_class_match *m = &a->lex.target.matches[k];
            if (m->score < SP_LEX_THRESHOLD) break;
            size_t at = strlen(matched);
            snprintf(matched + at, cap - at, "%s%s %.2f", at ? ", " : "",
                     sp_lex_vocab_class(c->scene, m->class_index), m->score);
        }
    } else {
        rc = sp_query_engine_query(c->engine, text, NULL, &plain, err);
        res = &plain;
    }
    if (!rc && sp_eval_merge_fragments(res, c->merge_gap_m, err) < 0) rc = err ? err->code : SP_E_NOMEM;
    if (!rc && res->valid) {
        memcpy(pos, res->position, sizeof(float) * 3);
        *conf = res->confidence;
    }
    if (a) {
        sp_lex_answer_free(a);
        free(a);
    } else if (!rc) sp_query_result_free(&plain);
    return rc ? sp_error_prefix(err, "query '%s': ", text) : 0;
}

int ev_vocab_row(const ev_vocab_ctx *c, const sp_ground_truth *gt, const sp_eval_query_spec *q,
                 sp_eval_vocab_row *row, sp_error *err)
{
    memset(row, 0, sizeof *row);
    row->spec = *q;
    row->open_error_m = row->closed_error_m = NAN;
    for (size_t i = 0; i < gt->n; i++) row->n_targets += is_target(gt, q, i);
    int rc = answer(c, q->text, row->open_position, &row->open_confidence, row->matched,
                    sizeof row->matched, err);
    if (rc) return rc;
    row->open_found = on_target(gt, q, row->open_position, c->radius, &row->open_error_m);
    /* the closed baseline: the COCO class WordNet finds for the text, if any */
    sp_lex_result *m = calloc(1, sizeof *m);
    if (!m) return sp_error_set(err, SP_E_NOMEM, "eval: out of memory");
    rc = sp_lex_match(c->coco, q->text, m, err);
    if (!rc && m->found && m->target.n_matches > 0) {
        const sp_lex_class_match *b = &m->target.matches[0];
        snprintf(row->coco_class, sizeof row->coco_class, "%s", sp_lex_vocab_class(c->coco, b->class_index));
        row->coco_score = b->score;
    }
    row->in_coco = q->coco >= 0 ? q->coco
                                : row->coco_class[0] && (m->target.matches[0].kind == SP_LEX_EXACT ||
                                                         m->target.matches[0].kind == SP_LEX_SYNONYM);
    free(m);
    if (rc) return rc;
    if (row->coco_class[0]) {
        float pos[3], conf;
        rc = answer(c, row->coco_class, pos, &conf, NULL, 0, err);
        if (!rc) row->closed_found = on_target(gt, q, pos, c->radius, &row->closed_error_m);
    }
    return rc;
}
