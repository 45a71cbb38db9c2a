/* The bridge's state, shared by bridge.c (odometry, map, paths), goal.c (NavigateToPose) and
 * path_client.c (ComputePathToPose). */
#ifndef SP_ROS_BRIDGE_INTERNAL_H
#define SP_ROS_BRIDGE_INTERNAL_H

#include "dds_internal.h"

#define BRIDGE_MAX_GOALS 16

struct sp_ros_goal {
    sp_ros_bridge *b;          /* NULL once the bridge is gone */
    uint8_t uuid[16];
    int64_t goal_seq, result_seq, cancel_seq;
    int answered, accepted;    /* the SendGoal reply */
    int cancel_answered, cancel_code;
    sp_ros_goal_status st;
    double last_heard;         /* monotonic */
    double terminal_since;     /* when status first said terminal (0: not yet) */
};

struct sp_ros_bridge {
    sp_ros_options opt;        /* strings point at the copies below */
    char ns[ROS_NAME_MAX], node_name[128], map_frame[128];
    char nav_fq[ROS_NAME_MAX], path_fq[ROS_NAME_MAX], paths_fq[ROS_NAME_MAX];
    char odom_topic[ROS_NAME_MAX + 8];
    ros_node *node;
    dds_entity_t odom_r, tf_r, map_w, path_w[SP_ROS_MAX_PATHS];
    sp_ros_transform map_odom;  /* the newest map -> odometry-frame transform from tf */
    int have_map_odom;
    int n_paths_shown;
    sp_ros_odom odom;
    int have_odom;
    double odom_rx;
    long odom_bad;
    char odom_bad_msg[512];
    ros_action_client nav, path;
    int nav_made, path_made;
    sp_ros_goal *goals[BRIDGE_MAX_GOALS];
    int n_goals;
    long bad_samples;          /* malformed action samples seen (the last message below) */
    char bad_msg[512];
};

/* Settles the distro from the peers when it was AUTO and something is known now. */
void bridge_tick(sp_ros_bridge *b);
/* Creates and connects an action client on first use (within server_timeout_s). */
int bridge_action(sp_ros_bridge *b, ros_action_kind kind, sp_error *err);
/* 16 random bytes as a version-4 UUID. */
void bridge_uuid(uint8_t uuid[16]);
/* Records a malformed sample (kept for messages about lost goals). */
void bridge_bad_sample(sp_ros_bridge *b, const sp_error *e);

#endif
