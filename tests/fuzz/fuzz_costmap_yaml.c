/* Nav2 map_server maps (sp_costmap_read_map: map.yaml and its PGM, then inflation): the first
 * byte picks which file the rest is (even: map.yaml beside a fixed 4x3 map.pgm; odd: map.pgm
 * beside a fixed map.yaml naming it). Never a crash, a clear error, and a map that loads has
 * cells of the three kinds, costs in 0..255, a positive resolution and a finite origin. */
#include "fuzz_util.h"
#include "semsplat/nav.h"

static const char yaml[] = "image: map.pgm\nresolution: 0.05\norigin: [-1.0, -2.0, 0.0]\nnegate: 0\n"
                           "occupied_thresh: 0.65\nfree_thresh: 0.196\nmode: trinary\n";
static const char pgm[] = "P5\n# fixed\n4 3\n255\n\x00\x10\x80\xff\xfe\xcd\x64\x00\xff\x00\xff\x00";

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1) return 0;
    char yp[1024], pp[1024];
    int fuzz_yaml = data[0] % 2 == 0;
    fz_write("map.yaml", fuzz_yaml ? (const void *)(data + 1) : yaml, fuzz_yaml ? size - 1 : sizeof yaml - 1, yp);
    fz_write("map.pgm", fuzz_yaml ? (const void *)pgm : data + 1, fuzz_yaml ? sizeof pgm - 1 : size - 1, pp);
    sp_costmap cm;
    sp_error err = {0};
    memset(&cm, 0, sizeof cm);
    int rc = sp_costmap_read_map(&cm, yp, NULL, &err);
    if (rc) {
        fz_check_error(rc, &err, "sp_costmap_read_map");
    } else {
        FZ_ASSERT(cm.nx > 0 && cm.ny > 0 && cm.res > 0 && isfinite(cm.res), "map %dx%d at %g", cm.nx, cm.ny, cm.res);
        FZ_ASSERT(isfinite(cm.origin[0]) && isfinite(cm.origin[1]), "origin not finite");
        for (size_t i = 0; i < (size_t)cm.nx * cm.ny; i++)
            FZ_ASSERT(cm.occ[i] == SP_CELL_FREE || cm.occ[i] == SP_CELL_OCCUPIED || cm.occ[i] == SP_CELL_UNKNOWN,
                      "cell %zu = %d", i, cm.occ[i]);
    }
    sp_costmap_free(&cm);
    return 0;
}
