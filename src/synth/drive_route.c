/* The route of a capture drive: where a robot goes to see every room. On the floor's clearance
 * grid: the connected parts of the free floor (cells a robot fits in), waypoints spread over each
 * part by farthest-point sampling weighted by clearance (so they sit in the open, not in
 * corners), visited in a nearest-neighbour tour; between waypoints the cheapest 8-connected path
 * (A*, steps near obstacles cost more so paths keep to the middle of doors and corridors), pulled
 * taut into straight legs wherever the line between two points stays on free cells. */
#include "internal.h"

#include <stdlib.h>
#include <string.h>

#define AREA_PER_WAYPOINT_M2 3.0 /* one spin per this much free floor */
#define MIN_PART_M2 2.0          /* smaller free patches (under tables, behind sofas) are skipped */
#define WAYPOINT_CLEAR_M 0.45f   /* preferred clearance of a waypoint: room to spin */
#define MIDDLE_M 0.8f            /* clearance beyond which a step costs its length only */

static int is_free(const sp_grid2 *g, float need, int i, int j)
{
    return i >= 0 && j >= 0 && i < g->nx && j < g->ny && g->data[(size_t)j * g->nx + i] >= need;
}

/* Labels the 8-connected parts of the free cells (1, 2, ...; 0 = not free); returns their count
 * and each part's cell count in *sizes (malloc'd, [count + 1]). */
static int label_parts(const sp_grid2 *g, float need, int32_t *label, size_t **sizes)
{
    size_t nc = (size_t)g->nx * g->ny;
    int32_t *stack = malloc(nc * sizeof *stack);
    size_t cap = 16, *sz = calloc(cap, sizeof *sz);
    if (!stack || !sz) {
        free(stack);
        free(sz);
        return -1;
    }
    memset(label, 0, nc * sizeof *label);
    int n = 0;
    for (size_t c = 0; c < nc; c++) {
        if (label[c] || !(g->data[c] >= need)) continue;
        if ((size_t)n + 2 > cap) {
            size_t *ns = realloc(sz, 2 * cap * sizeof *ns);
            if (!ns) {
                free(stack);
                free(sz);
                return -1;
            }
            memset(ns + cap, 0, cap * sizeof *ns);
            sz = ns;
            cap *= 2;
        }
        n++;
        size_t top = 0;
        stack[top++] = (int32_t)c;
        label[c] = n;
        while (top) {
            int32_t q = stack[--top];
            sz[n]++;
            int qi = q % g->nx, qj = q / g->nx;
            for (int dj = -1; dj <= 1; dj++)
                for (int di = -1; di <= 1; di++) {
                    if (!is_free(g, need, qi + di, qj + dj)) continue;
                    size_t r = (size_t)(qj + dj) * g->nx + (qi + di);
                    if (label[r]) continue;
                    label[r] = n;
                    stack[top++] = (int32_t)r;
                }
        }
    }
    free(stack);
    *sizes = sz;
    return n;
}

void synth_farthest_points(const sp_grid2 *g, float *mind, size_t first, int k, size_t *out)
{
    size_t nc = (size_t)g->nx * g->ny;
    for (int q = 0; q < k; q++) {
        size_t pick = first;
        if (q > 0) {
            float bd = -1;
            for (size_t c = 0; c < nc; c++) {
                if (mind[c] < 0) continue;
                float s = mind[c] * fminf(g->data[c] / MIDDLE_M, 1.0f);
                if (s > bd) { bd = s; pick = c; }
            }
        }
        out[q] = pick;
        float px = (float)(pick % g->nx), py = (float)(pick / g->nx);
        for (size_t c = 0; c < nc; c++) {
            if (mind[c] < 0) continue;
            float dx = (float)(c % g->nx) - px, dy = (float)(c / g->nx) - py, d = dx * dx + dy * dy;
            if (d < mind[c]) mind[c] = d;
        }
    }
}

/* Farthest-point sampling of k waypoints in part p, the first at its most open cell. */
static void pick_waypoints(const sp_grid2 *g, const int32_t *label, int p, int k, float *mind,
                           size_t *out)
{
    size_t nc = (size_t)g->nx * g->ny, first = 0;
    float best = -1;
    for (size_t c = 0; c < nc; c++)
        if (label[c] == p && g->data[c] > best) { best = g->data[c]; first = c; }
    float want = fminf(WAYPOINT_CLEAR_M, best);
    for (size_t c = 0; c < nc; c++) mind[c] = label[c] == p && g->data[c] >= want ? INFINITY : -1;
    synth_farthest_points(g, mind, first, k, out);
}

/* Nearest-neighbour tour over wp[0..k) starting at wp[0], in place. */
static void order_tour(const sp_grid2 *g, size_t *wp, int k)
{
    for (int a = 0; a + 1 < k; a++) {
        int best = a + 1;
        double bd = INFINITY;
        for (int b = a + 1; b < k; b++) {
            double dx = (double)(wp[b] % g->nx) - (double)(wp[a] % g->nx);
            double dy = (double)(wp[b] / g->nx) - (double)(wp[a] / g->nx);
            if (dx * dx + dy * dy < bd) { bd = dx * dx + dy * dy; best = b; }
        }
        size_t t = wp[a + 1];
        wp[a + 1] = wp[best];
        wp[best] = t;
    }
}

/* ---- A* on the free cells ------------------------------------------------------------------ */

typedef struct heap {
    size_t n, cap;
    float *key;
    int32_t *cell;
} heap;

static int heap_push(heap *h, float key, int32_t cell)
{
    if (h->n == h->cap) {
        size_t cap = h->cap ? 2 * h->cap : 1024;
        float *k = realloc(h->key, cap * sizeof *k);
        if (!k) return -1;
        h->key = k;
        int32_t *c = realloc(h->cell, cap * sizeof *c);
        if (!c) return -1;
        h->cell = c;
        h->cap = cap;
    }
    size_t i = h->n++;
    while (i > 0 && h->key[(i - 1) / 2] > key) {
        h->key[i] = h->key[(i - 1) / 2];
        h->cell[i] = h->cell[(i - 1) / 2];
        i = (i - 1) / 2;
    }
    h->key[i] = key;
    h->cell[i] = cell;
    return 0;
}

static int32_t heap_pop(heap *h)
{
    int32_t top = h->cell[0];
    float key = h->key[--h->n];
    int32_t cell = h->cell[h->n];
    size_t i = 0;
    for (;;) {
        size_t c = 2 * i + 1;
        if (c >= h->n) break;
        if (c + 1 < h->n && h->key[c + 1] < h->key[c]) c++;
        if (h->key[c] >= key) break;
        h->key[i] = h->key[c];
        h->cell[i] = h->cell[c];
        i = c;
    }
    h->key[i] = key;
    h->cell[i] = cell;
    return top;
}

typedef struct astar {
    float *cost;
    int32_t *parent;
    heap open;
} astar;

static float step_cost(const sp_grid2 *g, size_t c, float len)
{
    float cl = g->data[c];
    return len * (1.0f + 2.0f * fmaxf(0.0f, MIDDLE_M - cl) / MIDDLE_M);
}

/* Cheapest path from a to b over free cells; the cells from b back to a in path[], their count
 * returned (0 when b cannot be reached, -1 when out of memory). */
static long find_path(const sp_grid2 *g, float need, astar *s, size_t a, size_t b, int32_t *path)
{
    size_t nc = (size_t)g->nx * g->ny;
    for (size_t c = 0; c < nc; c++) {
        s->cost[c] = INFINITY;
        s->parent[c] = -1;
    }
    s->open.n = 0;
    int bi = (int)(b % g->nx), bj = (int)(b / g->nx);
    s->cost[a] = 0;
    if (heap_push(&s->open, 0, (int32_t)a)) return -1;
    while (s->open.n) {
        int32_t q = heap_pop(&s->open);
        if ((size_t)q == b) break;
        int qi = q % g->nx, qj = q / g->nx;
        for (int dj = -1; dj <= 1; dj++)
            for (int di = -1; di <= 1; di++) {
                if ((!di && !dj) || !is_free(g, need, qi + di, qj + dj)) continue;
                size_t r = (size_t)(qj + dj) * g->nx + (qi + di);
                float c = s->cost[q] + step_cost(g, r, g->res * (di && dj ? 1.41421356f : 1.0f));
                if (!(c < s->cost[r])) continue;
                s->cost[r] = c;
                s->parent[r] = q;
                /* octile distance: admissible, since a step costs at least its length */
                float dx = fabsf((float)(qi + di - bi)), dy = fabsf((float)(qj + dj - bj));
                float h = g->res * (fmaxf(dx, dy) + 0.41421356f * fminf(dx, dy));
                if (heap_push(&s->open, c + h, (int32_t)r)) return -1;
            }
    }
    if (!isfinite(s->cost[b])) return 0;
    long n = 0;
    for (int32_t c = (int32_t)b; c >= 0; c = s->parent[c]) path[n++] = c;
    return n;
}

static int line_free(const sp_grid2 *g, float need, size_t a, size_t b)
{
    float ax, ay, bx, by;
    sp_grid2_center(g, (int)(a % g->nx), (int)(a / g->nx), &ax, &ay);
    sp_grid2_center(g, (int)(b % g->nx), (int)(b / g->nx), &bx, &by);
    float L = hypotf(bx - ax, by - ay);
    int steps = (int)ceilf(L / (0.5f * g->res));
    for (int s = 1; s < steps; s++) {
        float u = (float)s / steps;
        int i, j;
        sp_grid2_cell(g, ax + u * (bx - ax), ay + u * (by - ay), &i, &j);
        if (!is_free(g, need, i, j)) return 0;
    }
    return 1;
}

/* ---- the route ----------------------------------------------------------------------------- */

static int route_add(drive_route *r, size_t *cap, const sp_grid2 *g, size_t cell, int stop, int jump)
{
    if (r->n == *cap) {
        size_t nc = *cap ? 2 * *cap : 64;
        float *xy = realloc(r->xy, nc * 2 * sizeof *xy);
        if (!xy) return -1;
        r->xy = xy;
        uint8_t *st = realloc(r->stop, nc);
        if (!st) return -1;
        r->stop = st;
        uint8_t *ju = realloc(r->jump, nc);
        if (!ju) return -1;
        r->jump = ju;
        *cap = nc;
    }
    sp_grid2_center(g, (int)(cell % g->nx), (int)(cell / g->nx), &r->xy[2 * r->n], &r->xy[2 * r->n + 1]);
    r->stop[r->n] = (uint8_t)stop;
    r->jump[r->n] = (uint8_t)jump;
    r->n++;
    return 0;
}

/* Appends the leg from a to b: A*, then the taut corners (b last, as a stop). */
static int add_leg(drive_route *r, size_t *cap, const sp_grid2 *g, float need, astar *s,
                   int32_t *path, size_t a, size_t b)
{
    long n = find_path(g, need, s, a, b, path);
    if (n < 0) return -1;
    if (n == 0) return route_add(r, cap, g, b, 1, 1); /* cannot happen within a part */
    /* path[n-1] = a ... path[0] = b; pull taut from a */
    long at = n - 1;
    while (at > 0) {
        long far = at - 1;
        for (long k = 0; k < at - 1; k++)
            if (line_free(g, need, (size_t)path[at], (size_t)path[k])) { far = k; break; }
        if (route_add(r, cap, g, (size_t)path[far], far == 0, 0)) return -1;
        at = far;
    }
    return 0;
}

int drive_plan_route(const sp_grid2 *g, float need, int max_waypoints, drive_route *r,
                     sp_error *err)
{
    memset(r, 0, sizeof *r);
    size_t nc = (size_t)g->nx * g->ny, cap = 0, *sizes = NULL;
    int32_t *label = malloc(nc * sizeof *label), *path = malloc(nc * sizeof *path);
    float *mind = malloc(nc * sizeof *mind);
    size_t *wp = malloc((size_t)(max_waypoints > 0 ? max_waypoints : 1) * sizeof *wp);
    astar s = {.cost = malloc(nc * sizeof(float)), .parent = malloc(nc * sizeof(int32_t))};
    int rc = 0, n_parts = -1;
    if (label && path && mind && wp && s.cost && s.parent) n_parts = label_parts(g, need, label, &sizes);
    if (n_parts < 0) rc = sp_error_set(err, SP_E_NOMEM, "drive route: out of memory");
    size_t n_free = 0, biggest = 0;
    for (int p = 1; !rc && p <= n_parts; p++) {
        n_free += sizes[p];
        if (sizes[p] > biggest) biggest = sizes[p];
    }
    double cell_m2 = (double)g->res * g->res;
    /* parts by size, largest first, each worth a segment of the drive when big enough */
    int budget = max_waypoints;
    for (int round = 0; !rc && n_parts > 0 && budget > 0; round++) {
        int p = 0;
        size_t sz = 0;
        for (int q = 1; q <= n_parts; q++)
            if (sizes[q] > sz) { sz = sizes[q]; p = q; }
        if (!p || (round > 0 && sz * cell_m2 < MIN_PART_M2)) break;
        sizes[p] = 0; /* taken */
        int k = (int)lround(sz * cell_m2 / AREA_PER_WAYPOINT_M2);
        if (k < 1) k = 1;
        if (k > budget) k = budget;
        budget -= k;
        pick_waypoints(g, label, p, k, mind, wp);
        order_tour(g, wp, k);
        if (route_add(r, &cap, g, wp[0], 1, r->n > 0)) rc = -1;
        for (int q = 1; !rc && q < k; q++)
            if (add_leg(r, &cap, g, need, &s, path, wp[q - 1], wp[q])) rc = -1;
        if (rc) rc = sp_error_set(err, SP_E_NOMEM, "drive route: out of memory");
        r->n_waypoints += k;
        r->n_segments++;
    }
    if (!rc && r->n == 0) rc = sp_error_set(err, SP_E_NOTFOUND, "drive route: no free floor");
    r->reachable_fraction = n_free ? (double)biggest / n_free : 0;
    free(label);
    free(path);
    free(mind);
    free(wp);
    free(sizes);
    free(s.cost);
    free(s.parent);
    free(s.open.key);
    free(s.open.cell);
    if (rc) drive_route_free(r);
    return rc;
}

void drive_route_free(drive_route *r)
{
    free(r->xy);
    free(r->stop);
    free(r->jump);
    memset(r, 0, sizeof *r);
}
