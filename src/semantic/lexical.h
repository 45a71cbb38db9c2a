/* Private pieces of the lexical text encoder: words (tokens, function words, base forms),
 * concepts (noun senses with their hypernym closure and definitions), prepared classes and the
 * scoring of one phrase against them. See the lexical section of semsplat/semantic.h. */
#ifndef SP_LEXICAL_H
#define SP_LEXICAL_H

#include <pthread.h>

#include "semsplat/semantic.h"
#include "wordnet.h"

/* The scoring constants (semantic.h documents the formula). */
#define LEX_MU 0.45f     /* siblings and cousins: MU * WuP < threshold, always */
#define LEX_PART 0.6f    /* the query names a part of the class */
#define LEX_BETA 0.3f    /* a query modifier naming another class of the scene */
#define LEX_EPS 0.1f     /* an attribute the class's definitions do not mention */
#define LEX_GAMMA 0.3f   /* weight of a description beside a head noun */
#define LEX_DELTA 0.8f   /* gloss word found one hypernym level up (squared two levels up) */
#define LEX_KIND_W (LEX_DELTA * LEX_DELTA) /* a definition of a kind of the class (one level down) */
#define LEX_SYN 0.8f     /* a description word matched through a lemma of its commonest sense */
#define LEX_GLOSS_LEVELS 2
#define LEX_HOLDS (LEX_DELTA * LEX_DELTA) /* the query names what a class's modifier names */
#define LEX_TIE 0.001f   /* orders hypernym matches the taxonomy ties: no evidence, an order */
/* A description ending in a preposition ("something to write ON") asks where or with what the
 * verb is done; a definition naming the class as what the verb acts on (a past participle,
 * "a WRITTEN work") is then one weak step (DELTA) of evidence, not a full match. */
#define LEX_PATIENT LEX_DELTA
/* A thing read from the activity table (data/semantic/uses.json: "wash hand" -> washbasin):
 * general knowledge of what affords what, one weak step from the user's words. */
#define LEX_USE LEX_DELTA

#define LEX_MAX_TOKENS 32
#define LEX_WORD 48
#define LEX_MAX_SENSES 12 /* physical senses kept per head */
#define LEX_MAX_ANC 96    /* ancestors in one closure */

typedef struct sp_lexicon {
    wn_db *db;
} lex_db;

/* ---- words ---------------------------------------------------------------------------------- */

typedef enum {
    LW_CONTENT = 0, /* a word to look up */
    LW_FUNCTION,    /* determiner, pronoun, auxiliary, request verb: dropped */
    LW_PLACEHOLDER, /* "something", "thing", "place": a head that says nothing */
    LW_PREP,        /* a preposition that may relate two phrases */
    LW_CLAUSE,      /* starts a description: "that", "which", "where", "for", "to" + verb */
    LW_PARTITIVE    /* "piece", "kind", "type" (+ of): skipped with its "of" */
} lex_word_class;

typedef struct lex_tokens {
    int n;
    char w[LEX_MAX_TOKENS][LEX_WORD];
} lex_tokens;

/* Lower-cases and splits text into words (letters, digits, ' and -), dropping "'s". */
void lex_tokenize(const char *text, lex_tokens *t);
/* Joins runs of 2..4 words that WordNet knows as one noun ("coffee tables" -> "coffee_table",
 * "chest of drawers", "book shelf" -> "bookshelf") into one token, its base form. */
int lex_merge_collocations(const lex_db *lx, const lex_tokens *in, lex_tokens *out, sp_error *err);
int lex_word_class_of(const char *w);
/* A particle of a phrasal verb ("up" of "clean up"): no collocation ends in one. */
int lex_is_particle(const char *w);
/* Relation phrase starting at token i: its length in tokens (0 = none) and its canonical name. */
int lex_relation_at(const lex_tokens *t, int i, const char **name);
/* Words that stand for "some area" ("area", "room", "corner", ...): regions by their complement,
 * and no description of an object ("something that lights the room"). */
int lex_is_generic_region(const char *w);
/* Category words of artifacts by use ("equipment", "appliance", "fitting"; base forms). */
int lex_is_category(const char *w);
/* Words that introduce what an area contains or resembles ("with", "like", "looks", ...). */
int lex_is_region_link(const char *w);

/* Base forms of a word as pos (morphy); returns the count (>= 0) or an error. */
int lex_bases(const lex_db *lx, wn_pos pos, const char *w, char out[][WN_LEMMA_MAX], sp_error *err);
/* 1 when w has a noun base form, etc. (negative on read errors). */
int lex_is_pos(const lex_db *lx, wn_pos pos, const char *w, sp_error *err);
/* A closed compound WordNet lacks ("nightstand"): the longest noun it ends in whose rest is a
 * noun or an adjective; 1 and both parts (WN_LEMMA_MAX each) when found. */
int lex_split_compound(const lex_db *lx, const char *w, char *left, char *right, sp_error *err);
/* Informativeness of a word: 1 / (1 + ln(1 + its number of senses over all parts of speech)). */
int lex_word_weight(const lex_db *lx, const char *w, float *weight, sp_error *err);

/* ---- concepts ------------------------------------------------------------------------------- */

typedef struct lex_anc {
    uint32_t off;
    short dist;    /* hypernym steps from the sense */
    short depth;   /* of this ancestor: 1 + shortest hypernym path to 'entity' */
    short parent;  /* index of the closure entry it was reached from (-1 for the sense itself) */
    char name[42]; /* first lemma, '_' as ' ' */
} lex_anc;

/* A noun sense with its hypernym closure (index 0 = the sense itself). */
typedef struct lex_sense {
    uint32_t off;
    int rank;              /* sense number of the lemma (1 = commonest) */
    int attested;          /* the first sense, or one the tagged corpora attest */
    int certain;           /* one the tagged corpora attest, or the word's only sense (the first of
                            * untagged senses is only WordNet's order) */
    char definition[192];  /* its name is anc[0].name */
    int n_anc;
    lex_anc anc[LEX_MAX_ANC];
    int n_holo;
    uint32_t holo[16];     /* part holonyms: what this is a part of */
    int instance;          /* a named individual (an instance hypernym, "@i": the Monitor, one
                            * ship), not a kind */
} lex_sense;

/* Reads the sense (closure, definition, part holonyms). */
int lex_sense_load(const lex_db *lx, uint32_t off, int rank, lex_sense *s, sp_error *err);
/* 1 when the sense is a physical entity (under physical_entity.n.01). */
int lex_sense_physical(const lex_sense *s);
/* 1 when the sense is a person (under person.n.01: "monitor" the supervisor). */
int lex_sense_person(const lex_sense *s);
/* 1 when the sense is a room (room.n.01 or a kind of it: WordNet's toilet, a closet, a booth). */
int lex_sense_room(const lex_sense *s);
/* 1 when the sense is a living thing (a plant, an animal, a person). */
int lex_sense_living(const lex_sense *s);
/* 1 when the sense is an animal ("jack" the fish, "crane" the bird). */
int lex_sense_animal(const lex_sense *s);
/* 1 when the sense is a food ("jack" the jackfruit, "grinder" the sandwich, "rack" of lamb). */
int lex_sense_food(const lex_sense *s);
/* 1 when the sense is an act (act.n.02: "storage", the act of storing). */
int lex_sense_act(const lex_sense *s);
/* 1 when s is a physical process ("microwave" the radiation, "current" the flow). */
int lex_sense_process(const lex_sense *s);
/* 1 when the sense is an artifact (under artifact.n.01). */
int lex_sense_artifact(const lex_sense *s);
/* Index of off in s's closure, or -1. */
int lex_anc_find(const lex_sense *s, uint32_t off);
/* The hypernym path from s up to its closure entry a: "s > ... > a". */
void lex_path(const lex_sense *s, int a, char *out, size_t cap);

/* Taxonomic comparison of a query sense q and a class sense c. */
typedef struct lex_tax {
    float score;
    int kind;     /* SP_LEX_SYNONYM, HYPERNYM, HYPONYM, PART, RELATED, NONE */
    int q_anc, c_anc; /* indices of the LCS in q's and c's closures (-1 none) */
} lex_tax;
lex_tax lex_compare(const lex_sense *q, const lex_sense *c);
/* Plain Wu-Palmer similarity 2 dep(lcs) / (dq + dc + 2 dep(lcs)) through the deepest common
 * ancestor (1 for the same synset). */
float lex_wup(const lex_sense *q, const lex_sense *c);

/* ---- gloss bags ------------------------------------------------------------------------------ */

typedef struct lex_bag_word {
    char w[LEX_WORD];  /* a base form */
    float weight;      /* DELTA^level */
    short src;         /* index into the bag's sources */
    short patient;     /* LEX_BAG_PATIENT: a verb's base read from its past participle ("written"
                        * -> write): the thing defined is what the verb acts on; LEX_BAG_AGENT:
                        * the verb of a relative clause on it ("a lamp that sits on a table"):
                        * what it does; 0: anything else */
    short kind;        /* from the definition of a kind of the class (one level down) */
} lex_bag_word;
#define LEX_BAG_PATIENT 1
#define LEX_BAG_AGENT 2
#define LEX_BAG_PERSON 3 /* a verb of a person's clause ("for those who cannot WALK"): what people do */

typedef struct lex_bag {
    int n, cap;
    lex_bag_word *words;
    int n_src;
    char (*src)[192];  /* "seat: furniture that is designed for sitting on" */
} lex_bag;

void lex_bag_free(lex_bag *b);
/* Adds the base forms of every content word of text at weight, citing source; kind: the text
 * defines a kind of the class. */
int lex_bag_add_text(const lex_db *lx, lex_bag *b, const char *text, float weight, int kind,
                     const char *source, sp_error *err);
/* Adds the words of WordNet lemmas as they are: a lemma is a base form already ("works", the
 * factory, is no "work"). */
int lex_bag_add_lemmas(lex_bag *b, const char *lemmas, float weight, const char *source, sp_error *err);
/* Adds a synset's lemmas and definition to the bag at weight (verbs: and its derived verbs'). */
int lex_bag_synset(const lex_db *lx, lex_bag *bag, wn_id id, float weight, int verbs, sp_error *err);
/* Best weight of any of the bases in the bag among entries weighing at least min_weight (0 =
 * absent), patient entries scaled by patient_factor, agent entries by agent_factor; own: the
 * class's own entries only, not its kinds'
 * (a kind's definition saying "red" does not make the class red); *src gets the source index. */
float lex_bag_find(const lex_bag *b, char bases[][WN_LEMMA_MAX], int n, float min_weight,
                   float patient_factor, float agent_factor, int own, int *src);

/* ---- phrases and classes -------------------------------------------------------------------- */

/* A noun phrase resolved against WordNet: the head (longest collocation ending at the last noun),
 * the modifiers before it and the description words after a clause marker. */
typedef struct lex_np {
    int n_words;
    char words[LEX_MAX_TOKENS][LEX_WORD]; /* content words in order (base forms for nouns) */
    int head_start, head_end;             /* [start, end) of the head collocation, -1 none */
    char head[WN_LEMMA_MAX];              /* the collocation as a WordNet lemma */
    int placeholder;                      /* the head was "something", "a place", ... */
    int fallback;                         /* class name without an attested physical sense */
    int n_alias;                          /* the last n_alias senses come from the alias table
                                           * (class names): context never drops them */
    int split;                            /* the head is a closed compound split in two: its
                                           * first part is the last modifier ("nightstand") */
    int stranded;                         /* the description ends in a preposition: "something
                                           * to write on" (where the verb is done) */
    int thing_does;                       /* the description says what the thing does ("something
                                           * THAT keeps food cold", "what tells the time"), not
                                           * what a person does with it ("something to sit on") */
    int n_senses;
    lex_sense *senses;                    /* [n_senses] all noun senses (queries) or physical (classes) */
    int n_mods;
    char mods[8][LEX_WORD];               /* content words before the head */
    int n_desc;
    char desc[16][LEX_WORD];              /* description words (purpose clause, relative clause) */
    float desc_w[16];
} lex_np;

void lex_np_free(lex_np *np);
/* 1 when a sense of np's head is a holder: a container or a support in WordNet (rack, shelf, bin,
 * case). */
int lex_np_holder(const lex_np *np);
/* 1 when a sense of np's head is a support in WordNet (rack, shelf, stand): it holds things up. */
int lex_np_support(const lex_np *np);
/* Parses tokens [from, to) into np; physical_only keeps physical senses (class names). */
int lex_np_parse(const lex_db *lx, const lex_tokens *t, int from, int to, int physical_only,
                 lex_np *np, sp_error *err);

typedef struct lex_class {
    char name[128];
    lex_np np;       /* the class name parsed (physical senses) */
    int spec;        /* its name has noun modifiers beside the head: one level more specific */
    int joined;      /* its name holds a word and a preposition WordNet writes with a hyphen
                      * ("walk in fridge": walk-in), read as that one word */
    lex_bag bag;     /* its names and definitions, with hypernyms' */
    int n_tok;
    char tok[8][LEX_WORD]; /* base forms of its name's words */
    int n_part;
    char part[4][LEX_WORD]; /* parts of a modifier WordNet lacks ("overbed": over, bed) */
    lex_np name_head; /* the last word of a name WordNet joins ("washing machine"), read alone:
                       * an English compound is a kind of its last word, wherever WordNet files
                       * it (its washer is home appliance, not machine); no senses otherwise */
    lex_np mod_head; /* the noun modifier next to the head of a name WordNet lacks, read alone
                      * ("dumbbell" of "dumbbell rack"): what the thing is for or holds */
    int holder;      /* its head is a container or a support in WordNet (rack, shelf, bin, case) */
    int n_kind;
    lex_np kind_np[3]; /* the name's words before its last, read alone with all their noun senses
                        * ("checkout" of "checkout counter"): the kind its modifier names */
    int kind_lexfile[3]; /* the lexicographer file of each one's commonest sense (-1 none) */
    lex_bag kind_bag;  /* those senses' lemmas and definitions */
    char act[WN_LEMMA_MAX]; /* the verb of an -ing word before its last ("wash" of "washing
                             * machine"): the activity the thing is for; "" none */
} lex_class;
/* The verb an -ing word is a form of ("rowing" -> "row"); 1 when it is one, 0 when not. */
int lex_ing_verb(const lex_db *lx, const char *w, char *verb, sp_error *err);

typedef struct lex_region {
    char name[64];
    int n_members;
    char members[24][64];
    sp_lex_phrase *cache; /* its members in this vocabulary, resolved on first use */
} lex_region;

/* A name WordNet lacks or files under another sense ("shop vac", "wheelie bin", "trolley"),
 * from data/semantic/aliases.json: another reading of the words, as WordNet lemmas. */
typedef struct lex_alias {
    int n_words;
    char words[4][LEX_WORD]; /* the name, tokenized (the last word also matches its plural) */
    int n_targets;
    char targets[3][64];     /* WordNet noun lemmas, words separated by spaces */
} lex_alias;

/* An activity and the things that afford it, from data/semantic/uses.json: a query asking to
 * do it ("where can I wash my hands") is also read as each thing's name. */
typedef struct lex_use {
    int n_words;
    char words[4][LEX_WORD]; /* the verb (base form), then the nouns of its object (singular) */
    int n_targets;
    char targets[4][64];     /* names of things, read as queries */
} lex_use;

struct sp_lex_vocab {
    const lex_db *lx;
    int n_aliases;
    lex_alias *aliases;
    int n_uses;
    lex_use *uses;
    int n;
    lex_class *classes;
    int n_vocab_words;
    char (*vocab_words)[LEX_WORD]; /* every class-name word: modifiers that discriminate */
    int n_regions;
    lex_region *regions;
    pthread_mutex_t region_lock; /* guards the regions' caches, filled on first use */
};

int lex_vocab_has_word(const sp_lex_vocab *v, const char *w);
struct cJSON;
/* Reads the JSON object path's member (a table of named entries: "names" of the alias table,
 * "uses" of the activity table) and calls add for each entry whose name does not start with '_';
 * what names the table in errors. */
int lex_entries_load(sp_lex_vocab *v, const char *path, const char *member, const char *what,
                     int (*add)(sp_lex_vocab *, const char *, const struct cJSON *, sp_error *), sp_error *err);
/* Loads an activity table (JSON {"uses": {"verb noun...": [names]}}) into v. */
int lex_uses_load(sp_lex_vocab *v, const char *path, sp_error *err);
/* The activity entries a query asks for: its verb used as a verb (after "to", a subject or a
 * modal: "something to wash", "where can I wash", "I need to wash") and every other word of the
 * entry among the query's words after it (any inflection). Only the most specific entries (most
 * words) are kept; returns how many, at most max, or a negative SP_E_* code. */
int lex_uses_find(const sp_lex_vocab *v, const lex_tokens *t, const lex_use **out, int max, sp_error *err);
const lex_region *lex_region_find(const sp_lex_vocab *v, const char *name);
/* Set while a name from the general tables is read (lex_np_commonest then applies to it). */
extern _Thread_local int lex_everyday_name;
/* Keeps only the commonest senses of a one-word head whose first sense is an attested artifact. */
void lex_np_commonest(lex_np *np);
/* The table region named stem, or "stem G" with G a generic area word ("utility" -> "utility
 * room"), or NULL. */
const lex_region *lex_region_find_stem(const sp_lex_vocab *v, const char *stem);
/* Loads a region table (JSON object name -> [phrases]) into v. */
int lex_regions_load(sp_lex_vocab *v, const char *path, sp_error *err);
/* The table region an NP's head stands for (itself or a synonym), or NULL; returns 1 when it was
 * found through a WordNet room named by a generic area's modifiers ("sleeping room"), else 0 or
 * a negative SP_E_* code. */
int lex_region_named(const sp_lex_vocab *v, const lex_np *np, const lex_region **r, sp_error *err);
/* 1 when np's head names a place one can be in: a generic area word, or one of its first senses
 * a room, a workplace or a functional part of a structure ("hall", "gallery"). */
int lex_place_head(const lex_np *np);
/* 1 for the surfaces every room has (wall, floor, ceiling): they define no room, and a thing
 * named after one ("wall cupboard", "ceiling fan") is mounted on it, not its area. */
int lex_building_surface(const char *base);
/* The definition of a region name's place sense (first sense that is a room, a functional area
 * or a workplace; for table entries any such sense, else the first), or NULL when none. */
const char *lex_region_definition(const lex_np *np, int table_entry);
/* Members of a named region into ph, sorted (table regions: resolved once, on first use). */
int lex_region_members(const sp_lex_vocab *v, const lex_region *r, const char *name,
                       const char *definition, sp_lex_phrase *ph, sp_error *err);
/* The region of an activity: the classes that do what the words name ("cooking", "storage" ->
 * "something to cook / store") raised in region (indexed by class); returns 1 when any. */
int lex_region_activity(const sp_lex_vocab *v, const lex_tokens *words, sp_lex_phrase *region, sp_error *err);
/* The region of whom or what an area is for ("the children's section": "something for
 * children", the high chair) raised in region (indexed by class); returns 1 when any. */
int lex_region_for(const sp_lex_vocab *v, const lex_tokens *words, sp_lex_phrase *region, sp_error *err);
/* Rewrites a way in a direction as the passage that goes there ("the way out" -> "the exit",
 * "get back up" -> "stairs"; lex_match.c). */
void lex_way_direction(lex_tokens *t);
/* The verbs an activity word names ("cooking" -> cook; "storage" -> store, WordNet's "+" from
 * its commonest noun sense); none for a word that is a verb base itself. Returns how many. */
int lex_activity_verbs(const lex_db *lx, const char *w, char out[][WN_LEMMA_MAX], int cap, sp_error *err);
/* Raises the classes named after the region's words ("kitchen counter" of the kitchen, "patient
 * bed" of "the patient area") to 0.9 in ph (indexed by class); returns 1 when any. */
int lex_region_named_after(const sp_lex_vocab *v, const char *region, sp_lex_phrase *ph);
/* Clears ph's matches to every class at score 0, indexed by class. */
void lex_region_start(const sp_lex_vocab *v, sp_lex_phrase *ph);
/* Raises ph's members (indexed by class) to the classes matching sub; returns 1 when any. */
int lex_region_absorb(sp_lex_phrase *region, const sp_lex_phrase *sub, const char *why);

/* Loads an alias table (JSON: {"names": {name: [lemma, ...]}}, keys starting with '_' ignored)
 * into v, appending. */
int lex_aliases_load(sp_lex_vocab *v, const char *path, sp_error *err);
/* in with every alias name replaced by its reading-th target (the longest name first at each
 * word); returns how many names were replaced (0: none has a reading-th target, out = in).
 * used gets "name = target; ...". */
int lex_alias_rewrite(const sp_lex_vocab *v, const lex_tokens *in, int reading, lex_tokens *out,
                      char *used, size_t cap);
/* A class name's reading through the alias table: 1 and its first target when the name is wholly
 * an alias, or when its head is no WordNet noun and is one (the words before it kept); 0 when
 * neither, negative on errors. */
int lex_alias_class(const sp_lex_vocab *v, const lex_tokens *in, lex_tokens *out, sp_error *err);
/* sp_lex_match on one reading of the text: its words already tokenized (lex_match.c). */
int lex_match_reading(const sp_lex_vocab *v, const char *text, const lex_tokens *raw,
                      sp_lex_result *res, sp_error *err);

/* What a query modifier did for the best class. */
enum { LEX_MOD_IGNORED = 0, LEX_MOD_USED = 1, LEX_MOD_CONTRARY = 2 };

/* Scores a parsed phrase against every class into ph (sorted best first); mod_use [np->n_mods]
 * (may be NULL) gets what each modifier did for the best class. */
int lex_score_np(const sp_lex_vocab *v, const lex_np *np, sp_lex_phrase *ph, int *mod_use,
                 sp_error *err);
/* Order of class matches: score, then kind (exact first), then class index. */
int lex_match_cmp(const void *a, const void *b);

/* ---- grounding (lex_ground.c) ----------------------------------------------------------------- */

/* A class match as the engine's results list it (lex_engine.c). */
void sem_lex_match_copy(sp_query_match *q, const sp_lex_class_match *m, const sp_lex_vocab *v, const char *role);
/* sp_lex_query with the call's options o; the caller holds the engine's lock. */
int sem_lex_answer(sp_query_engine *e, const sp_lex_vocab *v, const char *text, const sp_query_opts *o,
                   sp_lex_answer *a, sp_error *err);

#endif
