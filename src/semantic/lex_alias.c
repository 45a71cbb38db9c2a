/* Names WordNet lacks or files under another sense: everyday, regional (UK / US) and trade names of
 * indoor objects ("shop vac", "wheelie bin", "IV pole", "telly", "hoover", "trolley"), from a
 * curated table (data/semantic/aliases.json) that maps each to WordNet noun lemmas. An alias is
 * another READING of the words: a query is matched as written and with each alias replaced by
 * its targets, and every class keeps its best reading (a user may mean either: "trolley" is
 * WordNet's streetcar and the British cart). A class name is prepared through its first target
 * (lex_vocab.c): the scene's object is the thing the name usually means indoors. */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lexical.h"
#include "semsplat/io.h"

#define MAX_READINGS 3

static int add_alias(sp_lex_vocab *v, const char *path, const cJSON *it, sp_error *err)
{
    lex_tokens t;
    lex_tokenize(it->string, &t);
    if (t.n < 1 || t.n > 4 || (!cJSON_IsArray(it) && !cJSON_IsString(it)))
        return sp_error_set(err, SP_E_FORMAT, "%s: alias '%s': a name of 1 to 4 words with a lemma or a list "
                            "of lemmas", path, it->string);
    lex_alias *na = realloc(v->aliases, sizeof *na * (size_t)(v->n_aliases + 1));
    if (!na) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    v->aliases = na;
    lex_alias *a = memset(&na[v->n_aliases], 0, sizeof *na);
    a->n_words = t.n;
    for (int i = 0; i < t.n; i++) snprintf(a->words[i], LEX_WORD, "%s", t.w[i]);
    const cJSON *m = cJSON_IsString(it) ? it : it->child;
    for (; m && a->n_targets < MAX_READINGS; m = cJSON_IsString(it) ? NULL : m->next) {
        if (!cJSON_IsString(m) || !m->valuestring[0])
            return sp_error_set(err, SP_E_FORMAT, "%s: alias '%s': targets must be strings", path, it->string);
        snprintf(a->targets[a->n_targets++], 64, "%s", m->valuestring);
    }
    if (!a->n_targets) return sp_error_set(err, SP_E_FORMAT, "%s: alias '%s' has no target", path, it->string);
    v->n_aliases++;
    return 0;
}

int lex_aliases_load(sp_lex_vocab *v, const char *path, sp_error *err)
{
    return lex_entries_load(v, path, "names", "alias table", add_alias, err);
}

/* 1 when w is key or one of its plurals (-s, -es, -y -> -ies). */
static int word_or_plural(const char *w, const char *key)
{
    size_t nk = strlen(key), nw = strlen(w);
    if (!strcmp(w, key)) return 1;
    if (nw > nk && !strncmp(w, key, nk) && (!strcmp(w + nk, "s") || !strcmp(w + nk, "es"))) return 1;
    return nk > 1 && key[nk - 1] == 'y' && nw == nk + 2 && !strncmp(w, key, nk - 1) && !strcmp(w + nk - 1, "ies");
}

/* The words of tokens (a joined collocation "hospital_bed" gives two), each with its token. */
typedef struct {
    int n;
    char w[2 * LEX_MAX_TOKENS][LEX_WORD];
    int tok[2 * LEX_MAX_TOKENS];
} word_list;

static void words_of(const lex_tokens *in, word_list *wl)
{
    wl->n = 0;
    for (int i = 0; i < in->n; i++) {
        char t[LEX_WORD];
        snprintf(t, sizeof t, "%s", in->w[i]);
        for (char *save = NULL, *p = strtok_r(t, "_", &save); p && wl->n < 2 * LEX_MAX_TOKENS; p = strtok_r(NULL, "_", &save)) {
            snprintf(wl->w[wl->n], LEX_WORD, "%s", p);
            wl->tok[wl->n++] = i;
        }
    }
}

/* Whether a class of the scene is named by exactly the alias's words: the world's own name for
 * a thing shadows the table's general reading of it (a scene with a "card terminal" means that
 * class by it, not the cash register the table reads the name as). */
static int names_a_class(const sp_lex_vocab *v, const lex_alias *a)
{
    /* the words run together, hyphens dropped ("walk-in fridge" is the "walk in fridge") */
    char an[4 * LEX_WORD] = "";
    for (int j = 0; j < a->n_words; j++)
        for (const char *q = a->words[j]; *q; q++)
            if (*q != '-' && strlen(an) + 1 < sizeof an) strncat(an, q, 1);
    for (int c = 0; c < v->n; c++) {
        const lex_class *k = &v->classes[c];
        char kn[8 * LEX_WORD] = "";
        for (int j = 0; j < k->n_tok; j++)
            for (const char *q = k->tok[j]; *q; q++)
                if (*q != '-' && strlen(kn) + 1 < sizeof kn) strncat(kn, q, 1);
        if (!strcmp(an, kn)) return 1;
    }
    return 0;
}

/* The longest alias whose words are whole tokens from word p on (a WordNet collocation is not
 * broken up: "laundry cart" is WordNet's, its "cart" no alias) and that names no class of the
 * scene, or NULL. */
static const lex_alias *alias_at(const sp_lex_vocab *v, const word_list *wl, int p, int *span)
{
    const lex_alias *best = NULL;
    *span = 0;
    for (int k = 0; k < v->n_aliases; k++) {
        const lex_alias *a = &v->aliases[k];
        if (best && a->n_words <= best->n_words) continue;
        /* an alias word written with a hyphen is also the words it joins ("x-ray scanner" is the
         * class "x ray scanner") */
        int q = p, ok = 1;
        for (int j = 0; j < a->n_words && ok; j++) {
            int last = j + 1 == a->n_words;
            if (q < wl->n && (last ? word_or_plural(wl->w[q], a->words[j]) : !strcmp(wl->w[q], a->words[j]))) {
                q++;
                continue;
            }
            ok = 0;
            if (!strchr(a->words[j], '-')) break;
            char parts[LEX_WORD];
            snprintf(parts, sizeof parts, "%s", a->words[j]);
            int r = q, good = 1;
            char *save = NULL, *t = strtok_r(parts, "-", &save);
            while (t && good) {
                char *next = strtok_r(NULL, "-", &save);
                good = r < wl->n && (last && !next ? word_or_plural(wl->w[r], t) : !strcmp(wl->w[r], t));
                r++, t = next;
            }
            if (good) ok = 1, q = r;
        }
        int e = q; /* one past the last word */
        if (!ok || e > wl->n) continue;
        if (e < wl->n && wl->tok[e] == wl->tok[e - 1]) continue; /* ends inside a token */
        if (!names_a_class(v, a)) best = a, *span = e - p;
    }
    /* a name of two words WordNet writes as one ("hand basin", its handbasin, a bowl): the one
     * word of the query that is the name's words joined is that name */
    for (int k = 0; !best && k < v->n_aliases; k++) {
        const lex_alias *a = &v->aliases[k];
        if (a->n_words < 2 || (p + 1 < wl->n && wl->tok[p + 1] == wl->tok[p]) || (p > 0 && wl->tok[p - 1] == wl->tok[p]))
            continue;
        char joined[4 * LEX_WORD] = "";
        for (int j = 0; j < a->n_words; j++) strncat(joined, a->words[j], sizeof joined - strlen(joined) - 1);
        if (word_or_plural(wl->w[p], joined) && !names_a_class(v, a)) best = a, *span = 1;
    }
    return best;
}

int lex_alias_rewrite(const sp_lex_vocab *v, const lex_tokens *in, int reading, lex_tokens *out,
                      char *used, size_t cap)
{
    word_list words, *wl = &words; /* 3 KB: no allocation that could fail */
    int n = 0;
    size_t o = 0;
    *out = *in;
    if (used && cap) used[0] = 0;
    if (!v->n_aliases) return 0;
    words_of(in, wl);
    out->n = 0;
    for (int p = 0; p < wl->n;) {
        int span = 0;
        const lex_alias *a = (p == 0 || wl->tok[p] != wl->tok[p - 1]) ? alias_at(v, wl, p, &span) : NULL;
        if (!a || reading >= a->n_targets) { /* its tokens stay as they were */
            int e = p + (a ? span : 1);
            while (e < wl->n && wl->tok[e] == wl->tok[e - 1]) e++;
            for (int t = wl->tok[p]; t <= wl->tok[e - 1] && out->n < LEX_MAX_TOKENS; t++)
                snprintf(out->w[out->n++], LEX_WORD, "%s", in->w[t]);
            p = e;
            continue;
        }
        lex_tokens t;
        lex_tokenize(a->targets[reading], &t);
        for (int j = 0; j < t.n && out->n < LEX_MAX_TOKENS; j++) snprintf(out->w[out->n++], LEX_WORD, "%s", t.w[j]);
        if (used && o + 1 < cap) {
            char name[4 * LEX_WORD] = "";
            for (int j = 0; j < a->n_words; j++)
                snprintf(name + strlen(name), sizeof name - strlen(name), "%s%s", j ? " " : "", a->words[j]);
            int k = snprintf(used + o, cap - o, "%s'%s' = %s", o ? "; " : "", name, a->targets[reading]);
            if (k > 0) o += (size_t)k;
        }
        p += span;
        n++;
    }
    if (!n) *out = *in;
    return n;
}

int lex_alias_class(const sp_lex_vocab *v, const lex_tokens *in, lex_tokens *out, sp_error *err)
{
    word_list words, *wl = &words;
    words_of(in, wl);
    int span = 0;
    const lex_alias *a = wl->n ? alias_at(v, wl, 0, &span) : NULL;
    int rc = a && span == wl->n, noun = 1;
    if (rc) lex_tokenize(a->targets[0], out);
    else if (in->n > 1 && (noun = lex_is_pos(v->lx, WN_NOUN, in->w[in->n - 1], err)) < 0) rc = noun;
    else if (in->n > 1 && !noun) {
        /* a head WordNet lacks ("hand SANITIZER") is read through the table; the words before
         * it stay ("hand disinfectant") */
        lex_tokens last = {1, {{0}}}, read;
        snprintf(last.w[0], LEX_WORD, "%s", in->w[in->n - 1]);
        words_of(&last, wl);
        a = alias_at(v, wl, 0, &span);
        if ((rc = a && span == wl->n)) {
            *out = *in;
            out->n--;
            lex_tokenize(a->targets[0], &read);
            for (int i = 0; i < read.n && out->n < LEX_MAX_TOKENS; i++) snprintf(out->w[out->n++], LEX_WORD, "%s", read.w[i]);
        }
    }
    return rc;
}

static int plain(const sp_lex_result *r) { return !r->relation[0] && !r->target.is_region; }

/* Notes the alias reading in a match's explanation. */
static void cite(sp_lex_class_match *m, const char *used)
{
    char p[sizeof m->path];
    snprintf(p, sizeof p, "%s", m->path);
    snprintf(m->path, sizeof m->path, "alias %s%s%s", used, p[0] ? "; " : "", p);
}

/* Folds the alias reading alt into res: a plain phrase keeps every class's best reading; a
 * relation or a region reading replaces res when it is more confident. */
static void fold(sp_lex_result *res, sp_lex_result *alt, const char *used)
{
    /* the words as written have no noun for a head ("racking", "shelving": description words,
     * matched against every definition) but the alias names a thing: it is the reading */
    int named = plain(res) && plain(alt) && !res->target.head[0] && alt->target.head[0];
    if (plain(res) && plain(alt) && !named) {
        sp_lex_class_match *by_class[SP_LEX_MAX_CLASSES] = {0};
        for (int i = 0; i < res->target.n_matches; i++) by_class[res->target.matches[i].class_index] = &res->target.matches[i];
        int better = alt->confidence > res->confidence;
        for (int i = 0; i < alt->target.n_matches; i++) {
            sp_lex_class_match *m = &alt->target.matches[i], *r = by_class[m->class_index];
            if (r && m->score > r->score) *r = *m, cite(r, used);
        }
        qsort(res->target.matches, (size_t)res->target.n_matches, sizeof res->target.matches[0], lex_match_cmp);
        if (better) { /* the attributes are those of the reading that decided, in the user's words */
            lex_tokens said;
            lex_tokenize(res->text, &said);
            res->n_ignored = 0;
            for (int i = 0; i < alt->n_ignored; i++)
                for (int k = 0; k < said.n; k++)
                    if (!strcmp(said.w[k], alt->ignored[i])) {
                        snprintf(res->ignored[res->n_ignored++], sizeof res->ignored[0], "%s", alt->ignored[i]);
                        break;
                    }
        }
    } else if (res->target.is_region && !res->relation[0] && plain(alt) && res->target.n_matches &&
               alt->target.n_matches && res->found &&
               res->target.matches[0].class_index == alt->target.matches[0].class_index) {
        /* the words as written name a region whose first thing is what the alias names ("the
         * entrance": the entrance, its door first): the region says more */
    } else if (named || alt->confidence > res->confidence) {
        char text[sizeof res->text];
        snprintf(text, sizeof text, "%s", res->text);
        for (int i = 0; i < alt->target.n_matches; i++) cite(&alt->target.matches[i], used);
        *res = *alt;
        snprintf(res->text, sizeof res->text, "%s", text);
    }
    res->confidence = res->target.n_matches ? res->target.matches[0].score : 0;
    res->found = res->confidence >= SP_LEX_THRESHOLD;
}

/* Folds the reading of an activity's thing into res: a class that is the thing or a kind of it
 * (named, a synonym, a kind by WordNet or by its name, not a more general thing: a recliner is
 * for lying down, not every chair; at most one weak step from the thing:
 * score >= LEX_DELTA) keeps the reading, one weak step (LEX_USE) below its own score, when that
 * is better; definitions, parts, relatives and kinds with other modifiers ("ticket counter" is
 * no kiosk counter) do not count. */
static void fold_use(sp_lex_result *res, const sp_lex_result *alt, const lex_use *u, const char *thing)
{
    if (!plain(res) || !plain(alt)) return;
    sp_lex_class_match *by_class[SP_LEX_MAX_CLASSES] = {0};
    for (int i = 0; i < res->target.n_matches; i++) by_class[res->target.matches[i].class_index] = &res->target.matches[i];
    char used[160] = "";
    for (int k = 0; k < u->n_words; k++) {
        size_t o = strlen(used);
        snprintf(used + o, sizeof used - o, "%s%s", k ? " " : "'", u->words[k]);
    }
    size_t o = strlen(used);
    snprintf(used + o, sizeof used - o, "' is done with %s", thing);
    int changed = 0;
    for (int i = 0; i < alt->target.n_matches; i++) {
        const sp_lex_class_match *m = &alt->target.matches[i];
        sp_lex_class_match *r = by_class[m->class_index];
        if (m->kind != SP_LEX_EXACT && m->kind != SP_LEX_SYNONYM && m->kind != SP_LEX_HYPERNYM) continue;
        if (m->score < LEX_DELTA) continue;
        float s = m->score * LEX_USE;
        if (!r || s <= r->score) continue;
        *r = *m;
        r->score = s;
        char p[sizeof r->path];
        snprintf(p, sizeof p, "%s", r->path);
        snprintf(r->path, sizeof r->path, "activity %s%s%s", used, p[0] ? "; " : "", p);
        changed = 1;
    }
    if (!changed) return;
    qsort(res->target.matches, (size_t)res->target.n_matches, sizeof res->target.matches[0], lex_match_cmp);
    res->confidence = res->target.n_matches ? res->target.matches[0].score : 0;
    res->found = res->confidence >= SP_LEX_THRESHOLD;
}

/* A word and a preposition that a class's name holds side by side and WordNet joins with a
 * hyphen ("walk in" of the "walk in fridge", WordNet's walk-in) are that one word in a query too,
 * as the class name was read (class_prepare): "walk in fridge" is no walk in a fridge. */
static void join_name_words(const sp_lex_vocab *v, lex_tokens *t)
{
    for (int i = 0; i + 1 < t->n; i++) {
        if (lex_word_class_of(t->w[i + 1]) != LW_PREP && !lex_is_particle(t->w[i + 1])) continue;
        int held = 0;
        for (int c = 0; c < v->n && !held; c++) {
            const lex_class *k = &v->classes[c];
            if (!k->joined) continue;
            for (int j = 0; j + 1 < k->n_tok && !held; j++)
                held = !strcmp(k->tok[j], t->w[i]) && !strcmp(k->tok[j + 1], t->w[i + 1]);
        }
        if (!held) continue;
        char hy[2 * LEX_WORD + 2];
        snprintf(hy, sizeof hy, "%s-%s", t->w[i], t->w[i + 1]);
        if (strlen(hy) >= LEX_WORD) continue;
        snprintf(t->w[i], LEX_WORD, "%s", hy);
        memmove(t->w[i + 1], t->w[i + 2], sizeof t->w[0] * (size_t)(t->n - i - 2));
        t->n--;
    }
}

/* A query that starts with a verb in its base form followed by a determiner (after a particle
 * or not) is an instruction ("wash my hands", "keep the food cold", "throw away the scraps"):
 * what it asks for is the thing to do it with, read as "something to wash my hands". */
static int determiner(const char *w)
{
    static const char *const d[] = {"a", "an", "the", "my", "your", "our", "his", "her", "their", "its", "this",
                                    "these", "those", "some", NULL};
    for (int i = 0; d[i]; i++)
        if (!strcmp(w, d[i])) return 1;
    return 0;
}

static void imperative(const sp_lex_vocab *v, lex_tokens *t)
{
    if (t->n < 3 || t->n + 2 > LEX_MAX_TOKENS || lex_word_class_of(t->w[0]) != LW_CONTENT) return;
    /* "wash MY hands", "throw away THE scraps"; not "trash can", "roll up door" */
    if (!determiner(t->w[1]) && !(lex_is_particle(t->w[1]) && t->n > 3 && determiner(t->w[2]))) return;
    sp_error err = {0};
    char b[WN_MAX_BASES][WN_LEMMA_MAX];
    int nb = lex_bases(v->lx, WN_VERB, t->w[0], b, &err), base = 0;
    for (int i = 0; i < nb && !base; i++) base = !strcmp(b[i], t->w[0]);
    if (!base) return;
    memmove(t->w[2], t->w[0], sizeof t->w[0] * (size_t)t->n);
    snprintf(t->w[0], LEX_WORD, "something");
    snprintf(t->w[1], LEX_WORD, "to");
    t->n += 2;
}

int sp_lex_match(const sp_lex_vocab *v, const char *text, sp_lex_result *res, sp_error *err)
{
    if (!v || !text || !res) return sp_error_set(err, SP_E_ARG, "lexical: missing argument");
    lex_tokens raw;
    lex_tokenize(text, &raw);
    lex_way_direction(&raw); /* before the alias readings: "the way out" is the exit, a door */
    join_name_words(v, &raw);
    imperative(v, &raw);
    if (raw.n == 0) {
        memset(res, 0, sizeof *res);
        return sp_error_set(err, SP_E_ARG, "lexical: the query '%s' has no words", text);
    }
    lex_tokens merged;
    int rc = lex_match_reading(v, text, &raw, res, err);
    if (!rc) rc = lex_merge_collocations(v->lx, &raw, &merged, err);
    sp_lex_result *alt = NULL;
    for (int k = 0; k < MAX_READINGS && !rc; k++) {
        lex_tokens t;
        char used[160];
        if (lex_alias_rewrite(v, &merged, k, &t, used, sizeof used) == 0) break;
        if (!alt && !(alt = malloc(sizeof *alt))) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
        if (!(rc = lex_match_reading(v, text, &t, alt, err))) fold(res, alt, used);
    }
    const lex_use *uses[4];
    int nu = rc ? 0 : lex_uses_find(v, &raw, uses, 4, err);
    if (nu < 0) rc = nu;
    for (int k = 0; k < nu && !rc; k++)
        for (int j = 0; j < uses[k]->n_targets && !rc; j++) {
            lex_tokens t;
            lex_tokenize(uses[k]->targets[j], &t);
            if (!alt && !(alt = malloc(sizeof *alt))) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
            lex_everyday_name = 1;
            rc = lex_match_reading(v, text, &t, alt, err);
            lex_everyday_name = 0;
            if (!rc) fold_use(res, alt, uses[k], uses[k]->targets[j]);
        }
    free(alt);
    return rc;
}
