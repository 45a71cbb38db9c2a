/* The lexical text encoder's entry point: a query split into target and anchor at a spatial
 * relation where both sides match ("the chair near the window"), phrases that name regions
 * resolved to the classes that define them, everything else scored as a noun phrase. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

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

static float best_of(const sp_lex_phrase *ph) { return ph->n_matches ? ph->matches[0].score : 0; }

/* Resolves the phrase [from, to) of t into ph: a region or an object phrase. */
static int resolve(const sp_lex_vocab *v, const lex_tokens *t, int from, int to, sp_lex_phrase *ph,
                   sp_lex_result *res, int depth, sp_error *err);

/* 1 when table region r's name is made of np's modifiers and head ("the meeting room"). */
static int region_by_mods(const lex_np *np, const lex_region *r)
{
    char name[64];
    int by_mod = 0;
    snprintf(name, sizeof name, "%s", r->name);
    for (char *save = NULL, *w = strtok_r(name, " ", &save); w; w = strtok_r(NULL, " ", &save)) {
        int in = !strcmp(w, np->head);
        for (int i = 0; i < np->n_mods && !in; i++) in = by_mod = !strcmp(w, np->mods[i]);
        if (!in) return 0;
    }
    return by_mod;
}

/* *names = 1 when np's modifiers, read alone as an object phrase, name a class of the scene by
 * its name or a synonym at the threshold. */
static int mods_name_classes(const sp_lex_vocab *v, const lex_np *np, int depth, int *names, sp_error *err)
{
    *names = 0;
    lex_tokens ct = {0, {{0}}};
    for (int i = 0; i < np->n_mods && ct.n < LEX_MAX_TOKENS; i++) snprintf(ct.w[ct.n++], LEX_WORD, "%s", np->mods[i]);
    sp_lex_phrase *sub = malloc(sizeof *sub);
    if (!sub) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    int rc = resolve(v, &ct, 0, ct.n, sub, NULL, depth + 2, err);
    if (!rc && !sub->is_region && sub->n_matches && sub->matches[0].score >= SP_LEX_THRESHOLD &&
        (sub->matches[0].kind == SP_LEX_EXACT || sub->matches[0].kind == SP_LEX_SYNONYM))
        *names = 1;
    free(sub);
    return rc;
}

/* A phrase naming a region: a room of the table or of WordNet ("the kitchen", "bedroom"), or a
 * generic area defined by what follows a link word or by its modifiers ("area with appliances",
 * "the area that looks like a kitchen", "the kitchen area"). Sets *is_region. */
static int resolve_region(const sp_lex_vocab *v, const lex_np *np, const lex_tokens *t,
                          sp_lex_phrase *ph, sp_lex_result *res, int depth, int *is_region,
                          sp_error *err)
{
    *is_region = 0;
    if (np->head_start < 0) {
        /* a table region's name WordNet lacks ("the cattery"): the region by its name as written */
        char name[64] = "";
        for (int i = 0; i < np->n_words; i++) {
            strncat(name, i ? " " : "", sizeof name - strlen(name) - 1);
            strncat(name, np->words[i], sizeof name - strlen(name) - 1);
        }
        const lex_region *nr = np->n_words && !np->placeholder ? lex_region_find(v, name) : NULL;
        if (!nr) return 0;
        int rc = lex_region_members(v, nr, name, NULL, ph, err);
        if (rc) return rc;
        if (!sub_sorted(ph)) qsort(ph->matches, (size_t)v->n, sizeof ph->matches[0], lex_match_cmp);
        ph->is_region = 1;
        snprintf(ph->head, sizeof ph->head, "%s", name);
        *is_region = 1;
        return 0;
    }
    const lex_region *r = NULL;
    int rc = np->placeholder ? 0 : lex_region_named(v, np, &r, err);
    if (rc < 0) return rc;
    int by_wordnet_room = rc == 1; /* through a WordNet room's synonym: "sleeping room" */
    /* a table name is written as people say it: "the ladies", "the stacks" are no lady, no stack */
    if (!r && !np->placeholder && np->head_end == np->head_start + 1 && np->n_mods == 0 &&
        strcmp(t->w[np->head_start], np->head))
        r = lex_region_find(v, t->w[np->head_start]), by_wordnet_room = 0;
    rc = 0;
    /* A room of WordNet when its commonest sense is one ("kitchen"; not "car", whose fourth
     * sense is an elevator's cabin). */
    const char *def = np->placeholder ? NULL : lex_region_definition(np, r != NULL);
    int generic = lex_is_generic_region(np->head);
    /* a WordNet collocation of a generic area ("seating_area", "parking_area") that names no room
     * and no table region is such an area too, its leading words the complement */
    char lead[WN_LEMMA_MAX] = "";
    const char *last = strrchr(np->head, '_');
    if (!r && !def && last && lex_is_generic_region(last + 1))
        snprintf(lead, sizeof lead, "%.*s", (int)(last - np->head), np->head);
    int linked = np->head_start + 1 < t->n && lex_is_region_link(t->w[np->head_start + 1]);
    /* "somewhere for a patient to lie down" is a place to lie down: a placeholder whose
     * complement holds a purpose clause ("to" + verb) describes a thing, it names no area. */
    for (int i = np->head_start + 1; np->placeholder && linked && i + 1 < t->n; i++)
        if (!strcmp(t->w[i], "to")) linked = 0;
    int table = r || (def && !generic);
    /* "the sculpture hall", "the painting gallery": a place whose modifiers name classes of the
     * scene (by name or synonym) is the area of those classes, not the table's room its head
     * alone stands for (the hall is no hallway here); a table name its modifiers make ("the
     * meeting room", "the locker room") stays the table's. */
    int surface = 0; /* "wall cupboard": a thing mounted on the walls, not the walls' area */
    for (int i = 0; i < np->n_mods; i++) {
        char b[WN_MAX_BASES][WN_LEMMA_MAX];
        int nb = lex_bases(v->lx, WN_NOUN, np->mods[i], b, err);
        if (nb < 0) return nb;
        surface |= lex_building_surface(nb > 0 ? b[0] : np->mods[i]);
    }
    if (!generic && depth == 0 && np->n_mods > 0 && !np->placeholder && !np->n_desc && lex_place_head(np) &&
        !(r && region_by_mods(np, r)) && !surface) {
        int names = 0;
        if ((rc = mods_name_classes(v, np, depth, &names, err))) return rc;
        if (names) table = 0, r = NULL, def = NULL, generic = 1;
    }
    if (table && by_wordnet_room) {
        /* "the sleeping corner" is WordNet's sleeping room, a bedroom; when the scene shows no
         * bedroom (one bed is not two of its kinds) it is still the corner where one sleeps */
        sp_lex_phrase *keep = malloc(sizeof *keep);
        if (!keep) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
        *keep = *ph;
        if (!(rc = lex_region_members(v, r, np->head, def, ph, err)) && best_of(ph) < SP_LEX_THRESHOLD)
            *ph = *keep, table = 0, r = NULL;
        free(keep);
        if (rc) return rc;
    } else if (table) {
        if ((rc = lex_region_members(v, r, np->head, def, ph, err))) return rc;
    }
    if (!table && (generic || lead[0]) && depth == 0 && (linked || np->n_mods > 0 || lead[0])) {
        /* The complement: modifiers and the words after the link, without the link words. */
        lex_tokens ct = {0, {{0}}};
        for (int i = 0; i < np->n_mods; i++) snprintf(ct.w[ct.n++], LEX_WORD, "%s", np->mods[i]);
        for (char *save = NULL, *w = strtok_r(lead, "_", &save); w && ct.n < LEX_MAX_TOKENS; w = strtok_r(NULL, "_", &save))
            snprintf(ct.w[ct.n++], LEX_WORD, "%s", w);
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
                /* the classes named after its words ("the patient area": the patient bed), the
                 * objects it names, and when none of those an activity ("the cooking area"),
                 * else whom or what it is for ("the children's section") */
                char words[sizeof sub->text];
                join_words(&ct, 0, ct.n, words, sizeof words);
                /* only words that name the area ("the cooking area"), not its contents ("the
                 * corner with the plant": a plant or nothing) */
                int named_by = !linked;
                int any = named_by ? lex_region_named_after(v, words, ph) : 0;
                any |= lex_region_absorb(ph, sub, "objects of the area");
                if (named_by && !any && (rc = lex_region_activity(v, &ct, ph, err)) >= 0) any = rc, rc = 0;
                if (named_by && !rc && !any && (rc = lex_region_for(v, &ct, ph, err)) > 0) rc = 0;
            }
        }
        free(sub);
        if (rc) return rc;
    } else if (!table) {
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

/* A bare head whose commonest sense is an act ("storage": the act of storing) names the things
 * one does it with: the description "something to V" for the verbs WordNet derives from it, one
 * weak step (DELTA) below what that description finds, where that is more than the noun found
 * ("storage" -> the bookshelf, "a shelf on which to keep books"; the wardrobe, "storage space"). */
static int act_reading(const sp_lex_vocab *v, const lex_np *np, sp_lex_phrase *ph, sp_lex_result *res, int depth,
                       sp_error *err)
{
    if (depth > 0 || np->placeholder || !np->head[0] || np->n_mods || np->n_desc || !np->n_senses ||
        np->senses[0].rank != 1 || !lex_sense_act(&np->senses[0]) || best_of(ph) >= SP_LEX_THRESHOLD)
        return 0;
    char verbs[4][WN_LEMMA_MAX];
    int nv = lex_activity_verbs(v->lx, np->head, verbs, 4, err);
    if (nv <= 0) return nv;
    sp_lex_phrase *d = malloc(sizeof *d);
    if (!d) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    int rc = 0;
    for (int k = 0; k < nv && !rc; k++) {
        lex_tokens t;
        char text[2 * WN_LEMMA_MAX];
        snprintf(text, sizeof text, "something to %s", verbs[k]);
        lex_tokenize(text, &t);
        if ((rc = resolve(v, &t, 0, t.n, d, res, depth + 1, err))) break;
        for (int i = 0; i < d->n_matches; i++)
            for (int j = 0; j < ph->n_matches; j++)
                if (ph->matches[j].class_index == d->matches[i].class_index &&
                    LEX_DELTA * d->matches[i].score > ph->matches[j].score) {
                    ph->matches[j] = d->matches[i];
                    ph->matches[j].score *= LEX_DELTA;
                    snprintf(ph->matches[j].path, sizeof ph->matches[j].path, "'%s' is an act: %s", np->head, text);
                }
    }
    free(d);
    if (!rc) qsort(ph->matches, (size_t)ph->n_matches, sizeof ph->matches[0], lex_match_cmp);
    return rc;
}

static int resolve(const sp_lex_vocab *v, const lex_tokens *t, int from, int to, sp_lex_phrase *ph,
                   sp_lex_result *res, int depth, sp_error *err);

#define FURNITURE 3405725u        /* furniture.n.01 */
#define INSTRUMENTALITY 3575240u  /* instrumentality.n.03: devices, equipment, containers, ... */
#define COMMODITY 3076708u        /* commodity.n.01: WordNet files home appliances as durables */

/* 1 when a sense of class ci is a kind of synset off. */
static int class_under(const sp_lex_vocab *v, int ci, uint32_t off)
{
    const lex_np *np = &v->classes[ci].np;
    for (int s = 0; s < np->n_senses; s++)
        if (lex_anc_find(&np->senses[s], off) >= 0) return 1;
    return 0;
}

/* 1 when class ci is of the category cat: furniture for "furniture", any artifact for the
 * fittings and wares of a place, and otherwise a thing made to be used, an instrumentality or a
 * durable good (WordNet's appliances), that is no furniture ("office equipment" is no desk; no
 * floor, wall or door: "camping gear" is no floor). */
static int in_category(const sp_lex_vocab *v, int ci, const char *cat)
{
    int furniture = class_under(v, ci, FURNITURE);
    if (!strcmp(cat, "furniture") || !strcmp(cat, "furnishing")) return furniture;
    if (!strcmp(cat, "fitting") || !strcmp(cat, "ware")) return !furniture;
    return !furniture && (class_under(v, ci, INSTRUMENTALITY) || class_under(v, ci, COMMODITY));
}

/* A bare category word the taxonomy finds nothing for ("equipment", "machinery": WordNet's are
 * narrow) names every class of the scene in the category (in_category), at the threshold, the
 * least certain find, ordered among themselves by what the taxonomy had. Returns 1 when any. */
static int bare_category(const sp_lex_vocab *v, const char *cat, sp_lex_phrase *ph)
{
    if (best_of(ph) >= SP_LEX_THRESHOLD) return 0;
    int any = 0;
    for (int j = 0; j < ph->n_matches; j++) {
        sp_lex_class_match *m = &ph->matches[j];
        if (!in_category(v, m->class_index, cat)) continue;
        m->score = SP_LEX_THRESHOLD + 0.1f * m->score;
        m->kind = SP_LEX_HYPERNYM;
        snprintf(m->path, sizeof m->path, "%s: a thing of that category", cat);
        any = 1;
    }
    if (any) qsort(ph->matches, (size_t)ph->n_matches, sizeof ph->matches[0], lex_match_cmp);
    return any;
}

/* A category of artifacts named by a place or an activity ("kitchen equipment", "bathroom
 * fittings", "safety equipment", "refrigeration equipment"): WordNet's category word is narrower
 * than its everyday use (its equipment is no device, appliance or machine), and the modifier says
 * which things are meant: what "the M area" holds (a table region, an activity, the classes
 * named after M), raised in ph where that is more than the object reading found. Returns 1 when
 * the area brought in a class at the threshold. */
static int category_reading(const sp_lex_vocab *v, const lex_np *np, sp_lex_phrase *ph, sp_lex_result *res,
                            sp_error *err)
{
    /* the category of a collocation WordNet joins ("office_furniture") is its last word */
    const char *last = strrchr(np->head, '_');
    const char *cat = last ? last + 1 : np->head;
    if (np->placeholder || np->n_desc || !lex_is_category(cat)) return 0;
    if (!np->n_mods && !last) return bare_category(v, cat, ph);
    /* a category WordNet names has kinds of its own: its taxonomy stands where it finds one
     * ("kitchen appliance" -> the coffee maker, not the kitchen's sink) */
    if (last && !np->n_mods && best_of(ph) >= SP_LEX_THRESHOLD) return 0;
    lex_tokens ct = {0, {{0}}};
    for (int i = 0; i < np->n_mods; i++) snprintf(ct.w[ct.n++], LEX_WORD, "%s", np->mods[i]);
    char lead[WN_LEMMA_MAX];
    snprintf(lead, sizeof lead, "%.*s", last ? (int)(last - np->head) : 0, np->head);
    for (char *sv = NULL, *w = strtok_r(lead, "_", &sv); w && ct.n + 1 < LEX_MAX_TOKENS; w = strtok_r(NULL, "_", &sv))
        snprintf(ct.w[ct.n++], LEX_WORD, "%s", w);
    snprintf(ct.w[ct.n++], LEX_WORD, "area");
    sp_lex_phrase *sub = malloc(sizeof *sub);
    if (!sub) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    int rc = resolve(v, &ct, 0, ct.n, sub, res, 0, err), any = 0;
    for (int i = 0; !rc && sub->is_region && i < sub->n_matches; i++) {
        const sp_lex_class_match *m = &sub->matches[i];
        if (m->score < SP_LEX_THRESHOLD || !in_category(v, m->class_index, cat)) continue;
        for (int j = 0; j < ph->n_matches; j++)
            if (ph->matches[j].class_index == m->class_index && m->score > ph->matches[j].score) {
                ph->matches[j] = *m;
                ph->matches[j].kind = SP_LEX_HYPERNYM; /* the category names its members, not one class */
                snprintf(ph->matches[j].path, sizeof ph->matches[j].path, "%s: what the %s area holds", cat,
                         sub->region);
                any = 1;
            }
    }
    free(sub);
    if (rc) return rc;
    if (any) qsort(ph->matches, (size_t)ph->n_matches, sizeof ph->matches[0], lex_match_cmp);
    return any;
}

/* Moves m[i] to the front, the matches before it one place back (an order, the scores kept). */
static void match_to_front(sp_lex_class_match *m, int i)
{
    sp_lex_class_match x = m[i];
    memmove(&m[1], &m[0], sizeof x * (size_t)i);
    m[0] = x;
}

/* 1 when a sense of class ci is a room. */
static int class_is_room(const sp_lex_vocab *v, int ci)
{
    const lex_np *np = &v->classes[ci].np;
    for (int s = 0; s < np->n_senses; s++)
        if (lex_sense_room(&np->senses[s])) return 1;
    return 0;
}

/* Moves class ci to the front of region ph when it is a member at the threshold and the region
 * is found (its best member at the threshold); 0 when not. */
static int first_member(sp_lex_phrase *ph, int ci)
{
    if (best_of(ph) < SP_LEX_THRESHOLD) return 0;
    for (int i = 0; i < ph->n_matches; i++) {
        if (ph->matches[i].class_index != ci) continue;
        if (ph->matches[i].score < SP_LEX_THRESHOLD) return 0;
        if (ph->matches[i].score < ph->matches[0].score) ph->matches[i].score = ph->matches[0].score;
        match_to_front(ph->matches, i);
        return 1;
    }
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
    if (!rc && lex_everyday_name) lex_np_commonest(&np);
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
    if (!rc && !ph->is_region) rc = act_reading(v, &np, ph, res, depth, err);
    if (!rc && !ph->is_region && !named && depth == 0 && (rc = category_reading(v, &np, ph, res, err)) > 0) {
        for (int i = 0; i < np.n_mods; i++) use[i] = LEX_MOD_USED;
        rc = 0;
    }
    /* A bare area word ("the room", "the area", "a corner") names no object: WordNet's "area"
     * is a hypernym of lockers and cabinets (a compartment is a room), which no one means. */
    if (!rc && !ph->is_region && np.n_mods == 0 && !np.placeholder && lex_is_generic_region(np.head) &&
        !(ph->n_matches && ph->matches[0].kind == SP_LEX_EXACT))
        for (int i = 0; i < ph->n_matches; i++) ph->matches[i].score = 0;
    for (int i = 0; !rc && res && !ph->is_region && i < np.n_mods; i++)
        if (use[i] == LEX_MOD_IGNORED) add_ignored(res, np.mods[i]);
    lex_np_free(&np);
    return rc;
}


/* How strongly class ci belongs to the region ph (its membership score; 0 when none). */
static float membership(const sp_lex_phrase *region, int ci)
{
    for (int k = 0; k < region->n_matches; k++)
        if (region->matches[k].class_index == ci) return region->matches[k].score;
    return 0;
}

/* "the table in the dining room": among the target's matches, the classes that define the
 * anchor region come first; among members the target ties (the taxonomy finds "chair" in the
 * dining chair and the office chair alike), the one the region holds more strongly first ("the
 * chair in the office": the office chair, a member by name, 1.0, before the dining chair, a
 * member only as a kind of chair, 0.67); stable otherwise. */
static void prefer_members(sp_lex_phrase *target, const sp_lex_phrase *region)
{
    sp_lex_class_match in[SP_LEX_MAX_CLASSES], out[SP_LEX_MAX_CLASSES];
    float ms[SP_LEX_MAX_CLASSES];
    int ni = 0, no = 0;
    for (int i = 0; i < target->n_matches; i++) {
        const sp_lex_class_match *m = &target->matches[i];
        float r = membership(region, m->class_index);
        if (r >= SP_LEX_THRESHOLD && m->score >= SP_LEX_THRESHOLD) ms[ni] = r, in[ni++] = *m;
        else out[no++] = *m;
    }
    for (int i = 1; i < ni; i++) /* insertion sort: ties of the target by membership, stable */
        for (int j = i; j > 0 && in[j].score == in[j - 1].score && ms[j] > ms[j - 1]; j--) {
            sp_lex_class_match x = in[j];
            float y = ms[j];
            in[j] = in[j - 1], ms[j] = ms[j - 1];
            in[j - 1] = x, ms[j - 1] = y;
        }
    memcpy(target->matches, in, sizeof in[0] * (size_t)ni);
    memcpy(target->matches + ni, out, sizeof out[0] * (size_t)no);
}

/* "the toilet in the restroom": the region the target is in is known by its other things (the
 * sink, the hand dryer); when the target's class heads the region's members, the next member at
 * the threshold comes first (an order of the anchor's members; its extent is the same). */
static void other_member_first(sp_lex_phrase *region, const sp_lex_phrase *target)
{
    if (!region->n_matches || !target->n_matches || region->matches[0].class_index != target->matches[0].class_index)
        return;
    for (int i = 1; i < region->n_matches; i++) {
        if (region->matches[i].score < SP_LEX_THRESHOLD) return;
        if (region->matches[i].class_index == target->matches[0].class_index) continue;
        match_to_front(region->matches, i);
        return;
    }
}

/* 1 when class ci's name shares a word with class ai's name other than its last (its head). */
static int shares_modifier(const sp_lex_vocab *v, int ci, int ai)
{
    const lex_class *c = &v->classes[ci], *a = &v->classes[ai];
    for (int i = 0; i + 1 < c->n_tok; i++)
        for (int k = 0; k < a->n_tok; k++)
            if (!strcmp(c->tok[i], a->tok[k])) return 1;
    return 0;
}

/* "the chair at the teacher's desk": among the target's classes the taxonomy ties, one named
 * with a word of the anchor's name (the teacher chair) comes first: an order among equals, not
 * evidence (the grounding still ranks instances by where they stand). */
static void prefer_anchor_named(const sp_lex_vocab *v, sp_lex_phrase *target, const sp_lex_phrase *anchor)
{
    if (!anchor->n_matches || target->n_matches < 2) return;
    int ai = anchor->matches[0].class_index;
    sp_lex_class_match *m = target->matches;
    for (int i = 1; i < target->n_matches && m[i].score == m[0].score && m[i].kind == m[0].kind; i++)
        if (shares_modifier(v, m[i].class_index, ai) && !shares_modifier(v, m[0].class_index, ai)) {
            match_to_front(m, i);
            return;
        }
}

/* 1 when table region r lists class ci by its very name ("visitor chair" in the ward). */
static int region_lists(const sp_lex_vocab *v, const lex_region *r, int ci)
{
    const char *name = sp_lex_vocab_class(v, ci);
    for (int i = 0; i < r->n_members; i++)
        if (!strcasecmp(r->members[i], name)) return 1;
    return 0;
}

/* "the chair next to the bed": the target's classes the taxonomy ties (the visitor chair, the
 * waiting chair and the office chair are all chairs) are told apart by the company things keep:
 * one that a room of the region table lists by name together with the anchor (the ward lists
 * the patient bed and the visitor chair) comes first, when it is the only such one. An order
 * among equals, not evidence; the score is unchanged. By names only: a table entry is general
 * knowledge of which things stand together, read without WordNet, so it costs no resolution. */
static void prefer_company(const sp_lex_vocab *v, sp_lex_phrase *target, const sp_lex_phrase *anchor)
{
    if (!anchor->n_matches || target->n_matches < 2 || anchor->matches[0].score < SP_LEX_THRESHOLD) return;
    int ai = anchor->matches[0].class_index;
    sp_lex_class_match *m = target->matches;
    int nt = 1;
    while (nt < target->n_matches && m[nt].score == m[0].score) nt++;
    if (nt < 2) {
        /* "the chair at the desk": the bare class named first, a kind of it by name (the office
         * chair) that a room lists with the anchor is the one meant, when it is the only such */
        const char *top = sp_lex_vocab_class(v, m[0].class_index);
        if (strchr(top, ' ')) return;
        size_t nl = strlen(top);
        int found = -1, n_found = 0;
        for (int i = 1; i < target->n_matches && m[i].score >= SP_LEX_THRESHOLD; i++) {
            const char *nm = sp_lex_vocab_class(v, m[i].class_index);
            size_t n = strlen(nm);
            if (m[i].class_index == ai || n <= nl + 1 || nm[n - nl - 1] != ' ' || strcmp(nm + n - nl, top)) continue;
            int listed = 0;
            for (int r = 0; r < v->n_regions && !listed; r++)
                listed = region_lists(v, &v->regions[r], ai) && region_lists(v, &v->regions[r], m[i].class_index) &&
                         !region_lists(v, &v->regions[r], m[0].class_index);
            if (listed) found = i, n_found++;
        }
        /* or, listed nowhere, the one kind named with the anchor's word ("the chairs by the kids
         * table": the kids chair) */
        int named = -1, n_named = 0;
        for (int i = 1; n_found == 0 && i < target->n_matches && m[i].score >= SP_LEX_THRESHOLD; i++) {
            const char *nm = sp_lex_vocab_class(v, m[i].class_index);
            size_t n = strlen(nm);
            if (m[i].class_index == ai || n <= nl + 1 || nm[n - nl - 1] != ' ' || strcmp(nm + n - nl, top)) continue;
            if (shares_modifier(v, m[i].class_index, ai)) named = i, n_named++;
        }
        if (n_found == 0 && n_named == 1) found = named, n_found = 1;
        if (n_found == 1) match_to_front(m, found);
        return;
    }
    int with[SP_LEX_MAX_CLASSES] = {0}, n_with = 0, best = -1;
    for (int r = 0; r < v->n_regions; r++) {
        if (!region_lists(v, &v->regions[r], ai)) continue;
        for (int i = 0; i < nt; i++)
            if (m[i].class_index != ai && !with[i] && region_lists(v, &v->regions[r], m[i].class_index))
                with[i] = 1, n_with++, best = best < 0 ? i : best;
    }
    if (n_with == 1 && best > 0) match_to_front(m, best);
}

/* Where the anchor phrase starting at a begins: after a part of a place it names ("in the
 * MIDDLE OF the living room", "at the far END OF the hallway", "in the CORNER OF the bedroom"):
 * the thing is in that part of the anchor, so the anchor is what follows "of". */
static int anchor_start(const lex_tokens *t, int a)
{
    static const char *const parts[] = {"middle", "centre", "center", "end", "back", "rear", "front",
                                        "side", "corner", "edge", "top", "bottom", "far", "near",
                                        "left", "right", "other", "opposite", "half", NULL};
    int any = 0;
    for (int i = a; i < t->n - 1 && i < a + 5; i++) {
        if (!strcmp(t->w[i], "of")) return any ? i + 1 : a;
        int part = 0;
        for (int k = 0; parts[k] && !part; k++) part = !strcmp(t->w[i], parts[k]);
        if (part) any = 1;
        else if (lex_word_class_of(t->w[i]) != LW_FUNCTION) return a;
    }
    return a;
}

/* 1 when w is a verb's participle ("hanging", "parked", "hung", "left"): a verb form whose base
 * differs from it, not a third-person "-s" ("books" is no participle of "book"). */
static int participle(const sp_lex_vocab *v, const char *w)
{
    char b[WN_MAX_BASES][WN_LEMMA_MAX];
    sp_error err = {0};
    size_t n = strlen(w);
    if (n < 3 || w[n - 1] == 's' || lex_word_class_of(w) != LW_CONTENT) return 0;
    int nb = lex_bases(v->lx, WN_VERB, w, b, &err);
    for (int i = 0; i < nb; i++)
        if (strcmp(b[i], w)) return 1;
    return 0;
}

/* "between the sofa and the armchair": the two phrases around "and", each resolved, their
 * classes together the anchor (each class at its better score); unchanged when either half
 * finds nothing or names a region. */
static int between_pair(const sp_lex_vocab *v, const lex_tokens *t, int a, sp_lex_result *trial, int ignored,
                        sp_error *err)
{
    int j = a;
    while (j < t->n && strcmp(t->w[j], "and")) j++;
    if (j == a || j + 1 >= t->n) return 0;
    sp_lex_phrase *x = malloc(sizeof *x), *y = malloc(sizeof *y);
    int rc = x && y ? 0 : sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    /* the whole phrase read "sofa" as an ignored modifier of "armchair": the halves report
     * their own words when they are the anchor, the whole phrase's stand otherwise */
    int had = trial->n_ignored;
    char saved[SP_LEX_MAX_IGNORED][sizeof trial->ignored[0]];
    memcpy(saved, trial->ignored, sizeof saved);
    trial->n_ignored = ignored;
    if (!rc) rc = resolve(v, t, a, j, x, trial, 0, err);
    if (!rc) rc = resolve(v, t, j + 1, t->n, y, trial, 0, err);
    int merged = 0;
    if (!rc && best_of(x) >= SP_LEX_THRESHOLD && best_of(y) >= SP_LEX_THRESHOLD && !x->is_region && !y->is_region) {
        for (int i = 0; i < y->n_matches; i++)
            for (int k = 0; k < x->n_matches; k++)
                if (x->matches[k].class_index == y->matches[i].class_index && y->matches[i].score > x->matches[k].score)
                    x->matches[k] = y->matches[i];
        qsort(x->matches, (size_t)x->n_matches, sizeof x->matches[0], lex_match_cmp);
        join_words(t, a, t->n, x->text, sizeof x->text);
        trial->anchor = *x;
        merged = 1;
    }
    if (!merged) {
        trial->n_ignored = had;
        memcpy(trial->ignored, saved, sizeof saved);
    }
    free(x);
    free(y);
    return rc;
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

/* A query that is a "where" clause whose subject names things ("where the car is parked",
 * "where the bins are") names the place of that subject: it reads as "the place where ...", a
 * region of the objects it names. A question ("where is the car", "where can I sit"), a purpose
 * ("where to store my shoes") or a person's doing ("where I can cook", "where we keep the
 * tools": a thing to cook on, to keep them in) describes a thing and is left as it is. */
static int where_clause(lex_tokens *t)
{
    static const char *const aux[] = {"to", "is", "are", "was", "were", "can", "could", "do", "does",
                                      "did", "should", "would", "will", "shall", "may", "might", "must",
                                      "i", "we", "you", "one", "someone", "somebody", "people", "they",
                                      "he", "she", NULL};
    if (t->n < 3 || t->n >= LEX_MAX_TOKENS || strcmp(t->w[0], "where")) return 0;
    for (int i = 0; aux[i]; i++)
        if (!strcmp(t->w[1], aux[i])) return 0;
    memmove(t->w[1], t->w[0], sizeof t->w[0] * (size_t)t->n);
    snprintf(t->w[0], LEX_WORD, "place");
    t->n++;
    return 1;
}

/* 1 when w's commonest noun sense is a person ("teacher", "kids", "pupil"). */
static int names_person(const sp_lex_vocab *v, const char *w, sp_error *err)
{
    lex_tokens one = {1, {{0}}};
    snprintf(one.w[0], LEX_WORD, "%s", w);
    lex_np np;
    int rc = lex_np_parse(v->lx, &one, 0, 1, 0, &np, err);
    int person = !rc && np.n_senses > 0 && np.senses[0].rank == 1 && lex_sense_person(&np.senses[0]);
    lex_np_free(&np);
    return rc < 0 ? rc : person;
}

static int named_after(const sp_lex_vocab *v, const sp_lex_class_match *m, const char *w)
{
    const lex_class *c = &v->classes[m->class_index];
    for (int k = 0; k < c->n_tok; k++)
        if (!strcmp(c->tok[k], w)) return 1;
    return 0;
}

/* A way in a direction names the passage that goes there: "the way out", "how do I get
 * outside" -> the exit; "the way upstairs", "get back up to the kitchen" -> the stairs; "the way
 * in" -> the entrance. A closed list of direction words, after "way" or a verb of going ("get",
 * "go", "back" between); the words that follow stay ("the way out to the street" is the exit
 * to the street). */
void lex_way_direction(lex_tokens *t)
{
    static const char *const dirs[][2] = {{"out", "exit"},          {"outside", "exit"},   {"outdoors", "exit"},
                                          {"in", "entrance"},       {"inside", "entrance"}, {"indoors", "entrance"},
                                          {"up", "stairs"},         {"upstairs", "stairs"}, {"down", "stairs"},
                                          {"downstairs", "stairs"}};
    for (int i = 0; i + 1 < t->n; i++) {
        if (strcmp(t->w[i], "way") && strcmp(t->w[i], "get") && strcmp(t->w[i], "go")) continue;
        int j = i + 1;
        if (j + 1 < t->n && !strcmp(t->w[j], "back")) j++;
        for (size_t k = 0; k < sizeof dirs / sizeof dirs[0]; k++) {
            if (strcmp(t->w[j], dirs[k][0])) continue;
            /* "get in the car", "go up the stairs": a direction followed by what it enters is a
             * preposition with its object, not where the way leads (only "to", "of", "into" or the
             * end may follow) */
            if (j + 1 < t->n && strcmp(t->w[j + 1], "to") && strcmp(t->w[j + 1], "of") && strcmp(t->w[j + 1], "into"))
                break;
            snprintf(t->w[i], LEX_WORD, "%s", dirs[k][1]);
            memmove(t->w[i + 1], t->w[j + 1], sizeof t->w[0] * (size_t)(t->n - j - 1));
            t->n -= j - i;
            return;
        }
    }
}

/* Among equals, classes named after w first (stable otherwise). */
static void prefer_named_after(const sp_lex_vocab *v, sp_lex_phrase *ph, const char *w)
{
    sp_lex_class_match *m = ph->matches;
    for (int i = 1; i < ph->n_matches; i++)
        for (int j = i; j > 0 && m[j].score == m[j - 1].score && named_after(v, &m[j], w) && !named_after(v, &m[j - 1], w);
             j--) {
            sp_lex_class_match x = m[j];
            m[j] = m[j - 1], m[j - 1] = x;
        }
}

/* The -ing form of a verb base: "read" -> reading, "write" -> writing, "lie" -> lying, "sit" ->
 * sitting (a short consonant-vowel-consonant base doubles its last letter), "see" -> seeing; only
 * used to look a name up in the region table, where a wrong form finds nothing. */
static void gerund(const char *base, char *out, size_t cap)
{
    size_t n = strlen(base);
    const char *vowels = "aeiou";
    if (n > 2 && base[n - 1] == 'e' && base[n - 2] == 'i') snprintf(out, cap, "%.*sying", (int)(n - 2), base);
    else if (n > 2 && base[n - 1] == 'e' && base[n - 2] != 'e') snprintf(out, cap, "%.*sing", (int)(n - 1), base);
    else if (n >= 3 && n <= 4 && !strchr(vowels, base[n - 1]) && !strchr("wxy", base[n - 1]) &&
             strchr(vowels, base[n - 2]) && !strchr(vowels, base[n - 3]))
        snprintf(out, cap, "%s%cing", base, base[n - 1]);
    else snprintf(out, cap, "%sing", base);
}

/* The other reading of a "where" clause with a subject, when the place of its subject finds
 * nothing: a description of the thing where it happens. "where the books are kept" is somewhere
 * books are kept (the bookshelf: "a shelf on which to keep books"), "where the fish live"
 * somewhere fish live. A person doing it is anyone ("where the children hang their coats" is
 * where one hangs coats, as "where I can cook" is), and a class named after that person ("where
 * the teacher sits": the teacher chair) comes first among equals (an order, not evidence).
 * raw: the clause as tokenized. */
static int where_description(const sp_lex_vocab *v, const lex_tokens *raw, sp_lex_result *res, sp_error *err)
{
    lex_tokens t;
    int rc = lex_merge_collocations(v->lx, raw, &t, err);
    if (rc) return rc;
    int s = 1;
    while (s < t.n && lex_word_class_of(t.w[s]) == LW_FUNCTION) s++;
    if (s >= t.n - 1 || lex_word_class_of(t.w[s]) != LW_CONTENT) return 0;
    int person = names_person(v, t.w[s], err);
    if (person < 0) return person;
    char subject[WN_MAX_BASES][WN_LEMMA_MAX];
    int nb = lex_bases(v->lx, WN_NOUN, t.w[s], subject, err);
    if (nb < 0) return nb;
    if (person) { /* drop the person: "where I hang their coats" */
        memmove(t.w[s], t.w[s + 1], sizeof t.w[0] * (size_t)(t.n - s - 1));
        t.n--;
    }
    sp_lex_result *d = malloc(sizeof *d);
    if (!d) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    memset(d, 0, sizeof *d);
    snprintf(d->text, sizeof d->text, "%s", res->text);
    /* what a person does somewhere names an area first when the region table knows it: "where
     * the kids read" is the reading area, "where people wait" the waiting room (a region when
     * the scene shows one) */
    char vb[WN_MAX_BASES][WN_LEMMA_MAX];
    int nv = person && s < t.n ? lex_bases(v->lx, WN_VERB, t.w[s], vb, err) : 0;
    if (nv < 0) rc = nv;
    lex_tokens area = {3, {"the", "", "area"}};
    if (nv > 0) gerund(vb[0], area.w[1], LEX_WORD);
    if (nv > 0 && !lex_region_find_stem(v, area.w[1])) snprintf(area.w[1], LEX_WORD, "%s", vb[0]); /* "work area" */
    if (nv > 0 && lex_region_find_stem(v, area.w[1])) { /* a place the region table knows */
        if (!(rc = resolve(v, &area, 0, area.n, &d->target, d, 0, err)) && d->target.is_region &&
            best_of(&d->target) >= SP_LEX_THRESHOLD) {
            if (nb > 0) prefer_named_after(v, &d->target, subject[0]);
            *res = *d;
            free(d);
            return 0;
        }
        memset(d, 0, sizeof *d);
        snprintf(d->text, sizeof d->text, "%s", res->text);
    }
    if (!rc && !(rc = resolve(v, &t, 0, t.n, &d->target, d, 0, err)) && !d->target.is_region &&
        best_of(&d->target) > best_of(&res->target)) {
        if (person && nb > 0) prefer_named_after(v, &d->target, subject[0]);
        *res = *d;
    }
    free(d);
    return rc;
}

/* A class whose very name is a place of the region table ("nurses station", "charging
 * station") is met by that name as the place it is: the query reads as the region, the class
 * itself its first member (its name holds the region's), so "the nurses' station" is the
 * station's area with its desk and computer, found by the station first. */
static int named_place(const sp_lex_vocab *v, sp_lex_phrase *ph, sp_error *err)
{
    if (ph->is_region || !ph->n_matches || ph->matches[0].kind != SP_LEX_EXACT ||
        ph->matches[0].score < SP_LEX_THRESHOLD)
        return 0;
    int ci = ph->matches[0].class_index;
    const lex_region *r = lex_region_find(v, sp_lex_vocab_class(v, ci));
    if (!r) return 0;
    sp_lex_phrase *reg = malloc(sizeof *reg);
    if (!reg) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    *reg = *ph;
    int rc = lex_region_members(v, r, r->name, NULL, reg, err);
    if (!rc && reg->n_matches && reg->matches[0].class_index == ci) {
        reg->is_region = 1;
        snprintf(reg->head, sizeof reg->head, "%s", r->name);
        *ph = *reg;
    }
    free(reg);
    return rc;
}

/* A bare word whose commonest sense is a room that the region table knows, met by a class
 * through another sense ("the toilets": WordNet's first toilet is the room, a bathroom; the
 * class is the fixture), is the room: its region, that class first among its members, when the
 * scene shows it (the class a member at the threshold). A modifier keeps the thing ("the white
 * toilet"), and so does a relation ("the toilet near the bath"), and the class's own name. */
static int room_reading(const sp_lex_vocab *v, const lex_tokens *t, sp_lex_result *res, sp_error *err)
{
    sp_lex_phrase *ph = &res->target;
    if (ph->is_region || !ph->n_matches || ph->matches[0].score < SP_LEX_THRESHOLD ||
        (ph->matches[0].kind != SP_LEX_EXACT && ph->matches[0].kind != SP_LEX_SYNONYM) ||
        class_is_room(v, ph->matches[0].class_index))
        return 0;
    /* the class's own name as written, singular ("toilet", "the toilet"), is the thing: the
     * robot is sent to it, not to the middle of its room */
    const char *last = strrchr(res->text, ' ');
    last = last ? last + 1 : res->text;
    if (!strcasecmp(last, sp_lex_vocab_class(v, ph->matches[0].class_index))) return 0;
    lex_np np;
    int rc = lex_np_parse(v->lx, t, 0, t->n, 0, &np, err);
    const lex_region *r = NULL;
    /* whose room it is does not make it a thing: "the men's toilets", "the ladies' loos" */
    int persons = !rc && np.n_mods > 0;
    for (int i = 0; persons && i < np.n_mods; i++) {
        char b[WN_MAX_BASES][WN_LEMMA_MAX]; /* by any base: "men" is also WordNet's troops */
        int nb = lex_bases(v->lx, WN_NOUN, np.mods[i], b, err), p = 0;
        if (nb < 0) rc = nb;
        for (int k = 0; k < nb && !p && !rc; k++)
            if ((p = names_person(v, b[k], err)) < 0) rc = p;
        persons = p > 0;
    }
    if (!rc && !np.placeholder && (!np.n_mods || persons) && !np.n_desc && np.n_senses > 0 && np.senses[0].rank == 1 &&
        lex_sense_room(&np.senses[0]) && (rc = lex_region_named(v, &np, &r, err)) >= 0 && r) {
        rc = 0;
        sp_lex_phrase *reg = malloc(sizeof *reg);
        int is_region = 0;
        if (!reg) rc = sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
        else {
            *reg = *ph;
            rc = resolve_region(v, &np, t, reg, res, 0, &is_region, err);
            if (!rc && is_region && first_member(reg, ph->matches[0].class_index)) *ph = *reg;
            free(reg);
        }
    }
    lex_np_free(&np);
    return rc < 0 ? rc : 0;
}

int lex_match_reading(const sp_lex_vocab *v, const char *text, const lex_tokens *raw,
                      sp_lex_result *res, sp_error *err)
{
    memset(res, 0, sizeof *res);
    snprintf(res->text, sizeof res->text, "%s", text);
    lex_tokens t;
    int rc = lex_merge_collocations(v->lx, raw, &t, err);
    if (rc) return rc;
    int where = where_clause(&t);
    /* "the far end of the hallway", "the top of the bookshelf": a part of a place or a thing is
     * found where that place or thing is */
    int skip = anchor_start(&t, 0);
    if (skip > 0) {
        memmove(t.w[0], t.w[skip], sizeof t.w[0] * (size_t)(t.n - skip));
        t.n -= skip;
    }
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
        /* "area with appliances" is one region; "the nurses station next to the door" is two */
        if (lex_is_generic_region(t.w[i - 1]) && lex_is_region_link(t.w[i])) continue;
        memset(trial, 0, sizeof *trial);
        if ((rc = resolve(v, &t, 0, i, &trial->target, trial, 0, err))) break;
        /* "the painting HANGING above the couch", "the car PARKED in front of ...": a reduced
         * relative clause; its participles are dropped when the target does not match with them */
        for (int te = i; best_of(&trial->target) < SP_LEX_THRESHOLD && te > 1 && participle(v, t.w[te - 1]);) {
            memset(trial, 0, sizeof *trial);
            if ((rc = resolve(v, &t, 0, --te, &trial->target, trial, 0, err))) break;
        }
        if (rc) break;
        if (best_of(&trial->target) < SP_LEX_THRESHOLD || trial->target.is_region) continue;
        int ignored = trial->n_ignored;
        if ((rc = resolve(v, &t, anchor_start(&t, i + k), t.n, &trial->anchor, trial, 0, err))) break;
        if (!strcmp(name, "between") && (rc = between_pair(v, &t, anchor_start(&t, i + k), trial, ignored, err))) break;
        if (best_of(&trial->anchor) < SP_LEX_THRESHOLD) continue;
        snprintf(trial->text, sizeof trial->text, "%s", text);
        snprintf(trial->relation, sizeof trial->relation, "%s", name);
        if (trial->anchor.is_region) {
            prefer_members(&trial->target, &trial->anchor);
            /* a target the region does not hold is told apart by the company of the region's
             * first thing ("the chair in the patient room": the ward lists the patient bed and
             * the visitor chair) */
            if (trial->target.n_matches && membership(&trial->anchor, trial->target.matches[0].class_index) < SP_LEX_THRESHOLD)
                prefer_company(v, &trial->target, &trial->anchor);
            other_member_first(&trial->anchor, &trial->target);
        }
        else {
            prefer_anchor_named(v, &trial->target, &trial->anchor);
            prefer_company(v, &trial->target, &trial->anchor);
        }
        *res = *trial;
        split = 1;
    }
    free(trial);
    if (!rc && !split) rc = resolve(v, &t, 0, t.n, &res->target, res, 0, err);
    if (!rc && !split) rc = named_place(v, &res->target, err);
    if (!rc && !split && !where) rc = room_reading(v, &t, res, err);
    if (!rc && where && !split && best_of(&res->target) < SP_LEX_THRESHOLD) rc = where_description(v, raw, res, err);
    if (rc) return rc;
    res->confidence = best_of(&res->target);
    res->found = res->confidence >= SP_LEX_THRESHOLD;
    return 0;
}
