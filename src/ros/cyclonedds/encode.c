/* Serialized bytes of what the bridge and the simulated robot write: the same fill functions,
 * then Cyclone's own serializer over the ops idlc generated (dds_stream_write, XCDR1,
 * little-endian), behind the CDR_LE encapsulation header. The wire tests compare these with an
 * independent serializer; on the wire Cyclone may add up to 3 padding bytes and record their
 * count in the header's options, which ROS readers ignore. */
#include <stdlib.h>
#include <string.h>

#include <dds/ddsi/ddsi_cdrstream.h>

#include "dds_internal.h"

#define XCDR1 1 /* CDR_ENC_VERSION_1 */

int ros_serialize(const dds_topic_descriptor_t *desc, const void *sample, uint8_t **out,
                  size_t *n, sp_error *err)
{
    dds_ostream_t os;
    dds_ostream_init(&os, 0, XCDR1);
    dds_stream_write(&os, sample, desc->m_ops);
    uint8_t *b = malloc(4 + (size_t)os.m_index);
    if (!b) {
        dds_ostream_fini(&os);
        return sp_error_set(err, SP_E_NOMEM, "serializing %s", desc->m_typename);
    }
    static const uint8_t cdr_le[4] = {0x00, 0x01, 0x00, 0x00};
    memcpy(b, cdr_le, 4);
    if (os.m_index) memcpy(b + 4, os.m_buffer, os.m_index);
    *out = b;
    *n = 4 + (size_t)os.m_index;
    dds_ostream_fini(&os);
    return 0;
}

int ros_encode_odometry(const sp_ros_odom *o, const double pose_cov[36],
                        const double twist_cov[36], uint8_t **out, size_t *n, sp_error *err)
{
    nav_msgs_msg_dds__Odometry_ m;
    ros_fill_odometry(&m, o, pose_cov, twist_cov);
    return ros_serialize(ros_type_descriptor(RT_ODOMETRY), &m, out, n, err);
}

int ros_encode_occupancy_grid(const sp_ros_grid *g, double stamp_s, uint8_t **out, size_t *n,
                              sp_error *err)
{
    nav_msgs_msg_dds__OccupancyGrid_ m;
    ros_fill_occupancy_grid(&m, g, g->frame_id, stamp_s);
    return ros_serialize(ros_type_descriptor(RT_OCCUPANCY_GRID), &m, out, n, err);
}

int ros_encode_path(const sp_ros_path *p, double stamp_s, uint8_t **out, size_t *n,
                    sp_error *err)
{
    nav_msgs_msg_dds__Path_ m;
    if (ros_fill_path(&m, p, p->frame_id, stamp_s)) return sp_error_set(err, SP_E_NOMEM, "path");
    int rc = ros_serialize(ros_type_descriptor(RT_PATH), &m, out, n, err);
    ros_unfill_path(&m);
    return rc;
}

int ros_encode_nav_goal_request(const sp_ros_goal_request *r, double stamp_s, uint8_t **out,
                                size_t *n, sp_error *err)
{
    nav2_msgs_action_dds__NavigateToPose_SendGoal_Request_ m;
    ros_fill_nav_goal_request(&m, r, stamp_s);
    return ros_serialize(ros_type_descriptor(RT_NAV_GOAL_REQ), &m, out, n, err);
}

int ros_encode_nav_feedback_message(const sp_ros_feedback_message *f, double stamp_s,
                                    uint8_t **out, size_t *n, sp_error *err)
{
    nav2_msgs_action_dds__NavigateToPose_FeedbackMessage_ m;
    ros_fill_nav_feedback_message(&m, f, stamp_s);
    return ros_serialize(ros_type_descriptor(RT_NAV_FEEDBACK), &m, out, n, err);
}

int ros_encode_nav_result_response(const sp_ros_result_response *r, sp_ros_distro distro,
                                   uint8_t **out, size_t *n, sp_error *err)
{
    if (distro == SP_ROS_DISTRO_JAZZY) {
        jazzy_nav2_msgs_action_dds__NavigateToPose_GetResult_Response_ m;
        ros_fill_nav_result_jazzy(&m, r);
        return ros_serialize(ros_type_descriptor(RT_NAV_RESULT_REP_JAZZY), &m, out, n, err);
    }
    humble_nav2_msgs_action_dds__NavigateToPose_GetResult_Response_ m;
    ros_fill_nav_result_humble(&m, r);
    return ros_serialize(ros_type_descriptor(RT_NAV_RESULT_REP_HUMBLE), &m, out, n, err);
}

int ros_encode_path_result_response(const sp_ros_result_response *r, sp_ros_distro distro,
                                    double stamp_s, uint8_t **out, size_t *n, sp_error *err)
{
    int rc;
    if (distro == SP_ROS_DISTRO_JAZZY) {
        jazzy_nav2_msgs_action_dds__ComputePathToPose_GetResult_Response_ m;
        if (ros_fill_path_result_jazzy(&m, r, stamp_s)) return sp_error_set(err, SP_E_NOMEM, "path");
        rc = ros_serialize(ros_type_descriptor(RT_PATH_RESULT_REP_JAZZY), &m, out, n, err);
        ros_unfill_path(&m.result.path);
        return rc;
    }
    humble_nav2_msgs_action_dds__ComputePathToPose_GetResult_Response_ m;
    if (ros_fill_path_result_humble(&m, r, stamp_s)) return sp_error_set(err, SP_E_NOMEM, "path");
    rc = ros_serialize(ros_type_descriptor(RT_PATH_RESULT_REP_HUMBLE), &m, out, n, err);
    ros_unfill_path(&m.result.path);
    return rc;
}

int ros_encode_goal_status_array(const sp_ros_status_array *a, uint8_t **out, size_t *n,
                                 sp_error *err)
{
    action_msgs_msg_dds__GoalStatusArray_ m;
    if (ros_fill_status_array(&m, a)) return sp_error_set(err, SP_E_NOMEM, "status array");
    int rc = ros_serialize(ros_type_descriptor(RT_STATUS_ARRAY), &m, out, n, err);
    ros_unfill_status_array(&m);
    return rc;
}

int ros_encode_tf(const sp_ros_transform *t, double stamp_s, uint8_t **out, size_t *n,
                  sp_error *err)
{
    tf2_msgs_msg_dds__TFMessage_ m;
    struct geometry_msgs_msg_dds__TransformStamped_ one;
    ros_fill_tf(&m, &one, t, stamp_s);
    return ros_serialize(ros_type_descriptor(RT_TF), &m, out, n, err);
}
