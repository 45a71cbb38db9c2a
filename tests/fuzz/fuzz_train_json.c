/* train.json of a model folder, as lift reads it to find the capture (sp_semantic_lift_model
 * without --colmap): never a crash, a clear error. The folder holds no features, so every run
 * stops after train.json and splat.ply: nothing is written. */
#include "fuzz_folder.h"
#include "semsplat/semantic.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char p[1024], nofeat[1024];
    fz_write("train.json", data, size, p);
    fz_path("no-features-here", nofeat);
    sp_error err = {0};
    int rc = sp_semantic_lift_model(fz_dir(), nofeat, NULL, fz_dev, NULL, &err);
    FZ_ASSERT(rc != 0, "lift succeeded without features");
    fz_check_error(rc, &err, "sp_semantic_lift_model");
    return 0;
}
