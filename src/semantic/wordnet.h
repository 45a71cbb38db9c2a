/* A reader of the Princeton WordNet 3.0 database files (Debian's wordnet-base, /usr/share/wordnet),
 * private to the lexical text encoder. Nothing is loaded at open: the twelve files are mapped
 * read-only, lemmas and exception forms are found by binary search in the sorted index.<pos> and
 * <pos>.exc files, synsets are read from data.<pos> at their byte offset (the synset offset is
 * the byte offset). An open database is immutable and may be shared by threads.
 * Formats: wndb(5WN), morphy(7WN). */
#ifndef SP_WORDNET_H
#define SP_WORDNET_H

#include <stdint.h>

#include "semsplat/core.h"

typedef enum { WN_NOUN = 0, WN_VERB = 1, WN_ADJ = 2, WN_ADV = 3, WN_NPOS = 4 } wn_pos;

#define WN_LEMMA_MAX 96  /* longest lemma we handle (WordNet's longest is 71 bytes) */
#define WN_MAX_SENSES 80 /* most senses of one lemma in one part of speech ("break", verb: 59) */
#define WN_MAX_WORDS 64  /* most lemmas in one synset */
#define WN_MAX_BASES 8   /* base forms morphy returns at most */

/* Synset ids: the byte offset in data.<pos> (8 decimal digits) with the part of speech. */
typedef struct wn_id {
    uint32_t offset;
    uint8_t pos; /* wn_pos */
} wn_id;

typedef struct wn_db wn_db;

/* Opens the eight index/data files and the four exception lists of dir (their absence is an error
 * naming the file and the Debian package). Checks that data.noun holds the synset 'entity'. */
int wn_open(wn_db **out, const char *dir, sp_error *err);
void wn_close(wn_db *db);
const char *wn_dir(const wn_db *db);

/* Senses of a lemma (lower case, words joined by '_') in index order, i.e. by decreasing
 * frequency in the semantically tagged corpora: writes up to cap offsets; returns the count
 * (0 = not a lemma of pos) or a negative error. *tagged (may be NULL) gets how many senses were
 * ever tagged (the index's tagsense_cnt). */
int wn_lookup(const wn_db *db, wn_pos pos, const char *lemma, uint32_t *offsets, int cap,
              int *tagged, sp_error *err);
/* 1 when lemma is in index.<pos>, 0 when not, negative on a read error. */
int wn_has(const wn_db *db, wn_pos pos, const char *lemma, sp_error *err);

/* Princeton morphy: the base forms of an inflected word in pos that WordNet has. The word itself
 * when it is a lemma, then its forms in <pos>.exc ("geese" -> "goose"), then the detachment rules
 * (nouns: -s, -ses, -xes, -zes, -ches, -shes, -men, -ies; verbs: -s, -ies, -es, -ed, -ing; adjectives:
 * -er, -est) kept only when the result is a lemma. Collocations ("dining_chairs") inflect their last
 * word. Writes up to WN_MAX_BASES distinct forms into out; returns the count (>= 0) or an error. */
int wn_morphy(const wn_db *db, wn_pos pos, const char *word, char out[][WN_LEMMA_MAX],
              sp_error *err);

typedef struct wn_pointer {
    char symbol[4]; /* "@" hypernym, "@i" instance hypernym, "~" hyponym, "#p" part holonym,
                     * "%p" part meronym, "+" derivationally related form, ... */
    wn_id target;
    uint8_t source_word, target_word; /* 1-based word numbers, 0 = the whole synset */
} wn_pointer;

/* Lexicographer files of nouns (WordNet's lexnames) that name kinds of things. */
enum { WN_LEX_ANIMAL = 5, WN_LEX_ARTIFACT = 6, WN_LEX_COMMUNICATION = 10, WN_LEX_FOOD = 13, WN_LEX_PLANT = 20 };
/* ... and those whose nouns describe a thing rather than say which kind it is */
enum { WN_LEX_ATTRIBUTE = 7, WN_LEX_SHAPE = 25, WN_LEX_SUBSTANCE = 27 };
/* 1 when a noun of lexicographer file f names a kind of thing one can point at: an animal, an
 * artifact, a food, a plant, or a communication (a magazine, a menu, a sign), not an act,
 * attribute, state, substance or material, person, group, place or time. */
static inline int wn_lexfile_names_kind(int f)
{
    return f == WN_LEX_ANIMAL || f == WN_LEX_ARTIFACT || f == WN_LEX_COMMUNICATION || f == WN_LEX_FOOD ||
           f == WN_LEX_PLANT;
}

/* One synset, parsed from its data line. Owns its buffers (wn_synset_free). */
typedef struct wn_synset {
    wn_id id;
    int lexfile;               /* lexicographer file number ("noun.artifact" = 6) */
    int n_words;
    char *words[WN_MAX_WORDS]; /* lemmas as written ("TV_set"), adjective markers removed */
    int n_pointers;
    wn_pointer *pointers;
    char *gloss;               /* definition and examples, after the '|' */
    char *line;                /* the data line the fields point into */
} wn_synset;

/* Reads and parses the synset at id; errors name the data file and the offset. */
int wn_read(const wn_db *db, wn_id id, wn_synset *out, sp_error *err);
void wn_synset_free(wn_synset *s);

/* The definition part of a gloss: up to the first example (the first '"' after "; ") into out. */
void wn_definition(const char *gloss, char *out, size_t cap);

#endif
