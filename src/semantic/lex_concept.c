/* Concepts for the lexical text encoder: a noun sense with its hypernym closure (distances and
 * depths for Wu-Palmer), the taxonomic comparison of two senses, and bags of definition words. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lexical.h"

#define PHYSICAL_ENTITY 1930u /* physical_entity.n.01 */
#define PERSON 7846u /* person.n.01 */
#define ARTIFACT 21939u /* artifact.n.01 */
#define PROCESS 29677u /* process.n.06, physical process: radiation, waves, flows */
#define ACT_N02 30358u /* act.n.02: something that people do */
#define LIVING_THING 4258u /* living_thing.n.01: organisms, plants, animals */
#define ANIMAL 15388u      /* animal.n.01 */
#define FOOD_N01 21265u    /* food.n.01, nutrient: dishes, drinks, nutriment */
#define FOOD_N02 7555863u  /* food.n.02, solid food: produce, edible fruit, bread */
#define ROOM_N01 4105893u /* room.n.01: an area within a building enclosed by walls and floor and ceiling */
#define MAX_HYPER 8

static void name_of(const wn_synset *s, char *out, size_t cap)
{
    snprintf(out, cap, "%s", s->n_words ? s->words[0] : "?");
    for (char *p = out; *p; p++)
        if (*p == '_') *p = ' ';
}

/* Depth of closure entry i: 1 + the shallowest of its hypernyms (1 for 'entity'). */
static int depth_of(lex_sense *s, int i, const short hyp[][MAX_HYPER], const int *n_hyp)
{
    if (s->anc[i].depth > 0) return s->anc[i].depth;
    int best = 0;
    for (int k = 0; k < n_hyp[i]; k++) {
        if (hyp[i][k] < 0) continue;
        int d = depth_of(s, hyp[i][k], hyp, n_hyp);
        if (!best || d < best) best = d;
    }
    s->anc[i].depth = (short)(best + 1);
    return best + 1;
}

int lex_anc_find(const lex_sense *s, uint32_t off)
{
    for (int i = 0; i < s->n_anc; i++)
        if (s->anc[i].off == off) return i;
    return -1;
}

int lex_sense_load(const lex_db *lx, uint32_t off, int rank, lex_sense *s, sp_error *err)
{
    memset(s, 0, sizeof *s);
    s->off = off;
    s->rank = rank;
    short (*h)[MAX_HYPER] = calloc(LEX_MAX_ANC, sizeof *h);
    int *nh = calloc(LEX_MAX_ANC, sizeof *nh);
    if (!h || !nh) {
        free(h), free(nh);
        return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    }
    s->anc[0].off = off;
    s->anc[0].parent = -1;
    s->n_anc = 1;
    int rc = 0;
    /* Breadth first over hypernyms and instance hypernyms: the first visit is the shortest. */
    for (int i = 0; i < s->n_anc && !rc; i++) {
        wn_synset syn;
        wn_id id = {s->anc[i].off, WN_NOUN};
        if ((rc = wn_read(lx->db, id, &syn, err))) break;
        name_of(&syn, s->anc[i].name, sizeof s->anc[i].name);
        if (i == 0) {
            wn_definition(syn.gloss, s->definition, sizeof s->definition);
            for (int p = 0; p < syn.n_pointers && s->n_holo < 16; p++)
                if (!strcmp(syn.pointers[p].symbol, "#p") && syn.pointers[p].target.pos == WN_NOUN)
                    s->holo[s->n_holo++] = syn.pointers[p].target.offset;
            for (int p = 0; p < syn.n_pointers; p++) s->instance |= !strcmp(syn.pointers[p].symbol, "@i");
        }
        for (int p = 0; p < syn.n_pointers; p++) {
            const wn_pointer *ptr = &syn.pointers[p];
            if ((strcmp(ptr->symbol, "@") && strcmp(ptr->symbol, "@i")) || ptr->target.pos != WN_NOUN)
                continue;
            int j = lex_anc_find(s, ptr->target.offset);
            if (j < 0 && s->n_anc < LEX_MAX_ANC) {
                j = s->n_anc++;
                s->anc[j].off = ptr->target.offset;
                s->anc[j].dist = (short)(s->anc[i].dist + 1);
                s->anc[j].parent = (short)i;
            }
            if (j >= 0 && nh[i] < MAX_HYPER) h[i][nh[i]++] = (short)j;
        }
        wn_synset_free(&syn);
    }
    if (!rc)
        for (int i = 0; i < s->n_anc; i++) depth_of(s, i, (const short (*)[MAX_HYPER])h, nh);
    free(h);
    free(nh);
    return rc;
}

int lex_sense_physical(const lex_sense *s) { return lex_anc_find(s, PHYSICAL_ENTITY) >= 0; }
int lex_sense_person(const lex_sense *s) { return lex_anc_find(s, PERSON) >= 0; }
int lex_sense_artifact(const lex_sense *s) { return lex_anc_find(s, ARTIFACT) >= 0; }
int lex_sense_process(const lex_sense *s) { return lex_anc_find(s, PROCESS) >= 0; }
int lex_sense_room(const lex_sense *s) { return lex_anc_find(s, ROOM_N01) >= 0; }
int lex_sense_living(const lex_sense *s) { return lex_anc_find(s, LIVING_THING) >= 0; }
int lex_sense_animal(const lex_sense *s) { return lex_anc_find(s, ANIMAL) >= 0; }
int lex_sense_act(const lex_sense *s) { return lex_anc_find(s, ACT_N02) >= 0; }
int lex_sense_food(const lex_sense *s) { return lex_anc_find(s, FOOD_N01) >= 0 || lex_anc_find(s, FOOD_N02) >= 0; }

void lex_path(const lex_sense *s, int a, char *out, size_t cap)
{
    /* Walk from a down to the sense through parent links, then print in reverse. */
    int chain[LEX_MAX_ANC], n = 0;
    for (int i = a; i >= 0 && n < LEX_MAX_ANC; i = s->anc[i].parent) chain[n++] = i;
    size_t o = 0;
    out[0] = 0;
    for (int k = 0; k < n && o + 1 < cap; k++) {
        int w = snprintf(out + o, cap - o, "%s%s", k ? " > " : "", s->anc[chain[k]].name);
        if (w < 0) break;
        o += (size_t)w;
    }
}

static float wup(int depth_lcs, int dq, int dc)
{
    return 2.0f * (float)depth_lcs / (float)(dq + dc + 2 * depth_lcs);
}

lex_tax lex_compare(const lex_sense *q, const lex_sense *c)
{
    lex_tax t = {0, SP_LEX_NONE, -1, -1};
    int j = lex_anc_find(q, c->off);
    if (j == 0) return (lex_tax){1.0f, SP_LEX_SYNONYM, 0, 0};
    if (j > 0) { /* the class is a hypernym of the query: a laptop IS a computer, at any depth */
        int d = q->anc[j].dist, dep = c->anc[0].depth;
        t = (lex_tax){wup(dep, d, 0), SP_LEX_HYPONYM, j, 0};
    }
    int i = lex_anc_find(c, q->off);
    if (i > 0) { /* the query is a hypernym of the class */
        int d = c->anc[i].dist, dep = q->anc[0].depth;
        float s = wup(dep, 0, d);
        if (s > t.score) t = (lex_tax){s, SP_LEX_HYPERNYM, 0, i};
    }
    /* A part of the class names where it is, through one weak step: only for a sense of the
     * query people use (magazine the periodical, not a camera's film chamber). */
    for (int k = 0; k < q->n_holo && q->attested; k++)
        if (q->holo[k] == c->off && LEX_PART > t.score) t = (lex_tax){LEX_PART, SP_LEX_PART, -1, -1};
    if (t.kind != SP_LEX_NONE) return t;
    /* Neither subsumes the other: Wu-Palmer through the deepest common ancestor, scaled by MU. */
    int best_q = -1, best_c = -1;
    float best = 0;
    for (int a = 1; a < c->n_anc; a++) {
        int b = lex_anc_find(q, c->anc[a].off);
        if (b < 0) continue;
        float s = wup(c->anc[a].depth, q->anc[b].dist, c->anc[a].dist);
        if (s > best) best = s, best_q = b, best_c = a;
    }
    if (best_c >= 0) t = (lex_tax){LEX_MU * best, SP_LEX_RELATED, best_q, best_c};
    return t;
}

/* ---- bags of definition words ------------------------------------------------------------------ */

void lex_bag_free(lex_bag *b)
{
    free(b->words);
    free(b->src);
    memset(b, 0, sizeof *b);
}

static int bag_source(lex_bag *b, const char *source, sp_error *err)
{
    for (int i = 0; i < b->n_src; i++)
        if (!strcmp(b->src[i], source)) return i;
    char (*ns)[192] = realloc(b->src, sizeof *ns * (size_t)(b->n_src + 1));
    if (!ns) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    b->src = ns;
    snprintf(b->src[b->n_src], sizeof b->src[0], "%s", source);
    return b->n_src++;
}

static int bag_put(lex_bag *b, const char *w, float weight, int src, int patient, int kind, sp_error *err)
{
    for (int i = 0; i < b->n; i++)
        if (b->words[i].patient == patient && !strcmp(b->words[i].w, w)) {
            lex_bag_word *e = &b->words[i];
            if (weight > e->weight || (weight == e->weight && e->kind && !kind))
                e->weight = weight, e->src = (short)src, e->kind = (short)kind;
            return 0;
        }
    if (b->n == b->cap) {
        int nc = b->cap ? 2 * b->cap : 64;
        lex_bag_word *nw = realloc(b->words, sizeof *nw * (size_t)nc);
        if (!nw) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
        b->words = nw;
        b->cap = nc;
    }
    lex_bag_word *e = &b->words[b->n++];
    snprintf(e->w, sizeof e->w, "%s", w);
    e->weight = weight;
    e->src = (short)src;
    e->patient = (short)patient;
    e->kind = (short)kind;
    return 0;
}

/* 1 when w is a past form of the verb whose base is base ("written", "placed"): not the base
 * itself, not "-ing" (the activity: "writing surface"), not "-s". In a definition, a noun phrase,
 * such a form is a participle: the thing defined is what the verb acts on ("a written work"). */
static int past_form(const char *w, const char *base)
{
    size_t n = strlen(w);
    if (!strcmp(w, base)) return 0;
    if (n > 3 && !strcmp(w + n - 3, "ing")) return 0;
    return !(n > 1 && w[n - 1] == 's');
}

int lex_bag_add_lemmas(lex_bag *b, const char *lemmas, float weight, const char *source, sp_error *err)
{
    lex_tokens t;
    lex_tokenize(lemmas, &t);
    int src = bag_source(b, source, err);
    if (src < 0) return src;
    for (int i = 0; i < t.n; i++) {
        if (strlen(t.w[i]) < 2 || lex_word_class_of(t.w[i]) != LW_CONTENT) continue;
        int rc = bag_put(b, t.w[i], weight, src, 0, 0, err);
        if (rc) return rc;
    }
    return 0;
}

/* 1 when token i is the verb of a clause on persons: right after "who", or after "who" and an
 * auxiliary or "not" ("those who cannot walk", "someone who is ill"). */
static int persons_verb(const lex_tokens *t, int i)
{
    static const char *const aux[] = {"can", "cannot", "can't", "could", "do", "does", "did", "not", "will",
                                      "would", "may", "might", "must", "should", "is", "are", "was", "were", NULL};
    for (int j = i - 1; j >= 0 && j >= i - 3; j--) {
        if (!strcmp(t->w[j], "who") || !strcmp(t->w[j], "whom")) return 1;
        int is_aux = 0;
        for (int k = 0; aux[k] && !is_aux; k++) is_aux = !strcmp(t->w[j], aux[k]);
        if (!is_aux) return 0;
    }
    return 0;
}

int lex_bag_add_text(const lex_db *lx, lex_bag *b, const char *text, float weight, int kind,
                     const char *source, sp_error *err)
{
    lex_tokens t;
    lex_tokenize(text, &t);
    int src = bag_source(b, source, err);
    if (src < 0) return src;
    for (int i = 0; i < t.n; i++) {
        const char *w = t.w[i];
        if (strlen(w) < 2 || lex_word_class_of(w) != LW_CONTENT) continue;
        /* the verb of a relative clause on the thing defined ("a lamp THAT SITS on a table"):
         * what the thing does, every reading of the word (LEX_BAG_AGENT) */
        char vb[WN_MAX_BASES][WN_LEMMA_MAX];
        int agent = i > 0 && (!strcmp(t.w[i - 1], "that") || !strcmp(t.w[i - 1], "which"));
        /* and an -ing form right after a noun, a reduced relative clause ("a region LYING over
         * another", "a device CONSISTING of"); not after a preposition ("designed for sitting")
         * or before its noun ("a writing surface") */
        size_t wl = strlen(w);
        if (!agent && i > 0 && wl > 4 && !strcmp(w + wl - 3, "ing") && lex_word_class_of(t.w[i - 1]) == LW_CONTENT) {
            int pn = lex_is_pos(lx, WN_NOUN, t.w[i - 1], err);
            if (pn < 0) return pn;
            agent = pn > 0;
        }
        if (agent && (agent = lex_bases(lx, WN_VERB, w, vb, err)) < 0) return agent;
        agent = agent > 0 ? LEX_BAG_AGENT : 0;
        int person = !agent && persons_verb(&t, i);
        int rc = bag_put(b, w, weight, src, agent ? agent : person ? LEX_BAG_PERSON : 0, kind, err);
        for (int p = 0; p < 3 && !rc; p++) { /* nouns, verbs, adjectives */
            char bases[WN_MAX_BASES][WN_LEMMA_MAX];
            int nb = lex_bases(lx, (wn_pos)p, w, bases, err);
            if (nb < 0) return nb;
            for (int k = 0; k < nb && !rc; k++)
                rc = bag_put(b, bases[k], weight, src,
                             agent                                    ? agent
                             : person                                 ? LEX_BAG_PERSON
                             : p == WN_VERB && past_form(w, bases[k]) ? LEX_BAG_PATIENT
                                                                      : 0,
                             kind, err);
        }
        if (rc) return rc;
    }
    return 0;
}

float lex_bag_find(const lex_bag *b, char bases[][WN_LEMMA_MAX], int n, float min_weight,
                   float patient_factor, float agent_factor, int own, int *src)
{
    float best = 0;
    for (int i = 0; i < b->n; i++) {
        const lex_bag_word *e = &b->words[i];
        if (own && e->kind) continue;
        float f = e->patient == LEX_BAG_PATIENT ? patient_factor : e->patient == LEX_BAG_AGENT ? agent_factor : 1.0f;
        float w = e->weight * f;
        for (int k = 0; k < n; k++)
            if (e->weight >= min_weight && w > best && !strcmp(e->w, bases[k])) {
                best = w;
                if (src) *src = e->src;
            }
    }
    return best;
}

float lex_wup(const lex_sense *q, const lex_sense *c)
{
    float best = 0;
    for (int a = 0; a < c->n_anc; a++) {
        int b = lex_anc_find(q, c->anc[a].off);
        if (b < 0) continue;
        float s = wup(c->anc[a].depth, q->anc[b].dist, c->anc[a].dist);
        if (s > best) best = s;
    }
    return best;
}
