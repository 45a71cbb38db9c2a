/* Stand-in for src/nav/cairo/draw.c when Cairo is not installed: maps and contact sheets are
 * skipped (plan.json says why); everything else in nav works. */
#include "nav/nav_scene.h"

static const char *missing = "drawing maps and contact sheets needs Cairo: install libcairo2-dev "
                             "(scripts/install-deps.sh) and rebuild";

int nav_draw_available(const char **why)
{
    if (why) *why = missing;
    return 0;
}

int nav_draw_map(const nav_map_layers *layers, const char *png_path, sp_error *err)
{
    (void)layers;
    return sp_error_set(err, SP_E_UNSUPPORTED, "%s: %s", png_path, missing);
}

int nav_draw_sheet(const char *title, const sp_nav_preview *pv, int n, const char *png_path,
                   sp_error *err)
{
    (void)title, (void)pv, (void)n;
    return sp_error_set(err, SP_E_UNSUPPORTED, "%s: %s", png_path, missing);
}
