/* The planner on hand-drawn maps: paths never enter a lethal, inscribed or unknown cell, end at
 * the goal (point, pose, footprint), are no longer than needed; k distinct alternatives around
 * two obstacles obey the share and length rules, and fewer are returned (with a note) when the
 * map allows fewer; the share and clearance measures; every failure names its reason; the
 * default start (the camera in the largest free region). */
#include <stdio.h>

#include "nav/nav_internal.h"
#include "semsplat/nav.h"
#include "test.h"

/* One character per cell, first row = top (largest y): '#' occupied, '.' free, '?' unknown. */
static void ascii_map(sp_costmap *cm, const char *const *rows, int ny, float res, float radius)
{
    sp_error err = {0};
    memset(cm, 0, sizeof *cm);
    int nx = (int)strlen(rows[0]);
    cm->nx = nx, cm->ny = ny, cm->res = res;
    cm->origin[0] = -1.0f, cm->origin[1] = 2.0f;
    size_t n = (size_t)nx * ny;
    cm->occ = malloc(n), cm->cost = malloc(n), cm->dist = malloc(n * sizeof(float));
    for (int y = 0; y < ny; y++)
        for (int x = 0; x < nx; x++) {
            char c = rows[ny - 1 - y][x];
            cm->occ[(size_t)y * nx + x] = c == '#' ? SP_CELL_OCCUPIED : c == '?' ? SP_CELL_UNKNOWN : SP_CELL_FREE;
        }
    sp_costmap_opts o = sp_costmap_opts_default();
    o.resolution_m = res;
    o.robot_radius_m = radius;
    o.inflation_radius_m = 4 * radius;
    CHECK_OK(sp_costmap_inflate(cm, &o, &err), &err);
}

/* Two blocks in an open hall: three ways from left to right (below, between, above). */
static const char *const hall[] = {
    "########################################",
    "#......................................#",
    "#......................................#",
    "#......................................#",
    "#.............######...................#",
    "#.............######...................#",
    "#.............######...................#",
    "#......................................#",
    "#......................................#",
    "#......................................#",
    "#.............######...................#",
    "#.............######...................#",
    "#.............######...................#",
    "#......................................#",
    "#......................................#",
    "#......................................#",
    "########################################",
};
#define HALL_NY 17

typedef struct enter_ctx {
    const sp_costmap *cm;
    long start;
    int bad;
} enter_ctx;

static int enter_cell(void *v, long cell, float t0, float t1)
{
    enter_ctx *c = v;
    (void)t0, (void)t1;
    if (cell != c->start && !(c->cm->occ[cell] == SP_CELL_FREE && c->cm->cost[cell] < SP_COST_INSCRIBED)) c->bad++;
    return 0;
}

/* Number of non-traversable cells (other than the start's) the waypoint polyline touches. */
static int bad_cells(const sp_costmap *cm, const sp_path *p)
{
    int sx, sy;
    sp_costmap_cell(cm, p->waypoints[0], p->waypoints[1], &sx, &sy);
    enter_ctx c = {cm, nav_idx(cm, sx, sy), 0};
    for (int k = 0; k + 1 < p->n; k++) {
        float a[2] = {p->waypoints[4 * k], p->waypoints[4 * k + 1]};
        float b[2] = {p->waypoints[4 * k + 4], p->waypoints[4 * k + 5]};
        nav_traverse(cm, a, b, enter_cell, &c);
    }
    return c.bad;
}

static void test_point_and_pose(void)
{
    sp_error err = {0};
    sp_costmap cm;
    ascii_map(&cm, hall, HALL_NY, 0.1f, 0.1f);
    float start[3] = {-0.5f, 2.9f, 0.0f}; /* bottom-left area */
    sp_nav_goal g = sp_nav_goal_point(2.5f, 3.3f);
    sp_path p;
    CHECK_OK(sp_plan_path(&cm, start, &g, NULL, &p, &err), &err);
    CHECK(p.status == SP_NAV_OK);
    CHECK(bad_cells(&cm, &p) == 0);
    const float *e = p.waypoints + 4 * (p.n - 1);
    CHECK_NEAR(e[0], 2.5f, 1e-5);
    CHECK_NEAR(e[1], 3.3f, 1e-5);
    CHECK_NEAR(p.waypoints[0], start[0], 1e-5);
    float straight = hypotf(2.5f - start[0], 3.3f - start[1]);
    CHECK(p.length_m >= straight - 1e-4f && p.length_m < 1.15f * straight);
    for (int k = 0; k + 1 < p.n; k++) {
        float l = hypotf(p.waypoints[4 * k + 4] - p.waypoints[4 * k], p.waypoints[4 * k + 5] - p.waypoints[4 * k + 1]);
        CHECK(l <= 0.25f + 1e-4f);
    }
    CHECK(p.n_corners >= 2 && p.n_corners < 8); /* any-angle: a few corners, not a staircase */
    sp_path_free(&p);
    g = sp_nav_goal_pose(2.5f, 3.3f, 1.25f);
    CHECK_OK(sp_plan_path(&cm, start, &g, NULL, &p, &err), &err);
    CHECK_NEAR(p.waypoints[4 * (p.n - 1) + 3], 1.25f, 1e-6);
    CHECK_NEAR(p.waypoints[4 * (p.n - 1) + 2], cm.floor_z, 1e-6);
    sp_path_free(&p);
    sp_costmap_free(&cm);
}

static void test_region_goal(void)
{
    sp_error err = {0};
    sp_costmap cm;
    ascii_map(&cm, hall, HALL_NY, 0.1f, 0.1f);
    float start[3] = {-0.5f, 2.9f, 0.0f};
    /* the upper block: x cells 14..19, y rows 10..12 from the bottom */
    float lo[2] = {-1.0f + 1.4f, 2.0f + 1.0f}, hi[2] = {-1.0f + 2.0f, 2.0f + 1.3f};
    sp_nav_goal g = sp_nav_goal_box(lo, hi, 0.4f);
    sp_path p;
    CHECK_OK(sp_plan_path(&cm, start, &g, NULL, &p, &err), &err);
    const float *e = p.waypoints + 4 * (p.n - 1);
    CHECK(nav_box_dist(&g.boxes[0], e) <= 0.4f + 1e-4f);
    float q[2];
    nav_box_nearest(&g.boxes[0], e, q);
    float yaw = atan2f(q[1] - e[1], q[0] - e[0]);
    CHECK(fabsf(remainderf(e[3] - yaw, 2 * (float)M_PI)) < 1e-4f);
    CHECK(bad_cells(&cm, &p) == 0);
    sp_path_free(&p);
    sp_costmap_free(&cm);
}

static void test_k_distinct(void)
{
    sp_error err = {0};
    sp_costmap cm;
    ascii_map(&cm, hall, HALL_NY, 0.1f, 0.1f);
    float start[3] = {-0.5f, 2.0f + 0.85f, 0.0f}; /* left, middle row */
    sp_nav_goal g = sp_nav_goal_point(2.5f, 2.85f);
    sp_path_set set;
    sp_planner_opts o = sp_planner_opts_default();
    CHECK_OK(sp_plan_k(&cm, start, &g, 3, &o, &set, &err), &err);
    fprintf(stderr, "hall: %d paths in %d runs, %.1f ms; note '%s'\n", set.n, set.rounds, set.ms, set.note);
    CHECK(set.n == 3);
    for (int i = 0; i < set.n; i++) {
        const sp_path *p = &set.paths[i];
        fprintf(stderr, "  path %d: %.2f m, %d corners, share %.2f\n", i, p->length_m, p->n_corners, set.share[i]);
        CHECK(bad_cells(&cm, p) == 0);
        CHECK(p->length_m <= o.max_length_ratio * set.paths[0].length_m + 1e-4f);
        for (int j = 0; j < i; j++) {
            const sp_path *q = &set.paths[j];
            CHECK(sp_path_share(p->corners, p->n_corners, 2, q->corners, q->n_corners, 2, o.share_radius_m) <= o.max_share + 1e-6f);
        }
    }
    sp_path_set_free(&set);
    /* a corridor allows one route: fewer, with the reason */
    static const char *const corridor[] = {
        "##########################",
        "#........................#",
        "#........................#",
        "#........................#",
        "##########################",
    };
    sp_costmap c2;
    ascii_map(&c2, corridor, 5, 0.1f, 0.05f);
    float s2[3] = {-0.8f, 2.25f, 0};
    g = sp_nav_goal_point(1.3f, 2.25f);
    CHECK_OK(sp_plan_k(&c2, s2, &g, 3, &o, &set, &err), &err);
    CHECK(set.n == 1);
    CHECK(strstr(set.note, "1 of 3") != NULL);
    fprintf(stderr, "corridor: %s\n", set.note);
    sp_path_set_free(&set);
    sp_costmap_free(&c2);
    sp_costmap_free(&cm);
}

static void test_share_and_clearance(void)
{
    float a[4] = {0, 0, 4, 0}, b[4] = {0, 1, 4, 1}, c[4] = {2, 0, 6, 0};
    CHECK_NEAR(sp_path_share(a, 2, 2, a, 2, 2, 0.1f), 1.0, 1e-6);
    CHECK_NEAR(sp_path_share(a, 2, 2, b, 2, 2, 0.4f), 0.0, 1e-6);
    CHECK_NEAR(sp_path_share(a, 2, 2, c, 2, 2, 0.01f), 0.5, 0.02);
    sp_error err = {0};
    static const char *const corridor[] = {
        "##############################",
        "#............................#",
        "#............................#",
        "#............................#",
        "#............................#",
        "#............................#",
        "##############################",
    };
    sp_costmap cm;
    ascii_map(&cm, corridor, 7, 0.1f, 0.05f);
    float s[3] = {-0.45f, 2.35f, 0};
    sp_nav_goal g = sp_nav_goal_point(1.25f, 2.35f);
    sp_path p;
    CHECK_OK(sp_plan_path(&cm, s, &g, NULL, &p, &err), &err);
    float mn, mean;
    sp_path_clearance(&cm, &p, &mn, &mean);
    /* centre line of a 5-cell corridor: 3 cells to the wall cells' centres, 2.5 to their edges */
    CHECK_NEAR(mn, 0.25f, 0.051f);
    CHECK_NEAR(mean, 0.25f, 0.051f);
    sp_path_free(&p);
    sp_costmap_free(&cm);
}

static void test_failures(void)
{
    sp_error err = {0};
    sp_costmap cm;
    static const char *const rooms[] = {
        "##############",
        "#.....#......#",
        "#.....#......#",
        "#.....#..??..#",
        "#.....#......#",
        "##############",
    };
    ascii_map(&cm, rooms, 6, 0.1f, 0.0f);
    float s[3] = {-0.7f, 2.25f, 0};
    sp_path p;
    sp_nav_goal g = sp_nav_goal_point(-0.2f, 2.25f); /* the right room: walled off */
    CHECK_FAILS(sp_plan_path(&cm, s, &g, NULL, &p, &err), SP_E_NOTFOUND, &err, "no path");
    CHECK(p.status == SP_NAV_NO_VALID_PATH);
    char why[256];
    float s2[2] = {s[0], s[1]}, g2[2] = {-0.2f, 2.25f};
    CHECK(sp_costmap_check_goal(&cm, s2, g2, why, sizeof why) == SP_NAV_NO_VALID_PATH);
    CHECK(strstr(why, "not reachable") != NULL);
    g = sp_nav_goal_point(-0.35f, 2.25f); /* on the dividing wall */
    CHECK_FAILS(sp_plan_path(&cm, s, &g, NULL, &p, &err), SP_E_NOTFOUND, &err, "occupied");
    CHECK(p.status == SP_NAV_GOAL_OCCUPIED);
    g = sp_nav_goal_point(0.0f, 2.25f); /* unknown */
    CHECK_FAILS(sp_plan_path(&cm, s, &g, NULL, &p, &err), SP_E_NOTFOUND, &err, "unknown");
    g = sp_nav_goal_point(9.0f, 2.25f);
    CHECK_FAILS(sp_plan_path(&cm, s, &g, NULL, &p, &err), SP_E_NOTFOUND, &err, "outside");
    CHECK(p.status == SP_NAV_GOAL_OUTSIDE_MAP);
    float out[3] = {-5.0f, 0, 0};
    g = sp_nav_goal_point(-0.6f, 2.25f);
    CHECK_FAILS(sp_plan_path(&cm, out, &g, NULL, &p, &err), SP_E_NOTFOUND, &err, "start");
    CHECK(p.status == SP_NAV_START_OUTSIDE_MAP);
    float nan_start[3] = {NAN, 0, 0};
    CHECK_FAILS(sp_plan_path(&cm, nan_start, &g, NULL, &p, &err), SP_E_ARG, &err, "finite");
    sp_nav_goal bad = sp_nav_goal_box((float[2]){1, 1}, (float[2]){0, 0}, 0.3f);
    CHECK_FAILS(sp_plan_path(&cm, s, &bad, NULL, &p, &err), SP_E_ARG, &err, "footprint");
    sp_planner_opts o = sp_planner_opts_default();
    o.max_share = 2;
    CHECK_FAILS(sp_plan_path(&cm, s, &g, &o, &p, &err), SP_E_ARG, &err, "max_share");
    sp_path_set set;
    CHECK_FAILS(sp_plan_k(&cm, s, &g, 0, NULL, &set, &err), SP_E_ARG, &err, "k = 0");
    sp_costmap_free(&cm);
}

/* A small island (left) and a large room (right), split by a wall. */
static const char *const two_rooms[] = {
    "##############################",
    "#......#.....................#",
    "#......#.....................#",
    "#......#.....................#",
    "#......#.....................#",
    "#......#.....................#",
    "#......#.....................#",
    "##############################",
};

static sp_camera camera_at(float x, float y, float look_x, float look_y)
{
    sp_camera c;
    memset(&c, 0, sizeof c);
    sp_camera_intrinsics_fov(&c, 64, 48, 1.0f);
    sp_camera_look_at(&c, (sp_vec3){x, y, 1.2f}, (sp_vec3){look_x, look_y, 1.2f}, (sp_vec3){0, 0, 1});
    return c;
}

/* The default start: the camera standing in the larger free region, with its heading; none when
 * no camera has traversable floor within 2 m. */
static void test_default_start(void)
{
    sp_error err = {0};
    sp_costmap cm;
    ascii_map(&cm, two_rooms, 8, 0.1f, 0.1f);
    /* origin (-1, 2), 10 cm cells: the island is x -0.9..-0.3, the room x -0.2..1.9, y 2.1..2.7 */
    sp_camera cams[3] = {camera_at(-0.6f, 2.4f, -0.6f, 3.4f), camera_at(1.0f, 2.4f, 2.0f, 2.4f),
                         camera_at(9.0f, 9.0f, 9.0f, 10.0f)};
    float st[3];
    CHECK_OK(nav_pick_start(&cm, cams, 3, st, &err), &err);
    fprintf(stderr, "  start (%.2f, %.2f) yaw %.2f\n", st[0], st[1], st[2]);
    CHECK(st[0] > -0.2f && st[0] < 1.9f);
    CHECK_NEAR(st[1], 2.4f, 0.1f);
    CHECK_NEAR(st[2], 0.0f, 1e-3); /* camera 1 looks along +x */
    /* the island's camera alone: its own region */
    CHECK_OK(nav_pick_start(&cm, cams, 1, st, &err), &err);
    CHECK(st[0] < -0.3f);
    CHECK_NEAR(st[2], (float)M_PI_2, 1e-3);
    CHECK_FAILS(nav_pick_start(&cm, cams + 2, 1, st, &err), SP_E_NOTFOUND, &err, "no free floor");
    sp_costmap_free(&cm);
}

int main(void)
{
    RUN(test_point_and_pose);
    RUN(test_region_goal);
    RUN(test_k_distinct);
    RUN(test_share_and_clearance);
    RUN(test_failures);
    RUN(test_default_start);
    return TEST_EXIT();
}
