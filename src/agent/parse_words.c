/* The built-in parser's word layer: normalization (case, contractions, punctuation), tokens,
 * word lists, and numbers written as digits or words. Read-only tables only. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "parse_internal.h"

const char *const pw_determiners[] = {"the", "a", "an", "my", "our", "your", "that", "this",
                                      "these", "those", "some", "its", "their", NULL};
const char *const pw_fillers[] = {"please", "now", "pls", "plz", "thanks", "thank", "you",
                                  "quickly", "asap", "again", "robot", "immediately", "then",
                                  "first", "already", "for", "me", "right", "away", "soon",
                                  "ok", "okay", "location", "position", "spot", "place", NULL};
/* Longest first, so "next to" wins over "to" and "in front of" over "in". */
const char *const pw_relations[] = {"in front of", "in the vicinity of", "in the neighborhood of",
                                    "on top of", "next to", "close to", "adjacent to", "to the left of",
                                    "to the right of", "left of", "right of", "near", "nearby",
                                    "around", "surrounding", "surrounds", "beside", "besides", "by", "on", "in", "inside",
                                    "under", "underneath", "below", "above", "behind", "at",
                                    "against", NULL};
const char *const pw_self[] = {"me", "you", "yourself", "here", "robot", "us", NULL};
const char *const pw_pronouns[] = {"it", "there", "that", "them", "this", "one", NULL};

static const struct {
    const char *from, *to;
} contractions[] = {
    {"what's", "what is"},   {"where's", "where is"}, {"there's", "there is"},
    {"it's", "it is"},       {"that's", "that is"},   {"let's", "let us"},
    {"i'd", "i would"},      {"i'm", "i am"},         {"can't", "cannot"},
    {"don't", "do not"},     {"won't", "will not"},   {"isn't", "is not"},
    {"who's", "who is"},     {"how's", "how is"},     {"you're", "you are"},
    {"whats", "what is"},    {"wheres", "where is"},  {"i'll", "i will"},
    {"we'd", "we would"},    {"could've", "could have"},
};

/* Lowercases into out and expands the contractions word by word. */
static void lower_expand(const char *text, char *out, size_t cap)
{
    size_t j = 0;
    const char *p = text;
    size_t read = 0;
    while (*p && read < 1000 && j + 1 < cap) {
        /* a word's extent, apostrophes (ASCII or U+2019) included */
        const char *s = p;
        char word[40];
        size_t wn = 0;
        while (*p && read < 1000 && wn + 1 < sizeof word) {
            unsigned char c = (unsigned char)*p;
            if (isalnum(c) || c == '\'') {
                word[wn++] = (char)tolower(c);
                p++, read++;
            } else if (c == 0xE2 && (unsigned char)p[1] == 0x80 && (unsigned char)p[2] == 0x99) {
                word[wn++] = '\'';
                p += 3, read += 3;
            } else {
                break;
            }
        }
        word[wn] = 0;
        if (p == s) { /* not a word character: copy it (lowercased) */
            out[j++] = (char)tolower((unsigned char)*p);
            p++, read++;
            continue;
        }
        const char *rep = word;
        for (size_t k = 0; k < sizeof contractions / sizeof contractions[0]; k++)
            if (!strcmp(word, contractions[k].from)) rep = contractions[k].to;
        for (const char *r = rep; *r && j + 1 < cap; r++) out[j++] = *r;
    }
    out[j] = 0;
}

void pw_tokenize(const char *text, pw_words *out)
{
    char buf[1200];
    lower_expand(text ? text : "", buf, sizeof buf);
    out->n = 0;
    size_t len = strlen(buf);
    for (size_t i = 0; i < len; i++) {
        unsigned char c = (unsigned char)buf[i];
        int keep = isalnum(c) || (c == '.' && i > 0 && i + 1 < len && isdigit((unsigned char)buf[i - 1]) &&
                                  isdigit((unsigned char)buf[i + 1]));
        if (c >= 0x80) keep = 1; /* non-ASCII letters stay part of words */
        if (!keep) buf[i] = ' ';
        if (c == '\'') buf[i] = 0x01; /* possessive 's is dropped below */
    }
    char *save = NULL;
    for (char *tok = strtok_r(buf, " ", &save); tok && out->n < PW_MAX_WORDS;
         tok = strtok_r(NULL, " ", &save)) {
        char w[PW_WORD];
        size_t k = 0;
        for (const char *q = tok; *q && k + 1 < sizeof w; q++) {
            if (*q == 0x01) {
                if (q[1] == 's' && q[2] == 0) break; /* "robot's" -> "robot" */
                continue;
            }
            w[k++] = *q;
        }
        w[k] = 0;
        if (k) snprintf(out->w[out->n++], PW_WORD, "%s", w);
    }
}

int pw_in(const char *w, const char *const *list)
{
    for (; *list; list++)
        if (!strcmp(w, *list)) return 1;
    return 0;
}

int pw_find(const pw_words *t, int from, const char *const *list)
{
    for (int i = from < 0 ? 0 : from; i < t->n; i++)
        if (pw_in(t->w[i], list)) return i;
    return -1;
}

/* 1 when w is base + "ing", with a final 'e' dropped ("driving") or a final consonant after one
 * vowel doubled ("getting", "running"). */
static int is_ing_form(const char *w, const char *base)
{
    size_t n = strlen(base), m = strlen(w);
    if (m < n + 2 || strcmp(w + m - 3, "ing") != 0) return 0;
    char stem[PW_WORD];
    if (m - 3 >= sizeof stem) return 0;
    memcpy(stem, w, m - 3);
    stem[m - 3] = 0;
    if (!strcmp(stem, base)) return 1;
    if (n > 1 && base[n - 1] == 'e' && m - 3 == n - 1 && !strncmp(stem, base, n - 1)) return 1;
    return m - 3 == n + 1 && !strncmp(stem, base, n) && stem[n] == base[n - 1] &&
           !strchr("aeiouwy", base[n - 1]);
}

int pw_find_verb(const pw_words *t, int from, const char *const *list)
{
    for (int i = from < 0 ? 0 : from; i < t->n; i++)
        for (const char *const *b = list; *b; b++)
            if (!strcmp(t->w[i], *b) || is_ing_form(t->w[i], *b)) return i;
    return -1;
}

int pw_match(const pw_words *t, int i, const char *phrase)
{
    int n = 0;
    const char *p = phrase;
    while (*p) {
        const char *e = strchr(p, ' ');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        if (i + n >= t->n || strlen(t->w[i + n]) != len || strncmp(t->w[i + n], p, len)) return 0;
        n++;
        p += len;
        while (*p == ' ') p++;
    }
    return n;
}

int pw_find_phrase(const pw_words *t, int from, const char *const *phrases, int *len)
{
    for (int i = from < 0 ? 0 : from; i < t->n; i++)
        for (const char *const *p = phrases; *p; p++) {
            int n = pw_match(t, i, *p);
            if (n) {
                *len = n;
                return i;
            }
        }
    return -1;
}

void pw_erase(pw_words *t, int i, int n)
{
    if (i < 0 || n <= 0 || i >= t->n) return;
    if (i + n > t->n) n = t->n - i;
    memmove(t->w[i], t->w[i + n], (size_t)(t->n - i - n) * PW_WORD);
    t->n -= n;
}

void pw_join(const pw_words *t, int from, int to, char *out, size_t cap)
{
    size_t j = 0;
    out[0] = 0;
    for (int i = from; i < to && i < t->n; i++) {
        int n = snprintf(out + j, cap - j, "%s%s", j ? " " : "", t->w[i]);
        if (n < 0 || (size_t)n >= cap - j) break;
        j += (size_t)n;
    }
}

static const char *const number_words[] = {"zero", "one", "two", "three", "four", "five", "six",
                                           "seven", "eight", "nine", "ten", NULL};
static const char *const ordinal_words[] = {"zeroth", "first", "second", "third", "fourth",
                                            "fifth", "sixth", "seventh", "eighth", "ninth",
                                            "tenth", NULL};

int pw_number(const char *w, double *v)
{
    for (int i = 0; number_words[i]; i++)
        if (!strcmp(w, number_words[i])) return *v = i, 1;
    if (!strcmp(w, "couple") || !strcmp(w, "pair")) return *v = 2, 1;
    if (!strcmp(w, "few") || !strcmp(w, "several")) return *v = 3, 1;
    if (!strcmp(w, "half")) return *v = 0.5, 1;
    if (!isdigit((unsigned char)w[0])) return 0;
    char *end;
    double d = strtod(w, &end);
    if (*end && pw_unit_m(end) == 0) return 0; /* "2m" is a number with a unit; "3rd" is not */
    *v = d;
    return 1;
}

int pw_ordinal(const char *w)
{
    for (int i = 1; ordinal_words[i]; i++)
        if (!strcmp(w, ordinal_words[i])) return i;
    int n = atoi(w);
    if (n > 0 && n < 100) {
        const char *s = w;
        while (isdigit((unsigned char)*s)) s++;
        if (!strcmp(s, "st") || !strcmp(s, "nd") || !strcmp(s, "rd") || !strcmp(s, "th")) return n;
    }
    return 0;
}

double pw_unit_m(const char *w)
{
    if (!strcmp(w, "m") || !strncmp(w, "meter", 5) || !strncmp(w, "metre", 5)) return 1.0;
    if (!strcmp(w, "cm") || !strncmp(w, "centimet", 8)) return 0.01;
    if (!strcmp(w, "mm") || !strncmp(w, "millimet", 8)) return 0.001;
    if (!strcmp(w, "ft") || !strcmp(w, "foot") || !strcmp(w, "feet")) return 0.3048;
    if (!strcmp(w, "yard") || !strcmp(w, "yards") || !strcmp(w, "yd")) return 0.9144;
    return 0;
}
