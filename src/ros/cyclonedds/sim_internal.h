/* The simulated robot's state, shared by sim.c (the loop, the body, odometry) and
 * sim_actions.c (the NavigateToPose and ComputePathToPose servers). */
#ifndef SP_ROS_SIM_INTERNAL_H
#define SP_ROS_SIM_INTERNAL_H

#include "dds_internal.h"

#define SIM_MAX_GOALS 32
#define SIM_MAX_WAITING 4
/* How long a finished goal's result stays available (rcl's Humble default is 15 min, Jazzy's
 * 10 s; Nav2's bt_navigator 900 s). */
#define SIM_RESULT_KEEP_S 60.0

typedef struct sim_waiting {
    sp_ros_rpc_header header;
    dds_instance_handle_t writer;
} sim_waiting;

typedef struct sim_goal {
    ros_action_kind kind;
    uint8_t uuid[16];
    double accepted_stamp;     /* wall clock, for GoalInfo.stamp */
    int status;                /* action_msgs GoalStatus */
    sp_ros_pose target;
    double started_sim;        /* simulated time at acceptance */
    sp_ros_result_response result; /* valid once terminal; CPTP owns the path */
    sim_waiting waiting[SIM_MAX_WAITING]; /* GetResult requests held until the goal ends */
    int n_waiting;
    double finished_mono;      /* monotonic time it became terminal */
} sim_goal;

typedef struct sim {
    const sp_ros_sim_options *o;
    const sp_log *log;
    sp_ros_distro distro;
    ros_node *node;
    sp_costmap cm;             /* what it plans and collides on */
    ros_drive drive;
    ros_drive_limits lim;
    ros_action_server nav, path;
    dds_entity_t odom_w, tf_w, map_w;
    sim_goal goals[SIM_MAX_GOALS];
    int n_goals;
    int active;                /* index of the NavigateToPose goal being driven, -1 none */
    double sim_time;
    char odom_frame[32], base_frame[32], map_frame[128];
} sim;

/* Handles every request waiting on both action servers. */
void sim_serve(sim *s);
/* Advances the active goal after a drive step: success, cancel done, collision. */
void sim_goal_progress(sim *s, ros_drive_event ev);
/* Feedback for the active goal. */
void sim_feedback(sim *s);
/* Drops results older than SIM_RESULT_KEEP_S. */
void sim_expire(sim *s);

#endif
