/* Costs from occupancy: the distance transform and Nav2's inflation formula, the goal check
 * (free and reachable), and the nav_msgs/OccupancyGrid view of the map. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "nav_internal.h"

/* nav2_costmap_2d InflationLayer::computeCost, with d in metres:
 *   d == 0 -> LETHAL; d <= inscribed -> INSCRIBED; else 252 exp(-csf (d - inscribed)),
 * only within the inflation radius (0 beyond). */
static uint8_t inflation_cost(float d, const sp_costmap_opts *o)
{
    if (d <= 0.0f) return SP_COST_LETHAL;
    if (d <= o->robot_radius_m) return SP_COST_INSCRIBED;
    if (d > o->inflation_radius_m) return SP_COST_FREE;
    return (uint8_t)(SP_COST_MAX_NON_OBSTACLE * expf(-o->cost_scaling_factor * (d - o->robot_radius_m)));
}

int sp_costmap_inflate(sp_costmap *cm, const sp_costmap_opts *opts, sp_error *err)
{
    if (opts) {
        if (!(opts->robot_radius_m >= 0) || !(opts->inflation_radius_m >= opts->robot_radius_m) ||
            !(opts->cost_scaling_factor >= 0))
            return sp_error_set(err, SP_E_ARG, "costmap: robot radius %g m, inflation radius %g m, "
                                "cost scaling %g (need 0 <= robot <= inflation, scaling >= 0)",
                                opts->robot_radius_m, opts->inflation_radius_m,
                                opts->cost_scaling_factor);
        cm->opts = *opts;
    }
    size_t n = (size_t)cm->nx * cm->ny;
    uint8_t *seed = calloc(n ? n : 1, 1);
    float *du = cm->opts.keep_clear_of_unknown ? malloc(n * sizeof(float)) : NULL;
    if (!seed || (cm->opts.keep_clear_of_unknown && !du)) {
        free(seed), free(du);
        return sp_error_set(err, SP_E_NOMEM, "costmap: out of memory inflating %zu cells", n);
    }
    /* unknown cells where Gaussians no ray observed stand are kept clear of as obstacles are */
    for (size_t i = 0; i < n; i++) seed[i] = cm->occ[i] == SP_CELL_OCCUPIED || (cm->hidden && cm->hidden[i]);
    int rc = sp_edt2(seed, cm->nx, cm->ny, cm->res, cm->dist, NULL, err);
    if (!rc && du) {
        for (size_t i = 0; i < n; i++) seed[i] = cm->occ[i] == SP_CELL_UNKNOWN;
        rc = sp_edt2(seed, cm->nx, cm->ny, cm->res, du, NULL, err);
    }
    free(seed);
    if (rc) {
        free(du);
        return rc;
    }
    for (size_t i = 0; i < n; i++) {
        if (cm->occ[i] == SP_CELL_UNKNOWN) {
            cm->cost[i] = SP_COST_UNKNOWN;
            continue;
        }
        uint8_t c = cm->occ[i] == SP_CELL_OCCUPIED ? SP_COST_LETHAL : inflation_cost(cm->dist[i], &cm->opts);
        /* the robot's body must not reach into space nobody saw either (Nav2 leaves this to
         * inflate_around_unknown; our maps have unknown inside rooms, under-observed corners) */
        if (du && c < SP_COST_INSCRIBED && du[i] <= cm->opts.robot_radius_m) c = SP_COST_INSCRIBED;
        cm->cost[i] = c;
    }
    free(du);
    return SP_OK;
}

void sp_costmap_to_occupancy_grid(const sp_costmap *cm, int use_costs, int8_t *data)
{
    size_t n = (size_t)cm->nx * cm->ny;
    for (size_t i = 0; i < n; i++) {
        if (!use_costs) {
            data[i] = cm->occ[i] == SP_CELL_UNKNOWN ? -1 : cm->occ[i] == SP_CELL_OCCUPIED ? 100 : 0;
            continue;
        }
        uint8_t c = cm->cost[i];
        /* nav2_costmap_2d Costmap2DPublisher's translation table */
        data[i] = c == SP_COST_UNKNOWN ? -1 : c == SP_COST_LETHAL ? 100 : c == SP_COST_INSCRIBED ? 99
                  : c == 0 ? 0 : (int8_t)(1 + (97 * (c - 1)) / 251);
    }
}

const char *sp_nav_status_name(int status)
{
    switch (status) {
    case SP_NAV_OK: return "ok";
    case SP_NAV_START_OUTSIDE_MAP: return "start outside map";
    case SP_NAV_GOAL_OUTSIDE_MAP: return "goal outside map";
    case SP_NAV_START_OCCUPIED: return "start occupied";
    case SP_NAV_GOAL_OCCUPIED: return "goal occupied";
    case SP_NAV_TIMEOUT: return "timeout";
    case SP_NAV_NO_VALID_PATH: return "no valid path";
    default: return "unknown status";
    }
}

static const char *cell_word(const sp_costmap *cm, long i)
{
    if (cm->occ[i] == SP_CELL_UNKNOWN && cm->hidden && cm->hidden[i]) return "occupied (Gaussians no camera saw)";
    if (cm->occ[i] == SP_CELL_UNKNOWN) return "unknown (never observed)";
    if (cm->occ[i] == SP_CELL_OCCUPIED) return "occupied";
    if (cm->cost[i] >= SP_COST_INSCRIBED) return "within the robot radius of an obstacle or unknown space";
    return "free";
}

/* Flood fill over traversable cells from the start; 1 when the goal cell is reached, -1 when
 * out of memory. */
static int connected(const sp_costmap *cm, long s, long g)
{
    size_t n = (size_t)cm->nx * cm->ny;
    uint8_t *mark = calloc(n, 1);
    long *queue = malloc(sizeof(long) * n);
    if (!mark || !queue) {
        free(mark), free(queue);
        return -1;
    }
    long head = 0, tail = 0;
    queue[tail++] = s;
    mark[s] = 1;
    int found = 0;
    while (head < tail && !found) {
        long c = queue[head++];
        int cx = (int)(c % cm->nx), cy = (int)(c / cm->nx);
        for (int k = 0; k < 4; k++) {
            int x = cx + (k == 0) - (k == 1), y = cy + (k == 2) - (k == 3);
            if (!sp_costmap_traversable(cm, x, y)) continue;
            long j = nav_idx(cm, x, y);
            if (mark[j]) continue;
            mark[j] = 1;
            if (j == g) found = 1;
            queue[tail++] = j;
        }
    }
    free(mark), free(queue);
    return found;
}

int sp_costmap_check_goal(const sp_costmap *cm, const float start[2], const float goal[2],
                          char *why, size_t cap)
{
    int sx, sy, gx, gy;
    char dummy[8];
    if (!why) why = dummy, cap = sizeof dummy;
    why[0] = 0;
    if (sp_costmap_cell(cm, start[0], start[1], &sx, &sy)) {
        snprintf(why, cap, "the start (%.2f, %.2f) is outside the map", start[0], start[1]);
        return SP_NAV_START_OUTSIDE_MAP;
    }
    if (sp_costmap_cell(cm, goal[0], goal[1], &gx, &gy)) {
        snprintf(why, cap, "the goal (%.2f, %.2f) is outside the map", goal[0], goal[1]);
        return SP_NAV_GOAL_OUTSIDE_MAP;
    }
    long s = nav_idx(cm, sx, sy), g = nav_idx(cm, gx, gy);
    if (cm->occ[s] != SP_CELL_FREE) {
        snprintf(why, cap, "the start (%.2f, %.2f) is %s", start[0], start[1], cell_word(cm, s));
        return SP_NAV_START_OCCUPIED;
    }
    if (!sp_costmap_traversable(cm, gx, gy)) {
        snprintf(why, cap, "the goal (%.2f, %.2f) is %s", goal[0], goal[1], cell_word(cm, g));
        return SP_NAV_GOAL_OCCUPIED;
    }
    if (s == g) return SP_NAV_OK;
    /* the start itself may lie within the inscribed ring: the fill leaves it into traversable
     * cells only (4-connected, as the planner's diagonal moves never cut corners) */
    int ok = connected(cm, s, g);
    if (ok < 0) {
        snprintf(why, cap, "out of memory checking reachability");
        return SP_NAV_NO_VALID_PATH;
    }
    if (!ok) {
        snprintf(why, cap, "the goal (%.2f, %.2f) is free but not reachable from (%.2f, %.2f) "
                 "through free space", goal[0], goal[1], start[0], start[1]);
        return SP_NAV_NO_VALID_PATH;
    }
    return SP_NAV_OK;
}

void sp_costmap_compare(const sp_costmap *cm, const uint8_t *truth, sp_costmap_agreement *out)
{
    memset(out, 0, sizeof *out);
    out->cells = (long)cm->nx * cm->ny;
    for (long i = 0; i < out->cells; i++) {
        int t = truth[i] != 0;
        out->truth_occupied += t;
        if (cm->occ[i] == SP_CELL_UNKNOWN) continue;
        int o = cm->occ[i] == SP_CELL_OCCUPIED;
        out->known++;
        out->agree += o == t;
        out->occupied_as_free += t && !o;
        out->free_as_occupied += !t && o;
    }
    out->agreement = out->known ? (double)out->agree / out->known : 0;
    out->occupied_free_rate = out->truth_occupied ? (double)out->occupied_as_free / out->truth_occupied : 0;
    out->known_fraction = out->cells ? (double)out->known / out->cells : 0;
}
