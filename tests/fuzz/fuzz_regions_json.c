/* The lexical encoder's region table (data/semantic/regions.json or --regions: region name ->
 * object phrases; lex_regions_load): never a crash, a clear error, and regions with names and
 * at most 24 non-empty members. */
#include "fuzz_util.h"
#include "semantic/lexical.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char p[1024];
    fz_write("regions.json", data, size, p);
    sp_lex_vocab v;
    memset(&v, 0, sizeof v);
    sp_error err = {0};
    int rc = lex_regions_load(&v, p, &err);
    if (rc) fz_check_error(rc, &err, "lex_regions_load");
    for (int i = 0; i < v.n_regions; i++) {
        const lex_region *r = &v.regions[i];
        FZ_ASSERT(r->n_members >= 0 && r->n_members <= 24, "region %d: %d members", i, r->n_members);
        for (int m = 0; m < r->n_members; m++) FZ_ASSERT(r->members[m][0], "region %d: empty member %d", i, m);
    }
    free(v.regions);
    return 0;
}
