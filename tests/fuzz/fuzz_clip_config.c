/* A CLIP checkpoint's config.json and preprocessor_config.json (sp_clip_load): never a crash, a
 * clear error. The weights are the test fixture's tiny CLIP with the token embedding cut to 64
 * rows (so a load takes milliseconds); the seeds are its config with vocab_size 64 and the
 * preprocessor fields, and the fuzzed bytes are given as both files (each reads its own keys). */
#include "fuzz_util.h"
#include "semsplat/clip.h"
#include "semsplat/io.h"
#include "semsplat/render.h"

static sp_device *dev;
static char model[1024];

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    char src[1024];
    sp_safetensors st;
    sp_error err = {0};
    int rc = sp_safetensors_open(fz_source("tests/fixtures/clip/tiny/model.safetensors", src), &st, &err);
    if (!rc) {
        sp_tensor_info *t = malloc(st.n * sizeof *t);
        memcpy(t, st.tensors, st.n * sizeof *t);
        for (size_t i = 0; i < st.n; i++)
            if (!strcmp(t[i].name, "text_model.embeddings.token_embedding.weight")) {
                t[i].nbytes = t[i].nbytes / t[i].shape[0] * 64;
                t[i].shape[0] = 64;
            }
        rc = sp_safetensors_write(fz_path("model.safetensors", model), t, st.n, &err);
        free(t);
        sp_safetensors_close(&st);
    }
    if (!rc) rc = sp_device_create(&dev, SP_DEVICE_CPU, 1, &err);
    if (rc) {
        fprintf(stderr, "fuzz: %s\n", err.msg);
        abort();
    }
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char p[1024];
    fz_write("config.json", data, size, p);
    fz_write("preprocessor_config.json", data, size, p);
    sp_clip *c = NULL;
    sp_error err = {0};
    int rc = sp_clip_load(&c, model, NULL, dev, &err);
    if (rc) {
        fz_check_error(rc, &err, "sp_clip_load");
        FZ_ASSERT(!c, "a failed load returned a model");
        return 0;
    }
    const sp_clip_config *cfg = sp_clip_get_config(c);
    FZ_ASSERT(cfg->vocab_size == 64 && cfg->image_size % cfg->patch_size == 0, "loaded config is inconsistent");
    for (int i = 0; i < 3; i++) FZ_ASSERT(cfg->image_std[i] > 0 && isfinite(cfg->image_mean[i]), "bad image_std");
    sp_clip_free(c);
    return 0;
}
