/* semantic.json of a model folder (sp_query_engine_open on a CPU device): never a crash, a clear
 * error. The splat, PCA and folder beside it are fuzz_folder.h's. */
#include "fuzz_folder.h"
#include "semsplat/semantic.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char p[1024];
    fz_write("semantic.json", data, size, p);
    sp_query_engine *e = NULL;
    sp_error err = {0};
    int rc = sp_query_engine_open(&e, fz_dir(), NULL, fz_dev, NULL, &err);
    if (rc) {
        fz_check_error(rc, &err, "sp_query_engine_open");
        FZ_ASSERT(!e, "a failed open returned an engine");
        return 0;
    }
    FZ_ASSERT(sp_query_engine_full_dim(e) == 8, "full_dim %d", sp_query_engine_full_dim(e));
    sp_query_engine_free(e);
    return 0;
}
