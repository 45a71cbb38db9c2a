/* The NavigateToPose client, as rclcpp_action drives an action: SendGoal with a fresh UUID, on
 * acceptance GetResult at once (Jazzy's rcl keeps results only 10 s by default), then feedback
 * and status filtered by the goal's UUID, and cancel through CancelGoal. Replies are matched by
 * the {guid, seq} header. All samples of the bridge's action readers are taken by one pump and
 * handed to the goal they belong to, so several goal handles can coexist. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/random.h>
#include <time.h>
#include <unistd.h>

#include "bridge_internal.h"

void bridge_uuid(uint8_t uuid[16])
{
    if (getrandom(uuid, 16, 0) != 16) { /* no entropy source: time, pid and a counter */
        static const uint64_t mix = 0x9e3779b97f4a7c15ull;
        struct timespec ts;
        clock_gettime(CLOCK_REALTIME, &ts);
        uint64_t a = (uint64_t)ts.tv_nsec * mix ^ (uint64_t)ts.tv_sec, b2 = (uint64_t)getpid() * mix;
        memcpy(uuid, &a, 8);
        memcpy(uuid + 8, &b2, 8);
    }
    uuid[6] = (uint8_t)((uuid[6] & 0x0f) | 0x40);
    uuid[8] = (uint8_t)((uuid[8] & 0x3f) | 0x80);
}

void bridge_bad_sample(sp_ros_bridge *b, const sp_error *e)
{
    b->bad_samples++;
    snprintf(b->bad_msg, sizeof b->bad_msg, "%s", e->msg);
}

int bridge_action(sp_ros_bridge *b, ros_action_kind kind, sp_error *err)
{
    ros_action_client *a = kind == ROS_ACTION_NAV ? &b->nav : &b->path;
    int *made = kind == ROS_ACTION_NAV ? &b->nav_made : &b->path_made;
    const char *fq = kind == ROS_ACTION_NAV ? b->nav_fq : b->path_fq;
    int rc;
    if (!*made) {
        if ((rc = ros_action_client_init(a, b->node, kind, fq, err))) {
            ros_action_client_fini(a, b->node);
            return rc;
        }
        *made = 1;
    }
    return ros_action_client_connect(a, b->node, ros_now() + b->opt.server_timeout_s,
                                     b->opt.domain_id, err);
}

static sp_ros_goal *find_by_uuid(sp_ros_bridge *b, const uint8_t id[16])
{
    for (int i = 0; i < b->n_goals; i++)
        if (!memcmp(b->goals[i]->uuid, id, 16)) return b->goals[i];
    return NULL;
}

/* ---- the pump ---- */

static void on_goal_reply(void *ctx, const uint8_t *bytes, size_t n, const dds_sample_info_t *i)
{
    sp_ros_bridge *b = ctx;
    sp_ros_goal_response r;
    sp_error e = {0};
    (void)i;
    if (sp_ros_decode_goal_response(bytes, n, &r, &e)) { bridge_bad_sample(b, &e); return; }
    for (int k = 0; k < b->n_goals; k++) {
        sp_ros_goal *g = b->goals[k];
        if (g->goal_seq != r.header.seq || g->answered) continue;
        g->answered = 1;
        g->accepted = r.accepted;
        g->st.state = r.accepted ? SP_ROS_GOAL_ACCEPTED : SP_ROS_GOAL_REJECTED;
        g->last_heard = ros_now();
    }
}

static void on_result_reply(void *ctx, const uint8_t *bytes, size_t n, const dds_sample_info_t *i)
{
    sp_ros_bridge *b = ctx;
    sp_ros_result_response r;
    sp_error e = {0};
    (void)i;
    if (sp_ros_decode_nav_result_response(bytes, n, b->nav.distro, &r, &e))
        { bridge_bad_sample(b, &e); return; }
    for (int k = 0; k < b->n_goals; k++) {
        sp_ros_goal *g = b->goals[k];
        if (g->result_seq != r.header.seq || g->st.have_result) continue;
        g->st.have_result = 1;
        g->st.error_code = r.error_code;
        snprintf(g->st.error_msg, sizeof g->st.error_msg, "%s", r.error_msg);
        if (r.status == 0) { /* rclcpp_action's answer for a goal it does not know (expired) */
            g->st.state = SP_ROS_GOAL_LOST;
            snprintf(g->st.error_msg, sizeof g->st.error_msg, "the server does not know this "
                     "goal (its result may have expired)");
        } else if (r.status >= SP_ROS_GOAL_SUCCEEDED) {
            g->st.state = (sp_ros_goal_state)r.status;
        }
        g->last_heard = ros_now();
    }
}

static void on_cancel_reply(void *ctx, const uint8_t *bytes, size_t n, const dds_sample_info_t *i)
{
    sp_ros_bridge *b = ctx;
    sp_ros_cancel_response r;
    sp_error e = {0};
    (void)i;
    if (sp_ros_decode_cancel_response(bytes, n, &r, &e)) { bridge_bad_sample(b, &e); return; }
    for (int k = 0; k < b->n_goals; k++)
        if (b->goals[k]->cancel_seq == r.header.seq) {
            b->goals[k]->cancel_answered = 1;
            b->goals[k]->cancel_code = r.return_code;
        }
}

static void on_feedback(void *ctx, const uint8_t *bytes, size_t n, const dds_sample_info_t *i)
{
    sp_ros_bridge *b = ctx;
    sp_ros_feedback_message m;
    sp_error e = {0};
    (void)i;
    if (sp_ros_decode_nav_feedback_message(bytes, n, &m, &e)) { bridge_bad_sample(b, &e); return; }
    sp_ros_goal *g = find_by_uuid(b, m.goal_id);
    if (!g) return; /* someone else's goal on the same server */
    g->st.feedback = m.feedback;
    g->st.feedback_count++;
    g->last_heard = ros_now();
    if (g->st.state == SP_ROS_GOAL_ACCEPTED) g->st.state = SP_ROS_GOAL_EXECUTING;
}

static void on_status(void *ctx, const uint8_t *bytes, size_t n, const dds_sample_info_t *i)
{
    sp_ros_bridge *b = ctx;
    sp_ros_status_array a;
    sp_error e = {0};
    (void)i;
    if (sp_ros_decode_goal_status_array(bytes, n, &a, &e)) { bridge_bad_sample(b, &e); return; }
    for (size_t k = 0; k < a.n; k++) {
        sp_ros_goal *g = find_by_uuid(b, a.entries[k].goal_id);
        if (!g || g->st.have_result || a.entries[k].status == 0) continue;
        g->st.state = (sp_ros_goal_state)a.entries[k].status;
        g->last_heard = ros_now();
        if (sp_ros_goal_state_terminal(g->st.state) && !g->terminal_since)
            g->terminal_since = ros_now();
    }
    sp_ros_status_array_free(&a);
}

static void pump(sp_ros_bridge *b)
{
    if (!b->nav_made) return;
    ros_client_take(&b->nav.send_goal, on_goal_reply, b);
    if (b->nav.have_result_client) ros_client_take(&b->nav.get_result, on_result_reply, b);
    ros_client_take(&b->nav.cancel, on_cancel_reply, b);
    ros_take_raw(b->nav.feedback_r, on_feedback, b, 256);
    ros_take_raw(b->nav.status_r, on_status, b, 64);
}

/* ---- goals ---- */

static int register_goal(sp_ros_bridge *b, sp_ros_goal *g, sp_error *err)
{
    if (b->n_goals >= BRIDGE_MAX_GOALS)
        return sp_error_set(err, SP_E_ARG, "more than %d goal handles alive; free finished ones",
                            BRIDGE_MAX_GOALS);
    b->goals[b->n_goals++] = g;
    g->b = b;
    return 0;
}

static void unregister_goal(sp_ros_goal *g)
{
    sp_ros_bridge *b = g->b;
    if (!b) return;
    for (int i = 0; i < b->n_goals; i++)
        if (b->goals[i] == g) {
            b->goals[i] = b->goals[--b->n_goals];
            break;
        }
    g->b = NULL;
}

static int send_goal(sp_ros_bridge *b, sp_ros_goal *g, const sp_ros_pose *pose, const char *bt)
{
    sp_ros_goal_request r;
    memset(&r, 0, sizeof r);
    r.header.guid = b->nav.send_goal.guid;
    r.header.seq = g->goal_seq = ++b->nav.send_goal.seq;
    memcpy(r.goal_id, g->uuid, 16);
    r.pose = *pose;
    snprintf(r.frame_id, sizeof r.frame_id, "%s", b->map_frame);
    snprintf(r.behavior_tree, sizeof r.behavior_tree, "%s", bt ? bt : "");
    nav2_msgs_action_dds__NavigateToPose_SendGoal_Request_ m;
    ros_fill_nav_goal_request(&m, &r, ros_wall_time());
    return dds_write(b->nav.send_goal.req_w, &m) < 0 ? SP_E_NET : 0;
}

static int request_result(sp_ros_bridge *b, sp_ros_goal *g)
{
    ros_goal_id_request m;
    m.guid = b->nav.get_result.guid;
    m.seq = g->result_seq = ++b->nav.get_result.seq;
    memcpy(m.goal_id.uuid, g->uuid, 16);
    return dds_write(b->nav.get_result.req_w, &m) < 0 ? SP_E_NET : 0;
}

int sp_ros_navigate_to(sp_ros_bridge *b, const sp_ros_pose *goal, const char *behavior_tree,
                       sp_ros_goal **out, sp_error *err)
{
    if (!goal || !isfinite(goal->x) || !isfinite(goal->y) || !isfinite(goal->z) ||
        !isfinite(goal->yaw))
        return sp_error_set(err, SP_E_ARG, "navigate_to: the goal pose is missing or not finite");
    double deadline = ros_now() + b->opt.server_timeout_s;
    int rc = bridge_action(b, ROS_ACTION_NAV, err);
    if (rc) return rc;
    sp_ros_goal *g = calloc(1, sizeof *g);
    if (!g) return sp_error_set(err, SP_E_NOMEM, "goal");
    bridge_uuid(g->uuid);
    if ((rc = register_goal(b, g, err))) {
        free(g);
        return rc;
    }
    if ((rc = send_goal(b, g, goal, behavior_tree))) {
        sp_error_set(err, rc, "navigate_to: writing the goal failed");
        goto fail;
    }
    while (!g->answered && ros_now() < deadline + 1.0) {
        pump(b);
        if (!g->answered) ros_nap();
    }
    if (!g->answered) {
        rc = sp_error_set(err, SP_E_NET, "the %s server on %s did not answer the goal within "
                          "%.1f s", "NavigateToPose", b->nav_fq, b->opt.server_timeout_s + 1.0);
        goto fail;
    }
    g->last_heard = ros_now();
    if (g->accepted && (rc = request_result(b, g))) {
        sp_error_set(err, rc, "navigate_to: requesting the result failed");
        goto fail;
    }
    *out = g;
    return 0;
fail:
    unregister_goal(g);
    free(g);
    return rc;
}

/* The server vanished: neither its result service nor its status topic is matched. */
static int server_gone(sp_ros_bridge *b)
{
    return ros_matched_writers(b->nav.status_r) == 0 &&
           ros_matched_writers(b->nav.get_result.rep_r) == 0;
}

int sp_ros_goal_poll(sp_ros_goal *g, sp_ros_goal_status *st, sp_error *err)
{
    sp_ros_bridge *b = g->b;
    if (!b) return sp_error_set(err, SP_E_ARG, "goal: its bridge was freed");
    pump(b);
    if (!sp_ros_goal_state_terminal(g->st.state) && g->accepted && server_gone(b)) {
        g->st.state = SP_ROS_GOAL_LOST;
        snprintf(g->st.error_msg, sizeof g->st.error_msg, "the %s server on %s went away%s%s",
                 "NavigateToPose", b->nav_fq, b->bad_samples ? "; last malformed sample: " : "",
                 b->bad_samples ? b->bad_msg : "");
    }
    g->st.age_s = ros_now() - g->last_heard;
    *st = g->st;
    return 0;
}

int sp_ros_goal_wait(sp_ros_goal *g, double timeout_s, sp_ros_goal_status *st,
                     void (*on_feedback_fn)(void *user, const sp_ros_goal_status *st), void *user,
                     sp_error *err)
{
    double until = ros_now() + (timeout_s > 0 ? timeout_s : 0);
    long seen = g->st.feedback_count;
    for (;;) {
        int rc = sp_ros_goal_poll(g, st, err);
        if (rc) return rc;
        if (on_feedback_fn && st->feedback_count != seen) on_feedback_fn(user, st);
        seen = st->feedback_count;
        int terminal = sp_ros_goal_state_terminal(st->state);
        /* Status can say "done" before the result arrives; wait a little for the result. */
        if (terminal && (st->have_result || st->state == SP_ROS_GOAL_LOST ||
                         st->state == SP_ROS_GOAL_REJECTED ||
                         (g->terminal_since && ros_now() - g->terminal_since > 2.0)))
            return 0;
        if (ros_now() >= until) return 0;
        ros_nap();
    }
}

int sp_ros_goal_cancel(sp_ros_goal *g, double timeout_s, sp_error *err)
{
    sp_ros_bridge *b = g->b;
    if (!b) return sp_error_set(err, SP_E_ARG, "goal: its bridge was freed");
    if (!g->accepted || sp_ros_goal_state_terminal(g->st.state)) return 0;
    action_msgs_srv_dds__CancelGoal_Request_ m;
    memset(&m, 0, sizeof m);
    m.guid = b->nav.cancel.guid;
    m.seq = g->cancel_seq = ++b->nav.cancel.seq;
    memcpy(m.goal_info.goal_id.uuid, g->uuid, 16); /* zero stamp: this goal only */
    g->cancel_answered = 0;
    if (dds_write(b->nav.cancel.req_w, &m) < 0)
        return sp_error_set(err, SP_E_NET, "cancel: writing the request failed");
    double until = ros_now() + (timeout_s > 0 ? timeout_s : 0);
    while (!g->cancel_answered && ros_now() < until) {
        pump(b);
        if (!g->cancel_answered) ros_nap();
    }
    if (!g->cancel_answered)
        return sp_error_set(err, SP_E_NET, "cancel: no answer from %s within %.1f s", b->nav_fq,
                            timeout_s);
    switch (g->cancel_code) {
    case 0: /* ERROR_NONE: canceling */
    case 3: /* ERROR_GOAL_TERMINATED: it finished meanwhile */
        return 0;
    case 1:
        return sp_error_set(err, SP_E_ARG, "cancel: the server refused to cancel the goal");
    default:
        if (sp_ros_goal_state_terminal(g->st.state)) return 0;
        return sp_error_set(err, SP_E_ARG, "cancel: the server does not know the goal");
    }
}

void sp_ros_goal_uuid(const sp_ros_goal *g, uint8_t uuid[16]) { memcpy(uuid, g->uuid, 16); }

void sp_ros_goal_free(sp_ros_goal *g)
{
    if (!g) return;
    unregister_goal(g);
    free(g);
}
