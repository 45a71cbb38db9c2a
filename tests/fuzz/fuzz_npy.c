/* .npy from any bytes (sp_npy_parse): never a crash, a clear error, and what parses survives a
 * write and a re-read bit for bit (shape, dtype and data; Fortran order comes back as C order). */
#include "fuzz_util.h"
#include "semsplat/io.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sp_npy a, b;
    sp_error err = {0};
    int rc = sp_npy_parse(data, size, "fuzz.npy", &a, &err);
    if (rc) {
        fz_check_error(rc, &err, "sp_npy_parse");
        FZ_ASSERT(!a.data && a.ndim == 0, "a failed parse left data behind");
        return 0;
    }
    size_t n = sp_npy_count(&a);
    float *f = NULL;
    rc = sp_npy_to_f32(&a, &f, &err);
    FZ_ASSERT(rc == 0, "sp_npy_to_f32: %s", err.msg);
    sp_free(f);
    if (a.dtype != SP_DTYPE_BF16) { /* .npy has no bfloat16; the writer refuses it */
        char path[1024];
        fz_path("rt.npy", path);
        rc = sp_npy_write(path, a.dtype, a.ndim, a.shape, a.data, &err);
        FZ_ASSERT(rc == 0, "what parsed does not write back: %s", err.msg);
        rc = sp_npy_read(path, &b, &err);
        FZ_ASSERT(rc == 0, "what we wrote does not read back: %s", err.msg);
        FZ_ASSERT(b.dtype == a.dtype && b.ndim == a.ndim && !memcmp(b.shape, a.shape, sizeof a.shape),
                  "dtype/shape changed in a round trip");
        FZ_ASSERT(!memcmp(a.data, b.data, n * sp_dtype_size(a.dtype)), "data changed in a round trip");
        sp_npy_free(&b);
    }
    sp_npy_free(&a);
    return 0;
}
