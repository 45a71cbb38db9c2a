/* A scene's vocabulary for the lexical text encoder: each class name parsed once (head noun and
 * its physical senses, hypernym closures, the words of its definitions), and the region table. */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lexical.h"
#include "semsplat/io.h"

int sp_lexicon_open(sp_lexicon **out, const char *wordnet_dir, sp_error *err)
{
    *out = NULL;
    lex_db *lx = calloc(1, sizeof *lx);
    if (!lx) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    int rc = wn_open(&lx->db, wordnet_dir ? wordnet_dir : SP_LEX_DEFAULT_WORDNET, err);
    if (rc) {
        free(lx);
        return rc;
    }
    *out = lx;
    return 0;
}

void sp_lexicon_free(sp_lexicon *lx)
{
    if (!lx) return;
    wn_close(lx->db);
    free(lx);
}

void sp_lex_vocab_free(sp_lex_vocab *v)
{
    if (!v) return;
    for (int i = 0; i < v->n; i++) {
        lex_np_free(&v->classes[i].np);
        lex_np_free(&v->classes[i].name_head);
        lex_np_free(&v->classes[i].mod_head);
        lex_bag_free(&v->classes[i].bag);
        for (int k = 0; k < v->classes[i].n_kind; k++) lex_np_free(&v->classes[i].kind_np[k]);
        lex_bag_free(&v->classes[i].kind_bag);
    }
    free(v->classes);
    free(v->vocab_words);
    for (int i = 0; i < v->n_regions; i++) free(v->regions[i].cache);
    free(v->regions);
    free(v->aliases);
    free(v->uses);
    pthread_mutex_destroy(&v->region_lock);
    free(v);
}

int sp_lex_vocab_size(const sp_lex_vocab *v) { return v->n; }
const char *sp_lex_vocab_class(const sp_lex_vocab *v, int i)
{
    return i >= 0 && i < v->n ? v->classes[i].name : NULL;
}

int lex_vocab_has_word(const sp_lex_vocab *v, const char *w)
{
    for (int i = 0; i < v->n_vocab_words; i++)
        if (!strcmp(v->vocab_words[i], w)) return 1;
    return 0;
}


/* The verbs WordNet derives from the sense ("+" pointers: refrigerator -> refrigerate "make cool
 * or cold", bicycle -> bicycle "ride a bicycle", computer -> compute): what one does with the
 * thing, added one step from its own definition (weight * DELTA). */
static int bag_derived_verbs(const lex_db *lx, lex_bag *bag, const wn_synset *s, float weight, sp_error *err)
{
    int rc = 0;
    for (int p = 0; p < s->n_pointers && !rc; p++)
        if (!strcmp(s->pointers[p].symbol, "+") && s->pointers[p].target.pos == WN_VERB)
            rc = lex_bag_synset(lx, bag, s->pointers[p].target, weight * LEX_DELTA, 0, err);
    return rc;
}

/* Adds a synset's lemmas and definition to the bag at weight (verbs: and its derived verbs'). */
int lex_bag_synset(const lex_db *lx, lex_bag *bag, wn_id id, float weight, int verbs, sp_error *err)
{
    wn_synset s;
    int rc = wn_read(lx->db, id, &s, err);
    if (rc) return rc;
    char def[512], src[192], lemmas[512];
    wn_definition(s.gloss, def, sizeof def);
    size_t o = 0;
    lemmas[0] = 0;
    for (int i = 0; i < s.n_words && o + 1 < sizeof lemmas; i++) {
        int w = snprintf(lemmas + o, sizeof lemmas - o, "%s%s", i ? " " : "", s.words[i]);
        if (w > 0) o += (size_t)w;
    }
    for (char *p = lemmas; *p; p++)
        if (*p == '_') *p = ' ';
    snprintf(src, sizeof src, "%s%s: %s", s.words[0], id.pos == WN_VERB ? " (verb)" : "", def);
    for (char *p = src; *p && *p != ':'; p++)
        if (*p == '_') *p = ' ';
    rc = lex_bag_add_text(lx, bag, def, weight, 0, src, err);
    if (!rc) rc = lex_bag_add_lemmas(bag, lemmas, weight, src, err);
    if (!rc && verbs) rc = bag_derived_verbs(lx, bag, &s, weight, err);
    wn_synset_free(&s);
    return rc;
}

/* The definitions of the sense's kinds, one level down (WordNet's hyponyms, "~"), one weak step
 * (DELTA): what a kind of the thing is for, the thing is for ("washbasin: ... where you can
 * wash your hands and face" speaks for the sink). */
static int bag_kinds(const lex_db *lx, lex_bag *bag, uint32_t off, sp_error *err)
{
    wn_synset s;
    int rc = wn_read(lx->db, (wn_id){off, WN_NOUN}, &s, err);
    if (rc) return rc;
    for (int p = 0; !rc && p < s.n_pointers; p++)
        if (!strcmp(s.pointers[p].symbol, "~") && s.pointers[p].target.pos == WN_NOUN) {
            /* the definition only: a kind's names carry its own modifiers ("COAT closet") */
            wn_synset k;
            if ((rc = wn_read(lx->db, s.pointers[p].target, &k, err))) break;
            char def[512], src[192];
            wn_definition(k.gloss, def, sizeof def);
            snprintf(src, sizeof src, "%s: %s", k.words[0], def);
            for (char *q = src; *q && *q != ':'; q++)
                if (*q == '_') *q = ' ';
            rc = lex_bag_add_text(lx, bag, def, LEX_KIND_W, 1, src, err);
            wn_synset_free(&k);
        }
    wn_synset_free(&s);
    return rc;
}

/* Adds the physical senses of the class name's alias reading (tokens read) to np's; a name with
 * no head of its own takes the reading's head and modifiers. */
static int add_alias_senses(const lex_db *lx, lex_np *np, const lex_tokens *read, sp_error *err)
{
    lex_tokens t;
    lex_np a;
    int rc = lex_merge_collocations(lx, read, &t, err);
    if (!rc) rc = lex_np_parse(lx, &t, 0, t.n, 1, &a, err);
    if (rc) return rc;
    if (!np->n_senses) {
        lex_np_free(np);
        *np = a;
        return 0;
    }
    for (int i = 0; i < a.n_senses && np->n_senses < LEX_MAX_SENSES; i++) {
        int dup = 0;
        for (int j = 0; j < np->n_senses; j++) dup |= np->senses[j].off == a.senses[i].off;
        if (!dup) np->senses[np->n_senses++] = a.senses[i], np->n_alias++;
    }
    lex_np_free(&a);
    return 0;
}

/* The name's last word read alone, when WordNet joined the name into one collocation whose
 * last word is a noun of its own ("washing machine", "punching bag", "exercise bike"): the
 * scorer reads the class also as a kind of that word (one level below it). */
static int name_head_prepare(const lex_db *lx, lex_class *c, const lex_tokens *raw, sp_error *err)
{
    if (raw->n < 2 || !strchr(c->np.head, '_') || c->np.n_mods > 0) return 0;
    lex_tokens last;
    last.n = 1;
    snprintf(last.w[0], LEX_WORD, "%s", raw->w[raw->n - 1]);
    int rc = lex_np_parse(lx, &last, 0, 1, 1, &c->name_head, err);
    if (rc) return rc;
    if (!strcmp(c->name_head.head, c->np.head)) lex_np_free(&c->name_head), memset(&c->name_head, 0, sizeof c->name_head);
    return 0;
}

/* 1 when a sense of np's head has an ancestor of one of these names. */
static int has_ancestor_named(const lex_np *np, const char *const *holders)
{
    for (int s = 0; s < np->n_senses; s++)
        for (int a = 0; a < np->senses[s].n_anc; a++)
            for (int h = 0; holders[h]; h++)
                if (!strcmp(np->senses[s].anc[a].name, holders[h])) return 1;
    return 0;
}

int lex_np_holder(const lex_np *np)
{
    static const char *const holders[] = {"container", "support", "supporting structure", NULL};
    return has_ancestor_named(np, holders);
}

int lex_np_support(const lex_np *np)
{
    static const char *const supports[] = {"support", "supporting structure", NULL};
    return has_ancestor_named(np, supports);
}

/* The noun modifier next to the head of a name WordNet lacks ("dumbbell" of "dumbbell rack",
 * "storage" of "storage shelf"), its physical senses that are no person, when the head is a
 * holder (a container or a support in WordNet: rack, shelf, bin, case): a query naming it alone
 * is what the class holds ("dumbbells" -> the dumbbell rack). */
static int mod_head_prepare(const lex_db *lx, lex_class *c, sp_error *err)
{
    if (!lex_np_holder(&c->np)) return 0; /* a screen is not what holds its projector */
    lex_tokens one;
    one.n = 1;
    snprintf(one.w[0], LEX_WORD, "%s", c->np.mods[c->np.n_mods - 1]);
    int rc = lex_np_parse(lx, &one, 0, 1, 1, &c->mod_head, err);
    if (rc) return rc;
    int k = 0;
    for (int i = 0; i < c->mod_head.n_senses; i++)
        if (!lex_sense_person(&c->mod_head.senses[i])) c->mod_head.senses[k++] = c->mod_head.senses[i];
    c->mod_head.n_senses = k;
    return 0;
}

/* The words of the name before its last, read alone with every noun sense, and those senses'
 * lemmas and definitions: what kind of its head the class is ("checkout" counter, "drying" rack),
 * to tell a query naming another kind (lex_score.c, another_kind). */
static int kind_prepare(const lex_db *lx, lex_class *c, sp_error *err)
{
    int rc = 0;
    for (int i = 0; i + 1 < c->n_tok && c->n_kind < 3 && !rc; i++) {
        int noun = lex_is_pos(lx, WN_NOUN, c->tok[i], err); /* "overbed": no kind WordNet names */
        if (noun < 0) return noun;
        if (!noun) continue;
        lex_tokens one = {1, {{0}}};
        snprintf(one.w[0], LEX_WORD, "%s", c->tok[i]);
        lex_np *k = &c->kind_np[c->n_kind++];
        if ((rc = lex_np_parse(lx, &one, 0, 1, 0, k, err))) break;
        c->kind_lexfile[c->n_kind - 1] = -1;
        int tagged = 0;
        uint32_t first;
        int nl = wn_lookup(lx->db, WN_NOUN, c->tok[i], &first, 1, &tagged, err);
        if (nl < 0) return nl;
        if (k->n_senses && tagged) { /* an attested commonest sense */
            wn_synset syn;
            if ((rc = wn_read(lx->db, (wn_id){k->senses[0].off, WN_NOUN}, &syn, err))) break;
            c->kind_lexfile[c->n_kind - 1] = syn.lexfile;
            wn_synset_free(&syn);
        }
        for (int s = 0; s < k->n_senses && !rc; s++)
            rc = lex_bag_synset(lx, &c->kind_bag, (wn_id){k->senses[s].off, WN_NOUN}, 1.0f, 0, err);
    }
    return rc;
}

/* 1 when w is an -ing form of a verb that WordNet has neither as a noun nor as an adjective. */
static int gerund(const lex_db *lx, const char *w, sp_error *err)
{
    size_t n = strlen(w);
    if (n < 5 || strcmp(w + n - 3, "ing")) return 0;
    int adj = lex_is_pos(lx, WN_ADJ, w, err);
    if (adj) return adj < 0 ? adj : 0;
    return lex_is_pos(lx, WN_VERB, w, err);
}

int lex_ing_verb(const lex_db *lx, const char *w, char *verb, sp_error *err)
{
    size_t n = strlen(w);
    if (n < 5 || strcmp(w + n - 3, "ing")) return 0;
    char b[WN_MAX_BASES][WN_LEMMA_MAX];
    int nb = lex_bases(lx, WN_VERB, w, b, err);
    if (nb <= 0) return nb;
    snprintf(verb, WN_LEMMA_MAX, "%s", b[0]);
    return 1;
}

/* 1 when the noun synset is a named individual (an instance hypernym, "@i"). */
static int is_instance(const lex_db *lx, uint32_t off, sp_error *err)
{
    wn_synset s;
    int rc = wn_read(lx->db, (wn_id){off, WN_NOUN}, &s, err);
    if (rc) return rc < 0 ? rc : -rc;
    int inst = 0;
    for (int p = 0; p < s.n_pointers; p++) inst |= !strcmp(s.pointers[p].symbol, "@i");
    wn_synset_free(&s);
    return inst;
}

/* The words of a name before its last, by their commonest noun sense when the tagged corpora
 * attest it, one weak step (DELTA) in the class's definitions: what the thing is for, holds or
 * serves ("mop bucket": mop, "a cleaning implement ... for cleaning floors"; "barber chair":
 * barber, "a hairdresser who cuts hair and shaves beards"; "laundry basket": laundry, wash,
 * washing). A word WordNet's order alone puts first says nothing (change 23). */
static int bag_modifiers(const lex_db *lx, lex_class *c, sp_error *err)
{
    int rc = 0;
    for (int i = 0; i + 1 < c->n_tok && !rc; i++) {
        uint32_t off[8];
        int tagged = 0;
        int n = wn_lookup(lx->db, WN_NOUN, c->tok[i], off, 8, &tagged, err);
        if (n < 0) return n;
        int kinds = 0, first = -1; /* senses that are kinds, not named individuals ("Barber") */
        for (int k = 0; k < n && !rc; k++) {
            int inst = is_instance(lx, off[k], err);
            if (inst < 0) return inst;
            if (!inst && kinds++ == 0) first = k;
        }
        if (first >= 0 && (tagged || kinds == 1))
            rc = lex_bag_synset(lx, &c->bag, (wn_id){off[first], WN_NOUN}, LEX_DELTA, 0, err);
    }
    return rc;
}

/* 1 when a base form of one of the class name's modifiers is a word of synset off's lemmas or
 * definition. */
static int names_modifier(const lex_db *lx, const lex_class *c, uint32_t off, sp_error *err)
{
    lex_bag bag = {0};
    int rc = lex_bag_synset(lx, &bag, (wn_id){off, WN_NOUN}, 1.0f, 0, err), hit = 0;
    for (int i = 0; !rc && i < c->np.n_mods && !hit; i++) {
        /* a word that also describes ("back" counter: an adjective, an adverb) names no purpose */
        int adj = lex_is_pos(lx, WN_ADJ, c->np.mods[i], err);
        int adv = adj ? 0 : lex_is_pos(lx, WN_ADV, c->np.mods[i], err);
        if (adj || adv) {
            if (adj < 0 || adv < 0) rc = adj < 0 ? adj : adv;
            continue;
        }
        for (int p = 0; p < 3 && !rc && !hit; p++) {
            char b[WN_MAX_BASES][WN_LEMMA_MAX];
            int nb = lex_bases(lx, (wn_pos)p, c->np.mods[i], b, err);
            if (nb < 0) rc = nb;
            else hit = nb > 0 && lex_bag_find(&bag, b, nb, 0.0f, 1.0f, 1.0f, 0, NULL) > 0;
        }
    }
    lex_bag_free(&bag);
    return rc ? rc : hit;
}

/* The modifier of a name WordNet lacks chooses among its head's senses (Lesk 1986): the physical
 * senses of the head whose lemmas or definition say the modifier ("weighing scale": scale, "a
 * measuring instrument for WEIGHING", not the indicator of graduated marks the corpora attest)
 * replace the attested ones; the alias table's stay. Nothing changes when no sense says it. */
static int modifier_senses(const lex_db *lx, lex_class *c, sp_error *err)
{
    lex_np *np = &c->np;
    if (!np->n_mods || np->split || !np->head[0] || !np->senses) return 0;
    uint32_t offs[LEX_MAX_SENSES];
    int n = wn_lookup(lx->db, WN_NOUN, np->head, offs, LEX_MAX_SENSES, NULL, err);
    if (n <= 0) return n;
    lex_sense *keep = malloc(sizeof *keep * LEX_MAX_SENSES);
    if (!keep) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    int nk = 0, rc = 0;
    for (int k = 0; k < n && !rc; k++) {
        int hit = names_modifier(lx, c, offs[k], err);
        if (hit < 0) rc = hit;
        else if (hit && !(rc = lex_sense_load(lx, offs[k], k + 1, &keep[nk], err)) &&
                 lex_sense_physical(&keep[nk]) && !lex_sense_person(&keep[nk]))
            nk++;
    }
    if (!rc && nk) {
        int own = np->n_senses - np->n_alias;
        for (int i = own; i < np->n_senses && nk < LEX_MAX_SENSES; i++) keep[nk++] = np->senses[i];
        memcpy(np->senses, keep, sizeof *keep * (size_t)nk);
        np->n_senses = nk;
        np->fallback = 0;
    }
    free(keep);
    return rc;
}

static int class_prepare(const sp_lex_vocab *v, lex_class *c, const char *name, sp_error *err)
{
    const lex_db *lx = v->lx;
    snprintf(c->name, sizeof c->name, "%s", name);
    lex_tokens raw, t, read;
    lex_tokenize(name, &raw);
    /* a name is no relation: a word and a preposition WordNet joins with a hyphen are that one
     * word ("walk in fridge" is a walk-in fridge, not a walk in a fridge) */
    lex_tokens joined = raw;
    int rc = 0;
    for (int i = 0; i + 2 < joined.n && !rc; i++) {
        if (lex_word_class_of(joined.w[i + 1]) != LW_PREP && !lex_is_particle(joined.w[i + 1])) continue;
        char hy[2 * LEX_WORD + 2];
        snprintf(hy, sizeof hy, "%s-%s", joined.w[i], joined.w[i + 1]);
        if (strlen(hy) >= LEX_WORD) continue;
        int is = 0;
        for (int p = 0; p < 2 && !is && !rc; p++) {
            int k = lex_is_pos(lx, p == 0 ? WN_NOUN : WN_ADJ, hy, err);
            if (k < 0) rc = k;
            else is = k;
        }
        if (!is) continue;
        snprintf(joined.w[i], LEX_WORD, "%s", hy);
        memmove(joined.w[i + 1], joined.w[i + 2], sizeof joined.w[0] * (size_t)(joined.n - i - 2));
        joined.n--;
        c->joined = 1;
    }
    if (!rc) rc = lex_merge_collocations(lx, &joined, &t, err);
    if (!rc) rc = lex_np_parse(lx, &t, 0, t.n, 1, &c->np, err);
    /* a name that is wholly a name of the alias table also means what it usually means indoors
     * ("wheelie bin": a garbage can, its first target), and so does a head WordNet lacks ("hand
     * sanitizer"): those senses are added to its own. A head WordNet has is left alone:
     * "projector screen" is no "projector monitor". */
    int aliased = rc ? 0 : lex_alias_class(v, &t, &read, err);
    if (aliased < 0) return aliased;
    if (aliased) rc = add_alias_senses(lx, &c->np, &read, err);
    if (!rc) rc = modifier_senses(lx, c, err);
    /* The words of the name in base form ("walls" -> "wall"), for exact matches and modifiers. */
    for (int i = 0; i < raw.n && !rc && c->n_tok < 8; i++) {
        char b[WN_MAX_BASES][WN_LEMMA_MAX];
        int nb = lex_bases(lx, WN_NOUN, raw.w[i], b, err);
        if (nb < 0) return nb;
        snprintf(c->tok[c->n_tok++], LEX_WORD, "%s", nb > 0 ? b[0] : raw.w[i]);
    }
    if (!rc) rc = kind_prepare(lx, c, err);
    for (int i = 0; i + 1 < c->n_tok && !rc && !c->act[0]; i++) {
        int ing = lex_ing_verb(lx, c->tok[i], c->act, err);
        if (ing < 0) return ing;
    }
    if (!rc) rc = bag_modifiers(lx, c, err);
    /* A noun modifier names a particular kind of the head ("shoe cabinet"), and so does a word
     * WordNet does not know at all ("overbed table"): it cannot be an attribute we could ignore,
     * so the class is one level below its head and another kind of the head is its sibling.
     * A known adjective ("potted plant") describes the head and leaves the class at its level. */
    for (int i = 0; i < c->np.n_mods && !rc; i++) {
        int known = 0;
        for (int p = 0; p < WN_NPOS && !known; p++) {
            int is = lex_is_pos(lx, (wn_pos)p, c->np.mods[i], err);
            if (is < 0) return is;
            known = is;
            if (is && p == WN_NOUN) c->spec = 1;
        }
        /* a gerund names the kind by its purpose ("drying rack", "styling chair": a chair for
         * styling), as a noun modifier does; a participle adjective WordNet lists ("folding")
         * is known as an adjective and was handled above */
        int ger = gerund(lx, c->np.mods[i], err);
        if (ger < 0) return ger;
        if (ger) c->spec = 1;
        if (known) continue;
        c->spec = 1;
        /* its parts, when it is a closed compound ("overbed" = over + bed), agree with a query
         * modifier: "bed table" is the overbed table */
        char l[WN_LEMMA_MAX], r[WN_LEMMA_MAX];
        int sp = lex_split_compound(lx, c->np.mods[i], l, r, err);
        if (sp < 0) return sp;
        if (sp && c->n_part + 2 <= 4) {
            snprintf(c->part[c->n_part++], LEX_WORD, "%s", l);
            snprintf(c->part[c->n_part++], LEX_WORD, "%s", r);
        }
    }
    /* a closed compound WordNet lacks, split ("nightstand" = night + stand): its first part is a
     * word of its name too, so a query modifier saying it agrees ("NIGHT table") */
    if (!rc && c->np.split && c->np.n_mods > 0 && c->n_part < 4) {
        char left[LEX_WORD];
        snprintf(left, sizeof left, "%s", c->np.mods[c->np.n_mods - 1]);
        memcpy(c->part[c->n_part++], left, sizeof left);
    }
    c->holder = lex_np_holder(&c->np);
    if (!rc) rc = name_head_prepare(lx, c, &raw, err);
    if (!rc && c->spec && c->np.n_mods > 0) rc = mod_head_prepare(lx, c, err);
    if (!rc) rc = lex_bag_add_text(lx, &c->bag, name, 1.0f, 0, "the class name", err);
    /* Definitions: each physical sense's own (level 0) and its hypernyms' up to two levels. */
    for (int s = 0; s < c->np.n_senses && !rc; s++) {
        const lex_sense *se = &c->np.senses[s];
        for (int a = 0; a < se->n_anc && !rc; a++) {
            if (se->anc[a].dist > LEX_GLOSS_LEVELS) continue;
            float w = se->anc[a].dist == 0 ? 1.0f : se->anc[a].dist == 1 ? LEX_DELTA : LEX_DELTA * LEX_DELTA;
            rc = lex_bag_synset(lx, &c->bag, (wn_id){se->anc[a].off, WN_NOUN}, w, se->anc[a].dist == 0, err);
        }
        /* a name one level below its sense ("cafe table") is a sibling of the sense's kinds */
        if (!rc && !c->spec) rc = bag_kinds(lx, &c->bag, se->off, err);
    }
    return rc;
}

static int add_vocab_word(sp_lex_vocab *v, const char *w, sp_error *err)
{
    if (lex_vocab_has_word(v, w)) return 0;
    char (*nw)[LEX_WORD] = realloc(v->vocab_words, sizeof *nw * (size_t)(v->n_vocab_words + 1));
    if (!nw) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    v->vocab_words = nw;
    snprintf(v->vocab_words[v->n_vocab_words++], LEX_WORD, "%s", w);
    return 0;
}

/* A class name whose attested senses are not physical ("cube": the shapes) takes, among its
 * physical senses, those closest to the scene's other classes (Resnik 1999, "disambiguating noun
 * groupings"): support(s) = mean over other classes of the best Wu-Palmer similarity to one of
 * their senses; senses within 0.02 of the best support stay ("magic cube" in a bookstore: the
 * block, not the tropical shrub). */
static void choose_by_context(sp_lex_vocab *v, int ci)
{
    lex_np *np = &v->classes[ci].np;
    int own = np->n_senses - np->n_alias; /* the alias table's senses are not in question */
    if (own < 2 || v->n < 2) return;
    float support[LEX_MAX_SENSES], best = 0;
    for (int s = 0; s < own; s++) {
        float sum = 0;
        for (int k = 0; k < v->n; k++) {
            if (k == ci) continue;
            float b = 0;
            for (int j = 0; j < v->classes[k].np.n_senses; j++) {
                float w = lex_wup(&np->senses[s], &v->classes[k].np.senses[j]);
                if (w > b) b = w;
            }
            sum += b;
        }
        support[s] = sum / (float)(v->n - 1);
        if (support[s] > best) best = support[s];
    }
    /* a sense that is a part of the same whole as a sense of another class is the one meant:
     * the parts of a whole stand together (the monitor beside the keyboard is the computer's
     * display, both parts of a computer in WordNet, not the equipment that checks
     * transmissions); a whole the scene has as a class is not meant (a capstone is a part of
     * the walls the scene shows, not a thing standing beside them) */
    int shared[LEX_MAX_SENSES] = {0}, any_shared = 0;
    for (int s = 0; s < own; s++)
        for (int h = 0; h < np->senses[s].n_holo && !shared[s]; h++) {
            int whole_shown = 0;
            for (int k = 0; k < v->n && !whole_shown; k++)
                for (int j = 0; j < v->classes[k].np.n_senses && !whole_shown; j++)
                    whole_shown = v->classes[k].np.senses[j].off == np->senses[s].holo[h];
            if (whole_shown) continue;
            for (int k = 0; k < v->n && !shared[s]; k++) {
                if (k == ci) continue;
                const lex_np *o = &v->classes[k].np;
                for (int j = 0; j < o->n_senses && !shared[s]; j++)
                    for (int g = 0; g < o->senses[j].n_holo && !shared[s]; g++)
                        shared[s] = o->senses[j].holo[g] == np->senses[s].holo[h];
            }
        }
    for (int s = 0; s < own; s++) any_shared |= shared[s];
    int kept = 0;
    for (int s = 0; s < np->n_senses; s++)
        if (s >= own || (any_shared ? shared[s] : support[s] >= best - 0.02f)) np->senses[kept++] = np->senses[s];
    np->n_senses = kept;
}

int lex_entries_load(sp_lex_vocab *v, const char *path, const char *member, const char *what,
                     int (*add)(sp_lex_vocab *, const char *, const struct cJSON *, sp_error *), sp_error *err)
{
    cJSON *js = NULL;
    int rc = sp_json_read_file(path, &js, err);
    if (rc) return sp_error_prefix(err, "lexical: %s: ", what);
    const cJSON *entries = cJSON_GetObjectItemCaseSensitive(js, member), *it;
    if (!cJSON_IsObject(entries)) rc = sp_error_set(err, SP_E_FORMAT, "%s: missing object \"%s\"", path, member);
    cJSON_ArrayForEach(it, entries) {
        if (rc) break;
        if (it->string && it->string[0] != '_') rc = add(v, path, it, err);
    }
    cJSON_Delete(js);
    return rc;
}

/* A table of data/semantic/ (name: "aliases.json", "uses.json"), and the user's file of that
 * name beside a region table given by path, when there is one. */
static int load_table(sp_lex_vocab *v, const char *regions_path, const char *name,
                      int (*load)(sp_lex_vocab *, const char *, sp_error *), sp_error *err)
{
    char path[2048], mine[2048], rel[64];
    snprintf(rel, sizeof rel, "semantic/%s", name);
    sp_path_join(path, sizeof path, sp_data_dir(), rel);
    int rc = load(v, path, err);
    const char *slash = regions_path ? strrchr(regions_path, '/') : NULL;
    if (rc || !regions_path || !regions_path[0]) return rc;
    if (slash) snprintf(mine, sizeof mine, "%.*s/%s", (int)(slash - regions_path), regions_path, name);
    else snprintf(mine, sizeof mine, "%s", name);
    if (strcmp(mine, path) && sp_file_exists(mine)) rc = load(v, mine, err);
    return rc;
}

int sp_lex_vocab_create(sp_lex_vocab **out, const sp_lexicon *lx, const char *const *classes,
                        int n, const char *regions_path, sp_error *err)
{
    *out = NULL;
    if (!lx || (!classes && n > 0)) return sp_error_set(err, SP_E_ARG, "lexical: missing argument");
    if (n < 0 || n > SP_LEX_MAX_CLASSES)
        return sp_error_set(err, SP_E_ARG, "lexical: %d classes (at most %d)", n, SP_LEX_MAX_CLASSES);
    sp_lex_vocab *v = calloc(1, sizeof *v);
    if (!v) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    if (pthread_mutex_init(&v->region_lock, NULL) != 0) {
        free(v);
        return sp_error_set(err, SP_E_NOMEM, "lexical: cannot create a lock");
    }
    v->lx = lx;
    v->classes = calloc(n ? (size_t)n : 1, sizeof *v->classes);
    int rc = v->classes ? 0 : sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    if (!rc) rc = load_table(v, regions_path, "aliases.json", lex_aliases_load, err);
    if (!rc) rc = load_table(v, regions_path, "uses.json", lex_uses_load, err);
    for (int i = 0; i < n && !rc; i++) {
        if (!classes[i] || !classes[i][0]) {
            rc = sp_error_set(err, SP_E_ARG, "lexical: class %d has an empty name", i);
            break;
        }
        v->n = i + 1;
        if ((rc = class_prepare(v, &v->classes[i], classes[i], err)))
            sp_error_prefix(err, "lexical: class '%s': ", classes[i]);
        for (int k = 0; k < v->classes[i].n_tok && !rc; k++) rc = add_vocab_word(v, v->classes[i].tok[k], err);
    }
    for (int i = 0; i < v->n && !rc; i++)
        if (v->classes[i].np.fallback) choose_by_context(v, i);
    if (!rc) {
        char path[2048];
        if (!regions_path) sp_path_join(path, sizeof path, sp_data_dir(), "semantic/regions.json");
        else snprintf(path, sizeof path, "%s", regions_path);
        if (path[0]) rc = lex_regions_load(v, path, err);
    }
    if (rc) {
        sp_lex_vocab_free(v);
        return rc;
    }
    *out = v;
    return 0;
}
