/* Without Cyclone DDS there is no serializer to compare: the wire tests skip on this. */
#include "ros/ros_internal.h"

#define ENCODE_STUB(name, ...)                                                                 \
    int name(__VA_ARGS__, uint8_t **out, size_t *n, sp_error *err)                             \
    {                                                                                          \
        (void)out, (void)n;                                                                    \
        return sp_error_set(err, SP_E_UNSUPPORTED, "no Cyclone DDS serializer in this build"); \
    }
ENCODE_STUB(ros_encode_odometry, const sp_ros_odom *o, const double pose_cov[36],
            const double twist_cov[36])
ENCODE_STUB(ros_encode_occupancy_grid, const sp_ros_grid *g, double stamp_s)
ENCODE_STUB(ros_encode_path, const sp_ros_path *p, double stamp_s)
ENCODE_STUB(ros_encode_nav_goal_request, const sp_ros_goal_request *r, double stamp_s)
ENCODE_STUB(ros_encode_nav_feedback_message, const sp_ros_feedback_message *m, double stamp_s)
ENCODE_STUB(ros_encode_nav_result_response, const sp_ros_result_response *r, sp_ros_distro d)
ENCODE_STUB(ros_encode_path_result_response, const sp_ros_result_response *r, sp_ros_distro d,
            double stamp_s)
ENCODE_STUB(ros_encode_goal_status_array, const sp_ros_status_array *a)
ENCODE_STUB(ros_encode_tf, const sp_ros_transform *t, double stamp_s)
