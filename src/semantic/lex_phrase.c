/* Noun phrases for the lexical text encoder: WordNet collocations joined into one token, then
 * head noun, modifiers before it and description words after a clause marker ("something TO
 * sit on", "a seat FOR two people", "something THAT keeps the air cool"). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lexical.h"

/* The noun base of a (possibly joined) word: its first morphy form, or "" when none. */
static int noun_base(const lex_db *lx, const char *w, char *out, sp_error *err)
{
    char b[WN_MAX_BASES][WN_LEMMA_MAX];
    int n = lex_bases(lx, WN_NOUN, w, b, err);
    if (n < 0) return n;
    out[0] = 0;
    if (n > 0) snprintf(out, WN_LEMMA_MAX, "%s", b[0]);
    return n > 0;
}

/* The collocation of k words starting at i, when WordNet has one: 1 and its base form. */
static int collocation_at(const lex_db *lx, const lex_tokens *in, int i, int k, char *base, sp_error *err)
{
    if (i < 0 || i + k > in->n || lex_word_class_of(in->w[i]) != LW_CONTENT) return 0;
    int last = lex_word_class_of(in->w[i + k - 1]);
    /* a collocation may end in a partitive ("tv set") or in a function word that is also a noun
     * ("trash can", "watering can"): WordNet's entry decides */
    if (last != LW_CONTENT && last != LW_PARTITIVE && last != LW_FUNCTION) return 0;
    /* "clean up" is a verb and its particle, not the noun "cleanup" */
    if (lex_is_particle(in->w[i + k - 1])) return 0;
    char joined[4 * LEX_WORD];
    size_t o = 0;
    for (int j = 0; j < k; j++) o += (size_t)snprintf(joined + o, sizeof joined - o, "%s%s", j ? "_" : "", in->w[i + j]);
    int rc = strlen(joined) < WN_LEMMA_MAX ? noun_base(lx, joined, base, err) : 0;
    if (rc < 0) return rc;
    if (!rc && k == 2) { /* "book shelf" -> "bookshelf" */
        snprintf(joined, sizeof joined, "%s%s", in->w[i], in->w[i + 1]);
        if ((rc = noun_base(lx, joined, base, err)) < 0) return rc;
    }
    return rc;
}

int lex_merge_collocations(const lex_db *lx, const lex_tokens *in, lex_tokens *out, sp_error *err)
{
    /* English compounds are right-headed: the collocation that ends a run binds first, so "red
     * fire extinguisher" is red + fire_extinguisher, not red_fire + extinguisher, and "metal
     * filing cabinet" metal + filing_cabinet; spans are chosen from the right, longest first */
    int span[LEX_MAX_TOKENS] = {0};
    char bases[LEX_MAX_TOKENS][WN_LEMMA_MAX];
    for (int j = in->n - 1; j >= 0;) {
        int took = 0;
        for (int k = 4; k >= 2 && !took; k--) {
            if (j - k + 1 < 0) continue;
            int rc = collocation_at(lx, in, j - k + 1, k, bases[j - k + 1], err);
            if (rc < 0) return rc;
            if (rc) took = k;
        }
        if (took) span[j - took + 1] = took, j -= took;
        else j--;
    }
    out->n = 0;
    for (int i = 0; i < in->n;) {
        if (out->n == LEX_MAX_TOKENS) break;
        if (span[i]) {
            snprintf(out->w[out->n++], LEX_WORD, "%s", bases[i]);
            i += span[i];
        } else if (out->n > 0 && (!strcmp(in->w[i], "unit") || !strcmp(in->w[i], "units"))) {
            /* "unit" after a word WordNet has no noun for names that thing as one piece: a
             * "shelving unit" is shelving (WordNet's unit: "an assemblage of parts that is
             * regarded as a single entity"); after a noun it stays ("sink unit") */
            int noun = lex_is_pos(lx, WN_NOUN, out->w[out->n - 1], err);
            if (noun < 0) return noun;
            if (noun || lex_word_class_of(out->w[out->n - 1]) != LW_CONTENT)
                snprintf(out->w[out->n++], LEX_WORD, "%s", in->w[i]);
            i++;
        } else {
            snprintf(out->w[out->n++], LEX_WORD, "%s", in->w[i]);
            i++;
        }
    }
    return 0;
}

void lex_np_free(lex_np *np)
{
    free(np->senses);
    memset(np, 0, sizeof *np);
}

/* Loads the noun senses of lemma (all of its morphy bases). attested_only keeps the senses that
 * the tagged corpora attest (WordNet's tagsense_cnt: couch the sofa, not "a coat of paint"), and
 * the first sense when any is attested; physical_only drops the non-physical ones. */
static int load_senses(const lex_db *lx, const char *lemma, int physical_only, int attested_only,
                       int no_person, lex_np *np, sp_error *err)
{
    char b[WN_MAX_BASES][WN_LEMMA_MAX];
    int nb = lex_bases(lx, WN_NOUN, lemma, b, err);
    if (nb <= 0) return nb;
    free(np->senses);
    np->n_senses = 0;
    np->senses = calloc(LEX_MAX_SENSES, sizeof(lex_sense));
    lex_sense *tmp = malloc(sizeof *tmp);
    if (!np->senses || !tmp) {
        free(tmp);
        return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    }
    int rc = 0;
    for (int k = 0; k < nb && !rc && np->n_senses < LEX_MAX_SENSES; k++) {
        uint32_t offs[WN_MAX_SENSES];
        int tagged = 0;
        int n = wn_lookup(lx->db, WN_NOUN, b[k], offs, WN_MAX_SENSES, &tagged, err);
        if (n < 0) rc = n;
        for (int i = 0; i < n && !rc && np->n_senses < LEX_MAX_SENSES; i++) {
            /* with no tag counts at all WordNet's sense order means nothing (stretcher: the
             * painter's frame first, the litter third): none is attested then */
            if (attested_only && (tagged == 0 || (i > 0 && i >= tagged))) break;
            int dup = 0;
            for (int j = 0; j < np->n_senses; j++) dup |= np->senses[j].off == offs[i];
            if (dup) continue;
            if ((rc = lex_sense_load(lx, offs[i], i + 1, tmp, err))) break;
            tmp->attested = i == 0 || i < tagged;
            tmp->certain = i < tagged || n == 1;
            /* a class names a kind of thing, not a named individual (the Monitor, a ship) */
            if (physical_only && (!lex_sense_physical(tmp) || tmp->instance)) continue;
            if ((no_person & 1) && (lex_sense_person(tmp) || lex_sense_process(tmp) || lex_sense_animal(tmp) ||
                                    lex_sense_food(tmp)))
                continue;
            if ((no_person & 2) && lex_sense_room(tmp)) continue;
            if ((no_person & 4) && !lex_sense_artifact(tmp)) continue;
            np->senses[np->n_senses++] = *tmp;
        }
    }
    free(tmp);
    return rc;
}

/* A query word whose senses are all groups of the taxonomy ("ficus", the genus) stands for its
 * members (WordNet's member meronyms, "%m": the fig tree, the rubber plant): they are added as
 * further senses. */
static int add_members(const lex_db *lx, lex_np *np, sp_error *err)
{
    for (int i = 0; i < np->n_senses; i++)
        if (lex_sense_physical(&np->senses[i])) return 0;
    lex_sense *tmp = malloc(sizeof *tmp);
    if (!tmp) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    int rc = 0, n = np->n_senses;
    for (int i = 0; i < n && !rc && np->n_senses < LEX_MAX_SENSES; i++) {
        wn_synset syn;
        if ((rc = wn_read(lx->db, (wn_id){np->senses[i].off, WN_NOUN}, &syn, err))) break;
        for (int p = 0; p < syn.n_pointers && !rc && np->n_senses < LEX_MAX_SENSES; p++) {
            const wn_pointer *pt = &syn.pointers[p];
            if (strcmp(pt->symbol, "%m") || pt->target.pos != WN_NOUN) continue;
            if (!(rc = lex_sense_load(lx, pt->target.offset, np->senses[i].rank, tmp, err)) &&
                lex_sense_physical(tmp))
                np->senses[np->n_senses++] = *tmp;
        }
        wn_synset_free(&syn);
    }
    free(tmp);
    return rc;
}

/* A closed compound WordNet lacks ("nightstand"): the longest noun it ends in whose rest is a
 * noun or an adjective ("night" + "stand"). Returns 1 and both parts when found. */
int lex_split_compound(const lex_db *lx, const char *w, char *left, char *right, sp_error *err)
{
    size_t n = strlen(w);
    for (size_t k = 3; k + 3 <= n; k++) {
        char l[WN_LEMMA_MAX], r[WN_LEMMA_MAX];
        snprintf(l, sizeof l, "%.*s", (int)k, w);
        snprintf(r, sizeof r, "%s", w + k);
        int rn = lex_is_pos(lx, WN_NOUN, r, err);
        if (rn < 0) return rn;
        if (!rn) continue;
        int ln = lex_is_pos(lx, WN_NOUN, l, err);
        int la = ln > 0 ? 1 : lex_is_pos(lx, WN_ADJ, l, err);
        if (ln < 0 || la < 0) return ln < 0 ? ln : la;
        if (ln || la) {
            snprintf(left, WN_LEMMA_MAX, "%s", l);
            snprintf(right, WN_LEMMA_MAX, "%s", r);
            return 1;
        }
    }
    return 0;
}

/* 1 when w is a noun, or a closed compound ending in one. */
static int noun_like(const lex_db *lx, const char *w, sp_error *err)
{
    char l[WN_LEMMA_MAX], r[WN_LEMMA_MAX];
    int rc = lex_is_pos(lx, WN_NOUN, w, err);
    return rc != 0 ? rc : lex_split_compound(lx, w, l, r, err);
}

/* The head's senses; a split compound's first part becomes the last modifier. Queries keep
 * every sense (a user may mean any); class names their attested physical ones, or when none is
 * attested all physical ones (np->fallback: the vocabulary chooses by context), or all. */
static int head_senses(const lex_db *lx, const char *w, int physical_only, lex_np *np, sp_error *err)
{
    char left[WN_LEMMA_MAX], right[WN_LEMMA_MAX];
    int rc = lex_is_pos(lx, WN_NOUN, w, err);
    if (rc < 0) return rc;
    const char *h = w;
    if (!rc) {
        if ((rc = lex_split_compound(lx, w, left, right, err)) < 0) return rc;
        if (rc == 1) {
            if (np->n_mods < 8) snprintf(np->mods[np->n_mods++], LEX_WORD, "%s", left);
            np->split = 1;
            h = right;
        }
    }
    /* A class is a thing standing in the scene: no person sense ("monitor" the supervisor,
     * "printer" the tradesman), no animal ("jack" the fish, "crane" the bird), no physical
     * process ("microwave" the radiation, its only attested sense) and no food ("jack" the
     * jackfruit, "grinder" the sandwich) when the name also names an artifact ("person" keeps
     * its own, a plant its organism), and no room when it also names an artifact that is none
     * ("toilet" the fixture, not the room WordNet's commonest sense calls a bathroom; a
     * "kitchen" keeps its room). */
    int no_person = 0;
    rc = 0;
    if (physical_only) {
        rc = load_senses(lx, h, 1, 0, 0, np, err);
        for (int i = 0; !rc && i < np->n_senses; i++) {
            no_person |= lex_sense_artifact(&np->senses[i]);
            if (lex_sense_artifact(&np->senses[i]) && !lex_sense_room(&np->senses[i])) no_person |= 2;
        }
    }
    /* a closed compound WordNet lacks ("whiteboard") is built on a common sense of its last
     * word: the senses the corpora attest (no "board" that is a dining table) */
    if (!rc) rc = load_senses(lx, h, physical_only, physical_only || np->split, no_person, np, err);
    if (!rc && !physical_only && np->split && np->n_senses == 0) rc = load_senses(lx, h, 0, 0, no_person, np, err);
    /* attested senses that are neither artifacts nor living things ("radiator": any object that
     * radiates energy) while the name also names artifacts (the heater, the car's radiator): a
     * class is a thing made to stand there, its artifact senses are chosen by context */
    int made = physical_only && !rc && (no_person & 2) && np->n_senses > 0;
    for (int i = 0; made && i < np->n_senses; i++)
        if (lex_sense_artifact(&np->senses[i]) || lex_sense_living(&np->senses[i])) made = 0;
    if (made) {
        np->fallback = 1;
        rc = load_senses(lx, h, 1, 0, no_person | 4, np, err);
    }
    if (!rc && physical_only && np->n_senses == 0) {
        np->fallback = 1; /* no attested physical sense: the vocabulary chooses (lex_vocab.c) */
        rc = load_senses(lx, h, 1, 0, no_person, np, err);
    }
    if (!rc && physical_only && np->n_senses == 0) rc = load_senses(lx, h, 0, 0, 0, np, err);
    if (!rc && !physical_only) rc = add_members(lx, np, err);
    char b[WN_MAX_BASES][WN_LEMMA_MAX];
    int nb = rc ? 0 : lex_bases(lx, WN_NOUN, h, b, err);
    if (nb < 0) return nb;
    if (np->split) snprintf(np->head, sizeof np->head, "%s", w);
    else snprintf(np->head, sizeof np->head, "%s", nb > 0 ? b[0] : w);
    return rc;
}

/* The description's first word, when a verb, is what the thing is for ("to WASH hair", "that
 * KEEPS food cold"): it weighs at least as much as any of its objects, which a definition names
 * by a more general word or not at all (hair, shirt, samples), however many senses the verb has. */
static int purpose_weight(const lex_db *lx, lex_np *np, sp_error *err)
{
    /* a light verb says little of what the thing is for ("to PUT books on", "to KEEP food cold"):
     * the object carries it (Jespersen's light verbs, those that are not already function words) */
    static const char *const light[] = {"put", "keep", "make", "have", "give", "use", "place", "leave", NULL};
    if (np->n_desc < 2) return 0;
    for (int i = 0; light[i]; i++)
        if (!strcmp(np->desc[0], light[i])) return 0;
    int verb = lex_is_pos(lx, WN_VERB, np->desc[0], err);
    if (verb <= 0) return verb;
    for (int i = 1; i < np->n_desc; i++)
        if (np->desc_w[i] > np->desc_w[0]) np->desc_w[0] = np->desc_w[i];
    return 0;
}

int lex_np_parse(const lex_db *lx, const lex_tokens *t, int from, int to, int physical_only,
                 lex_np *np, sp_error *err)
{
    memset(np, 0, sizeof *np);
    np->head_start = np->head_end = -1;
    int marker = 0, n_np = 0, np_idx[LEX_MAX_TOKENS], np_ph[LEX_MAX_TOKENS], person = 0;
    const char *clause = NULL;
    for (int k = from; k < to; k++) {
        const char *w = t->w[k];
        int cls = lex_word_class_of(w);
        person |= !strcmp(w, "i") || !strcmp(w, "we") || !strcmp(w, "you");
        if (cls == LW_CLAUSE && !clause) clause = w;
        /* an auxiliary that ends the phrase is the noun when WordNet has one ("a can", "the
         * jerry can": no verb follows it) */
        if (cls == LW_FUNCTION && k == to - 1 && !lex_is_particle(w)) {
            int noun = lex_is_pos(lx, WN_NOUN, w, err), verb = lex_is_pos(lx, WN_VERB, w, err);
            if (noun < 0 || verb < 0) return noun < 0 ? noun : verb;
            if (noun && verb) cls = LW_CONTENT;
        }
        if (cls == LW_FUNCTION) continue;
        if (cls == LW_PARTITIVE && k + 1 < to && !strcmp(t->w[k + 1], "of")) {
            k++;
            continue;
        }
        if (cls == LW_PARTITIVE) cls = LW_CONTENT; /* without "of" a word like any: "to TYPE on" */
        if (cls == LW_CLAUSE || cls == LW_PREP) {
            /* a preposition closing a description: "something to write on" */
            if (cls == LW_PREP && np->n_desc > 0 && k == to - 1) np->stranded = 1;
            marker = 1;
            continue;
        }
        if (marker) {
            char b[WN_MAX_BASES][WN_LEMMA_MAX];
            int nb = lex_bases(lx, WN_NOUN, w, b, err);
            if (nb < 0) return nb;
            int where = lex_is_generic_region(w) || (nb > 0 && lex_is_generic_region(b[0]));
            if (cls != LW_CONTENT || where) continue;
            /* a description is matched word by word against definitions, which hold words, not
             * collocations: "keep FROZEN FOOD" is frozen + food ("in which food is frozen") */
            char parts[LEX_WORD];
            snprintf(parts, sizeof parts, "%s", w);
            for (char *save = NULL, *p = strtok_r(parts, "_", &save); p && np->n_desc < 16; p = strtok_r(NULL, "_", &save))
                snprintf(np->desc[np->n_desc++], LEX_WORD, "%s", p);
            continue;
        }
        if (n_np < LEX_MAX_TOKENS) np_idx[n_np] = k, np_ph[n_np++] = cls == LW_PLACEHOLDER;
    }
    /* "something that keeps food cold", "what tells the time": the thing does it */
    np->thing_does = clause && !person && (!strcmp(clause, "that") || !strcmp(clause, "which") || !strcmp(clause, "what"));
    /* The head: the last noun of the phrase before any clause; words after it describe. */
    int head = -1, rc;
    for (int i = n_np - 1; i >= 0 && head < 0; i--) {
        if (np_ph[i]) { head = i; break; }
        if ((rc = noun_like(lx, t->w[np_idx[i]], err)) < 0) return rc;
        if (rc) head = i;
    }
    for (int i = 0; i < n_np; i++) {
        const char *w = t->w[np_idx[i]];
        if (i < head && !np_ph[i] && np->n_mods < 8) snprintf(np->mods[np->n_mods++], LEX_WORD, "%s", w);
        else if (i > head && !np_ph[i] && np->n_desc < 16) snprintf(np->desc[np->n_desc++], LEX_WORD, "%s", w);
        if (!np_ph[i] && np->n_words < LEX_MAX_TOKENS) snprintf(np->words[np->n_words++], LEX_WORD, "%s", w);
    }
    if (head >= 0) {
        np->head_start = np_idx[head];
        np->head_end = np_idx[head] + 1;
    }
    if (head >= 0 && np_ph[head]) {
        np->placeholder = 1;
        snprintf(np->head, sizeof np->head, "%s", t->w[np_idx[head]]);
    } else if (head >= 0 && (rc = head_senses(lx, t->w[np_idx[head]], physical_only, np, err))) {
        return rc;
    }
    for (int i = 0; i < np->n_desc; i++)
        if ((rc = lex_word_weight(lx, np->desc[i], &np->desc_w[i], err))) return rc;
    return purpose_weight(lx, np, err);
}
