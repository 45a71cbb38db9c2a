/* Wire bytes: what the bridge and the simulated robot serialize (the fill functions + Cyclone's
 * serializer, ros_encode_*) equals byte for byte what an independent ROS 2 serializer writes for
 * the same values: npm @foxglove/rosmsg2-serialization with @foxglove/rosmsg-msgs-common's
 * Humble and Jazzy definitions (nav2 definitions written out from nav2_msgs' .action files,
 * with the rmw_cyclonedds {guid, seq} header as two leading fields). Skips without Cyclone (no
 * encoder) or without the npm set-up. */
#include <cjson/cJSON.h>
#include <math.h>

#include "ros/ros_internal.h"
#include "ros_test.h"
#include "test.h"

#define STAMP 1700000000.25 /* exact in binary: sec 1700000000, nanosec 250000000 */

typedef struct {
    char name[96];
    uint8_t *ours;
    size_t n;
} wire_case;

static wire_case cases[32];
static int n_cases;
static cJSON *json_cases;

static cJSON *jtime(double t)
{
    int32_t sec;
    uint32_t nsec;
    ros_split_time(t, &sec, &nsec);
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "sec", sec);
    cJSON_AddNumberToObject(o, "nanosec", nsec);
    return o;
}

static cJSON *jheader(double stamp, const char *frame)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddItemToObject(o, "stamp", jtime(stamp));
    cJSON_AddStringToObject(o, "frame_id", frame);
    return o;
}

/* cJSON prints doubles with 15 digits when they compare equal within an epsilon, which can lose
 * the last bit; doubles travel as "num:%.17g" strings the script turns back into numbers. */
static cJSON *jnum(double v)
{
    char s[48];
    snprintf(s, sizeof s, "num:%.17g", v);
    return cJSON_CreateString(s);
}

static cJSON *jnums(const double *v, int n)
{
    cJSON *a = cJSON_CreateArray();
    for (int i = 0; i < n; i++) cJSON_AddItemToArray(a, jnum(v[i]));
    return a;
}

static cJSON *jxyz(double x, double y, double z)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddItemToObject(o, "x", jnum(x));
    cJSON_AddItemToObject(o, "y", jnum(y));
    cJSON_AddItemToObject(o, "z", jnum(z));
    return o;
}

static cJSON *jquat(double x, double y, double z, double w)
{
    cJSON *o = jxyz(x, y, z);
    cJSON_AddItemToObject(o, "w", jnum(w));
    return o;
}

static cJSON *jpose(const sp_ros_pose *p)
{
    double qx, qy, qz, qw;
    sp_ros_yaw_quat(p->yaw, &qx, &qy, &qz, &qw);
    cJSON *o = cJSON_CreateObject();
    cJSON_AddItemToObject(o, "position", jxyz(p->x, p->y, p->z));
    cJSON_AddItemToObject(o, "orientation", jquat(qx, qy, qz, qw));
    return o;
}

static cJSON *jpose_stamped(const sp_ros_pose *p, const char *frame, double stamp)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddItemToObject(o, "header", jheader(stamp, frame));
    cJSON_AddItemToObject(o, "pose", jpose(p));
    return o;
}

static cJSON *juuid(const uint8_t id[16])
{
    cJSON *o = cJSON_CreateObject(), *a = cJSON_CreateArray();
    for (int i = 0; i < 16; i++) cJSON_AddItemToArray(a, cJSON_CreateNumber(id[i]));
    cJSON_AddItemToObject(o, "uuid", a);
    return o;
}

static cJSON *jbig(uint64_t v, int is_signed)
{
    char s[40];
    if (is_signed) snprintf(s, sizeof s, "bigint:%lld", (long long)v);
    else snprintf(s, sizeof s, "bigint:%llu", (unsigned long long)v);
    return cJSON_CreateString(s);
}

static void jrpc(cJSON *o, const sp_ros_rpc_header *h)
{
    cJSON_AddItemToObject(o, "guid", jbig(h->guid, 0));
    cJSON_AddItemToObject(o, "seq", jbig((uint64_t)h->seq, 1));
}

static cJSON *jpath(const sp_ros_path *p, double stamp)
{
    cJSON *o = cJSON_CreateObject(), *a = cJSON_CreateArray();
    cJSON_AddItemToObject(o, "header", jheader(stamp, p->frame_id));
    for (size_t i = 0; i < p->n; i++)
        cJSON_AddItemToArray(a, jpose_stamped(&p->poses[i], p->frame_id, stamp));
    cJSON_AddItemToObject(o, "poses", a);
    return o;
}

static cJSON *jduration(double t)
{
    return jtime(t); /* {sec, nanosec}, the same split */
}

/* Adds a case: our bytes (rc from the encoder), the reference's type or definition, message. */
static void add_case(const char *name, sp_ros_distro d, int rc, uint8_t *ours, size_t n,
                     const char *type, const char *definition, cJSON *message)
{
    if (rc == SP_E_UNSUPPORTED) TEST_SKIP("no Cyclone DDS serializer in this build");
    CHECK_MSG(rc == 0, "encoding %s failed", name);
    wire_case *c = &cases[n_cases++];
    snprintf(c->name, sizeof c->name, "%s (%s)", name, sp_ros_distro_name(d));
    c->ours = ours;
    c->n = n;
    cJSON *j = cJSON_CreateObject();
    cJSON_AddStringToObject(j, "distro", sp_ros_distro_name(d));
    if (type) cJSON_AddStringToObject(j, "type", type);
    else cJSON_AddStringToObject(j, "definition", definition);
    cJSON_AddItemToObject(j, "message", message);
    cJSON_AddItemToArray(json_cases, j);
}

#define SEP "================================================================================\n"
static const char def_goal_request[] =
    "uint64 guid\nint64 seq\nunique_identifier_msgs/UUID goal_id\n"
    "nav2_msgs/NavigateToPose_Goal goal\n" SEP "MSG: nav2_msgs/NavigateToPose_Goal\n"
    "geometry_msgs/PoseStamped pose\nstring behavior_tree\n";
static const char def_feedback[] =
    "unique_identifier_msgs/UUID goal_id\nnav2_msgs/NavigateToPose_Feedback feedback\n" SEP
    "MSG: nav2_msgs/NavigateToPose_Feedback\ngeometry_msgs/PoseStamped current_pose\n"
    "builtin_interfaces/Duration navigation_time\nbuiltin_interfaces/Duration "
    "estimated_time_remaining\nint16 number_of_recoveries\nfloat32 distance_remaining\n";
static const char def_nav_result_humble[] =
    "uint64 guid\nint64 seq\nint8 status\nnav2_msgs/NavigateToPose_Result result\n" SEP
    "MSG: nav2_msgs/NavigateToPose_Result\nstd_msgs/Empty result\n";
static const char def_nav_result_jazzy[] =
    "uint64 guid\nint64 seq\nint8 status\nnav2_msgs/NavigateToPose_Result result\n" SEP
    "MSG: nav2_msgs/NavigateToPose_Result\nuint16 NONE=0\nuint16 error_code\nstring error_msg\n";
static const char def_path_result_humble[] =
    "uint64 guid\nint64 seq\nint8 status\nnav2_msgs/ComputePathToPose_Result result\n" SEP
    "MSG: nav2_msgs/ComputePathToPose_Result\nnav_msgs/Path path\n"
    "builtin_interfaces/Duration planning_time\n";
static const char def_path_result_jazzy[] =
    "uint64 guid\nint64 seq\nint8 status\nnav2_msgs/ComputePathToPose_Result result\n" SEP
    "MSG: nav2_msgs/ComputePathToPose_Result\nuint16 NONE=0\nuint16 NO_VALID_PATH=208\n"
    "nav_msgs/Path path\nbuiltin_interfaces/Duration planning_time\nuint16 error_code\n"
    "string error_msg\n";

static sp_ros_pose path_poses[3] = {{0.5, -1.25, 0, 0.0}, {1.75, 0.5, 0.1, 0.785}, {3, 2, 0, -2.5}};

static void add_odometry(sp_ros_distro d)
{
    sp_ros_odom o = {{1.5, -2.25, 0.125, 0.7}, 0, 0, 0, 0, 0.4, -0.05, 0.3, STAMP, "odom",
                     "base_link"};
    sp_ros_yaw_quat(o.pose.yaw, &o.qx, &o.qy, &o.qz, &o.qw);
    double pc[36], tc[36];
    for (int i = 0; i < 36; i++) pc[i] = 0.001 * (i + 1), tc[i] = -0.5 * i;
    uint8_t *b;
    size_t n;
    int rc = ros_encode_odometry(&o, pc, tc, &b, &n, NULL);
    cJSON *m = cJSON_CreateObject(), *pose = cJSON_CreateObject(), *twist = cJSON_CreateObject(),
          *tw = cJSON_CreateObject();
    cJSON_AddItemToObject(m, "header", jheader(STAMP, "odom"));
    cJSON_AddStringToObject(m, "child_frame_id", "base_link");
    cJSON_AddItemToObject(pose, "pose", jpose(&o.pose));
    cJSON_AddItemToObject(pose, "covariance", jnums(pc, 36));
    cJSON_AddItemToObject(m, "pose", pose);
    cJSON_AddItemToObject(tw, "linear", jxyz(o.vx, o.vy, 0));
    cJSON_AddItemToObject(tw, "angular", jxyz(0, 0, o.wz));
    cJSON_AddItemToObject(twist, "twist", tw);
    cJSON_AddItemToObject(twist, "covariance", jnums(tc, 36));
    cJSON_AddItemToObject(m, "twist", twist);
    add_case("nav_msgs/Odometry", d, rc, b, n, "nav_msgs/Odometry", NULL, m);
}

static void add_grid(sp_ros_distro d)
{
    int8_t cells[12] = {-1, 0, 100, 37, 0, 0, -1, 100, 5, 99, 1, 0};
    sp_ros_grid g = {4, 3, 0.05, -3.5, 2.25, 0.3, cells, "map"};
    uint8_t *b;
    size_t n;
    int rc = ros_encode_occupancy_grid(&g, STAMP, &b, &n, NULL);
    cJSON *m = cJSON_CreateObject(), *info = cJSON_CreateObject(), *data = cJSON_CreateArray();
    sp_ros_pose origin = {g.origin_x, g.origin_y, 0, g.origin_yaw};
    cJSON_AddItemToObject(m, "header", jheader(STAMP, "map"));
    cJSON_AddItemToObject(info, "map_load_time", jtime(STAMP));
    cJSON_AddItemToObject(info, "resolution", jnum((double)(float)g.resolution_m));
    cJSON_AddNumberToObject(info, "width", g.width);
    cJSON_AddNumberToObject(info, "height", g.height);
    cJSON_AddItemToObject(info, "origin", jpose(&origin));
    cJSON_AddItemToObject(m, "info", info);
    for (int i = 0; i < 12; i++) cJSON_AddItemToArray(data, cJSON_CreateNumber(cells[i]));
    cJSON_AddItemToObject(m, "data", data);
    add_case("nav_msgs/OccupancyGrid", d, rc, b, n, "nav_msgs/OccupancyGrid", NULL, m);
}

static void add_path(sp_ros_distro d)
{
    sp_ros_path p = {3, path_poses, "map"};
    uint8_t *b;
    size_t n;
    int rc = ros_encode_path(&p, STAMP, &b, &n, NULL);
    add_case("nav_msgs/Path", d, rc, b, n, "nav_msgs/Path", NULL, jpath(&p, STAMP));
}

static void add_goal_request(sp_ros_distro d)
{
    sp_ros_goal_request r = {.header = {0x1122334455667788ull, 42}, .pose = {1, 2, 0, 1.25},
                             .frame_id = "map", .behavior_tree = ""};
    for (int i = 0; i < 16; i++) r.goal_id[i] = (uint8_t)(i + 1);
    uint8_t *b;
    size_t n;
    int rc = ros_encode_nav_goal_request(&r, STAMP, &b, &n, NULL);
    cJSON *m = cJSON_CreateObject(), *goal = cJSON_CreateObject();
    jrpc(m, &r.header);
    cJSON_AddItemToObject(m, "goal_id", juuid(r.goal_id));
    cJSON_AddItemToObject(goal, "pose", jpose_stamped(&r.pose, "map", STAMP));
    cJSON_AddStringToObject(goal, "behavior_tree", "");
    cJSON_AddItemToObject(m, "goal", goal);
    add_case("NavigateToPose SendGoal request (rmw_cyclonedds header)", d, rc, b, n, NULL,
             def_goal_request, m);
}

static void add_feedback(sp_ros_distro d)
{
    sp_ros_feedback_message f = {{0}, {{2.5, 1.25, 0, -0.5}, "map", 12.75, 3.5, 2, 4.125f}};
    for (int i = 0; i < 16; i++) f.goal_id[i] = (uint8_t)(0xf0 - i);
    uint8_t *b;
    size_t n;
    int rc = ros_encode_nav_feedback_message(&f, STAMP, &b, &n, NULL);
    cJSON *m = cJSON_CreateObject(), *fb = cJSON_CreateObject();
    cJSON_AddItemToObject(m, "goal_id", juuid(f.goal_id));
    cJSON_AddItemToObject(fb, "current_pose", jpose_stamped(&f.feedback.current_pose, "map", STAMP));
    cJSON_AddItemToObject(fb, "navigation_time", jduration(12.75));
    cJSON_AddItemToObject(fb, "estimated_time_remaining", jduration(3.5));
    cJSON_AddNumberToObject(fb, "number_of_recoveries", 2);
    cJSON_AddItemToObject(fb, "distance_remaining", jnum(4.125));
    cJSON_AddItemToObject(m, "feedback", fb);
    add_case("NavigateToPose FeedbackMessage", d, rc, b, n, NULL, def_feedback, m);
}

static void add_results(sp_ros_distro d)
{
    int jazzy = d == SP_ROS_DISTRO_JAZZY;
    sp_ros_path p = {3, path_poses, "map"};
    sp_ros_result_response r = {{77, 5}, 6, 104, "goal blocked", p, 0.375};
    uint8_t *b;
    size_t n;
    int rc = ros_encode_nav_result_response(&r, d, &b, &n, NULL);
    cJSON *m = cJSON_CreateObject(), *res = cJSON_CreateObject();
    jrpc(m, &r.header);
    cJSON_AddNumberToObject(m, "status", 6);
    if (jazzy) {
        cJSON_AddNumberToObject(res, "error_code", 104);
        cJSON_AddStringToObject(res, "error_msg", "goal blocked");
    } else {
        cJSON_AddItemToObject(res, "result", cJSON_CreateObject());
    }
    cJSON_AddItemToObject(m, "result", res);
    add_case("NavigateToPose GetResult response", d, rc, b, n, NULL,
             jazzy ? def_nav_result_jazzy : def_nav_result_humble, m);
    rc = ros_encode_path_result_response(&r, d, STAMP, &b, &n, NULL);
    m = cJSON_CreateObject();
    res = cJSON_CreateObject();
    jrpc(m, &r.header);
    cJSON_AddNumberToObject(m, "status", 6);
    cJSON_AddItemToObject(res, "path", jpath(&p, STAMP));
    cJSON_AddItemToObject(res, "planning_time", jduration(0.375));
    if (jazzy) {
        cJSON_AddNumberToObject(res, "error_code", 104);
        cJSON_AddStringToObject(res, "error_msg", "goal blocked");
    }
    cJSON_AddItemToObject(m, "result", res);
    add_case("ComputePathToPose GetResult response", d, rc, b, n, NULL,
             jazzy ? def_path_result_jazzy : def_path_result_humble, m);
}

static void add_status_and_tf(sp_ros_distro d)
{
    sp_ros_goal_status_entry e[2] = {{{1, 2, 3}, STAMP, 2}, {{9, 8, 7}, STAMP + 1, 5}};
    sp_ros_status_array a = {2, e};
    uint8_t *b;
    size_t n;
    int rc = ros_encode_goal_status_array(&a, &b, &n, NULL);
    cJSON *m = cJSON_CreateObject(), *list = cJSON_CreateArray();
    for (int i = 0; i < 2; i++) {
        cJSON *s = cJSON_CreateObject(), *info = cJSON_CreateObject();
        cJSON_AddItemToObject(info, "goal_id", juuid(e[i].goal_id));
        cJSON_AddItemToObject(info, "stamp", jtime(e[i].stamp_s));
        cJSON_AddItemToObject(s, "goal_info", info);
        cJSON_AddNumberToObject(s, "status", e[i].status);
        cJSON_AddItemToArray(list, s);
    }
    cJSON_AddItemToObject(m, "status_list", list);
    add_case("action_msgs/GoalStatusArray", d, rc, b, n, "action_msgs/GoalStatusArray", NULL, m);
    sp_ros_transform t = {1, "odom", "base_link", 1.5, -2, 0, 0, 0, 0.3826834323650898, 0.9238795325112867};
    rc = ros_encode_tf(&t, STAMP, &b, &n, NULL);
    m = cJSON_CreateObject();
    cJSON *ts = cJSON_CreateObject(), *tr = cJSON_CreateObject(), *arr = cJSON_CreateArray();
    cJSON_AddItemToObject(ts, "header", jheader(STAMP, "odom"));
    cJSON_AddStringToObject(ts, "child_frame_id", "base_link");
    cJSON_AddItemToObject(tr, "translation", jxyz(t.x, t.y, t.z));
    cJSON_AddItemToObject(tr, "rotation", jquat(t.qx, t.qy, t.qz, t.qw));
    cJSON_AddItemToObject(ts, "transform", tr);
    cJSON_AddItemToArray(arr, ts);
    cJSON_AddItemToObject(m, "transforms", arr);
    add_case("tf2_msgs/TFMessage", d, rc, b, n, "tf2_msgs/TFMessage", NULL, m);
}

/* Runs the reference serializer over all cases; returns its output lines (malloc'd text). */
static char *run_reference(const char *json_path)
{
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "NODE_PATH='%s/node_modules' timeout 60 node '%s/tests/ros/foxglove_write.js' '%s'",
             SP_NPM_DIR, SP_SOURCE_DIR, json_path);
    FILE *p = popen(cmd, "r");
    if (!p) return NULL;
    size_t cap = 1 << 16, n = 0;
    char *out = malloc(cap);
    size_t k;
    while ((k = fread(out + n, 1, cap - n - 1, p)) > 0) {
        n += k;
        if (cap - n < 1024) out = realloc(out, cap *= 2);
    }
    out[n] = 0;
    int st = pclose(p);
    if (st != 0) {
        fprintf(stderr, "reference serializer failed (status %d): %s\n", st, out);
        free(out);
        return NULL;
    }
    return out;
}

static int hexval(char c) { return c <= '9' ? c - '0' : c - 'a' + 10; }

static void compare(const wire_case *c, const char *hex, size_t hex_len)
{
    size_t n = hex_len / 2;
    size_t first = (size_t)-1;
    for (size_t i = 0; i < n && i < c->n; i++)
        if ((uint8_t)(hexval(hex[2 * i]) * 16 + hexval(hex[2 * i + 1])) != c->ours[i]) {
            first = i;
            break;
        }
    CHECK_MSG(n == c->n && first == (size_t)-1, "%s: ours %zu bytes, reference %zu, first "
              "difference at %zd", c->name, c->n, n, first == (size_t)-1 ? (ssize_t)-1 : (ssize_t)first);
    if (n == c->n && first == (size_t)-1) fprintf(stderr, "  equal: %-60s %4zu bytes\n", c->name, n);
}

static void test_foxglove_equal(void)
{
    char marker[1024];
    snprintf(marker, sizeof marker, "%s/node_modules/@foxglove/rosmsg2-serialization", SP_NPM_DIR);
    if (access(marker, F_OK) != 0)
        TEST_SKIP("the reference serializer is not installed (ros/npm_setup skipped: no npm or "
                  "no registry)");
    json_cases = cJSON_CreateArray();
    for (int k = 0; k < 2; k++) {
        sp_ros_distro d = k ? SP_ROS_DISTRO_JAZZY : SP_ROS_DISTRO_HUMBLE;
        add_odometry(d);
        add_grid(d);
        add_path(d);
        add_goal_request(d);
        add_feedback(d);
        add_results(d);
        add_status_and_tf(d);
    }
    char path[1024];
    snprintf(path, sizeof path, "%s/cases.json", test_tmpdir("ros_wire"));
    char *text = cJSON_Print(json_cases);
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
    free(text);
    char *out = run_reference(path);
    CHECK(out != NULL);
    char *line = out;
    for (int i = 0; i < n_cases && line && *line; i++) {
        char *nl = strchr(line, '\n');
        size_t len = nl ? (size_t)(nl - line) : strlen(line);
        compare(&cases[i], line, len);
        line = nl ? nl + 1 : NULL;
    }
    for (int i = 0; i < n_cases; i++) free(cases[i].ours);
    free(out);
    cJSON_Delete(json_cases);
}

int main(void)
{
    RUN(test_foxglove_equal);
    return TEST_EXIT();
}
