/* The CLIP tokenizer, reproducing transformers' CLIPTokenizer (5.x: the Rust `tokenizers`
 * pipeline, identical ids to CLIPTokenizerFast): the special tokens <|startoftext|> and
 * <|endoftext|> are cut out of the raw text first (exact match), then each piece is normalised
 * (NFC, every \s+ run -> ' ', per-character lower-case), split by the CLIP pattern without its
 * special-token alternatives (as transformers' converter builds it)
 *   's|'t|'re|'ve|'m|'ll|'d | \p{L}+ | \p{N} | [^\s\p{L}\p{N}]+
 * (whitespace dropped), and each piece's UTF-8 bytes go through byte-level BPE with '</w>' on
 * the last symbol. Unicode data come from unicode_tables.h (gen_unicode.py). The older Python
 * tokenizer differed (it dropped control characters, spaced CJK ideographs, used final sigma). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cJSON.h>

#include "semsplat/clip.h"
#include "semsplat/io.h"
#include "unicode_tables.h"

#define N_MERGES 48894 /* 49152 - 256 - 2: what CLIP (and HF) read from merges.txt */

struct sp_clip_tokenizer {
    int32_t byte_id[256], byte_id_w[256]; /* initial symbols: byte, byte + "</w>" */
    size_t cap;                           /* merge table (open addressing, power of two) */
    uint64_t *keys;                       /* (left id << 32 | right id) + 1, 0 = empty */
    int32_t *rank, *merged;
};

/* ---- Unicode lookups ------------------------------------------------------------------------ */

static int range_lookup(const uint32_t *starts, const uint8_t *vals, int n, uint32_t cp)
{
    int lo = 0, hi = n - 1;
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (starts[mid] <= cp) lo = mid;
        else hi = mid - 1;
    }
    return vals[lo];
}

#define NELEM(a) ((int)(sizeof(a) / sizeof((a)[0])))
enum { UC_OTHER = 0, UC_LETTER = 1, UC_NUMBER = 2, UC_SPACE = 4 };

static int uc_class(uint32_t cp)
{
    if (cp >= 0x110000) return UC_OTHER;
    return range_lookup(uc_class_start, uc_class_val, NELEM(uc_class_start), cp);
}

static int pair_find(const uint32_t (*tab)[2], int n, uint32_t cp)
{
    int lo = 0, hi = n - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        if (tab[mid][0] == cp) return mid;
        if (tab[mid][0] < cp) lo = mid + 1;
        else hi = mid - 1;
    }
    return -1;
}

static int ccc_of(uint32_t cp)
{
    if (cp < 0x300) return 0;
    int i = pair_find(uc_ccc, NELEM(uc_ccc), cp);
    return i < 0 ? 0 : (int)uc_ccc[i][1];
}

static int decomp_find(uint32_t cp)
{
    int lo = 0, hi = NELEM(uc_decomp) - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        if (uc_decomp[mid][0] == cp) return mid;
        if (uc_decomp[mid][0] < cp) lo = mid + 1;
        else hi = mid - 1;
    }
    return -1;
}

enum { S_BASE = 0xAC00, L_BASE = 0x1100, V_BASE = 0x1161, T_BASE = 0x11A7, L_COUNT = 19,
       V_COUNT = 21, T_COUNT = 28, N_COUNT = 588, S_COUNT = 11172 };

/* A growable code point buffer. */
typedef struct { uint32_t *v; size_t n, cap; int oom; } cpbuf;

static void cp_push(cpbuf *b, uint32_t c)
{
    if (b->n == b->cap) {
        size_t nc = b->cap ? b->cap * 2 : 64;
        uint32_t *nv = realloc(b->v, nc * sizeof *nv);
        if (!nv) { b->oom = 1; return; }
        b->v = nv;
        b->cap = nc;
    }
    b->v[b->n++] = c;
}

static void decompose(uint32_t cp, cpbuf *out)
{
    if (cp >= S_BASE && cp < S_BASE + S_COUNT) {
        uint32_t s = cp - S_BASE;
        cp_push(out, L_BASE + s / N_COUNT);
        cp_push(out, V_BASE + (s % N_COUNT) / T_COUNT);
        if (s % T_COUNT) cp_push(out, T_BASE + s % T_COUNT);
        return;
    }
    int i = cp < 0xC0 ? -1 : decomp_find(cp);
    if (i < 0) {
        cp_push(out, cp);
        return;
    }
    decompose(uc_decomp[i][1], out);
    if (uc_decomp[i][2]) decompose(uc_decomp[i][2], out);
}

static uint32_t compose_pair(uint32_t a, uint32_t b)
{
    if (a >= L_BASE && a < L_BASE + L_COUNT && b >= V_BASE && b < V_BASE + V_COUNT)
        return S_BASE + ((a - L_BASE) * V_COUNT + (b - V_BASE)) * T_COUNT;
    if (a >= S_BASE && a < S_BASE + S_COUNT && (a - S_BASE) % T_COUNT == 0 && b > T_BASE &&
        b < T_BASE + T_COUNT)
        return a + (b - T_BASE);
    int lo = 0, hi = NELEM(uc_comp) - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        const uint32_t *e = uc_comp[mid];
        if (e[0] == a && e[1] == b) return e[2];
        if (e[0] < a || (e[0] == a && e[1] < b)) lo = mid + 1;
        else hi = mid - 1;
    }
    return 0;
}

/* Unicode NFC (UAX #15: full canonical decomposition, canonical ordering, composition). */
static void nfc(cpbuf *b)
{
    int ascii = 1;
    for (size_t i = 0; i < b->n && ascii; i++) ascii = b->v[i] < 0x80;
    if (ascii) return;
    cpbuf d = {0};
    for (size_t i = 0; i < b->n; i++) decompose(b->v[i], &d);
    if (d.oom) { b->oom = 1; free(d.v); return; }
    for (size_t i = 1; i < d.n; i++) { /* stable insertion sort of combining-mark runs */
        int c = ccc_of(d.v[i]);
        if (!c) continue;
        size_t j = i;
        while (j > 0) {
            int p = ccc_of(d.v[j - 1]);
            if (p <= c) break;
            uint32_t t = d.v[j]; d.v[j] = d.v[j - 1]; d.v[j - 1] = t;
            j--;
        }
    }
    b->n = 0;
    long starter = -1;
    int last = 0;
    for (size_t i = 0; i < d.n; i++) {
        uint32_t c = d.v[i];
        int cc = ccc_of(c);
        if (starter >= 0 && (b->n == (size_t)starter + 1 || (last != 0 && last < cc))) {
            uint32_t k = compose_pair(b->v[starter], c);
            if (k) { b->v[starter] = k; continue; }
        }
        if (cc == 0) starter = (long)b->n;
        last = cc;
        cp_push(b, c);
    }
    free(d.v);
}

/* Per-character full lower-case mapping (Rust's char::to_lowercase): U+0130 -> i + U+0307, no
 * final-sigma context. */
static void lower_into(const uint32_t *v, size_t a, size_t b, cpbuf *out)
{
    for (size_t i = a; i < b; i++) {
        uint32_t c = v[i];
        if (c < 0x80) {
            cp_push(out, (c >= 'A' && c <= 'Z') ? c + 32 : c);
        } else if (c == 0x130) {
            cp_push(out, 'i');
            cp_push(out, 0x307);
        } else {
            int k = pair_find(uc_lower, NELEM(uc_lower), c);
            cp_push(out, k < 0 ? c : uc_lower[k][1]);
        }
    }
}

/* UTF-8 to code points as Python's decode(errors="replace") would (maximal subparts). */
static void utf8_decode(const unsigned char *s, cpbuf *out)
{
    while (*s) {
        unsigned c = *s;
        if (c < 0x80) { cp_push(out, c); s++; continue; }
        int n; uint32_t cp, min;
        if (c >= 0xC2 && c <= 0xDF) { n = 1; cp = c & 0x1F; min = 0x80; }
        else if (c >= 0xE0 && c <= 0xEF) { n = 2; cp = c & 0x0F; min = 0x800; }
        else if (c >= 0xF0 && c <= 0xF4) { n = 3; cp = c & 0x07; min = 0x10000; }
        else { cp_push(out, 0xFFFD); s++; continue; }
        int k = 1;
        for (; k <= n; k++) {
            unsigned d = s[k];
            if ((d & 0xC0) != 0x80) break;
            cp = (cp << 6) | (d & 0x3F);
            /* reject overlongs / surrogates / > U+10FFFF at the second byte, as Python does */
            if (k == 1) {
                if ((c == 0xE0 && d < 0xA0) || (c == 0xED && d > 0x9F) || (c == 0xF0 && d < 0x90) ||
                    (c == 0xF4 && d > 0x8F))
                    break;
            }
        }
        if (k <= n) { cp_push(out, 0xFFFD); s += k; continue; }
        cp_push(out, cp >= min ? cp : 0xFFFD);
        s += n + 1;
    }
}

static int utf8_encode(uint32_t c, unsigned char *o)
{
    if (c < 0x80) { o[0] = (unsigned char)c; return 1; }
    if (c < 0x800) { o[0] = 0xC0 | (c >> 6); o[1] = 0x80 | (c & 0x3F); return 2; }
    if (c < 0x10000) {
        o[0] = 0xE0 | (c >> 12); o[1] = 0x80 | ((c >> 6) & 0x3F); o[2] = 0x80 | (c & 0x3F);
        return 3;
    }
    o[0] = 0xF0 | (c >> 18); o[1] = 0x80 | ((c >> 12) & 0x3F);
    o[2] = 0x80 | ((c >> 6) & 0x3F); o[3] = 0x80 | (c & 0x3F);
    return 4;
}

/* ---- BPE --------------------------------------------------------------------------------------- */

static uint64_t hash64(uint64_t x)
{
    x ^= x >> 33; x *= 0xff51afd7ed558ccdULL; x ^= x >> 33; x *= 0xc4ceb9fe1a85ec53ULL;
    return x ^ (x >> 33);
}

static long merge_lookup(const sp_clip_tokenizer *t, int32_t a, int32_t b)
{
    uint64_t key = (((uint64_t)(uint32_t)a << 32) | (uint32_t)b) + 1;
    size_t m = t->cap - 1;
    for (size_t h = hash64(key) & m;; h = (h + 1) & m) {
        if (t->keys[h] == key) return (long)h;
        if (!t->keys[h]) return -1;
    }
}

typedef struct { int32_t *ids; int cap; int n; int oom; } idlist;

static void id_push(idlist *l, int32_t id)
{
    if (l->n < l->cap) l->ids[l->n] = id;
    l->n++;
}

/* BPE of one pre-token (its UTF-8 bytes): repeatedly merge the lowest-ranked adjacent pair. */
static void bpe_word(const sp_clip_tokenizer *t, const unsigned char *bytes, size_t len,
                     idlist *out, int32_t *work)
{
    size_t n = len;
    for (size_t i = 0; i < len; i++)
        work[i] = i + 1 == len ? t->byte_id_w[bytes[i]] : t->byte_id[bytes[i]];
    while (n > 1) {
        int32_t best = INT32_MAX;
        long best_slot = -1;
        for (size_t i = 0; i + 1 < n; i++) {
            long s = merge_lookup(t, work[i], work[i + 1]);
            if (s >= 0 && t->rank[s] < best) { best = t->rank[s]; best_slot = s; }
        }
        if (best_slot < 0) break;
        int32_t a = (int32_t)((t->keys[best_slot] - 1) >> 32);
        int32_t b = (int32_t)((t->keys[best_slot] - 1) & 0xffffffffu);
        size_t j = 0;
        for (size_t i = 0; i < n;) {
            if (i + 1 < n && work[i] == a && work[i + 1] == b) {
                work[j++] = t->merged[best_slot];
                i += 2;
            } else {
                work[j++] = work[i++];
            }
        }
        n = j;
    }
    for (size_t i = 0; i < n; i++) id_push(out, work[i]);
}

/* ---- pre-tokenization -------------------------------------------------------------------------- */

static int match_lit(const uint32_t *v, size_t n, size_t i, const char *lit)
{
    size_t k = 0;
    for (; lit[k]; k++)
        if (i + k >= n || v[i + k] != (uint32_t)(unsigned char)lit[k]) return 0;
    return (int)k;
}

static int emit(const sp_clip_tokenizer *t, const uint32_t *v, size_t a, size_t b, idlist *out)
{
    size_t cap = (b - a) * 4;
    unsigned char *bytes = malloc(cap + 1);
    int32_t *work = malloc((cap + 1) * sizeof *work);
    if (!bytes || !work) { free(bytes); free(work); return -1; }
    size_t len = 0;
    for (size_t i = a; i < b; i++) len += (size_t)utf8_encode(v[i], bytes + len);
    bpe_word(t, bytes, len, out, work);
    free(bytes);
    free(work);
    return 0;
}

static int pretokenize(const sp_clip_tokenizer *t, const uint32_t *v, size_t n, idlist *out)
{
    static const char *const contractions[] = {"'s", "'t", "'re", "'ve", "'m", "'ll", "'d"};
    size_t i = 0;
    while (i < n) {
        int k = 0;
        int cls = uc_class(v[i]);
        if (cls == UC_SPACE) { i++; continue; }
        size_t j = i;
        for (int c = 0; c < 7 && !k; c++) k = match_lit(v, n, i, contractions[c]);
        if (k) j = i + (size_t)k;
        else if (cls == UC_LETTER) { while (j < n && uc_class(v[j]) == UC_LETTER) j++; }
        else if (cls == UC_NUMBER) j = i + 1;
        else {
            while (j < n) {
                int c = uc_class(v[j]);
                if (c == UC_LETTER || c == UC_NUMBER || c == UC_SPACE) break;
                j++;
            }
        }
        if (emit(t, v, i, j, out)) return -1;
        i = j;
    }
    return 0;
}

/* Normalises v[a..b) (NFC, whitespace runs -> ' ', lower-case) and pre-tokenizes it into out. */
static int tokenize_piece(const sp_clip_tokenizer *t, const uint32_t *v, size_t a, size_t b, idlist *out)
{
    cpbuf nf = {0}, low = {0};
    int rc = 0;
    for (size_t i = a; i < b; i++) cp_push(&nf, v[i]);
    nfc(&nf);
    for (size_t i = 0; i < nf.n;) {
        if (uc_class(nf.v[i]) == UC_SPACE) {
            while (i < nf.n && uc_class(nf.v[i]) == UC_SPACE) i++;
            cp_push(&low, ' ');
            continue;
        }
        size_t j = i;
        while (j < nf.n && uc_class(nf.v[j]) != UC_SPACE) j++;
        lower_into(nf.v, i, j, &low);
        i = j;
    }
    if (nf.oom || low.oom || pretokenize(t, low.v, low.n, out)) rc = -1;
    free(nf.v);
    free(low.v);
    return rc;
}

int sp_clip_tokenize(const sp_clip_tokenizer *t, const char *text, int32_t *ids, int cap,
                     int *n_out, sp_error *err)
{
    cpbuf raw = {0};
    int rc = 0;
    utf8_decode((const unsigned char *)(text ? text : ""), &raw);
    idlist out = {ids, ids ? cap : 0, 0, 0};
    /* special tokens are matched on the raw text, before any normalisation */
    size_t start = 0;
    for (size_t i = 0; i <= raw.n && !rc && !raw.oom; i++) {
        int k = 0;
        int32_t special = 0;
        if (i < raw.n && (k = match_lit(raw.v, raw.n, i, "<|startoftext|>"))) special = SP_CLIP_BOS;
        else if (i < raw.n && (k = match_lit(raw.v, raw.n, i, "<|endoftext|>"))) special = SP_CLIP_EOS;
        if (!special && i < raw.n) continue;
        if (i > start && tokenize_piece(t, raw.v, start, i, &out)) rc = -1;
        if (special) id_push(&out, special);
        start = i + (size_t)k;
        if (k) i += (size_t)k - 1;
    }
    if (raw.oom || rc)
        rc = sp_error_set(err, SP_E_NOMEM, "tokenizer: out of memory (text of %zu code points)",
                          raw.n);
    *n_out = out.n;
    free(raw.v);
    return rc;
}

int sp_clip_tokenize_context(const sp_clip_tokenizer *t, const char *text,
                             int32_t ids[SP_CLIP_CONTEXT], int *len, sp_error *err)
{
    int n = 0;
    ids[0] = SP_CLIP_BOS;
    int rc = sp_clip_tokenize(t, text, ids + 1, SP_CLIP_CONTEXT - 2, &n, err);
    if (rc) return rc;
    if (n > SP_CLIP_CONTEXT - 2) n = SP_CLIP_CONTEXT - 2;
    ids[n + 1] = SP_CLIP_EOS;
    for (int i = n + 2; i < SP_CLIP_CONTEXT; i++) ids[i] = SP_CLIP_EOS;
    if (len) *len = n + 2;
    return 0;
}

/* ---- loading ----------------------------------------------------------------------------------- */

/* bytes_to_unicode of GPT-2/CLIP: printable bytes map to themselves, the rest to 256+k. */
static void byte_unicode(uint32_t map[256])
{
    int n = 0;
    for (int b = 0; b < 256; b++) {
        int printable = (b >= '!' && b <= '~') || (b >= 0xA1 && b <= 0xAC) || (b >= 0xAE && b <= 0xFF);
        map[b] = printable ? (uint32_t)b : (uint32_t)(256 + n++);
    }
}

void sp_clip_tokenizer_free(sp_clip_tokenizer *t)
{
    if (!t) return;
    free(t->keys);
    free(t->rank);
    free(t->merged);
    free(t);
}

/* vocab.json as a string -> id hash table (cJSON's own lookup is a linear scan). */
typedef struct { size_t cap; const char **keys; int32_t *ids; } strmap;

static uint64_t hash_str(const char *s)
{
    uint64_t h = 1469598103934665603ULL;
    for (; *s; s++) h = (h ^ (unsigned char)*s) * 1099511628211ULL;
    return h;
}

static int strmap_build(strmap *m, const cJSON *vocab)
{
    m->cap = 1;
    while (m->cap < (size_t)cJSON_GetArraySize(vocab) * 2 + 16) m->cap *= 2;
    m->keys = calloc(m->cap, sizeof *m->keys);
    m->ids = calloc(m->cap, sizeof *m->ids);
    if (!m->keys || !m->ids) return -1;
    const cJSON *it;
    cJSON_ArrayForEach(it, vocab) {
        long id;
        if (!it->string || sp_json_int(it, 0, INT32_MAX, &id)) continue;
        size_t h = hash_str(it->string) & (m->cap - 1);
        while (m->keys[h] && strcmp(m->keys[h], it->string)) h = (h + 1) & (m->cap - 1);
        m->keys[h] = it->string;
        m->ids[h] = (int32_t)id;
    }
    return 0;
}

static int32_t vocab_id(const strmap *m, const char *s)
{
    for (size_t h = hash_str(s) & (m->cap - 1); m->keys[h]; h = (h + 1) & (m->cap - 1))
        if (!strcmp(m->keys[h], s)) return m->ids[h];
    return -1;
}

int sp_clip_tokenizer_load(sp_clip_tokenizer **out, const char *dir, sp_error *err)
{
    *out = NULL;
    char base[1024], vpath[1200], mpath[1200];
    if (dir) snprintf(base, sizeof base, "%s", dir);
    else sp_path_join(base, sizeof base, sp_data_dir(), "clip");
    sp_path_join(vpath, sizeof vpath, base, "vocab.json");
    sp_path_join(mpath, sizeof mpath, base, "merges.txt");
    char *vtext = NULL, *mtext = NULL;
    size_t vsize, msize;
    cJSON *vocab = NULL;
    strmap vm = {0};
    sp_clip_tokenizer *t = calloc(1, sizeof *t);
    int rc;
    if (!t) return sp_error_set(err, SP_E_NOMEM, "tokenizer: out of memory");
    if ((rc = sp_read_file(vpath, &vtext, &vsize, err))) goto fail;
    if ((rc = sp_read_file(mpath, &mtext, &msize, err))) goto fail;
    vocab = cJSON_ParseWithLength(vtext, vsize);
    if (!cJSON_IsObject(vocab)) {
        rc = sp_error_set(err, SP_E_FORMAT, "%s: not a JSON object", vpath);
        goto fail;
    }
    if (strmap_build(&vm, vocab)) {
        rc = sp_error_set(err, SP_E_NOMEM, "tokenizer: out of memory");
        goto fail;
    }
    uint32_t bmap[256];
    byte_unicode(bmap);
    for (int b = 0; b < 256; b++) {
        char s[16];
        int l = utf8_encode(bmap[b], (unsigned char *)s);
        s[l] = 0;
        t->byte_id[b] = vocab_id(&vm, s);
        snprintf(s + l, sizeof s - (size_t)l, "</w>");
        t->byte_id_w[b] = vocab_id(&vm, s);
        if (t->byte_id[b] < 0 || t->byte_id_w[b] < 0) {
            rc = sp_error_set(err, SP_E_FORMAT, "%s: byte token for 0x%02X missing", vpath, b);
            goto fail;
        }
    }
    t->cap = 131072;
    t->keys = calloc(t->cap, sizeof *t->keys);
    t->rank = calloc(t->cap, sizeof *t->rank);
    t->merged = calloc(t->cap, sizeof *t->merged);
    if (!t->keys || !t->rank || !t->merged) {
        rc = sp_error_set(err, SP_E_NOMEM, "tokenizer: out of memory");
        goto fail;
    }
    char *line = mtext, *next;
    int lineno = 0, rank = 0;
    for (; line && *line && rank < N_MERGES; line = next) {
        next = strchr(line, '\n');
        if (next) *next++ = 0;
        lineno++;
        size_t L = strlen(line);
        if (L && line[L - 1] == '\r') line[--L] = 0;
        if (lineno == 1 && !strncmp(line, "#version", 8)) continue;
        char *sp = strchr(line, ' ');
        if (!sp || sp == line || !sp[1] || strchr(sp + 1, ' ')) {
            rc = sp_error_set(err, SP_E_FORMAT, "%s:%d: expected two symbols", mpath, lineno);
            goto fail;
        }
        *sp = 0;
        char joined[512];
        snprintf(joined, sizeof joined, "%s%s", line, sp + 1);
        int32_t a = vocab_id(&vm, line), b = vocab_id(&vm, sp + 1), m = vocab_id(&vm, joined);
        if (a < 0 || b < 0 || m < 0) {
            rc = sp_error_set(err, SP_E_FORMAT, "%s:%d: '%s %s' not in %s", mpath, lineno, line,
                              sp + 1, vpath);
            goto fail;
        }
        uint64_t key = (((uint64_t)(uint32_t)a << 32) | (uint32_t)b) + 1;
        size_t h = hash64(key) & (t->cap - 1);
        while (t->keys[h] && t->keys[h] != key) h = (h + 1) & (t->cap - 1);
        t->keys[h] = key; /* a repeated pair keeps its last rank, as HF's dict(zip(...)) */
        t->rank[h] = rank;
        t->merged[h] = m;
        rank++;
    }
    if (rank < 1000) {
        rc = sp_error_set(err, SP_E_FORMAT, "%s: only %d merges", mpath, rank);
        goto fail;
    }
    free(vm.keys);
    free(vm.ids);
    cJSON_Delete(vocab);
    free(vtext);
    free(mtext);
    *out = t;
    return 0;
fail:
    free(vm.keys);
    free(vm.ids);
    cJSON_Delete(vocab);
    free(vtext);
    free(mtext);
    sp_clip_tokenizer_free(t);
    return rc;
}
