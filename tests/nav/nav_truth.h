/* Issue 18's acceptance against a world's ground truth, shared by tests/nav/test_house.c and
 * bench/bench_nav.c: the cells a robot centre truly reaches from a start (at least a robot radius
 * from truly occupied cells, connected), whether an object is truly reachable on the floor (a
 * reachable cell within REACH_M of its footprint), the cells a path enters, and the k-paths
 * distinctness rule. truth: [ny][nx] 1 occupied (sp_synth_floor_plan on the costmap's grid). */
#ifndef SP_TEST_NAV_TRUTH_H
#define SP_TEST_NAV_TRUTH_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "nav/nav_internal.h"
#include "semsplat/nav.h"

#define NT_REACH_M 0.6f /* a path ends within this of the object's footprint */

/* reach [ny][nx] (caller's, zeroed here): 1 where a robot centre truly reaches from start. */
static inline int nt_reach(const sp_costmap *cm, const uint8_t *truth, const float start[2], float robot_radius_m,
                           uint8_t *reach, sp_error *err)
{
    size_t n = (size_t)cm->nx * cm->ny;
    float *d = malloc(sizeof(float) * n);
    long *queue = malloc(sizeof(long) * n), head = 0, tail = 0;
    if (!d || !queue) {
        free(d), free(queue);
        return sp_error_set(err, SP_E_NOMEM, "nav truth: out of memory");
    }
    int rc = sp_edt2(truth, cm->nx, cm->ny, cm->res, d, NULL, err);
    memset(reach, 0, n);
    int sx, sy;
    if (!rc && sp_costmap_cell(cm, start[0], start[1], &sx, &sy) == 0) {
        queue[tail++] = nav_idx(cm, sx, sy);
        reach[queue[0]] = 1;
    }
    while (!rc && head < tail) {
        long c = queue[head++];
        int cx = (int)(c % cm->nx), cy = (int)(c / cm->nx);
        for (int k = 0; k < 4; k++) {
            int x = cx + (k == 0) - (k == 1), y = cy + (k == 2) - (k == 3);
            if (!nav_inside(cm, x, y)) continue;
            long j = nav_idx(cm, x, y);
            if (reach[j] || d[j] <= robot_radius_m) continue;
            reach[j] = 1;
            queue[tail++] = j;
        }
    }
    free(queue), free(d);
    return rc;
}

/* Is some truly reachable cell within NT_REACH_M of the box? */
static inline int nt_box_reachable(const sp_costmap *cm, const uint8_t *reach, const sp_nav_box *b)
{
    for (int iy = 0; iy < cm->ny; iy++)
        for (int ix = 0; ix < cm->nx; ix++) {
            if (!reach[nav_idx(cm, ix, iy)]) continue;
            float c[2];
            sp_costmap_cell_center(cm, ix, iy, c);
            if (nav_box_dist(b, c) <= NT_REACH_M) return 1;
        }
    return 0;
}

typedef struct nt_enter_ctx {
    const sp_costmap *cm;
    const uint8_t *truth;
    long start;
    int bad, truly_occupied;
} nt_enter_ctx;

static inline int nt_enter_cell(void *v, long cell, float t0, float t1)
{
    nt_enter_ctx *c = v;
    (void)t0, (void)t1;
    if (cell != c->start && !(c->cm->occ[cell] == SP_CELL_FREE && c->cm->cost[cell] < SP_COST_INSCRIBED)) c->bad++;
    c->truly_occupied += c->truth[cell];
    return 0;
}

/* Cells the path's segments enter that are not traversable (the start's excepted: the robot is
 * there), and that are truly occupied. */
static inline void nt_path_cells(const sp_costmap *cm, const uint8_t *truth, const sp_path *p, int *bad,
                                 int *truly_occupied)
{
    int sx, sy;
    sp_costmap_cell(cm, p->waypoints[0], p->waypoints[1], &sx, &sy);
    nt_enter_ctx c = {cm, truth, nav_idx(cm, sx, sy), 0, 0};
    for (int k = 0; k + 1 < p->n; k++) {
        float a[2] = {p->waypoints[4 * k], p->waypoints[4 * k + 1]};
        float b[2] = {p->waypoints[4 * k + 4], p->waypoints[4 * k + 5]};
        nav_traverse(cm, a, b, nt_enter_cell, &c);
    }
    *bad = c.bad, *truly_occupied = c.truly_occupied;
}

/* A path to an object judged against the truth: it enters no untraversable cell and ends in a
 * truly free cell within NT_REACH_M of the object's true footprint. */
typedef struct nt_verdict {
    int bad, truly_occupied, end_free;
    float end_dist;
    int pass;
} nt_verdict;

static inline nt_verdict nt_judge(const sp_costmap *cm, const uint8_t *truth, const sp_nav_box *true_box,
                                  const sp_path *p)
{
    nt_verdict v;
    nt_path_cells(cm, truth, p, &v.bad, &v.truly_occupied);
    const float *e = p->waypoints + 4 * (p->n - 1);
    int ix, iy;
    sp_costmap_cell(cm, e[0], e[1], &ix, &iy);
    v.end_dist = nav_box_dist(true_box, e);
    v.end_free = nav_inside(cm, ix, iy) && !truth[nav_idx(cm, ix, iy)];
    v.pass = v.bad == 0 && v.end_dist <= NT_REACH_M && v.end_free;
    return v;
}

/* Pairs of paths breaking the distinctness rule: longer than max_length_ratio x the shortest, or
 * sharing more than max_share (+0.02) of their length with another path, either way. */
static inline int nt_distinct_violations(const sp_path *const *paths, int n, const sp_planner_opts *po)
{
    float shortest = INFINITY;
    int bad = 0;
    for (int i = 0; i < n; i++) shortest = fminf(shortest, paths[i]->length_m);
    for (int i = 0; i < n; i++) {
        bad += paths[i]->length_m > po->max_length_ratio * shortest + 1e-3f;
        for (int j = 0; j < n; j++)
            if (j != i && sp_path_share(paths[i]->waypoints, paths[i]->n, 4, paths[j]->waypoints, paths[j]->n, 4,
                                        po->share_radius_m) > po->max_share + 0.02f)
                bad++;
    }
    return bad;
}

#endif
