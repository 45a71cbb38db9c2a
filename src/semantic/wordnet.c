/* WordNet 3.0 database reader: binary search in the sorted index and exception files, synsets
 * read from the data files at their byte offset. The files are mapped read-only (mmap): a lookup
 * touches a few pages and makes no system call, and threads share the mapping. */
#include "wordnet.h"

#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#define WIN 1024 /* index and exception lines are shorter (index.verb's longest: 567 bytes) */

static const char *const pos_file[WN_NPOS] = {"noun", "verb", "adj", "adv"};

typedef struct wn_file {
    int fd;
    off_t size;
    const char *map; /* the whole file, read-only */
    char path[1100];
} wn_file;

struct wn_db {
    char dir[1024];
    wn_file index[WN_NPOS], data[WN_NPOS], exc[WN_NPOS];
};

static int file_open(wn_file *f, const char *dir, const char *name, sp_error *err)
{
    snprintf(f->path, sizeof f->path, "%s/%s", dir, name);
    f->fd = open(f->path, O_RDONLY | O_CLOEXEC);
    if (f->fd < 0)
        return sp_error_set(err, errno == ENOENT ? SP_E_NOTFOUND : SP_E_IO,
                            "%s: %s (WordNet 3.0 database files: install Debian's wordnet-base, "
                            "or name the folder holding index.noun and data.noun)",
                            f->path, strerror(errno));
    struct stat st;
    if (fstat(f->fd, &st) != 0) return sp_error_set(err, SP_E_IO, "%s: %s", f->path, strerror(errno));
    f->size = st.st_size;
    if (f->size == 0) return sp_error_set(err, SP_E_FORMAT, "%s: empty file", f->path);
    void *m = mmap(NULL, (size_t)f->size, PROT_READ, MAP_SHARED, f->fd, 0);
    if (m == MAP_FAILED) return sp_error_set(err, SP_E_IO, "%s: mmap: %s", f->path, strerror(errno));
    f->map = m;
    return 0;
}

static void file_close(wn_file *f)
{
    if (f->map) munmap((void *)f->map, (size_t)f->size);
    if (f->fd >= 0) close(f->fd);
}

void wn_close(wn_db *db)
{
    if (!db) return;
    for (int p = 0; p < WN_NPOS; p++) {
        file_close(&db->index[p]);
        file_close(&db->data[p]);
        file_close(&db->exc[p]);
    }
    free(db);
}

const char *wn_dir(const wn_db *db) { return db->dir; }

int wn_open(wn_db **out, const char *dir, sp_error *err)
{
    *out = NULL;
    wn_db *db = calloc(1, sizeof *db);
    if (!db) return sp_error_set(err, SP_E_NOMEM, "wordnet: out of memory");
    for (int p = 0; p < WN_NPOS; p++) db->index[p].fd = db->data[p].fd = db->exc[p].fd = -1;
    /* (maps are NULL from calloc) */
    snprintf(db->dir, sizeof db->dir, "%s", dir);
    int rc = 0;
    char name[32];
    for (int p = 0; p < WN_NPOS && !rc; p++) {
        snprintf(name, sizeof name, "index.%s", pos_file[p]);
        rc = file_open(&db->index[p], dir, name, err);
        snprintf(name, sizeof name, "data.%s", pos_file[p]);
        if (!rc) rc = file_open(&db->data[p], dir, name, err);
        snprintf(name, sizeof name, "%s.exc", pos_file[p]);
        if (!rc) rc = file_open(&db->exc[p], dir, name, err);
    }
    if (!rc) {
        /* The first noun synset of WordNet 3.0: a wrong folder or another version fails here. */
        wn_synset s;
        wn_id entity = {1740, WN_NOUN};
        rc = wn_read(db, entity, &s, err);
        if (!rc) {
            if (s.n_words < 1 || strcmp(s.words[0], "entity"))
                rc = sp_error_set(err, SP_E_FORMAT, "%s: offset 00001740 is not 'entity' (not WordNet 3.0?)",
                                  db->data[WN_NOUN].path);
            wn_synset_free(&s);
        }
        if (rc) sp_error_prefix(err, "wordnet: ");
    }
    if (rc) {
        wn_close(db);
        return rc;
    }
    *out = db;
    return 0;
}

/* The line holding byte pos of f: [*start, *end). */
static void line_at(const wn_file *f, off_t pos, off_t *start, off_t *end)
{
    off_t s = pos, e = pos;
    while (s > 0 && f->map[s - 1] != '\n') s--;
    while (e < f->size && f->map[e] != '\n') e++;
    *start = s;
    *end = e;
}

/* strcmp of key with the first field (up to a space) of the line at p. */
static int cmp_key(const char *key, const char *p, const char *end)
{
    const unsigned char *a = (const unsigned char *)key, *b = (const unsigned char *)p;
    const unsigned char *be = (const unsigned char *)end;
    while (*a && b < be && *b != ' ' && *b != '\n' && *a == *b) a++, b++;
    int bend = b >= be || *b == ' ' || *b == '\n';
    if (!*a && bend) return 0;
    if (!*a) return -1;
    if (bend) return 1;
    return (int)*a - (int)*b;
}

/* Binary search of a file of lines sorted by their first field (license lines, which start with
 * spaces, sort first). Returns 1 and the line (NUL-terminated) when found, 0 when not, negative
 * on a line too long for the buffer. */
static int find_line(const wn_file *f, const char *key, char line[2 * WIN + 1], sp_error *err)
{
    off_t lo = 0, hi = f->size;
    while (lo < hi) {
        off_t mid = lo + (hi - lo) / 2, s, e;
        line_at(f, mid, &s, &e);
        int c = cmp_key(key, f->map + s, f->map + e);
        if (c == 0) {
            if (e - s > 2 * WIN)
                return sp_error_set(err, SP_E_FORMAT, "%s: line at byte %lld is longer than %d bytes",
                                    f->path, (long long)s, 2 * WIN);
            memcpy(line, f->map + s, (size_t)(e - s));
            line[e - s] = 0;
            return 1;
        }
        if (c < 0) hi = s;
        else lo = e + 1;
    }
    return 0;
}

/* Normalises a lemma for the index: lower case, spaces as '_'. */
static void index_key(const char *lemma, char *key)
{
    size_t i = 0;
    for (; lemma[i] && i + 1 < WN_LEMMA_MAX; i++)
        key[i] = lemma[i] == ' ' ? '_' : (char)tolower((unsigned char)lemma[i]);
    key[i] = 0;
}

int wn_lookup(const wn_db *db, wn_pos pos, const char *lemma, uint32_t *offsets, int cap,
              int *tagged, sp_error *err)
{
    char key[WN_LEMMA_MAX], line[2 * WIN + 1];
    if (tagged) *tagged = 0;
    if (!lemma[0] || strlen(lemma) >= WN_LEMMA_MAX) return 0;
    index_key(lemma, key);
    int rc = find_line(&db->index[pos], key, line, err);
    if (rc <= 0) return rc;
    /* lemma pos synset_cnt p_cnt [ptr_symbol...] sense_cnt tagsense_cnt synset_offset... */
    char *save = NULL, *tok = strtok_r(line, " ", &save);
    tok = strtok_r(NULL, " ", &save);
    char *cnt_s = strtok_r(NULL, " ", &save), *pcnt_s = strtok_r(NULL, " ", &save);
    if (!tok || !cnt_s || !pcnt_s) goto bad;
    int n = atoi(cnt_s), np = atoi(pcnt_s);
    for (int i = 0; i < np; i++)
        if (!strtok_r(NULL, " ", &save)) goto bad;
    if (!strtok_r(NULL, " ", &save)) goto bad; /* sense_cnt (= synset_cnt) */
    char *tag_s = strtok_r(NULL, " ", &save);
    if (!tag_s) goto bad;
    if (tagged) *tagged = atoi(tag_s);
    int k = 0;
    for (int i = 0; i < n; i++) {
        char *o = strtok_r(NULL, " ", &save);
        if (!o) goto bad;
        if (k < cap) offsets[k++] = (uint32_t)strtoul(o, NULL, 10);
    }
    return k;
bad:
    return sp_error_set(err, SP_E_FORMAT, "%s: malformed entry for '%s'", db->index[pos].path, key);
}

int wn_has(const wn_db *db, wn_pos pos, const char *lemma, sp_error *err)
{
    char key[WN_LEMMA_MAX], line[2 * WIN + 1];
    if (!lemma[0] || strlen(lemma) >= WN_LEMMA_MAX) return 0;
    index_key(lemma, key);
    return find_line(&db->index[pos], key, line, err);
}

/* ---- morphy ------------------------------------------------------------------------------------ */

typedef struct {
    const char *suffix, *ending;
} detach_rule;

/* Princeton morphy's detachment rules (morph.c). */
static const detach_rule noun_rules[] = {{"s", ""},     {"ses", "s"},   {"xes", "x"},   {"zes", "z"},
                                         {"ches", "ch"}, {"shes", "sh"}, {"men", "man"}, {"ies", "y"},
                                         {NULL, NULL}};
static const detach_rule verb_rules[] = {{"s", ""},  {"ies", "y"}, {"es", "e"},  {"es", ""},
                                         {"ed", "e"}, {"ed", ""},   {"ing", "e"}, {"ing", ""},
                                         {NULL, NULL}};
static const detach_rule adj_rules[] = {{"er", ""}, {"est", ""}, {"er", "e"}, {"est", "e"}, {NULL, NULL}};
static const detach_rule *const rules[WN_NPOS] = {noun_rules, verb_rules, adj_rules, NULL};

static int add_base(char out[][WN_LEMMA_MAX], int n, const char *b)
{
    if (n >= WN_MAX_BASES) return n;
    for (int i = 0; i < n; i++)
        if (!strcmp(out[i], b)) return n;
    snprintf(out[n], WN_LEMMA_MAX, "%s", b);
    return n + 1;
}

static int ends_with(const char *s, const char *suf)
{
    size_t a = strlen(s), b = strlen(suf);
    return a >= b && !strcmp(s + a - b, suf);
}

/* Base forms of one word (no '_'): exceptions, then rules. */
static int morph_word(const wn_db *db, wn_pos pos, const char *w, char out[][WN_LEMMA_MAX], int n,
                      sp_error *err)
{
    char line[2 * WIN + 1];
    int rc = wn_has(db, pos, w, err);
    if (rc < 0) return rc;
    if (rc) n = add_base(out, n, w);
    rc = find_line(&db->exc[pos], w, line, err);
    if (rc < 0) return rc;
    if (rc) {
        char *save = NULL, *tok = strtok_r(line, " ", &save);
        while ((tok = strtok_r(NULL, " ", &save))) n = add_base(out, n, tok);
    }
    const detach_rule *r = rules[pos];
    size_t len = strlen(w);
    if (!r || (pos == WN_NOUN && (len <= 2 || ends_with(w, "ss")))) return n;
    for (; r->suffix; r++) {
        size_t ls = strlen(r->suffix);
        if (len <= ls || !ends_with(w, r->suffix)) continue;
        char cand[WN_LEMMA_MAX];
        snprintf(cand, sizeof cand, "%.*s%s", (int)(len - ls), w, r->ending);
        if ((rc = wn_has(db, pos, cand, err)) < 0) return rc;
        if (rc) n = add_base(out, n, cand);
    }
    return n;
}

int wn_morphy(const wn_db *db, wn_pos pos, const char *word, char out[][WN_LEMMA_MAX], sp_error *err)
{
    char key[WN_LEMMA_MAX];
    if (!word[0] || strlen(word) >= WN_LEMMA_MAX) return 0;
    index_key(word, key);
    const char *us = strrchr(key, '_');
    if (!us) return morph_word(db, pos, key, out, 0, err);
    /* A collocation: itself, then its last word inflected ("dining_chairs" -> "dining_chair"). */
    int n = 0, rc = wn_has(db, pos, key, err);
    if (rc < 0) return rc;
    if (rc) n = add_base(out, n, key);
    char last[WN_MAX_BASES][WN_LEMMA_MAX];
    int nl = morph_word(db, pos, us + 1, last, 0, err);
    if (nl < 0) return nl;
    for (int i = 0; i < nl; i++) {
        char cand[2 * WN_LEMMA_MAX];
        snprintf(cand, sizeof cand, "%.*s_%s", (int)(us - key), key, last[i]);
        if (strlen(cand) >= WN_LEMMA_MAX) continue;
        if ((rc = wn_has(db, pos, cand, err)) < 0) return rc;
        if (rc) n = add_base(out, n, cand);
    }
    return n;
}

/* ---- synsets ----------------------------------------------------------------------------------- */

void wn_synset_free(wn_synset *s)
{
    if (!s) return;
    free(s->pointers);
    free(s->line);
    memset(s, 0, sizeof *s);
}

static int pos_of(char c)
{
    switch (c) {
    case 'n': return WN_NOUN;
    case 'v': return WN_VERB;
    case 'a': case 's': return WN_ADJ;
    case 'r': return WN_ADV;
    default: return -1;
    }
}

/* Copies the whole data line at offset (lines run up to 13 kB: "city" has 600 instances). */
static int read_data_line(const wn_file *f, uint32_t offset, char **out, sp_error *err)
{
    if ((off_t)offset >= f->size || (offset > 0 && f->map[offset - 1] != '\n'))
        return sp_error_set(err, SP_E_FORMAT, "%s: no synset line starts at offset %08u", f->path, offset);
    const char *p = f->map + offset, *nl = memchr(p, '\n', (size_t)(f->size - (off_t)offset));
    if (!nl) return sp_error_set(err, SP_E_FORMAT, "%s: truncated synset at offset %08u", f->path, offset);
    size_t n = (size_t)(nl - p);
    char *buf = malloc(n + 1);
    if (!buf) return sp_error_set(err, SP_E_NOMEM, "wordnet: out of memory");
    memcpy(buf, p, n);
    buf[n] = 0;
    *out = buf;
    return 0;
}

int wn_read(const wn_db *db, wn_id id, wn_synset *out, sp_error *err)
{
    memset(out, 0, sizeof *out);
    if (id.pos >= WN_NPOS) return sp_error_set(err, SP_E_ARG, "wordnet: bad part of speech %d", id.pos);
    const wn_file *f = &db->data[id.pos];
    char *line = NULL;
    int rc = read_data_line(f, id.offset, &line, err);
    if (rc) return rc;
    out->line = line;
    out->id = id;
    char *save = NULL, *t = strtok_r(line, " ", &save);
    if (!t || strtoul(t, NULL, 10) != id.offset || strlen(t) != 8) goto bad;
    char *lex = strtok_r(NULL, " ", &save), *type = strtok_r(NULL, " ", &save),
         *wc = strtok_r(NULL, " ", &save);
    if (!lex || !type || !wc || pos_of(type[0]) != id.pos) goto bad;
    out->lexfile = atoi(lex);
    int nw = (int)strtol(wc, NULL, 16);
    for (int i = 0; i < nw; i++) {
        char *w = strtok_r(NULL, " ", &save);
        if (!w || !strtok_r(NULL, " ", &save)) goto bad; /* word, lex_id */
        char *paren = strchr(w, '(');                    /* adjective markers: (a) (p) (ip) */
        if (paren) *paren = 0;
        if (out->n_words < WN_MAX_WORDS) out->words[out->n_words++] = w;
    }
    char *pc = strtok_r(NULL, " ", &save);
    if (!pc) goto bad;
    int np = atoi(pc);
    out->pointers = calloc(np ? (size_t)np : 1, sizeof(wn_pointer));
    if (!out->pointers) {
        wn_synset_free(out);
        return sp_error_set(err, SP_E_NOMEM, "wordnet: out of memory");
    }
    for (int i = 0; i < np; i++) {
        char *sym = strtok_r(NULL, " ", &save), *off = strtok_r(NULL, " ", &save),
             *ps = strtok_r(NULL, " ", &save), *st = strtok_r(NULL, " ", &save);
        if (!sym || !off || !ps || !st || strlen(sym) > 3 || pos_of(ps[0]) < 0 || strlen(st) != 4) goto bad;
        wn_pointer *p = &out->pointers[out->n_pointers++];
        snprintf(p->symbol, sizeof p->symbol, "%s", sym);
        p->target.offset = (uint32_t)strtoul(off, NULL, 10);
        p->target.pos = (uint8_t)pos_of(ps[0]);
        unsigned v = (unsigned)strtoul(st, NULL, 16);
        p->source_word = (uint8_t)(v >> 8);
        p->target_word = (uint8_t)(v & 0xff);
    }
    /* Verb frames (skipped), then "| gloss". The rest of the line is the gloss. */
    char *bar = save ? strchr(save, '|') : NULL;
    if (!bar) goto bad;
    bar++;
    while (*bar == ' ') bar++;
    size_t gl = strlen(bar);
    while (gl > 0 && (bar[gl - 1] == ' ' || bar[gl - 1] == '\r')) bar[--gl] = 0;
    out->gloss = bar;
    return 0;
bad:
    wn_synset_free(out);
    return sp_error_set(err, SP_E_FORMAT, "%s: malformed synset at offset %08u", f->path, id.offset);
}

void wn_definition(const char *gloss, char *out, size_t cap)
{
    size_t n = 0;
    for (const char *p = gloss; *p && n + 1 < cap; p++) {
        if (*p == '"' || (*p == ';' && p[1] == ' ' && p[2] == '"')) break;
        out[n++] = *p;
    }
    while (n > 0 && (out[n - 1] == ' ' || out[n - 1] == ';')) n--;
    out[n] = 0;
}
