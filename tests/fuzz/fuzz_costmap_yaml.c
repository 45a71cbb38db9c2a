/* Nav2 map_server maps (sp_ros_grid_load_yaml: map.yaml and its PGM): the first byte picks which
 * file the rest is (even: map.yaml beside a fixed 4x3 map.pgm; odd: map.pgm beside a fixed
 * map.yaml naming it). Never a crash, a clear error, and a grid that loads has cells in the
 * occupancy range and a positive resolution. */
#include "fuzz_util.h"
#include "semsplat/ros.h"

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
    sp_ros_grid g;
    sp_error err = {0};
    memset(&g, 0, sizeof g);
    int rc = sp_ros_grid_load_yaml(yp, &g, &err);
    if (rc) {
        fz_check_error(rc, &err, "sp_ros_grid_load_yaml");
    } else {
        FZ_ASSERT(g.width > 0 && g.height > 0 && g.resolution_m > 0 && isfinite(g.resolution_m), "grid %dx%d at %g",
                  g.width, g.height, g.resolution_m);
        FZ_ASSERT(isfinite(g.origin_x) && isfinite(g.origin_y) && isfinite(g.origin_yaw), "origin not finite");
        for (size_t i = 0; i < (size_t)g.width * g.height; i++)
            FZ_ASSERT(g.cells[i] >= -1 && g.cells[i] <= 100, "cell %zu = %d", i, g.cells[i]);
    }
    sp_ros_grid_free(&g);
    return 0;
}
