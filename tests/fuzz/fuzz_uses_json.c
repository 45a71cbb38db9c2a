/* The lexical encoder's activity table (data/semantic/uses.json, or a uses.json beside a
 * --regions table; lex_uses_load): never a crash, a clear error, and activities of 1 to 4
 * non-empty words with 1 to 4 non-empty names. */
#include "fuzz_util.h"
#include "semantic/lexical.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char p[1024];
    fz_write("uses.json", data, size, p);
    sp_lex_vocab v;
    memset(&v, 0, sizeof v);
    sp_error err = {0};
    int rc = lex_uses_load(&v, p, &err);
    if (rc) fz_check_error(rc, &err, "lex_uses_load");
    for (int i = 0; i < v.n_uses; i++) {
        const lex_use *u = &v.uses[i];
        FZ_ASSERT(u->n_words >= 1 && u->n_words <= 4, "use %d: %d words", i, u->n_words);
        FZ_ASSERT(u->n_targets >= 1 && u->n_targets <= 4, "use %d: %d names", i, u->n_targets);
        for (int w = 0; w < u->n_words; w++) FZ_ASSERT(u->words[w][0], "use %d: empty word %d", i, w);
        for (int t = 0; t < u->n_targets; t++) FZ_ASSERT(u->targets[t][0], "use %d: empty name %d", i, t);
    }
    free(v.uses);
    return 0;
}
