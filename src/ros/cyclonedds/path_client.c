/* The ComputePathToPose client (Nav2's planner_server): one blocking call, goal then result
 * (requested right after acceptance: Jazzy's planner_server keeps results only 10 s). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bridge_internal.h"

typedef struct {
    sp_ros_bridge *b;
    int64_t goal_seq, result_seq;
    int answered, accepted, have_result;
    sp_ros_result_response result;
    sp_error decode_err;
    int decode_failed;
} path_call;

static void on_goal_reply(void *ctx, const uint8_t *bytes, size_t n, const dds_sample_info_t *i)
{
    path_call *c = ctx;
    sp_ros_goal_response r;
    (void)i;
    if (sp_ros_decode_goal_response(bytes, n, &r, &c->decode_err)) {
        c->decode_failed = 1;
        return;
    }
    if (r.header.seq != c->goal_seq) return;
    c->answered = 1;
    c->accepted = r.accepted;
}

static void on_result_reply(void *ctx, const uint8_t *bytes, size_t n, const dds_sample_info_t *i)
{
    path_call *c = ctx;
    sp_ros_result_response r;
    (void)i;
    if (sp_ros_decode_path_result_response(bytes, n, c->b->path.distro, &r, &c->decode_err)) {
        c->decode_failed = 1;
        return;
    }
    if (r.header.seq != c->result_seq || c->have_result) {
        sp_ros_result_response_free(&r);
        return;
    }
    c->result = r;
    c->have_result = 1;
}

static void write_goal(sp_ros_bridge *b, path_call *c, const sp_ros_pose *start,
                       const sp_ros_pose *goal, const char *planner_id, const uint8_t uuid[16])
{
    nav2_msgs_action_dds__ComputePathToPose_SendGoal_Request_ m;
    sp_ros_pose zero = {0, 0, 0, 0};
    double now = ros_wall_time();
    memset(&m, 0, sizeof m);
    m.guid = b->path.send_goal.guid;
    m.seq = c->goal_seq = ++b->path.send_goal.seq;
    memcpy(m.goal_id.uuid, uuid, 16);
    ros_fill_pose_stamped(&m.goal.goal, goal, b->map_frame, now);
    ros_fill_pose_stamped(&m.goal.start, start ? start : &zero, b->map_frame, now);
    m.goal.planner_id = (char *)(planner_id ? planner_id : "");
    m.goal.use_start = start != NULL;
    dds_write(b->path.send_goal.req_w, &m);
}

static int wait_for(sp_ros_bridge *b, path_call *c, const int *flag, double until)
{
    while (!*flag && ros_now() < until) {
        ros_client_take(&b->path.send_goal, on_goal_reply, c);
        ros_client_take(&b->path.get_result, on_result_reply, c);
        if (!*flag) ros_nap();
    }
    return *flag ? 0 : -1;
}

static int finished(sp_ros_bridge *b, path_call *c, sp_ros_path *path, double *planning_time_s,
                    sp_error *err)
{
    sp_ros_result_response *r = &c->result;
    if (r->status != SP_ROS_GOAL_SUCCEEDED) {
        /* Jazzy's planner codes 203..208 are 200 + nav's status (nav.h mirrors them) */
        int named = r->error_code >= 203 && r->error_code <= 208;
        int rc = sp_error_set(err, SP_E_NOTFOUND, "the planner on %s found no path: goal %s%s%s "
                              "(error_code %d%s%s)", b->path_fq,
                              sp_ros_goal_state_name((sp_ros_goal_state)r->status),
                              r->error_msg[0] ? ": " : "", r->error_msg, r->error_code,
                              named ? ": " : "",
                              named ? sp_nav_status_name(r->error_code - 200) : "");
        sp_ros_result_response_free(r);
        return rc;
    }
    *path = r->path;
    if (planning_time_s) *planning_time_s = r->planning_time_s;
    return 0;
}

int sp_ros_compute_path(sp_ros_bridge *b, const sp_ros_pose *start, const sp_ros_pose *goal,
                        const char *planner_id, double timeout_s, sp_ros_path *path,
                        double *planning_time_s, sp_error *err)
{
    if (!goal || !isfinite(goal->x) || !isfinite(goal->y) || !isfinite(goal->yaw) ||
        (start && (!isfinite(start->x) || !isfinite(start->y) || !isfinite(start->yaw))))
        return sp_error_set(err, SP_E_ARG, "compute_path: goal or start pose not finite");
    int rc = bridge_action(b, ROS_ACTION_PATH, err);
    if (rc) return rc;
    path_call c;
    memset(&c, 0, sizeof c);
    c.b = b;
    uint8_t uuid[16];
    bridge_uuid(uuid);
    double until = ros_now() + (timeout_s > 0 ? timeout_s : b->opt.server_timeout_s);
    write_goal(b, &c, start, goal, planner_id, uuid);
    if (wait_for(b, &c, &c.answered, until))
        return sp_error_set(err, SP_E_NET, "the planner on %s did not answer the goal in time%s%s",
                            b->path_fq, c.decode_failed ? ": " : "",
                            c.decode_failed ? c.decode_err.msg : "");
    if (!c.accepted)
        return sp_error_set(err, SP_E_NOTFOUND, "the planner on %s rejected the goal (%.2f, %.2f)",
                            b->path_fq, goal->x, goal->y);
    ros_goal_id_request m;
    m.guid = b->path.get_result.guid;
    m.seq = c.result_seq = ++b->path.get_result.seq;
    memcpy(m.goal_id.uuid, uuid, 16);
    dds_write(b->path.get_result.req_w, &m);
    if (wait_for(b, &c, &c.have_result, until))
        return sp_error_set(err, SP_E_NET, "the planner on %s gave no result within %.1f s%s%s",
                            b->path_fq, timeout_s, c.decode_failed ? ": " : "",
                            c.decode_failed ? c.decode_err.msg : "");
    return finished(b, &c, path, planning_time_s, err);
}
