/* Plain values -> the IDL structs idlc generated, in one place, so that what the bridge and the
 * simulated robot write and what the wire tests serialize come from the same code. Strings point
 * into the inputs (Cyclone only reads them); sequences that need a different element layout are
 * allocated and freed by the matching ros_unfill_*. */
#include <stdlib.h>
#include <string.h>

#include "dds_internal.h"

void ros_fill_time(struct builtin_interfaces_msg_dds__Time_ *t, double seconds)
{
    ros_split_time(seconds, &t->sec, &t->nanosec);
}

static void fill_duration(struct builtin_interfaces_msg_dds__Duration_ *d, double seconds)
{
    ros_split_time(seconds, &d->sec, &d->nanosec);
}

void ros_fill_pose(struct geometry_msgs_msg_dds__Pose_ *p, const sp_ros_pose *pose)
{
    p->position.x = pose->x;
    p->position.y = pose->y;
    p->position.z = pose->z;
    sp_ros_yaw_quat(pose->yaw, &p->orientation.x, &p->orientation.y, &p->orientation.z,
                    &p->orientation.w);
}

static void fill_header(struct std_msgs_msg_dds__Header_ *h, const char *frame, double stamp_s)
{
    ros_fill_time(&h->stamp, stamp_s);
    h->frame_id = (char *)(frame ? frame : "");
}

void ros_fill_pose_stamped(struct geometry_msgs_msg_dds__PoseStamped_ *p, const sp_ros_pose *pose,
                           const char *frame, double stamp_s)
{
    fill_header(&p->header, frame, stamp_s);
    ros_fill_pose(&p->pose, pose);
}

void ros_fill_odometry(nav_msgs_msg_dds__Odometry_ *m, const sp_ros_odom *o,
                       const double pose_cov[36], const double twist_cov[36])
{
    memset(m, 0, sizeof *m);
    fill_header(&m->header, o->frame_id, o->stamp_s);
    m->child_frame_id = (char *)o->child_frame_id;
    m->pose.pose.position.x = o->pose.x;
    m->pose.pose.position.y = o->pose.y;
    m->pose.pose.position.z = o->pose.z;
    m->pose.pose.orientation.x = o->qx;
    m->pose.pose.orientation.y = o->qy;
    m->pose.pose.orientation.z = o->qz;
    m->pose.pose.orientation.w = o->qw;
    m->twist.twist.linear.x = o->vx;
    m->twist.twist.linear.y = o->vy;
    m->twist.twist.angular.z = o->wz;
    if (pose_cov) memcpy(m->pose.covariance, pose_cov, sizeof m->pose.covariance);
    if (twist_cov) memcpy(m->twist.covariance, twist_cov, sizeof m->twist.covariance);
}

/* The poses of a path as PoseStamped with the path's frame and stamp (as Nav2 fills them). */
static struct geometry_msgs_msg_dds__PoseStamped_ *fill_poses(const sp_ros_path *p,
                                                              const char *frame, double stamp_s)
{
    struct geometry_msgs_msg_dds__PoseStamped_ *ps = calloc(p->n ? p->n : 1, sizeof *ps);
    if (!ps) return NULL;
    for (size_t i = 0; i < p->n; i++) ros_fill_pose_stamped(&ps[i], &p->poses[i], frame, stamp_s);
    return ps;
}

int ros_fill_path(nav_msgs_msg_dds__Path_ *m, const sp_ros_path *p, const char *frame,
                  double stamp_s)
{
    memset(m, 0, sizeof *m);
    fill_header(&m->header, frame, stamp_s);
    m->poses._buffer = fill_poses(p, frame, stamp_s);
    if (!m->poses._buffer) return SP_E_NOMEM;
    m->poses._length = m->poses._maximum = (uint32_t)p->n;
    return 0;
}

void ros_unfill_path(nav_msgs_msg_dds__Path_ *m)
{
    free(m->poses._buffer);
    m->poses._buffer = NULL;
}

void ros_fill_occupancy_grid(nav_msgs_msg_dds__OccupancyGrid_ *m, const sp_ros_grid *g,
                             const char *frame, double stamp_s)
{
    memset(m, 0, sizeof *m);
    fill_header(&m->header, frame, stamp_s);
    ros_fill_time(&m->info.map_load_time, stamp_s);
    m->info.resolution = (float)g->resolution_m;
    m->info.width = (uint32_t)g->width;
    m->info.height = (uint32_t)g->height;
    sp_ros_pose origin = {g->origin_x, g->origin_y, 0, g->origin_yaw};
    ros_fill_pose(&m->info.origin, &origin);
    m->data._length = m->data._maximum = (uint32_t)((size_t)g->width * g->height);
    m->data._buffer = g->cells;
}

void ros_fill_nav_goal_request(nav2_msgs_action_dds__NavigateToPose_SendGoal_Request_ *m,
                               const sp_ros_goal_request *r, double stamp_s)
{
    memset(m, 0, sizeof *m);
    m->guid = r->header.guid;
    m->seq = r->header.seq;
    memcpy(m->goal_id.uuid, r->goal_id, 16);
    ros_fill_pose_stamped(&m->goal.pose, &r->pose, r->frame_id, stamp_s);
    m->goal.behavior_tree = (char *)r->behavior_tree;
}

void ros_fill_nav_feedback_message(nav2_msgs_action_dds__NavigateToPose_FeedbackMessage_ *m,
                                   const sp_ros_feedback_message *f, double stamp_s)
{
    const sp_ros_nav_feedback *fb = &f->feedback;
    memset(m, 0, sizeof *m);
    memcpy(m->goal_id.uuid, f->goal_id, 16);
    ros_fill_pose_stamped(&m->feedback.current_pose, &fb->current_pose, fb->current_frame,
                          stamp_s);
    fill_duration(&m->feedback.navigation_time, fb->navigation_time_s);
    fill_duration(&m->feedback.estimated_time_remaining, fb->eta_s);
    m->feedback.number_of_recoveries = (int16_t)fb->recoveries;
    m->feedback.distance_remaining = (float)fb->distance_remaining_m;
}

void ros_fill_tf(tf2_msgs_msg_dds__TFMessage_ *m,
                 struct geometry_msgs_msg_dds__TransformStamped_ *one, const sp_ros_transform *t,
                 double stamp_s)
{
    memset(m, 0, sizeof *m);
    memset(one, 0, sizeof *one);
    fill_header(&one->header, t->frame_id, stamp_s);
    one->child_frame_id = (char *)t->child_frame_id;
    one->transform.translation.x = t->x;
    one->transform.translation.y = t->y;
    one->transform.translation.z = t->z;
    one->transform.rotation.x = t->qx;
    one->transform.rotation.y = t->qy;
    one->transform.rotation.z = t->qz;
    one->transform.rotation.w = t->qw;
    m->transforms._buffer = one;
    m->transforms._length = m->transforms._maximum = 1;
}

void ros_fill_nav_result_humble(humble_nav2_msgs_action_dds__NavigateToPose_GetResult_Response_ *m,
                                const sp_ros_result_response *r)
{
    memset(m, 0, sizeof *m);
    m->guid = r->header.guid;
    m->seq = r->header.seq;
    m->status = (int8_t)r->status;
}

void ros_fill_nav_result_jazzy(jazzy_nav2_msgs_action_dds__NavigateToPose_GetResult_Response_ *m,
                               const sp_ros_result_response *r)
{
    memset(m, 0, sizeof *m);
    m->guid = r->header.guid;
    m->seq = r->header.seq;
    m->status = (int8_t)r->status;
    m->result.error_code = (uint16_t)r->error_code;
    m->result.error_msg = (char *)r->error_msg;
}

/* Both distros' ComputePathToPose results share the path and planning time. */
#define FILL_PATH_RESULT(m, r, stamp_s)                                                          \
    do {                                                                                       \
        memset(m, 0, sizeof *m);                                                               \
        m->guid = r->header.guid;                                                              \
        m->seq = r->header.seq;                                                                \
        m->status = (int8_t)r->status;                                                         \
        if (ros_fill_path(&m->result.path, &r->path, r->path.frame_id, stamp_s))               \
            return SP_E_NOMEM;                                                                 \
        fill_duration(&m->result.planning_time, r->planning_time_s);                           \
    } while (0)

int ros_fill_path_result_humble(
    humble_nav2_msgs_action_dds__ComputePathToPose_GetResult_Response_ *m,
    const sp_ros_result_response *r, double stamp_s)
{
    FILL_PATH_RESULT(m, r, stamp_s);
    return 0;
}

int ros_fill_path_result_jazzy(jazzy_nav2_msgs_action_dds__ComputePathToPose_GetResult_Response_ *m,
                               const sp_ros_result_response *r, double stamp_s)
{
    FILL_PATH_RESULT(m, r, stamp_s);
    m->result.error_code = (uint16_t)r->error_code;
    m->result.error_msg = (char *)r->error_msg;
    return 0;
}
#undef FILL_PATH_RESULT

int ros_fill_status_array(action_msgs_msg_dds__GoalStatusArray_ *m, const sp_ros_status_array *a)
{
    memset(m, 0, sizeof *m);
    struct action_msgs_msg_dds__GoalStatus_ *s = calloc(a->n ? a->n : 1, sizeof *s);
    if (!s) return SP_E_NOMEM;
    for (size_t i = 0; i < a->n; i++) {
        memcpy(s[i].goal_info.goal_id.uuid, a->entries[i].goal_id, 16);
        ros_fill_time(&s[i].goal_info.stamp, a->entries[i].stamp_s);
        s[i].status = (int8_t)a->entries[i].status;
    }
    m->status_list._buffer = s;
    m->status_list._length = m->status_list._maximum = (uint32_t)a->n;
    return 0;
}

void ros_unfill_status_array(action_msgs_msg_dds__GoalStatusArray_ *m)
{
    free(m->status_list._buffer);
    m->status_list._buffer = NULL;
}
