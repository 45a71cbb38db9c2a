/* The built-in parser's word layer: normalized tokens, word lists, numbers and units. */
#ifndef SEMSPLAT_AGENT_PARSE_INTERNAL_H
#define SEMSPLAT_AGENT_PARSE_INTERNAL_H

#include <stddef.h>

#define PW_MAX_WORDS 64
#define PW_WORD 32

typedef struct pw_words {
    int n;
    char w[PW_MAX_WORDS][PW_WORD];
} pw_words;

/* Lowercases, expands contractions ("what's" -> "what is"), turns punctuation into spaces (a
 * '.' between digits stays) and splits into words. At most 1000 input bytes are read. */
void pw_tokenize(const char *text, pw_words *out);

/* 1 when w is in the NULL-terminated list. */
int pw_in(const char *w, const char *const *list);
/* Index of the first word at or after `from` that is in list, or -1. */
int pw_find(const pw_words *t, int from, const char *const *list);
/* Like pw_find, but a word also matches a list entry's -ing form ("going", "driving",
 * "getting"): verbs in polite or progressive phrasing ("would you mind heading to ..."). */
int pw_find_verb(const pw_words *t, int from, const char *const *list);
/* Matches a space-separated phrase ("next to") at position i; returns its word count or 0. */
int pw_match(const pw_words *t, int i, const char *phrase);
/* The first position >= from where one of the phrases (NULL-terminated) matches; *len gets its
 * length. -1 when none. */
int pw_find_phrase(const pw_words *t, int from, const char *const *phrases, int *len);
/* Removes words [i, i + n). */
void pw_erase(pw_words *t, int i, int n);
/* Joins words [from, to) with spaces. */
void pw_join(const pw_words *t, int from, int to, char *out, size_t cap);

/* A number word or digits ("3", "three", "2.5"); 1 on success. */
int pw_number(const char *w, double *v);
/* An ordinal ("second", "2nd") -> 2; 0 when not one. */
int pw_ordinal(const char *w);
/* A length unit -> metres per unit; 0 when not one. */
double pw_unit_m(const char *w);

extern const char *const pw_determiners[];
extern const char *const pw_fillers[];     /* "please", "now", ... at the ends of a target */
extern const char *const pw_relations[];   /* "next to", "near", "on", ... (phrases) */
extern const char *const pw_self[];        /* "me", "you", "here", "the robot" */
extern const char *const pw_pronouns[];    /* "it", "there", "that" */

#endif
