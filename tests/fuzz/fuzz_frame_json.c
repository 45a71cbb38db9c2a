/* frame.json of a model or capture folder (sp_frame_read): never a crash, a clear error, and a
 * frame that reads passes sp_frame_check (finite similarity, known source) and round-trips
 * through sp_frame_write to the same frame. */
#include "fuzz_util.h"
#include "semsplat/io.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char p[1024], q[1024];
    fz_write("frame.json", data, size, p);
    sp_frame f, g;
    sp_error err = {0};
    int rc = sp_frame_read(p, &f, &err);
    if (rc) {
        fz_check_error(rc, &err, "sp_frame_read");
        return 0;
    }
    FZ_ASSERT(sp_frame_check(&f, "fuzz", &err) == 0, "a frame that read fails its check: %s", err.msg);
    for (int i = 0; i < 16; i++) FZ_ASSERT(isfinite(f.world_from_model[i]), "element %d not finite", i);
    fz_path("again.json", q);
    FZ_ASSERT(sp_frame_write(q, &f, &err) == 0, "a frame that read does not write: %s", err.msg);
    FZ_ASSERT(sp_frame_read(q, &g, &err) == 0, "a written frame does not read back: %s", err.msg);
    FZ_ASSERT(!memcmp(f.world_from_model, g.world_from_model, sizeof f.world_from_model) &&
                  !strcmp(f.source, g.source) && !strcmp(f.up, g.up) && !strcmp(f.units, g.units),
              "frame changed in a round trip");
    return 0;
}
