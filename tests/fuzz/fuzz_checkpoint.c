/* Training checkpoints (SPCKPT01: header, then parameters and both Adam moments; train --resume):
 * never a crash, a clear error, and what reads writes back byte for byte. The custom mutator
 * keeps the Gaussian count consistent with the file size most of the time (the reader wants it
 * exact), so mutated values reach the finiteness checks. */
#include "fuzz_util.h"
#include "train/train_internal.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[1024], back[1024];
    fz_write("checkpoint.bin", data, size, path);
    tr_checkpoint ck;
    sp_error err = {0};
    int rc = tr_checkpoint_read(path, &ck, &err);
    if (rc) {
        fz_check_error(rc, &err, "tr_checkpoint_read");
        FZ_ASSERT(!ck.params.n && !ck.params.means, "a failed read left a splat behind");
        return 0;
    }
    fz_path("rt.bin", back);
    rc = tr_checkpoint_write(back, ck.step, ck.rng, &ck.params, &ck.m, &ck.v, &err);
    FZ_ASSERT(rc == 0, "what read does not write back: %s", err.msg);
    size_t n;
    unsigned char *again = fz_slurp(back, &n);
    FZ_ASSERT(again && n == size, "rewritten checkpoint is %zu bytes, read %zu", n, size);
    /* the header's padding word is not kept */
    FZ_ASSERT(!memcmp(again, data, 20) && !memcmp(again + 24, data + 24, size - 24), "round trip changed the bytes");
    free(again);
    tr_checkpoint_free(&ck);
    return 0;
}

size_t LLVMFuzzerCustomMutator(uint8_t *data, size_t size, size_t max_size, unsigned int seed)
{
    size = LLVMFuzzerMutate(data, size, max_size);
    if (size < 40 || seed % 4 == 0) return size;
    int32_t sh, F;
    memcpy(&sh, data + 12, 4);
    memcpy(&F, data + 16, 4);
    if (sh < 0 || sh > 3 || F < 0 || F > 64) return size;
    size_t per = 3 * 4 * (size_t)(11 + 3 * (sh + 1) * (sh + 1) + F); /* 3 + 4 + 3 + 1 + 3K + F floats, x3 */
    uint64_t n = (size - 40) / per;
    fz_put_u64(data + 32, n);
    return 40 + (size_t)n * per;
}
