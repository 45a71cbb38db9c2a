/* The planner: 8-connected A* on the inflated costmap (no corner cutting; step cost = length x
 * (w_euc + w_trav (cost/252)^2 + penalty), integrated cell by cell), then string pulling: a
 * corner is dropped when the straight segment has line of sight through traversable cells and
 * costs no more than the grid path it replaces. Waypoints sample the corners at a fixed spacing
 * with the heading along the path; the last faces the goal. */
#include <stdlib.h>
#include <string.h>

#include "nav_internal.h"

sp_planner_opts sp_planner_opts_default(void)
{
    sp_planner_opts o;
    memset(&o, 0, sizeof o);
    o.w_euc = 1.0f;
    o.w_trav = 2.0f;
    o.waypoint_spacing_m = 0.25f;
    o.z = NAN;
    o.max_share = 0.6f;
    o.max_length_ratio = 1.4f;
    o.share_radius_m = 0.4f;
    o.penalty = 1.0f;
    o.penalty_radius_m = 0.5f;
    o.max_rounds = 6;
    return o;
}

sp_nav_goal sp_nav_goal_point(float x, float y)
{
    sp_nav_goal g;
    memset(&g, 0, sizeof g);
    g.kind = SP_GOAL_POINT;
    g.xy[0] = x, g.xy[1] = y;
    g.approach_m = 0.5f;
    return g;
}

sp_nav_goal sp_nav_goal_pose(float x, float y, float yaw)
{
    sp_nav_goal g = sp_nav_goal_point(x, y);
    g.kind = SP_GOAL_POSE;
    g.yaw = yaw;
    return g;
}

sp_nav_goal sp_nav_goal_box(const float min_xy[2], const float max_xy[2], float approach_m)
{
    sp_nav_goal g = sp_nav_goal_point(0.5f * (min_xy[0] + max_xy[0]), 0.5f * (min_xy[1] + max_xy[1]));
    g.kind = SP_GOAL_REGION;
    g.n_boxes = 1;
    for (int k = 0; k < 2; k++) g.boxes[0].min[k] = min_xy[k], g.boxes[0].max[k] = max_xy[k];
    g.approach_m = approach_m;
    return g;
}

void sp_path_free(sp_path *p)
{
    if (!p) return;
    free(p->waypoints);
    free(p->corners);
    memset(p, 0, sizeof *p);
}

int sp_path_copy(sp_path *dst, const sp_path *src, sp_error *err)
{
    *dst = *src;
    dst->waypoints = malloc(sizeof(float) * 4 * (src->n ? src->n : 1));
    dst->corners = malloc(sizeof(float) * 2 * (src->n_corners ? src->n_corners : 1));
    if (!dst->waypoints || !dst->corners) {
        free(dst->waypoints), free(dst->corners);
        memset(dst, 0, sizeof *dst);
        return sp_error_set(err, SP_E_NOMEM, "path: out of memory");
    }
    memcpy(dst->waypoints, src->waypoints, sizeof(float) * 4 * src->n);
    memcpy(dst->corners, src->corners, sizeof(float) * 2 * src->n_corners);
    return SP_OK;
}

/* ---- geometry --------------------------------------------------------------------------------- */

float nav_point_segment_dist(const float p[2], const float a[2], const float b[2])
{
    float ux = b[0] - a[0], uy = b[1] - a[1], l2 = ux * ux + uy * uy;
    float t = l2 > 0 ? ((p[0] - a[0]) * ux + (p[1] - a[1]) * uy) / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    float dx = a[0] + t * ux - p[0], dy = a[1] + t * uy - p[1];
    return sqrtf(dx * dx + dy * dy);
}

void nav_box_nearest(const sp_nav_box *b, const float p[2], float out[2])
{
    for (int k = 0; k < 2; k++) out[k] = p[k] < b->min[k] ? b->min[k] : p[k] > b->max[k] ? b->max[k] : p[k];
}

float nav_box_dist(const sp_nav_box *b, const float p[2])
{
    float q[2];
    nav_box_nearest(b, p, q);
    return hypotf(q[0] - p[0], q[1] - p[1]);
}

static float region_dist(const sp_nav_goal *g, const float p[2], int *which)
{
    float best = INFINITY;
    for (int b = 0; b < g->n_boxes; b++) {
        float d = nav_box_dist(&g->boxes[b], p);
        if (d < best) best = d, *which = b;
    }
    return best;
}

float nav_goal_bound(const sp_nav_goal *g, const float p[2])
{
    int w = 0;
    float d = g->kind == SP_GOAL_REGION ? region_dist(g, p, &w) - g->approach_m
                                        : hypotf(p[0] - g->xy[0], p[1] - g->xy[1]) - g->tolerance_m;
    return d > 0 ? d : 0;
}

long nav_goal_mask(const sp_costmap *cm, const sp_nav_goal *g, uint8_t *mask)
{
    long n = 0;
    memset(mask, 0, (size_t)cm->nx * cm->ny);
    int gx, gy, inside = !sp_costmap_cell(cm, g->xy[0], g->xy[1], &gx, &gy);
    for (int iy = 0; iy < cm->ny; iy++)
        for (int ix = 0; ix < cm->nx; ix++) {
            if (!sp_costmap_traversable(cm, ix, iy)) continue;
            float p[2];
            sp_costmap_cell_center(cm, ix, iy, p);
            int w = 0, hit = g->kind == SP_GOAL_REGION
                                 ? region_dist(g, p, &w) <= g->approach_m
                                 : (inside && ix == gx && iy == gy) ||
                                       hypotf(p[0] - g->xy[0], p[1] - g->xy[1]) <= g->tolerance_m;
            if (hit) mask[nav_idx(cm, ix, iy)] = 1, n++;
        }
    return n;
}

/* ---- A* --------------------------------------------------------------------------------------- */

typedef struct heap_item {
    float f;
    int32_t cell;
} heap_item;

typedef struct heap {
    heap_item *a;
    long n, cap;
} heap;

static int heap_push(heap *h, float f, int32_t cell)
{
    if (h->n == h->cap) {
        long cap = h->cap ? 2 * h->cap : 4096;
        heap_item *a = realloc(h->a, sizeof(heap_item) * cap);
        if (!a) return -1;
        h->a = a, h->cap = cap;
    }
    long i = h->n++;
    while (i > 0) {
        long p = (i - 1) / 2;
        if (h->a[p].f <= f) break;
        h->a[i] = h->a[p];
        i = p;
    }
    h->a[i].f = f, h->a[i].cell = cell;
    return 0;
}

static heap_item heap_pop(heap *h)
{
    heap_item top = h->a[0], last = h->a[--h->n];
    long i = 0;
    for (;;) {
        long c = 2 * i + 1;
        if (c >= h->n) break;
        if (c + 1 < h->n && h->a[c + 1].f < h->a[c].f) c++;
        if (h->a[c].f >= last.f) break;
        h->a[i] = h->a[c];
        i = c;
    }
    if (h->n > 0) h->a[i] = last;
    return top;
}

typedef struct cost_field {
    const sp_costmap *cm;
    const sp_planner_opts *o;
    const float *penalty;
    long start;         /* the start cell may be inscribed */
} cost_field;

/* Cost per metre inside cell i. */
static inline float cell_rate(const cost_field *cf, long i)
{
    return cf->o->w_euc + cf->o->w_trav * nav_cost_term(cf->cm->cost[i]) + (cf->penalty ? cf->penalty[i] : 0.0f);
}

static int astar(const cost_field *cf, long start, const sp_nav_goal *goal, const uint8_t *goal_mask,
                 long max_exp, int32_t **cells_out, int *n_out, int *status, long *expanded)
{
    const sp_costmap *cm = cf->cm;
    long n = (long)cm->nx * cm->ny;
    float *g = malloc(sizeof(float) * n);
    int32_t *parent = malloc(sizeof(int32_t) * n);
    uint8_t *closed = calloc((size_t)n, 1);
    heap h = {0};
    int rc = -1;
    if (!g || !parent || !closed) goto done;
    for (long i = 0; i < n; i++) g[i] = INFINITY;
    g[start] = 0;
    parent[start] = -1;
    float p[2];
    sp_costmap_cell_center(cm, (int)(start % cm->nx), (int)(start / cm->nx), p);
    if (heap_push(&h, cf->o->w_euc * nav_goal_bound(goal, p), (int32_t)start)) goto done;
    static const int dx[8] = {1, -1, 0, 0, 1, 1, -1, -1}, dy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
    long expansions = 0, found = -1;
    *status = SP_NAV_NO_VALID_PATH;
    while (h.n > 0) {
        heap_item it = heap_pop(&h);
        long c = it.cell;
        if (closed[c]) continue;
        closed[c] = 1;
        if (goal_mask[c]) {
            found = c;
            break;
        }
        if (++expansions > max_exp) {
            *status = SP_NAV_TIMEOUT;
            break;
        }
        int cx = (int)(c % cm->nx), cy = (int)(c / cm->nx);
        float rc_c = cell_rate(cf, c);
        for (int k = 0; k < 8; k++) {
            int x = cx + dx[k], y = cy + dy[k];
            if (!sp_costmap_traversable(cm, x, y)) continue;
            if (k >= 4 && (!sp_costmap_traversable(cm, cx + dx[k], cy) || !sp_costmap_traversable(cm, cx, cy + dy[k])))
                continue; /* no corner cutting */
            long j = nav_idx(cm, x, y);
            if (closed[j]) continue;
            float len = (k >= 4 ? 1.41421356f : 1.0f) * cm->res;
            float gj = g[c] + 0.5f * len * (rc_c + cell_rate(cf, j));
            if (gj >= g[j]) continue;
            g[j] = gj;
            parent[j] = (int32_t)c;
            sp_costmap_cell_center(cm, x, y, p);
            if (heap_push(&h, gj + cf->o->w_euc * nav_goal_bound(goal, p), (int32_t)j)) goto done;
        }
    }
    *expanded = expansions;
    if (found >= 0) {
        int m = 0;
        for (long c = found; c >= 0; c = parent[c]) m++;
        int32_t *cells = malloc(sizeof(int32_t) * m);
        if (!cells) goto done;
        int k = m;
        for (long c = found; c >= 0; c = parent[c]) cells[--k] = (int32_t)c;
        *cells_out = cells;
        *n_out = m;
        *status = SP_NAV_OK;
    }
    rc = 0;
done:
    free(g), free(parent), free(closed), free(h.a);
    return rc;
}

/* ---- line of sight and string pulling ---------------------------------------------------------- */

typedef struct seg_ctx {
    const cost_field *cf;
    float len;
    float cost;
} seg_ctx;

static int seg_cell(void *vctx, long cell, float t0, float t1)
{
    seg_ctx *s = vctx;
    const sp_costmap *cm = s->cf->cm;
    if (cell != s->cf->start && !(cm->occ[cell] == SP_CELL_FREE && cm->cost[cell] < SP_COST_INSCRIBED))
        return 1;
    s->cost += (t1 - t0) * s->len * cell_rate(s->cf, cell);
    return 0;
}

/* Cost of the straight segment a -> b, INFINITY without line of sight. */
static float segment_cost(const cost_field *cf, const float a[2], const float b[2])
{
    seg_ctx s = {cf, hypotf(b[0] - a[0], b[1] - a[1]), 0};
    return nav_traverse(cf->cm, a, b, seg_cell, &s) ? INFINITY : s.cost;
}

/* pts [m][2]: exact start, cell centres, (exact goal). Keeps a subset as corners. */
static int string_pull(const cost_field *cf, const float *pts, int m, float *corners, int *n_out)
{
    double *prefix = malloc(sizeof(double) * m);
    if (!prefix) return -1;
    prefix[0] = 0;
    for (int i = 1; i < m; i++) {
        float c = segment_cost(cf, pts + 2 * (i - 1), pts + 2 * i);
        prefix[i] = prefix[i - 1] + (isfinite(c) ? c : 1e30);
    }
    int n = 0, i = 0;
    memcpy(corners, pts, sizeof(float) * 2);
    n = 1;
    while (i < m - 1) {
        int j = i + 1;
        while (j + 1 < m) {
            float c = segment_cost(cf, pts + 2 * i, pts + 2 * (j + 1));
            if (!(c <= (prefix[j + 1] - prefix[i]) * (1.0 + 1e-4) + 1e-6)) break;
            j++;
        }
        memcpy(corners + 2 * n, pts + 2 * j, sizeof(float) * 2);
        n++;
        i = j;
    }
    free(prefix);
    /* a second look over the corners: drop one whose neighbours see each other more cheaply */
    for (int pass = 0; pass < 2; pass++)
        for (int k = 1; k + 1 < n;) {
            float via = segment_cost(cf, corners + 2 * (k - 1), corners + 2 * k) +
                        segment_cost(cf, corners + 2 * k, corners + 2 * (k + 1));
            float direct = segment_cost(cf, corners + 2 * (k - 1), corners + 2 * (k + 1));
            if (direct <= via) {
                memmove(corners + 2 * k, corners + 2 * (k + 1), sizeof(float) * 2 * (n - k - 1));
                n--;
            } else {
                k++;
            }
        }
    *n_out = n;
    return 0;
}

/* ---- waypoints -------------------------------------------------------------------------------- */

static float final_yaw(const sp_nav_goal *g, const float *corners, int n)
{
    const float *e = corners + 2 * (n - 1);
    if (g->kind == SP_GOAL_POSE) return g->yaw;
    if (g->kind == SP_GOAL_REGION) {
        int w = 0;
        float q[2], d = region_dist(g, e, &w);
        const sp_nav_box *b = &g->boxes[w];
        if (d < 1e-3f) q[0] = 0.5f * (b->min[0] + b->max[0]), q[1] = 0.5f * (b->min[1] + b->max[1]);
        else nav_box_nearest(b, e, q);
        if (hypotf(q[0] - e[0], q[1] - e[1]) > 1e-4f) return atan2f(q[1] - e[1], q[0] - e[0]);
    }
    if (n >= 2) return atan2f(e[1] - e[-1], e[0] - e[-2]);
    return 0;
}

static int make_waypoints(sp_path *p, const sp_nav_goal *g, float spacing, float z, float start_yaw)
{
    int cap = 2;
    for (int k = 1; k < p->n_corners; k++) {
        float l = hypotf(p->corners[2 * k] - p->corners[2 * k - 2], p->corners[2 * k + 1] - p->corners[2 * k - 1]);
        cap += (int)ceilf(l / spacing) + 1;
    }
    p->waypoints = malloc(sizeof(float) * 4 * cap);
    if (!p->waypoints) return -1;
    int n = 0;
    p->length_m = 0;
    for (int k = 0; k + 1 < p->n_corners; k++) {
        const float *a = p->corners + 2 * k, *b = a + 2;
        float l = hypotf(b[0] - a[0], b[1] - a[1]), yaw = atan2f(b[1] - a[1], b[0] - a[0]);
        int steps = (int)ceilf(l / spacing);
        if (steps < 1) steps = 1;
        for (int s = 0; s < steps; s++) {
            float t = (float)s / steps, *w = p->waypoints + 4 * n++;
            w[0] = a[0] + t * (b[0] - a[0]), w[1] = a[1] + t * (b[1] - a[1]), w[2] = z, w[3] = yaw;
        }
        p->length_m += l;
    }
    float *w = p->waypoints + 4 * n++;
    const float *e = p->corners + 2 * (p->n_corners - 1);
    w[0] = e[0], w[1] = e[1], w[2] = z;
    w[3] = p->n_corners == 1 && g->kind == SP_GOAL_POINT ? start_yaw : final_yaw(g, p->corners, p->n_corners);
    p->n = n;
    return 0;
}

/* ---- the entry points ------------------------------------------------------------------------- */

static int check_goal_args(const sp_nav_goal *g, const float start[3], sp_error *err)
{
    if (!g || !start) return sp_error_set(err, SP_E_ARG, "plan: missing start or goal");
    if (!isfinite(start[0]) || !isfinite(start[1]) || !isfinite(start[2]))
        return sp_error_set(err, SP_E_ARG, "plan: start (%g, %g, %g) is not finite", start[0], start[1], start[2]);
    if (g->kind < SP_GOAL_POINT || g->kind > SP_GOAL_REGION)
        return sp_error_set(err, SP_E_ARG, "plan: goal kind %d", g->kind);
    if (g->kind == SP_GOAL_REGION) {
        if (g->n_boxes < 1 || g->n_boxes > SP_NAV_MAX_BOXES)
            return sp_error_set(err, SP_E_ARG, "plan: a region goal needs 1..%d footprints, not %d",
                                SP_NAV_MAX_BOXES, g->n_boxes);
        if (!(g->approach_m >= 0))
            return sp_error_set(err, SP_E_ARG, "plan: approach distance %g m", g->approach_m);
        for (int b = 0; b < g->n_boxes; b++)
            for (int k = 0; k < 2; k++)
                if (!isfinite(g->boxes[b].min[k]) || !isfinite(g->boxes[b].max[k]) ||
                    g->boxes[b].min[k] > g->boxes[b].max[k])
                    return sp_error_set(err, SP_E_ARG, "plan: footprint %d is not a box", b);
    } else if (!isfinite(g->xy[0]) || !isfinite(g->xy[1]) || !isfinite(g->yaw) || !(g->tolerance_m >= 0)) {
        return sp_error_set(err, SP_E_ARG, "plan: goal (%g, %g, yaw %g, tolerance %g) is not valid",
                            g->xy[0], g->xy[1], g->yaw, g->tolerance_m);
    }
    return SP_OK;
}

int nav_plan_once(const sp_costmap *cm, const float start[3], const sp_nav_goal *goal,
                  const sp_planner_opts *o, const float *penalty, const uint8_t *goal_mask,
                  sp_path *path, sp_error *err)
{
    double t0 = sp_time_now();
    memset(path, 0, sizeof *path);
    int sx, sy;
    if (sp_costmap_cell(cm, start[0], start[1], &sx, &sy)) {
        path->status = SP_NAV_START_OUTSIDE_MAP;
        return sp_error_set(err, SP_E_NOTFOUND, "plan: the start (%.2f, %.2f) is outside the map",
                            start[0], start[1]);
    }
    long s = nav_idx(cm, sx, sy);
    if (cm->occ[s] != SP_CELL_FREE) {
        path->status = SP_NAV_START_OCCUPIED;
        return sp_error_set(err, SP_E_NOTFOUND, "plan: the start (%.2f, %.2f) is %s", start[0], start[1],
                            cm->occ[s] == SP_CELL_UNKNOWN ? "in unknown space" : "occupied");
    }
    cost_field cf = {cm, o, penalty, s};
    int32_t *cells = NULL;
    int m = 0, status = SP_NAV_NO_VALID_PATH;
    long max_exp = o->max_expansions > 0 ? o->max_expansions : (long)cm->nx * cm->ny;
    long expanded = 0;
    if (astar(&cf, s, goal, goal_mask, max_exp, &cells, &m, &status, &expanded))
        return sp_error_set(err, SP_E_NOMEM, "plan: out of memory");
    if (status == SP_NAV_TIMEOUT) {
        path->status = status;
        return sp_error_set(err, SP_E_NOTFOUND, "plan: search budget of %ld cells exhausted from (%.2f, %.2f)",
                            max_exp, start[0], start[1]);
    }
    if (status != SP_NAV_OK) {
        path->status = status;
        return sp_error_set(err, SP_E_NOTFOUND, "plan: no path through free space from (%.2f, %.2f): the "
                            "traversable space around the start holds %.1f m^2 (%ld cells) and does not reach "
                            "the goal", start[0], start[1], expanded * cm->res * cm->res, expanded);
    }
    /* exact start, the cells' centres, and the exact goal point when it lies in the last cell */
    float *pts = malloc(sizeof(float) * 2 * (m + 2)), *corners = malloc(sizeof(float) * 2 * (m + 2));
    if (!pts || !corners) {
        free(cells), free(pts), free(corners);
        return sp_error_set(err, SP_E_NOMEM, "plan: out of memory");
    }
    /* The segments exact start -> its cell's centre and last centre -> exact goal stay inside
     * one cell; string pulling drops the centres where the line of sight allows. */
    int np = 0;
    pts[np * 2] = start[0], pts[np * 2 + 1] = start[1], np++;
    for (int i = 0; i < m; i++, np++)
        sp_costmap_cell_center(cm, cells[i] % cm->nx, cells[i] / cm->nx, pts + 2 * np);
    int gx, gy;
    if (goal->kind != SP_GOAL_REGION && !sp_costmap_cell(cm, goal->xy[0], goal->xy[1], &gx, &gy) &&
        nav_idx(cm, gx, gy) == cells[m - 1]) {
        pts[np * 2] = goal->xy[0], pts[np * 2 + 1] = goal->xy[1], np++;
    }
    free(cells);
    int nc = 0;
    if (string_pull(&cf, pts, np, corners, &nc)) {
        free(pts), free(corners);
        return sp_error_set(err, SP_E_NOMEM, "plan: out of memory");
    }
    free(pts);
    path->corners = corners;
    path->n_corners = nc;
    path->cost = 0;
    for (int k = 1; k < nc; k++) path->cost += segment_cost(&cf, corners + 2 * (k - 1), corners + 2 * k);
    float z = isnan(o->z) ? cm->floor_z : o->z;
    if (make_waypoints(path, goal, o->waypoint_spacing_m, z, start[2])) {
        sp_path_free(path);
        return sp_error_set(err, SP_E_NOMEM, "plan: out of memory");
    }
    path->status = SP_NAV_OK;
    path->ms = 1e3 * (sp_time_now() - t0);
    return SP_OK;
}

float nav_path_cost(const sp_costmap *cm, const sp_planner_opts *o, const sp_path *p)
{
    int sx, sy;
    if (p->n_corners < 1 || sp_costmap_cell(cm, p->corners[0], p->corners[1], &sx, &sy)) return INFINITY;
    cost_field cf = {cm, o, NULL, nav_idx(cm, sx, sy)};
    float c = 0;
    for (int k = 1; k < p->n_corners; k++) c += segment_cost(&cf, p->corners + 2 * (k - 1), p->corners + 2 * k);
    return c;
}

int nav_check_planner_opts(const sp_planner_opts *o, sp_error *err)
{
    if (!(o->w_euc > 0) || !(o->w_trav >= 0) || !(o->waypoint_spacing_m > 0) || !(o->penalty >= 0) ||
        !(o->max_share >= 0 && o->max_share <= 1) || !(o->max_length_ratio >= 1) ||
        !(o->share_radius_m >= 0) || !(o->penalty_radius_m >= 0) || o->max_rounds < 0)
        return sp_error_set(err, SP_E_ARG,
                            "plan: options w_euc %g (> 0), w_trav %g (>= 0), waypoint spacing %g (> 0), "
                            "max_share %g (0..1), max_length_ratio %g (>= 1), penalty %g, radii %g/%g, "
                            "rounds %d", o->w_euc, o->w_trav, o->waypoint_spacing_m, o->max_share,
                            o->max_length_ratio, o->penalty, o->share_radius_m, o->penalty_radius_m,
                            o->max_rounds);
    return SP_OK;
}

int nav_goal_prepare(const sp_costmap *cm, const float start[3], const sp_nav_goal *goal,
                     const sp_planner_opts *o, uint8_t **mask_out, int *status, sp_error *err)
{
    *mask_out = NULL;
    *status = SP_NAV_OK;
    int rc = check_goal_args(goal, start, err);
    if (!rc) rc = nav_check_planner_opts(o, err);
    if (rc) return rc;
    uint8_t *mask = malloc((size_t)cm->nx * cm->ny);
    if (!mask) return sp_error_set(err, SP_E_NOMEM, "plan: out of memory");
    if (nav_goal_mask(cm, goal, mask) == 0) {
        free(mask);
        int gx, gy;
        if (goal->kind == SP_GOAL_REGION) {
            *status = SP_NAV_GOAL_OCCUPIED;
            return sp_error_set(err, SP_E_NOTFOUND, "plan: no free cell within %.2f m of the target's "
                                "footprint (%.2f..%.2f, %.2f..%.2f)", goal->approach_m,
                                goal->boxes[0].min[0], goal->boxes[0].max[0], goal->boxes[0].min[1],
                                goal->boxes[0].max[1]);
        }
        if (sp_costmap_cell(cm, goal->xy[0], goal->xy[1], &gx, &gy)) {
            *status = SP_NAV_GOAL_OUTSIDE_MAP;
            return sp_error_set(err, SP_E_NOTFOUND, "plan: the goal (%.2f, %.2f) is outside the map",
                                goal->xy[0], goal->xy[1]);
        }
        *status = SP_NAV_GOAL_OCCUPIED;
        long i = nav_idx(cm, gx, gy);
        return sp_error_set(err, SP_E_NOTFOUND, "plan: the goal (%.2f, %.2f) is %s", goal->xy[0], goal->xy[1],
                            cm->occ[i] == SP_CELL_UNKNOWN ? "in unknown space (never observed)"
                            : cm->occ[i] == SP_CELL_OCCUPIED ? "occupied"
                                                             : "within the robot radius of an obstacle or unknown space");
    }
    *mask_out = mask;
    return SP_OK;
}

int sp_plan_path(const sp_costmap *cm, const float start[3], const sp_nav_goal *goal,
                 const sp_planner_opts *opts, sp_path *path, sp_error *err)
{
    memset(path, 0, sizeof *path);
    sp_planner_opts o = opts ? *opts : sp_planner_opts_default();
    uint8_t *mask;
    int status, rc = nav_goal_prepare(cm, start, goal, &o, &mask, &status, err);
    if (rc) {
        path->status = status;
        return rc;
    }
    rc = nav_plan_once(cm, start, goal, &o, NULL, mask, path, err);
    free(mask);
    return rc;
}
