/* Scoring one noun phrase against every class of a vocabulary: exact names, the taxonomy of head
 * nouns (synonym, hypernym, hyponym, part, related), modifiers, description words against the
 * classes' definitions, and the modifier-as-referent reading of compounds ("tv monitor"). The
 * formula is documented in semsplat/semantic.h; the constants are in lexical.h. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "lexical.h"

#define MAX_EXP 40

/* A word's expansions for matching definitions: its base forms (factor 1) and the lemmas of its
 * commonest noun and verb senses (factor LEX_SYN). */
typedef struct {
    int n;
    char w[MAX_EXP][WN_LEMMA_MAX];
    float f[MAX_EXP];
} expansion;

static void exp_add(expansion *e, const char *w, float f)
{
    for (int i = 0; i < e->n; i++)
        if (!strcmp(e->w[i], w)) {
            if (f > e->f[i]) e->f[i] = f;
            return;
        }
    if (e->n == MAX_EXP) return;
    snprintf(e->w[e->n], WN_LEMMA_MAX, "%s", w);
    e->f[e->n++] = f;
}

/* 1 when synset s is the commonest sense of lemma w: a synonym stands in for the word only
 * where it would be read so ("pee" -> "water" of the urine synset: a definition's "water" is
 * the liquid, not urine). */
static int commonest_of(const lex_db *lx, const char *w, const wn_synset *s)
{
    uint32_t off;
    sp_error err = {0};
    return lx && wn_lookup(lx->db, (wn_pos)s->id.pos, w, &off, 1, NULL, &err) == 1 && off == s->id.offset;
}

/* Adds the single-word lemmas of synset s at f (lower case); heads: and the last word of the
 * others ("low_temperature" -> temperature); lx: only lemmas whose commonest sense s is. */
static void exp_add_words(const lex_db *lx, expansion *e, const wn_synset *s, float f, int heads)
{
    for (int k = 0; k < s->n_words; k++) {
        char w[WN_LEMMA_MAX];
        snprintf(w, sizeof w, "%s", s->words[k]);
        for (char *q = w; *q; q++) *q = (char)(*q >= 'A' && *q <= 'Z' ? *q - 'A' + 'a' : *q);
        const char *last = strrchr(w, '_');
        if (!last && (!lx || commonest_of(lx, w, s))) exp_add(e, w, f);
        else if (last && heads) exp_add(e, last + 1, f);
    }
}

/* Adds the lemmas of synset id at f, multi-word ones by their head. */
static int exp_add_synset(const lex_db *lx, wn_id id, expansion *e, float f, sp_error *err)
{
    wn_synset s;
    int rc = wn_read(lx->db, id, &s, err);
    if (rc) return rc;
    exp_add_words(NULL, e, &s, f, 1);
    wn_synset_free(&s);
    return 0;
}

/* An adjective's commonest sense by the nouns WordNet derives from it ("+": hot -> hotness, heat,
 * high temperature: "hot water" meets "heated water"; cold -> coldness, low temperature), one weak
 * step like a synonym (LEX_SYN). */
static int expand_adjective(const lex_db *lx, const char *base, expansion *e, sp_error *err)
{
    uint32_t off;
    int n = wn_lookup(lx->db, WN_ADJ, base, &off, 1, NULL, err);
    if (n <= 0) return n;
    wn_synset s;
    int rc = wn_read(lx->db, (wn_id){off, WN_ADJ}, &s, err);
    if (rc) return rc;
    for (int k = 0; !rc && k < s.n_pointers; k++)
        if (!strcmp(s.pointers[k].symbol, "+") && s.pointers[k].target.pos == WN_NOUN)
            rc = exp_add_synset(lx, s.pointers[k].target, e, LEX_SYN, err);
    wn_synset_free(&s);
    return rc;
}

static int expand(const lex_db *lx, const char *word, expansion *e, sp_error *err)
{
    e->n = 0;
    exp_add(e, word, 1.0f);
    for (int p = 0; p < 3; p++) {
        char b[WN_MAX_BASES][WN_LEMMA_MAX];
        int nb = lex_bases(lx, (wn_pos)p, word, b, err);
        if (nb < 0) return nb;
        for (int k = 0; k < nb; k++) exp_add(e, b[k], 1.0f);
        if (nb == 0) continue;
        if (p == WN_ADJ) {
            int rc = expand_adjective(lx, b[0], e, err);
            if (rc) return rc;
            continue;
        }
        uint32_t off;
        int n = wn_lookup(lx->db, (wn_pos)p, b[0], &off, 1, NULL, err);
        if (n < 0) return n;
        if (n == 0) continue;
        wn_synset s;
        wn_id id = {off, (uint8_t)p};
        int rc = wn_read(lx->db, id, &s, err);
        if (rc) return rc;
        exp_add_words(lx, e, &s, LEX_SYN, 0);
        /* a verb's commonest sense also by the nouns WordNet derives from it ("+": type ->
         * typewriter, store -> storage), the same one weak step */
        for (int k = 0; p == WN_VERB && k < s.n_pointers && !rc; k++) {
            const wn_pointer *pt = &s.pointers[k];
            if (strcmp(pt->symbol, "+") || pt->target.pos != WN_NOUN || !pt->target_word) continue;
            wn_synset ns;
            if ((rc = wn_read(lx->db, pt->target, &ns, err))) break;
            if (pt->target_word <= ns.n_words && !strchr(ns.words[pt->target_word - 1], '_') &&
                commonest_of(lx, ns.words[pt->target_word - 1], &ns)) {
                char w[WN_LEMMA_MAX];
                snprintf(w, sizeof w, "%s", ns.words[pt->target_word - 1]);
                for (char *q = w; *q; q++) *q = (char)(*q >= 'A' && *q <= 'Z' ? *q - 'A' + 'a' : *q);
                exp_add(e, w, LEX_SYN);
            }
            wn_synset_free(&ns);
        }
        wn_synset_free(&s);
        if (rc) return rc;
    }
    return 0;
}

/* Best weight of word (its expansions) in a class's bag, patient entries scaled by pf (own: not
 * in its kinds' definitions); why gets "word (source)". */
static float bag_match(const lex_class *c, const expansion *e, const char *word, float pf, float af, int own,
                       char *why, size_t cap)
{
    float best = 0;
    int src = -1;
    for (int i = 0; i < e->n; i++) {
        char one[1][WN_LEMMA_MAX];
        snprintf(one[0], WN_LEMMA_MAX, "%s", e->w[i]);
        int s = -1;
        /* one indirection at most: a synonym counts in the class's own definition only */
        float w = lex_bag_find(&c->bag, one, 1, e->f[i] < 1.0f ? 1.0f : 0.0f, pf, af, own, &s) * e->f[i];
        if (w > best) best = w, src = s;
    }
    if (best > 0 && why && src >= 0) {
        /* say when the match is the participle's, weakened by a stranded preposition */
        int weak = pf < 1.0f && bag_match(c, e, word, 1.0f, af, own, NULL, 0) > best;
        snprintf(why, cap, "%s (%s)%s", word, c->bag.src[src], weak ? " [participle: what it acts on]" : "");
    }
    return best;
}

/* Gloss overlap G = sum_d w_d m_d / sum_d w_d; pf scales patient entries (see LEX_PATIENT).
 * A kind's definition (one level down, change 46) is evidence of one kind: words found in two
 * kinds' definitions describe two different things ("what heats the house": the double
 * glazing's "heat" and the bay window's "house" make no window that heats a house), so m_d is
 * the best of the class's own entries and those of the one kind that explains the most. */
typedef struct {
    short src, word;
    float v;
} kind_hit;

static float gloss_overlap(const lex_class *c, const expansion *exps, const float *w, int n,
                           const char (*words)[LEX_WORD], float pf, float af, char *why, size_t cap)
{
    float own[24] = {0}, den = 0;
    int own_src[24];
    kind_hit kh[256];
    int nk = 0;
    if (n > 24) n = 24;
    for (int i = 0; i < n; i++) {
        own_src[i] = -1;
        den += w[i];
        for (int k = 0; k < exps[i].n; k++)
            for (int b = 0; b < c->bag.n; b++) {
                const lex_bag_word *e = &c->bag.words[b];
                /* one indirection at most: a synonym counts in the class's own definition only */
                if ((exps[i].f[k] < 1.0f && e->weight < 1.0f) || strcmp(e->w, exps[i].w[k])) continue;
                float f = e->patient == LEX_BAG_PATIENT ? pf : e->patient == LEX_BAG_AGENT ? af : 1.0f;
                float v = e->weight * f * exps[i].f[k];
                if (!e->kind) {
                    if (v > own[i]) own[i] = v, own_src[i] = e->src;
                    continue;
                }
                int j = 0;
                while (j < nk && (kh[j].src != e->src || kh[j].word != i)) j++;
                if (j == nk && nk < 256) kh[nk++] = (kind_hit){e->src, (short)i, 0};
                if (j < nk && v > kh[j].v) kh[j].v = v;
            }
    }
    float num = 0;
    for (int i = 0; i < n; i++) num += w[i] * own[i];
    int best_src = -1;
    for (int j = 0; j < nk; j++) { /* each kind that some word was found in */
        int seen = 0;
        for (int q = 0; q < j; q++) seen |= kh[q].src == kh[j].src;
        if (seen) continue;
        float t = 0;
        for (int i = 0; i < n; i++) {
            float m = own[i];
            for (int q = j; q < nk; q++)
                if (kh[q].src == kh[j].src && kh[q].word == i && kh[q].v > m) m = kh[q].v;
            t += w[i] * m;
        }
        if (t > num) num = t, best_src = kh[j].src;
    }
    if (why && cap) {
        size_t o = 0;
        why[0] = 0;
        for (int i = 0; i < n && o + 1 < cap; i++) {
            int src = own_src[i];
            float m = own[i];
            for (int q = 0; q < nk; q++)
                if (kh[q].src == best_src && kh[q].word == i && kh[q].v > m) m = kh[q].v, src = best_src;
            if (m <= 0 || src < 0) continue;
            int k = snprintf(why + o, cap - o, "%s%s (%s)", o ? "; " : "", words[i], c->bag.src[src]);
            if (k > 0) o += (size_t)k;
        }
    }
    return den > 0 ? num / den : 0;
}

static int is_exact(const lex_np *np, const lex_class *c, const char (*mod_base)[WN_LEMMA_MAX])
{
    if (!np->head[0]) return 0;
    char seq[LEX_MAX_TOKENS][WN_LEMMA_MAX];
    int n = 0;
    /* a WordNet collocation among the modifiers ("blood_pressure monitor") is its words, as the
     * class name's are */
    for (int i = 0; i < np->n_mods - np->split && n < LEX_MAX_TOKENS; i++) {
        char mod[WN_LEMMA_MAX];
        snprintf(mod, sizeof mod, "%s", mod_base[i]);
        /* and a hyphenated modifier is its words ("roll-up door" is the roll up door) */
        for (char *save = NULL, *t = strtok_r(mod, "_-", &save); t && n < LEX_MAX_TOKENS;
             t = strtok_r(NULL, "_-", &save))
            snprintf(seq[n++], WN_LEMMA_MAX, "%s", t);
    }
    char head[WN_LEMMA_MAX];
    snprintf(head, sizeof head, "%s", np->head);
    for (char *save = NULL, *t = strtok_r(head, "_-", &save); t && n < LEX_MAX_TOKENS;
         t = strtok_r(NULL, "_-", &save))
        snprintf(seq[n++], WN_LEMMA_MAX, "%s", t);
    if (n != c->n_tok) {
        /* one-word spellings of two-word names and back ("bookshelf", "book shelf") */
        char a[256] = "", b[256] = "";
        for (int i = 0; i < n; i++) strncat(a, seq[i], sizeof a - strlen(a) - 1);
        for (int i = 0; i < c->n_tok; i++) strncat(b, c->tok[i], sizeof b - strlen(b) - 1);
        return !strcmp(a, b);
    }
    for (int i = 0; i < n; i++)
        if (strcmp(seq[i], c->tok[i])) return 0;
    return 1;
}

/* 1 when a hyphenated word's parts, or a WordNet collocation's words, are all words of class c's
 * name ("roll-up" of "roll up door", "first_aid" of "first aid kit"), as is_exact reads them. */
static int parts_in_name(const char *w, const lex_class *c)
{
    if (!strchr(w, '-') && !strchr(w, '_')) return 0;
    char buf[WN_LEMMA_MAX];
    snprintf(buf, sizeof buf, "%s", w);
    int all = 1;
    for (char *save = NULL, *t = strtok_r(buf, "-_", &save); t && all; t = strtok_r(NULL, "-_", &save)) {
        int in = 0;
        for (int k = 0; k < c->n_tok && !in; k++) in = !strcmp(c->tok[k], t);
        all = in;
    }
    return all;
}

static float wup3(int depth_lcs, int dq, int dc)
{
    return 2.0f * (float)depth_lcs / (float)(dq + dc + 2 * depth_lcs);
}

/* A name made of a noun modifier and a head ("shoe cabinet") is one level below the head's
 * sense: the head alone is its hypernym, and another kind of the head ("dresser", a cabinet) is
 * its sibling, not a match. The comparison t of the head senses is redone with the class's path
 * one step longer (cspec), and the query's when it is a closed compound WordNet lacks, split
 * into a modifier and a head (qspec: one word names one particular kind, "nightstand" is no IV
 * stand). */
static lex_tax specialize(lex_tax t, const lex_sense *q, const lex_sense *c, int qspec, int cspec)
{
    int dq, dc, dep;
    switch (t.kind) {
    case SP_LEX_SYNONYM: dq = 0, dc = 0, dep = c->anc[0].depth; break;
    case SP_LEX_HYPERNYM: dq = 0, dc = c->anc[t.c_anc].dist, dep = q->anc[0].depth; break;
    case SP_LEX_HYPONYM: dq = q->anc[t.q_anc].dist, dc = 0, dep = c->anc[0].depth; break;
    case SP_LEX_RELATED: dq = q->anc[t.q_anc].dist, dc = c->anc[t.c_anc].dist, dep = c->anc[t.c_anc].depth; break;
    default: return t;
    }
    dc += cspec, dq += qspec;
    lex_tax r = t;
    if (dq == 0) r.score = wup3(dep, 0, dc), r.kind = SP_LEX_HYPERNYM;
    else if (dc == 0) r.score = wup3(dep, dq, 0), r.kind = SP_LEX_HYPONYM;
    else r.score = LEX_MU * wup3(dep, dq, dc), r.kind = SP_LEX_RELATED;
    return r;
}

/* The best taxonomic comparison of two sense sets; cspec / qspec: the class / the query is one
 * level below its head. */
static lex_tax best_tax(const lex_sense *qs, int nq, const lex_sense *cs, int nc, int qspec, int cspec,
                        int *bq, int *bc)
{
    lex_tax best = {0, SP_LEX_NONE, -1, -1};
    *bq = *bc = -1;
    for (int i = 0; i < nq; i++)
        for (int j = 0; j < nc; j++) {
            lex_tax t = lex_compare(&qs[i], &cs[j]);
            if (cspec || qspec) t = specialize(t, &qs[i], &cs[j], qspec, cspec);
            if (t.score > best.score) best = t, *bq = i, *bc = j;
        }
    return best;
}

static float best_wup(const lex_sense *qs, int nq, const lex_sense *cs, int nc)
{
    float best = 0;
    for (int i = 0; i < nq; i++)
        for (int j = 0; j < nc; j++) {
            float w = lex_wup(&qs[i], &cs[j]);
            if (w > best) best = w;
        }
    return best;
}

static void describe_tax(sp_lex_class_match *m, const lex_tax *t, const lex_sense *q, const lex_sense *c)
{
    snprintf(m->query_sense, sizeof m->query_sense, "%s", q->anc[0].name);
    snprintf(m->class_sense, sizeof m->class_sense, "%s", c->anc[0].name);
    snprintf(m->definition, sizeof m->definition, "%s", c->definition);
    if (t->kind == SP_LEX_HYPERNYM) lex_path(c, t->c_anc, m->path, sizeof m->path);
    else if (t->kind == SP_LEX_HYPONYM) lex_path(q, t->q_anc, m->path, sizeof m->path);
    else if (t->kind == SP_LEX_RELATED) {
        char a[128], b[128];
        lex_path(c, t->c_anc, a, sizeof a);
        lex_path(q, t->q_anc, b, sizeof b);
        snprintf(m->path, sizeof m->path, "%s | %s", a, b);
    } else if (t->kind == SP_LEX_PART)
        snprintf(m->path, sizeof m->path, "%s is part of %s", q->anc[0].name, c->anc[0].name);
}

/* Per query: the modifiers' base forms, expansions and (for those that name a class) senses. */
typedef struct {
    char mod_base[8][WN_LEMMA_MAX];
    expansion mod_exp[8], desc_exp[16];
    lex_np ref[8]; /* modifier (or first part of a joined head) read as a noun of its own */
    int n_ref;
    char ref_word[8][LEX_WORD];
    int n_agent;   /* verbs the head is the agent noun of ("dispenser" <- dispense) */
    char agent[4][WN_LEMMA_MAX];
    float agent_w, mod_w[8]; /* informativeness of the head and of each modifier */
    int mod_kind[8];       /* modifier i names a kind of thing (kind_modifier) ... */
    char mod_act[8][WN_LEMMA_MAX]; /* the verb of modifier i when an -ing form ("rowing") */
    int mod_noun[8];       /* modifier i is a noun or a word WordNet lacks, no adjective: it
                            * makes the query a particular kind of its head (noun_modifier) */
    lex_np mod_np[8];      /* ... read alone, every noun sense */
    lex_bag mod_bag[8];    /* ... and its commonest sense's lemmas and definition */
    int holder;            /* the query's head is a support that holds things (lex_np_support) */
    lex_np desc_np[16];    /* description nouns read alone (not the purpose verb): what a holder
                            * class may hold ("where do I put my SUITCASE") */
    /* query senses defined as "any <kind> <condition>" ("light: any device serving as a source
     * of illumination"): the sense, and its definition's words with their weights */
    int n_any, any_sense[2], any_n[2];
    char any_word[2][12][LEX_WORD];
    expansion any_exp[2][12];
    float any_w[2][12];
} query_prep;

/* 1 when noun is an agent noun of verb: the verb's stem (a final 'e' dropped) followed by -er,
 * -or or -ar, a consonant doubled ("dispenser" <- dispense, "projector" <- project, "shredder" <-
 * shred). */
static int agent_of(const char *noun, const char *verb)
{
    size_t nv = strlen(verb), nn = strlen(noun);
    if (nv > 1 && verb[nv - 1] == 'e') nv--;
    if (nn < nv + 2 || strncmp(noun, verb, nv)) return 0;
    const char *rest = noun + nv;
    if (rest[0] == verb[nv - 1] && strlen(rest) == 3) rest++; /* doubled consonant */
    return !strcmp(rest, "er") || !strcmp(rest, "or") || !strcmp(rest, "ar");
}

/* The verbs a query head names the doer of: WordNet's derivational links ("+") from the head's
 * physical senses that are not persons to verbs whose lemma it is the agent noun of. */
static int agent_verbs(const lex_db *lx, const lex_np *np, query_prep *qp, sp_error *err)
{
    qp->n_agent = 0;
    if (!np->head[0] || np->placeholder || strchr(np->head, '_')) return 0;
    for (int i = 0; i < np->n_senses; i++) {
        /* an object that does it: a person ("writer", "keeper") is no object of the scene */
        if (!lex_sense_physical(&np->senses[i]) || lex_sense_person(&np->senses[i])) continue;
        wn_synset s;
        int rc = wn_read(lx->db, (wn_id){np->senses[i].off, WN_NOUN}, &s, err);
        if (rc) return rc;
        for (int p = 0; p < s.n_pointers && !rc; p++) {
            const wn_pointer *pt = &s.pointers[p];
            if (strcmp(pt->symbol, "+") || pt->target.pos != WN_VERB) continue;
            wn_synset vs;
            if ((rc = wn_read(lx->db, pt->target, &vs, err))) break;
            int k = pt->target_word ? pt->target_word - 1 : 0;
            if (k < vs.n_words && agent_of(np->head, vs.words[k]) && qp->n_agent < 4) {
                int dup = 0;
                for (int j = 0; j < qp->n_agent; j++) dup |= !strcmp(qp->agent[j], vs.words[k]);
                if (!dup) snprintf(qp->agent[qp->n_agent++], WN_LEMMA_MAX, "%s", vs.words[k]);
            }
            wn_synset_free(&vs);
        }
        wn_synset_free(&s);
        if (rc) return rc;
    }
    return 0;
}

/* any_* of qp (see query_prep). */
static int prepare_any(const lex_db *lx, const lex_np *np, query_prep *qp, sp_error *err)
{
    int rc = 0;
    for (int i = 0; i < np->n_senses && qp->n_any < 2 && !rc; i++) {
        if (strncmp(np->senses[i].definition, "any ", 4)) continue;
        int k = qp->n_any, n = 0;
        lex_tokens t;
        char def[192];
        snprintf(def, sizeof def, "%s", np->senses[i].definition);
        def[strcspn(def, "(;")] = 0; /* the condition, without examples or asides */
        lex_tokenize(def, &t);
        for (int j = 1; j < t.n && n < 12 && !rc; j++) {
            if (strlen(t.w[j]) < 2 || lex_word_class_of(t.w[j]) != LW_CONTENT) continue;
            snprintf(qp->any_word[k][n], LEX_WORD, "%s", t.w[j]);
            if (!(rc = expand(lx, t.w[j], &qp->any_exp[k][n], err))) rc = lex_word_weight(lx, t.w[j], &qp->any_w[k][n], err);
            n++;
        }
        qp->any_sense[k] = i, qp->any_n[k] = n, qp->n_any++;
    }
    return rc;
}

/* 1 when a query modifier names a kind of thing by its commonest noun sense (an artifact, a food,
 * a plant or an animal: "wine", "shoe", "coffee", "flower"; WordNet's lexicographer files) and has
 * no adjective reading: it says which kind of the head is meant ("WINE rack"), so it is no
 * attribute to ignore. A substance or material ("leather", "glass", "oak" whose commonest sense is
 * the wood), a colour, an act or a person stays an attribute. *s gets that sense. */
/* 1 when word reads as an adjective: it has an adjective base that the tagged corpora attest,
 * or a noun base they do not ("coffee" the colour is no corpus's reading beside coffee the
 * drink: WordNet's order only); negative on read errors. */
static int adj_reading(const lex_db *lx, const char *word, const char *base, sp_error *err)
{
    char b[WN_MAX_BASES][WN_LEMMA_MAX];
    int n = wn_morphy(lx->db, WN_ADJ, word, b, err);
    if (n <= 0) return n;
    uint32_t off;
    int at = 0, nt = 0;
    for (int i = 0; i < n; i++) {
        int t = 0, k = wn_lookup(lx->db, WN_ADJ, b[i], &off, 1, &t, err);
        if (k < 0) return k;
        at += t;
    }
    int k = wn_lookup(lx->db, WN_NOUN, base, &off, 1, &nt, err);
    if (k < 0) return k;
    return at > 0 || nt == 0;
}

static int kind_modifier(const lex_db *lx, const char *word, const char *base, lex_np *np, lex_bag *bag,
                         sp_error *err)
{
    int adj = adj_reading(lx, word, base, err);
    if (adj) return adj < 0 ? adj : 0;
    /* an -ing form of a verb describes ("hanging" lamp, "serving" counter): a participle */
    size_t n = strlen(word);
    if (n > 4 && !strcmp(word + n - 3, "ing")) {
        int verb = lex_is_pos(lx, WN_VERB, word, err);
        if (verb) return verb < 0 ? verb : 0;
    }
    uint32_t off;
    int tagged = 0;
    int k = wn_lookup(lx->db, WN_NOUN, base, &off, 1, &tagged, err);
    if (k <= 0) return k;
    if (!tagged) return 0; /* no attested sense: WordNet's order says nothing (change 23) */
    wn_synset syn;
    int rc = wn_read(lx->db, (wn_id){off, WN_NOUN}, &syn, err);
    if (rc) return rc;
    int f = syn.lexfile;
    wn_synset_free(&syn);
    if (!wn_lexfile_names_kind(f)) return 0;
    lex_tokens one = {1, {{0}}};
    snprintf(one.w[0], LEX_WORD, "%s", base);
    if ((rc = lex_np_parse(lx, &one, 0, 1, 0, np, err))) return rc;
    if ((rc = lex_bag_synset(lx, bag, (wn_id){off, WN_NOUN}, 1.0f, 0, err))) return rc;
    return np->n_senses > 0;
}

/* 1 when a query modifier is a noun without an adjective reading, or no word WordNet has at all
 * ("DOCK door", "LOADING bay door"): as for a class name (class_prepare), it names a particular
 * kind of the head, where an adjective ("red", "front") describes it, and so does a noun whose
 * commonest sense is a material, a quality or a shape ("steel", "leather": phase 9's rule). */
static int noun_modifier(const lex_db *lx, const char *word, const char *base, sp_error *err)
{
    int adj = lex_is_pos(lx, WN_ADJ, word, err);
    if (adj) return adj < 0 ? adj : 0;
    uint32_t off;
    int k = wn_lookup(lx->db, WN_NOUN, base, &off, 1, NULL, err);
    if (k < 0) return k;
    if (k > 0) {
        wn_synset syn;
        int rc = wn_read(lx->db, (wn_id){off, WN_NOUN}, &syn, err);
        if (rc) return rc < 0 ? rc : -rc;
        int f = syn.lexfile;
        wn_synset_free(&syn);
        return f != WN_LEX_SUBSTANCE && f != WN_LEX_ATTRIBUTE && f != WN_LEX_SHAPE;
    }
    for (int p = 0; p < WN_NPOS; p++) {
        int is = lex_is_pos(lx, (wn_pos)p, word, err);
        if (is) return is < 0 ? is : 0;
    }
    return 1;
}

static int prepare(const sp_lex_vocab *v, const lex_np *np, query_prep *qp, sp_error *err)
{
    const lex_db *lx = v->lx;
    int rc = 0;
    for (int i = 0; i < np->n_mods && !rc; i++) {
        char b[WN_MAX_BASES][WN_LEMMA_MAX];
        int nb = lex_bases(lx, WN_NOUN, np->mods[i], b, err);
        if (nb < 0) return nb;
        snprintf(qp->mod_base[i], WN_LEMMA_MAX, "%s", nb > 0 ? b[0] : np->mods[i]);
        rc = expand(lx, np->mods[i], &qp->mod_exp[i], err);
        if (!rc && !(np->split && i == np->n_mods - 1)) {
            int k = kind_modifier(lx, np->mods[i], qp->mod_base[i], &qp->mod_np[i], &qp->mod_bag[i], err);
            if (k < 0) return k;
            qp->mod_kind[i] = k;
            int ing = lex_ing_verb(lx, np->mods[i], qp->mod_act[i], err);
            if (ing < 0) return ing;
            int nm = noun_modifier(lx, np->mods[i], qp->mod_base[i], err);
            if (nm < 0) return nm;
            qp->mod_noun[i] = nm;
            if (nm && !k) { /* its senses, to tell a related modifier (modifier_related) */
                lex_tokens one = {1, {{0}}};
                snprintf(one.w[0], LEX_WORD, "%s", qp->mod_base[i]);
                if ((rc = lex_np_parse(lx, &one, 0, 1, 0, &qp->mod_np[i], err))) return rc;
            }
        }
    }
    for (int i = 0; i < np->n_desc && !rc; i++) {
        rc = expand(lx, np->desc[i], &qp->desc_exp[i], err);
        int verb = !rc && i == 0 && np->n_desc > 1 ? lex_is_pos(lx, WN_VERB, np->desc[i], err) : 0;
        if (verb < 0) return verb;
        if (!rc && !verb) {
            lex_tokens one = {1, {{0}}};
            snprintf(one.w[0], LEX_WORD, "%s", np->desc[i]);
            rc = lex_np_parse(lx, &one, 0, 1, 1, &qp->desc_np[i], err);
        }
    }
    qp->holder = np->head[0] && !np->placeholder && lex_np_support(np);
    if (!rc) rc = agent_verbs(lx, np, qp, err);
    if (!rc && !np->placeholder) rc = prepare_any(lx, np, qp, err);
    if (!rc && qp->n_agent) rc = lex_word_weight(lx, np->head, &qp->agent_w, err);
    for (int i = 0; i < np->n_mods && !rc && qp->n_agent; i++) rc = lex_word_weight(lx, np->mods[i], &qp->mod_w[i], err);
    /* Candidates for the modifier-as-referent reading: modifiers, and the leading words of a
     * joined head ("tv" of "tv_monitor"), that are words of this scene's class names. */
    char cand[8][LEX_WORD];
    int nc = 0;
    for (int i = 0; i < np->n_mods && nc < 8; i++) snprintf(cand[nc++], LEX_WORD, "%s", qp->mod_base[i]);
    if (strchr(np->head, '_')) {
        char h[WN_LEMMA_MAX];
        snprintf(h, sizeof h, "%s", np->head);
        char *last = strrchr(h, '_');
        *last = 0;
        for (char *save = NULL, *t = strtok_r(h, "_", &save); t && nc < 8; t = strtok_r(NULL, "_", &save))
            snprintf(cand[nc++], LEX_WORD, "%s", t);
    }
    for (int i = 0; i < nc && !rc; i++) {
        if (!lex_vocab_has_word(v, cand[i]) || !np->n_senses) continue;
        lex_tokens one = {1, {{0}}};
        snprintf(one.w[0], LEX_WORD, "%s", cand[i]);
        lex_np *r = &qp->ref[qp->n_ref];
        if ((rc = lex_np_parse(lx, &one, 0, 1, 0, r, err))) break;
        if (r->n_senses) snprintf(qp->ref_word[qp->n_ref++], LEX_WORD, "%s", cand[i]);
        else lex_np_free(r);
    }
    return rc;
}

/* The agent reading of a head ("water dispenser"): a class whose own definition says it does the
 * verb (base or -ing form, not the past participle: "pictures can be PROJECTED" is no projector)
 * is one weak step (DELTA) away, times the share of the query's modifiers its definitions name.
 * Returns the score; why gets the evidence, used[i] whether modifier i was found. */
/* 1 when the class's own definitions say the thing does verb: not as what it is acted on (a
 * participle) nor as what its users do ("a wheelchair: ... for those who cannot WALK" is no
 * walker). */
static int agent_entry(const lex_bag *b, const char *verb, int *src)
{
    for (int i = 0; i < b->n; i++) {
        const lex_bag_word *e = &b->words[i];
        if (e->weight >= 1.0f && e->patient != LEX_BAG_PATIENT && e->patient != LEX_BAG_PERSON &&
            !strcmp(e->w, verb)) {
            *src = e->src;
            return 1;
        }
    }
    return 0;
}

static float agent_score(const lex_class *c, const lex_np *np, const query_prep *qp, int *used, char *why,
                         size_t cap)
{
    int src = -1;
    for (int a = 0; a < qp->n_agent && src < 0; a++) {
        char one[1][WN_LEMMA_MAX];
        snprintf(one[0], WN_LEMMA_MAX, "%s", qp->agent[a]);
        if (!agent_entry(&c->bag, qp->agent[a], &src)) src = -1;
        else if (why) snprintf(why, cap, "%s '%s' (%s)", np->head, qp->agent[a], c->bag.src[src]);
    }
    if (src < 0) return 0;
    float num = qp->agent_w, den = qp->agent_w;
    for (int i = 0; i < np->n_mods - np->split; i++) {
        float m = bag_match(c, &qp->mod_exp[i], np->mods[i], 1.0f, 1.0f, 1, NULL, 0);
        used[i] = m > 0;
        num += qp->mod_w[i] * m, den += qp->mod_w[i];
    }
    return LEX_DELTA * num / den;
}

/* 1 when the query is a split closed compound whose first part is no word of class c's name:
 * another particular kind of the head ("nightstand" against "iv stand"); "whiteboards" against
 * "whiteboard" agrees. */
static int split_kind(const lex_np *np, const lex_class *c)
{
    if (!np->split || np->n_mods < 1) return 0;
    for (int k = 0; k < c->n_tok; k++)
        if (!strcmp(c->tok[k], np->mods[np->n_mods - 1])) return 0;
    for (int k = 0; k < c->n_part; k++)
        if (!strcmp(c->part[k], np->mods[np->n_mods - 1])) return 0;
    for (int k = 0; k < c->np.n_mods; k++) /* the class split the same way ("white" + "board") */
        if (!strcmp(c->np.mods[k], np->mods[np->n_mods - 1])) return 0;
    return 1;
}

/* A name WordNet joins is also a kind of its last word ("machine" -> the washing machine, which
 * WordNet files under home appliance): a query naming that word's sense itself (or a synonym)
 * scores the class one level below it, as for a name WordNet lacks. Only the word itself: the
 * word's own place in WordNet is not the class's ("cooler" is a refrigerator, the water cooler
 * a device), so its hypernyms do not reach the class this way. */
static void name_head_tax(const lex_np *np, const lex_class *c, float *base, sp_lex_class_match *m)
{
    const lex_np *h = &c->name_head;
    for (int i = 0; i < np->n_senses; i++)
        for (int j = 0; j < h->n_senses; j++) {
            lex_tax t = lex_compare(&np->senses[i], &h->senses[j]);
            if (t.kind != SP_LEX_SYNONYM) continue;
            t = specialize(t, &np->senses[i], &h->senses[j], split_kind(np, c), 1);
            if (t.score <= *base) continue;
            *base = t.score;
            m->kind = t.kind;
            describe_tax(m, &t, &np->senses[i], &h->senses[j]);
        }
}

/* 1 when two senses are one kind: the same, one a kind of the other, or siblings (one direct
 * hypernym in common: "cappuccino" and "espresso", both coffee). */
static int same_kind(const lex_sense *a, const lex_sense *b, int siblings)
{
    if (lex_anc_find(a, b->off) >= 0 || lex_anc_find(b, a->off) >= 0) return 1;
    for (int i = 1; siblings && i < a->n_anc; i++)
        if (a->anc[i].dist == 1)
            for (int j = 1; j < b->n_anc; j++)
                if (b->anc[j].dist == 1 && b->anc[j].off == a->anc[i].off) return 1;
    return 0;
}

/* 1 when the kind-naming query modifier i (kind_modifier) makes the query another kind than class
 * c: the class is a particular kind of the query's head, named by a modifier of its own
 * ("drying rack", "checkout counter"), which the query does not name, and the modifier is no
 * kind of the class's modifier or of one of its senses, nor the other way, nor its sibling by
 * their commonest senses, and neither's definition or lemmas name the other ("bakery: where
 * baked goods (breads and cakes and PASTRIES) are sold" agrees with the pastry case, "drug: a
 * substance used as a MEDICINE" with the medicine cart). A query 'M H' is then a sibling of
 * 'M2 H' ("wine rack" / drying rack), not the class; a class without a modifier accepts it
 * ("office chair" -> chair, "double bed" -> bed). */
static int another_kind(const lex_class *c, const lex_np *np, const query_prep *qp, int i, const int *named)
{
    if (c->n_tok < 2 || !c->n_kind || *named) return 0;
    for (int k = 0; k + 1 < c->n_tok; k++) /* the query's head is the class's modifier ("wire shelving") */
        if (!strcmp(c->tok[k], np->head)) return 0;
    int kind = 0; /* the class's modifier names a kind too ("magazine" rack), not a purpose, a
                   * quality or a material ("storage" shelf, "privacy" curtain, "cardboard" box) */
    for (int k = 0; k < c->n_kind; k++) kind |= c->kind_np[k].n_senses > 0 && wn_lexfile_names_kind(c->kind_lexfile[k]);
    /* a name WordNet joins is a kind of its head by WordNet's own word, whatever its modifier
     * names ("vending machine", "washing machine", "double bed") */
    kind |= c->np.n_mods == 0 && strchr(c->np.head, '_') != NULL;
    /* and so is a name the alias table reads as a WordNet kind ("arcade machine": a slot machine) */
    kind |= c->np.n_alias > 0;
    if (!kind) return 0;
    const lex_np *m = &qp->mod_np[i];
    char parts[WN_LEMMA_MAX], one[1][WN_LEMMA_MAX];
    snprintf(parts, sizeof parts, "%s", qp->mod_base[i]);
    int all_in = 1; /* "ice cream" of "ice cream freezer" */
    for (char *save = NULL, *t = strtok_r(parts, "_", &save); t; t = strtok_r(NULL, "_", &save)) {
        int in = 0;
        for (int k = 0; k < c->n_tok; k++) in |= !strcmp(c->tok[k], t);
        all_in &= in;
    }
    if (all_in) return 0;
    for (int k = 0; k < c->n_kind; k++) {
        const lex_np *m2 = &c->kind_np[k];
        for (int a = 0; a < m->n_senses; a++)
            for (int b = 0; b < m2->n_senses; b++)
                if (same_kind(&m->senses[a], &m2->senses[b], a == 0 && b == 0)) return 0;
        snprintf(one[0], WN_LEMMA_MAX, "%s", c->tok[k]);
        if (lex_bag_find(&qp->mod_bag[i], one, 1, 0.0f, 1.0f, 1.0f, 0, NULL) > 0) return 0;
    }
    snprintf(one[0], WN_LEMMA_MAX, "%s", qp->mod_base[i]);
    if (lex_bag_find(&c->kind_bag, one, 1, 0.0f, 1.0f, 1.0f, 0, NULL) > 0) return 0;
    return 1;
}

/* 1 when query modifier i names the thing by another activity than class c's name ("ROWING
 * machine" / "WASHING machine", "sewing" / "washing"): two purposes, two kinds of the head, a
 * sibling as in another_kind, unless the verbs are one family or c's definitions name the
 * query's verb. */
static int another_activity(const lex_class *c, const query_prep *qp, int i)
{
    const char *a = c->act, *b = qp->mod_act[i];
    if (!a[0] || !b[0]) return 0;
    /* one verb the other's stem: one family ("pack" / "package") */
    if (!strncmp(a, b, strlen(a)) || !strncmp(a, b, strlen(b))) return 0;
    char one[1][WN_LEMMA_MAX];
    snprintf(one[0], WN_LEMMA_MAX, "%s", qp->mod_act[i]);
    return lex_bag_find(&c->bag, one, 1, 0.0f, 1.0f, 1.0f, 0, NULL) <= 0;
}

/* What a holder class holds: the modifier of a name WordNet lacks, or of one it joins ("luggage
 * rack"); NULL for a class that is no holder. */
static const lex_np *held_by(const lex_class *c)
{
    if (c->mod_head.n_senses) return &c->mod_head;
    return c->holder && c->n_kind ? &c->kind_np[c->n_kind - 1] : NULL;
}

/* The taxonomy's score of q against what a holder holds: the same sense, a kind of it or a
 * hypernym of it (0 otherwise). */
static float held_score(const lex_np *q, const lex_np *held)
{
    float t = 0;
    for (int i = 0; i < q->n_senses; i++)
        for (int j = 0; j < held->n_senses; j++) {
            if (!lex_sense_physical(&held->senses[j])) continue;
            lex_tax x = lex_compare(&q->senses[i], &held->senses[j]);
            int related = x.kind == SP_LEX_SYNONYM || x.kind == SP_LEX_HYPERNYM || x.kind == SP_LEX_HYPONYM;
            if (related && x.score > t) t = x.score;
        }
    return t;
}

/* 1 when w (a base form, '_' between words) is the whole name of a class of v. */
static int names_class(const sp_lex_vocab *v, const char *w)
{
    for (int i = 0; i < v->n; i++) {
        const char *a = v->classes[i].name, *b = w;
        while (*a && *b && (*a == *b || (*a == ' ' && *b == '_'))) a++, b++;
        if (!*a && !*b) return 1;
        if (!strcmp(v->classes[i].np.head, w) && v->classes[i].np.n_mods == 0) return 1;
    }
    return 0;
}

/* A description naming what a holder class holds ("where do I put my suitcase": the luggage
 * rack; "where are the plasters", "somewhere to hang my jacket" -> the coat rack): a description
 * noun that is the class's modifier's sense, a kind of it or a hypernym of it scores as the
 * holder reading of that noun alone (LEX_HOLDS times the taxonomy), the rest of the description
 * then weighing as a description beside a head (1 - GAMMA + GAMMA * its overlap). */
static float holder_desc(const sp_lex_vocab *v, const lex_class *c, const lex_np *np, const query_prep *qp, float pf,
                         float af, int *word)
{
    float best = 0;
    *word = -1;
    const lex_np *held = held_by(c);
    for (int d = 0; d < np->n_desc && held; d++) {
        const lex_np *q = &qp->desc_np[d];
        /* a thing the scene has by name is what the description is about ("something to watch
         * TV on" is the tv, not the tv stand that holds it) */
        if (q->head[0] && names_class(v, q->head)) continue;
        float t = held_score(q, held);
        if (t <= 0) continue;
        expansion rest[16];
        float w[16];
        char words[16][LEX_WORD];
        int n = 0;
        for (int k = 0; k < np->n_desc; k++) /* its other objects and attributes, not the verb */
            if (k != d && qp->desc_np[k].n_words)
                rest[n] = qp->desc_exp[k], w[n] = np->desc_w[k], snprintf(words[n++], LEX_WORD, "%s", np->desc[k]);
        float g = n ? gloss_overlap(c, rest, w, n, (const char (*)[LEX_WORD])words, pf, af, NULL, 0) : 1.0f;
        float s = LEX_HOLDS * t * (1.0f - LEX_GAMMA + LEX_GAMMA * g);
        if (s > best) best = s, *word = d;
    }
    return best;
}

/* 1 when class c is a kind WordNet names with one word or collocation of its own (no modifier of
 * the scene's, no split compound), found as a proper kind of the query's head ("atm", a machine),
 * and the kind-naming query modifier i names none of its senses' words or kinds ("COFFEE
 * machine"): the query names another kind of the head, a sibling. */
static int another_named_kind(const lex_class *c, const lex_np *np, const query_prep *qp, int i,
                              const sp_lex_class_match *m)
{
    if (c->np.n_mods || c->np.split || c->n_tok > 1 || m->kind != SP_LEX_HYPERNYM || !np->n_senses) return 0;
    const lex_np *mq = &qp->mod_np[i];
    for (int a = 0; a < mq->n_senses; a++)
        for (int b = 0; b < c->np.n_senses; b++)
            if (same_kind(&mq->senses[a], &c->np.senses[b], 0)) return 0;
    char one[1][WN_LEMMA_MAX];
    snprintf(one[0], WN_LEMMA_MAX, "%s", qp->mod_base[i]);
    return lex_bag_find(&c->bag, one, 1, 0.0f, 1.0f, 1.0f, 0, NULL) <= 0;
}

/* 1 when the query has a noun modifier (noun_modifier) that class c's name does not say, that
 * names no class of the scene and that c's definitions do not mention: the query is then one
 * level below its head, as a class named so is. */
static int query_level(const sp_lex_vocab *v, const lex_class *c, const lex_np *np, const query_prep *qp)
{
    for (int i = 0; i < np->n_mods - np->split; i++) {
        if (!qp->mod_noun[i] || lex_vocab_has_word(v, qp->mod_base[i]) || parts_in_name(qp->mod_base[i], c)) continue;
        int in = 0;
        for (int k = 0; k < c->n_tok && !in; k++) in = !strcmp(c->tok[k], qp->mod_base[i]);
        for (int k = 0; k < c->n_part && !in; k++) in = !strcmp(c->part[k], qp->mod_base[i]);
        if (!in && bag_match(c, &qp->mod_exp[i], np->mods[i], 1.0f, 1.0f, 1, NULL, 0) <= 0) return 1;
    }
    return 0;
}

/* 1 when a class of the scene named below the query's head (c->spec) is at the query's level
 * (query_level) with the same head word and sense: only then does the bare head class give way to it;
 * alone, it stays the query's synonym ("bistro chair" is the chair, not a WordNet kind of one). */
static int level_candidate(const sp_lex_vocab *v, const lex_np *np, const query_prep *qp)
{
    for (int j = 0; j < v->n; j++) {
        const lex_class *o = &v->classes[j];
        if (!o->spec || !o->np.n_senses || strcmp(o->np.head, np->head) || !query_level(v, o, np, qp)) continue;
        int bq, bc;
        lex_tax t = best_tax(np->senses, np->n_senses, o->np.senses, o->np.n_senses, 0, 0, &bq, &bc);
        if (t.kind == SP_LEX_SYNONYM) return 1;
    }
    return 0;
}

/* 1 when query modifier i and a modifier of class c's name are one kind or siblings by their
 * commonest senses ("newspaper" / "magazine", both press; "drug" / "medicine"), or the class's
 * modifier's senses name it: the query then is no cousin of the class. */
static int modifier_related(const lex_class *c, const query_prep *qp, int i)
{
    const lex_np *m = &qp->mod_np[i];
    for (int k = 0; k < c->n_kind; k++)
        for (int a = 0; a < m->n_senses; a++)
            for (int b = 0; b < c->kind_np[k].n_senses; b++)
                if (same_kind(&m->senses[a], &c->kind_np[k].senses[b], a == 0 && b == 0)) return 1;
    char one[1][WN_LEMMA_MAX];
    snprintf(one[0], WN_LEMMA_MAX, "%s", qp->mod_base[i]);
    return lex_bag_find(&c->kind_bag, one, 1, 0.0f, 1.0f, 1.0f, 0, NULL) > 0;
}

/* 1 when some query modifier is at the query's level for c (query_level) and unrelated to c's
 * own modifiers (modifier_related). */
static int cousin_modifier(const sp_lex_vocab *v, const lex_class *c, const lex_np *np, const query_prep *qp)
{
    for (int i = 0; i < np->n_mods - np->split; i++) {
        if (!qp->mod_noun[i] || parts_in_name(qp->mod_base[i], c)) continue;
        int in = 0;
        for (int k = 0; k < c->n_tok && !in; k++) in = !strcmp(c->tok[k], qp->mod_base[i]);
        for (int k = 0; k < c->n_part && !in; k++) in = !strcmp(c->part[k], qp->mod_base[i]);
        if (in || bag_match(c, &qp->mod_exp[i], np->mods[i], 1.0f, 1.0f, 1, NULL, 0) > 0) continue;
        if (!modifier_related(c, qp, i)) return 1;
    }
    return 0;
}

/* The query and the class at their levels (query_level, c->spec) when both name the same head
 * sense: a query "M H" is a kind of H, so a class "H" is its hypernym (WuP one step), and a class
 * "M2 H" WordNet lacks may be the same kind under another name ("dock door" / roll up door), the
 * modifier M then an attribute not shown (EPSILON) unless it names another kind (another_kind:
 * the sibling's MU). Before, the bare class won as a synonym and the specific one lost a step. */
static void level_tax(const sp_lex_vocab *v, const lex_class *c, const lex_np *np, const query_prep *qp,
                      float *base, sp_lex_class_match *m)
{
    if (!np->n_senses || !c->np.n_senses || np->split) return;
    int bq, bc;
    lex_tax t = best_tax(np->senses, np->n_senses, c->np.senses, c->np.n_senses, 0, 0, &bq, &bc);
    if (t.kind == SP_LEX_HYPERNYM && m->kind == SP_LEX_HYPERNYM && cousin_modifier(v, c, np, qp)) {
        /* a kind of H the modifier names, against a class that is another kind of H (its own
         * modifier, or WordNet's own word) the modifier has nothing to do with: cousins, MU
         * ("massage table" / coffee table, "deli counter" / checkout counter) */
        lex_tax r = best_tax(np->senses, np->n_senses, c->np.senses, c->np.n_senses, 1, c->spec, &bq, &bc);
        if (r.score < *base) *base = r.score, m->kind = r.kind;
        return;
    }
    if (t.kind != SP_LEX_SYNONYM || !query_level(v, c, np, qp)) return;
    if (c->spec && !strcmp(c->np.head, np->head) && *base < t.score) { /* the same head word */
        *base = t.score;
        describe_tax(m, &t, &np->senses[bq], &c->np.senses[bc]);
        /* still a hypernym match: the query does not name the class, so a region reading
         * ("the nail station") is still tried (lex_match.c, resolve) */
        m->kind = SP_LEX_HYPERNYM;
        snprintf(m->path, sizeof m->path, "both are kinds of %s named by a modifier", np->head);
    } else if (!c->spec && m->kind == SP_LEX_SYNONYM && level_candidate(v, np, qp)) {
        const lex_sense *cs = &c->np.senses[bc];
        *base = wup3(cs->anc[0].depth, 1, 0);
        m->kind = SP_LEX_HYPONYM;
    }
}

/* 1 when every modifier of class c's name (its words before the last) is a word of the query: a
 * modifier's part ("ticket" of "ticket_office window") or a word of the head collocation before
 * its last ("reception" of WordNet's reception_desk); 2 when some agree only through a lemma of a
 * query modifier's commonest sense or as a kind of it ("baggage", "espresso"); 0 otherwise. */
static int mods_agree(const lex_np *np, const lex_class *c, const char (*mod_base)[WN_LEMMA_MAX],
                      const expansion *mod_exp, const lex_np *mod_np)
{
    if (!c->spec || c->n_tok < 2 || c->joined) return 0;
    char q[LEX_MAX_TOKENS][WN_LEMMA_MAX];
    int n = 0;
    for (int i = 0; i < np->n_mods - np->split && n < LEX_MAX_TOKENS; i++) {
        char mod[WN_LEMMA_MAX];
        snprintf(mod, sizeof mod, "%s", mod_base[i]);
        for (char *save = NULL, *t = strtok_r(mod, "_-", &save); t && n < LEX_MAX_TOKENS; t = strtok_r(NULL, "_-", &save))
            snprintf(q[n++], WN_LEMMA_MAX, "%s", t);
    }
    char head[WN_LEMMA_MAX];
    snprintf(head, sizeof head, "%s", np->head);
    char *last = strrchr(head, '_');
    if (last) {
        *last = 0;
        for (char *save = NULL, *t = strtok_r(head, "_-", &save); t && n < LEX_MAX_TOKENS; t = strtok_r(NULL, "_-", &save))
            snprintf(q[n++], WN_LEMMA_MAX, "%s", t);
    }
    int syn = 0;
    for (int k = 0; k + 1 < c->n_tok; k++) {
        int in = 0;
        for (int i = 0; i < n && !in; i++) in = !strcmp(q[i], c->tok[k]);
        /* or a lemma of a modifier's commonest sense ("baggage" of "luggage trolley") */
        for (int i = 0; i < np->n_mods - np->split && !in && mod_exp; i++)
            for (int e = 1; e < mod_exp[i].n && !in; e++) in = !strcmp(mod_exp[i].w[e], c->tok[k]);
        /* or a kind of it by the modifier's commonest sense ("espresso" of "coffee machine") */
        for (int j = 0; j < c->n_kind && !in && mod_np; j++) {
            if (strcmp(c->kind_np[j].head, c->tok[k])) continue;
            for (int i = 0; i < np->n_mods - np->split && !in; i++)
                for (int b = 0; b < c->kind_np[j].n_senses && b < 2 && !in && mod_np[i].n_senses; b++)
                    in = lex_anc_find(&mod_np[i].senses[0], c->kind_np[j].senses[b].off) > 0;
        }
        if (!in) return 0;
        int exact = 0;
        for (int i = 0; i < n && !exact; i++) exact = !strcmp(q[i], c->tok[k]);
        syn |= !exact;
    }
    return syn ? 2 : 1;
}

/* 1 when class c ("office chair") is the query's head word with other modifiers and a room of the
 * region table lists c by name together with the query's one other modifier as a thing ("desk
 * chair": the office lists the desk and the office chair): the chair that stands with a desk. */
static int company_agree(const sp_lex_vocab *v, const lex_np *np, const lex_class *c, const query_prep *qp)
{
    if (!c->spec || c->n_tok < 2 || np->n_mods - np->split != 1 || np->split || strchr(np->head, '_') ||
        strcmp(c->tok[c->n_tok - 1], np->head))
        return 0;
    const char *m = qp->mod_base[0];
    for (int k = 0; k < c->n_tok; k++)
        if (!strcmp(c->tok[k], m)) return 0;
    for (int r = 0; r < v->n_regions; r++) {
        const lex_region *g = &v->regions[r];
        int has_c = 0, has_m = 0;
        for (int i = 0; i < g->n_members; i++) {
            has_c |= !strcasecmp(g->members[i], c->name);
            has_m |= !strcasecmp(g->members[i], m);
        }
        if (has_c && has_m) return 1;
    }
    return 0;
}

/* Scores class c; mod_use [n_mods] gets what each modifier did. */
static void score_class(const sp_lex_vocab *v, const lex_np *np, const query_prep *qp, int ci,
                        sp_lex_class_match *m, int *mod_use)
{
    const lex_class *c = &v->classes[ci];
    memset(m, 0, sizeof *m);
    m->class_index = ci;
    int has_head = np->head[0] && !np->placeholder && np->n_senses > 0;
    float base = 0;
    int rare = 0; /* the head matched only through a sense no corpus attests, after its first */
    if (has_head && is_exact(np, c, qp->mod_base)) {
        base = 1.0f;
        m->kind = SP_LEX_EXACT;
        snprintf(m->query_sense, sizeof m->query_sense, "%s", np->head);
        snprintf(m->class_sense, sizeof m->class_sense, "%s", c->name);
        if (c->np.n_senses) snprintf(m->definition, sizeof m->definition, "%s", c->np.senses[0].definition);
    } else if (has_head && c->np.n_senses) {
        int bq, bc;
        lex_tax t = best_tax(np->senses, np->n_senses, c->np.senses, c->np.n_senses, split_kind(np, c), c->spec, &bq, &bc);
        base = t.score;
        m->kind = t.kind;
        if (bq >= 0) describe_tax(m, &t, &np->senses[bq], &c->np.senses[bc]);
        rare = bq >= 0 && !np->senses[bq].attested && np->senses[bq].rank > 1;
    }
    /* A query sense defined as any thing of a kind meeting a condition ("light: any device
     * serving as a source of illumination") names the classes below its hypernym that meet it:
     * the taxonomy's score from that hypernym times the share of the definition's words the
     * class's own definitions hold (the lamp, "an artificial source of visible illumination";
     * WordNet makes the light source and the lamp siblings). */
    for (int k = 0; has_head && k < qp->n_any && m->kind != SP_LEX_EXACT; k++) {
        const lex_sense *q = &np->senses[qp->any_sense[k]];
        for (int a = 1; a < q->n_anc; a++) {
            if (q->anc[a].dist != 1) continue;
            for (int j = 0; j < c->np.n_senses; j++) {
                int b = lex_anc_find(&c->np.senses[j], q->anc[a].off);
                if (b < 0) continue;
                float t = wup3(q->anc[a].depth, 0, c->np.senses[j].anc[b].dist + c->spec);
                float g = gloss_overlap(c, qp->any_exp[k], qp->any_w[k], qp->any_n[k],
                                        (const char (*)[LEX_WORD])qp->any_word[k], 1.0f, 1.0f, NULL, 0);
                if (t * g <= base) continue;
                base = t * g;
                m->kind = SP_LEX_HYPERNYM;
                snprintf(m->query_sense, sizeof m->query_sense, "%s", q->anc[0].name);
                snprintf(m->class_sense, sizeof m->class_sense, "%s", c->np.senses[j].anc[0].name);
                snprintf(m->definition, sizeof m->definition, "%s", c->np.senses[j].definition);
                snprintf(m->path, sizeof m->path, "'%s' is any %s that meets its definition: %s", q->anc[0].name,
                         q->anc[a].name, q->definition);
            }
        }
    }
    /* A name WordNet joins is also a kind of its last word ("machine" -> the washing machine,
     * which WordNet files under home appliance): the query against that word's senses, the
     * class one level below them, as for a name WordNet lacks. */
    if (has_head && m->kind != SP_LEX_EXACT && c->name_head.n_senses) name_head_tax(np, c, &base, m);
    if (has_head && m->kind != SP_LEX_EXACT) level_tax(v, c, np, qp, &base, m);
    /* The query's words hold the class's modifiers ("ticket desk", "reception desk" against the
     * ticket counter, the reception counter): the same kind named by the same words, so the heads
     * are compared without the class's extra level, and heads that are siblings by the query's
     * commonest or attested sense ("desk", "counter": both furniture) by Wu-Palmer one weak step
     * (DELTA), not as cousins (MU). */
    int agree = has_head && m->kind != SP_LEX_EXACT && c->np.n_senses ? mods_agree(np, c, qp->mod_base, qp->mod_exp, qp->mod_np) : 0;
    /* the thing that stands with what the modifier names: "desk chair" -> the office chair, one
     * weak step (LEX_SYN) from the head's own sense */
    int company = has_head && m->kind != SP_LEX_EXACT && !agree && c->np.n_senses && company_agree(v, np, c, qp);
    for (int i = 0; company && i < np->n_senses; i++)
        for (int j = 0; j < c->np.n_senses; j++) {
            lex_tax t = lex_compare(&np->senses[i], &c->np.senses[j]);
            if (t.kind != SP_LEX_SYNONYM || LEX_SYN * t.score <= base) continue;
            base = LEX_SYN * t.score;
            m->kind = SP_LEX_HYPERNYM;
            describe_tax(m, &t, &np->senses[i], &c->np.senses[j]);
            snprintf(m->path, sizeof m->path, "a room lists the %s with the %s", c->name, qp->mod_base[0]);
        }
    int sibling = 0; /* the score is that of another head through the shared modifiers */
    /* a modifier that is itself a class of the scene ("DESK chair" beside the desk) says where
     * the thing is or what it serves, not a name two kinds share: no sibling reading */
    int mod_is_class = 0;
    for (int i = 0; agree && i < np->n_mods - np->split && !mod_is_class; i++)
        for (int j = 0; j < v->n && !mod_is_class; j++) mod_is_class = !strcmp(v->classes[j].name, qp->mod_base[i]);
    if (agree) {
        for (int i = 0; i < np->n_senses; i++)
            for (int j = 0; j < c->np.n_senses; j++) {
                lex_tax t = lex_compare(&np->senses[i], &c->np.senses[j]);
                if (t.kind == SP_LEX_NONE) continue;
                float sc = t.score;
                if (t.kind == SP_LEX_RELATED) {
                    if (!np->senses[i].attested || strchr(np->head, '_') || mod_is_class) continue;
                    /* through an ancestor as general as an artifact, a structure, an
                     * instrumentality (depth < 6) they are no siblings ("safety barrier" / safety cone) */
                    if (c->np.senses[j].anc[t.c_anc].depth < 6) continue;
                    sc = LEX_DELTA * lex_wup(&np->senses[i], &c->np.senses[j]); /* another head: one weak step */
                }
                if (agree == 2) sc *= LEX_SYN; /* agreeing through a synonym: one weak step */
                if (sc <= base) continue;
                base = sc;
                sibling = t.kind == SP_LEX_RELATED;
                m->kind = t.kind == SP_LEX_RELATED ? SP_LEX_HYPERNYM : t.kind;
                describe_tax(m, &t, &np->senses[i], &c->np.senses[j]);
                snprintf(m->path, sizeof m->path, "'%s' and '%s' share the modifiers; heads %.2f alike", np->head,
                         c->name, sc);
            }
    }
    /* a part of any counter is one of the reception counter too: a class whose name says more
     * than the query comes after the bare one (an order, not evidence) */
    if (m->kind == SP_LEX_PART && c->n_tok > 1 && !agree) base -= LEX_TIE;
    /* The query names what a holder class's modifier names, or a hypernym of it, and nothing
     * else ("dumbbells", "weights" -> the dumbbell rack): the thing the class holds is found
     * there, two weak steps away (LEX_HOLDS times the taxonomy's score). */
    if (has_head && np->n_mods == 0 && !np->n_desc && m->kind != SP_LEX_EXACT && c->mod_head.n_senses &&
        base < LEX_HOLDS)
        for (int i = 0; i < np->n_senses; i++)
            for (int j = 0; j < c->mod_head.n_senses; j++) {
                lex_tax t = lex_compare(&np->senses[i], &c->mod_head.senses[j]);
                if (t.kind != SP_LEX_SYNONYM && t.kind != SP_LEX_HYPERNYM) continue;
                if (LEX_HOLDS * t.score <= base) continue;
                {
                    base = LEX_HOLDS * t.score;
                    m->kind = SP_LEX_MODIFIER;
                    snprintf(m->query_sense, sizeof m->query_sense, "%s", np->senses[i].anc[0].name);
                    snprintf(m->class_sense, sizeof m->class_sense, "%s", c->name);
                    snprintf(m->path, sizeof m->path, "'%s' is what the %s holds", np->head, c->name);
                }
            }
    /* A holder of the same things: a query naming a holder and what it holds ("shoe rack",
     * "luggage stand") against a holder class whose modifier names that, a kind of it or a
     * hypernym of it (the shoe cabinet, the luggage rack): another name of the place those
     * things are kept, one weak step (DELTA times the taxonomy of the thing held). */
    int held_mod = -1;
    const lex_np *held = has_head && np->n_mods > np->split && m->kind != SP_LEX_EXACT && qp->holder ? held_by(c) : NULL;
    int last = np->n_mods - 1 - np->split;
    if (held && last >= 0 && qp->mod_np[last].n_senses) {
        float t = LEX_DELTA * held_score(&qp->mod_np[last], held);
        if (t > base) {
            base = t, held_mod = last;
            m->kind = SP_LEX_MODIFIER;
            snprintf(m->query_sense, sizeof m->query_sense, "%s", np->head);
            snprintf(m->class_sense, sizeof m->class_sense, "%s", c->name);
            snprintf(m->path, sizeof m->path, "both hold %s", np->mods[last]);
        }
    }
    /* Among classes the taxonomy puts equally far below the query ("container": the bin, the can
     * and the car, a wheeled vehicle), those whose own definition names the query's word come
     * first ("bin: a container; usually has a lid"): an order among equals, not evidence. */
    if (m->kind == SP_LEX_HYPERNYM && base < 1.0f) {
        char one[1][WN_LEMMA_MAX];
        snprintf(one[0], WN_LEMMA_MAX, "%s", np->head);
        int src;
        if (lex_bag_find(&c->bag, one, 1, 1.0f, 1.0f, 1.0f, 0, &src) > 0) base = base + LEX_TIE > 1.0f ? 1.0f : base + LEX_TIE;
        /* and before them those whose name says it, as a word or as the end of a closed compound
         * ("rack": the luggage rack before the nightstand, whose stand WordNet also calls a rack;
         * "board": the whiteboard) */
        size_t nh = strlen(np->head);
        for (int k = 0; k < c->n_tok; k++) {
            size_t nt = strlen(c->tok[k]);
            if (!strcmp(c->tok[k], np->head) || (nt >= nh + 3 && !strcmp(c->tok[k] + nt - nh, np->head))) {
                base = base + LEX_TIE > 1.0f ? 1.0f : base + LEX_TIE;
                break;
            }
        }
    }
    /* Modifiers: a word of this class's name agrees; a word naming other classes of the scene
     * contradicts; anything else is an attribute we cannot see, unless a definition mentions it. */
    float fmod = 1.0f;
    int named = 0; /* a query modifier is a word of the class's name ("swivel BAR stool") */
    for (int i = 0; i < np->n_mods - np->split; i++)
        for (int k = 0; k + 1 < c->n_tok; k++)
            named |= !strcmp(c->tok[k], qp->mod_base[i]) || parts_in_name(qp->mod_base[i], c);
    if (strchr(np->head, '_')) { /* "cabinet TABLE saw": the head is the class's own name */
        char h[WN_LEMMA_MAX];
        snprintf(h, sizeof h, "%s", np->head);
        for (char *save = NULL, *t = strtok_r(h, "_", &save); t; t = strtok_r(NULL, "_", &save))
            for (int k = 0; k + 1 < c->n_tok; k++) named |= !strcmp(c->tok[k], t);
    }
    for (int i = 0; i < np->n_mods; i++) {
        int use = LEX_MOD_IGNORED;
        if (np->split && i == np->n_mods - 1) { /* part of the head: "night" of "nightstand" */
            if (mod_use) mod_use[i] = LEX_MOD_USED;
            continue;
        }
        if (i == held_mod || (company && i == 0)) use = LEX_MOD_USED;
        for (int k = 0; k < c->n_tok && use == LEX_MOD_IGNORED; k++)
            if (!strcmp(c->tok[k], qp->mod_base[i])) use = LEX_MOD_USED;
        if (use == LEX_MOD_IGNORED && parts_in_name(qp->mod_base[i], c)) use = LEX_MOD_USED;
        for (int e = 1; use == LEX_MOD_IGNORED && agree == 2 && e < qp->mod_exp[i].n; e++)
            for (int k = 0; k + 1 < c->n_tok; k++)
                if (!strcmp(c->tok[k], qp->mod_exp[i].w[e])) use = LEX_MOD_USED;
        for (int j = 0; use == LEX_MOD_IGNORED && agree == 2 && j < c->n_kind && qp->mod_np[i].n_senses; j++)
            for (int b = 0; b < c->kind_np[j].n_senses && b < 2; b++)
                if (lex_anc_find(&qp->mod_np[i].senses[0], c->kind_np[j].senses[b].off) > 0) use = LEX_MOD_USED;
        if (use == LEX_MOD_IGNORED && agree && (strchr(qp->mod_base[i], '_') || strchr(qp->mod_base[i], '-'))) {
            char buf[WN_LEMMA_MAX];
            snprintf(buf, sizeof buf, "%s", qp->mod_base[i]);
            for (char *save = NULL, *t = strtok_r(buf, "_-", &save); t && use == LEX_MOD_IGNORED; t = strtok_r(NULL, "_-", &save))
                for (int k = 0; k + 1 < c->n_tok; k++)
                    if (!strcmp(c->tok[k], t)) use = LEX_MOD_USED;
        }
        for (int k = 0; k < c->n_part && use == LEX_MOD_IGNORED; k++)
            if (!strcmp(c->part[k], qp->mod_base[i])) use = LEX_MOD_USED;
        if (use == LEX_MOD_IGNORED && lex_vocab_has_word(v, qp->mod_base[i])) use = LEX_MOD_CONTRARY;
        if (use == LEX_MOD_IGNORED && bag_match(c, &qp->mod_exp[i], np->mods[i], 1.0f, 1.0f, 1, NULL, 0) > 0)
            use = LEX_MOD_USED;
        if (use == LEX_MOD_IGNORED && has_head &&
            ((qp->mod_kind[i] && (another_kind(c, np, qp, i, &named) || another_named_kind(c, np, qp, i, m))) ||
             another_activity(c, qp, i))) {
            use = LEX_MOD_CONTRARY; /* a sibling: "wine rack" is no drying rack */
            fmod *= LEX_MU;
            size_t o = strlen(m->path);
            snprintf(m->path + o, sizeof m->path - o, "%s'%s' names another kind than %s: a sibling", o ? "; " : "",
                     np->mods[i], c->name);
        } else if (use == LEX_MOD_CONTRARY) fmod *= 1.0f - LEX_BETA;
        /* a modifier naming a kind of thing ("BAR stool") on a head read in a sense no corpus
         * attests (the stool that is a toilet), which the class's definitions do not mention:
         * the words name another thing by their commonest reading, a cousin (MU) */
        if (use == LEX_MOD_IGNORED && rare && qp->mod_kind[i] && !c->spec) {
            use = LEX_MOD_CONTRARY;
            fmod *= LEX_MU;
        }
        if (use == LEX_MOD_IGNORED) fmod *= 1.0f - LEX_EPS;
        if (mod_use) mod_use[i] = use;
    }
    char why[192] = "";
    float pf = np->stranded ? LEX_PATIENT : 1.0f;
    /* what the thing itself does ("a lamp that sits on a table") is two weak steps from what a
     * person does with it ("something to sit on", "somewhere to lie down") */
    float af = np->thing_does ? 1.0f : LEX_PATIENT * LEX_PATIENT;
    if (has_head) {
        float s = base * fmod;
        if (np->n_desc) {
            float g = gloss_overlap(c, qp->desc_exp, np->desc_w, np->n_desc, np->desc, pf, af, why, sizeof why);
            s *= 1.0f - LEX_GAMMA + LEX_GAMMA * g;
            snprintf(m->gloss_words, sizeof m->gloss_words, "%s", why);
        }
        /* named by the query's words: first among equals; through another head, last */
        if (agree && !sibling && s < 1.0f) s = s + LEX_TIE > 1.0f ? 1.0f : s + LEX_TIE;
        else if (sibling) s -= LEX_TIE;
        m->score = s;
        int used[8] = {0};
        char awhy[192] = "";
        float a = qp->n_agent ? agent_score(c, np, qp, used, awhy, sizeof awhy) : 0;
        if (a > m->score) {
            m->score = a;
            m->kind = SP_LEX_GLOSS;
            m->path[0] = 0; /* the taxonomy's comparison lost: not the evidence */
            snprintf(m->gloss_words, sizeof m->gloss_words, "agent noun: %s", awhy);
            if (c->np.n_senses) snprintf(m->definition, sizeof m->definition, "%s", c->np.senses[0].definition);
            for (int i = 0; mod_use && i < np->n_mods - np->split; i++)
                if (used[i]) mod_use[i] = LEX_MOD_USED;
        }
    } else {
        /* Description only: every content word counts against the definitions. */
        expansion all[24];
        float w[24];
        char words[24][LEX_WORD];
        int n = 0;
        for (int i = 0; i < np->n_desc && n < 24; i++, n++)
            all[n] = qp->desc_exp[i], w[n] = np->desc_w[i], snprintf(words[n], LEX_WORD, "%s", np->desc[i]);
        for (int i = 0; i < np->n_mods && n < 24; i++, n++) {
            all[n] = qp->mod_exp[i];
            snprintf(words[n], LEX_WORD, "%s", np->mods[i]);
            w[n] = 1.0f; /* weights of modifiers are not precomputed; equal */
        }
        if (np->head[0] && !np->placeholder && n < 24) { /* a head WordNet does not know as a noun */
            expansion e = {1, {{0}}, {1.0f}};
            snprintf(e.w[0], WN_LEMMA_MAX, "%s", np->head);
            all[n] = e, w[n] = 1.0f, snprintf(words[n++], LEX_WORD, "%s", np->head);
        }
        float g = gloss_overlap(c, all, w, n, (const char (*)[LEX_WORD])words, pf, af, why, sizeof why);
        m->score = g;
        m->kind = g > 0 ? SP_LEX_GLOSS : SP_LEX_NONE;
        snprintf(m->gloss_words, sizeof m->gloss_words, "%s", why);
        if (c->np.n_senses) snprintf(m->definition, sizeof m->definition, "%s", c->np.senses[0].definition);
        int hw = -1;
        float h = np->n_mods ? 0 : holder_desc(v, c, np, qp, pf, af, &hw);
        if (h > m->score) {
            m->score = h;
            m->kind = SP_LEX_MODIFIER;
            snprintf(m->path, sizeof m->path, "'%s' is what the %s holds", np->desc[hw], c->name);
        }
    }
    /* A compound whose modifier names this class: T(modifier, c) * WuP(head, c). */
    for (int r = 0; r < qp->n_ref && c->np.n_senses; r++) {
        int bq, bc;
        lex_tax t = best_tax(qp->ref[r].senses, qp->ref[r].n_senses, c->np.senses, c->np.n_senses,
                             0, c->spec, &bq, &bc);
        if (t.kind == SP_LEX_RELATED) continue;
        float w = best_wup(np->senses, np->n_senses, c->np.senses, c->np.n_senses);
        /* the query's other modifiers weigh as in every reading (an attribute not shown, EPS) */
        float s = t.score * w * w * fmod;
        if (s > m->score) {
            m->score = s;
            m->kind = SP_LEX_MODIFIER;
            snprintf(m->query_sense, sizeof m->query_sense, "%s", qp->ref_word[r]);
            snprintf(m->class_sense, sizeof m->class_sense, "%s", c->np.senses[bc].anc[0].name);
            snprintf(m->path, sizeof m->path, "'%s' names this class; '%s' is %s-like", qp->ref_word[r],
                     np->head, c->name);
        }
    }
}

int lex_match_cmp(const void *a, const void *b)
{
    const sp_lex_class_match *x = a, *y = b;
    if (x->score != y->score) return x->score < y->score ? 1 : -1;
    if (x->kind != y->kind) return x->kind - y->kind; /* exact before synonym before ... */
    return x->class_index - y->class_index;
}

static int score_senses(const sp_lex_vocab *v, const lex_np *np, sp_lex_phrase *ph, int *mod_use,
                        sp_error *err);

/* 1 when query sense q is what class c's name means by its last word: one of c's senses or a
 * hypernym of one ("stool" of "bar stool": the seat, not WordNet's fourth stool, the toilet). */
static int named_sense(const lex_class *c, const lex_sense *q)
{
    for (int j = 0; j < c->np.n_senses; j++)
        if (lex_anc_find(&c->np.senses[j], q->off) >= 0) return 1;
    return 0;
}

/* The scene's senses of the query's head word: when classes of the scene end in that word, the
 * physical senses their names use are what the word means here, and its others are dropped
 * (keep[i] = 0; alias senses stay; a "periodic table", a tabular array, says nothing of
 * tables). Returns how many are kept, 0 when the scene says nothing. */
static int scene_senses(const sp_lex_vocab *v, const lex_np *np, int *keep)
{
    if (!np->head[0] || np->placeholder || np->split || np->n_senses < 2) return 0;
    int n = 0, own = np->n_senses - np->n_alias;
    for (int i = 0; i < np->n_senses; i++) keep[i] = i >= own;
    for (int ci = 0; ci < v->n; ci++) {
        const lex_class *c = &v->classes[ci];
        if (!c->n_tok || strcmp(c->tok[c->n_tok - 1], np->head)) continue;
        for (int i = 0; i < own; i++)
            if (!keep[i] && lex_sense_physical(&np->senses[i]) && named_sense(c, &np->senses[i])) keep[i] = 1, n++;
    }
    return n;
}

/* np with only the senses keep[] marks (a shallow copy; its senses array is the caller's). */
static lex_np keep_senses(const lex_np *np, const int *keep, lex_sense *buf)
{
    lex_np r = *np;
    r.n_senses = 0;
    r.n_alias = 0;
    int own = np->n_senses - np->n_alias;
    for (int i = 0; i < np->n_senses; i++)
        if (keep[i]) buf[r.n_senses++] = np->senses[i], r.n_alias += i >= own;
    r.senses = buf;
    return r;
}

int lex_score_np(const sp_lex_vocab *v, const lex_np *np, sp_lex_phrase *ph, int *mod_use,
                 sp_error *err)
{
    int keep[LEX_MAX_SENSES * 2];
    lex_sense *buf = NULL;
    lex_np scene;
    if (np->n_senses <= (int)(sizeof keep / sizeof keep[0]) && scene_senses(v, np, keep)) {
        buf = malloc(sizeof *buf * (size_t)np->n_senses);
        if (!buf) return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
        scene = keep_senses(np, keep, buf);
        np = &scene;
    }
    int rc = score_senses(v, np, ph, mod_use, err);
    free(buf);
    return rc;
}

/* The sense of class c that is a part of synset whole (WordNet's part holonyms), or 0. */
static uint32_t class_part_of(const lex_class *c, uint32_t whole)
{
    for (int j = 0; j < c->np.n_senses; j++)
        for (int h = 0; h < c->np.senses[j].n_holo; h++)
            if (c->np.senses[j].holo[h] == whole) return c->np.senses[j].off;
    return 0;
}

/* A whole the scene does not name stands where its parts do: when two or more classes are parts
 * of what a commonly used sense of the query's head is (or of a hypernym of it up to two steps:
 * a PC is a computer), each of those classes matches it through one weak step, LEX_PART, as a
 * part names its whole ("computer" -> the monitor and the keyboard, both parts of a computer in
 * WordNet). One part alone says nothing (a keyboard is also part of a piano); the sense must be
 * one the tagged corpora attest or the word's only one ("bulletin board" is no computer system). In matches
 * indexed by class (before sorting). */
static void whole_parts(const sp_lex_vocab *v, const lex_np *np, sp_lex_phrase *ph)
{
    if (!np->head[0] || np->placeholder) return;
    for (int i = 0; i < np->n_senses; i++) {
        const lex_sense *q = &np->senses[i];
        if (!q->certain) continue;
        /* a device, a piece of equipment, a system: a building or a room is no whole of this
         * kind (its walls and doors are not where a "toilet" or a "garage" stands) */
        int inst = lex_anc_find(q, 3575240u); /* instrumentality.n.03 */
        if (inst < 0) continue;
        for (int a = 0; a < q->n_anc; a++) {
            if (q->anc[a].dist > 2 || q->anc[a].depth <= q->anc[inst].depth) continue;
            /* two different parts (two kinds of shelf are one part of a cupboard) */
            uint32_t first = 0;
            int n = 0;
            for (int ci = 0; ci < v->n && n < 2; ci++) {
                uint32_t p = class_part_of(&v->classes[ci], q->anc[a].off);
                if (p && !first) first = p, n = 1;
                else if (p && p != first) n = 2;
            }
            if (n < 2) continue;
            for (int ci = 0; ci < v->n; ci++) {
                sp_lex_class_match *m = &ph->matches[ci];
                if (m->score >= LEX_PART || !class_part_of(&v->classes[ci], q->anc[a].off)) continue;
                m->score = LEX_PART;
                m->kind = SP_LEX_PART;
                snprintf(m->query_sense, sizeof m->query_sense, "%s", q->anc[0].name);
                snprintf(m->class_sense, sizeof m->class_sense, "%s", v->classes[ci].name);
                snprintf(m->path, sizeof m->path, "%s is part of %s", v->classes[ci].name, q->anc[a].name);
            }
        }
    }
}

static int score_senses(const sp_lex_vocab *v, const lex_np *np, sp_lex_phrase *ph, int *mod_use,
                        sp_error *err)
{
    query_prep *qp = calloc(1, sizeof *qp);
    int *uses = calloc((size_t)(v->n ? v->n : 1) * 8, sizeof *uses);
    if (!qp || !uses) {
        free(qp), free(uses);
        return sp_error_set(err, SP_E_NOMEM, "lexical: out of memory");
    }
    int rc = prepare(v, np, qp, err);
    if (!rc) {
        snprintf(ph->head, sizeof ph->head, "%s", np->placeholder ? "" : np->head);
        for (char *p = ph->head; *p; p++)
            if (*p == '_') *p = ' ';
        ph->n_matches = v->n;
        for (int i = 0; i < v->n; i++) score_class(v, np, qp, i, &ph->matches[i], uses + 8 * i);
        whole_parts(v, np, ph);
        qsort(ph->matches, (size_t)v->n, sizeof ph->matches[0], lex_match_cmp);
        if (mod_use && v->n) memcpy(mod_use, uses + 8 * ph->matches[0].class_index, sizeof(int) * (size_t)np->n_mods);
    }
    for (int r = 0; r < qp->n_ref; r++) lex_np_free(&qp->ref[r]);
    for (int i = 0; i < 8; i++) lex_np_free(&qp->mod_np[i]), lex_bag_free(&qp->mod_bag[i]);
    for (int i = 0; i < 16; i++) lex_np_free(&qp->desc_np[i]);
    free(qp);
    free(uses);
    return rc;
}
