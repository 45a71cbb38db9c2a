/* Regions of a home on the map: which room a point is in, in words. Each region's objects (found
 * the way sp_nav_resolve finds the region's name: the engine's own instances of the word, or the
 * objects a household keeps there) seed the free cells inside their rectangle hull and beside
 * them; a breadth-first walk over free cells gives every other cell the region nearest on foot,
 * so a wall between two rooms separates them where straight-line distance would not. An open
 * plan (kitchen and dining area without a wall) is split where the hulls' walks meet, not where
 * the builder drew the line: a rule of thumb, not a room segmentation. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "nav_scene.h"

#define REGION_NONE 255
#define REGION_MAX_WALK_M 5.0f /* past this on foot from any region's objects: no region */
#define OFF_FLOOR_SEARCH_M 1.0f

/* Seeds region r: the free cells inside the rectangle hull of its objects (a room's furniture
 * stands along its walls, so the hull is most of the room) and those beside each object. A cell
 * two hulls claim goes to the region with the nearer object (tie[] holds that distance). */
static void seed_region(const sp_costmap *cm, const sp_nav_target *t, int r, uint8_t *label,
                        float *tie, long *queue, long *tail)
{
    sp_nav_box hull = t->inst[0].box;
    for (int k = 1; k < t->n; k++)
        for (int d = 0; d < 2; d++)
            hull.min[d] = fminf(hull.min[d], t->inst[k].box.min[d]), hull.max[d] = fmaxf(hull.max[d], t->inst[k].box.max[d]);
    int x0, y0, x1, y1;
    nav_nearest_free(cm, &hull, &x0, &y0, &x1, &y1); /* the window: the hull and 1 m around */
    for (int y = y0; y <= y1; y++)
        for (int x = x0; x <= x1; x++) {
            long i = nav_idx(cm, x, y);
            if (cm->occ[i] != SP_CELL_FREE) continue;
            float c[2], near = INFINITY;
            sp_costmap_cell_center(cm, x, y, c);
            int beside = 0;
            for (int k = 0; k < t->n; k++) {
                float d = nav_box_dist(&t->inst[k].box, c);
                near = fminf(near, d);
                beside |= d <= 1.5f * cm->res + 0.5f * cm->opts.robot_radius_m;
            }
            if ((nav_box_dist(&hull, c) > 0 && !beside) || near >= tie[i]) continue;
            if (!isfinite(tie[i])) queue[(*tail)++] = i;
            label[i] = (uint8_t)r, tie[i] = near;
        }
}

static int build_regions(sp_nav *nav, sp_error *err)
{
    const sp_costmap *cm = &nav->cm;
    long n = (long)cm->nx * cm->ny, head = 0, tail = 0;
    nav->region_label = malloc((size_t)n);
    float *dist = malloc(sizeof(float) * n);
    long *queue = malloc(sizeof(long) * n);
    sp_nav_target *t = malloc(sizeof *t);
    int rc = 0;
    if (!nav->region_label || !dist || !queue || !t) {
        rc = sp_error_set(err, SP_E_NOMEM, "nav: out of memory for the regions");
        goto done;
    }
    memset(nav->region_label, REGION_NONE, (size_t)n);
    for (long i = 0; i < n; i++) dist[i] = INFINITY; /* first the seeds' tie distances */
    for (int r = 0; r < nav_n_regions() && r < REGION_NONE && nav->engine; r++) {
        if ((rc = sp_nav_resolve(nav, nav_region_name(r), t, err))) goto done;
        if (t->found && t->n > 0) seed_region(cm, t, r, nav->region_label, dist, queue, &tail);
    }
    for (long q = 0; q < tail; q++) dist[queue[q]] = 0;
    while (head < tail) { /* breadth first: every step one cell */
        long c = queue[head++];
        int cx = (int)(c % cm->nx), cy = (int)(c / cm->nx);
        if (dist[c] + cm->res > REGION_MAX_WALK_M) continue;
        for (int k = 0; k < 4; k++) {
            int x = cx + (k == 0) - (k == 1), y = cy + (k == 2) - (k == 3);
            if (!nav_inside(cm, x, y)) continue;
            long j = nav_idx(cm, x, y);
            if (cm->occ[j] != SP_CELL_FREE || isfinite(dist[j])) continue;
            dist[j] = dist[c] + cm->res;
            nav->region_label[j] = nav->region_label[c];
            queue[tail++] = j;
        }
    }
    nav->regions_built = 1;
done:
    free(dist), free(queue), free(t);
    if (rc) free(nav->region_label), nav->region_label = NULL;
    return rc;
}

/* The label of the cell at (x, y), or of the nearest labelled free cell within 1 m. */
static int label_at(const sp_nav *nav, float x, float y)
{
    const sp_costmap *cm = &nav->cm;
    int cx, cy;
    sp_costmap_cell(cm, x, y, &cx, &cy);
    if (nav_inside(cm, cx, cy) && nav->region_label[nav_idx(cm, cx, cy)] != REGION_NONE)
        return nav->region_label[nav_idx(cm, cx, cy)];
    int r = (int)ceilf(OFF_FLOOR_SEARCH_M / cm->res), best = REGION_NONE;
    float bd = INFINITY;
    for (int yy = cy - r; yy <= cy + r; yy++)
        for (int xx = cx - r; xx <= cx + r; xx++) {
            if (!nav_inside(cm, xx, yy) || nav->region_label[nav_idx(cm, xx, yy)] == REGION_NONE) continue;
            float d = hypotf((float)(xx - cx), (float)(yy - cy));
            if (d < bd) bd = d, best = nav->region_label[nav_idx(cm, xx, yy)];
        }
    return bd * cm->res <= OFF_FLOOR_SEARCH_M ? best : REGION_NONE;
}

int sp_nav_region_of(sp_nav *nav, float x, float y, char *out, size_t cap, sp_error *err)
{
    if (cap) out[0] = 0;
    if (!isfinite(x) || !isfinite(y))
        return sp_error_set(err, SP_E_ARG, "nav: region of a non-finite point (%g, %g)", x, y);
    if (!nav->regions_built) {
        int rc = build_regions(nav, err);
        if (rc) return rc;
    }
    int r = label_at(nav, x, y);
    if (r != REGION_NONE && cap) snprintf(out, cap, "%s", nav_region_name(r));
    return SP_OK;
}
