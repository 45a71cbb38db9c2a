/* semsplat ros-goal: talks to a ROS 2 robot from the command line through the bridge: send a
 * NavigateToPose goal and follow it, ask ComputePathToPose for a path, or print the pose. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "cli_ros.h"

static void help(void)
{
    printf("usage: semsplat ros-goal --to x,y[,yaw] [--timeout S] [--cancel-after S] [ROS flags]\n"
           "       semsplat ros-goal --plan x,y[,yaw] [--timeout S] [ROS flags]\n"
           "       semsplat ros-goal --pose [ROS flags]\n\n"
           "--to sends a NavigateToPose goal (map frame) and prints its feedback and result;\n"
           "exit 0 when it succeeded (or was canceled by --cancel-after), 1 otherwise.\n"
           "--plan asks the ComputePathToPose server for a path from the robot's pose.\n"
           "--pose prints the latest odometry.\n\nROS flags:\n%s", cli_ros_help);
}

static void on_feedback(void *user, const sp_ros_goal_status *st)
{
    double *last = user;
    const sp_ros_nav_feedback *f = &st->feedback;
    if (f->navigation_time_s - *last < 0.5) return;
    *last = f->navigation_time_s;
    printf("feedback: at (%.2f, %.2f, %.2f)  %.2f m to go  eta %.1f s  recoveries %d\n",
           f->current_pose.x, f->current_pose.y, f->current_pose.yaw, f->distance_remaining_m,
           f->eta_s, f->recoveries);
    fflush(stdout);
}

static int print_pose(sp_ros_bridge *b, double timeout)
{
    sp_ros_odom o;
    sp_error err = {0};
    if (sp_ros_odom_wait(b, timeout, &o, &err)) return cli_fail("ros-goal", &err);
    printf("pose: (%.3f, %.3f, %.3f) yaw %.3f in %s\n", o.pose.x, o.pose.y, o.pose.z, o.pose.yaw,
           o.frame_id);
    sp_ros_pose m;
    if (sp_ros_robot_pose(b, &m, NULL, &err) == 0)
        printf("map pose: (%.3f, %.3f, %.3f) yaw %.3f\n", m.x, m.y, m.z, m.yaw);
    else
        printf("map pose: unknown (%s)\n", err.msg);
    return 0;
}

static int plan(sp_ros_bridge *b, const sp_ros_pose *goal, double timeout)
{
    sp_ros_path path = {0};
    double t;
    sp_error err = {0};
    if (sp_ros_compute_path(b, NULL, goal, NULL, timeout, &path, &t, &err))
        return cli_fail("ros-goal", &err);
    double len = 0;
    for (size_t i = 1; i < path.n; i++)
        len += hypot(path.poses[i].x - path.poses[i - 1].x, path.poses[i].y - path.poses[i - 1].y);
    printf("path: %zu poses, %.2f m, planned in %.1f ms\n", path.n, len, t * 1e3);
    sp_ros_path_free(&path);
    return 0;
}

static int navigate(sp_ros_bridge *b, const sp_ros_pose *goal, double timeout, double cancel_after)
{
    sp_ros_goal *g;
    sp_ros_goal_status st;
    sp_error err = {0};
    double last = -1;
    if (sp_ros_navigate_to(b, goal, NULL, &g, &err)) return cli_fail("ros-goal", &err);
    sp_ros_goal_poll(g, &st, &err);
    printf("goal (%.2f, %.2f, %.2f): %s\n", goal->x, goal->y, goal->yaw,
           sp_ros_goal_state_name(st.state));
    if (st.state == SP_ROS_GOAL_REJECTED) {
        sp_ros_goal_free(g);
        return 1;
    }
    int rc = 0;
    if (cancel_after > 0) {
        sp_ros_goal_wait(g, cancel_after, &st, on_feedback, &last, &err);
        if (!sp_ros_goal_state_terminal(st.state)) {
            rc = sp_ros_goal_cancel(g, 5.0, &err);
            printf("cancel: %s\n", rc ? err.msg : "requested");
        }
    }
    if (!rc) rc = sp_ros_goal_wait(g, timeout, &st, on_feedback, &last, &err);
    if (rc) {
        sp_ros_goal_free(g);
        return cli_fail("ros-goal", &err);
    }
    printf("result: %s%s%s\n", sp_ros_goal_state_name(st.state), st.error_msg[0] ? ": " : "",
           st.error_msg);
    sp_ros_goal_free(g);
    int ok = st.state == SP_ROS_GOAL_SUCCEEDED ||
             (cancel_after > 0 && st.state == SP_ROS_GOAL_CANCELED);
    print_pose(b, 1.0);
    return ok ? 0 : 1;
}

int cmd_ros_goal(int argc, char **argv)
{
    sp_ros_options o;
    cli_ros_defaults(&o);
    o.node_name = "semsplat_ros_goal";
    sp_ros_pose to = {0, 0, 0, 0};
    int mode = 0, bad = 0; /* 1 navigate, 2 plan, 3 pose */
    double timeout = 120, cancel_after = 0;
    const char *v;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return help(), 0;
        if (cli_ros_flag("ros-goal", argc, argv, &i, &o, &bad)) {
            if (bad) return 2;
            continue;
        }
        if ((v = cli_flag_value(argc, argv, &i, "--to", &bad))) {
            if (cli_parse_pose("ros-goal", "--to", v, &to)) return 2;
            mode = 1;
        } else if ((v = cli_flag_value(argc, argv, &i, "--plan", &bad))) {
            if (cli_parse_pose("ros-goal", "--plan", v, &to)) return 2;
            mode = 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--timeout", &bad))) {
            if (cli_parse_float("ros-goal", "--timeout", v, &timeout)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--cancel-after", &bad))) {
            if (cli_parse_float("ros-goal", "--cancel-after", v, &cancel_after)) return 2;
        } else if (!strcmp(argv[i], "--pose")) mode = 3;
        else if (!bad) return cli_usage_error("ros-goal", "unknown argument '%s'", argv[i]);
        if (bad) return 2;
    }
    if (!mode) return cli_usage_error("ros-goal", "one of --to, --plan or --pose is needed");
    if (!(timeout > 0 && timeout <= 86400)) return cli_usage_error("ros-goal", "--timeout %g: expected 0..86400 s", timeout);
    if (!(cancel_after >= 0 && cancel_after <= 86400))
        return cli_usage_error("ros-goal", "--cancel-after %g: expected 0..86400 s", cancel_after);
    sp_ros_bridge *b;
    sp_error err = {0};
    if (sp_ros_bridge_create(&b, &o, &err)) return cli_fail("ros-goal", &err);
    int rc = mode == 1 ? navigate(b, &to, timeout, cancel_after)
             : mode == 2 ? plan(b, &to, timeout) : print_pose(b, o.server_timeout_s);
    sp_ros_bridge_free(b);
    return rc;
}
