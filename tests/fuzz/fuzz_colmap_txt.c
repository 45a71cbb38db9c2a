/* COLMAP text model files (cameras.txt, images.txt, points3D.txt): see fuzz_colmap.h. */
#include "fuzz_colmap.h"

static int parse_txt(sp_colmap_part part, const void *data, size_t size, const char *name, sp_colmap_model *m,
                     sp_error *err)
{
    return sp_colmap_parse_txt(part, data, size, name, m, err);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const names[3] = {"cameras.txt", "images.txt", "points3D.txt"};
    return fz_colmap_one(data, size, parse_txt, sp_colmap_write_txt, names);
}
