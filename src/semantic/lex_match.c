/* The lexical text encoder's entry point: a query split into target and anchor at a spatial
 * relation where both sides match ("the chair near the window"), phrases that name regions
 * resolved to the classes that define them, everything else scored as a noun phrase. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lexical.h"

const char *sp_lex_kind_name(int kind)
{
    static const char *const names[] = {"none",    "exact", "synonym", "hypernym", "hyponym",
                                        "part",    "related", "gloss", "modifier", "region"};
    return kind >= 0 && kind <= SP_LEX_REGION ? names[kind] : "?";
}

static void join_words(const lex_tokens *t, int from, int to, char *out, size_t cap)
{
    size_t o = 0;
    out[0] = 0;
    for (int i = from; i < to && o + 1 < cap; i++) {
        int k = snprintf(out + o, cap - o, "%s%s", o ? " " : "", t->w[i]);
        if (k > 0) o += (size_t)k;
    }
    for (char *p = out; *p; p++)
        if (*p == '_') *p = ' ';
}

static void add_ignored(sp_lex_result *res, const char *w)
{
    for (int i = 0; i < res->n_ignored; i++)
        if (!strcmp(res->ignored[i], w)) return;
    if (res->n_ignored < SP_LEX_MAX_IGNORED) snprintf(res->ignored[res->n_ignored++], 32, "%s", w);
}

/* 1 when ph's matches are already sorted best first. */
static int sub_sorted(const sp_lex_phrase *ph)
{
    for (int i = 1; i < ph->n_matches; i++)
        if (lex_match_cmp(&ph->matches[i - 1], &ph->matches[i]) > 0) return 0;
    return 1;
}

/* Resolves the phrase [from, to) of t into ph: a region or an object phrase. */
static int resolve(const sp_lex_vocab *v, const lex_tokens *t, int from, int to, sp_lex_phrase *ph,
                   sp_lex_result *res, int depth, sp_error *err);

/* A phrase naming a region: a room of the table or of WordNet ("the kitchen", "bedroom"), or a
 * generic area defined by what follows a link word or by its modifiers ("area with appliances",
 * "the area that looks like a kitchen", "the kitchen area"). Sets *is_region. */
static int resolve_region(const sp_lex_vocab *v, const lex_np *np, const lex_tokens *t,
                          sp_lex_phrase *ph, sp_lex_result *res, int depth, int *is_region,
                          sp_error *err)
{
    *is_region = 0;
    if (np->head_start < 0) return 0;
    const lex_region *r = NULL;
    int rc = np->placeholder ? 0 : lex_region_named(v, np, &r, err);
    if (rc) return rc;
    /* A room of WordNet when its commonest sense is one ("kitchen"; not "car", whose fourth
     * sense is an elevator's cabin). */
    const char *def = np->placeholder ? NULL : lex_region_definition(np, r != NULL);
    int generic = lex_is_generic_region(np->head);
    int linked = np->head_start + 1 < t->n && lex_is_region_link(t->w[np->head_start + 1]);
    /* "somewhere for a patient to lie down" is a place to lie down: a placeholder whose
     * complement holds a purpose clause ("to" + verb) describes a thing, it names no area. */
    for (int i = np->head_start + 1; np->placeholder && linked && i + 1 < t->n; i++)
        if (!strcmp(t->w[i], "to")) linked = 0;
    if (r || (def && !generic)) {
        if ((rc = lex_region_members(v, r, np->head, def, ph, err))) return rc;
    } else if (generic && depth == 0 && (linked || np->n_mods > 0)) {
        /* The complement: modifiers and the words after the link, without the link words. */
        lex_tokens ct = {0, {{0}}};
        for (int i = 0; i < np->n_mods; i++) snprintf(ct.w[ct.n++], LEX_WORD, "%s", np->mods[i]);
        for (int i = 0; i < np->n_desc && ct.n < LEX_MAX_TOKENS; i++)
            if (!lex_is_region_link(np->desc[i])) snprintf(ct.w[ct.n++], LEX_WORD, "%s", np->desc[i]);
        if (ct.n == 0) return 0;
        sp_lex_phrase *sub = malloc(sizeof *sub);
        if (!sub) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
        if (!(rc = resolve(v, &ct, 0, ct.n, sub, res, depth + 1, err))) {
            snprintf(ph->region, sizeof ph->region, "%s", sub->is_region ? sub->region : sub->text);
            if (sub->is_region) {
                memcpy(ph->matches, sub->matches, sizeof ph->matches);
                ph->n_matches = sub->n_matches;
            } else {
                lex_region_start(v, ph);
                lex_region_absorb(ph, sub, "objects of the area");
            }
        }
        free(sub);
        if (rc) return rc;
    } else {
        return 0;
    }
    if (!sub_sorted(ph)) qsort(ph->matches, (size_t)v->n, sizeof ph->matches[0], lex_match_cmp);
    ph->is_region = 1;
    snprintf(ph->head, sizeof ph->head, "%s", np->head);
    for (char *p = ph->head; *p; p++)
        if (*p == '_') *p = ' ';
    *is_region = 1;
    return 0;
}

static int resolve(const sp_lex_vocab *v, const lex_tokens *t, int from, int to, sp_lex_phrase *ph,
                   sp_lex_result *res, int depth, sp_error *err)
{
    memset(ph, 0, sizeof *ph);
    join_words(t, from, to, ph->text, sizeof ph->text);
    lex_np np;
    int use[8] = {0};
    int rc = lex_np_parse(v->lx, t, from, to, 0, &np, err);
    if (!rc) rc = lex_score_np(v, &np, ph, use, err);
    /* The object reading wins when the scene has the thing by name ("closet" is a room in
     * WordNet and the wardrobe's synonym); otherwise a phrase that names a region is one. */
    const sp_lex_class_match *b = &ph->matches[0];
    int named = ph->n_matches && b->score >= SP_LEX_THRESHOLD &&
                (b->kind == SP_LEX_EXACT || b->kind == SP_LEX_SYNONYM);
    if (!rc && !named && depth < 2) {
        sp_lex_phrase *reg = malloc(sizeof *reg);
        int is_region = 0;
        if (!reg) rc = sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
        else {
            *reg = *ph;
            rc = resolve_region(v, &np, t, reg, res, depth, &is_region, err);
            if (!rc && is_region) *ph = *reg;
            free(reg);
        }
    }
    for (int i = 0; !rc && res && !ph->is_region && i < np.n_mods; i++)
        if (use[i] == LEX_MOD_IGNORED) add_ignored(res, np.mods[i]);
    lex_np_free(&np);
    return rc;
}

static float best_of(const sp_lex_phrase *ph) { return ph->n_matches ? ph->matches[0].score : 0; }

/* "the table in the dining room": among the target's matches, the classes that define the
 * anchor region come first (stable otherwise). */
static void prefer_members(sp_lex_phrase *target, const sp_lex_phrase *region)
{
    sp_lex_class_match in[SP_LEX_MAX_CLASSES], out[SP_LEX_MAX_CLASSES];
    int ni = 0, no = 0;
    for (int i = 0; i < target->n_matches; i++) {
        const sp_lex_class_match *m = &target->matches[i];
        int member = 0;
        for (int k = 0; k < region->n_matches && !member; k++)
            member = region->matches[k].class_index == m->class_index && region->matches[k].score >= SP_LEX_THRESHOLD;
        if (member && m->score >= SP_LEX_THRESHOLD) in[ni++] = *m;
        else out[no++] = *m;
    }
    memcpy(target->matches, in, sizeof in[0] * (size_t)ni);
    memcpy(target->matches + ni, out, sizeof out[0] * (size_t)no);
}

/* "to" before a verb that is no noun starts a purpose clause ("something to sit on"). */
static int purpose_to(const sp_lex_vocab *v, const lex_tokens *t, int i, sp_error *err)
{
    if (i + 1 >= t->n) return 0;
    const char *w = t->w[i + 1];
    if (lex_word_class_of(w) != LW_CONTENT) return 0;
    int verb = lex_is_pos(v->lx, WN_VERB, w, err), noun = lex_is_pos(v->lx, WN_NOUN, w, err);
    return verb > 0 && noun == 0;
}

int lex_match_reading(const sp_lex_vocab *v, const char *text, const lex_tokens *raw,
                      sp_lex_result *res, sp_error *err)
{
    memset(res, 0, sizeof *res);
    snprintf(res->text, sizeof res->text, "%s", text);
    lex_tokens t;
    int rc = lex_merge_collocations(v->lx, raw, &t, err);
    if (rc) return rc;
    sp_lex_result *trial = malloc(sizeof *trial);
    if (!trial) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    /* The first relation word where both sides match splits target and anchor. */
    int split = 0;
    for (int i = 1; i < t.n - 1 && !rc && !split; i++) {
        const char *name;
        int k = lex_relation_at(&t, i, &name);
        if (!k || i + k >= t.n) continue;
        if (!strcmp(name, "to") && purpose_to(v, &t, i, err)) continue;
        if (!strcmp(name, "of") && lex_word_class_of(t.w[i - 1]) == LW_PARTITIVE) continue;
        if (lex_is_generic_region(t.w[i - 1])) continue; /* "area with appliances" is one region */
        memset(trial, 0, sizeof *trial);
        if ((rc = resolve(v, &t, 0, i, &trial->target, trial, 0, err))) break;
        if (best_of(&trial->target) < SP_LEX_THRESHOLD || trial->target.is_region) continue;
        if ((rc = resolve(v, &t, i + k, t.n, &trial->anchor, trial, 0, err))) break;
        if (best_of(&trial->anchor) < SP_LEX_THRESHOLD) continue;
        snprintf(trial->text, sizeof trial->text, "%s", text);
        snprintf(trial->relation, sizeof trial->relation, "%s", name);
        if (trial->anchor.is_region) prefer_members(&trial->target, &trial->anchor);
        *res = *trial;
        split = 1;
    }
    free(trial);
    if (!rc && !split) rc = resolve(v, &t, 0, t.n, &res->target, res, 0, err);
    if (rc) return rc;
    res->confidence = best_of(&res->target);
    res->found = res->confidence >= SP_LEX_THRESHOLD;
    return 0;
}
