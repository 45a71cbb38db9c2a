/* The simulated robot's planner: 8-connected grid A* on an occupancy grid, with the robot's
 * radius as a hard clearance and a soft cost that keeps paths off walls, then line-of-sight
 * shortcuts. It stands behind ros_planner_* (ros_internal.h) until the nav module's costmap
 * and planner replace it. Occupancy: < 0 unknown, >= ROS_LETHAL occupied (map_server's default
 * occupied_thresh 0.65), anything else free; unknown space is never entered. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ros_internal.h"

#define ROS_LETHAL 65
/* Beyond the robot radius, cost falls from 1 to 0 over this distance (a soft inflation). */
#define ROS_SOFT_M 0.5
#define ROS_SOFT_WEIGHT 4.0

struct ros_planner {
    sp_ros_grid grid;   /* own copy of the cells */
    float *dist_m;      /* distance from a cell centre to the nearest blocked cell (INF: none) */
    double radius_m;
    double cos_o, sin_o;
};

static int blocked(int8_t v) { return v < 0 || v >= ROS_LETHAL; }

/* Distance from each cell centre to the nearest blocked cell centre (core's exact EDT). */
static int distance_field(ros_planner *p, sp_error *err)
{
    const sp_ros_grid *g = &p->grid;
    size_t n = (size_t)g->width * g->height;
    uint8_t *seed = malloc(n);
    if (!seed) return sp_error_set(err, SP_E_NOMEM, "planner: %zu cells", n);
    for (size_t i = 0; i < n; i++) seed[i] = blocked(g->cells[i]);
    int rc = sp_edt2(seed, g->width, g->height, (float)g->resolution_m, p->dist_m, NULL, err);
    free(seed);
    return rc;
}

int ros_planner_create(ros_planner **out, const sp_ros_grid *grid, double robot_radius_m,
                       sp_error *err)
{
    if (!grid || grid->width <= 0 || grid->height <= 0 || !grid->cells)
        return sp_error_set(err, SP_E_ARG, "planner: empty grid");
    if (!(grid->resolution_m > 0) || !isfinite(grid->resolution_m) || !isfinite(grid->origin_x) ||
        !isfinite(grid->origin_y) || !isfinite(grid->origin_yaw))
        return sp_error_set(err, SP_E_ARG, "planner: grid resolution %g or origin not valid",
                            grid->resolution_m);
    if (!(robot_radius_m >= 0) || robot_radius_m > 5)
        return sp_error_set(err, SP_E_ARG, "planner: robot radius %g m", robot_radius_m);
    ros_planner *p = calloc(1, sizeof *p);
    size_t n = (size_t)grid->width * (size_t)grid->height;
    if (!p) return sp_error_set(err, SP_E_NOMEM, "planner");
    p->grid = *grid;
    p->grid.cells = malloc(n);
    p->dist_m = malloc(n * sizeof(float));
    if (!p->grid.cells || !p->dist_m) {
        ros_planner_free(p);
        return sp_error_set(err, SP_E_NOMEM, "planner: %zu cells", n);
    }
    memcpy(p->grid.cells, grid->cells, n);
    p->radius_m = robot_radius_m;
    p->cos_o = cos(grid->origin_yaw);
    p->sin_o = sin(grid->origin_yaw);
    int rc = distance_field(p, err);
    if (rc) {
        ros_planner_free(p);
        return rc;
    }
    *out = p;
    return 0;
}

void ros_planner_free(ros_planner *p)
{
    if (!p) return;
    free(p->grid.cells);
    free(p->dist_m);
    free(p);
}

const sp_ros_grid *ros_planner_grid(const ros_planner *p) { return &p->grid; }

/* World -> cell (col, row); returns 0 when outside the grid. */
static int to_cell(const ros_planner *p, double x, double y, int *col, int *row)
{
    const sp_ros_grid *g = &p->grid;
    double dx = x - g->origin_x, dy = y - g->origin_y;
    double u = (p->cos_o * dx + p->sin_o * dy) / g->resolution_m;
    double v = (-p->sin_o * dx + p->cos_o * dy) / g->resolution_m;
    if (!(u >= 0 && v >= 0 && u < g->width && v < g->height)) return 0;
    *col = (int)u;
    *row = (int)v;
    return 1;
}

static void to_world(const ros_planner *p, int col, int row, double *x, double *y)
{
    const sp_ros_grid *g = &p->grid;
    double u = (col + 0.5) * g->resolution_m, v = (row + 0.5) * g->resolution_m;
    *x = g->origin_x + p->cos_o * u - p->sin_o * v;
    *y = g->origin_y + p->sin_o * u + p->cos_o * v;
}

ros_cell_class ros_planner_classify(const ros_planner *p, double x, double y)
{
    int c, r;
    if (!to_cell(p, x, y, &c, &r)) return ROS_CELL_OUTSIDE;
    long i = (long)r * p->grid.width + c;
    int8_t v = p->grid.cells[i];
    if (v < 0) return ROS_CELL_UNKNOWN;
    if (v >= ROS_LETHAL) return ROS_CELL_OCCUPIED;
    return p->dist_m[i] < p->radius_m ? ROS_CELL_NEAR_OBSTACLE : ROS_CELL_FREE;
}

const char *ros_cell_class_name(ros_cell_class c)
{
    switch (c) {
    case ROS_CELL_FREE: return "free";
    case ROS_CELL_OCCUPIED: return "occupied";
    case ROS_CELL_UNKNOWN: return "unknown";
    case ROS_CELL_OUTSIDE: return "outside the map";
    default: return "closer to an obstacle than the robot radius";
    }
}

int ros_planner_is_lethal(const ros_planner *p, double x, double y)
{
    ros_cell_class k = ros_planner_classify(p, x, y);
    return k == ROS_CELL_OCCUPIED || k == ROS_CELL_OUTSIDE || k == ROS_CELL_UNKNOWN;
}

/* ---- A* ---- */

typedef struct { float f; int idx; } heap_item;
typedef struct { heap_item *a; size_t n, cap; } heap;

static int heap_push(heap *h, float f, int idx)
{
    if (h->n == h->cap) {
        size_t cap = h->cap ? h->cap * 2 : 1024;
        heap_item *a = realloc(h->a, cap * sizeof *a);
        if (!a) return -1;
        h->a = a;
        h->cap = cap;
    }
    size_t i = h->n++;
    while (i > 0 && h->a[(i - 1) / 2].f > f) {
        h->a[i] = h->a[(i - 1) / 2];
        i = (i - 1) / 2;
    }
    h->a[i].f = f;
    h->a[i].idx = idx;
    return 0;
}

static heap_item heap_pop(heap *h)
{
    heap_item top = h->a[0], last = h->a[--h->n];
    size_t i = 0;
    for (;;) {
        size_t c = 2 * i + 1;
        if (c >= h->n) break;
        if (c + 1 < h->n && h->a[c + 1].f < h->a[c].f) c++;
        if (h->a[c].f >= last.f) break;
        h->a[i] = h->a[c];
        i = c;
    }
    if (h->n) h->a[i] = last;
    return top;
}

typedef struct {
    const ros_planner *p;
    int start_col, start_row;
    double escape_m; /* near-obstacle cells within this of the start may be crossed */
} walk_rules;

/* Cost factor of entering cell i (>= 1), or 0 when the robot may not enter it. */
static double enter_cost(const walk_rules *w, int col, int row)
{
    const ros_planner *p = w->p;
    long i = (long)row * p->grid.width + col;
    float d = p->dist_m[i];
    if (blocked(p->grid.cells[i])) return 0;
    if (d < p->radius_m) {
        double dc = (col - w->start_col) * p->grid.resolution_m;
        double dr = (row - w->start_row) * p->grid.resolution_m;
        if (dc * dc + dr * dr > w->escape_m * w->escape_m) return 0;
        return 1 + ROS_SOFT_WEIGHT * 2;
    }
    double soft = 1.0 - (d - p->radius_m) / ROS_SOFT_M;
    return 1 + ROS_SOFT_WEIGHT * (soft > 0 ? soft : 0) + p->grid.cells[i] / 100.0;
}

/* Straight segment between cell centres stays in cells the robot fits in. */
static int line_clear(const ros_planner *p, int c0, int r0, int c1, int r1)
{
    int steps = 2 * (abs(c1 - c0) > abs(r1 - r0) ? abs(c1 - c0) : abs(r1 - r0)) + 1;
    for (int s = 0; s <= steps; s++) {
        double t = (double)s / steps;
        int c = (int)floor(c0 + 0.5 + t * (c1 - c0)), r = (int)floor(r0 + 0.5 + t * (r1 - r0));
        long i = (long)r * p->grid.width + c;
        if (blocked(p->grid.cells[i]) || p->dist_m[i] < p->radius_m) return 0;
    }
    return 1;
}

static int goal_check(const ros_planner *p, const char *what, double x, double y, sp_error *err)
{
    ros_cell_class k = ros_planner_classify(p, x, y);
    if (k == ROS_CELL_FREE) return 0;
    return sp_error_set(err, SP_E_ARG, "%s (%.2f, %.2f) is %s", what, x, y, ros_cell_class_name(k));
}

/* Walks parents back from the goal, keeping only the cells line-of-sight shortcuts need. */
static int build_path(const ros_planner *p, const int *parent, int s, int g, double **xy,
                      size_t *n)
{
    int W = p->grid.width;
    size_t len = 1;
    for (int i = g; i != s; i = parent[i]) len++;
    int *cells = malloc(len * sizeof *cells);
    if (!cells) return SP_E_NOMEM;
    size_t k = len;
    for (int i = g;; i = parent[i]) {
        cells[--k] = i;
        if (i == s) break;
    }
    double *out = malloc(2 * len * sizeof *out);
    if (!out) {
        free(cells);
        return SP_E_NOMEM;
    }
    size_t m = 0, a = 0;
    to_world(p, cells[0] % W, cells[0] / W, &out[0], &out[1]);
    m = 1;
    while (a + 1 < len) {
        size_t b = a + 1;
        /* The first cell may sit in the escape zone; shortcuts start once clear of it. */
        for (size_t c = len - 1; c > a + 1; c--)
            if (line_clear(p, cells[a] % W, cells[a] / W, cells[c] % W, cells[c] / W)) {
                b = c;
                break;
            }
        to_world(p, cells[b] % W, cells[b] / W, &out[2 * m], &out[2 * m + 1]);
        m++;
        a = b;
    }
    free(cells);
    *xy = out;
    *n = m;
    return 0;
}

int ros_planner_plan(const ros_planner *p, double sx, double sy, double gx, double gy,
                     double **xy, size_t *n, sp_error *err)
{
    int sc, sr, gc, gr;
    ros_cell_class ks = ros_planner_classify(p, sx, sy);
    if (ks != ROS_CELL_FREE && ks != ROS_CELL_NEAR_OBSTACLE)
        return sp_error_set(err, SP_E_ARG, "start (%.2f, %.2f) is %s", sx, sy,
                            ros_cell_class_name(ks));
    if (goal_check(p, "goal", gx, gy, err)) return SP_E_ARG;
    to_cell(p, sx, sy, &sc, &sr);
    to_cell(p, gx, gy, &gc, &gr);
    int W = p->grid.width, H = p->grid.height;
    size_t N = (size_t)W * H;
    float *gcost = malloc(N * sizeof *gcost);
    int *parent = malloc(N * sizeof *parent);
    unsigned char *closed = calloc(N, 1);
    heap h = {0};
    int rc = SP_E_NOMEM;
    if (!gcost || !parent || !closed) goto done;
    for (size_t i = 0; i < N; i++) gcost[i] = FLT_MAX;
    walk_rules rules = {p, sc, sr, 2 * p->radius_m + p->grid.resolution_m};
    int s = sr * W + sc, g = gr * W + gc;
    double res = p->grid.resolution_m;
    gcost[s] = 0;
    parent[s] = s;
    if (heap_push(&h, 0, s)) goto done;
    rc = SP_E_NOTFOUND;
    while (h.n) {
        heap_item it = heap_pop(&h);
        int i = it.idx;
        if (closed[i]) continue;
        closed[i] = 1;
        if (i == g) {
            rc = build_path(p, parent, s, g, xy, n);
            if (!rc) { /* exact end points rather than their cell centres */
                (*xy)[0] = sx, (*xy)[1] = sy;
                (*xy)[2 * *n - 2] = gx, (*xy)[2 * *n - 1] = gy;
            }
            break;
        }
        int c = i % W, r = i / W;
        for (int dr = -1; dr <= 1; dr++)
            for (int dc = -1; dc <= 1; dc++) {
                int cc = c + dc, rr = r + dr;
                if ((!dr && !dc) || cc < 0 || cc >= W || rr < 0 || rr >= H) continue;
                int j = rr * W + cc;
                if (closed[j]) continue;
                double f = enter_cost(&rules, cc, rr);
                if (f == 0) continue;
                /* Diagonal moves may not cut the corner of a cell the robot cannot enter. */
                if (dr && dc && (!enter_cost(&rules, c + dc, r) || !enter_cost(&rules, c, r + dr)))
                    continue;
                float ng = gcost[i] + (float)(res * (dr && dc ? M_SQRT2 : 1.0) * f);
                if (ng >= gcost[j]) continue;
                gcost[j] = ng;
                parent[j] = i;
                double ddx = fabs((double)(cc - gc)), ddy = fabs((double)(rr - gr));
                double hcost = res * (fmax(ddx, ddy) + (M_SQRT2 - 1) * fmin(ddx, ddy));
                if (heap_push(&h, ng + (float)hcost, j)) {
                    rc = SP_E_NOMEM;
                    goto done;
                }
            }
    }
    if (rc == SP_E_NOTFOUND)
        sp_error_set(err, SP_E_NOTFOUND, "no path from (%.2f, %.2f) to (%.2f, %.2f): the goal is "
                     "not reachable through free space", sx, sy, gx, gy);
    else if (rc == SP_E_NOMEM)
        sp_error_set(err, SP_E_NOMEM, "planner: out of memory");
done:
    if (rc == SP_E_NOMEM && err && err->code != SP_E_NOMEM)
        sp_error_set(err, SP_E_NOMEM, "planner: out of memory");
    free(gcost);
    free(parent);
    free(closed);
    free(h.a);
    return rc;
}
