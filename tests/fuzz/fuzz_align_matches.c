/* The matches file of `semsplat align --matches` (sp_align_read_matches, point matches
 * 'x y z X Y Z'; image matches need a COLMAP model, so they are refused here): never a crash, a
 * clear error, and matches that read are finite. */
#include <math.h>

#include "fuzz_util.h"
#include "semsplat/semantic.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char p[1024];
    fz_write("matches.txt", data, size, p);
    sp_align_matches m;
    sp_error err = {0};
    int rc = sp_align_read_matches(p, NULL, &m, &err);
    if (rc) {
        fz_check_error(rc, &err, "sp_align_read_matches");
        FZ_ASSERT(m.n == 0, "a failed read left %zu matches", m.n);
        return 0;
    }
    for (size_t i = 0; i < 3 * m.n; i++) FZ_ASSERT(isfinite(m.src[i]) && isfinite(m.dst[i]), "coordinate %zu", i);
    sp_align_matches_free(&m);
    return 0;
}
