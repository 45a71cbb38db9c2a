/* What affords what: "where can I wash my hands", "something to charge my phone", "I need to
 * print this" ask for a thing by what one does with it, and a building's things are named, not
 * defined: WordNet's definitions rarely say that a washbasin is where hands are washed or a
 * charging point where a phone is charged. A curated table (data/semantic/uses.json, written from
 * general knowledge of activities in buildings, as ConceptNet's UsedFor / AtLocation relations
 * are) maps an activity, a verb and the nouns of its object, to the names of the things that
 * afford it; a query that asks to do it is also read as each of those names (lex_alias.c folds the
 * readings), and a class counts when it is that thing or a kind of it. */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lexical.h"
#include "semsplat/io.h"

static int add_use(sp_lex_vocab *v, const char *path, const cJSON *it, sp_error *err)
{
    lex_tokens t;
    lex_tokenize(it->string, &t);
    if (t.n < 1 || t.n > 4 || !cJSON_IsArray(it) || cJSON_GetArraySize(it) < 1)
        return sp_error_set(err, SP_E_FORMAT, "%s: use '%s': an activity of 1 to 4 words with a list of names",
                            path, it->string);
    lex_use *nu = realloc(v->uses, sizeof *nu * (size_t)(v->n_uses + 1));
    if (!nu) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    v->uses = nu;
    lex_use *u = memset(&nu[v->n_uses], 0, sizeof *nu);
    u->n_words = t.n;
    for (int i = 0; i < t.n; i++) snprintf(u->words[i], LEX_WORD, "%s", t.w[i]);
    const cJSON *m;
    cJSON_ArrayForEach(m, it) {
        if (!cJSON_IsString(m) || !m->valuestring[0] || strlen(m->valuestring) >= sizeof u->targets[0])
            return sp_error_set(err, SP_E_FORMAT, "%s: use '%s': names must be strings under %zu bytes", path,
                                it->string, sizeof u->targets[0]);
        if (u->n_targets < 4) snprintf(u->targets[u->n_targets++], sizeof u->targets[0], "%s", m->valuestring);
    }
    v->n_uses++;
    return 0;
}

int lex_uses_load(sp_lex_vocab *v, const char *path, sp_error *err)
{
    return lex_entries_load(v, path, "uses", "activity table", add_use, err);
}

/* A query's words with their base forms as a verb and as a noun (WordNet's morphy), found once
 * per query: the table has over a thousand entries. */
typedef struct {
    int n;
    int cued[LEX_MAX_TOKENS]; /* a cue word stands before it */
    int n_verb[LEX_MAX_TOKENS], n_noun[LEX_MAX_TOKENS];
    char verb[LEX_MAX_TOKENS][WN_MAX_BASES + 1][WN_LEMMA_MAX];
    char noun[LEX_MAX_TOKENS][WN_MAX_BASES + 1][WN_LEMMA_MAX];
} query_forms;

/* The word itself and its bases as pos into out; returns the count or a negative SP_E_* code. */
static int forms_of(const sp_lex_vocab *v, wn_pos pos, const char *w, char out[][WN_LEMMA_MAX], sp_error *err)
{
    snprintf(out[0], WN_LEMMA_MAX, "%s", w);
    int nb = lex_bases(v->lx, pos, w, out + 1, err);
    return nb < 0 ? nb : nb + 1;
}

static int has_form(char forms[][WN_LEMMA_MAX], int n, const char *key)
{
    for (int i = 0; i < n; i++)
        if (!strcmp(forms[i], key)) return 1;
    return 0;
}

/* A word before a verb that makes it one: the purpose "to", a subject, a modal ("something TO
 * wash", "where can I wash", "somewhere WE can eat", "a place FOR washing"). */
static int verb_cue(const char *w)
{
    static const char *const cue[] = {"to",    "i",     "we",  "you",   "they", "people", "someone", "somebody",
                                      "one",   "can",   "could", "do",  "should", "would", "will",  "must",
                                      "may",   "might", "lets", "let's", "for",   "me",     "us",     NULL};
    for (int i = 0; cue[i]; i++)
        if (!strcmp(w, cue[i])) return 1;
    return 0;
}

/* 1 when the query asks to do u: its verb after a cue, its other words among what follows. */
static int asks_for(const query_forms *q, const lex_use *u)
{
    for (int i = 1; i < q->n; i++) {
        if (!q->cued[i] || !has_form((char (*)[WN_LEMMA_MAX])q->verb[i], q->n_verb[i], u->words[0])) continue;
        int all = 1;
        for (int k = 1; k < u->n_words && all; k++) {
            int found = 0;
            for (int j = i + 1; j < q->n && !found; j++)
                found = has_form((char (*)[WN_LEMMA_MAX])q->noun[j], q->n_noun[j], u->words[k]);
            all = found;
        }
        if (all) return 1;
    }
    return 0;
}

int lex_uses_find(const sp_lex_vocab *v, const lex_tokens *t, const lex_use **out, int max, sp_error *err)
{
    int any = 0; /* a verb needs a cue before it: without one the query asks for no activity */
    for (int i = 1; i < t->n && !any; i++) any = verb_cue(t->w[i - 1]);
    if (!v->n_uses || !any) return 0;
    query_forms *q = calloc(1, sizeof *q);
    if (!q) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    q->n = t->n;
    int rc = 0;
    for (int i = 1; i < t->n; i++) q->cued[i] = verb_cue(t->w[i - 1]);
    /* the verb's forms where a cue stands before it; every word's noun forms (its objects) */
    for (int i = 1; i < t->n && rc >= 0; i++) {
        if (q->cued[i] && (rc = forms_of(v, WN_VERB, t->w[i], q->verb[i], err)) >= 0) q->n_verb[i] = rc;
        if (rc >= 0 && (rc = forms_of(v, WN_NOUN, t->w[i], q->noun[i], err)) >= 0) q->n_noun[i] = rc;
    }
    int n = 0, best = 0;
    for (int k = 0; rc >= 0 && k < v->n_uses; k++) {
        const lex_use *u = &v->uses[k];
        if (u->n_words < best || !asks_for(q, u)) continue;
        if (u->n_words > best) best = u->n_words, n = 0;
        if (n < max) out[n++] = u;
    }
    free(q);
    return rc < 0 ? rc : n;
}
