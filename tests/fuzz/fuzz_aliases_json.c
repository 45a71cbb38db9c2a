/* The lexical encoder's alias table (data/semantic/aliases.json, or an aliases.json beside a
 * --regions table; lex_aliases_load): never a crash, a clear error, and aliases of 1 to 4
 * non-empty words with 1 to 3 non-empty targets. */
#include "fuzz_util.h"
#include "semantic/lexical.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char p[1024];
    fz_write("aliases.json", data, size, p);
    sp_lex_vocab v;
    memset(&v, 0, sizeof v);
    sp_error err = {0};
    int rc = lex_aliases_load(&v, p, &err);
    if (rc) fz_check_error(rc, &err, "lex_aliases_load");
    for (int i = 0; i < v.n_aliases; i++) {
        const lex_alias *a = &v.aliases[i];
        FZ_ASSERT(a->n_words >= 1 && a->n_words <= 4, "alias %d: %d words", i, a->n_words);
        FZ_ASSERT(a->n_targets >= 1 && a->n_targets <= 3, "alias %d: %d targets", i, a->n_targets);
        for (int w = 0; w < a->n_words; w++) FZ_ASSERT(a->words[w][0], "alias %d: empty word %d", i, w);
        for (int t = 0; t < a->n_targets; t++) FZ_ASSERT(a->targets[t][0], "alias %d: empty target %d", i, t);
    }
    free(v.aliases);
    return 0;
}
