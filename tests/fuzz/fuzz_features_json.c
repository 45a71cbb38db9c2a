/* features.json of a feature folder (sp_features_open, then each map and the PCA round trip):
 * never a crash, a clear error. The folder beside it is fuzz_folder.h's. */
#include "fuzz_folder.h"
#include "semsplat/clip.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char p[1024];
    fz_write("features.json", data, size, p);
    sp_features f;
    sp_error err = {0};
    int rc = sp_features_open(fz_dir(), &f, &err);
    if (rc) {
        fz_check_error(rc, &err, "sp_features_open");
        FZ_ASSERT(!f.images && !f.pca_mean, "a failed open left arrays behind");
        return 0;
    }
    FZ_ASSERT(f.dim >= 1 && f.full_dim >= f.dim && f.pca_mean && f.pca_basis, "opened with dim %d of %d", f.dim,
              f.full_dim);
    for (size_t i = 0; i < f.n_images && i < 4; i++) {
        rc = sp_features_load_map(&f, i, &err);
        if (rc) fz_check_error(rc, &err, "sp_features_load_map");
        else FZ_ASSERT(f.images[i].map, "map %zu loaded without data", i);
    }
    long k = sp_features_find(&f, "a.png");
    FZ_ASSERT(k < (long)f.n_images, "find returned %ld of %zu", k, f.n_images);
    float *full = malloc(sizeof(float) * (size_t)f.full_dim), *feat = calloc((size_t)f.dim, sizeof(float));
    FZ_ASSERT(full && feat, "out of memory");
    sp_features_decode(&f, feat, full);
    sp_features_encode(&f, full, feat);
    free(full);
    free(feat);
    sp_features_free(&f);
    return 0;
}
