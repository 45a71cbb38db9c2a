/* Words for the lexical text encoder: tokens, the closed classes of English words that carry no
 * object meaning (read-only tables), relation phrases, base forms and word weights. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "lexical.h"

/* The ASCII letter a UTF-8 Latin-1 letter folds to ("cafe" for "café", "creme" for "crème"):
 * WordNet's lemmas are ASCII, so an accented word would be split at its accent. Lead byte 0xC3,
 * continuation 0x80..0xBF (U+00C0..U+00FF); 0 for signs and letters with no one-letter fold. */
static char fold_latin1(unsigned char cont)
{
    static const char map[] = "aaaaaaaceeeeiiii"  /* U+00C0..CF (AE ligature as a) */
                              "dnooooo\0ouuuuy\0s" /* U+00D0..DF (x sign, thorn: none) */
                              "aaaaaaaceeeeiiii"  /* U+00E0..EF */
                              "dnooooo\0ouuuuy\0y"; /* U+00F0..FF */
    if (cont < 0x80 || cont > 0xBF) return 0;
    return map[cont - 0x80];
}

/* A UTF-8 sequence at p that reads as one ASCII character: an accented Latin-1 letter, or a
 * typographic apostrophe (U+2019, "fridge’s"). Returns its length in bytes (0: none) and the
 * character in *out. */
static int fold_utf8(const unsigned char *p, unsigned char *out)
{
    if (p[0] == 0xC3 && p[1]) {
        char f = fold_latin1(p[1]);
        if (f) { *out = (unsigned char)f; return 2; }
    }
    if (p[0] == 0xE2 && p[1] == 0x80 && (p[2] == 0x98 || p[2] == 0x99)) { *out = '\''; return 3; }
    return 0;
}

void lex_tokenize(const char *text, lex_tokens *t)
{
    t->n = 0;
    char cur[LEX_WORD];
    int len = 0;
    for (const char *p = text;; p++) {
        unsigned char c = (unsigned char)*p, f;
        int step = fold_utf8((const unsigned char *)p, &f);
        if (step) {
            c = f;
            p += step - 1;
        }
        int keep = isalnum(c) || ((c == '\'' || c == '-') && len > 0 && isalnum((unsigned char)p[1]));
        if (keep) {
            if (len + 1 < LEX_WORD) cur[len++] = (char)tolower(c);
            continue;
        }
        if (len > 0 && t->n < LEX_MAX_TOKENS) {
            cur[len] = 0;
            if (len > 2 && !strcmp(cur + len - 2, "'s")) cur[len - 2] = 0; /* possessive */
            snprintf(t->w[t->n++], LEX_WORD, "%s", cur);
        }
        len = 0;
        if (!c) break;
    }
}

static int in_list(const char *w, const char *const *list)
{
    for (int i = 0; list[i]; i++)
        if (!strcmp(w, list[i])) return 1;
    return 0;
}

/* Determiners, pronouns, auxiliaries, numbers, and the verbs of requests ("find", "show me",
 * "take me to"): closed classes whose members name no object. */
static const char *const function_words[] = {
    "a", "an", "the", "my", "your", "our", "his", "her", "their", "its", "this", "these", "those",
    "some", "any", "me", "i", "you", "we", "us", "he", "she", "they", "it", "them", "is", "are",
    "was", "were", "be", "am", "been", "being", "can", "could", "would", "should", "will",
    "shall", "may", "might", "must", "do", "does", "did", "please", "find", "show", "locate", "go",
    "take", "bring", "navigate", "drive", "move", "look", "search", "point", "lead", "guide",
    "there", "here", "and", "or", "but", "so", "also", "just", "only", "very", "really", "each",
    "every", "all", "both", "own", "want", "need", "let", "lets", "i'd", "i'm", "one", "two",
    "three", "four", "five", "six", "seven", "eight", "nine", "ten", "how", "why", "get", "then",
    "not", "no", "else", "other", "another", "such", "much", "many", "more", "most", "usually",
    "typically", "often",
    /* particles of phrasal verbs ("clean UP", "lie DOWN", "let OUT"): they name nothing */
    "up", "down", "out", "off", "away", NULL};
/* Heads that say nothing about what the thing is: the description carries the meaning. */
static const char *const placeholder_words[] = {
    "something", "anything", "somewhere", "anywhere", "someplace", "anyplace", "everything",
    "thing", "things", "stuff", "object", "objects", "item", "items", "place", "places", "spot",
    "ones", NULL};
static const char *const clause_words[] = {"that", "which", "what", "who", "whom", "whose", "where",
                                           "when", "for", "to", NULL};
static const char *const partitive_words[] = {"piece", "pieces", "kind", "kinds", "type", "types",
                                              "sort", "sorts", "pair", "set", "bit", "bunch",
                                              "sort", NULL};

static const char *const particle_words[] = {"up", "down", "out", "off", "away", NULL};

int lex_is_particle(const char *w) { return in_list(w, particle_words); }

int lex_word_class_of(const char *w)
{
    if (in_list(w, function_words)) return LW_FUNCTION;
    if (in_list(w, placeholder_words)) return LW_PLACEHOLDER;
    if (in_list(w, clause_words)) return LW_CLAUSE;
    if (in_list(w, partitive_words)) return LW_PARTITIVE;
    const char *name;
    lex_tokens one;
    one.n = 1;
    snprintf(one.w[0], LEX_WORD, "%s", w);
    if (lex_relation_at(&one, 0, &name)) return LW_PREP;
    return LW_CONTENT;
}

typedef struct {
    const char *words[4];
    const char *name;
} relation_phrase;

/* Spatial relations, longest first; several spellings share one canonical name. */
static const relation_phrase relations[] = {
    {{"in", "front", "of"}, "in front of"}, {{"on", "top", "of"}, "on"},
    {{"next", "to"}, "next to"},             {{"close", "to"}, "near"},
    {{"near", "to"}, "near"},                {{"adjacent", "to"}, "next to"},
    {{"across", "from"}, "across from"},    {{"leading", "to"}, "to"},
    {{"closest", "to"}, "near"},             {{"nearest", "to"}, "near"},
    {{"out", "to"}, "to"},                   {{"out", "into"}, "to"},
    {{"near"}, "near"},   {{"nearby"}, "near"},   {{"beside"}, "beside"}, {{"besides"}, "beside"},
    {{"by"}, "by"},       {{"in"}, "in"},         {{"inside"}, "in"},     {{"within"}, "in"},
    {{"into"}, "in"},     {{"on"}, "on"},         {{"onto"}, "on"},       {{"upon"}, "on"},
    {{"under"}, "under"}, {{"underneath"}, "under"}, {{"beneath"}, "under"}, {{"below"}, "below"},
    {{"above"}, "above"}, {{"over"}, "above"},    {{"behind"}, "behind"}, {{"at"}, "at"},
    {{"to"}, "to"},       {{"towards"}, "to"},    {{"toward"}, "to"},     {{"of"}, "of"},
    {{"from"}, "from"},   {{"opposite"}, "across from"}, {{"facing"}, "across from"},
    {{"along"}, "along"}, {{"against"}, "against"}, {{"around"}, "near"}, {{"with"}, "with"},
    {{"between"}, "between"}, {{NULL}, NULL}};

int lex_relation_at(const lex_tokens *t, int i, const char **name)
{
    for (int r = 0; relations[r].name; r++) {
        int k = 0;
        while (k < 4 && relations[r].words[k] && i + k < t->n && !strcmp(t->w[i + k], relations[r].words[k]))
            k++;
        if (k > 0 && (k == 4 || !relations[r].words[k])) {
            *name = relations[r].name;
            return k;
        }
    }
    return 0;
}

int lex_is_region_link(const char *w)
{
    static const char *const links[] = {"with", "containing", "contains", "contain", "like",
                                        "looks", "look", "resembling", "resembles", "has", "have",
                                        "having", "full", "of", "where", "that", "which", "there",
                                        "is", "are", "for", NULL};
    return in_list(w, links);
}

int lex_bases(const lex_db *lx, wn_pos pos, const char *w, char out[][WN_LEMMA_MAX], sp_error *err)
{
    return wn_morphy(lx->db, pos, w, out, err);
}

int lex_is_pos(const lex_db *lx, wn_pos pos, const char *w, sp_error *err)
{
    char b[WN_MAX_BASES][WN_LEMMA_MAX];
    int n = wn_morphy(lx->db, pos, w, b, err);
    return n < 0 ? n : n > 0;
}

int lex_word_weight(const lex_db *lx, const char *w, float *weight, sp_error *err)
{
    int senses = 0;
    for (int p = 0; p < WN_NPOS; p++) {
        char b[WN_MAX_BASES][WN_LEMMA_MAX];
        int nb = wn_morphy(lx->db, (wn_pos)p, w, b, err);
        if (nb < 0) return nb;
        if (nb == 0) continue;
        uint32_t offs[WN_MAX_SENSES];
        int n = wn_lookup(lx->db, (wn_pos)p, b[0], offs, WN_MAX_SENSES, NULL, err);
        if (n < 0) return n;
        senses += n;
    }
    *weight = 1.0f / (1.0f + logf(1.0f + (float)senses));
    return 0;
}

/* Words for a category of artifacts by use ("equipment", "appliances", "fittings"): with a modifier
 * they name what belongs to a place or an activity ("kitchen equipment", "safety equipment").
 * Not "fixture": WordNet's lighting fixture is a lamp, no lighting area's contents. */
int lex_is_category(const char *w)
{
    static const char *const words[] = {"equipment", "gear", "apparatus", "appliance", "device",
                                        "fitting", "furniture", "furnishing", "supply", "supplies", "ware", "machinery",
                                        "electronics", NULL};
    for (int i = 0; words[i]; i++)
        if (!strcmp(w, words[i])) return 1;
    return 0;
}

/* Words that stand for "some area" and take their meaning from what follows ("area with
 * appliances") or precedes ("the kitchen area"). */
int lex_is_generic_region(const char *w)
{
    static const char *const words[] = {"area", "areas", "region", "zone", "section", "part",
                                        "corner", "space", "room", "place", "somewhere", "spot", "station", "nook", "alcove",
                                        "side", NULL};
    for (int i = 0; words[i]; i++)
        if (!strcmp(w, words[i])) return 1;
    return 0;
}
