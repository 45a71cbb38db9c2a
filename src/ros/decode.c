/* Wire decoders, one per ROS 2 type semsplat reads (public: sp_ros_decode_* in ros.h). Each reads
 * the sample straight through with the bounds-checked reader of cdr.c, in the field order of the
 * .msg/.action definitions (Humble and Jazzy where they differ), and checks once at the end. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cdr.h"

/* Smallest wire size of a PoseStamped: stamp 8, empty frame_id 5, padding to 8 (3), pose 56. */
#define POSE_STAMPED_MIN 72

static int fail_numeric(cdr_in *in, const char *prefix, const char *field, double v)
{
    cdr_fail(in, prefix, field, "%g is not finite", v);
    in->failed = SP_E_NUMERIC;
    if (in->err) in->err->code = SP_E_NUMERIC;
    return -1;
}

int sp_ros_decode_odometry(const uint8_t *bytes, size_t size, sp_ros_odom *out, sp_error *err)
{
    memset(out, 0, sizeof *out); /* zeroed whatever happens (ros.h): a failed decode frees nothing unowned */
    cdr_in in;
    sp_ros_odom o;
    memset(&o, 0, sizeof o);
    if (cdr_begin(&in, bytes, size, "nav_msgs/Odometry", err)) return cdr_end(&in);
    double q[4], tw[6];
    static const char *tw_names[6] = {"linear.x",  "linear.y",  "linear.z",
                                      "angular.x", "angular.y", "angular.z"};
    cdr_header(&in, "header", &o.stamp_s, o.frame_id, sizeof o.frame_id);
    cdr_string(&in, NULL, "child_frame_id", o.child_frame_id, sizeof o.child_frame_id, 0);
    cdr_pose(&in, "pose.pose", &o.pose, q);
    cdr_skip_f64(&in, "pose", "covariance", 36);
    for (int i = 0; i < 6; i++)
        if (!cdr_f64(&in, "twist.twist", tw_names[i], &tw[i]) && !isfinite(tw[i]))
            fail_numeric(&in, "twist.twist", tw_names[i], tw[i]);
    cdr_skip_f64(&in, "twist", "covariance", 36);
    int rc = cdr_end(&in);
    if (rc) return rc;
    o.qx = q[0];
    o.qy = q[1];
    o.qz = q[2];
    o.qw = q[3];
    o.vx = tw[0];
    o.vy = tw[1];
    o.wz = tw[5];
    *out = o;
    return 0;
}

void sp_ros_path_free(sp_ros_path *p)
{
    if (!p) return;
    free(p->poses);
    p->poses = NULL;
    p->n = 0;
}

/* nav_msgs/Path from the reader's position (also the body of ComputePathToPose's result). */
static int read_path(cdr_in *in, const char *prefix, sp_ros_path *out)
{
    char p[64], frame[128];
    double stamp;
    size_t n;
    snprintf(p, sizeof p, "%s%sheader", prefix ? prefix : "", prefix ? "." : "");
    if (cdr_header(in, p, &stamp, out->frame_id, sizeof out->frame_id)) return -1;
    if (cdr_count(in, prefix, "poses", POSE_STAMPED_MIN, &n)) return -1;
    out->poses = n ? calloc(n, sizeof *out->poses) : NULL;
    if (n && !out->poses) {
        in->failed = SP_E_NOMEM;
        return sp_error_set(in->err, SP_E_NOMEM, "%s: %zu poses", in->type, n);
    }
    out->n = n;
    for (size_t i = 0; i < n; i++) {
        snprintf(p, sizeof p, "%s%sposes[%zu]", prefix ? prefix : "", prefix ? "." : "", i);
        if (cdr_pose_stamped(in, p, &out->poses[i], frame, sizeof frame)) return -1;
    }
    return 0;
}

int sp_ros_decode_path(const uint8_t *bytes, size_t size, sp_ros_path *out, sp_error *err)
{
    memset(out, 0, sizeof *out); /* zeroed whatever happens (ros.h): a failed decode frees nothing unowned */
    cdr_in in;
    sp_ros_path path;
    memset(&path, 0, sizeof path);
    if (cdr_begin(&in, bytes, size, "nav_msgs/Path", err)) return cdr_end(&in);
    read_path(&in, NULL, &path);
    int rc = cdr_end(&in);
    if (rc) {
        sp_ros_path_free(&path);
        return rc;
    }
    *out = path;
    return 0;
}

void sp_ros_grid_free(sp_ros_grid *g)
{
    if (!g) return;
    free(g->cells);
    g->cells = NULL;
    g->width = g->height = 0;
}

static int read_map_info(cdr_in *in, sp_ros_grid *g)
{
    double load_time, q[4];
    float res;
    uint32_t w, h;
    sp_ros_pose origin;
    cdr_time(in, "info.map_load_time", &load_time);
    cdr_f32(in, "info", "resolution", &res);
    cdr_u32(in, "info", "width", &w);
    cdr_u32(in, "info", "height", &h);
    if (cdr_pose(in, "info.origin", &origin, q)) return -1;
    if (!(res > 0) || !isfinite(res))
        return cdr_fail(in, "info", "resolution", "%g is not a positive size", (double)res);
    if (w > 1u << 20 || h > 1u << 20 || (uint64_t)w * h > (1u << 30))
        return cdr_fail(in, "info", "width", "%u x %u cells is beyond 2^30", w, h);
    g->resolution_m = res;
    g->width = (int)w;
    g->height = (int)h;
    g->origin_x = origin.x;
    g->origin_y = origin.y;
    g->origin_yaw = origin.yaw;
    return 0;
}

int sp_ros_decode_occupancy_grid(const uint8_t *bytes, size_t size, sp_ros_grid *out,
                                 sp_error *err)
{
    memset(out, 0, sizeof *out); /* zeroed whatever happens (ros.h): a failed decode frees nothing unowned */
    cdr_in in;
    sp_ros_grid g;
    double stamp;
    size_t n = 0;
    memset(&g, 0, sizeof g);
    if (cdr_begin(&in, bytes, size, "nav_msgs/OccupancyGrid", err)) return cdr_end(&in);
    cdr_header(&in, "header", &stamp, g.frame_id, sizeof g.frame_id);
    if (!read_map_info(&in, &g) && !cdr_count(&in, NULL, "data", 1, &n)) {
        if (n != (size_t)g.width * (size_t)g.height)
            cdr_fail(&in, NULL, "data", "%zu cells for a %d x %d grid", n, g.width, g.height);
        else if (n && !(g.cells = malloc(n)))
            in.failed = sp_error_set(err, SP_E_NOMEM, "nav_msgs/OccupancyGrid: %zu cells", n);
        else if (!cdr_bytes(&in, NULL, "data", g.cells, n))
            for (size_t i = 0; i < n; i++)
                if (g.cells[i] < -1 || g.cells[i] > 100) {
                    cdr_fail(&in, NULL, "data", "cell %zu is %d (-1 unknown, 0..100 expected)",
                             i, g.cells[i]);
                    break;
                }
    }
    int rc = cdr_end(&in);
    if (rc) {
        sp_ros_grid_free(&g);
        return rc;
    }
    *out = g;
    return 0;
}

/* tf2 frame ids carry no leading '/' in ROS 2; ROS 1 bags and old code may add one. */
static int same_frame(const char *a, const char *b)
{
    return !strcmp(a + (a[0] == '/'), b + (b[0] == '/'));
}

/* Reads a TFMessage through; keeps the first transform, or the first parent -> child one. */
static int decode_tf(const uint8_t *bytes, size_t size, const char *parent, const char *child,
                     sp_ros_transform *out, int *found, sp_error *err)
{
    static const char *names[7] = {"translation.x", "translation.y", "translation.z",
                                   "rotation.x",    "rotation.y",    "rotation.z", "rotation.w"};
    cdr_in in;
    sp_ros_transform t, keep;
    size_t n = 0;
    memset(&keep, 0, sizeof keep);
    *found = 0;
    if (cdr_begin(&in, bytes, size, "tf2_msgs/TFMessage", err)) return cdr_end(&in);
    /* TransformStamped: header 13 + child_frame_id 5 + padding 6 + transform 56 at least. */
    cdr_count(&in, NULL, "transforms", 80, &n);
    for (size_t i = 0; i < n && !in.failed; i++) {
        char p[64];
        double stamp, v[7];
        memset(&t, 0, sizeof t);
        snprintf(p, sizeof p, "transforms[%zu].header", i);
        cdr_header(&in, p, &stamp, t.frame_id, sizeof t.frame_id);
        snprintf(p, sizeof p, "transforms[%zu]", i);
        cdr_string(&in, p, "child_frame_id", t.child_frame_id, sizeof t.child_frame_id, 0);
        snprintf(p, sizeof p, "transforms[%zu].transform", i);
        for (int k = 0; k < 7 && !in.failed; k++)
            if (!cdr_f64(&in, p, names[k], &v[k]) && !isfinite(v[k]))
                fail_numeric(&in, p, names[k], v[k]);
        int wanted = parent ? same_frame(t.frame_id, parent) && same_frame(t.child_frame_id, child)
                            : i == 0;
        if (wanted && !*found && !in.failed) {
            keep = t;
            keep.x = v[0], keep.y = v[1], keep.z = v[2];
            keep.qx = v[3], keep.qy = v[4], keep.qz = v[5], keep.qw = v[6];
            *found = 1;
        }
    }
    int rc = cdr_end(&in);
    if (rc) return rc;
    keep.n_transforms = n;
    *out = keep;
    return 0;
}

int sp_ros_decode_tf_message(const uint8_t *bytes, size_t size, sp_ros_transform *out,
                             sp_error *err)
{
    memset(out, 0, sizeof *out); /* zeroed whatever happens (ros.h): a failed decode frees nothing unowned */
    int found;
    return decode_tf(bytes, size, NULL, NULL, out, &found, err);
}

int sp_ros_decode_tf_find(const uint8_t *bytes, size_t size, const char *parent,
                          const char *child, sp_ros_transform *out, sp_error *err)
{
    memset(out, 0, sizeof *out); /* zeroed whatever happens (ros.h): a failed decode frees nothing unowned */
    int found;
    if (!parent || !child) return sp_error_set(err, SP_E_ARG, "tf: parent and child frames needed");
    sp_ros_transform t;
    int rc = decode_tf(bytes, size, parent, child, &t, &found, err);
    if (rc) return rc;
    if (!found)
        return sp_error_set(err, SP_E_NOTFOUND, "tf2_msgs/TFMessage: no %s -> %s among its %zu "
                            "transforms", parent, child, t.n_transforms);
    *out = t;
    return 0;
}

static int read_status(cdr_in *in, const char *prefix, int *status)
{
    int8_t s;
    if (cdr_i8(in, prefix, "status", &s)) return -1;
    if (s < 0 || s > 6) return cdr_fail(in, prefix, "status", "%d is not a GoalStatus (0..6)", s);
    *status = s;
    return 0;
}

int sp_ros_decode_nav_goal_request(const uint8_t *bytes, size_t size, sp_ros_goal_request *out,
                                   sp_error *err)
{
    memset(out, 0, sizeof *out); /* zeroed whatever happens (ros.h): a failed decode frees nothing unowned */
    cdr_in in;
    sp_ros_goal_request r;
    memset(&r, 0, sizeof r);
    if (cdr_begin(&in, bytes, size, "nav2_msgs/action/NavigateToPose_SendGoal_Request", err))
        return cdr_end(&in);
    cdr_rpc_header(&in, &r.header);
    cdr_bytes(&in, NULL, "goal_id", r.goal_id, 16);
    cdr_pose_stamped(&in, "goal.pose", &r.pose, r.frame_id, sizeof r.frame_id);
    cdr_string(&in, "goal", "behavior_tree", r.behavior_tree, sizeof r.behavior_tree, 1);
    int rc = cdr_end(&in);
    if (!rc) *out = r;
    return rc;
}

int sp_ros_decode_path_goal_request(const uint8_t *bytes, size_t size, sp_ros_goal_request *out,
                                    sp_error *err)
{
    memset(out, 0, sizeof *out); /* zeroed whatever happens (ros.h): a failed decode frees nothing unowned */
    cdr_in in;
    sp_ros_goal_request r;
    memset(&r, 0, sizeof r);
    if (cdr_begin(&in, bytes, size, "nav2_msgs/action/ComputePathToPose_SendGoal_Request", err))
        return cdr_end(&in);
    cdr_rpc_header(&in, &r.header);
    cdr_bytes(&in, NULL, "goal_id", r.goal_id, 16);
    cdr_pose_stamped(&in, "goal.goal", &r.pose, r.frame_id, sizeof r.frame_id);
    cdr_pose_stamped(&in, "goal.start", &r.start, r.start_frame_id, sizeof r.start_frame_id);
    cdr_string(&in, "goal", "planner_id", r.behavior_tree, sizeof r.behavior_tree, 1);
    cdr_bool(&in, "goal", "use_start", &r.use_start);
    int rc = cdr_end(&in);
    if (!rc) *out = r;
    return rc;
}

int sp_ros_decode_goal_response(const uint8_t *bytes, size_t size, sp_ros_goal_response *out,
                                sp_error *err)
{
    memset(out, 0, sizeof *out); /* zeroed whatever happens (ros.h): a failed decode frees nothing unowned */
    cdr_in in;
    sp_ros_goal_response r;
    memset(&r, 0, sizeof r);
    if (cdr_begin(&in, bytes, size, "SendGoal_Response", err)) return cdr_end(&in);
    cdr_rpc_header(&in, &r.header);
    cdr_bool(&in, NULL, "accepted", &r.accepted);
    cdr_time(&in, "stamp", &r.stamp_s);
    int rc = cdr_end(&in);
    if (!rc) *out = r;
    return rc;
}

int sp_ros_decode_goal_id_request(const uint8_t *bytes, size_t size, sp_ros_goal_id_request *out,
                                  sp_error *err)
{
    memset(out, 0, sizeof *out); /* zeroed whatever happens (ros.h): a failed decode frees nothing unowned */
    cdr_in in;
    sp_ros_goal_id_request r;
    memset(&r, 0, sizeof r);
    if (cdr_begin(&in, bytes, size, "GetResult_Request", err)) return cdr_end(&in);
    cdr_rpc_header(&in, &r.header);
    cdr_bytes(&in, NULL, "goal_id", r.goal_id, 16);
    int rc = cdr_end(&in);
    if (!rc) *out = r;
    return rc;
}

static int check_distro(sp_ros_distro distro, const char *what, sp_error *err)
{
    if (distro == SP_ROS_DISTRO_HUMBLE || distro == SP_ROS_DISTRO_JAZZY) return 0;
    return sp_error_set(err, SP_E_ARG, "%s: the layout depends on the distro; pass humble or "
                        "jazzy, not %s", what, sp_ros_distro_name(distro));
}

/* Jazzy's result tail: uint16 error_code, string error_msg. */
static void read_error_fields(cdr_in *in, sp_ros_result_response *r)
{
    uint16_t code;
    if (!cdr_u16(in, "result", "error_code", &code)) r->error_code = code;
    cdr_string(in, "result", "error_msg", r->error_msg, sizeof r->error_msg, 1);
}

int sp_ros_decode_nav_result_response(const uint8_t *bytes, size_t size, sp_ros_distro distro,
                                      sp_ros_result_response *out, sp_error *err)
{
    memset(out, 0, sizeof *out); /* zeroed whatever happens (ros.h): a failed decode frees nothing unowned */
    const char *type = "nav2_msgs/action/NavigateToPose_GetResult_Response";
    if (check_distro(distro, type, err)) return SP_E_ARG;
    cdr_in in;
    sp_ros_result_response r;
    memset(&r, 0, sizeof r);
    if (cdr_begin(&in, bytes, size, type, err)) return cdr_end(&in);
    cdr_rpc_header(&in, &r.header);
    read_status(&in, NULL, &r.status);
    if (distro == SP_ROS_DISTRO_HUMBLE) {
        uint8_t empty;
        cdr_u8(&in, "result.result", "structure_needs_at_least_one_member", &empty);
    } else {
        read_error_fields(&in, &r);
    }
    int rc = cdr_end(&in);
    if (!rc) *out = r;
    return rc;
}

int sp_ros_decode_path_result_response(const uint8_t *bytes, size_t size, sp_ros_distro distro,
                                       sp_ros_result_response *out, sp_error *err)
{
    memset(out, 0, sizeof *out); /* zeroed whatever happens (ros.h): a failed decode frees nothing unowned */
    const char *type = "nav2_msgs/action/ComputePathToPose_GetResult_Response";
    if (check_distro(distro, type, err)) return SP_E_ARG;
    cdr_in in;
    sp_ros_result_response r;
    memset(&r, 0, sizeof r);
    if (cdr_begin(&in, bytes, size, type, err)) return cdr_end(&in);
    cdr_rpc_header(&in, &r.header);
    read_status(&in, NULL, &r.status);
    read_path(&in, "result.path", &r.path);
    cdr_duration(&in, "result.planning_time", &r.planning_time_s);
    if (distro == SP_ROS_DISTRO_JAZZY) read_error_fields(&in, &r);
    int rc = cdr_end(&in);
    if (rc) {
        sp_ros_result_response_free(&r);
        return rc;
    }
    *out = r;
    return 0;
}

void sp_ros_result_response_free(sp_ros_result_response *r)
{
    if (r) sp_ros_path_free(&r->path);
}

int sp_ros_decode_nav_feedback_message(const uint8_t *bytes, size_t size,
                                       sp_ros_feedback_message *out, sp_error *err)
{
    memset(out, 0, sizeof *out); /* zeroed whatever happens (ros.h): a failed decode frees nothing unowned */
    cdr_in in;
    sp_ros_feedback_message m;
    memset(&m, 0, sizeof m);
    if (cdr_begin(&in, bytes, size, "nav2_msgs/action/NavigateToPose_FeedbackMessage", err))
        return cdr_end(&in);
    sp_ros_nav_feedback *f = &m.feedback;
    int16_t rec;
    float dist;
    cdr_bytes(&in, NULL, "goal_id", m.goal_id, 16);
    cdr_pose_stamped(&in, "feedback.current_pose", &f->current_pose, f->current_frame,
                     sizeof f->current_frame);
    cdr_duration(&in, "feedback.navigation_time", &f->navigation_time_s);
    cdr_duration(&in, "feedback.estimated_time_remaining", &f->eta_s);
    if (!cdr_i16(&in, "feedback", "number_of_recoveries", &rec)) f->recoveries = rec;
    if (!cdr_f32(&in, "feedback", "distance_remaining", &dist)) {
        if (!isfinite(dist)) fail_numeric(&in, "feedback", "distance_remaining", dist);
        f->distance_remaining_m = dist;
    }
    int rc = cdr_end(&in);
    if (!rc) *out = m;
    return rc;
}

void sp_ros_status_array_free(sp_ros_status_array *a)
{
    if (!a) return;
    free(a->entries);
    a->entries = NULL;
    a->n = 0;
}

/* action_msgs/GoalInfo: uuid then stamp. */
static int read_goal_info(cdr_in *in, const char *prefix, uint8_t id[16], double *stamp)
{
    char p[64];
    if (cdr_bytes(in, prefix, "goal_id", id, 16)) return -1;
    snprintf(p, sizeof p, "%s.stamp", prefix);
    return cdr_time(in, p, stamp);
}

int sp_ros_decode_goal_status_array(const uint8_t *bytes, size_t size, sp_ros_status_array *out,
                                    sp_error *err)
{
    memset(out, 0, sizeof *out); /* zeroed whatever happens (ros.h): a failed decode frees nothing unowned */
    cdr_in in;
    sp_ros_status_array a;
    size_t n = 0;
    memset(&a, 0, sizeof a);
    if (cdr_begin(&in, bytes, size, "action_msgs/GoalStatusArray", err)) return cdr_end(&in);
    if (!cdr_count(&in, NULL, "status_list", 25, &n) && n) {
        a.entries = calloc(n, sizeof *a.entries);
        if (!a.entries) in.failed = sp_error_set(err, SP_E_NOMEM, "GoalStatusArray: %zu", n);
        else a.n = n;
    }
    for (size_t i = 0; i < a.n && !in.failed; i++) {
        char p[48];
        snprintf(p, sizeof p, "status_list[%zu].goal_info", i);
        read_goal_info(&in, p, a.entries[i].goal_id, &a.entries[i].stamp_s);
        snprintf(p, sizeof p, "status_list[%zu]", i);
        read_status(&in, p, &a.entries[i].status);
    }
    int rc = cdr_end(&in);
    if (rc) {
        sp_ros_status_array_free(&a);
        return rc;
    }
    *out = a;
    return 0;
}

int sp_ros_decode_cancel_request(const uint8_t *bytes, size_t size, sp_ros_cancel_request *out,
                                 sp_error *err)
{
    memset(out, 0, sizeof *out); /* zeroed whatever happens (ros.h): a failed decode frees nothing unowned */
    cdr_in in;
    sp_ros_cancel_request r;
    memset(&r, 0, sizeof r);
    if (cdr_begin(&in, bytes, size, "action_msgs/srv/CancelGoal_Request", err))
        return cdr_end(&in);
    cdr_rpc_header(&in, &r.header);
    read_goal_info(&in, "goal_info", r.goal_id, &r.stamp_s);
    int rc = cdr_end(&in);
    if (!rc) *out = r;
    return rc;
}

int sp_ros_decode_cancel_response(const uint8_t *bytes, size_t size, sp_ros_cancel_response *out,
                                  sp_error *err)
{
    memset(out, 0, sizeof *out); /* zeroed whatever happens (ros.h): a failed decode frees nothing unowned */
    cdr_in in;
    sp_ros_cancel_response r;
    int8_t code;
    size_t n = 0;
    memset(&r, 0, sizeof r);
    if (cdr_begin(&in, bytes, size, "action_msgs/srv/CancelGoal_Response", err))
        return cdr_end(&in);
    cdr_rpc_header(&in, &r.header);
    if (!cdr_i8(&in, NULL, "return_code", &code)) {
        if (code < 0 || code > 3)
            cdr_fail(&in, NULL, "return_code", "%d is not 0..3", code);
        r.return_code = code;
    }
    cdr_count(&in, NULL, "goals_canceling", 24, &n);
    for (size_t i = 0; i < n && !in.failed; i++) {
        char p[48];
        uint8_t id[16];
        double stamp;
        snprintf(p, sizeof p, "goals_canceling[%zu]", i);
        if (!read_goal_info(&in, p, id, &stamp) && i == 0) memcpy(r.first_goal_id, id, 16);
    }
    r.n_canceling = n;
    int rc = cdr_end(&in);
    if (!rc) *out = r;
    return rc;
}
