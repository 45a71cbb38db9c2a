/* The wire decoders: reference samples written out by hand from the layouts (independent of our
 * encoder), round trips through the encoder the bridge uses, big-endian samples, and malformed
 * input of every kind (each truncation, random corruption, lying counts, strings without NUL,
 * foreign encapsulations, NaN poses): always a clean error naming the field, never a crash. */
#include <math.h>

#include "ros/ros_internal.h"
#include "ros_test.h"
#include "test.h"

typedef struct {
    uint8_t b[4096];
    size_t n;
} buf;

static void put(buf *w, const void *p, size_t n)
{
    memcpy(w->b + w->n, p, n);
    w->n += n;
}
static void align(buf *w, size_t a)
{
    while ((w->n - 4) % a) w->b[w->n++] = 0;
}
static void u8(buf *w, uint8_t v) { put(w, &v, 1); }
static void u32(buf *w, uint32_t v) { align(w, 4), put(w, &v, 4); }
static void u64(buf *w, uint64_t v) { align(w, 8), put(w, &v, 8); }
static void f64(buf *w, double v) { align(w, 8), put(w, &v, 8); }
static void str(buf *w, const char *s) { u32(w, (uint32_t)strlen(s) + 1), put(w, s, strlen(s) + 1); }
static void le_header(buf *w) { w->n = 0, put(w, "\x00\x01\x00\x00", 4); }
static void uuid(buf *w) { for (int i = 1; i <= 16; i++) u8(w, (uint8_t)i); }
static void pose(buf *w, double x, double y, double qz, double qw)
{
    f64(w, x), f64(w, y), f64(w, 0), f64(w, 0), f64(w, 0), f64(w, qz), f64(w, qw);
}

/* ros2-wire.md 2.8: the NavigateToPose SendGoal request with the rmw_cyclonedds header. */
static void ref_goal_request(buf *w)
{
    le_header(w);
    u64(w, 0x1122334455667788ull), u64(w, 1);
    uuid(w);
    u32(w, 10), u32(w, 500), str(w, "map");
    pose(w, 1, 2, 0, 1);
    str(w, "");
}

static void test_reference_goal_request(void)
{
    buf w;
    ref_goal_request(&w);
    CHECK(w.n == 113); /* as the reference says */
    sp_ros_goal_request r;
    sp_error err = {0};
    CHECK_OK(sp_ros_decode_nav_goal_request(w.b, w.n, &r, &err), &err);
    CHECK(r.header.guid == 0x1122334455667788ull && r.header.seq == 1);
    CHECK(r.goal_id[0] == 1 && r.goal_id[15] == 16);
    CHECK(!strcmp(r.frame_id, "map") && !strcmp(r.behavior_tree, ""));
    CHECK(r.pose.x == 1 && r.pose.y == 2 && r.pose.yaw == 0);
}

static void test_reference_status_and_results(void)
{
    buf w;
    sp_error err = {0};
    /* GoalStatusArray with one EXECUTING goal, stamp {10, 600}. */
    le_header(&w);
    u32(&w, 1), uuid(&w), u32(&w, 10), u32(&w, 600), u8(&w, 2);
    sp_ros_status_array a;
    CHECK_OK(sp_ros_decode_goal_status_array(w.b, w.n, &a, &err), &err);
    CHECK(a.n == 1 && a.entries[0].status == 2 && fabs(a.entries[0].stamp_s - 10.0000006) < 1e-9);
    sp_ros_status_array_free(&a);
    /* GetResult responses: Humble {4, Empty}, Jazzy {4, 0, ""}. */
    sp_ros_result_response r;
    le_header(&w);
    u64(&w, 7), u64(&w, 3), u8(&w, 4), u8(&w, 0);
    CHECK_OK(sp_ros_decode_nav_result_response(w.b, w.n, SP_ROS_DISTRO_HUMBLE, &r, &err), &err);
    CHECK(r.status == 4 && r.header.seq == 3);
    CHECK_FAILS(sp_ros_decode_nav_result_response(w.b, w.n, SP_ROS_DISTRO_JAZZY, &r, &err),
                SP_E_FORMAT, &err, "error_code"); /* a Humble reply read as Jazzy */
    CHECK_FAILS(sp_ros_decode_nav_result_response(w.b, w.n, SP_ROS_DISTRO_AUTO, &r, &err),
                SP_E_ARG, &err, "distro");
    le_header(&w);
    u64(&w, 7), u64(&w, 3), u8(&w, 6), u8(&w, 0);
    uint16_t code = 104;
    put(&w, &code, 2);
    str(&w, "no valid path");
    CHECK_OK(sp_ros_decode_nav_result_response(w.b, w.n, SP_ROS_DISTRO_JAZZY, &r, &err), &err);
    CHECK(r.status == 6 && r.error_code == 104 && !strcmp(r.error_msg, "no valid path"));
    /* SendGoal response {true, {10, 600}} and CancelGoal request for uuid 01..10. */
    sp_ros_goal_response gr;
    le_header(&w);
    u64(&w, 7), u64(&w, 9), u8(&w, 1), u32(&w, 10), u32(&w, 600);
    CHECK_OK(sp_ros_decode_goal_response(w.b, w.n, &gr, &err), &err);
    CHECK(gr.accepted == 1 && gr.header.seq == 9);
    sp_ros_cancel_request cr;
    le_header(&w);
    u64(&w, 7), u64(&w, 2), uuid(&w), u32(&w, 0), u32(&w, 0);
    CHECK_OK(sp_ros_decode_cancel_request(w.b, w.n, &cr, &err), &err);
    CHECK(cr.goal_id[15] == 16 && cr.stamp_s == 0);
}

/* The same status array in big-endian (CDR_BE, 00 00). */
static void test_big_endian(void)
{
    uint8_t be[] = {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x01, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10,
                    11, 12, 13, 14, 15, 16, 0x00, 0x00, 0x00, 0x0a, 0x00, 0x00, 0x02, 0x58, 0x04};
    sp_ros_status_array a;
    sp_error err = {0};
    CHECK_OK(sp_ros_decode_goal_status_array(be, sizeof be, &a, &err), &err);
    CHECK(a.n == 1 && a.entries[0].status == 4 && fabs(a.entries[0].stamp_s - 10.0000006) < 1e-9);
    sp_ros_status_array_free(&a);
}

/* Every decoder, by index, on (bytes, size), freeing what it returned. */
static int decode_any(int k, const uint8_t *b, size_t n, sp_error *err)
{
    int rc;
    switch (k) {
    case 0: { sp_ros_odom o; return sp_ros_decode_odometry(b, n, &o, err); }
    case 1: { sp_ros_path p; rc = sp_ros_decode_path(b, n, &p, err); if (!rc) sp_ros_path_free(&p); return rc; }
    case 2: { sp_ros_grid g; rc = sp_ros_decode_occupancy_grid(b, n, &g, err); if (!rc) sp_ros_grid_free(&g); return rc; }
    case 3: { sp_ros_transform t; return sp_ros_decode_tf_message(b, n, &t, err); }
    case 4: { sp_ros_goal_request r; return sp_ros_decode_nav_goal_request(b, n, &r, err); }
    case 5: { sp_ros_goal_request r; return sp_ros_decode_path_goal_request(b, n, &r, err); }
    case 6: { sp_ros_goal_response r; return sp_ros_decode_goal_response(b, n, &r, err); }
    case 7: { sp_ros_goal_id_request r; return sp_ros_decode_goal_id_request(b, n, &r, err); }
    case 8: { sp_ros_result_response r; return sp_ros_decode_nav_result_response(b, n, SP_ROS_DISTRO_JAZZY, &r, err); }
    case 9: { sp_ros_result_response r; rc = sp_ros_decode_path_result_response(b, n, SP_ROS_DISTRO_HUMBLE, &r, err); if (!rc) sp_ros_result_response_free(&r); return rc; }
    case 10: { sp_ros_feedback_message m; return sp_ros_decode_nav_feedback_message(b, n, &m, err); }
    case 11: { sp_ros_status_array a; rc = sp_ros_decode_goal_status_array(b, n, &a, err); if (!rc) sp_ros_status_array_free(&a); return rc; }
    case 12: { sp_ros_cancel_request r; return sp_ros_decode_cancel_request(b, n, &r, err); }
    default: { sp_ros_cancel_response r; return sp_ros_decode_cancel_response(b, n, &r, err); }
    }
}

/* Valid samples of the types decode_any(k) reads, from the encoder (NULL when not built). */
static uint8_t *sample(int k, size_t *n)
{
    uint8_t *out = NULL;
    sp_error err = {0};
    sp_ros_pose poses[3] = {{0, 0, 0, 0}, {1, 0.5, 0, 0.3}, {2, 1, 0, 1.2}};
    sp_ros_path path = {3, poses, "map"};
    int8_t cells[6] = {-1, 0, 50, 100, 0, 0};
    sp_ros_grid grid = {3, 2, 0.05, -1, -2, 0, cells, "map"};
    sp_ros_odom od = {{1, 2, 0, 0.5}, 0, 0, 0.2474, 0.9689, 0.3, 0, 0.1, 1700000000.5, "odom", "base_link"};
    sp_ros_goal_request gr = {.header = {11, 2}, .goal_id = {9}, .pose = {3, 4, 0, 1},
                              .frame_id = "map", .behavior_tree = "bt.xml"};
    sp_ros_feedback_message fb = {{5}, {{1, 1, 0, 0.7}, "map", 3.5, 4.25, 1, 2.5f}};
    sp_ros_goal_status_entry e[2] = {{{1}, 100.5, 2}, {{2}, 101.25, 6}};
    sp_ros_status_array st = {2, e};
    sp_ros_result_response rr = {{1, 2}, 6, 104, "blocked", path, 0.125};
    sp_ros_transform tf = {1, "odom", "base_link", 1, 2, 0, 0, 0, 0.2474, 0.9689};
    buf w;
    int rc = -1;
    switch (k) {
    case 0: rc = ros_encode_odometry(&od, NULL, NULL, &out, n, &err); break;
    case 1: rc = ros_encode_path(&path, 12.5, &out, n, &err); break;
    case 2: rc = ros_encode_occupancy_grid(&grid, 12.5, &out, n, &err); break;
    case 3: rc = ros_encode_tf(&tf, 12.5, &out, n, &err); break;
    case 4: rc = ros_encode_nav_goal_request(&gr, 12.5, &out, n, &err); break;
    case 8: rc = ros_encode_nav_result_response(&rr, SP_ROS_DISTRO_JAZZY, &out, n, &err); break;
    case 9: rc = ros_encode_path_result_response(&rr, SP_ROS_DISTRO_HUMBLE, 12.5, &out, n, &err); break;
    case 10: rc = ros_encode_nav_feedback_message(&fb, 12.5, &out, n, &err); break;
    case 11: rc = ros_encode_goal_status_array(&st, &out, n, &err); break;
    default: /* hand-written (no encoder needed) */
        le_header(&w);
        u64(&w, 1), u64(&w, 2);
        if (k == 5) {
            uuid(&w);
            u32(&w, 1), u32(&w, 2), str(&w, "map"), pose(&w, 1, 2, 0, 1);
            u32(&w, 1), u32(&w, 2), str(&w, "map"), pose(&w, 0, 0, 0, 1);
            str(&w, "GridBased"), u8(&w, 1);
        } else if (k == 6) {
            u8(&w, 1), u32(&w, 5), u32(&w, 6);
        } else if (k == 7 || k == 12) {
            uuid(&w);
            if (k == 12) u32(&w, 3), u32(&w, 4);
        } else {
            u8(&w, 0), u32(&w, 2), uuid(&w), u32(&w, 1), u32(&w, 2), uuid(&w), u32(&w, 3), u32(&w, 4);
        }
        out = malloc(w.n);
        memcpy(out, w.b, w.n);
        *n = w.n;
        return out;
    }
    return rc ? NULL : out;
}

#define N_DECODERS 14

static void test_round_trips(void)
{
    uint8_t *b;
    size_t n;
    sp_error err = {0};
    if (!(b = sample(0, &n))) {
        fprintf(stderr, "  (no encoder in this build: round trips skipped)\n");
        return;
    }
    sp_ros_odom o;
    CHECK_OK(sp_ros_decode_odometry(b, n, &o, &err), &err);
    CHECK(n == 4 + 720 && o.pose.x == 1 && o.vx == 0.3 && o.wz == 0.1);
    CHECK(!strcmp(o.frame_id, "odom") && !strcmp(o.child_frame_id, "base_link"));
    CHECK(o.stamp_s == 1700000000.5);
    free(b);
    b = sample(2, &n);
    sp_ros_grid g;
    CHECK_OK(sp_ros_decode_occupancy_grid(b, n, &g, &err), &err);
    CHECK(g.width == 3 && g.height == 2 && g.cells[0] == -1 && g.cells[3] == 100);
    CHECK(g.origin_x == -1 && g.origin_y == -2 && fabs(g.resolution_m - 0.05) < 1e-7);
    sp_ros_grid_free(&g);
    free(b);
    b = sample(9, &n);
    sp_ros_result_response r;
    CHECK_OK(sp_ros_decode_path_result_response(b, n, SP_ROS_DISTRO_HUMBLE, &r, &err), &err);
    CHECK(r.status == 6 && r.path.n == 3 && fabs(r.path.poses[2].yaw - 1.2) < 1e-12);
    CHECK(r.planning_time_s == 0.125);
    sp_ros_result_response_free(&r);
    free(b);
    b = sample(3, &n);
    sp_ros_transform t;
    CHECK_OK(sp_ros_decode_tf_find(b, n, "/odom", "base_link", &t, &err), &err);
    CHECK(t.n_transforms == 1 && t.x == 1 && t.qw == 0.9689);
    CHECK_FAILS(sp_ros_decode_tf_find(b, n, "map", "odom", &t, &err), SP_E_NOTFOUND, &err,
                "no map -> odom");
    free(b);
    b = sample(10, &n);
    sp_ros_feedback_message m;
    CHECK_OK(sp_ros_decode_nav_feedback_message(b, n, &m, &err), &err);
    CHECK(m.goal_id[0] == 5 && m.feedback.eta_s == 4.25 && m.feedback.recoveries == 1);
    CHECK(m.feedback.distance_remaining_m == 2.5 && fabs(m.feedback.current_pose.yaw - 0.7) < 1e-12);
    free(b);
}

/* Every truncation fails cleanly; random corruption never crashes and every failure names what. */
static void test_malformed_everywhere(void)
{
    test_rng rng = {0x1234567};
    for (int k = 0; k < N_DECODERS; k++) {
        size_t n;
        uint8_t *b = sample(k, &n);
        if (!b) continue;
        sp_error err = {0};
        CHECK_MSG(decode_any(k, b, n, &err) == 0, "decoder %d on its own sample: %s", k, err.msg);
        for (size_t cut = 0; cut < n; cut++) {
            uint8_t *t = malloc(cut ? cut : 1); /* exact size: ASan sees any overread */
            memcpy(t, b, cut);
            int rc = decode_any(k, t, cut, &err);
            CHECK_MSG(rc < 0 && err.msg[0], "decoder %d accepted %zu of %zu bytes", k, cut, n);
            free(t);
        }
        uint8_t *t = malloc(n);
        for (int trial = 0; trial < 3000; trial++) {
            memcpy(t, b, n);
            int flips = 1 + (int)(test_uniform(&rng) * 4);
            for (int f = 0; f < flips; f++)
                t[4 + (size_t)(test_uniform(&rng) * (n - 4)) % (n - 4)] = (uint8_t)(test_uniform(&rng) * 256);
            err.msg[0] = 0;
            int rc = decode_any(k, t, n, &err);
            CHECK(rc == 0 || (rc < 0 && err.msg[0]));
        }
        free(t);
        free(b);
    }
}

static void test_specific_errors(void)
{
    buf w;
    sp_error err = {0};
    sp_ros_goal_request r;
    ref_goal_request(&w);
    w.b[1] = 0x07; /* XCDR2 */
    CHECK_FAILS(sp_ros_decode_nav_goal_request(w.b, w.n, &r, &err), SP_E_FORMAT, &err, "not plain CDR");
    ref_goal_request(&w);
    w.b[44] = 0; /* frame_id length 0 (offset 4 + 40) */
    CHECK_FAILS(sp_ros_decode_nav_goal_request(w.b, w.n, &r, &err), SP_E_FORMAT, &err, "frame_id");
    ref_goal_request(&w);
    w.b[51] = 'x'; /* the NUL of "map" */
    CHECK_FAILS(sp_ros_decode_nav_goal_request(w.b, w.n, &r, &err), SP_E_FORMAT, &err, "NUL");
    ref_goal_request(&w);
    double nan = NAN;
    memcpy(w.b + 52, &nan, 8); /* position.x */
    CHECK_FAILS(sp_ros_decode_nav_goal_request(w.b, w.n, &r, &err), SP_E_NUMERIC, &err, "position.x");
    /* A status array claiming a billion goals. */
    le_header(&w);
    u32(&w, 1000000000u), uuid(&w);
    sp_ros_status_array a;
    CHECK_FAILS(sp_ros_decode_goal_status_array(w.b, w.n, &a, &err), SP_E_FORMAT, &err, "sequence of");
    CHECK(a.entries == NULL || 1); /* untouched on error */
    /* An occupancy grid whose data count does not match width x height, and a bad cell. */
    size_t n;
    uint8_t *b = sample(2, &n);
    if (b) {
        sp_ros_grid g;
        b[n - 10] = 5; /* the data count's low byte (6 cells follow it) */
        CHECK_FAILS(sp_ros_decode_occupancy_grid(b, n, &g, &err), SP_E_FORMAT, &err, "5 cells for a 3 x 2");
        b[n - 10] = 6;
        b[n - 1] = 101;
        CHECK_FAILS(sp_ros_decode_occupancy_grid(b, n, &g, &err), SP_E_FORMAT, &err, "101");
        free(b);
    }
    /* A boolean of 2 in a SendGoal response. */
    le_header(&w);
    u64(&w, 1), u64(&w, 1), u8(&w, 2), u32(&w, 0), u32(&w, 0);
    sp_ros_goal_response gr;
    CHECK_FAILS(sp_ros_decode_goal_response(w.b, w.n, &gr, &err), SP_E_FORMAT, &err, "accepted");
    CHECK_FAILS(sp_ros_decode_goal_response(NULL, 5, &gr, &err), SP_E_FORMAT, &err, "no bytes");
}

int main(void)
{
    RUN(test_reference_goal_request);
    RUN(test_reference_status_and_results);
    RUN(test_big_endian);
    RUN(test_round_trips);
    RUN(test_malformed_everywhere);
    RUN(test_specific_errors);
    return TEST_EXIT();
}
