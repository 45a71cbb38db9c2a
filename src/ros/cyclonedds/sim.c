/* The simulated robot (sp_ros_sim_run): loads or builds the nav costmap (simnav.c), creates the endpoints a Nav2 robot
 * offers (odom, tf, map, navigate_to_pose, compute_path_to_pose), then runs a fixed-rate loop:
 * serve requests as they come (every 5 ms), step the differential drive, publish odometry and
 * the odom -> base_link transform every tick and action feedback every other tick. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sim_internal.h"

static int check_options(const sp_ros_sim_options *o, sp_error *err)
{
    const struct { const char *name; double v; } pos[] = {
        {"max_speed", o->max_speed},         {"max_accel", o->max_accel},
        {"max_yaw_rate", o->max_yaw_rate},   {"max_yaw_accel", o->max_yaw_accel},
        {"goal_tolerance_m", o->goal_tolerance_m}, {"yaw_tolerance_rad", o->yaw_tolerance_rad},
        {"rate_hz", o->rate_hz},             {"time_scale", o->time_scale}};
    for (size_t i = 0; i < sizeof pos / sizeof pos[0]; i++)
        if (!(pos[i].v > 0) || !isfinite(pos[i].v))
            return sp_error_set(err, SP_E_ARG, "sim-robot: %s must be positive (is %g)",
                                pos[i].name, pos[i].v);
    if (!(o->robot_radius_m >= 0) || !isfinite(o->start_x) || !isfinite(o->start_y) ||
        !isfinite(o->start_yaw) || !(o->duration_s >= 0))
        return sp_error_set(err, SP_E_ARG, "sim-robot: radius, start pose or duration invalid");
    return 0;
}

static int make_endpoints(sim *s, sp_error *err)
{
    const sp_ros_options *r = &s->o->ros;
    sp_ros_options d;
    sp_ros_options_default(&d);
    char fq[ROS_NAME_MAX], topic[ROS_NAME_MAX + 8];
#define TOPIC(name, dflt) (ros_fq_name(r->ns, (name) && (name)[0] ? (name) : (dflt), fq, sizeof fq, err) || \
                           ros_dds_name(fq, 't', topic, sizeof topic, err))
    if (TOPIC(r->odom_topic, d.odom_topic)) return SP_E_ARG;
    /* Reliable, volatile, depth 10: what a driver with the default QoS publishes. */
    if ((s->odom_w = ros_writer(s->node, RT_ODOMETRY, topic, ROS_QOS_DEFAULT, NULL, err)) < 0)
        return (int)s->odom_w;
    if (TOPIC("tf", "tf")) return SP_E_ARG;
    if ((s->tf_w = ros_writer(s->node, RT_TF, topic, ((ros_qos){1, 0, 100}), NULL, err)) < 0)
        return (int)s->tf_w;
    if (TOPIC("map", "map")) return SP_E_ARG;
    if ((s->map_w = ros_writer(s->node, RT_OCCUPANCY_GRID, topic, ROS_QOS_LATCHED, NULL, err)) < 0)
        return (int)s->map_w;
#undef TOPIC
    int rc;
    if ((rc = ros_fq_name(r->ns, r->navigate_action && r->navigate_action[0] ? r->navigate_action
                                                                               : d.navigate_action,
                          fq, sizeof fq, err)) ||
        (rc = ros_action_server_init(&s->nav, s->node, ROS_ACTION_NAV, fq, s->distro, err)))
        return rc;
    if ((rc = ros_fq_name(r->ns, r->compute_path_action && r->compute_path_action[0]
                                     ? r->compute_path_action : d.compute_path_action,
                          fq, sizeof fq, err)) ||
        (rc = ros_action_server_init(&s->path, s->node, ROS_ACTION_PATH, fq, s->distro, err)))
        return rc;
    return ros_node_announce(s->node, err);
}

/* map -> odom, identity: the simulator knows where it is, as a perfect localization would. */
static void publish_localization(sim *s)
{
    sp_ros_transform t;
    memset(&t, 0, sizeof t);
    snprintf(t.frame_id, sizeof t.frame_id, "%s", s->map_frame);
    snprintf(t.child_frame_id, sizeof t.child_frame_id, "%s", s->odom_frame);
    t.qw = 1;
    tf2_msgs_msg_dds__TFMessage_ tm;
    struct geometry_msgs_msg_dds__TransformStamped_ one;
    ros_fill_tf(&tm, &one, &t, ros_wall_time());
    dds_write(s->tf_w, &tm);
}

static void publish_odometry(sim *s)
{
    static const double cov[36] = {[0] = 1e-3, [7] = 1e-3, [14] = 1e6, [21] = 1e6, [28] = 1e6,
                                   [35] = 1e-3};
    sp_ros_odom o;
    memset(&o, 0, sizeof o);
    o.pose = (sp_ros_pose){s->drive.x, s->drive.y, 0, s->drive.yaw};
    sp_ros_yaw_quat(s->drive.yaw, &o.qx, &o.qy, &o.qz, &o.qw);
    o.vx = s->drive.v;
    o.wz = s->drive.w;
    o.stamp_s = ros_wall_time();
    snprintf(o.frame_id, sizeof o.frame_id, "%s", s->odom_frame);
    snprintf(o.child_frame_id, sizeof o.child_frame_id, "%s", s->base_frame);
    nav_msgs_msg_dds__Odometry_ m;
    ros_fill_odometry(&m, &o, cov, cov);
    dds_write(s->odom_w, &m);
    sp_ros_transform t;
    memset(&t, 0, sizeof t);
    snprintf(t.frame_id, sizeof t.frame_id, "%s", s->odom_frame);
    snprintf(t.child_frame_id, sizeof t.child_frame_id, "%s", s->base_frame);
    t.x = o.pose.x, t.y = o.pose.y, t.qx = o.qx, t.qy = o.qy, t.qz = o.qz, t.qw = o.qw;
    tf2_msgs_msg_dds__TFMessage_ tm;
    struct geometry_msgs_msg_dds__TransformStamped_ one;
    ros_fill_tf(&tm, &one, &t, o.stamp_s);
    dds_write(s->tf_w, &tm);
}

static int write_ready(const char *path, sp_error *err)
{
    return path ? sp_write_file_atomic(path, "ready\n", 6, err) : 0;
}

static void run_loop(sim *s, const volatile sig_atomic_t *stop)
{
    const sp_ros_sim_options *o = s->o;
    double period = 1.0 / o->rate_hz, t0 = ros_now(), next = t0;
    long tick = 0;
    while (!(stop && *stop) && !(o->duration_s > 0 && ros_now() - t0 >= o->duration_s)) {
        sim_serve(s);
        double now = ros_now();
        if (now >= next) {
            double dt = period * o->time_scale;
            ros_drive_event ev = ros_drive_step(&s->drive, &s->lim, dt);
            s->sim_time += dt;
            sim_goal_progress(s, ev);
            publish_odometry(s);
            if (tick % 2 == 0) sim_feedback(s);
            if (tick++ % 10 == 0) publish_localization(s);
            sim_expire(s);
            next += period;
            if (next < now) next = now + period; /* fell behind (a slow machine): skip ahead */
        }
        double wait = fmin(next - ros_now(), 0.005);
        if (wait > 0) dds_sleepfor(DDS_SECS(wait));
    }
}

static void sim_free(sim *s)
{
    for (int i = 0; i < s->n_goals; i++) sp_ros_result_response_free(&s->goals[i].result);
    ros_drive_free(&s->drive);
    ros_node_free(s->node);
    sp_costmap_free(&s->cm);
}

/* The map as map_server publishes it (free 0, occupied 100, unknown -1), latched. */
static int publish_map(sim *s, sp_error *err)
{
    sp_ros_grid g;
    int rc = sp_ros_grid_from_costmap(&s->cm, 0, s->map_frame, &g, err);
    if (rc) return rc;
    nav_msgs_msg_dds__OccupancyGrid_ m;
    ros_fill_occupancy_grid(&m, &g, s->map_frame, ros_wall_time());
    rc = dds_write(s->map_w, &m) < 0 ? sp_error_set(err, SP_E_NET, "sim-robot: writing the map") : 0;
    sp_ros_grid_free(&g);
    return rc;
}

int sp_ros_sim_run(const sp_ros_sim_options *o, const volatile sig_atomic_t *stop,
                   const sp_log *log, sp_error *err)
{
    if (check_options(o, err)) return SP_E_ARG;
    sim s;
    memset(&s, 0, sizeof s);
    s.o = o;
    s.log = log;
    s.active = -1;
    s.distro = o->ros.distro == SP_ROS_DISTRO_AUTO ? SP_ROS_DISTRO_JAZZY : o->ros.distro;
    snprintf(s.odom_frame, sizeof s.odom_frame, "odom");
    snprintf(s.base_frame, sizeof s.base_frame, "base_link");
    snprintf(s.map_frame, sizeof s.map_frame, "%s", o->ros.map_frame && o->ros.map_frame[0] ? o->ros.map_frame : "map");
    s.lim = (ros_drive_limits){o->max_speed, o->max_accel, o->max_yaw_rate, o->max_yaw_accel,
                               o->goal_tolerance_m, o->yaw_tolerance_rad, 0.35};
    int rc = ros_sim_costmap(o, log, &s.cm, err);
    if (rc == 0) rc = ros_sim_check_start(&s.cm, o->start_x, o->start_y, err);
    sp_ros_options ropt = o->ros;
    ropt.distro = s.distro;
    if (!ropt.node_name || !ropt.node_name[0]) ropt.node_name = "semsplat_sim_robot";
    if (rc == 0) rc = ros_node_create(&s.node, &ropt, err);
    ros_drive_init(&s.drive, o->start_x, o->start_y, o->start_yaw);
    if (rc == 0) rc = make_endpoints(&s, err);
    if (rc == 0) rc = publish_map(&s, err);
    if (rc == 0) {
        publish_odometry(&s);
        rc = write_ready(o->ready_file, err);
    }
    if (rc == 0) {
        sp_logf(log, SP_LOG_INFO, "sim-robot: %s, domain %d, %dx%d map at %.3f m, start (%.2f, "
                "%.2f, %.2f)", sp_ros_distro_name(s.distro), o->ros.domain_id, s.cm.nx, s.cm.ny,
                s.cm.res, o->start_x, o->start_y, o->start_yaw);
        run_loop(&s, stop);
    }
    sim_free(&s);
    return rc;
}
