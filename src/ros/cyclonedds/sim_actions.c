/* The simulated robot's action servers, with rclcpp_action's semantics: NavigateToPose's
 * SendGoal accepts or rejects (sp_costmap_check_goal: a goal outside the map, occupied, unknown,
 * within the robot radius of an obstacle or unreachable is rejected); ComputePathToPose accepts
 * and aborts with Nav2's planner error codes when there is no path; a new NavigateToPose
 * goal preempts the running one (aborted), GetResult is answered when the goal is terminal (held
 * until then; unknown goals get STATUS_UNKNOWN), CancelGoal follows action_msgs' rules, and
 * GoalStatusArray is republished on every change. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sim_internal.h"

static const uint8_t zero_uuid[16];

static sim_goal *find(sim *s, ros_action_kind k, const uint8_t id[16])
{
    for (int i = 0; i < s->n_goals; i++)
        if (s->goals[i].kind == k && !memcmp(s->goals[i].uuid, id, 16)) return &s->goals[i];
    return NULL;
}

static void drop(sim *s, int i)
{
    sp_ros_result_response_free(&s->goals[i].result);
    if (s->active == i) s->active = -1;
    else if (s->active == s->n_goals - 1) s->active = i; /* the last goal moves into slot i */
    s->goals[i] = s->goals[--s->n_goals];
}

static sim_goal *new_goal(sim *s, ros_action_kind k, const uint8_t id[16])
{
    if (s->n_goals == SIM_MAX_GOALS) { /* make room: the oldest finished goal goes */
        int oldest = -1;
        for (int i = 0; i < s->n_goals; i++)
            if (s->goals[i].status >= SP_ROS_GOAL_SUCCEEDED &&
                (oldest < 0 || s->goals[i].finished_mono < s->goals[oldest].finished_mono))
                oldest = i;
        if (oldest < 0) return NULL;
        drop(s, oldest);
    }
    sim_goal *g = &s->goals[s->n_goals++];
    memset(g, 0, sizeof *g);
    g->kind = k;
    memcpy(g->uuid, id, 16);
    g->accepted_stamp = ros_wall_time();
    g->status = SP_ROS_GOAL_ACCEPTED;
    g->started_sim = s->sim_time;
    return g;
}

static void publish_status(sim *s, ros_action_kind k)
{
    sp_ros_goal_status_entry e[SIM_MAX_GOALS];
    sp_ros_status_array a = {0, e};
    for (int i = 0; i < s->n_goals; i++) {
        if (s->goals[i].kind != k) continue;
        memcpy(e[a.n].goal_id, s->goals[i].uuid, 16);
        e[a.n].stamp_s = s->goals[i].accepted_stamp;
        e[a.n].status = s->goals[i].status;
        a.n++;
    }
    action_msgs_msg_dds__GoalStatusArray_ m;
    if (ros_fill_status_array(&m, &a)) return;
    dds_write(k == ROS_ACTION_NAV ? s->nav.status_w : s->path.status_w, &m);
    ros_unfill_status_array(&m);
}

/* A lost reply leaves the client waiting out its timeout: say so in the robot's log. */
static void reply(sim *s, ros_server *srv, dds_instance_handle_t writer, const void *m)
{
    if (ros_server_reply(srv, writer, m))
        sp_logf(s->log, SP_LOG_WARN, "%s: reply dropped: the client is gone or its reply reader "
                "was not discovered within %.1f s", srv->fq, ROS_REPLY_WAIT_S);
}

static void send_result(sim *s, const sim_goal *g, const sim_waiting *w)
{
    sp_ros_result_response r = g->result;
    r.header = w->header;
    ros_server *srv = g->kind == ROS_ACTION_NAV ? &s->nav.get_result : &s->path.get_result;
    int jazzy = s->distro == SP_ROS_DISTRO_JAZZY;
    if (g->kind == ROS_ACTION_NAV && jazzy) {
        jazzy_nav2_msgs_action_dds__NavigateToPose_GetResult_Response_ m;
        ros_fill_nav_result_jazzy(&m, &r);
        reply(s, srv, w->writer, &m);
    } else if (g->kind == ROS_ACTION_NAV) {
        humble_nav2_msgs_action_dds__NavigateToPose_GetResult_Response_ m;
        ros_fill_nav_result_humble(&m, &r);
        reply(s, srv, w->writer, &m);
    } else if (jazzy) {
        jazzy_nav2_msgs_action_dds__ComputePathToPose_GetResult_Response_ m;
        if (ros_fill_path_result_jazzy(&m, &r, ros_wall_time())) return;
        reply(s, srv, w->writer, &m);
        ros_unfill_path(&m.result.path);
    } else {
        humble_nav2_msgs_action_dds__ComputePathToPose_GetResult_Response_ m;
        if (ros_fill_path_result_humble(&m, &r, ros_wall_time())) return;
        reply(s, srv, w->writer, &m);
        ros_unfill_path(&m.result.path);
    }
}

static void finish(sim *s, sim_goal *g, int status, int error_code, const char *msg)
{
    g->status = status;
    g->result.status = status;
    g->result.error_code = error_code;
    snprintf(g->result.error_msg, sizeof g->result.error_msg, "%s", msg ? msg : "");
    g->finished_mono = ros_now();
    for (int i = 0; i < g->n_waiting; i++) send_result(s, g, &g->waiting[i]);
    g->n_waiting = 0;
    publish_status(s, g->kind);
    sp_logf(s->log, SP_LOG_INFO, "%s goal to (%.2f, %.2f): %s%s%s", ros_action_type_name(g->kind),
            g->target.x, g->target.y, sp_ros_goal_state_name((sp_ros_goal_state)status),
            msg && msg[0] ? ": " : "", msg ? msg : "");
}

static void reply_goal(sim *s, ros_server *srv, const sp_ros_rpc_header *h,
                       dds_instance_handle_t writer, int accepted)
{
    /* NavigateToPose_ and ComputePathToPose_SendGoal_Response_ have the same layout. */
    nav2_msgs_action_dds__NavigateToPose_SendGoal_Response_ m;
    memset(&m, 0, sizeof m);
    m.guid = h->guid;
    m.seq = h->seq;
    m.accepted = accepted != 0;
    ros_fill_time(&m.stamp, ros_wall_time());
    reply(s, srv, writer, &m);
}

/* Goals are in the map frame, which the simulator takes as its odom frame; others are refused. */
static int frame_refused(const sim *s, const char *frame, sp_error *e)
{
    if (!frame[0] || !strcmp(frame, s->map_frame) || !strcmp(frame, s->odom_frame)) return 0;
    sp_error_set(e, SP_E_ARG, "frame '%s' is neither %s nor %s", frame, s->map_frame, s->odom_frame);
    return 1;
}

/* Plans from where the robot stands (or start) to the goal; *status is 0 with *path filled, or
 * the sp_nav_status why not (e says it). */
static void plan(sim *s, const sp_ros_pose *start, const sp_ros_pose *goal, sp_path *path,
                 int *status, sp_error *e)
{
    double from[3] = {s->drive.x, s->drive.y, s->drive.yaw};
    if (start) from[0] = start->x, from[1] = start->y, from[2] = start->yaw;
    if (ros_sim_plan(&s->cm, from, goal, path, status, e) && *status == SP_NAV_OK)
        *status = SP_NAV_NO_VALID_PATH; /* a bad argument or no memory: no path either way */
}

static void on_nav_goal(void *ctx, const uint8_t *bytes, size_t n, const dds_sample_info_t *info)
{
    sim *s = ctx;
    sp_ros_goal_request r;
    sp_error e = {0};
    if (sp_ros_decode_nav_goal_request(bytes, n, &r, &e)) {
        sp_logf(s->log, SP_LOG_WARN, "NavigateToPose: malformed goal ignored: %s", e.msg);
        return;
    }
    double *xy = NULL;
    size_t np = 0;
    sp_path p = {0};
    int status = SP_NAV_OK;
    if (!frame_refused(s, r.frame_id, &e)) plan(s, NULL, &r.pose, &p, &status, &e);
    if (!e.code && ros_sim_drive_path(&p, &r.pose, &xy, &np))
        sp_error_set(&e, SP_E_NOMEM, "out of memory");
    sp_path_free(&p);
    sim_goal *g = e.code ? NULL : new_goal(s, ROS_ACTION_NAV, r.goal_id);
    if (!g) {
        sp_logf(s->log, SP_LOG_INFO, "NavigateToPose goal (%.2f, %.2f) rejected: %s%s%s", r.pose.x,
                r.pose.y, status ? sp_nav_status_name(status) : "", status ? ": " : "",
                e.code ? e.msg : "too many goals");
        free(xy);
        reply_goal(s, &s->nav.send_goal, &r.header, info->publication_handle, 0);
        return;
    }
    g->target = r.pose;
    if (s->active >= 0) finish(s, &s->goals[s->active], SP_ROS_GOAL_ABORTED, 0, "preempted by a new goal");
    s->active = (int)(g - s->goals);
    ros_drive_follow(&s->drive, xy, np, r.pose.yaw);
    reply_goal(s, &s->nav.send_goal, &r.header, info->publication_handle, 1);
    g->status = SP_ROS_GOAL_EXECUTING;
    publish_status(s, ROS_ACTION_NAV);
    sp_logf(s->log, SP_LOG_INFO, "NavigateToPose goal (%.2f, %.2f, yaw %.2f) accepted: %zu "
            "corners, %.2f m", r.pose.x, r.pose.y, r.pose.yaw, np, ros_drive_remaining(&s->drive));
}

/* As Nav2's planner server: every goal is accepted, then it succeeds with the path or aborts
 * with the planner's error code (Jazzy) and a message saying why. */
static void on_path_goal(void *ctx, const uint8_t *bytes, size_t n, const dds_sample_info_t *info)
{
    sim *s = ctx;
    sp_ros_goal_request r;
    sp_error e = {0};
    if (sp_ros_decode_path_goal_request(bytes, n, &r, &e)) {
        sp_logf(s->log, SP_LOG_WARN, "ComputePathToPose: malformed goal ignored: %s", e.msg);
        return;
    }
    sim_goal *g = new_goal(s, ROS_ACTION_PATH, r.goal_id);
    if (!g) {
        sp_logf(s->log, SP_LOG_INFO, "ComputePathToPose goal (%.2f, %.2f) rejected: too many goals",
                r.pose.x, r.pose.y);
        reply_goal(s, &s->path.send_goal, &r.header, info->publication_handle, 0);
        return;
    }
    g->target = r.pose;
    reply_goal(s, &s->path.send_goal, &r.header, info->publication_handle, 1);
    double t0 = ros_now();
    sp_path p = {0};
    int status = SP_NAV_OK, code = 0;
    if (frame_refused(s, r.frame_id, &e) || (r.use_start && frame_refused(s, r.start_frame_id, &e)))
        code = 202; /* TF_ERROR */
    else plan(s, r.use_start ? &r.start : NULL, &r.pose, &p, &status, &e);
    if (!code && status) code = ROS_PATH_ERROR_CODE(status);
    if (!code && ros_sim_path_result(&p, &r.pose, s->map_frame, &g->result.path))
        code = 200, sp_error_set(&e, SP_E_NOMEM, "out of memory"); /* UNKNOWN */
    sp_path_free(&p);
    g->result.planning_time_s = ros_now() - t0;
    if (code) finish(s, g, SP_ROS_GOAL_ABORTED, code, e.msg);
    else finish(s, g, SP_ROS_GOAL_SUCCEEDED, 0, "");
}

typedef struct {
    sim *s;
    ros_action_kind kind;
} sim_ctx;

static void on_result_request(void *ctx, const uint8_t *bytes, size_t n,
                              const dds_sample_info_t *info)
{
    sim_ctx *c = ctx;
    sp_ros_goal_id_request r;
    sp_error e = {0};
    if (sp_ros_decode_goal_id_request(bytes, n, &r, &e)) return;
    sim_waiting w = {r.header, info->publication_handle};
    sim_goal *g = find(c->s, c->kind, r.goal_id);
    if (!g) { /* rclcpp_action: an unknown goal's result is STATUS_UNKNOWN at once */
        sim_goal unknown;
        memset(&unknown, 0, sizeof unknown);
        unknown.kind = c->kind;
        send_result(c->s, &unknown, &w);
    } else if (g->status >= SP_ROS_GOAL_SUCCEEDED) {
        send_result(c->s, g, &w);
    } else if (g->n_waiting < SIM_MAX_WAITING) {
        g->waiting[g->n_waiting++] = w;
    }
}

/* action_msgs/srv/CancelGoal: zero id and stamp cancel everything; a stamp cancels all goals
 * accepted at or before it; an id cancels that goal. */
static int cancel_matches(const sim_goal *g, const sp_ros_cancel_request *r)
{
    int by_id = memcmp(r->goal_id, zero_uuid, 16) != 0;
    if (!by_id && r->stamp_s == 0) return 1;
    if (by_id && !memcmp(g->uuid, r->goal_id, 16)) return 1;
    return r->stamp_s != 0 && g->accepted_stamp <= r->stamp_s;
}

static void on_cancel_request(void *ctx, const uint8_t *bytes, size_t n,
                              const dds_sample_info_t *info)
{
    sim_ctx *c = ctx;
    sim *s = c->s;
    sp_ros_cancel_request r;
    sp_error e = {0};
    if (sp_ros_decode_cancel_request(bytes, n, &r, &e)) return;
    struct action_msgs_msg_dds__GoalInfo_ canceling[SIM_MAX_GOALS];
    uint32_t k = 0;
    int found_terminal = 0;
    for (int i = 0; i < s->n_goals; i++) {
        sim_goal *g = &s->goals[i];
        if (g->kind != c->kind || !cancel_matches(g, &r)) continue;
        if (g->status >= SP_ROS_GOAL_SUCCEEDED) {
            found_terminal = 1;
            continue;
        }
        g->status = SP_ROS_GOAL_CANCELING;
        if (i == s->active) ros_drive_stop(&s->drive);
        memcpy(canceling[k].goal_id.uuid, g->uuid, 16);
        ros_fill_time(&canceling[k].stamp, g->accepted_stamp);
        k++;
    }
    action_msgs_srv_dds__CancelGoal_Response_ m;
    memset(&m, 0, sizeof m);
    m.guid = r.header.guid;
    m.seq = r.header.seq;
    int by_id = memcmp(r.goal_id, zero_uuid, 16) != 0;
    m.return_code = k ? 0 : found_terminal ? 3 : by_id ? 2 : 1;
    m.goals_canceling._buffer = canceling;
    m.goals_canceling._length = m.goals_canceling._maximum = k;
    reply(s, c->kind == ROS_ACTION_NAV ? &s->nav.cancel : &s->path.cancel,
          info->publication_handle, &m);
    if (k) {
        publish_status(s, c->kind);
        sp_logf(s->log, SP_LOG_INFO, "%s: canceling %u goal(s)", ros_action_type_name(c->kind), k);
    }
}

void sim_serve(sim *s)
{
    sim_ctx nav = {s, ROS_ACTION_NAV}, path = {s, ROS_ACTION_PATH};
    ros_server_take(&s->nav.send_goal, on_nav_goal, s);
    ros_server_take(&s->path.send_goal, on_path_goal, s);
    ros_server_take(&s->nav.get_result, on_result_request, &nav);
    ros_server_take(&s->path.get_result, on_result_request, &path);
    ros_server_take(&s->nav.cancel, on_cancel_request, &nav);
    ros_server_take(&s->path.cancel, on_cancel_request, &path);
}

void sim_goal_progress(sim *s, ros_drive_event ev)
{
    if (s->active < 0) return;
    sim_goal *g = &s->goals[s->active];
    if (ev == ROS_DRIVE_ARRIVED) {
        s->active = -1;
        finish(s, g, SP_ROS_GOAL_SUCCEEDED, 0, "");
    } else if (ev == ROS_DRIVE_STOPPED && g->status == SP_ROS_GOAL_CANCELING) {
        s->active = -1;
        finish(s, g, SP_ROS_GOAL_CANCELED, 0, "");
    } else if (ev == ROS_DRIVE_STOPPED) {
        s->active = -1;
        finish(s, g, SP_ROS_GOAL_ABORTED, 0, "the robot stopped before an obstacle");
    } else if (ros_sim_collides(&s->cm, s->drive.x, s->drive.y) && !s->drive.stopping) {
        ros_drive_stop(&s->drive); /* collision: stop; the goal aborts once at rest */
        sp_logf(s->log, SP_LOG_WARN, "collision at (%.2f, %.2f): stopping", s->drive.x, s->drive.y);
    }
}

void sim_feedback(sim *s)
{
    if (s->active < 0) return;
    sim_goal *g = &s->goals[s->active];
    sp_ros_feedback_message f;
    memset(&f, 0, sizeof f);
    memcpy(f.goal_id, g->uuid, 16);
    sp_ros_nav_feedback *fb = &f.feedback;
    fb->current_pose = (sp_ros_pose){s->drive.x, s->drive.y, 0, s->drive.yaw};
    snprintf(fb->current_frame, sizeof fb->current_frame, "%s", s->map_frame);
    fb->navigation_time_s = s->sim_time - g->started_sim;
    fb->distance_remaining_m = ros_drive_remaining(&s->drive);
    fb->eta_s = fb->distance_remaining_m / fmax(s->lim.max_speed, 1e-3);
    nav2_msgs_action_dds__NavigateToPose_FeedbackMessage_ m;
    ros_fill_nav_feedback_message(&m, &f, ros_wall_time());
    dds_write(s->nav.feedback_w, &m);
}

void sim_expire(sim *s)
{
    double now = ros_now();
    int changed[2] = {0, 0};
    for (int i = s->n_goals - 1; i >= 0; i--)
        if (s->goals[i].status >= SP_ROS_GOAL_SUCCEEDED &&
            now - s->goals[i].finished_mono > SIM_RESULT_KEEP_S) {
            changed[s->goals[i].kind] = 1;
            drop(s, i);
        }
    for (int k = 0; k < 2; k++)
        if (changed[k]) publish_status(s, (ros_action_kind)k);
}
