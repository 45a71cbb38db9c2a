/* `semsplat sim-robot --model DIR` over DDS: the robot builds its costmap from a model folder's
 * splat and training cameras (the nav test room: walls, a pillar, a low table, made of flat
 * Gaussians, written as splat.ply + a COLMAP capture) in the folder's world frame (frame.json
 * moves it by (10, -5) m). Checked from outside, on the loopback interface with a random domain:
 * the map it publishes (transient local) is, cell for cell, the costmap this test builds from the
 * same folder with sp_costmap_build_model; a NavigateToPose goal behind the pillar succeeds with
 * feedback and the odometry ends within 0.3 m of it; goals inside the pillar and the table are
 * rejected; ComputePathToPose goes round the pillar keeping the robot's radius. Built only with
 * Cyclone DDS. */
#include <math.h>

#include "../../nav/nav_scene.h" /* tests/nav/ (src/nav/ has a private header of that name) */
#include "ros/cyclonedds/bridge_internal.h"
#include "ros_test.h"
#include "semsplat/device.h"
#include "semsplat/nav.h"
#include "test.h"

/* world = model + (DX, DY): the robot must plan in the world frame of frame.json */
#define DX 10.0
#define DY -5.0
#define RADIUS 0.2

static int domain;
static char ns[64], dir[1024], model[1200];

static double wx(double x) { return x + NS_OFFX + DX; }
static double wy(double y) { return y + NS_OFFY + DY; }

static int write_frame(void)
{
    sp_frame f;
    sp_frame_init(&f, "align");
    f.world_from_model[3] = DX;
    f.world_from_model[7] = DY;
    snprintf(f.note, sizeof f.note, "test: the room moved by (%g, %g) m", DX, DY);
    char path[1300];
    sp_error err = {0};
    snprintf(path, sizeof path, "%s/frame.json", model);
    CHECK_OK(sp_frame_write(path, &f, &err), &err);
    return err.code;
}

static int reference_costmap(sp_costmap *cm)
{
    sp_device *dev = NULL;
    sp_error err = {0};
    sp_costmap_opts o = sp_costmap_opts_default();
    o.robot_radius_m = RADIUS;
    double t0 = sp_time_now();
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CPU, 2, &err), &err);
    if (dev) CHECK_OK(sp_costmap_build_model(cm, model, &o, dev, NULL, &err), &err);
    sp_device_free(dev);
    fprintf(stderr, "  reference costmap %d x %d in %.1f s\n", cm->nx, cm->ny, sp_time_now() - t0);
    return err.code;
}

typedef struct {
    uint8_t *b;
    size_t n;
} raw_copy;

static void keep(void *ctx, const uint8_t *bytes, size_t n, const dds_sample_info_t *info)
{
    raw_copy *r = ctx;
    (void)info;
    free(r->b);
    r->b = malloc(n);
    if (r->b) memcpy(r->b, bytes, n), r->n = n;
}

/* The robot's map as a late subscriber (RViz started after the robot) receives it. */
static void check_map(const sp_costmap *ref)
{
    sp_ros_options o;
    sp_ros_options_default(&o);
    o.domain_id = domain, o.ns = ns, o.loopback_only = 1, o.distro = SP_ROS_DISTRO_JAZZY;
    o.node_name = "tap";
    ros_node *tap = NULL;
    sp_error err = {0};
    CHECK_OK(ros_node_create(&tap, &o, &err), &err);
    if (!tap) return;
    char topic[300];
    snprintf(topic, sizeof topic, "rt%s/map", ns);
    dds_entity_t rd = ros_reader(tap, RT_OCCUPANCY_GRID, topic, ROS_QOS_LATCHED, NULL, &err);
    raw_copy r = {NULL, 0};
    for (double until = sp_time_now() + 30; rd > 0 && !r.b && sp_time_now() < until;) {
        ros_take_raw(rd, keep, &r, 1);
        if (!r.b) usleep(20000);
    }
    CHECK_MSG(r.b, "no map on %s within 30 s", topic);
    sp_ros_grid g = {0};
    if (r.b) CHECK_OK(sp_ros_decode_occupancy_grid(r.b, r.n, &g, &err), &err);
    if (g.cells) {
        CHECK(g.width == ref->nx && g.height == ref->ny && !strcmp(g.frame_id, "map"));
        CHECK_NEAR(g.resolution_m, ref->res, 1e-6);
        CHECK_NEAR(g.origin_x, ref->origin[0], 1e-5);
        CHECK_NEAR(g.origin_y, ref->origin[1], 1e-5);
        CHECK(g.origin_x > DX - 2 && g.origin_y > DY - 2); /* in the world frame */
        int8_t *want = malloc((size_t)ref->nx * ref->ny);
        long diff = 0, n = (long)ref->nx * ref->ny, occupied = 0, free_cells = 0;
        if (want && g.width == ref->nx && g.height == ref->ny) {
            sp_costmap_to_occupancy_grid(ref, 0, want);
            for (long i = 0; i < n; i++) {
                diff += g.cells[i] != want[i];
                occupied += g.cells[i] == 100, free_cells += g.cells[i] == 0;
            }
        }
        CHECK_MSG(diff == 0 && occupied > 0 && free_cells > 0,
                  "%ld of %ld cells differ from sp_costmap_build_model (%ld occupied, %ld free)",
                  diff, n, occupied, free_cells);
        fprintf(stderr, "  map on the wire: %d x %d, %ld occupied, %ld free, %ld unknown\n",
                g.width, g.height, occupied, free_cells, n - occupied - free_cells);
        free(want);
    }
    sp_ros_grid_free(&g);
    free(r.b);
    ros_node_free(tap);
}

static void on_feedback(void *user, const sp_ros_goal_status *st)
{
    double *last = user;
    *last = st->feedback.distance_remaining_m;
}

static void goal_behind_pillar(sp_ros_bridge *b)
{
    sp_ros_pose goal = {wx(4.6), wy(2.6), 0, 0};
    sp_ros_goal *g = NULL;
    sp_ros_goal_status st;
    sp_error err = {0};
    double last = -1;
    CHECK_OK(sp_ros_navigate_to(b, &goal, NULL, &g, &err), &err);
    if (!g) return;
    CHECK_OK(sp_ros_goal_wait(g, 60.0, &st, on_feedback, &last, &err), &err);
    CHECK_MSG(st.state == SP_ROS_GOAL_SUCCEEDED, "ended %s (%s)", sp_ros_goal_state_name(st.state),
              st.error_msg);
    CHECK_MSG(st.feedback_count >= 3 && last >= 0 && last < 0.3, "%ld feedback, last %.2f m to go",
              st.feedback_count, last);
    sp_ros_odom o;
    double miss = INFINITY;
    for (double until = sp_time_now() + 10; sp_time_now() < until; usleep(50000))
        if (!sp_ros_odom_wait(b, 2.0, &o, &err) && fabs(o.vx) < 1e-3 && fabs(o.wz) < 1e-3) {
            miss = hypot(o.pose.x - goal.x, o.pose.y - goal.y);
            break;
        }
    CHECK_MSG(miss <= 0.3, "odometry ends %.3f m from the goal", miss);
    fprintf(stderr, "  goal behind the pillar: %ld feedback, ended %.3f m from it\n",
            st.feedback_count, miss);
    sp_ros_goal_free(g);
}

static void goal_rejected(sp_ros_bridge *b, double x, double y, const char *what)
{
    sp_error err = {0};
    sp_ros_goal_state st = test_goal_answer(b, wx(x), wy(y), &err);
    CHECK_MSG(st == SP_ROS_GOAL_REJECTED, "a goal %s was %s %s", what, sp_ros_goal_state_name(st), err.msg);
}

/* Distance from (x, y) (model frame) to the pillar's footprint. */
static double pillar_distance(double x, double y)
{
    double dx = fmax(fmax(ns_pillar.lo[0] + NS_OFFX - x, x - ns_pillar.hi[0] - NS_OFFX), 0);
    double dy = fmax(fmax(ns_pillar.lo[1] + NS_OFFY - y, y - ns_pillar.hi[1] - NS_OFFY), 0);
    return hypot(dx, dy);
}

static void path_round_pillar(sp_ros_bridge *b)
{
    sp_ros_pose start = {wx(1.5), wy(2.0), 0, 0}, goal = {wx(4.2), wy(2.0), 0, 0};
    sp_ros_path p = {0};
    sp_error err = {0};
    CHECK_OK(sp_ros_compute_path(b, &start, &goal, NULL, 20.0, &p, NULL, &err), &err);
    double closest = INFINITY, length = 0;
    for (size_t i = 0; i < p.n; i++) {
        closest = fmin(closest, pillar_distance(p.poses[i].x - DX, p.poses[i].y - DY));
        if (i) length += hypot(p.poses[i].x - p.poses[i - 1].x, p.poses[i].y - p.poses[i - 1].y);
    }
    /* waypoints every 0.25 m at most, so the poses sample the whole path */
    CHECK_MSG(p.n >= 2 && closest >= RADIUS - 0.05 && length > 2.7 + 0.2,
              "%zu poses, %.2f m long, %.3f m from the pillar", p.n, length, closest);
    fprintf(stderr, "  path round the pillar: %.2f m, %.2f m from it at the closest\n", length,
            closest);
    sp_ros_path_free(&p);
}

static sp_ros_bridge *g_bridge;

static void test_model_robot(void)
{
    sp_error err = {0};
    CHECK_OK(ns_write_model(dir, 1, 160, 120, model, sizeof model, &err), &err);
    sp_costmap ref = {0};
    if (err.code || write_frame() || reference_costmap(&ref)) return;
    char ready[1300], log[1300], dom[16], start[64];
    snprintf(ready, sizeof ready, "%s/ready", dir);
    snprintf(log, sizeof log, "%s/robot.log", dir);
    snprintf(dom, sizeof dom, "%d", domain);
    snprintf(start, sizeof start, "%g,%g,0", wx(1.0), wy(2.0));
    char *argv[] = {SP_BUILD_DIR "/semsplat", "sim-robot", "--model", model, "--start", start,
                    "--device", "cpu", "--threads", "2", "--loopback", "--domain", dom,
                    "--namespace", ns, "--ros-distro", "jazzy", "--max-speed", "1.0",
                    "--time-scale", "2", "--duration", "240", "--ready-file", ready, NULL};
    pid_t robot = test_spawn(argv, log);
    /* the robot builds the costmap before it is ready: generous for a loaded 2-core machine */
    int up = test_wait_file(ready, 180.0) == 0;
    CHECK_MSG(up, "sim-robot --model did not get ready in 180 s");
    if (up) {
        check_map(&ref);
        goal_behind_pillar(g_bridge);
        goal_rejected(g_bridge, 3.0, 2.0, "inside the pillar");
        goal_rejected(g_bridge, 4.8, 0.9, "on the table");
        goal_rejected(g_bridge, 8.0, 2.0, "outside the room");
        path_round_pillar(g_bridge);
    }
    if (t_case_failed) test_print_file(log);
    test_stop(robot);
    sp_costmap_free(&ref);
}

int main(void)
{
    sp_error err = {0};
    sp_ros_options o;
    sp_ros_options_default(&o);
    o.loopback_only = 1;
    domain = test_random_domain(ns, sizeof ns);
    o.domain_id = domain, o.ns = ns, o.server_timeout_s = 30, o.node_name = "semsplat_test_client";
    if (sp_ros_bridge_create(&g_bridge, &o, &err) == SP_E_UNSUPPORTED) TEST_SKIP(err.msg);
    CHECK_OK(err.code, &err);
    if (!g_bridge) return TEST_EXIT();
    snprintf(dir, sizeof dir, "%s", test_tmpdir("ros_sim_model"));
    fprintf(stderr, "domain %d, namespace %s\n", domain, ns);
    RUN(test_model_robot);
    sp_ros_bridge_free(g_bridge);
    return TEST_EXIT();
}
