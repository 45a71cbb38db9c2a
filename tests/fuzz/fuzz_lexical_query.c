/* The lexical text encoder's query text (any bytes, up to the first NUL, as a user types them to
 * `semsplat query` or the agent): matching never crashes, fails only with a clear error (empty
 * text), and gives a well-formed result: scores in [0, 1], class indices in range, a relation
 * only with an anchor, found agreeing with the threshold; its JSON and explanation are built
 * too. The vocabulary is a house's and a shop's classes with the shipped region and alias tables,
 * so regions, relations, aliases and collocations are all reached. */
#include "fuzz_util.h"
#include "semsplat/semantic.h"

static sp_lexicon *lx;
static sp_lex_vocab *vocab;
static sp_lex_result *res;

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    static const char *const classes[] = {
        "refrigerator", "stove", "kitchen counter", "sink", "dining table", "chair", "couch",
        "tv monitor", "bookshelf", "bed", "wardrobe", "nightstand", "door", "window", "floor lamp",
        "coffee table", "potted plant", "trash can", "shopping cart", "cash register",
        "display case", "first aid kit", "fire extinguisher", "wall", "floor"};
    sp_error err = {0};
    res = malloc(sizeof *res);
    if (!res || sp_lexicon_open(&lx, NULL, &err) ||
        sp_lex_vocab_create(&vocab, lx, classes, (int)(sizeof classes / sizeof classes[0]), NULL, &err)) {
        fprintf(stderr, "fuzz: %s (WordNet: Debian wordnet-base)\n", err.msg);
        abort();
    }
    return 0;
}

static void check_phrase(const sp_lex_phrase *ph, int n_classes, const char *which)
{
    FZ_ASSERT(ph->n_matches >= 0 && ph->n_matches <= n_classes, "%s: %d matches", which, ph->n_matches);
    for (int i = 0; i < ph->n_matches; i++) {
        const sp_lex_class_match *m = &ph->matches[i];
        FZ_ASSERT(m->class_index >= 0 && m->class_index < n_classes, "%s: class %d", which, m->class_index);
        FZ_ASSERT(m->score >= 0.f && m->score <= 1.f, "%s: score %g", which, m->score);
        FZ_ASSERT(i == 0 || m->score <= ph->matches[i - 1].score, "%s: matches out of order", which);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > 4096) size = 4096; /* a query line, not a file */
    char *text = malloc(size + 1);
    FZ_ASSERT(text, "out of memory");
    memcpy(text, data, size);
    text[size] = 0;
    sp_error err = {0};
    int rc = sp_lex_match(vocab, text, res, &err);
    if (rc) {
        fz_check_error(rc, &err, "sp_lex_match");
        free(text);
        return 0;
    }
    const int n = sp_lex_vocab_size(vocab);
    check_phrase(&res->target, n, "target");
    if (res->relation[0]) check_phrase(&res->anchor, n, "anchor");
    FZ_ASSERT(res->confidence >= 0.f && res->confidence <= 1.f, "confidence %g", res->confidence);
    FZ_ASSERT(!res->found || res->confidence >= SP_LEX_THRESHOLD, "found at confidence %g", res->confidence);
    FZ_ASSERT(res->n_ignored >= 0 && res->n_ignored <= SP_LEX_MAX_IGNORED, "%d ignored", res->n_ignored);
    char *json = sp_lex_result_json(res, vocab, 0.f);
    FZ_ASSERT(json, "no JSON for a result");
    free(json);
    char explain[4096];
    sp_lex_explain(res, vocab, explain, sizeof explain);
    FZ_ASSERT(memchr(explain, 0, sizeof explain), "explanation not terminated");
    free(text);
    return 0;
}
