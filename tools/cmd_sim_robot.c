/* semsplat sim-robot: a simulated differential-drive robot that serves Nav2's NavigateToPose
 * and ComputePathToPose over DDS on a costmap, and publishes /odom (20 Hz) and /tf. */
#include <signal.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "cli_ros.h"

static volatile sig_atomic_t stop_requested = 0;

static void on_signal(int sig)
{
    (void)sig;
    stop_requested = 1;
}

static void help(void)
{
    printf("usage: semsplat sim-robot (--map MAP.yaml | --model DIR) [--start x,y,yaw]\n"
           "                         [--radius M] [--max-speed M/S] [--max-accel M/S2]\n"
           "                         [--max-yaw-rate RAD/S] [--rate HZ] [--time-scale K]\n"
           "                         [--duration S] [--ready-file PATH] [ROS flags]\n"
           "                         [--device cpu|cuda|auto] [--threads N] [--quiet] [--verbose]\n\n"
           "A differential-drive robot with velocity and acceleration limits, standing in for a\n"
           "robot running Nav2: it plans on the nav module's costmap (read from a Nav2 map.yaml,\n"
           "or built from the model folder's splat and training cameras on --device), refuses\n"
           "goals outside the map, in occupied or unknown space, too close to obstacles or not\n"
           "reachable, drives the path, and publishes odom, tf (odom -> base_link) and map.\n"
           "Stops on Ctrl-C or after --duration seconds. --ros-distro auto means jazzy here.\n\n"
           "ROS flags:\n%s",
           cli_ros_help);
}

static int parse_number(const char *flag, const char *v, double *out)
{
    return cli_parse_float("sim-robot", flag, v, out);
}

int cmd_sim_robot(int argc, char **argv)
{
    sp_ros_sim_options o;
    sp_ros_sim_options_default(&o);
    cli_ros_defaults(&o.ros);
    o.ros.node_name = "semsplat_sim_robot";
    cli_common c = cli_common_default();
    int bad = 0, r;
    const char *v;
    sp_ros_pose start = {0, 0, 0, 0};
    /* each with its range: beyond it a robot is not simulated but stuck (a rate of 1e30 Hz spins,
     * a duration of 1e30 s never ends) */
    static const struct { const char *flag; size_t off; double lo, hi; } nums[] = {
        {"--radius", offsetof(sp_ros_sim_options, robot_radius_m), 0, 10},
        {"--max-speed", offsetof(sp_ros_sim_options, max_speed), 1e-3, 10},
        {"--max-accel", offsetof(sp_ros_sim_options, max_accel), 1e-3, 100},
        {"--max-yaw-rate", offsetof(sp_ros_sim_options, max_yaw_rate), 1e-3, 100},
        {"--rate", offsetof(sp_ros_sim_options, rate_hz), 0.1, 1000},
        {"--time-scale", offsetof(sp_ros_sim_options, time_scale), 1e-3, 1000},
        {"--duration", offsetof(sp_ros_sim_options, duration_s), 0, 1e7}};
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return help(), 0;
        if (cli_ros_flag("sim-robot", argc, argv, &i, &o.ros, &bad)) {
            if (bad) return 2;
            continue;
        }
        if ((r = cli_common_flag("sim-robot", argc, argv, &i, CLI_ALL, &c))) {
            if (r == 2) return 2;
            continue;
        }
        int used = 0;
        for (size_t k = 0; k < sizeof nums / sizeof nums[0] && !used && !bad; k++)
            if ((v = cli_flag_value(argc, argv, &i, nums[k].flag, &bad))) {
                used = 1;
                double *dst = (double *)((char *)&o + nums[k].off);
                if (parse_number(nums[k].flag, v, dst)) return 2;
                if (!(*dst >= nums[k].lo && *dst <= nums[k].hi))
                    return cli_usage_error("sim-robot", "%s %g: expected %g..%g", nums[k].flag, *dst, nums[k].lo,
                                           nums[k].hi);
            }
        if (used) continue;
        if ((v = cli_flag_value(argc, argv, &i, "--map", &bad))) o.map_yaml = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--model", &bad))) o.model_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--ready-file", &bad))) o.ready_file = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--start", &bad))) {
            if (cli_parse_pose("sim-robot", "--start", v, &start)) return 2;
        } else if (!bad) return cli_usage_error("sim-robot", "unknown argument '%s'", argv[i]);
        if (bad) return 2;
    }
    if (!o.map_yaml && !o.model_dir)
        return cli_usage_error("sim-robot", "--map or --model is required");
    if (o.map_yaml && o.model_dir) return cli_usage_error("sim-robot", "--map and --model exclude each other");
    o.start_x = start.x, o.start_y = start.y, o.start_yaw = start.yaw;
    signal(SIGINT, on_signal);
    signal(SIGTERM, on_signal);
    sp_log log = cli_log(&c, SP_LOG_INFO);
    if (c.quiet) log.min_level = SP_LOG_WARN;
    sp_device *dev = NULL; /* only a model's costmap renders */
    if (o.model_dir && cli_device_open("sim-robot", &c, &dev)) return 1;
    o.device = dev;
    sp_error err = {0};
    int rc = sp_ros_sim_run(&o, &stop_requested, &log, &err);
    sp_device_free(dev);
    return rc ? cli_fail("sim-robot", &err) : 0;
}
