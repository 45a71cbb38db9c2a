/* Built when Cyclone DDS (cyclonedds-dev, idlc) was not found: every function that needs DDS
 * fails with SP_E_UNSUPPORTED naming the package. Names, the decoders, the map loader and the
 * planner work without it. */
#include <string.h>

#include "ros/ros_internal.h"

static int unsupported(sp_error *err)
{
    return sp_error_set(err, SP_E_UNSUPPORTED, "ROS 2 needs Cyclone DDS: this semsplat was built "
                        "without it (install cyclonedds-dev, which brings idlc, and rebuild)");
}

int sp_ros_bridge_create(sp_ros_bridge **out, const sp_ros_options *opt, sp_error *err)
{
    (void)out, (void)opt;
    return unsupported(err);
}
void sp_ros_bridge_free(sp_ros_bridge *b) { (void)b; }
sp_ros_distro sp_ros_bridge_distro(sp_ros_bridge *b)
{
    (void)b;
    return SP_ROS_DISTRO_AUTO;
}
int sp_ros_odom_latest(sp_ros_bridge *b, sp_ros_odom *out, double *age_s, sp_error *err)
{
    (void)b, (void)out, (void)age_s;
    return unsupported(err);
}
int sp_ros_odom_wait(sp_ros_bridge *b, double timeout_s, sp_ros_odom *out, sp_error *err)
{
    (void)b, (void)timeout_s, (void)out;
    return unsupported(err);
}
int sp_ros_robot_pose(sp_ros_bridge *b, sp_ros_pose *map_pose, double *age_s, sp_error *err)
{
    (void)b, (void)map_pose, (void)age_s;
    return unsupported(err);
}
int sp_ros_navigate_to(sp_ros_bridge *b, const sp_ros_pose *goal, const char *behavior_tree,
                       sp_ros_goal **out, sp_error *err)
{
    (void)b, (void)goal, (void)behavior_tree, (void)out;
    return unsupported(err);
}
int sp_ros_goal_poll(sp_ros_goal *g, sp_ros_goal_status *st, sp_error *err)
{
    (void)g, (void)st;
    return unsupported(err);
}
int sp_ros_goal_wait(sp_ros_goal *g, double timeout_s, sp_ros_goal_status *st,
                     void (*on_feedback)(void *user, const sp_ros_goal_status *st), void *user,
                     sp_error *err)
{
    (void)g, (void)timeout_s, (void)st, (void)on_feedback, (void)user;
    return unsupported(err);
}
int sp_ros_goal_cancel(sp_ros_goal *g, double timeout_s, sp_error *err)
{
    (void)g, (void)timeout_s;
    return unsupported(err);
}
void sp_ros_goal_uuid(const sp_ros_goal *g, uint8_t uuid[16])
{
    (void)g;
    memset(uuid, 0, 16);
}
void sp_ros_goal_free(sp_ros_goal *g) { (void)g; }
int sp_ros_compute_path(sp_ros_bridge *b, const sp_ros_pose *start, const sp_ros_pose *goal,
                        const char *planner_id, double timeout_s, sp_ros_path *path,
                        double *planning_time_s, sp_error *err)
{
    (void)b, (void)start, (void)goal, (void)planner_id, (void)timeout_s, (void)path,
        (void)planning_time_s;
    return unsupported(err);
}
int sp_ros_publish_map(sp_ros_bridge *b, const sp_ros_grid *grid, sp_error *err)
{
    (void)b, (void)grid;
    return unsupported(err);
}
int sp_ros_publish_paths(sp_ros_bridge *b, const sp_ros_path *paths, int n, sp_error *err)
{
    (void)b, (void)paths, (void)n;
    return unsupported(err);
}
int sp_ros_sim_run(const sp_ros_sim_options *o, const volatile sig_atomic_t *stop,
                   const sp_log *log, sp_error *err)
{
    (void)o, (void)stop, (void)log;
    return unsupported(err);
}
