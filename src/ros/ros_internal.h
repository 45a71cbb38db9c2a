/* Private declarations of the ros module that do not need DDS: ROS names, the simulated robot's
 * map and plans (on the nav module) and its drive, and the message encoders the wire tests
 * compare with an independent serializer (implemented over Cyclone in cyclonedds/encode.c;
 * stubs without it). */
#ifndef SP_ROS_INTERNAL_H
#define SP_ROS_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "semsplat/nav.h"
#include "semsplat/ros.h"

#define ROS_NAME_MAX 256

/* ---- names (names.c) ---- */
int ros_check_namespace(const char *ns, sp_error *err);
/* Resolves a ROS name against a namespace: "odom" + "/r1" -> "/r1/odom"; "/odom" stays. */
int ros_fq_name(const char *ns, const char *name, char *out, size_t cap, sp_error *err);
/* "rt" + fq (kind 't'), "rq" + fq + "Request" ('q'), "rr" + fq + "Reply" ('r'). */
int ros_dds_name(const char *fq, char kind, char *out, size_t cap, sp_error *err);

/* ---- time ---- */
/* Seconds since the epoch (CLOCK_REALTIME), as ROS stamps headers. */
double ros_wall_time(void);
/* Seconds -> (sec, nanosec) with nanosec in [0, 1e9). */
void ros_split_time(double t, int32_t *sec, uint32_t *nsec);

/* ---- the simulated robot's map and plans (simnav.c), on the nav module ---- */
/* The costmap the robot drives on: o->costmap (copied), o->map_yaml or o->model_dir (exactly
 * one), inflated for o->robot_radius_m. */
int ros_sim_costmap(const sp_ros_sim_options *o, const sp_log *log, sp_costmap *cm,
                    sp_error *err);
/* SP_E_ARG (naming the cell and the map's extent) when the robot cannot stand at (x, y):
 * outside the map, occupied or unknown; within the robot radius of an obstacle is allowed. */
int ros_sim_check_start(const sp_costmap *cm, double x, double y, sp_error *err);
/* Checks the goal (sp_costmap_check_goal: outside, occupied, unknown, within the robot radius,
 * not reachable) and plans from start (x, y, yaw) with sp_plan_path. *status is the
 * sp_nav_status (ComputePathToPose's codes); SP_NAV_OK with *path filled and 0 returned,
 * else SP_E_NOTFOUND with err saying why (SP_E_ARG for a non-finite goal, SP_E_NOMEM). */
int ros_sim_plan(const sp_costmap *cm, const double start[3], const sp_ros_pose *goal,
                 sp_path *path, int *status, sp_error *err);
/* 1 when the robot's centre at (x, y) is on an occupied cell or off the map (a collision). */
int ros_sim_collides(const sp_costmap *cm, double x, double y);
/* The plan's any-angle polyline as xy pairs for the drive (malloc'd), ending on the goal. */
int ros_sim_drive_path(const sp_path *p, const sp_ros_pose *goal, double **xy, size_t *n);
/* The plan's waypoints as a ComputePathToPose result in frame, the last pose the goal's. */
int ros_sim_path_result(const sp_path *p, const sp_ros_pose *goal, const char *frame,
                        sp_ros_path *out);
/* ComputePathToPose's Jazzy error_code for an sp_nav_status (START_OUTSIDE_MAP 203 ..
 * NO_VALID_PATH 208: 200 + the status; 0 for OK). */
#define ROS_PATH_ERROR_CODE(status) ((status) ? 200 + (status) : 0)

/* ---- differential drive (drive.c): a unicycle with velocity and acceleration limits following
 * a path (pure pursuit), then turning to the goal heading ---- */
typedef struct ros_drive_limits {
    double max_speed, max_accel, max_yaw_rate, max_yaw_accel;
    double goal_tolerance_m, yaw_tolerance_rad;
    double lookahead_m;
} ros_drive_limits;

typedef struct ros_drive {
    double x, y, yaw;      /* pose in the odom (= map) frame */
    double v, w;           /* current forward and yaw rates */
    double *path;          /* xy pairs being followed (owned), NULL when idle */
    size_t n_path;
    size_t progress;       /* index of the segment the robot is on */
    double goal_yaw;
    int stopping;          /* decelerating to rest (cancel / abort) */
    int turning_in_place;  /* reached the goal position, turning to goal_yaw */
} ros_drive;

typedef enum { ROS_DRIVE_IDLE = 0, ROS_DRIVE_MOVING, ROS_DRIVE_ARRIVED, ROS_DRIVE_STOPPED }
    ros_drive_event;

void ros_drive_init(ros_drive *d, double x, double y, double yaw);
void ros_drive_free(ros_drive *d);
/* Starts following path (taken over, malloc'd xy pairs) to a final heading goal_yaw. */
void ros_drive_follow(ros_drive *d, double *path, size_t n, double goal_yaw);
/* Brings the robot to rest (the path is dropped once stopped). */
void ros_drive_stop(ros_drive *d);
/* Advances dt seconds; ARRIVED once within tolerance and at rest, STOPPED once a stop finished. */
ros_drive_event ros_drive_step(ros_drive *d, const ros_drive_limits *lim, double dt);
/* Length of the path still ahead of the robot. */
double ros_drive_remaining(const ros_drive *d);

/* ---- encoders (cyclonedds/encode.c): exactly what the bridge and the robot write, through the
 * same fill functions and Cyclone's serializer; bytes include the encapsulation header
 * 00 01 00 00, without the padding Cyclone adds on the wire. *out is malloc'd. ---- */
int ros_encode_odometry(const sp_ros_odom *o, const double pose_cov[36],
                        const double twist_cov[36], uint8_t **out, size_t *n, sp_error *err);
int ros_encode_occupancy_grid(const sp_ros_grid *g, double stamp_s, uint8_t **out, size_t *n,
                              sp_error *err);
int ros_encode_path(const sp_ros_path *p, double stamp_s, uint8_t **out, size_t *n,
                    sp_error *err);
int ros_encode_nav_goal_request(const sp_ros_goal_request *r, double stamp_s, uint8_t **out,
                                size_t *n, sp_error *err);
int ros_encode_nav_feedback_message(const sp_ros_feedback_message *m, double stamp_s,
                                    uint8_t **out, size_t *n, sp_error *err);
int ros_encode_nav_result_response(const sp_ros_result_response *r, sp_ros_distro distro,
                                   uint8_t **out, size_t *n, sp_error *err);
int ros_encode_path_result_response(const sp_ros_result_response *r, sp_ros_distro distro,
                                    double stamp_s, uint8_t **out, size_t *n, sp_error *err);
int ros_encode_goal_status_array(const sp_ros_status_array *a, uint8_t **out, size_t *n,
                                 sp_error *err);
int ros_encode_tf(const sp_ros_transform *t, double stamp_s, uint8_t **out, size_t *n,
                  sp_error *err);

#endif
