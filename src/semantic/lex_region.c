/* Regions for the lexical text encoder: the region table (data/semantic/regions.json), and the
 * classes that define a region: the table's object phrases, the nouns of the region's WordNet
 * definition, classes named after it, the classes doing what its name says is done there. Table
 * regions are resolved once, on first use. */
#include <cjson/cJSON.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lexical.h"
#include "semsplat/io.h"

_Thread_local int lex_everyday_name;

/* The general tables (the region table's members, the activity table's things) name things by
 * everyday words, in their commonest sense when that is an attested artifact: their "bench" is
 * the seat, not WordNet's later workbench. Keeps only the first senses of a one-word head. */
void lex_np_commonest(lex_np *np)
{
    if (np->n_mods || strchr(np->head, '_') || np->n_senses < 2 || np->senses[0].rank != 1 ||
        !np->senses[0].attested || !lex_sense_artifact(&np->senses[0]))
        return;
    int k = 1;
    for (int i = 1; i < np->n_senses; i++)
        if (np->senses[i].rank == 1) np->senses[k++] = np->senses[i];
    np->n_senses = k;
}

/* Scores text (an object phrase) into ph; the region resolution's building block. A member
 * phrase names a particular kind ("tool rack", "drying rack", "kitchen cabinet"): when its best
 * class matches only with a modifier ignored (the TV stand is a rack, but no tool rack), the
 * scene lacks that kind and the phrase supports nothing (two such phrases made a storage room
 * or a laundry of any TV stand and trash can). */
static int score_tokens(const sp_lex_vocab *v, const lex_tokens *t, sp_lex_phrase *ph, int member, sp_error *err)
{
    lex_np np;
    int use[8] = {0};
    int rc = lex_np_parse(v->lx, t, 0, t->n, 0, &np, err);
    if (!rc && member) lex_np_commonest(&np);
    if (!rc) rc = lex_score_np(v, &np, ph, use, err);
    for (int i = 0; !rc && i < np.n_mods && i < 8; i++)
        if (use[i] == LEX_MOD_IGNORED) ph->n_matches = 0;
    /* a member names an object: with no noun for a head it is no description to match against
     * every definition ("shelving unit" without the alias table is the verb shelve) */
    if (!rc && member && (!np.head[0] || np.placeholder)) ph->n_matches = 0;
    lex_np_free(&np);
    return rc;
}

/* ... a member of the region table read as a query is: as written and through the alias table
 * ("shelving" = shelf), each class at its best reading, never as a description. */
static int score_text_as(const sp_lex_vocab *v, const char *text, sp_lex_phrase *ph, int member, sp_error *err)
{
    lex_tokens raw, t;
    lex_tokenize(text, &raw);
    int rc = lex_merge_collocations(v->lx, &raw, &t, err);
    if (!rc) rc = score_tokens(v, &t, ph, member, err);
    sp_lex_phrase *alt = NULL;
    for (int k = 0; member && k < 3 && !rc; k++) {
        lex_tokens a;
        if (lex_alias_rewrite(v, &t, k, &a, NULL, 0) == 0) break;
        if (!alt && !(alt = malloc(sizeof *alt))) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
        if ((rc = score_tokens(v, &a, alt, member, err))) break;
        for (int i = 0; i < alt->n_matches; i++) {
            int found = 0;
            for (int j = 0; j < ph->n_matches && !found; j++)
                if (ph->matches[j].class_index == alt->matches[i].class_index) {
                    found = 1;
                    if (alt->matches[i].score > ph->matches[j].score) ph->matches[j] = alt->matches[i];
                }
            if (!found && ph->n_matches < SP_LEX_MAX_CLASSES) ph->matches[ph->n_matches++] = alt->matches[i];
        }
        qsort(ph->matches, (size_t)ph->n_matches, sizeof ph->matches[0], lex_match_cmp);
    }
    free(alt);
    return rc;
}

static int score_text(const sp_lex_vocab *v, const char *text, sp_lex_phrase *ph, sp_error *err)
{
    return score_text_as(v, text, ph, 0, err);
}

/* Raises the membership of every class matching ph at or above the threshold (region->matches
 * indexed by class, unsorted); returns 1 when ph supports the region (some class matched). */
int lex_region_absorb(sp_lex_phrase *region, const sp_lex_phrase *ph, const char *why)
{
    int any = 0;
    for (int i = 0; i < ph->n_matches; i++) {
        const sp_lex_class_match *m = &ph->matches[i];
        if (m->score < SP_LEX_THRESHOLD) continue;
        any = 1;
        sp_lex_class_match *r = &region->matches[m->class_index]; /* indexed by class until sorted */
        if (m->score <= r->score) continue;
        *r = *m; /* keeps how the member phrase matched: exact members rank before gloss ones */
        snprintf(r->path, sizeof r->path, "%s: '%s' (%s)", why, ph->text, sp_lex_kind_name(m->kind));
    }
    return any;
}


/* The genus of a definition into *genus: the last noun of its first run of content words ("a
 * BOOTH for taking a shower", "a small STOREROOM for storing foods"), what the place is, not what
 * stands in it (-1 when none). Returns 0 or a negative SP_E_* code. */
static int definition_genus(const lex_db *lx, const lex_tokens *t, int *genus, sp_error *err)
{
    *genus = -1;
    for (int i = 0; i < t->n; i++) {
        int cls = lex_word_class_of(t->w[i]);
        if (cls == LW_FUNCTION && *genus < 0) continue; /* "a", "an" before it */
        if (cls != LW_CONTENT) break;
        char b[WN_MAX_BASES][WN_LEMMA_MAX];
        int nb = lex_bases(lx, WN_NOUN, t->w[i], b, err);
        if (nb < 0) return nb;
        if (nb > 0) *genus = i;
    }
    return 0;
}

/* The surfaces every room has ("a small area set off by WALLS", "the FLOOR of a hall"): they
 * define no room, so a definition naming them adds no member. */
int lex_building_surface(const char *base)
{
    return !strcmp(base, "wall") || !strcmp(base, "floor") || !strcmp(base, "ceiling");
}

/* Members of a named region: the table's phrases and the nouns of its WordNet definition;
 * *support counts the phrases that found a class. */
static int region_members(const sp_lex_vocab *v, const lex_region *r, const char *definition,
                          sp_lex_phrase *out, int *support, int *first, sp_error *err)
{
    *first = -1;
    sp_lex_phrase *ph = malloc(sizeof *ph);
    if (!ph) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    int rc = 0;
    for (int i = 0; r && i < r->n_members && !rc; i++) {
        snprintf(ph->text, sizeof ph->text, "%s", r->members[i]);
        if ((rc = score_text_as(v, r->members[i], ph, 1, err))) break;
        /* the class the table's first member names exactly: the place's defining object */
        if (i == 0 && ph->n_matches && ph->matches[0].score >= SP_LEX_THRESHOLD && ph->matches[0].kind == SP_LEX_EXACT &&
            (ph->n_matches < 2 || ph->matches[1].score < ph->matches[0].score))
            *first = ph->matches[0].class_index;
        /* the table lists a place's defining objects first (the entrance: its door before the
         * coat rack): among members that match equally, the earlier comes first (LEX_TIE, an
         * order, not evidence) */
        for (int k = 0; k < ph->n_matches; k++)
            if (ph->matches[k].score >= SP_LEX_THRESHOLD + LEX_TIE)
                ph->matches[k].score -= LEX_TIE * (float)i / (float)r->n_members;
        *support += lex_region_absorb(out, ph, "region table");
    }
    /* The nouns of the region's definition, as object phrases (bathroom: "a room ... containing
     * a bathtub or shower and usually a washbasin and toilet"). Its verbs are not used: "used",
     * "containing" are in thousands of definitions. */
    lex_tokens t = {0, {{0}}};
    if (definition) lex_tokenize(definition, &t);
    int genus = -1;
    rc = definition_genus(v->lx, &t, &genus, err);
    for (int i = 0; i < t.n && !rc; i++) {
        if (i == genus) continue;
        const char *w = t.w[i];
        char base[WN_MAX_BASES][WN_LEMMA_MAX];
        int nb = lex_bases(v->lx, WN_NOUN, w, base, err);
        if (nb < 0) rc = nb;
        if (rc || nb == 0 || lex_word_class_of(w) != LW_CONTENT || lex_is_generic_region(base[0]) ||
            lex_building_surface(base[0]))
            continue;
        snprintf(ph->text, sizeof ph->text, "%s", w);
        if ((rc = score_text(v, w, ph, err))) break;
        /* a part the definition names is not what stands there ("a storage compartment ... has
         * a LOCK": no door) */
        for (int k = 0; k < ph->n_matches; k++)
            if (ph->matches[k].kind == SP_LEX_PART) ph->matches[k].score = 0;
        /* and after the table's members that match equally (the bathroom's toilet, first in
         * the table, before the shower its definition names): an order, not evidence */
        for (int k = 0; r && k < ph->n_matches; k++)
            if (ph->matches[k].score >= SP_LEX_THRESHOLD + LEX_TIE) ph->matches[k].score -= LEX_TIE;
        *support += lex_region_absorb(out, ph, "WordNet definition");
    }
    free(ph);
    return rc;
}


#define ROOM 4105893u      /* room.n.01 */
#define AREA 2735688u      /* area.n.05: a part of a structure having some specific function */
#define WORKPLACE 4602044u
#define FURNITURE 3405725u /* furniture.n.01 */
#define CONTAINER 3094503u /* container.n.01 */ /* workplace.n.01: a place where work is done (workshop, laboratory) */

int lex_region_for(const sp_lex_vocab *v, const lex_tokens *words, sp_lex_phrase *region, sp_error *err)
{
    char text[sizeof region->text] = "something for";
    int n = 0;
    for (int i = 0; i < words->n; i++) {
        if (lex_is_generic_region(words->w[i])) continue;
        strncat(text, " ", sizeof text - strlen(text) - 1);
        strncat(text, words->w[i], sizeof text - strlen(text) - 1);
        n++;
    }
    if (!n) return 0;
    sp_lex_phrase *ph = malloc(sizeof *ph);
    if (!ph) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    snprintf(ph->text, sizeof ph->text, "%s", text);
    int rc = score_text(v, text, ph, err);
    if (!rc) rc = lex_region_absorb(region, ph, "what the area is for");
    free(ph);
    return rc;
}

/* 1 when the sense is a place one can be in: a room or a workplace, and for a name of the
 * region table also a part of a structure with a function (a showroom; not for any word: a
 * fireplace, a recess in a wall, is such an area too). A building as a whole is none: a shed or
 * a garage is also a thing seen from outside. */
static int place_sense(const lex_sense *s, int table_entry)
{
    return lex_anc_find(s, ROOM) > 0 || lex_anc_find(s, WORKPLACE) > 0 || (table_entry && lex_anc_find(s, AREA) > 0);
}

/* The verbs an activity word names: the word is a form of the verb ("cooking" -> cook, "parking"
 * -> park), else the verbs WordNet derives from this very word in its commonest noun sense ("+":
 * storage -> store). A word that is itself a verb's base names a thing as often as an act ("the
 * back room", "the work area": "something to back" is a chair), so it names none. */
int lex_activity_verbs(const lex_db *lx, const char *w, char out[][WN_LEMMA_MAX], int cap, sp_error *err)
{
    char vb[WN_MAX_BASES][WN_LEMMA_MAX];
    int nb0 = lex_bases(lx, WN_VERB, w, vb, err), n = 0;
    if (nb0 < 0) return nb0;
    for (int i = 0; i < nb0; i++)
        if (!strcmp(vb[i], w)) nb0 = 0; /* the word is a verb base itself */
    for (int i = 0; i < nb0 && n < cap; i++) snprintf(out[n++], WN_LEMMA_MAX, "%s", vb[i]);
    if (n != 0 || lex_bases(lx, WN_VERB, w, vb, err) > 0) return n;
    uint32_t offs[WN_MAX_SENSES];
    char b[WN_MAX_BASES][WN_LEMMA_MAX];
    int nb = lex_bases(lx, WN_NOUN, w, b, err);
    int ns = nb > 0 ? wn_lookup(lx->db, WN_NOUN, b[0], offs, WN_MAX_SENSES, NULL, err) : nb;
    if (ns <= 0) return ns;
    wn_synset syn;
    int rc = wn_read(lx->db, (wn_id){offs[0], WN_NOUN}, &syn, err);
    if (rc) return rc;
    int self = 0; /* the word's number in its synset */
    for (int k = 0; k < syn.n_words; k++)
        if (!strcmp(syn.words[k], b[0])) self = k + 1;
    for (int p = 0; p < syn.n_pointers && !rc && n < cap; p++) {
        const wn_pointer *pt = &syn.pointers[p];
        if (strcmp(pt->symbol, "+") || pt->target.pos != WN_VERB || (pt->source_word && pt->source_word != self))
            continue;
        wn_synset vs;
        if ((rc = wn_read(lx->db, pt->target, &vs, err))) break;
        int k = pt->target_word ? pt->target_word - 1 : 0;
        int dup = 0;
        for (int j = 0; j < n; j++) dup |= !strcmp(out[j], vs.words[k]);
        if (k < vs.n_words && !dup && !strchr(vs.words[k], '_') && strcmp(vs.words[k], w))
            snprintf(out[n++], WN_LEMMA_MAX, "%s", vs.words[k]);
        wn_synset_free(&vs);
    }
    wn_synset_free(&syn);
    return rc ? rc : n;
}

int lex_region_activity(const sp_lex_vocab *v, const lex_tokens *words, sp_lex_phrase *region, sp_error *err)
{
    sp_lex_phrase *ph = malloc(sizeof *ph);
    if (!ph) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    int rc = 0, any = 0;
    for (int i = 0; i < words->n && !rc; i++) {
        if (lex_word_class_of(words->w[i]) != LW_CONTENT || lex_is_generic_region(words->w[i])) continue;
        char verbs[4][WN_LEMMA_MAX];
        int nv = lex_activity_verbs(v->lx, words->w[i], verbs, 4, err);
        if (nv < 0) rc = nv;
        for (int k = 0; k < nv && !rc; k++) {
            /* the things one does it with: "something to store" */
            char text[2 * WN_LEMMA_MAX];
            snprintf(text, sizeof text, "something to %s", verbs[k]);
            snprintf(ph->text, sizeof ph->text, "%s", text);
            char why[96];
            snprintf(why, sizeof why, "what one does there ('%s': %s)", words->w[i], verbs[k]);
            if (!(rc = score_text(v, text, ph, err))) any |= lex_region_absorb(region, ph, why);
        }
    }
    free(ph);
    return rc ? rc : any;
}

/* The table region a head stands for: its own name or a synonym's ("hall" -> hallway). */
int lex_region_named(const sp_lex_vocab *v, const lex_np *np, const lex_region **r,
                             sp_error *err)
{
    *r = NULL;
    /* A table name WordNet does not join ("meeting room", "break room"): the head with its last
     * modifiers, longest first ("the big meeting room" -> "meeting room"), before the head alone
     * ("the booking office" is the table's booking office, not any office). */
    int n_mods = np->n_mods - np->split;
    for (int from = 0; !*r && np->head[0] && from < n_mods; from++) {
        char name[64] = "";
        for (int i = from; i < n_mods; i++) {
            strncat(name, np->mods[i], sizeof name - strlen(name) - 1);
            strncat(name, " ", sizeof name - strlen(name) - 1);
        }
        strncat(name, np->head, sizeof name - strlen(name) - 1);
        *r = lex_region_find(v, name);
    }
    if (!*r) *r = lex_region_find(v, np->head);
    /* a plural WordNet keeps as a lemma of its own ("rooms", an apartment): the table's name is
     * by the singular ("the consulting rooms" -> "consulting room") */
    char hb[WN_MAX_BASES][WN_LEMMA_MAX];
    int nhb = !*r && np->head[0] && n_mods > 0 ? lex_bases(v->lx, WN_NOUN, np->head, hb, err) : 0;
    if (nhb < 0) return nhb;
    for (int b = 0; b < nhb && !*r; b++) {
        if (!strcmp(hb[b], np->head)) continue;
        for (int from = 0; !*r && from < n_mods; from++) {
            char name[64] = "";
            for (int i = from; i < n_mods; i++) {
                strncat(name, np->mods[i], sizeof name - strlen(name) - 1);
                strncat(name, " ", sizeof name - strlen(name) - 1);
            }
            strncat(name, hb[b], sizeof name - strlen(name) - 1);
            *r = lex_region_find(v, name);
        }
    }
    /* The kind of area is a word of style: "the utility corner" is the table's "utility room",
     * "the work space" its "work area" (only after a generic head: a "locker" is no locker room). */
    if (!*r && lex_is_generic_region(np->head)) {
        char stem[64] = "";
        for (int i = 0; i < n_mods; i++) {
            strncat(stem, i ? " " : "", sizeof stem - strlen(stem) - 1);
            strncat(stem, np->mods[i], sizeof stem - strlen(stem) - 1);
        }
        if (stem[0]) *r = lex_region_find_stem(v, stem);
        /* or a WordNet room of that name whose synonym the table holds ("the sitting area":
         * WordNet's sitting room is a living room) */
        static const char *const kinds[] = {"room", "area", NULL};
        for (int g = 0; !*r && stem[0] && kinds[g]; g++) {
            char coll[WN_LEMMA_MAX];
            snprintf(coll, sizeof coll, "%s_%s", stem, kinds[g]);
            for (char *p = coll; *p; p++)
                if (*p == ' ') *p = '_';
            uint32_t off;
            int n = wn_lookup(v->lx->db, WN_NOUN, coll, &off, 1, NULL, err);
            if (n < 0) return n;
            wn_synset syn;
            if (n == 0 || (n = wn_read(v->lx->db, (wn_id){off, WN_NOUN}, &syn, err))) {
                if (n < 0) return n;
                continue;
            }
            for (int k = 0; k < syn.n_words && !*r; k++) *r = lex_region_find(v, syn.words[k]);
            wn_synset_free(&syn);
            if (*r) return 1;
        }
    }
    const char *last = strrchr(np->head, '_'); /* a WordNet collocation: "parking_area" */
    if (!*r && last && lex_is_generic_region(last + 1)) {
        char stem[64];
        snprintf(stem, sizeof stem, "%.*s", (int)(last - np->head), np->head);
        *r = lex_region_find_stem(v, stem);
    }
    for (int s = 0; !*r && s < np->n_senses && s < 3; s++) {
        /* a synonym by a sense that is no physical thing names no place ("post", a job, is
         * an "office") */
        if (!lex_sense_physical(&np->senses[s])) continue;
        wn_synset syn;
        wn_id id = {np->senses[s].off, WN_NOUN};
        int rc = wn_read(v->lx->db, id, &syn, err);
        if (rc) return rc;
        for (int k = 0; k < syn.n_words && !*r; k++) *r = lex_region_find(v, syn.words[k]);
        wn_synset_free(&syn);
    }
    /* A place whose own name the table lacks is the table's nearest kind of place it is a kind
     * of, one or two hypernym steps up ("washroom" -> the bathroom, "refectory" -> dining hall
     * -> the dining room), never the bare "room" or "area"; only for a commonest sense that is
     * a place (a room or a workplace), as for WordNet's definitions. */
    const lex_sense *se = np->n_senses ? &np->senses[0] : NULL;
    for (int a = 1; !*r && se && se->rank == 1 && place_sense(se, 0) && a < se->n_anc; a++) {
        if (se->anc[a].dist > 2) continue;
        wn_synset syn;
        int rc = wn_read(v->lx->db, (wn_id){se->anc[a].off, WN_NOUN}, &syn, err);
        if (rc) return rc;
        for (int k = 0; k < syn.n_words && !*r; k++)
            if (!lex_is_generic_region(syn.words[k])) *r = lex_region_find(v, syn.words[k]);
        wn_synset_free(&syn);
    }
    return 0;
}

void lex_region_start(const sp_lex_vocab *v, sp_lex_phrase *ph)
{
    memset(ph->matches, 0, sizeof ph->matches);
    for (int i = 0; i < v->n; i++) ph->matches[i].class_index = i;
    ph->n_matches = v->n;
}

/* Classes named after the region ("kitchen counter" belongs to the kitchen); returns 1 when any,
 * 2 when a class's modifiers hold the region's whole name (the cafe's cafe table, the bathroom's
 * bathroom sink, not the utility room's utility sink nor the shop floor's floor): such a class
 * says by its name that it is of the place, 1.0; one named by a word of it, 0.9. */
int lex_region_named_after(const sp_lex_vocab *v, const char *region, sp_lex_phrase *ph)
{
    int any = 0;
    char name[WN_LEMMA_MAX], words[8][LEX_WORD];
    int nw = 0;
    snprintf(name, sizeof name, "%s", region);
    for (char *save = NULL, *w = strtok_r(name, "_ ", &save); w; w = strtok_r(NULL, "_ ", &save))
        if (!lex_is_generic_region(w) && nw < 8) snprintf(words[nw++], LEX_WORD, "%s", w);
    for (int i = 0; i < v->n; i++) {
        const lex_class *c = &v->classes[i];
        sp_lex_class_match *m = &ph->matches[i];
        int some = 0, all = nw > 0;
        for (int a = 0; a < nw; a++) {
            int in = 0, mod = 0;
            for (int k = 0; k < c->n_tok; k++)
                if (!strcmp(c->tok[k], words[a])) in = 1, mod |= k + 1 < c->n_tok;
            some |= in;
            all &= mod;
        }
        if (!some) continue;
        float score = all ? 1.0f : 0.9f;
        if (m->kind == SP_LEX_REGION ? m->score >= score : (!all && m->score >= score)) continue;
        memset(m, 0, sizeof *m);
        m->class_index = i;
        m->score = score;
        m->kind = SP_LEX_REGION;
        snprintf(m->path, sizeof m->path, "named after the region ('%s')", region);
        any = any > (all ? 2 : 1) ? any : (all ? 2 : 1);
    }
    return any;
}


/* Members of a named region into ph (sorted best first). r: its table entry or NULL (a place
 * WordNet knows); definition: the WordNet definition of its place sense. */
static int members_compute(const sp_lex_vocab *v, const lex_region *r, const char *name,
                           const char *definition, sp_lex_phrase *ph, sp_error *err)
{
    lex_region_start(v, ph);
    snprintf(ph->region, sizeof ph->region, "%s", name);
    for (char *p = ph->region; *p; p++)
        if (*p == '_') *p = ' ';
    int support = 0, first = -1, rc = region_members(v, r, definition, ph, &support, &first, err);
    if (rc) return rc;
    if (!r) { /* a place WordNet knows and the table does not: also what its name says is done */
        lex_tokens t;
        lex_tokenize(ph->region, &t);
        if ((rc = lex_region_activity(v, &t, ph, err)) < 0) return rc;
    }
    /* A class named after the place says by its name that it is of it (1.0 for the whole
     * name: the cafe's cafe table ranks with the table's first member, before the display case
     * a cafe usually has; the first member, listed first as the place's defining object, keeps
     * its place by kind) */
    lex_region_named_after(v, ph->region, ph);
    /* A room is known by its furniture: one kind of object alone (a sink) makes no bathroom; a
     * class named after the place says by its name that it is of it ("the shower stall" ->
     * the shower, "a booth for taking a shower") and stays. */
    /* ... unless that one is the object the table lists first by its very name (the laundry's
     * washing machine, the bike parking's cycle rack): the place's defining object stands for it */
    int kinds = 0;
    for (int i = 0; i < v->n; i++) kinds += ph->matches[i].score >= SP_LEX_THRESHOLD;
    if (kinds < 2)
        for (int i = 0; i < v->n; i++) {
            if (ph->matches[i].kind == SP_LEX_REGION) continue;
            if (kinds == 1 && ph->matches[i].class_index == first && ph->matches[i].score >= SP_LEX_THRESHOLD) continue;
            ph->matches[i].score *= LEX_MU;
            if (ph->matches[i].score > 0)
                snprintf(ph->matches[i].gloss_words, sizeof ph->matches[i].gloss_words,
                         "only one of the region's objects is in this scene");
        }
    qsort(ph->matches, (size_t)v->n, sizeof ph->matches[0], lex_match_cmp);
    return 0;
}

int lex_place_head(const lex_np *np)
{
    if (lex_is_generic_region(np->head)) return 1;
    /* its commonest physical sense is no piece of furniture and no container (a cabinet, a
     * drawer is also a compartment, a room, in a later sense), and one of its first senses is a
     * place (the hall: a hallway, an entrance hall, a large room; the gallery: a room where
     * works of art are exhibited) */
    int place = 0, first = 1;
    for (int s = 0; s < np->n_senses && s < 4; s++) {
        const lex_sense *se = &np->senses[s];
        if (first && lex_sense_physical(se)) {
            if (lex_anc_find(se, FURNITURE) >= 0 || lex_anc_find(se, CONTAINER) >= 0) return 0;
            first = 0;
        }
        place |= place_sense(se, 1);
    }
    return place;
}

/* The definition a region's name gives: its first sense that is a place, else its first. */
const char *lex_region_definition(const lex_np *np, int table_entry)
{
    if (np->n_senses && np->senses[0].rank == 1 && place_sense(&np->senses[0], table_entry))
        return np->senses[0].definition;
    for (int s = 0; table_entry && s < np->n_senses; s++)
        if (place_sense(&np->senses[s], 1)) return np->senses[s].definition;
    return table_entry && np->n_senses ? np->senses[0].definition : NULL;
}

/* A table region's members in this vocabulary, resolved into r->cache. WordNet's definition only
 * for a name WordNet has as one noun: "meeting room" is no entry, and the definition of its head
 * "room" (walls, floor, ceiling) defines no kind. */
static int region_prepare(const sp_lex_vocab *v, lex_region *r, sp_error *err)
{
    lex_tokens raw, t;
    lex_tokenize(r->name, &raw);
    lex_np np;
    int rc = lex_merge_collocations(v->lx, &raw, &t, err);
    if (rc || (rc = lex_np_parse(v->lx, &t, 0, t.n, 0, &np, err))) return rc;
    sp_lex_phrase *ph = malloc(sizeof *ph);
    if (!ph) rc = sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    else if (!(rc = members_compute(v, r, r->name, np.n_mods == np.split ? lex_region_definition(&np, 1) : NULL,
                                    ph, err)))
        r->cache = ph;
    else
        free(ph);
    lex_np_free(&np);
    return rc;
}

int lex_region_members(const sp_lex_vocab *v, const lex_region *r, const char *name,
                       const char *definition, sp_lex_phrase *ph, sp_error *err)
{
    if (!r) return members_compute(v, NULL, name, definition, ph, err);
    /* Table regions are resolved on first use, not when the vocabulary is made (the table has
     * dozens of rooms a scene never asks about: start-up stays small); the cache is written once
     * under the vocabulary's lock, so threads may share the vocabulary. */
    sp_lex_vocab *mv = (sp_lex_vocab *)v;
    lex_region *mr = (lex_region *)r;
    pthread_mutex_lock(&mv->region_lock);
    int rc = mr->cache ? 0 : region_prepare(v, mr, err);
    if (!rc) {
        memcpy(ph->matches, mr->cache->matches, sizeof ph->matches);
        ph->n_matches = mr->cache->n_matches;
        snprintf(ph->region, sizeof ph->region, "%s", r->name);
    }
    pthread_mutex_unlock(&mv->region_lock);
    return rc;
}

int lex_regions_load(sp_lex_vocab *v, const char *path, sp_error *err)
{
    cJSON *js = NULL;
    int rc = sp_json_read_file(path, &js, err);
    if (rc) return sp_error_prefix(err, "lexical: region table: ");
    if (!cJSON_IsObject(js)) {
        cJSON_Delete(js);
        return sp_error_set(err, SP_E_FORMAT, "%s: the region table must be a JSON object", path);
    }
    int n = cJSON_GetArraySize(js);
    v->regions = calloc(n ? (size_t)n : 1, sizeof *v->regions);
    if (!v->regions) {
        cJSON_Delete(js);
        return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    }
    const cJSON *it;
    cJSON_ArrayForEach(it, js) {
        if (it->string && it->string[0] == '_') continue;
        if (!cJSON_IsArray(it)) {
            rc = sp_error_set(err, SP_E_FORMAT, "%s: region '%s' must list object phrases", path, it->string);
            break;
        }
        lex_region *r = &v->regions[v->n_regions++];
        snprintf(r->name, sizeof r->name, "%s", it->string);
        const cJSON *m;
        cJSON_ArrayForEach(m, it) {
            if (!cJSON_IsString(m) || !m->valuestring[0]) {
                rc = sp_error_set(err, SP_E_FORMAT, "%s: region '%s': members must be strings", path, r->name);
                break;
            }
            if (r->n_members < 24) snprintf(r->members[r->n_members++], 64, "%s", m->valuestring);
        }
        if (rc) break;
    }
    cJSON_Delete(js);
    return rc;
}

const lex_region *lex_region_find_stem(const sp_lex_vocab *v, const char *stem)
{
    char key[64];
    snprintf(key, sizeof key, "%s", stem);
    for (char *p = key; *p; p++)
        if (*p == '_') *p = ' ';
    size_t n = strlen(key);
    const lex_region *r = lex_region_find(v, key);
    for (int i = 0; !r && n && i < v->n_regions; i++) {
        const char *name = v->regions[i].name;
        if (!strncmp(name, key, n) && name[n] == ' ' && lex_is_generic_region(name + n + 1)) r = &v->regions[i];
    }
    return r;
}

const lex_region *lex_region_find(const sp_lex_vocab *v, const char *name)
{
    char key[64];
    snprintf(key, sizeof key, "%s", name);
    for (char *p = key; *p; p++)
        if (*p == '_') *p = ' ';
    for (int i = 0; i < v->n_regions; i++)
        if (!strcmp(v->regions[i].name, key)) return &v->regions[i];
    return NULL;
}
