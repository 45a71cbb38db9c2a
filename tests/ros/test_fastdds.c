/* Interoperation with an independent DDS implementation: a peer built on eProsima Fast DDS with
 * Fast CDR (tests/ros/fastdds_peer.cpp, ROS 2's default middleware) publishes /odom under the
 * ROS 2 names and subscribes to our /semsplat/map and candidate paths. Both directions must
 * decode to the values sent. Loopback only, a random domain and namespace; skips when Fast DDS
 * (libfastrtps-dev) was not found at build time. */
#include <math.h>

#include "ros_test.h"
#include "test.h"

static uint32_t checksum(const int8_t *cells, size_t n)
{
    uint32_t sum = 0;
    for (size_t i = 0; i < n; i++) sum += (uint32_t)(i + 1) * (uint8_t)cells[i];
    return sum;
}

static void check_peer_output(const char *log, const sp_ros_grid *g, const sp_ros_path *paths)
{
    char *text = NULL;
    size_t size;
    sp_error err = {0};
    CHECK_OK(sp_read_file(log, &text, &size, &err), &err);
    if (!text) return;
    int saw_map = 0, saw_path[2] = {0, 0};
    for (char *line = strtok(text, "\n"); line; line = strtok(NULL, "\n")) {
        unsigned w, h, sum;
        double res, ox, oy, oyaw;
        char frame[64];
        size_t n;
        int k;
        double x0, y0, yaw0, x1, y1, yaw1;
        if (sscanf(line, "map %u %u %lf %lf %lf %lf %u %63s %zu", &w, &h, &res, &ox, &oy, &oyaw, &sum,
                   frame, &n) == 9) {
            saw_map = 1;
            CHECK_MSG(w == (unsigned)g->width && h == (unsigned)g->height && n == w * h,
                      "map %ux%u (%zu cells)", w, h, n);
            CHECK_NEAR(res, (float)g->resolution_m, 1e-9);
            CHECK_NEAR(ox, g->origin_x, 1e-9);
            CHECK_NEAR(oy, g->origin_y, 1e-9);
            CHECK_NEAR(oyaw, g->origin_yaw, 1e-9);
            CHECK(sum == checksum(g->cells, (size_t)g->width * g->height));
            CHECK(!strcmp(frame, "map"));
        } else if (sscanf(line, "path %d %zu %lf %lf %lf %lf %lf %lf %63s", &k, &n, &x0, &y0, &yaw0,
                          &x1, &y1, &yaw1, frame) == 9 && k >= 1 && k <= 2) {
            const sp_ros_path *p = &paths[k - 1];
            saw_path[k - 1] = 1;
            CHECK(n == p->n && !strcmp(frame, "map"));
            CHECK_NEAR(x0, p->poses[0].x, 1e-9);
            CHECK_NEAR(y0, p->poses[0].y, 1e-9);
            CHECK_NEAR(yaw0, p->poses[0].yaw, 1e-9);
            CHECK_NEAR(x1, p->poses[p->n - 1].x, 1e-9);
            CHECK_NEAR(y1, p->poses[p->n - 1].y, 1e-9);
            CHECK_NEAR(yaw1, p->poses[p->n - 1].yaw, 1e-9);
        }
    }
    CHECK_MSG(saw_map && saw_path[0] && saw_path[1], "the Fast DDS peer decoded map %d, paths %d %d",
              saw_map, saw_path[0], saw_path[1]);
    free(text);
}

static void test_fastdds_both_ways(void)
{
    char ns[64], dom[16], log[1200];
    int domain = test_random_domain(ns, sizeof ns);
    snprintf(dom, sizeof dom, "%d", domain);
    snprintf(log, sizeof log, "%s/peer.log", test_tmpdir("ros_fastdds"));
    sp_ros_options o;
    sp_ros_options_default(&o);
    o.domain_id = domain;
    o.ns = ns;
    o.distro = SP_ROS_DISTRO_HUMBLE;
    o.loopback_only = 1;
    sp_ros_bridge *b;
    sp_error err = {0};
    int rc = sp_ros_bridge_create(&b, &o, &err);
    if (rc == SP_E_UNSUPPORTED) TEST_SKIP(err.msg);
    CHECK_OK(rc, &err);
    if (rc) return;
    sp_ros_grid g;
    room_grid(&g);
    g.origin_x = -1.0, g.origin_y = 0.5, g.origin_yaw = 0.25;
    sp_ros_pose a[3] = {{1, 1, 0, 0}, {3, 4.5, 0, 0.9}, {6, 2, 0, -1.2}};
    sp_ros_pose c[2] = {{1, 1, 0, 1.5}, {2.5, 5, 0, 3.0}};
    sp_ros_path paths[2] = {{3, a, ""}, {2, c, "map"}};
    CHECK_OK(sp_ros_publish_map(b, &g, &err), &err);
    CHECK_OK(sp_ros_publish_paths(b, paths, 2, &err), &err);
    char *argv[] = {SP_FASTDDS_PEER, "--domain", dom, "--ns", ns, "--seconds", "25", NULL};
    pid_t peer = test_spawn(argv, log);
    sp_ros_odom od;
    int have = 0;
    double until = sp_time_now() + 30;
    int status = -1;
    while (sp_time_now() < until && (status = test_wait_pid(peer, 0.05)) < 0)
        if (sp_ros_odom_latest(b, &od, NULL, &err) == 0) have = 1;
    if (status < 0) test_stop(peer);
    CHECK_MSG(status == 0, "the Fast DDS peer exited with %d", status);
    if (status != 0) test_print_file(log);
    CHECK_MSG(have, "no odometry from the Fast DDS peer: %s", err.msg);
    if (have) {
        double k = (od.pose.x - 1.25) / 0.01;
        CHECK_MSG(fabs(k - rint(k)) < 1e-6 && k >= 0, "x = %.9f", od.pose.x);
        CHECK_NEAR(od.pose.y, -0.5, 1e-12);
        CHECK_NEAR(od.pose.yaw, 0.3, 1e-12);
        CHECK_NEAR(od.vx, 0.2, 1e-12);
        CHECK_NEAR(od.wz, -0.1, 1e-12);
        CHECK(!strcmp(od.frame_id, "odom") && !strcmp(od.child_frame_id, "base_link"));
        CHECK_NEAR(od.stamp_s - floor(od.stamp_s), 0.5, 1e-6);
        fprintf(stderr, "  odometry from Fast DDS: x %.2f (message %d), yaw %.3f\n", od.pose.x,
                (int)rint(k), od.pose.yaw);
    }
    check_peer_output(log, &g, paths);
    sp_ros_grid_free(&g);
    sp_ros_bridge_free(b);
}

int main(void)
{
    if (!SP_FASTDDS_PEER[0]) TEST_SKIP("Fast DDS (libfastrtps-dev) was not found at build time");
    RUN(test_fastdds_both_ways);
    return TEST_EXIT();
}
