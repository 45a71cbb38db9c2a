/* rmw_cyclonedds conventions as other ROS 2 nodes see them, checked from a bare Cyclone "tap"
 * participant: ros_discovery_info (node name and namespace, the participant GUID as gid, 24
 * bytes on Humble with 8 zeros, 16 on Jazzy, our endpoints listed), participant USER_DATA
 * enclave=/;, clientid=/serviceid= on service endpoints (the same id on a client's request writer
 * and reply reader), no typehash= from us, the action status and map writers transient-local,
 * and what Cyclone really sends for a map: our encoder's bytes plus at most 3 padding bytes
 * counted in the header's options. Each distro runs in its own process (the two discovery
 * layouts share a type name). Built only with Cyclone DDS. */
#include <math.h>

#include "ros/cyclonedds/bridge_internal.h"
#include "ros_test.h"
#include "test.h"

static int domain;
static char ns[64];
static sp_ros_distro distro;

/* ---- ros_discovery_info ---- */

#define DISCOVERY_CHECK(prefix)                                                                   \
    static int discovery_##prefix(dds_entity_t rd, const char *node, const dds_guid_t *gid,     \
                                  int *n_readers, int *n_writers)                                \
    {                                                                                            \
        void *s[16] = {NULL};                                                                    \
        dds_sample_info_t si[16];                                                                \
        int k = dds_read(rd, s, si, 16, 16), found = 0;                                          \
        for (int i = 0; i < k; i++) {                                                            \
            const prefix##_rmw_dds_common_msg_dds__ParticipantEntitiesInfo_ *p = s[i];          \
            if (!si[i].valid_data || p->node_entities_info_seq._length != 1) continue;         \
            const prefix##_rmw_dds_common_msg_dds__NodeEntitiesInfo_ *n =                        \
                &p->node_entities_info_seq._buffer[0];                                           \
            if (strcmp(n->node_name, node)) continue;                                            \
            found = 1;                                                                           \
            CHECK(!strcmp(n->node_namespace, ns));                                               \
            if (gid) CHECK(!memcmp(p->gid.data, gid->v, 16));                                    \
            for (size_t z = 16; z < sizeof p->gid.data; z++) CHECK(p->gid.data[z] == 0);         \
            *n_readers = (int)n->reader_gid_seq._length;                                        \
            *n_writers = (int)n->writer_gid_seq._length;                                        \
        }                                                                                        \
        if (k > 0) dds_return_loan(rd, s, k);                                                    \
        return found;                                                                            \
    }
DISCOVERY_CHECK(humble)
DISCOVERY_CHECK(jazzy)

static int find_node(dds_entity_t rd, const char *node, const dds_guid_t *gid, int *nr, int *nw)
{
    double until = sp_time_now() + 10;
    while (sp_time_now() < until) {
        int ok = distro == SP_ROS_DISTRO_JAZZY ? discovery_jazzy(rd, node, gid, nr, nw)
                                               : discovery_humble(rd, node, gid, nr, nw);
        if (ok) return 1;
        usleep(50000);
    }
    return 0;
}

/* ---- endpoints seen through discovery ---- */

typedef struct {
    char topic[300];
    char user_data[300];
    int reliable, transient_local;
} seen_endpoint;

static int scan(dds_entity_t rd, seen_endpoint *out, int cap)
{
    void *s[64] = {NULL};
    dds_sample_info_t si[64];
    int k = dds_read(rd, s, si, 64, 64), n = 0;
    for (int i = 0; i < k && n < cap; i++) {
        const dds_builtintopic_endpoint_t *ep = s[i];
        if (!si[i].valid_data || !ep->topic_name || strlen(ep->topic_name) < 2 ||
            strncmp(ep->topic_name + 2, ns, strlen(ns)))
            continue;
        seen_endpoint *e = &out[n++];
        snprintf(e->topic, sizeof e->topic, "%s", ep->topic_name);
        void *ud = NULL;
        size_t sz = 0;
        e->user_data[0] = 0;
        if (dds_qget_userdata(ep->qos, &ud, &sz) && ud) {
            snprintf(e->user_data, sizeof e->user_data, "%.*s", (int)sz, (const char *)ud);
            dds_free(ud);
        }
        dds_reliability_kind_t rk;
        dds_duration_t mb;
        dds_durability_kind_t dk;
        e->reliable = dds_qget_reliability(ep->qos, &rk, &mb) && rk == DDS_RELIABILITY_RELIABLE;
        e->transient_local = dds_qget_durability(ep->qos, &dk) && dk == DDS_DURABILITY_TRANSIENT_LOCAL;
    }
    if (k > 0) dds_return_loan(rd, s, k);
    return n;
}

static const seen_endpoint *find_ep(const seen_endpoint *e, int n, const char *suffix,
                                    const char *with)
{
    size_t ls = strlen(suffix);
    for (int i = 0; i < n; i++) {
        size_t lt = strlen(e[i].topic);
        if (lt >= ls && !strcmp(e[i].topic + lt - ls, suffix) && (!with || strstr(e[i].user_data, with)))
            return &e[i];
    }
    return NULL;
}

static void id_of(const char *ud, const char *key, char *out, size_t cap)
{
    const char *p = strstr(ud, key);
    out[0] = 0;
    if (!p) return;
    p += strlen(key);
    size_t n = strcspn(p, ";");
    snprintf(out, cap, "%.*s", (int)(n < cap ? n : cap - 1), p);
}

static void check_endpoints(dds_entity_t pubs, dds_entity_t subs)
{
    seen_endpoint w[64], r[64];
    int nw = 0, nr = 0;
    double until = sp_time_now() + 10;
    const char *want = "/navigate_to_pose/_action/get_resultReply";
    /* Wait until the bridge's client endpoints (clientid) have been discovered too. */
    while (sp_time_now() < until && !find_ep(r, nr, want, "clientid=")) {
        usleep(50000);
        nw = scan(pubs, w, 64);
        nr = scan(subs, r, 64);
    }
    const char *marker = distro == SP_ROS_DISTRO_JAZZY ? "semsplat_distro=jazzy;" : "semsplat_distro=humble;";
    for (int i = 0; i < nw; i++) CHECK_MSG(!strstr(w[i].user_data, "typehash="), "%s", w[i].topic);
    /* The robot's server side: serviceid on request readers and reply writers. */
    const seen_endpoint *sreq = find_ep(r, nr, "/navigate_to_pose/_action/send_goalRequest", "serviceid=");
    const seen_endpoint *srep = find_ep(w, nw, "/navigate_to_pose/_action/send_goalReply", "serviceid=");
    CHECK(sreq && srep && strstr(sreq->user_data, marker));
    /* The bridge's client side: one clientid on its request writer and reply reader. */
    const seen_endpoint *creq = find_ep(w, nw, "/navigate_to_pose/_action/get_resultRequest", "clientid=");
    const seen_endpoint *crep = find_ep(r, nr, want, "clientid=");
    CHECK(creq && crep);
    if (creq && crep) {
        char a[128], b[128];
        id_of(creq->user_data, "clientid=", a, sizeof a);
        id_of(crep->user_data, "clientid=", b, sizeof b);
        CHECK_MSG(a[0] && !strcmp(a, b), "clientid '%s' vs '%s'", a, b);
        CHECK(creq->reliable && crep->reliable && !creq->transient_local);
    }
    const seen_endpoint *status = find_ep(w, nw, "/navigate_to_pose/_action/status", NULL);
    const seen_endpoint *map = find_ep(w, nw, "/semsplat/map", NULL);
    CHECK(status && status->reliable && status->transient_local);
    CHECK(map && map->reliable && map->transient_local);
    const seen_endpoint *fb = find_ep(r, nr, "/navigate_to_pose/_action/feedback", NULL);
    CHECK(fb && fb->reliable); /* Cyclone's default reader is best effort: set explicitly */
}

/* ---- what goes on the wire for a map ---- */

typedef struct {
    uint8_t b[512];
    size_t n;
    int got;
} raw_sample;

static void keep_raw(void *ctx, const uint8_t *bytes, size_t n, const dds_sample_info_t *info)
{
    raw_sample *r = ctx;
    (void)info;
    if (n <= sizeof r->b) memcpy(r->b, bytes, n), r->n = n, r->got = 1;
}

static void check_map_bytes(ros_node *tap, sp_ros_bridge *b)
{
    char topic[300];
    snprintf(topic, sizeof topic, "rt%s/semsplat/map", ns);
    sp_error err = {0};
    dds_entity_t rd = ros_reader(tap, RT_OCCUPANCY_GRID, topic, ROS_QOS_LATCHED, NULL, &err);
    CHECK(rd > 0);
    int8_t cells[9] = {0, 100, -1, 0, 0, 0, 50, 100, -1};
    sp_ros_grid g = {3, 3, 0.1, 1, 2, 0, cells, "map"};
    CHECK_OK(sp_ros_publish_map(b, &g, &err), &err);
    raw_sample r = {{0}, 0, 0};
    double until = sp_time_now() + 5;
    while (!r.got && sp_time_now() < until) {
        ros_take_raw(rd, keep_raw, &r, 8);
        usleep(20000);
    }
    CHECK(r.got);
    uint8_t *ours;
    size_t n;
    CHECK_OK(ros_encode_occupancy_grid(&g, 0, &ours, &n, &err), &err);
    /* Same bytes except the two stamps (header at body 0, map_load_time at body 16) and
     * Cyclone's padding: body 109 bytes -> 3 padding bytes, counted in the options' low bits. */
    CHECK_MSG(r.n >= n && r.n - n <= 3 && (r.n - 4) % 4 == 0, "wire %zu bytes, ours %zu", r.n, n);
    CHECK(r.b[0] == 0 && r.b[1] == 1 && (r.b[3] & 3) == (uint8_t)(r.n - n));
    for (size_t i = 4; i < n; i++) {
        size_t body = i - 4;
        if (body < 8 || (body >= 16 && body < 24)) continue;
        CHECK_MSG(r.b[i] == ours[i], "byte %zu: wire %02x, ours %02x", i, r.b[i], ours[i]);
    }
    for (size_t i = n; i < r.n; i++) CHECK(r.b[i] == 0);
    fprintf(stderr, "  map on the wire: %zu bytes = our %zu + %zu padding\n", r.n, n, r.n - n);
    free(ours);
}

/* ---- the map-frame pose: odometry composed with a localization's map -> odom ---- */

static void check_map_pose(ros_node *tap)
{
    char ns2[128], topic[300];
    snprintf(ns2, sizeof ns2, "%s/loc", ns);
    sp_ros_options o;
    sp_ros_options_default(&o);
    o.domain_id = domain, o.ns = ns2, o.loopback_only = 1, o.distro = distro;
    sp_ros_bridge *b = NULL;
    sp_error err = {0};
    CHECK_OK(sp_ros_bridge_create(&b, &o, &err), &err);
    snprintf(topic, sizeof topic, "rt%s/odom", ns2);
    dds_entity_t ow = ros_writer(tap, RT_ODOMETRY, topic, ROS_QOS_DEFAULT, NULL, &err);
    snprintf(topic, sizeof topic, "rt%s/tf", ns2);
    dds_entity_t tw = ros_writer(tap, RT_TF, topic, ROS_QOS_DEFAULT, NULL, &err);
    CHECK(b && ow > 0 && tw > 0);
    if (!b || ow <= 0 || tw <= 0) return;
    sp_ros_odom od = {{1, 0.5, 0, 0.3}, 0, 0, 0, 0, 0, 0, 0, 0, "odom", "base_link"};
    sp_ros_yaw_quat(0.3, &od.qx, &od.qy, &od.qz, &od.qw);
    sp_ros_transform t = {1, "map", "odom", 2, -1, 0, 0, 0, sin(M_PI / 4), cos(M_PI / 4)};
    sp_ros_pose m = {0, 0, 0, 0};
    int rc = -1;
    for (double until = sp_time_now() + 5; rc && sp_time_now() < until; usleep(50000)) {
        nav_msgs_msg_dds__Odometry_ om;
        tf2_msgs_msg_dds__TFMessage_ tm;
        struct geometry_msgs_msg_dds__TransformStamped_ one;
        od.stamp_s = ros_wall_time();
        ros_fill_odometry(&om, &od, NULL, NULL);
        ros_fill_tf(&tm, &one, &t, od.stamp_s);
        dds_write(ow, &om);
        dds_write(tw, &tm);
        rc = sp_ros_robot_pose(b, &m, NULL, &err);
    }
    CHECK_OK(rc, &err);
    /* (2, -1) + R(90 deg) (1, 0.5) = (1.5, 0); yaw 90 deg + 0.3. */
    CHECK_NEAR(m.x, 1.5, 1e-9);
    CHECK_NEAR(m.y, 0.0, 1e-9);
    CHECK_NEAR(m.yaw, M_PI / 2 + 0.3, 1e-9);
    sp_ros_bridge_free(b);
}

/* ---- one distro, in this process ---- */

static int run_distro(const char *dir)
{
    char yaml[1200], ready[1200], log[1200], dom[16];
    snprintf(yaml, sizeof yaml, "%s", room_write_yaml(dir));
    snprintf(ready, sizeof ready, "%s/ready", dir);
    snprintf(log, sizeof log, "%s/robot.log", dir);
    snprintf(dom, sizeof dom, "%d", domain);
    char *argv[] = {SP_BUILD_DIR "/semsplat", "sim-robot", "--map", yaml, "--start", "1,1,0",
                    "--loopback", "--domain", dom, "--namespace", ns, "--ros-distro",
                    (char *)sp_ros_distro_name(distro), "--duration", "60", "--ready-file",
                    ready, "--quiet", NULL};
    pid_t robot = test_spawn(argv, log);
    CHECK(test_wait_file(ready, 60) == 0);
    sp_ros_options o;
    sp_ros_options_default(&o);
    o.domain_id = domain, o.ns = ns, o.loopback_only = 1, o.server_timeout_s = 10;
    o.node_name = "semsplat_rmw_test";
    sp_ros_bridge *b = NULL;
    sp_error err = {0};
    CHECK_OK(sp_ros_bridge_create(&b, &o, &err), &err);
    ros_node *tap = NULL;
    sp_ros_options to = o;
    to.node_name = "tap";
    to.distro = distro;
    CHECK_OK(ros_node_create(&tap, &to, &err), &err);
    if (b && tap) {
        /* A goal makes the client endpoints and settles the distro (detected). */
        sp_ros_pose goal = {1.5, 1.0, 0, 0};
        sp_ros_goal *g = NULL;
        sp_ros_goal_status st;
        CHECK_OK(sp_ros_navigate_to(b, &goal, NULL, &g, &err), &err);
        if (g) CHECK_OK(sp_ros_goal_wait(g, 20, &st, NULL, NULL, &err), &err);
        sp_ros_goal_free(g);
        CHECK(sp_ros_bridge_distro(b) == distro);
        ros_type dt = ros_type_for(RT_DISCOVERY_HUMBLE, distro);
        dds_entity_t disc = ros_reader(tap, dt, "ros_discovery_info", ((ros_qos){1, 1, 0}), NULL, &err);
        int nr = 0, nw = 0;
        CHECK_MSG(find_node(disc, "semsplat_rmw_test", &b->node->guid, &nr, &nw),
                  "the bridge is not in ros_discovery_info");
        CHECK_MSG(nr >= 6 && nw >= 5, "bridge lists %d readers, %d writers", nr, nw);
        /* The robot: 3 request readers per action; odom, tf, map, 3 reply writers, feedback and
         * status per action. */
        CHECK_MSG(find_node(disc, "semsplat_sim_robot", NULL, &nr, &nw), "the robot is not listed");
        CHECK_MSG(nr >= 6 && nw >= 13, "robot lists %d readers, %d writers", nr, nw);
        check_endpoints(tap->builtin_pub, tap->builtin_sub);
        check_map_bytes(tap, b);
        check_map_pose(tap);
        void *s[8] = {NULL};
        dds_sample_info_t si[8];
        dds_entity_t parts = dds_create_reader(tap->pp, DDS_BUILTIN_TOPIC_DCPSPARTICIPANT, NULL, NULL);
        usleep(200000);
        int k = dds_read(parts, s, si, 8, 8), enclaves = 0;
        for (int i = 0; i < k; i++) {
            char v[64];
            const dds_builtintopic_participant_t *p = s[i];
            if (si[i].valid_data && !ros_qos_user_data_key(p->qos, "enclave", v, sizeof v) && !strcmp(v, "/"))
                enclaves++;
        }
        if (k > 0) dds_return_loan(parts, s, k);
        CHECK_MSG(enclaves >= 3, "%d participants with enclave=/;", enclaves); /* robot, bridge, tap */
    }
    ros_node_free(tap);
    sp_ros_bridge_free(b);
    test_stop(robot);
    return t_failures ? 1 : 0;
}

int main(int argc, char **argv)
{
    if (argc == 4) { /* a child: <distro> <domain> <namespace> */
        sp_error err = {0};
        if (sp_ros_distro_parse(argv[1], &distro, &err)) return 2;
        domain = atoi(argv[2]);
        snprintf(ns, sizeof ns, "%s", argv[3]);
        char name[64];
        snprintf(name, sizeof name, "ros_rmw_%s", argv[1]);
        t_case_failed = 0;
        t_cases = 1;
        int rc = run_distro(test_tmpdir(name));
        fprintf(stderr, "%s rmw conventions (%s)\n", rc ? "FAIL" : "ok  ", argv[1]);
        return TEST_EXIT();
    }
    const char *distros[2] = {"humble", "jazzy"};
    test_tmpdir("ros_rmw");
    for (int i = 0; i < 2; i++) {
        char dom[16], log[1024];
        domain = test_random_domain(ns, sizeof ns);
        snprintf(dom, sizeof dom, "%d", domain);
        snprintf(log, sizeof log, "%s/test-tmp/ros_rmw_%s.log", SP_BUILD_DIR, distros[i]);
        char *cargv[] = {argv[0], (char *)distros[i], dom, ns, NULL};
        pid_t pid = test_spawn(cargv, log);
        int rc = test_wait_pid(pid, 90);
        if (rc < 0) test_stop(pid);
        test_print_file(log);
        t_checks++, t_cases++;
        if (rc != 0) t_failures++;
        fprintf(stderr, "%s %s (exit %d)\n", rc ? "FAIL" : "ok  ", distros[i], rc);
    }
    return TEST_EXIT();
}
