/* Shared by the harnesses of our folders' JSON files (features.json, semantic.json, train.json):
 * a scratch folder holding the files a reader needs beside the fuzzed JSON, made once: a PCA of
 * dim 4 over full_dim 8 (pca_*.npy and semantic_pca_*.npy), one map maps/a.npy [2][3][4] f16,
 * and a splat.ply of 3 Gaussians with 4 features. The seeds use those sizes so a mutated file
 * reaches past its own fields into the loading they drive. A CPU device of one thread. */
#ifndef SP_FUZZ_FOLDER_H
#define SP_FUZZ_FOLDER_H

#include "fuzz_util.h"
#include "semsplat/io.h"
#include "semsplat/render.h"

static sp_device *fz_dev;

static inline void fz_folder_init(void)
{
    char p[1024];
    sp_error err = {0};
    float mean[8], basis[32];
    for (int i = 0; i < 8; i++) mean[i] = 0.01f * (float)i;
    for (int i = 0; i < 32; i++) basis[i] = (i % 9 == 0) ? 1.0f : 0.0f; /* rows e_0..e_3 */
    size_t s1[1] = {8}, s2[2] = {4, 8}, s3[3] = {2, 3, 4};
    uint16_t map[24];
    for (int i = 0; i < 24; i++) map[i] = sp_float_to_half(0.1f * (float)(i % 5));
    sp_splat s;
    int rc = sp_npy_write(fz_path("pca_mean.npy", p), SP_DTYPE_F32, 1, s1, mean, &err);
    rc |= sp_npy_write(fz_path("pca_basis.npy", p), SP_DTYPE_F32, 2, s2, basis, &err);
    rc |= sp_npy_write(fz_path("semantic_pca_mean.npy", p), SP_DTYPE_F32, 1, s1, mean, &err);
    rc |= sp_npy_write(fz_path("semantic_pca_basis.npy", p), SP_DTYPE_F32, 2, s2, basis, &err);
    rc |= sp_mkdirs(fz_path("maps", p), &err);
    rc |= sp_npy_write(fz_path("maps/a.npy", p), SP_DTYPE_F16, 3, s3, map, &err);
    rc |= sp_splat_alloc(&s, 3, 0, 4, &err);
    if (!rc) {
        for (size_t i = 0; i < 3 * 3; i++) s.means[i] = 0.1f * (float)i;
        for (size_t i = 0; i < 3 * 4; i++) s.features[i] = 0.25f;
        rc = sp_ply_write_splat(fz_path("splat.ply", p), &s, &err);
        sp_splat_free(&s);
    }
    if (!rc) rc = sp_device_create(&fz_dev, SP_DEVICE_CPU, 1, &err);
    if (rc) {
        fprintf(stderr, "fuzz: cannot set up the scratch folder: %s\n", err.msg);
        abort();
    }
}

/* The three folder harnesses' initializer. */
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    fz_folder_init();
    return 0;
}

#endif
