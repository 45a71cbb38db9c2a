/* Flags shared by the ROS commands (sim-robot, ros-goal): domain, distro, namespace, topics,
 * the Cyclone configuration. */
#ifndef SEMSPLAT_CLI_ROS_H
#define SEMSPLAT_CLI_ROS_H

#include "semsplat/ros.h"

/* Defaults, with the domain from $ROS_DOMAIN_ID when set (as ROS 2 does). */
void cli_ros_defaults(sp_ros_options *o);
/* Consumes argv[*i] (and its value) when it is a ROS flag: returns 1 if it was, 0 if not; sets
 * *bad on a malformed value. */
int cli_ros_flag(const char *cmd, int argc, char **argv, int *i, sp_ros_options *o, int *bad);
/* The help lines for those flags. */
extern const char cli_ros_help[];
/* "x,y" or "x,y,yaw" (metres, radians). */
int cli_parse_pose(const char *cmd, const char *flag, const char *s, sp_ros_pose *p);

#endif
