/* The simulated robot's map and plans, on the nav module: the costmap it drives on (a model
 * folder's splat, a Nav2 map.yaml or a costmap in memory, inflated for the robot's radius), the
 * goal check and planner (sp_costmap_check_goal, sp_plan_path), and the conversions of a plan
 * into what the drive follows and what ComputePathToPose returns. No DDS here, so the tests
 * exercise it without a network. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ros_internal.h"
#include "semsplat/device.h"
#include "semsplat/nav.h"

/* base with the robot's radius; the inflation reaches at least as far as the body. */
static sp_costmap_opts costmap_opts(sp_costmap_opts c, double robot_radius_m)
{
    c.robot_radius_m = (float)robot_radius_m;
    if (c.inflation_radius_m < c.robot_radius_m) c.inflation_radius_m = c.robot_radius_m;
    return c;
}

static int build_from_model(const sp_ros_sim_options *o, const sp_costmap_opts *c,
                            const sp_log *log, sp_costmap *cm, sp_error *err)
{
    sp_device *dev = o->device, *own = NULL;
    if (!dev) {
        int rc = sp_device_create(&own, SP_DEVICE_CPU, 0, err);
        if (rc) return rc;
        dev = own;
    }
    sp_logf(log, SP_LOG_INFO, "sim-robot: building the costmap of %s on %s", o->model_dir,
            sp_device_name(dev));
    int rc = sp_costmap_build_model(cm, o->model_dir, c, dev, log, err);
    sp_device_free(own);
    return rc;
}

int ros_sim_costmap(const sp_ros_sim_options *o, const sp_log *log, sp_costmap *cm,
                    sp_error *err)
{
    memset(cm, 0, sizeof *cm);
    if (!(o->robot_radius_m >= 0) || o->robot_radius_m > 5)
        return sp_error_set(err, SP_E_ARG, "sim-robot: robot radius %g m (0..5)",
                            o->robot_radius_m);
    sp_costmap_opts c = costmap_opts(sp_costmap_opts_default(), o->robot_radius_m);
    int given = !!o->costmap + !!o->map_yaml + !!o->model_dir, rc;
    if (given != 1)
        return sp_error_set(err, SP_E_ARG, "sim-robot: %s", given ? "give one costmap, not several "
                            "(--map FILE.yaml or --model DIR)" : "no costmap (--map FILE.yaml or "
                            "--model DIR)");
    if (o->costmap) {
        if ((rc = sp_costmap_copy(cm, o->costmap, err))) return rc;
        c = costmap_opts(cm->opts, o->robot_radius_m); /* as it was built, for this robot */
        if ((rc = sp_costmap_inflate(cm, &c, err))) sp_costmap_free(cm);
        return rc;
    }
    if (o->map_yaml) return sp_costmap_read_map(cm, o->map_yaml, &c, err);
    return build_from_model(o, &c, log, cm, err);
}

int ros_sim_check_start(const sp_costmap *cm, double x, double y, sp_error *err)
{
    char why[256];
    float p[2] = {(float)x, (float)y};
    /* The start may lie within the robot radius of an obstacle (the robot is there): only
     * outside, occupied or unknown is refused, which check_goal reports as START_*. */
    int st = sp_costmap_check_goal(cm, p, p, why, sizeof why);
    if (st == SP_NAV_START_OUTSIDE_MAP || st == SP_NAV_START_OCCUPIED)
        return sp_error_set(err, SP_E_ARG, "sim-robot: %s (the map spans x %.2f..%.2f, "
                            "y %.2f..%.2f; pass --start x,y,yaw on free floor)", why, cm->origin[0],
                            cm->origin[0] + cm->nx * cm->res, cm->origin[1],
                            cm->origin[1] + cm->ny * cm->res);
    return 0;
}

int ros_sim_plan(const sp_costmap *cm, const double start[3], const sp_ros_pose *goal,
                 sp_path *path, int *status, sp_error *err)
{
    memset(path, 0, sizeof *path);
    char why[256];
    float s[3] = {(float)start[0], (float)start[1], (float)start[2]};
    float g[2] = {(float)goal->x, (float)goal->y};
    if (!isfinite(goal->x) || !isfinite(goal->y) || !isfinite(goal->yaw))
        return sp_error_set(err, SP_E_ARG, "the goal (%g, %g, yaw %g) is not finite", goal->x,
                            goal->y, goal->yaw);
    *status = sp_costmap_check_goal(cm, s, g, why, sizeof why);
    if (*status != SP_NAV_OK) return sp_error_set(err, SP_E_NOTFOUND, "%s", why);
    sp_nav_goal ng = sp_nav_goal_pose(g[0], g[1], (float)goal->yaw);
    int rc = sp_plan_path(cm, s, &ng, NULL, path, err);
    *status = rc ? (path->status != SP_NAV_OK ? path->status : SP_NAV_NO_VALID_PATH) : SP_NAV_OK;
    return rc;
}

int ros_sim_collides(const sp_costmap *cm, double x, double y)
{
    int ix, iy;
    if (sp_costmap_cell(cm, (float)x, (float)y, &ix, &iy)) return 1;
    return cm->occ[(size_t)iy * cm->nx + ix] == SP_CELL_OCCUPIED;
}

int ros_sim_drive_path(const sp_path *p, const sp_ros_pose *goal, double **xy, size_t *n)
{
    size_t k = p->n_corners > 0 ? (size_t)p->n_corners : 0;
    *xy = malloc(sizeof(double) * 2 * (k ? k : 1));
    *n = 0;
    if (!*xy) return SP_E_NOMEM;
    for (size_t i = 0; i < k; i++) {
        (*xy)[2 * i] = p->corners[2 * i];
        (*xy)[2 * i + 1] = p->corners[2 * i + 1];
    }
    if (k) { /* the corner is the goal point in floats: end on the goal as asked */
        (*xy)[2 * k - 2] = goal->x;
        (*xy)[2 * k - 1] = goal->y;
    }
    *n = k;
    return 0;
}

int ros_sim_path_result(const sp_path *p, const sp_ros_pose *goal, const char *frame,
                        sp_ros_path *out)
{
    memset(out, 0, sizeof *out);
    size_t k = p->n > 0 ? (size_t)p->n : 0;
    out->poses = calloc(k ? k : 1, sizeof *out->poses);
    if (!out->poses) return SP_E_NOMEM;
    out->n = k;
    snprintf(out->frame_id, sizeof out->frame_id, "%s", frame);
    for (size_t i = 0; i < k; i++) {
        const float *w = p->waypoints + 4 * i;
        out->poses[i] = (sp_ros_pose){w[0], w[1], 0, w[3]};
    }
    if (k) out->poses[k - 1] = (sp_ros_pose){goal->x, goal->y, 0, goal->yaw};
    return 0;
}

int sp_ros_grid_from_costmap(const struct sp_costmap *cm, int use_costs, const char *frame_id,
                             sp_ros_grid *out, sp_error *err)
{
    memset(out, 0, sizeof *out);
    if (!cm || cm->nx <= 0 || cm->ny <= 0 || !cm->occ || !cm->cost)
        return sp_error_set(err, SP_E_ARG, "costmap -> grid: empty costmap");
    size_t n = (size_t)cm->nx * cm->ny;
    out->cells = malloc(n);
    if (!out->cells) return sp_error_set(err, SP_E_NOMEM, "costmap -> grid: %zu cells", n);
    sp_costmap_to_occupancy_grid(cm, use_costs, out->cells);
    out->width = cm->nx, out->height = cm->ny;
    out->resolution_m = cm->res;
    out->origin_x = cm->origin[0], out->origin_y = cm->origin[1], out->origin_yaw = 0;
    snprintf(out->frame_id, sizeof out->frame_id, "%s", frame_id && frame_id[0] ? frame_id : "map");
    return 0;
}
