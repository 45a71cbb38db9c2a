/* The simulated robot's parts without DDS, on the nav module: its costmap (a Nav2 map as
 * map_saver writes it, one in memory re-inflated for the robot, what it publishes), plans
 * through the door that keep the robot's radius, goals refused with ComputePathToPose's codes
 * (occupied, unknown, too close, outside, unreachable), starts, collisions, and the
 * differential drive (limits respected, goal reached, stop). */
#include <math.h>

#include "ros/ros_internal.h"
#include "ros_test.h"
#include "test.h"

/* The room's Nav2 map (as map_saver writes it), through the robot's loader. */
static int room_costmap(sp_costmap *cm, double radius_m)
{
    sp_ros_sim_options o;
    sp_ros_sim_options_default(&o);
    o.map_yaml = room_write_yaml(test_tmpdir("ros_plan_room"));
    o.robot_radius_m = radius_m;
    sp_error err = {0};
    int rc = ros_sim_costmap(&o, NULL, cm, &err);
    CHECK_OK(rc, &err);
    return rc;
}

static void test_room_map(void)
{
    sp_costmap cm;
    if (room_costmap(&cm, 0.2)) return;
    CHECK(cm.nx == ROOM_W && cm.ny == ROOM_H);
    CHECK_NEAR(cm.res, 0.05, 1e-7);
    CHECK_NEAR(cm.origin[0], 0, 1e-9);
    CHECK_NEAR(cm.opts.robot_radius_m, 0.2, 1e-7);
    long diff = 0;
    for (int r = 0; r < ROOM_H; r++)
        for (int c = 0; c < ROOM_W; c++) {
            int8_t v = room_cell_at((c + 0.5) * ROOM_RES, (r + 0.5) * ROOM_RES);
            uint8_t want = v < 0 ? SP_CELL_UNKNOWN : v ? SP_CELL_OCCUPIED : SP_CELL_FREE;
            diff += cm.occ[r * ROOM_W + c] != want;
        }
    CHECK_MSG(diff == 0, "%ld cells differ (unknown must stay unknown, rows flipped)", diff);
    /* what the robot publishes on its map topic */
    sp_ros_grid g;
    sp_error err = {0};
    CHECK_OK(sp_ros_grid_from_costmap(&cm, 0, NULL, &g, &err), &err);
    sp_ros_grid want;
    room_grid(&want);
    CHECK(g.width == ROOM_W && g.height == ROOM_H && !strcmp(g.frame_id, "map"));
    CHECK(g.cells && !memcmp(g.cells, want.cells, ROOM_W * ROOM_H));
    sp_ros_grid_free(&g);
    sp_ros_grid_free(&want);
    CHECK_OK(sp_ros_grid_from_costmap(&cm, 1, "world", &g, &err), &err);
    long lethal = 0, bad = 0;
    for (int i = 0; i < ROOM_W * ROOM_H; i++) {
        lethal += g.cells[i] == 100;
        bad += (cm.cost[i] == SP_COST_INSCRIBED) != (g.cells[i] == 99) ||
               (cm.cost[i] == SP_COST_UNKNOWN) != (g.cells[i] == -1);
    }
    CHECK(!strcmp(g.frame_id, "world") && lethal > 0 && bad == 0);
    sp_ros_grid_free(&g);
    sp_costmap_free(&cm);
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (f) fputs(text, f), fclose(f);
}

/* One costmap, and only one: a map, a model folder or one in memory. */
static void test_costmap_sources(void)
{
    const char *dir = test_tmpdir("ros_plan_sources");
    char yaml[1024], pgm[1024];
    sp_ros_sim_options o;
    sp_ros_sim_options_default(&o);
    sp_costmap cm;
    sp_error err = {0};
    CHECK_FAILS(ros_sim_costmap(&o, NULL, &cm, &err), SP_E_ARG, &err, "no costmap");
    snprintf(yaml, sizeof yaml, "%s/a.yaml", dir);
    snprintf(pgm, sizeof pgm, "%s/x.pgm", dir);
    write_text(pgm, "P2\n2 1\n255\n0 254\n"); /* ascii, negate: black is free */
    write_text(yaml, "image: x.pgm\nresolution: 0.1\norigin: [1, 2, 0]\nnegate: 1\n"
                     "occupied_thresh: 0.65\nfree_thresh: 0.19\n");
    o.map_yaml = yaml;
    o.model_dir = dir;
    CHECK_FAILS(ros_sim_costmap(&o, NULL, &cm, &err), SP_E_ARG, &err, "not several");
    o.model_dir = NULL;
    CHECK_OK(ros_sim_costmap(&o, NULL, &cm, &err), &err);
    CHECK(cm.nx == 2 && cm.occ[0] == SP_CELL_FREE && cm.occ[1] == SP_CELL_OCCUPIED);
    CHECK_NEAR(cm.origin[1], 2, 1e-9);
    /* in memory: copied and inflated for this robot */
    sp_costmap room;
    if (room_costmap(&room, 0.2) == 0) {
        sp_costmap big;
        float near_wall[2] = {3.6f, 2.0f}, start[2] = {1.0f, 1.0f};
        o.map_yaml = NULL, o.costmap = &room, o.robot_radius_m = 0.4;
        CHECK_OK(ros_sim_costmap(&o, NULL, &big, &err), &err);
        CHECK(sp_costmap_check_goal(&room, start, near_wall, NULL, 0) == SP_NAV_OK);
        CHECK(sp_costmap_check_goal(&big, start, near_wall, NULL, 0) == SP_NAV_GOAL_OCCUPIED);
        CHECK_NEAR(room.opts.robot_radius_m, 0.2, 1e-7); /* the caller's is left alone */
        sp_costmap_free(&big);
        sp_costmap_free(&room);
    }
    sp_costmap_free(&cm);
    o.costmap = NULL;
    o.map_yaml = "/nonexistent/map.yaml";
    CHECK_FAILS(ros_sim_costmap(&o, NULL, &cm, &err), SP_E_IO, &err, "/nonexistent/map.yaml");
    o.map_yaml = NULL;
    o.model_dir = "/nonexistent/model";
    CHECK_FAILS(ros_sim_costmap(&o, NULL, &cm, &err), SP_E_IO, &err, "/nonexistent/model");
}

static double path_length(const double *xy, size_t n)
{
    double L = 0;
    for (size_t i = 1; i < n; i++) L += hypot(xy[2 * i] - xy[2 * i - 2], xy[2 * i + 1] - xy[2 * i - 1]);
    return L;
}

static int traversable_at(const sp_costmap *cm, double x, double y)
{
    int ix, iy;
    return !sp_costmap_cell(cm, (float)x, (float)y, &ix, &iy) && sp_costmap_traversable(cm, ix, iy);
}

static void test_plan_through_door(void)
{
    sp_costmap cm;
    if (room_costmap(&cm, 0.2)) return;
    sp_error err = {0};
    double start[3] = {1.0, 1.0, 0.0};
    sp_ros_pose goal = {6.0, 2.0, 0, 1.3};
    sp_path p;
    int status = -1;
    CHECK_OK(ros_sim_plan(&cm, start, &goal, &p, &status, &err), &err);
    CHECK(status == SP_NAV_OK);
    double *xy = NULL;
    size_t n = 0;
    CHECK(ros_sim_drive_path(&p, &goal, &xy, &n) == 0);
    if (xy && n >= 2) {
        CHECK_NEAR(xy[0], 1.0, 1e-6);
        CHECK(xy[2 * n - 2] == 6.0 && xy[2 * n - 1] == 2.0);
        /* Every point along the path is traversable (the robot's radius from walls, never
         * unknown), and it crosses x = 4 through the door (4 < y < 5). */
        int crossed = 0;
        long blocked = 0;
        for (size_t i = 1; i < n; i++)
            for (int s = 0; s <= 50; s++) {
                double t = s / 50.0;
                double x = xy[2 * i - 2] + t * (xy[2 * i] - xy[2 * i - 2]);
                double y = xy[2 * i - 1] + t * (xy[2 * i + 1] - xy[2 * i - 1]);
                blocked += !traversable_at(&cm, x, y) && hypot(x - 1, y - 1) > 0.08;
                if (fabs(x - 4.0) < 0.03) crossed = crossed || (y > 4.0 && y < 5.0);
            }
        CHECK_MSG(blocked == 0, "%ld points of the path not traversable", blocked);
        CHECK(crossed);
        /* Through the door: at least the straight-line distance via the door's centre, and not
         * much more (the inflation cost keeps it off walls). */
        double via = hypot(4 - 1, 4.5 - 1) + hypot(6 - 4, 2 - 4.5);
        double L = path_length(xy, n);
        CHECK_MSG(L > via * 0.97 && L < via * 1.25, "length %.2f, via the door %.2f", L, via);
    }
    sp_ros_path rp;
    CHECK(ros_sim_path_result(&p, &goal, "map", &rp) == 0);
    CHECK(rp.n >= 2 && !strcmp(rp.frame_id, "map"));
    if (rp.n >= 2) {
        CHECK(rp.poses[rp.n - 1].x == 6.0 && rp.poses[rp.n - 1].yaw == 1.3);
        CHECK_NEAR(rp.poses[0].x, 1.0, 1e-6);
        /* headings along the path: the first points into the first leg */
        double lx = rp.poses[1].x - rp.poses[0].x, ly = rp.poses[1].y - rp.poses[0].y;
        CHECK_NEAR(remainder(rp.poses[0].yaw - atan2(ly, lx), 2 * M_PI), 0, 0.05);
    }
    sp_ros_path_free(&rp);
    free(xy);
    sp_path_free(&p);
    sp_costmap_free(&cm);
}

/* Goals refused with ComputePathToPose's codes (Jazzy error_code = 200 + status). */
static void test_refusals(void)
{
    sp_costmap cm;
    if (room_costmap(&cm, 0.2)) return;
    static const struct {
        double x, y;
        int status, code;
        const char *why;
    } cases[] = {
        {4.0, 2.0, SP_NAV_GOAL_OCCUPIED, 206, "occupied"},
        {7.0, 1.0, SP_NAV_GOAL_OCCUPIED, 206, "unknown"},
        {3.75, 2.0, SP_NAV_GOAL_OCCUPIED, 206, "robot radius"},
        {20.0, 1.0, SP_NAV_GOAL_OUTSIDE_MAP, 204, "outside the map"},
        {7.1, 3.5, SP_NAV_NO_VALID_PATH, 208, "not reachable"}, /* the closet */
    };
    double start[3] = {1, 1, 0};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        sp_ros_pose goal = {cases[i].x, cases[i].y, 0, 0};
        sp_path p;
        int status = -1;
        sp_error err = {0};
        CHECK_FAILS(ros_sim_plan(&cm, start, &goal, &p, &status, &err), SP_E_NOTFOUND, &err,
                    cases[i].why);
        CHECK_MSG(status == cases[i].status && ROS_PATH_ERROR_CODE(status) == cases[i].code,
                  "(%.2f, %.2f): status %d (%s)", cases[i].x, cases[i].y, status,
                  sp_nav_status_name(status));
        CHECK(p.n == 0 && p.waypoints == NULL);
    }
    CHECK(ROS_PATH_ERROR_CODE(SP_NAV_OK) == 0);
    /* starting: never on a wall, in unknown space or off the map; close to a wall is fine */
    sp_error err = {0};
    CHECK_FAILS(ros_sim_check_start(&cm, 4.0, 2.0, &err), SP_E_ARG, &err, "occupied");
    CHECK_FAILS(ros_sim_check_start(&cm, 7.0, 1.0, &err), SP_E_ARG, &err, "unknown");
    CHECK_FAILS(ros_sim_check_start(&cm, -3.0, 1.0, &err), SP_E_ARG, &err, "outside");
    CHECK_OK(ros_sim_check_start(&cm, 3.86, 2.0, &err), &err);
    CHECK(ros_sim_collides(&cm, 4.0, 2.0) && ros_sim_collides(&cm, -1, 0) && !ros_sim_collides(&cm, 1, 1));
    CHECK(!ros_sim_collides(&cm, 7.0, 1.0)); /* unknown is not an obstacle to the body */
    sp_costmap_free(&cm);
}

static ros_drive_limits limits(void)
{
    ros_drive_limits l = {0.5, 0.5, 1.5, 3.0, 0.1, 0.15, 0.35};
    return l;
}

static void test_drive_reaches_goal_within_limits(void)
{
    sp_costmap cm;
    if (room_costmap(&cm, 0.2)) return;
    sp_error err = {0};
    double start[3] = {1.0, 1.0, -2.0};
    sp_ros_pose goal = {6.0, 5.0, 0, M_PI / 2};
    sp_path p;
    int status;
    double *xy = NULL;
    size_t n = 0;
    CHECK_OK(ros_sim_plan(&cm, start, &goal, &p, &status, &err), &err);
    CHECK(ros_sim_drive_path(&p, &goal, &xy, &n) == 0);
    sp_path_free(&p);
    ros_drive d;
    ros_drive_init(&d, 1.0, 1.0, -2.0);
    ros_drive_follow(&d, xy, n, M_PI / 2);
    ros_drive_limits l = limits();
    double dt = 0.05, v0 = 0, w0 = 0, t = 0;
    int collided = 0;
    ros_drive_event ev = ROS_DRIVE_MOVING;
    while (ev == ROS_DRIVE_MOVING && t < 120) {
        ev = ros_drive_step(&d, &l, dt);
        t += dt;
        CHECK(fabs(d.v) <= l.max_speed + 1e-9 && fabs(d.w) <= l.max_yaw_rate + 1e-9);
        CHECK(fabs(d.v - v0) <= l.max_accel * dt + 1e-9);
        CHECK(fabs(d.w - w0) <= l.max_yaw_accel * dt + 1e-9);
        collided += ros_sim_collides(&cm, d.x, d.y);
        v0 = d.v, w0 = d.w;
    }
    CHECK_MSG(ev == ROS_DRIVE_ARRIVED, "event %d after %.1f s at (%.2f, %.2f)", ev, t, d.x, d.y);
    CHECK(collided == 0);
    CHECK_MSG(hypot(d.x - 6, d.y - 5) <= l.goal_tolerance_m + 0.02, "ended at (%.3f, %.3f)", d.x, d.y);
    CHECK(fabs(remainder(d.yaw - M_PI / 2, 2 * M_PI)) <= l.yaw_tolerance_rad);
    /* About 7.4 m at 0.5 m/s with the turns: well under a minute. */
    CHECK_MSG(t > 14 && t < 40, "took %.1f s", t);
    ros_drive_free(&d);
    sp_costmap_free(&cm);
}

static void test_drive_stop(void)
{
    double *xy = malloc(4 * sizeof *xy);
    xy[0] = 0, xy[1] = 0, xy[2] = 10, xy[3] = 0;
    ros_drive d;
    ros_drive_init(&d, 0, 0, 0);
    ros_drive_follow(&d, xy, 2, 0);
    ros_drive_limits l = limits();
    for (int i = 0; i < 60; i++) ros_drive_step(&d, &l, 0.05); /* 3 s: at full speed */
    CHECK_NEAR(d.v, 0.5, 1e-9);
    ros_drive_stop(&d);
    double x_stop = d.x;
    ros_drive_event ev = ROS_DRIVE_MOVING;
    int steps = 0;
    while (ev == ROS_DRIVE_MOVING && steps++ < 200) ev = ros_drive_step(&d, &l, 0.05);
    CHECK(ev == ROS_DRIVE_STOPPED);
    /* Braking from 0.5 m/s at 0.5 m/s^2 takes 1 s and 0.25 m. */
    CHECK_MSG(steps <= 22 && d.x - x_stop < 0.3, "%d steps, %.3f m", steps, d.x - x_stop);
    CHECK(d.v == 0 && d.w == 0 && d.path == NULL);
    CHECK(ros_drive_step(&d, &l, 0.05) == ROS_DRIVE_IDLE);
}

static void test_names(void)
{
    char out[256];
    sp_error err = {0};
    sp_ros_options o;
    sp_ros_options_default(&o);
    CHECK_OK(sp_ros_dds_topic_name(&o, "odom", 't', out, sizeof out, &err), &err);
    CHECK(!strcmp(out, "rt/odom"));
    o.ns = "/robot1";
    CHECK_OK(sp_ros_dds_topic_name(&o, "navigate_to_pose/_action/send_goal", 'q', out, sizeof out,
                                   &err), &err);
    CHECK(!strcmp(out, "rq/robot1/navigate_to_pose/_action/send_goalRequest"));
    CHECK_OK(sp_ros_dds_topic_name(&o, "/map", 't', out, sizeof out, &err), &err);
    CHECK(!strcmp(out, "rt/map"));
    CHECK_FAILS(sp_ros_dds_topic_name(&o, "a//b", 't', out, sizeof out, &err), -1, &err, "empty token");
    CHECK_FAILS(sp_ros_dds_topic_name(&o, "2d", 't', out, sizeof out, &err), -1, &err, "digit");
    CHECK_FAILS(sp_ros_dds_topic_name(&o, "o-dom", 't', out, sizeof out, &err), -1, &err, "'-'");
    o.ns = "robot1";
    CHECK_FAILS(sp_ros_dds_topic_name(&o, "odom", 't', out, sizeof out, &err), -1, &err, "namespace");
    sp_ros_distro d;
    CHECK_OK(sp_ros_distro_parse("jazzy", &d, &err), &err);
    CHECK(d == SP_ROS_DISTRO_JAZZY);
    CHECK_FAILS(sp_ros_distro_parse("iron", &d, &err), SP_E_ARG, &err, "iron");
}

int main(void)
{
    RUN(test_room_map);
    RUN(test_costmap_sources);
    RUN(test_plan_through_door);
    RUN(test_refusals);
    RUN(test_drive_reaches_goal_within_limits);
    RUN(test_drive_stop);
    RUN(test_names);
    return TEST_EXIT();
}
