/* The lexical encoder inside the query engine: sp_lex_query's answer (with the call's options)
 * turned into a plain query result, so that every caller of sp_query_engine_query (the CLI,
 * Python, eval, the agent) gets the matched classes, regions and relations, and why, without
 * knowing about encoders. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lexical.h"
#include "sem_internal.h"

#define EXPLAIN_CAP 32768

void sem_lex_match_copy(sp_query_match *q, const sp_lex_class_match *m, const sp_lex_vocab *v, const char *role)
{
    memset(q, 0, sizeof *q);
    snprintf(q->label, sizeof q->label, "%s", sp_lex_vocab_class(v, m->class_index));
    snprintf(q->role, sizeof q->role, "%s", role);
    q->score = m->score;
    snprintf(q->kind, sizeof q->kind, "%s", sp_lex_kind_name(m->kind));
    snprintf(q->query_sense, sizeof q->query_sense, "%s", m->query_sense);
    snprintf(q->class_sense, sizeof q->class_sense, "%s", m->class_sense);
    snprintf(q->path, sizeof q->path, "%s", m->path);
    snprintf(q->gloss_words, sizeof q->gloss_words, "%s", m->gloss_words);
    snprintf(q->definition, sizeof q->definition, "%s", m->definition);
}

/* How many of a phrase's matches the result lists: those at or above the threshold, else the
 * nearest one below it (so that a miss can be explained). */
static int listed(const sp_lex_phrase *ph)
{
    int n = 0;
    while (n < ph->n_matches && ph->matches[n].score >= SP_LEX_THRESHOLD) n++;
    return n ? n : (ph->n_matches && ph->matches[0].score > 0);
}

static int add_matches(sp_query_result *res, const sp_lex_result *lex, const sp_lex_vocab *v, sp_error *err)
{
    int nt = listed(&lex->target), na = lex->relation[0] ? listed(&lex->anchor) : 0;
    if (nt + na == 0) return 0;
    res->matches = calloc((size_t)(nt + na), sizeof *res->matches);
    if (!res->matches) return sp_error_set(err, SP_E_NOMEM, "lexical query: out of memory");
    for (int i = 0; i < nt; i++) sem_lex_match_copy(&res->matches[res->n_matches++], &lex->target.matches[i], v, "target");
    for (int i = 0; i < na; i++) sem_lex_match_copy(&res->matches[res->n_matches++], &lex->anchor.matches[i], v, "anchor");
    return 0;
}

static void region_of(sp_query_region *r, const sp_lex_extent *x, const char *name)
{
    memset(r, 0, sizeof *r);
    r->valid = 1;
    snprintf(r->name, sizeof r->name, "%s", name);
    memcpy(r->extent_min, x->extent_min, sizeof r->extent_min);
    memcpy(r->extent_max, x->extent_max, sizeof r->extent_max);
    memcpy(r->centre, x->centre, sizeof r->centre);
    r->n_instances = x->n_instances;
}

/* What the scene made of the match, after WordNet's part. */
static void explain_grounding(const sp_lex_answer *a, const sp_query_result *res, char *out, size_t cap)
{
    size_t o = strlen(out);
    if (o + 1 >= cap) return;
    if (res->valid)
        snprintf(out + o, cap - o, "in the scene: %d instance%s%s%s, the best at (%.2f, %.2f, %.2f) in the %s frame\n",
                 res->n_instances, res->n_instances == 1 ? "" : "s", a->is_region ? " of the region " : "",
                 a->is_region ? a->lex.target.region : "", (double)res->position[0], (double)res->position[1],
                 (double)res->position[2], res->frame.name);
    else if (a->lex.found && a->lex.relation[0])
        snprintf(out + o, cap - o, "in the scene: the target or the anchor of the relation is not seen\n");
    else if (a->lex.found)
        snprintf(out + o, cap - o, "in the scene: the matched classes are named but not seen enough to localize\n");
}

/* The heatmap of an answer that has none (a region, or nothing found): the lexical embedding of
 * the text (its classes' label embeddings weighted by score; its own hash when none matches, so
 * absent things get the faded heatmap of the other encoders). */
static int text_heatmap(sp_query_engine *e, const sp_query_opts *o, sp_query_result *res, sp_error *err)
{
    float *q = malloc(sizeof(float) * (size_t)e->pca.full_dim);
    int rc = q ? e->enc->embed(e, res->text, q, err) : sp_error_set(err, SP_E_NOMEM, "lexical query: out of memory");
    sp_query_result h;
    if (!rc && !(rc = sem_query_embedding(e, q, res->text, o, &h, err))) {
        res->relevancy_image = h.relevancy_image, res->relevancy = h.relevancy;
        h.relevancy_image = NULL, h.relevancy = NULL;
        res->width = h.width, res->height = h.height;
        if (res->view_index < 0) {
            res->view_index = h.view_index;
            snprintf(res->view_name, sizeof res->view_name, "%s", h.view_name);
        }
        res->ms_heatmap = h.ms_total;
        res->ms_total += h.ms_total;
        sp_query_result_free(&h);
    }
    free(q);
    return rc;
}

/* Moves the answer's result into res and adds what the encoder understood. */
static int to_result(sp_query_engine *e, sp_lex_answer *a, const sp_query_opts *o, sp_query_result *res,
                     sp_error *err)
{
    *res = a->result;
    memset(&a->result, 0, sizeof a->result);
    res->source = e->source;
    if (!res->valid && !(res->confidence > 0)) res->confidence = a->lex.confidence; /* how near it came */
    for (int k = 0; k < res->n_instances; k++) {
        sp_query_instance *I = &res->instances[k];
        if (a->instance_class) snprintf(I->label, sizeof I->label, "%s", sp_lex_vocab_class(e->vocab, a->instance_class[k]));
        I->relation_m = a->relation_m ? a->relation_m[k] : NAN;
    }
    snprintf(res->relation, sizeof res->relation, "%s", a->lex.relation);
    if (a->is_region && res->n_instances) region_of(&res->region, &a->region, a->lex.target.region);
    if (a->has_anchor && a->relation_m)
        region_of(&res->anchor, &a->anchor, a->lex.anchor.is_region ? a->lex.anchor.region : a->lex.anchor.text);
    res->n_ignored = a->lex.n_ignored < SP_QUERY_MAX_IGNORED ? a->lex.n_ignored : SP_QUERY_MAX_IGNORED;
    for (int i = 0; i < res->n_ignored; i++) snprintf(res->ignored[i], sizeof res->ignored[i], "%s", a->lex.ignored[i]);
    int rc = add_matches(res, &a->lex, e->vocab, err);
    if (!rc && !(res->explanation = malloc(EXPLAIN_CAP))) rc = sp_error_set(err, SP_E_NOMEM, "lexical query: out of memory");
    if (!rc) {
        sp_lex_explain(&a->lex, e->vocab, res->explanation, EXPLAIN_CAP);
        explain_grounding(a, res, res->explanation, EXPLAIN_CAP);
    }
    res->method = o->method == SP_QUERY_MULTIVIEW && e->n_cams > 0 ? SP_QUERY_MULTIVIEW : SP_QUERY_3D;
    if (!rc && o->heatmap && e->n_cams > 0 && !res->relevancy_image) rc = text_heatmap(e, o, res, err);
    return rc;
}

int sem_lex_engine_query(sp_query_engine *e, const char *text, const sp_query_opts *o, sp_query_result *res,
                         sp_error *err)
{
    sp_lex_answer *a = malloc(sizeof *a);
    if (!a) return sp_error_set(err, SP_E_NOMEM, "lexical query: out of memory");
    int rc = sem_lex_answer(e, e->vocab, text, o, a, err);
    if (!rc) rc = to_result(e, a, o, res, err);
    sp_lex_answer_free(a);
    free(a);
    return rc;
}
