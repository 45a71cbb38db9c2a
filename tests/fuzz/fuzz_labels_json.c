/* labels.json of a capture (label id -> class, read by the `labels` feature source): never a
 * crash, a clear error, and a table whose every id maps to one of its classes. */
#include "clip/clip_internal.h"
#include "fuzz_util.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char p[1024];
    fz_write("labels.json", data, size, p);
    clip_label_table t;
    sp_error err = {0};
    int rc = clip_label_table_read(p, &t, &err);
    if (rc) {
        fz_check_error(rc, &err, "clip_label_table_read");
        FZ_ASSERT(!t.cls && !t.n, "a failed read left a table behind");
        return 0;
    }
    FZ_ASSERT(t.n >= 1 && t.n <= 65536 && t.n_classes >= 1 && t.n_classes <= t.n, "%d ids, %d classes", t.n,
              t.n_classes);
    for (int i = 0; i < t.n; i++)
        FZ_ASSERT(t.class_of[i] >= 0 && t.class_of[i] < t.n_classes && t.cls[i][0], "id %d -> class %d", i,
                  t.class_of[i]);
    clip_label_table_free(&t);
    return 0;
}
