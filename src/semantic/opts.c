/* Ranges of the query options, checked at every query (the engine's check_opts; options come
 * per call), so a bad value is an error naming it. */
#include <stddef.h>

#include "sem_internal.h"

typedef struct {
    const char *name;
    size_t offset;
    double lo, hi;
} range;

#define OFF(f) offsetof(sp_query_opts, f)

static const range floats[] = {
    {"min_confidence", OFF(min_confidence), -1, 1},   {"keep_fraction", OFF(keep_fraction), 0, 1},
    {"min_relevancy", OFF(min_relevancy), 0, 1},      {"min_opacity", OFF(min_opacity), 0, 1},
    {"temperature", OFF(temperature), 1e-6, 1e6},     {"voxel_m", OFF(voxel_m), 1e-6, 1e6},
    {"min_instance_fraction", OFF(min_instance_fraction), 0, 1},
};

int sem_check_opts(const sp_query_opts *o, sp_error *err)
{
    for (size_t i = 0; i < sizeof floats / sizeof floats[0]; i++) {
        double v = *(const float *)((const char *)o + floats[i].offset);
        if (!(v >= floats[i].lo && v <= floats[i].hi))
            return sp_error_set(err, SP_E_ARG, "query: %s %g is outside %g..%g", floats[i].name, v, floats[i].lo,
                                floats[i].hi);
    }
    if (o->n_views < 1 || o->n_views > 256)
        return sp_error_set(err, SP_E_ARG, "query: views %d outside 1..256", o->n_views);
    if (o->render_downscale < 1 || o->render_downscale > 64)
        return sp_error_set(err, SP_E_ARG, "query: render_downscale %d outside 1..64", o->render_downscale);
    if (o->heatmap_view < -1) return sp_error_set(err, SP_E_ARG, "query: heatmap view %d (-1: the best)", o->heatmap_view);
    return SP_OK;
}
