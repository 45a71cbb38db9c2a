/* The simulated robot's parts without DDS: the Nav2 map loader, the grid planner (clearance,
 * doors, refusals) and the differential drive (limits respected, goal reached, stop). */
#include <math.h>

#include "ros/ros_internal.h"
#include "ros_test.h"
#include "test.h"

static void test_map_yaml_roundtrip(void)
{
    const char *dir = test_tmpdir("ros_plan_yaml");
    const char *yaml = room_write_yaml(dir);
    sp_ros_grid g, want;
    sp_error err = {0};
    room_grid(&want);
    CHECK_OK(sp_ros_grid_load_yaml(yaml, &g, &err), &err);
    CHECK(g.width == ROOM_W && g.height == ROOM_H);
    CHECK_NEAR(g.resolution_m, 0.05, 1e-12);
    long diff = 0;
    for (int i = 0; i < ROOM_W * ROOM_H; i++) diff += g.cells[i] != want.cells[i];
    CHECK_MSG(diff == 0, "%ld cells differ (unknown must stay unknown, rows flipped)", diff);
    sp_ros_grid_free(&g);
    sp_ros_grid_free(&want);
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (f) fputs(text, f), fclose(f);
}

static void test_map_yaml_errors(void)
{
    const char *dir = test_tmpdir("ros_plan_yaml_bad");
    char path[1024], pgm[1024];
    sp_ros_grid g;
    sp_error err = {0};
    snprintf(path, sizeof path, "%s/a.yaml", dir);
    write_text(path, "image: missing.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n");
    CHECK_FAILS(sp_ros_grid_load_yaml(path, &g, &err), SP_E_IO, &err, "missing.pgm");
    write_text(path, "image: x.pgm\nresolution: -1\norigin: [0, 0, 0]\n");
    CHECK_FAILS(sp_ros_grid_load_yaml(path, &g, &err), SP_E_FORMAT, &err, "resolution");
    write_text(path, "image: x.pgm\nresolution: 0.05\norigin: [0, 0]\n");
    CHECK_FAILS(sp_ros_grid_load_yaml(path, &g, &err), SP_E_FORMAT, &err, "origin");
    snprintf(pgm, sizeof pgm, "%s/x.pgm", dir);
    write_text(pgm, "P5\n4 4\n255\nab"); /* 2 of 16 pixels */
    write_text(path, "image: x.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n");
    CHECK_FAILS(sp_ros_grid_load_yaml(path, &g, &err), SP_E_FORMAT, &err, "pixel bytes");
    write_text(pgm, "P2\n2 1\n255\n0 254\n"); /* ascii, negate: black is free */
    write_text(path, "image: x.pgm\nresolution: 0.1\norigin: [1, 2, 0]\nnegate: 1\n");
    CHECK_OK(sp_ros_grid_load_yaml(path, &g, &err), &err);
    CHECK(g.width == 2 && g.cells[0] == 0 && g.cells[1] == 100);
    sp_ros_grid_free(&g);
}

static double path_length(const double *xy, size_t n)
{
    double L = 0;
    for (size_t i = 1; i < n; i++) L += hypot(xy[2 * i] - xy[2 * i - 2], xy[2 * i + 1] - xy[2 * i - 1]);
    return L;
}

static void test_planner_through_door(void)
{
    sp_ros_grid g;
    room_grid(&g);
    ros_planner *p;
    sp_error err = {0};
    CHECK_OK(ros_planner_create(&p, &g, 0.2, &err), &err);
    double *xy = NULL;
    size_t n = 0;
    CHECK_OK(ros_planner_plan(p, 1.0, 1.0, 6.0, 2.0, &xy, &n, &err), &err);
    if (xy) {
        CHECK(n >= 3);
        CHECK_NEAR(xy[0], 1.0, 1e-12);
        CHECK_NEAR(xy[2 * n - 1], 2.0, 1e-12);
        /* Every point along the path keeps the robot's radius from walls, and it crosses x = 4
         * through the door (4 < y < 5). */
        int crossed = 0;
        for (size_t i = 1; i < n; i++)
            for (int s = 0; s <= 50; s++) {
                double t = s / 50.0;
                double x = xy[2 * i - 2] + t * (xy[2 * i] - xy[2 * i - 2]);
                double y = xy[2 * i - 1] + t * (xy[2 * i + 1] - xy[2 * i - 1]);
                CHECK_MSG(ros_planner_classify(p, x, y) == ROS_CELL_FREE, "(%.2f, %.2f) is %s", x,
                          y, ros_cell_class_name(ros_planner_classify(p, x, y)));
                if (fabs(x - 4.0) < 0.03) crossed = crossed || (y > 4.0 && y < 5.0);
            }
        CHECK(crossed);
        /* Through the door: at least the straight-line distance via the door's centre, and not
         * much more (the soft cost keeps it off walls). */
        double via = hypot(4 - 1, 4.5 - 1) + hypot(6 - 4, 2 - 4.5);
        double L = path_length(xy, n);
        CHECK_MSG(L > via * 0.97 && L < via * 1.25, "length %.2f, via the door %.2f", L, via);
    }
    free(xy);
    ros_planner_free(p);
    sp_ros_grid_free(&g);
}

static void test_planner_refusals(void)
{
    sp_ros_grid g;
    room_grid(&g);
    ros_planner *p;
    sp_error err = {0};
    double *xy = NULL;
    size_t n;
    CHECK_OK(ros_planner_create(&p, &g, 0.2, &err), &err);
    CHECK_FAILS(ros_planner_plan(p, 1, 1, 4.0, 2.0, &xy, &n, &err), SP_E_ARG, &err, "occupied");
    CHECK_FAILS(ros_planner_plan(p, 1, 1, 7.0, 1.0, &xy, &n, &err), SP_E_ARG, &err, "unknown");
    CHECK_FAILS(ros_planner_plan(p, 1, 1, 20, 1, &xy, &n, &err), SP_E_ARG, &err, "outside");
    CHECK_FAILS(ros_planner_plan(p, 1, 1, 3.75, 2.0, &xy, &n, &err), SP_E_ARG, &err, "radius");
    /* Close the door: the other half of the room cannot be reached. */
    for (int r = 0; r < ROOM_H; r++)
        for (int c = 78; c < 82; c++) g.cells[r * ROOM_W + c] = 100;
    ros_planner_free(p);
    CHECK_OK(ros_planner_create(&p, &g, 0.2, &err), &err);
    CHECK_FAILS(ros_planner_plan(p, 1, 1, 6, 2, &xy, &n, &err), SP_E_NOTFOUND, &err, "no path");
    ros_planner_free(p);
    sp_ros_grid bad = g;
    bad.resolution_m = NAN;
    CHECK_FAILS(ros_planner_create(&p, &bad, 0.2, &err), SP_E_ARG, &err, "resolution");
    sp_ros_grid_free(&g);
}

static ros_drive_limits limits(void)
{
    ros_drive_limits l = {0.5, 0.5, 1.5, 3.0, 0.1, 0.15, 0.35};
    return l;
}

static void test_drive_reaches_goal_within_limits(void)
{
    sp_ros_grid g;
    room_grid(&g);
    ros_planner *p;
    sp_error err = {0};
    CHECK_OK(ros_planner_create(&p, &g, 0.2, &err), &err);
    double *xy = NULL;
    size_t n = 0;
    CHECK_OK(ros_planner_plan(p, 1.0, 1.0, 6.0, 5.0, &xy, &n, &err), &err);
    ros_drive d;
    ros_drive_init(&d, 1.0, 1.0, -2.0);
    ros_drive_follow(&d, xy, n, M_PI / 2);
    ros_drive_limits l = limits();
    double dt = 0.05, v0 = 0, w0 = 0, t = 0, min_clear_ok = 1;
    ros_drive_event ev = ROS_DRIVE_MOVING;
    while (ev == ROS_DRIVE_MOVING && t < 120) {
        ev = ros_drive_step(&d, &l, dt);
        t += dt;
        CHECK(fabs(d.v) <= l.max_speed + 1e-9 && fabs(d.w) <= l.max_yaw_rate + 1e-9);
        CHECK(fabs(d.v - v0) <= l.max_accel * dt + 1e-9);
        CHECK(fabs(d.w - w0) <= l.max_yaw_accel * dt + 1e-9);
        if (ros_planner_is_lethal(p, d.x, d.y)) min_clear_ok = 0;
        v0 = d.v, w0 = d.w;
    }
    CHECK_MSG(ev == ROS_DRIVE_ARRIVED, "event %d after %.1f s at (%.2f, %.2f)", ev, t, d.x, d.y);
    CHECK(min_clear_ok);
    CHECK_MSG(hypot(d.x - 6, d.y - 5) <= l.goal_tolerance_m + 0.02, "ended at (%.3f, %.3f)", d.x, d.y);
    CHECK(fabs(remainder(d.yaw - M_PI / 2, 2 * M_PI)) <= l.yaw_tolerance_rad);
    /* About 7.4 m at 0.5 m/s with the turns: well under a minute. */
    CHECK_MSG(t > 14 && t < 40, "took %.1f s", t);
    ros_drive_free(&d);
    ros_planner_free(p);
    sp_ros_grid_free(&g);
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
    RUN(test_map_yaml_roundtrip);
    RUN(test_map_yaml_errors);
    RUN(test_planner_through_door);
    RUN(test_planner_refusals);
    RUN(test_drive_reaches_goal_within_limits);
    RUN(test_drive_stop);
    RUN(test_names);
    return TEST_EXIT();
}
