/* The CLIP tokenizer's input (any bytes as text, up to the first NUL): tokenizing never fails or
 * crashes, ids are in the vocabulary, the 77-token context is BOS ... EOS. */
#include "fuzz_util.h"
#include "semsplat/clip.h"

static sp_clip_tokenizer *tok;

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    char dir[1024];
    sp_error err = {0};
    if (sp_clip_tokenizer_load(&tok, fz_source("data/clip", dir), &err)) {
        fprintf(stderr, "fuzz: %s\n", err.msg);
        abort();
    }
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    FZ_ASSERT(text, "out of memory");
    memcpy(text, data, size);
    text[size] = 0;
    int32_t ids[128], ctx[SP_CLIP_CONTEXT];
    int n = -1, len = -1;
    sp_error err = {0};
    int rc = sp_clip_tokenize(tok, text, ids, 128, &n, &err);
    FZ_ASSERT(rc == 0, "tokenize failed: %s", err.msg);
    FZ_ASSERT(n >= 0, "%d ids", n);
    for (int i = 0; i < n && i < 128; i++) FZ_ASSERT(ids[i] >= 0 && ids[i] < 49408, "id %d = %d", i, ids[i]);
    rc = sp_clip_tokenize_context(tok, text, ctx, &len, &err);
    FZ_ASSERT(rc == 0, "tokenize_context failed: %s", err.msg);
    FZ_ASSERT(len >= 2 && len <= SP_CLIP_CONTEXT && ctx[0] == SP_CLIP_BOS && ctx[len - 1] == SP_CLIP_EOS,
              "context of length %d", len);
    free(text);
    return 0;
}
