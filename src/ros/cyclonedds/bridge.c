/* The bridge: odometry in, our map and candidate paths out (sp_ros_bridge_*, sp_ros_odom_*,
 * sp_ros_publish_*). The action clients live in goal.c and path_client.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bridge_internal.h"

static void copy_opt(char *dst, size_t cap, const char *v, const char *dflt)
{
    snprintf(dst, cap, "%s", v && v[0] ? v : dflt);
}

/* Keeps private copies of the option strings (the caller's may not outlive the bridge). */
static void keep_options(sp_ros_bridge *b, const sp_ros_options *o)
{
    sp_ros_options d;
    sp_ros_options_default(&d);
    b->opt = *o;
    copy_opt(b->ns, sizeof b->ns, o->ns, "");
    copy_opt(b->node_name, sizeof b->node_name, o->node_name, d.node_name);
    copy_opt(b->map_frame, sizeof b->map_frame, o->map_frame, d.map_frame);
    b->opt.ns = b->ns;
    b->opt.node_name = b->node_name;
    b->opt.map_frame = b->map_frame;
    b->opt.dds_config = NULL; /* only needed while creating the domain */
    if (!(b->opt.server_timeout_s > 0)) b->opt.server_timeout_s = d.server_timeout_s;
    if (!(b->opt.odom_stale_s > 0)) b->opt.odom_stale_s = d.odom_stale_s;
}

static int resolve(sp_ros_bridge *b, const char *name, const char *dflt, char *fq, sp_error *err)
{
    return ros_fq_name(b->ns, name && name[0] ? name : dflt, fq, ROS_NAME_MAX, err);
}

static int make_endpoints(sp_ros_bridge *b, const sp_ros_options *o, sp_error *err)
{
    sp_ros_options d;
    sp_ros_options_default(&d);
    char fq[ROS_NAME_MAX], topic[ROS_NAME_MAX + 8];
    if (resolve(b, o->navigate_action, d.navigate_action, b->nav_fq, err) ||
        resolve(b, o->compute_path_action, d.compute_path_action, b->path_fq, err) ||
        resolve(b, o->paths_topic, d.paths_topic, b->paths_fq, err))
        return SP_E_ARG;
    if (resolve(b, o->odom_topic, d.odom_topic, fq, err) ||
        ros_dds_name(fq, 't', b->odom_topic, sizeof b->odom_topic, err))
        return SP_E_ARG;
    b->odom_r = ros_reader(b->node, RT_ODOMETRY, b->odom_topic, ROS_QOS_SENSOR, NULL, err);
    if (b->odom_r < 0) return (int)b->odom_r;
    if (resolve(b, "tf", "tf", fq, err) || ros_dds_name(fq, 't', topic, sizeof topic, err))
        return SP_E_ARG;
    b->tf_r = ros_reader(b->node, RT_TF, topic, ((ros_qos){0, 0, 100}), NULL, err);
    if (b->tf_r < 0) return (int)b->tf_r;
    if (resolve(b, o->map_topic, d.map_topic, fq, err) ||
        ros_dds_name(fq, 't', topic, sizeof topic, err))
        return SP_E_ARG;
    /* Like map_server: late subscribers (RViz started after us) still get the map. */
    b->map_w = ros_writer(b->node, RT_OCCUPANCY_GRID, topic, ROS_QOS_LATCHED, NULL, err);
    return b->map_w < 0 ? (int)b->map_w : 0;
}

int sp_ros_bridge_create(sp_ros_bridge **out, const sp_ros_options *opt, sp_error *err)
{
    sp_ros_options d;
    if (!opt) {
        sp_ros_options_default(&d);
        opt = &d;
    }
    sp_ros_bridge *b = calloc(1, sizeof *b);
    if (!b) return sp_error_set(err, SP_E_NOMEM, "ros bridge");
    keep_options(b, opt);
    sp_ros_options with_config = b->opt; /* the domain needs the caller's Cyclone config */
    with_config.dds_config = opt->dds_config;
    int rc = ros_node_create(&b->node, &with_config, err);
    if (rc) {
        free(b);
        return rc;
    }
    if ((rc = make_endpoints(b, opt, err)) || (rc = ros_node_announce(b->node, err))) {
        sp_ros_bridge_free(b);
        return rc;
    }
    *out = b;
    return 0;
}

void sp_ros_bridge_free(sp_ros_bridge *b)
{
    if (!b) return;
    for (int i = 0; i < b->n_goals; i++) b->goals[i]->b = NULL; /* handles outlive us safely */
    ros_node_free(b->node);  /* deletes every DDS entity of ours */
    free(b);
}

sp_ros_distro sp_ros_bridge_distro(sp_ros_bridge *b)
{
    bridge_tick(b);
    return b->node->distro;
}

void bridge_tick(sp_ros_bridge *b)
{
    if (b->node->configured || b->node->distro != SP_ROS_DISTRO_AUTO) return;
    sp_ros_distro d = ros_node_distro(b->node);
    if (d != SP_ROS_DISTRO_AUTO) ros_node_set_distro(b->node, d, NULL);
}

/* ---- odometry ---- */

static void on_odom(void *ctx, const uint8_t *bytes, size_t n, const dds_sample_info_t *info)
{
    sp_ros_bridge *b = ctx;
    sp_ros_odom o;
    sp_error e = {0};
    (void)info;
    if (sp_ros_decode_odometry(bytes, n, &o, &e)) {
        b->odom_bad++;
        snprintf(b->odom_bad_msg, sizeof b->odom_bad_msg, "%s", e.msg);
        return;
    }
    b->odom = o;
    b->have_odom = 1;
    b->odom_rx = ros_now();
}

int sp_ros_odom_latest(sp_ros_bridge *b, sp_ros_odom *out, double *age_s, sp_error *err)
{
    bridge_tick(b);
    ros_take_raw(b->odom_r, on_odom, b, 1000);
    if (!b->have_odom) {
        if (b->odom_bad)
            return sp_error_set(err, SP_E_NOTFOUND, "no usable odometry on %s: %ld malformed "
                                "samples, the last: %s", b->odom_topic, b->odom_bad,
                                b->odom_bad_msg);
        return sp_error_set(err, SP_E_NOTFOUND, "no odometry received on %s (ROS domain %d) "
                            "yet", b->odom_topic, b->opt.domain_id);
    }
    double age = ros_now() - b->odom_rx;
    *out = b->odom;
    if (age_s) *age_s = age;
    if (age > b->opt.odom_stale_s)
        return sp_error_set(err, SP_E_NET, "odometry on %s is stale: the newest is %.2f s old "
                            "(limit %.2f s)", b->odom_topic, age, b->opt.odom_stale_s);
    return 0;
}

int sp_ros_odom_wait(sp_ros_bridge *b, double timeout_s, sp_ros_odom *out, sp_error *err)
{
    double until = ros_now() + (timeout_s > 0 ? timeout_s : 0), age;
    int rc;
    while ((rc = sp_ros_odom_latest(b, out, &age, err)) != 0 && ros_now() < until) ros_nap();
    return rc;
}

/* ---- the pose in the map frame ---- */

static const char *odom_frame(const sp_ros_bridge *b)
{
    return b->have_odom && b->odom.frame_id[0] ? b->odom.frame_id : "odom";
}

static void on_tf(void *ctx, const uint8_t *bytes, size_t n, const dds_sample_info_t *info)
{
    sp_ros_bridge *b = ctx;
    sp_ros_transform t;
    (void)info;
    if (sp_ros_decode_tf_find(bytes, n, b->map_frame, odom_frame(b), &t, NULL)) return;
    b->map_odom = t;
    b->have_map_odom = 1;
}

int sp_ros_robot_pose(sp_ros_bridge *b, sp_ros_pose *map_pose, double *age_s, sp_error *err)
{
    sp_ros_odom o;
    int rc = sp_ros_odom_latest(b, &o, age_s, err);
    if (rc) return rc;
    ros_take_raw(b->tf_r, on_tf, b, 1000);
    if (!strcmp(o.frame_id, b->map_frame)) {
        *map_pose = o.pose;
        return 0;
    }
    if (!b->have_map_odom)
        return sp_error_set(err, SP_E_NOTFOUND, "no %s -> %s transform on tf yet: is the robot's "
                            "localization (AMCL, slam_toolbox) running?", b->map_frame, o.frame_id);
    /* Planar composition: map_pose = T(map -> odom) * odom_pose. */
    const sp_ros_transform *t = &b->map_odom;
    double yaw = sp_ros_quat_yaw(t->qx, t->qy, t->qz, t->qw), c = cos(yaw), s = sin(yaw);
    map_pose->x = t->x + c * o.pose.x - s * o.pose.y;
    map_pose->y = t->y + s * o.pose.x + c * o.pose.y;
    map_pose->z = t->z + o.pose.z;
    map_pose->yaw = atan2(sin(yaw + o.pose.yaw), cos(yaw + o.pose.yaw));
    return 0;
}

/* ---- map and paths ---- */

static int check_grid(const sp_ros_grid *g, sp_error *err)
{
    if (!g || g->width <= 0 || g->height <= 0 || !g->cells)
        return sp_error_set(err, SP_E_ARG, "map: empty grid (%d x %d)", g ? g->width : 0,
                            g ? g->height : 0);
    if ((size_t)g->width * (size_t)g->height > (1u << 30))
        return sp_error_set(err, SP_E_ARG, "map: %d x %d cells is too large", g->width, g->height);
    if (!(g->resolution_m > 0) || !isfinite(g->resolution_m) || !isfinite(g->origin_x) ||
        !isfinite(g->origin_y) || !isfinite(g->origin_yaw))
        return sp_error_set(err, SP_E_ARG, "map: resolution %g or origin (%g, %g, %g) invalid",
                            g->resolution_m, g->origin_x, g->origin_y, g->origin_yaw);
    for (size_t i = 0; i < (size_t)g->width * g->height; i++)
        if (g->cells[i] < -1 || g->cells[i] > 100)
            return sp_error_set(err, SP_E_ARG, "map: cell %zu (row %zu, col %zu) is %d; "
                                "OccupancyGrid cells are -1 (unknown) or 0..100", i,
                                i / g->width, i % g->width, g->cells[i]);
    return 0;
}

int sp_ros_publish_map(sp_ros_bridge *b, const sp_ros_grid *grid, sp_error *err)
{
    if (check_grid(grid, err)) return SP_E_ARG;
    bridge_tick(b);
    nav_msgs_msg_dds__OccupancyGrid_ m;
    const char *frame = grid->frame_id[0] ? grid->frame_id : b->map_frame;
    ros_fill_occupancy_grid(&m, grid, frame, ros_wall_time());
    dds_return_t rc = dds_write(b->map_w, &m);
    if (rc < 0) return sp_error_set(err, SP_E_NET, "publishing the map: %s", dds_strretcode(rc));
    return 0;
}

static int check_path(const sp_ros_path *p, int k, sp_error *err)
{
    if (p->n && !p->poses) return sp_error_set(err, SP_E_ARG, "path %d: %zu poses, none given", k, p->n);
    for (size_t i = 0; i < p->n; i++) {
        const sp_ros_pose *q = &p->poses[i];
        if (!isfinite(q->x) || !isfinite(q->y) || !isfinite(q->z) || !isfinite(q->yaw))
            return sp_error_set(err, SP_E_ARG, "path %d, pose %zu is not finite", k, i);
    }
    return 0;
}

static int path_writer(sp_ros_bridge *b, int i, sp_error *err)
{
    if (b->path_w[i] > 0) return 0;
    char ros[ROS_NAME_MAX + 8], topic[ROS_NAME_MAX + 16];
    snprintf(ros, sizeof ros, "%s_%d", b->paths_fq, i + 1);
    if (ros_dds_name(ros, 't', topic, sizeof topic, err)) return SP_E_ARG;
    dds_entity_t w = ros_writer(b->node, RT_PATH, topic, ROS_QOS_LATCHED, NULL, err);
    if (w < 0) return (int)w;
    b->path_w[i] = w;
    return ros_node_announce(b->node, err);
}

static int write_path(sp_ros_bridge *b, int i, const sp_ros_path *p, double stamp, sp_error *err)
{
    nav_msgs_msg_dds__Path_ m;
    const char *frame = p->frame_id[0] ? p->frame_id : b->map_frame;
    if (ros_fill_path(&m, p, frame, stamp)) return sp_error_set(err, SP_E_NOMEM, "path");
    dds_return_t rc = dds_write(b->path_w[i], &m);
    ros_unfill_path(&m);
    if (rc < 0) return sp_error_set(err, SP_E_NET, "publishing path %d: %s", i + 1, dds_strretcode(rc));
    return 0;
}

int sp_ros_publish_paths(sp_ros_bridge *b, const sp_ros_path *paths, int n, sp_error *err)
{
    if (n < 0 || n > SP_ROS_MAX_PATHS || (n && !paths))
        return sp_error_set(err, SP_E_ARG, "publish_paths: %d paths (0..%d)", n, SP_ROS_MAX_PATHS);
    for (int i = 0; i < n; i++)
        if (check_path(&paths[i], i + 1, err)) return SP_E_ARG;
    bridge_tick(b);
    double stamp = ros_wall_time();
    int rc;
    for (int i = 0; i < n; i++)
        if ((rc = path_writer(b, i, err)) || (rc = write_path(b, i, &paths[i], stamp, err)))
            return rc;
    sp_ros_path empty;
    memset(&empty, 0, sizeof empty);
    for (int i = n; i < b->n_paths_shown; i++) /* clear candidates of an earlier, longer call */
        if ((rc = write_path(b, i, &empty, stamp, err))) return rc;
    b->n_paths_shown = n;
    return 0;
}
