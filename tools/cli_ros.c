/* The ROS commands' common flags. */
#include "cli_ros.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

const char cli_ros_help[] =
    "  --domain N          ROS domain id (default $ROS_DOMAIN_ID or 0)\n"
    "  --ros-distro D      humble, jazzy or auto (detect from the peers; default)\n"
    "  --namespace NS      ROS namespace, e.g. /robot1\n"
    "  --odom-topic T      odometry topic (default odom)\n"
    "  --nav-action A      NavigateToPose action (default navigate_to_pose)\n"
    "  --path-action A     ComputePathToPose action (default compute_path_to_pose)\n"
    "  --server-timeout S  how long to wait for an action server to appear (default 5)\n"
    "  --loopback          Cyclone DDS on 127.0.0.1 only, no multicast (one machine)\n"
    "  --dds-config XML    Cyclone configuration (XML text or file://path; default\n"
    "                      $CYCLONEDDS_URI)\n";

void cli_ros_defaults(sp_ros_options *o)
{
    sp_ros_options_default(o);
    const char *d = getenv("ROS_DOMAIN_ID");
    char *end;
    long v = d ? strtol(d, &end, 10) : 0;
    if (d && *d && !*end && v >= 0 && v <= 232) o->domain_id = (int)v;
}

int cli_ros_flag(const char *cmd, int argc, char **argv, int *i, sp_ros_options *o, int *bad)
{
    const char *v;
    long n;
    sp_error err = {0};
    if ((v = cli_flag_value(argc, argv, i, "--domain", bad))) {
        if (cli_parse_int(cmd, "--domain", v, &n)) *bad = 1;
        else o->domain_id = (int)n;
    } else if ((v = cli_flag_value(argc, argv, i, "--ros-distro", bad))) {
        if (sp_ros_distro_parse(v, &o->distro, &err)) *bad = 1, cli_fail(cmd, &err);
    } else if ((v = cli_flag_value(argc, argv, i, "--namespace", bad))) o->ns = v;
    else if ((v = cli_flag_value(argc, argv, i, "--odom-topic", bad))) o->odom_topic = v;
    else if ((v = cli_flag_value(argc, argv, i, "--nav-action", bad))) o->navigate_action = v;
    else if ((v = cli_flag_value(argc, argv, i, "--path-action", bad))) o->compute_path_action = v;
    else if ((v = cli_flag_value(argc, argv, i, "--dds-config", bad))) o->dds_config = v;
    else if ((v = cli_flag_value(argc, argv, i, "--server-timeout", bad))) {
        if (cli_parse_float(cmd, "--server-timeout", v, &o->server_timeout_s)) *bad = 1;
        else if (!(o->server_timeout_s > 0) || o->server_timeout_s > 3600)
            *bad = 1, cli_usage_error(cmd, "--server-timeout: %s s not in (0, 3600]", v);
    }
    else if (!strcmp(argv[*i], "--loopback")) o->loopback_only = 1;
    else return *bad;
    return 1;
}

int cli_parse_pose(const char *cmd, const char *flag, const char *s, sp_ros_pose *p)
{
    double x, y, yaw = 0;
    char tail;
    int k = sscanf(s, "%lf,%lf,%lf%c", &x, &y, &yaw, &tail);
    if ((k != 2 && k != 3) || !isfinite(x) || !isfinite(y) || !isfinite(yaw))
        return cli_usage_error(cmd, "%s: '%s' is not x,y or x,y,yaw", flag, s);
    p->x = x, p->y = y, p->z = 0, p->yaw = yaw;
    return 0;
}
