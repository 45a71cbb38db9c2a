/* A capture's ground_truth.json (sp_ground_truth_read, what eval scores against): never a crash,
 * a clear error, and objects that read have names, classes and finite boxes with min <= max. */
#include "fuzz_util.h"
#include "semsplat/eval.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char p[1024];
    fz_write("ground_truth.json", data, size, p);
    sp_ground_truth gt;
    sp_error err = {0};
    int rc = sp_ground_truth_read(p, &gt, &err);
    if (rc) {
        fz_check_error(rc, &err, "sp_ground_truth_read");
        sp_ground_truth_free(&gt);
        return 0;
    }
    for (size_t i = 0; i < gt.n; i++) {
        const sp_gt_object *o = &gt.objects[i];
        FZ_ASSERT(memchr(o->name, 0, sizeof o->name) && memchr(o->cls, 0, sizeof o->cls), "object %zu unterminated", i);
        for (int k = 0; k < 3; k++)
            FZ_ASSERT(isfinite(o->center[k]) && isfinite(o->aabb_min[k]) && isfinite(o->aabb_max[k]) &&
                          o->aabb_min[k] <= o->aabb_max[k],
                      "object %zu axis %d: box %g..%g centre %g", i, k, o->aabb_min[k], o->aabb_max[k], o->center[k]);
    }
    sp_ground_truth_free(&gt);
    return 0;
}
