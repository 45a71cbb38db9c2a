/* Private declarations of the ros module that do not need DDS: ROS names, the simulated robot's
 * planner and drive, and the message encoders the wire tests compare with an independent
 * serializer (implemented over Cyclone in cyclonedds/encode.c; stubs without it). */
#ifndef SP_ROS_INTERNAL_H
#define SP_ROS_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

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

/* ---- the simulated robot's planner (plan.c): behind a small interface so the nav module's
 * costmap and planner can replace the built-in grid A* without touching the robot ---- */
typedef struct ros_planner ros_planner;
typedef enum { ROS_CELL_FREE = 0, ROS_CELL_OCCUPIED, ROS_CELL_UNKNOWN, ROS_CELL_OUTSIDE,
               ROS_CELL_NEAR_OBSTACLE } ros_cell_class;
/* A planner over the grid (copied) for a robot of radius robot_radius_m. */
int ros_planner_create(ros_planner **out, const sp_ros_grid *grid, double robot_radius_m,
                       sp_error *err);
void ros_planner_free(ros_planner *p);
/* Where a point falls: free for the robot's centre, occupied, unknown, outside the map, or free
 * but closer than the robot radius to an obstacle or unknown space. */
ros_cell_class ros_planner_classify(const ros_planner *p, double x, double y);
const char *ros_cell_class_name(ros_cell_class c);
/* A path from (sx, sy) to (gx, gy) through cells the robot fits in: xy[2*i], xy[2*i+1] for
 * i < *n (malloc'd, caller frees), start and goal included. SP_E_NOTFOUND when none exists;
 * SP_E_ARG when start or goal is not free (the message says why). */
int ros_planner_plan(const ros_planner *p, double sx, double sy, double gx, double gy,
                     double **xy, size_t *n, sp_error *err);
/* Is the robot's footprint centre at (x, y) clear of lethal cells (for collision checks)? */
int ros_planner_is_lethal(const ros_planner *p, double x, double y);
const sp_ros_grid *ros_planner_grid(const ros_planner *p);

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
