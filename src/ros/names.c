/* ROS names and defaults (no DDS needed): distro names, option defaults, ROS name rules, and the
 * DDS topic names rmw_cyclonedds derives from them ("rt" + fully qualified name for topics,
 * "rq" + name + "Request" / "rr" + name + "Reply" for services; rmw_cyclonedds_cpp
 * namespace_prefix.hpp and rmw_node.cpp make_fqtopic). */
#include <ctype.h>
#include <stdio.h>
#include <string.h>

#include "ros_internal.h"

int sp_ros_distro_parse(const char *name, sp_ros_distro *out, sp_error *err)
{
    if (name && !strcmp(name, "auto")) *out = SP_ROS_DISTRO_AUTO;
    else if (name && !strcmp(name, "humble")) *out = SP_ROS_DISTRO_HUMBLE;
    else if (name && !strcmp(name, "jazzy")) *out = SP_ROS_DISTRO_JAZZY;
    else
        return sp_error_set(err, SP_E_ARG, "ROS distro '%s': expected humble, jazzy or auto",
                            name ? name : "(null)");
    return 0;
}

const char *sp_ros_distro_name(sp_ros_distro d)
{
    switch (d) {
    case SP_ROS_DISTRO_HUMBLE: return "humble";
    case SP_ROS_DISTRO_JAZZY: return "jazzy";
    default: return "auto";
    }
}

const char *sp_ros_goal_state_name(sp_ros_goal_state s)
{
    static const char *names[] = {"unknown",   "accepted", "executing", "canceling", "succeeded",
                                  "canceled",  "aborted",  "rejected",  "lost"};
    return (unsigned)s < sizeof names / sizeof names[0] ? names[s] : "invalid";
}

void sp_ros_options_default(sp_ros_options *o)
{
    memset(o, 0, sizeof *o);
    o->domain_id = 0;
    o->distro = SP_ROS_DISTRO_AUTO;
    o->ns = "";
    o->node_name = "semsplat";
    o->odom_topic = "odom";
    o->navigate_action = "navigate_to_pose";
    o->compute_path_action = "compute_path_to_pose";
    o->map_topic = "semsplat/map";
    o->paths_topic = "semsplat/path";
    o->map_frame = "map";
    o->server_timeout_s = 5.0;
    o->odom_stale_s = 0.5;
}

void sp_ros_sim_options_default(sp_ros_sim_options *o)
{
    memset(o, 0, sizeof *o);
    sp_ros_options_default(&o->ros);
    o->ros.node_name = "semsplat_sim_robot";
    o->robot_radius_m = 0.2;
    o->max_speed = 0.5;
    o->max_accel = 0.5;
    o->max_yaw_rate = 1.5;
    o->max_yaw_accel = 3.0;
    o->goal_tolerance_m = 0.1;
    o->yaw_tolerance_rad = 0.15;
    o->rate_hz = 20.0;
    o->time_scale = 1.0;
}

/* rcl's rules for names, the subset we accept: tokens of [A-Za-z0-9_] not starting with a digit,
 * separated by single '/', no trailing '/'. Substitutions ({node}) and '~' are not supported. */
static int check_tokens(const char *s, const char *what, sp_error *err)
{
    int at_token_start = 1;
    for (const char *p = s; *p; p++) {
        if (*p == '/') {
            if (p[1] == '/' || p[1] == 0)
                return sp_error_set(err, SP_E_ARG, "%s '%s': empty token (\"//\" or a trailing "
                                    "'/')", what, s);
            at_token_start = 1;
            continue;
        }
        if (!(isalnum((unsigned char)*p) || *p == '_'))
            return sp_error_set(err, SP_E_ARG, "%s '%s': character '%c' is not allowed in ROS "
                                "names (letters, digits, '_', '/')", what, s, *p);
        if (at_token_start && isdigit((unsigned char)*p))
            return sp_error_set(err, SP_E_ARG, "%s '%s': a token may not start with a digit",
                                what, s);
        at_token_start = 0;
    }
    return 0;
}

int ros_check_namespace(const char *ns, sp_error *err)
{
    if (!ns || !ns[0] || !strcmp(ns, "/")) return 0;
    if (ns[0] != '/')
        return sp_error_set(err, SP_E_ARG, "namespace '%s' must start with '/'", ns);
    return check_tokens(ns + 1, "namespace", err);
}

int ros_fq_name(const char *ns, const char *name, char *out, size_t cap, sp_error *err)
{
    if (!name || !name[0]) return sp_error_set(err, SP_E_ARG, "empty ROS name");
    if (ros_check_namespace(ns, err)) return SP_E_ARG;
    if (check_tokens(name[0] == '/' ? name + 1 : name, "ROS name", err)) return SP_E_ARG;
    int n;
    if (name[0] == '/') n = snprintf(out, cap, "%s", name);
    else if (!ns || !ns[0] || !strcmp(ns, "/")) n = snprintf(out, cap, "/%s", name);
    else n = snprintf(out, cap, "%s/%s", ns, name);
    if (n < 0 || (size_t)n >= cap)
        return sp_error_set(err, SP_E_ARG, "ROS name '%s' is too long", name);
    return 0;
}

int ros_dds_name(const char *fq, char kind, char *out, size_t cap, sp_error *err)
{
    int n;
    switch (kind) {
    case 't': n = snprintf(out, cap, "rt%s", fq); break;
    case 'q': n = snprintf(out, cap, "rq%sRequest", fq); break;
    case 'r': n = snprintf(out, cap, "rr%sReply", fq); break;
    default: return sp_error_set(err, SP_E_ARG, "topic kind '%c' (t, q or r)", kind);
    }
    if (n < 0 || (size_t)n >= cap)
        return sp_error_set(err, SP_E_ARG, "DDS topic name for '%s' is too long", fq);
    return 0;
}

int sp_ros_dds_topic_name(const sp_ros_options *opt, const char *ros_name, char kind, char *out,
                          size_t cap, sp_error *err)
{
    char fq[ROS_NAME_MAX];
    if (ros_fq_name(opt ? opt->ns : "", ros_name, fq, sizeof fq, err)) return -1;
    return ros_dds_name(fq, kind, out, cap, err) ? -1 : 0;
}
