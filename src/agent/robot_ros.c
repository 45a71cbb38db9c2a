/* The ROS 2 robot (--ros): the ros module's bridge behind the agent's robot interface. The pose
 * is the map-frame pose (odometry composed with the localization's map -> odom); a goal is a Nav2
 * NavigateToPose goal to the plan's end (Nav2 plans its own path there: NavigateToPose carries
 * no path and no speed, so the plan the session issued decides where, the robot's controller
 * how); feedback, the result and cancelling come from the action. The issued plan is published
 * as nav_msgs/Path on the bridge's paths topic for RViz / Foxglove. Real time: the session waits
 * between polls. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "agent_internal.h"
#include "semsplat/ros.h"

#define CANCEL_WAIT_S 5.0
#define POSE_RETRY_S 1.0 /* a pose missing for a moment (a late tf) is waited for this long */

typedef struct ros_robot {
    sp_ros_bridge *bridge;
    sp_ros_goal *goal;
    int status;        /* sp_agent_goal_status of the goal being followed */
    char message[200];
    double t_sent;
} ros_robot;

static void nap(double s)
{
    struct timespec ts = {(time_t)s, (long)((s - (double)(time_t)s) * 1e9)};
    nanosleep(&ts, NULL);
}

/* The map pose, waiting up to wait_s for odometry and the map -> odom transform. */
static int pose_wait(ros_robot *r, double wait_s, sp_agent_pose *pose, sp_error *err)
{
    double until = sp_time_now() + wait_s;
    sp_ros_pose p;
    int rc;
    while ((rc = sp_ros_robot_pose(r->bridge, &p, NULL, err)) != 0 && sp_time_now() < until) nap(0.05);
    if (rc) return rc;
    pose->x = p.x, pose->y = p.y, pose->z = p.z, pose->yaw = p.yaw;
    return SP_OK;
}

static int ros_pose(void *ctx, sp_agent_pose *pose, sp_error *err)
{
    return pose_wait(ctx, POSE_RETRY_S, pose, err);
}

/* The plan as a nav_msgs/Path (best effort: a viewer's convenience, never a reason to fail). */
static void publish_plan(ros_robot *r, const sp_agent_goal *g)
{
    if (!g->waypoints || g->n_waypoints < 1) return;
    sp_ros_path path = {0};
    path.poses = malloc(sizeof *path.poses * (size_t)g->n_waypoints);
    if (!path.poses) return;
    for (int i = 0; i < g->n_waypoints; i++) {
        const double *w = g->waypoints + 4 * i;
        path.poses[i] = (sp_ros_pose){w[0], w[1], isfinite(w[2]) ? w[2] : 0, isfinite(w[3]) ? w[3] : 0};
    }
    path.n = (size_t)g->n_waypoints;
    sp_error e = {0};
    sp_ros_publish_paths(r->bridge, &path, 1, &e);
    free(path.poses);
}

static int ros_send(void *ctx, const sp_agent_goal *g, sp_error *err)
{
    ros_robot *r = ctx;
    sp_ros_goal_free(r->goal);
    r->goal = NULL;
    r->message[0] = 0;
    publish_plan(r, g);
    sp_ros_pose p = {g->pose.x, g->pose.y, 0, isfinite(g->pose.yaw) ? g->pose.yaw : 0};
    int rc = sp_ros_navigate_to(r->bridge, &p, NULL, &r->goal, err);
    if (rc) return rc;
    r->t_sent = sp_time_now();
    r->status = SP_AGENT_GOAL_ACTIVE;
    return SP_OK;
}

static int agent_status(sp_ros_goal_state s)
{
    switch (s) {
    case SP_ROS_GOAL_SUCCEEDED: return SP_AGENT_GOAL_SUCCEEDED;
    case SP_ROS_GOAL_CANCELED: return SP_AGENT_GOAL_CANCELED;
    case SP_ROS_GOAL_ABORTED:
    case SP_ROS_GOAL_LOST: return SP_AGENT_GOAL_ABORTED;
    case SP_ROS_GOAL_REJECTED: return SP_AGENT_GOAL_REJECTED;
    default: return SP_AGENT_GOAL_ACTIVE; /* unknown (not yet heard), accepted, executing, canceling */
    }
}

static int ros_poll(void *ctx, sp_agent_feedback *fb, sp_error *err)
{
    ros_robot *r = ctx;
    memset(fb, 0, sizeof *fb);
    int rc = ros_pose(r, &fb->pose, err);
    if (rc) return rc;
    if (!r->goal) {
        fb->status = SP_AGENT_GOAL_NONE;
        return SP_OK;
    }
    sp_ros_goal_status st;
    rc = sp_ros_goal_poll(r->goal, &st, err);
    if (rc) return rc;
    fb->status = agent_status(st.state);
    fb->feedback_count = st.feedback_count;
    fb->elapsed_s = sp_time_now() - r->t_sent;
    if (st.feedback_count > 0) {
        fb->distance_remaining_m = st.feedback.distance_remaining_m;
        fb->eta_s = st.feedback.eta_s;
        fb->recoveries = st.feedback.recoveries;
    }
    if (fb->status == SP_AGENT_GOAL_SUCCEEDED) fb->distance_remaining_m = 0;
    if (fb->status != SP_AGENT_GOAL_ACTIVE && fb->status != SP_AGENT_GOAL_SUCCEEDED)
        snprintf(r->message, sizeof r->message, "%s%s%s", sp_ros_goal_state_name(st.state),
                 st.error_msg[0] ? ": " : "", st.error_msg);
    snprintf(fb->message, sizeof fb->message, "%s", r->message);
    r->status = fb->status;
    return SP_OK;
}

static int ros_cancel(void *ctx, sp_error *err)
{
    ros_robot *r = ctx;
    if (!r->goal || r->status != SP_AGENT_GOAL_ACTIVE) return SP_OK;
    return sp_ros_goal_cancel(r->goal, CANCEL_WAIT_S, err);
}

static void ros_close(void *ctx)
{
    ros_robot *r = ctx;
    if (!r) return;
    sp_error e = {0};
    if (r->goal && r->status == SP_AGENT_GOAL_ACTIVE) sp_ros_goal_cancel(r->goal, 1.0, &e); /* never left driving */
    sp_ros_goal_free(r->goal);
    sp_ros_bridge_free(r->bridge);
    free(r);
}

static const sp_agent_robot_ops ros_ops = {"ros2", 1, ros_pose, ros_send, ros_poll, ros_cancel, ros_close};

int agent_robot_open_ros(sp_agent_robot *out, const sp_agent_config *cfg, sp_error *err)
{
    memset(out, 0, sizeof *out);
    ros_robot *r = calloc(1, sizeof *r);
    if (!r) return sp_error_set(err, SP_E_NOMEM, "ros robot: out of memory");
    sp_ros_options o = cfg->ros;
    if (!o.node_name) o.node_name = "semsplat_agent";
    int rc = sp_ros_bridge_create(&r->bridge, &o, err);
    sp_agent_pose p;
    double wait = isfinite(cfg->ros_wait_s) && cfg->ros_wait_s > 0 ? cfg->ros_wait_s : 10;
    if (!rc && (rc = pose_wait(r, wait, &p, err)))
        sp_error_prefix(err, "ros robot: no pose after %.0f s on domain %d (is the robot running, and "
                        "its localization publishing map -> odom?): ", wait, o.domain_id);
    if (rc) {
        ros_close(r);
        return rc;
    }
    out->ops = &ros_ops;
    out->ctx = r;
    return SP_OK;
}
