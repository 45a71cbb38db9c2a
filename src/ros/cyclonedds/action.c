/* ROS 2 actions over DDS (rcl_action names.c): three services and two topics under
 * <action>/_action/{send_goal, cancel_goal, get_result, feedback, status}; services, feedback
 * reliable volatile depth 10, status reliable transient-local depth 1 (rcl_action default QoS).
 * The client checks the server is rmw_cyclonedds (its request readers carry serviceid=) of the
 * distro we speak before it sends anything. */
#include <stdio.h>
#include <string.h>

#include "dds_internal.h"

const char *ros_action_type_name(ros_action_kind k)
{
    return k == ROS_ACTION_NAV ? "NavigateToPose" : "ComputePathToPose";
}

int ros_action_part(const char *action_fq, const char *part, char kind, char *out, size_t cap,
                    sp_error *err)
{
    char ros[ROS_NAME_MAX + 32];
    int n = snprintf(ros, sizeof ros, "%s/_action/%s", action_fq, part);
    if (n < 0 || (size_t)n >= sizeof ros) return sp_error_set(err, SP_E_ARG, "action name too long");
    if (kind == 0) return snprintf(out, cap, "%s", ros) >= (int)cap ? SP_E_ARG : 0;
    return ros_dds_name(ros, kind, out, cap, err);
}

static ros_type goal_req(ros_action_kind k) { return k == ROS_ACTION_NAV ? RT_NAV_GOAL_REQ : RT_PATH_GOAL_REQ; }
static ros_type goal_rep(ros_action_kind k) { return k == ROS_ACTION_NAV ? RT_NAV_GOAL_REP : RT_PATH_GOAL_REP; }
static ros_type result_req(ros_action_kind k)
{
    return k == ROS_ACTION_NAV ? RT_NAV_RESULT_REQ : RT_PATH_RESULT_REQ;
}
static ros_type result_rep(ros_action_kind k, sp_ros_distro d)
{
    return ros_type_for(k == ROS_ACTION_NAV ? RT_NAV_RESULT_REP_HUMBLE : RT_PATH_RESULT_REP_HUMBLE, d);
}

/* The ROS service name of an action part ("/navigate_to_pose/_action/send_goal"). */
static int part_name(const char *fq, const char *part, char *out, size_t cap, sp_error *err)
{
    return ros_action_part(fq, part, 0, out, cap, err);
}

int ros_action_client_init(ros_action_client *a, ros_node *n, ros_action_kind kind,
                           const char *action_fq, sp_error *err)
{
    char svc[ROS_NAME_MAX + 32], topic[ROS_NAME_MAX + 40], id[64];
    memset(a, 0, sizeof *a);
    a->kind = kind;
    a->distro = SP_ROS_DISTRO_AUTO;
    snprintf(a->fq, sizeof a->fq, "%s", action_fq);
    int rc;
    ros_node_csid(n, id, sizeof id);
    if ((rc = part_name(action_fq, "send_goal", svc, sizeof svc, err)) ||
        (rc = ros_client_init(&a->send_goal, n, svc, goal_req(kind), goal_rep(kind), id, err)))
        return rc;
    ros_node_csid(n, id, sizeof id);
    if ((rc = part_name(action_fq, "cancel_goal", svc, sizeof svc, err)) ||
        (rc = ros_client_init(&a->cancel, n, svc, RT_CANCEL_REQ, RT_CANCEL_REP, id, err)))
        return rc;
    if (kind == ROS_ACTION_NAV) {
        if ((rc = ros_action_part(action_fq, "feedback", 't', topic, sizeof topic, err))) return rc;
        a->feedback_r = ros_reader(n, RT_NAV_FEEDBACK, topic, ROS_QOS_DEFAULT, NULL, err);
        if (a->feedback_r < 0) return (int)a->feedback_r;
    }
    if ((rc = ros_action_part(action_fq, "status", 't', topic, sizeof topic, err))) return rc;
    a->status_r = ros_reader(n, RT_STATUS_ARRAY, topic, ROS_QOS_LATCHED, NULL, err);
    return a->status_r < 0 ? (int)a->status_r : 0;
}

/* Which distro to speak with this server: what it shows, else what we were told, else Humble
 * (an rmw_cyclonedds server without typehash= is Humble: Jazzy's rmw always adds it). */
static int pick_distro(ros_action_client *a, ros_node *n, sp_ros_distro *out, sp_error *err)
{
    int has_serviceid;
    sp_ros_distro shown;
    ros_client_server_info(&a->send_goal, &has_serviceid, &shown);
    if (!has_serviceid)
        return sp_error_set(err, SP_E_UNSUPPORTED,
                            "the %s server on %s is not rmw_cyclonedds (its request reader has no "
                            "serviceid in USER_DATA): run the robot with "
                            "RMW_IMPLEMENTATION=rmw_cyclonedds_cpp for actions and services "
                            "(topics work with any RMW)", ros_action_type_name(a->kind), a->fq);
    sp_ros_distro server = shown != SP_ROS_DISTRO_AUTO ? shown : SP_ROS_DISTRO_HUMBLE;
    if (n->configured && n->distro != server)
        return sp_error_set(err, SP_E_UNSUPPORTED,
                            "the %s server on %s speaks %s, but we were told --ros-distro %s "
                            "(the result layouts differ)", ros_action_type_name(a->kind), a->fq,
                            sp_ros_distro_name(server), sp_ros_distro_name(n->distro));
    *out = server;
    return 0;
}

int ros_action_client_connect(ros_action_client *a, ros_node *n, double deadline,
                              int domain_id, sp_error *err)
{
    double t0 = ros_now();
    while (!ros_client_ready(&a->send_goal) && ros_now() < deadline) ros_nap();
    if (!ros_client_ready(&a->send_goal))
        return sp_error_set(err, SP_E_NOTFOUND,
                            "no %s action server answers on %s (ROS domain %d) after %.1f s: is "
                            "Nav2 running, on the same ROS_DOMAIN_ID and network, with "
                            "RMW_IMPLEMENTATION=rmw_cyclonedds_cpp?", ros_action_type_name(a->kind),
                            a->fq, domain_id, ros_now() - t0);
    if (!a->have_result_client) {
        sp_ros_distro d = SP_ROS_DISTRO_HUMBLE;
        char svc[ROS_NAME_MAX + 32], id[64];
        int rc = pick_distro(a, n, &d, err);
        if (rc) return rc;
        if (n->distro == SP_ROS_DISTRO_AUTO && (rc = ros_node_set_distro(n, d, err))) return rc;
        ros_node_csid(n, id, sizeof id);
        if ((rc = part_name(a->fq, "get_result", svc, sizeof svc, err)) ||
            (rc = ros_client_init(&a->get_result, n, svc, result_req(a->kind),
                                  result_rep(a->kind, d), id, err)))
            return rc;
        a->distro = d;
        a->have_result_client = 1;
        if ((rc = ros_node_announce(n, err))) return rc;
    }
    /* The other endpoints of the server; feedback and status only help, so time is shared. */
    while (!(ros_client_ready(&a->get_result) && ros_client_ready(&a->cancel)) &&
           ros_now() < deadline)
        ros_nap();
    if (!ros_client_ready(&a->get_result))
        return sp_error_set(err, SP_E_NOTFOUND, "the %s server on %s has no get_result service "
                            "after %.1f s", ros_action_type_name(a->kind), a->fq, ros_now() - t0);
    while (((a->feedback_r > 0 && !ros_matched_writers(a->feedback_r)) ||
            !ros_matched_writers(a->status_r)) && ros_now() < deadline)
        ros_nap();
    return 0;
}

void ros_action_client_fini(ros_action_client *a, ros_node *n)
{
    ros_client_fini(&a->send_goal, n);
    ros_client_fini(&a->cancel, n);
    if (a->have_result_client) ros_client_fini(&a->get_result, n);
    ros_endpoint_delete(n, a->feedback_r > 0 ? a->feedback_r : 0);
    ros_endpoint_delete(n, a->status_r > 0 ? a->status_r : 0);
    memset(a, 0, sizeof *a);
}

int ros_action_server_init(ros_action_server *a, ros_node *n, ros_action_kind kind,
                           const char *action_fq, sp_ros_distro distro, sp_error *err)
{
    char svc[ROS_NAME_MAX + 32], topic[ROS_NAME_MAX + 40], id[64];
    memset(a, 0, sizeof *a);
    a->kind = kind;
    snprintf(a->fq, sizeof a->fq, "%s", action_fq);
    int rc;
    ros_node_csid(n, id, sizeof id);
    if ((rc = part_name(action_fq, "send_goal", svc, sizeof svc, err)) ||
        (rc = ros_server_init(&a->send_goal, n, svc, goal_req(kind), goal_rep(kind), id, err)))
        return rc;
    ros_node_csid(n, id, sizeof id);
    if ((rc = part_name(action_fq, "cancel_goal", svc, sizeof svc, err)) ||
        (rc = ros_server_init(&a->cancel, n, svc, RT_CANCEL_REQ, RT_CANCEL_REP, id, err)))
        return rc;
    ros_node_csid(n, id, sizeof id);
    if ((rc = part_name(action_fq, "get_result", svc, sizeof svc, err)) ||
        (rc = ros_server_init(&a->get_result, n, svc, result_req(kind), result_rep(kind, distro),
                              id, err)))
        return rc;
    if ((rc = ros_action_part(action_fq, "feedback", 't', topic, sizeof topic, err))) return rc;
    a->feedback_w = ros_writer(n, kind == ROS_ACTION_NAV ? RT_NAV_FEEDBACK : RT_PATH_FEEDBACK,
                               topic, ROS_QOS_DEFAULT, NULL, err);
    if (a->feedback_w < 0) return (int)a->feedback_w;
    if ((rc = ros_action_part(action_fq, "status", 't', topic, sizeof topic, err))) return rc;
    a->status_w = ros_writer(n, RT_STATUS_ARRAY, topic, ROS_QOS_LATCHED, NULL, err);
    return a->status_w < 0 ? (int)a->status_w : 0;
}

void ros_action_server_fini(ros_action_server *a, ros_node *n)
{
    ros_server_fini(&a->send_goal, n);
    ros_server_fini(&a->cancel, n);
    ros_server_fini(&a->get_result, n);
    ros_endpoint_delete(n, a->feedback_w > 0 ? a->feedback_w : 0);
    ros_endpoint_delete(n, a->status_w > 0 ? a->status_w : 0);
    memset(a, 0, sizeof *a);
}
