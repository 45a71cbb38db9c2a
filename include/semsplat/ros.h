/* semsplat ros: talks to a ROS 2 robot directly over DDS (Eclipse Cyclone DDS), exactly as a node
 * using rmw_cyclonedds_cpp does, without ROS 2 installed. Three parts:
 *
 *   - the bridge (sp_ros_bridge): the latest /odom pose with its age; a Nav2 NavigateToPose
 *     client (send, accepted/rejected, feedback, status, result, cancel); a ComputePathToPose
 *     client; publishing our costmap as nav_msgs/OccupancyGrid (transient local, like
 *     map_server) and ranked candidate paths as nav_msgs/Path, for RViz and Foxglove;
 *   - the simulated robot (sp_ros_sim_run): a differential-drive robot that serves
 *     NavigateToPose and ComputePathToPose on the nav module's costmap and planner (so ros
 *     depends on nav), publishes /odom at 20 Hz and /tf
 *     (odom -> base_link at 20 Hz, map -> odom identity at 2 Hz, as a localization would);
 *   - wire decoders (sp_ros_decode_*): bounds-checked CDR readers, one per message type, that
 *     take (bytes, size) and fail with a message naming the field and offset; never a crash.
 *
 * The API speaks robot: poses as x, y, z, yaw in metres and radians, grids as plain cells; no
 * DDS type appears here. ROS names follow ROS rules: relative names ("odom") get the namespace,
 * absolute ones ("/odom") do not. Humble and Jazzy differ on the wire (NavigateToPose's result,
 * discovery GIDs); the distro is chosen by the options or detected from the peers.
 *
 * Threads: a bridge is not thread-safe; use it from one thread (Cyclone's own threads run
 * beneath it). Nothing runs in the background of ours: state (odometry, feedback, results) is
 * taken from DDS when a function is called. Ownership: whoever creates frees; *_free() accepts
 * NULL. Errors: 0 or a negative SP_E_* code with a message in the sp_error; outputs are left as
 * they were on error unless documented. Without Cyclone DDS at build time, every function that
 * needs it fails with SP_E_UNSUPPORTED naming the package (cyclonedds-dev). */
#ifndef SEMSPLAT_ROS_H
#define SEMSPLAT_ROS_H

#include <signal.h>
#include <stddef.h>
#include <stdint.h>

#include "semsplat/core.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- common types ---------------------------------------------------------------------------- */

typedef enum {
    SP_ROS_DISTRO_AUTO = 0, /* detect from the peers (typehash= in USER_DATA means Jazzy) */
    SP_ROS_DISTRO_HUMBLE,
    SP_ROS_DISTRO_JAZZY
} sp_ros_distro;

/* "auto", "humble" or "jazzy"; anything else is SP_E_ARG naming the value. */
int sp_ros_distro_parse(const char *name, sp_ros_distro *out, sp_error *err);
const char *sp_ros_distro_name(sp_ros_distro d);

/* A planar robot pose in a frame (usually "map" or "odom"): metres and radians (yaw about +z,
 * counter-clockwise from +x). z is carried through (0 for ground robots). */
typedef struct sp_ros_pose {
    double x, y, z, yaw;
} sp_ros_pose;

/* A path: n poses (owned; sp_ros_path_free) in frame_id (empty = the bridge's map frame). */
typedef struct sp_ros_path {
    size_t n;
    sp_ros_pose *poses;
    char frame_id[128];
} sp_ros_path;
void sp_ros_path_free(sp_ros_path *p);

/* An occupancy grid as nav_msgs/OccupancyGrid has it: cells[row * width + col], row 0 at the
 * lowest y (the origin's side), -1 unknown, 0 free .. 100 occupied. origin_* is the pose of cell
 * (0, 0)'s outer corner in the map frame. sp_ros_publish_map borrows cells; the decoder and
 * sp_ros_grid_from_costmap allocate them (free with sp_ros_grid_free). */
typedef struct sp_ros_grid {
    int width, height;
    double resolution_m;
    double origin_x, origin_y, origin_yaw;
    int8_t *cells;
    char frame_id[128];
} sp_ros_grid;
void sp_ros_grid_free(sp_ros_grid *g);

/* The nav module's costmap as a grid (sp_costmap_to_occupancy_grid: with use_costs 0 the map,
 * free 0 / occupied 100 / unknown -1; with 1 the inflated costs as Nav2's costmap publisher
 * sends them), in frame_id (NULL or "" = "map"). Cells are allocated (sp_ros_grid_free). */
struct sp_costmap;
int sp_ros_grid_from_costmap(const struct sp_costmap *cm, int use_costs, const char *frame_id,
                             sp_ros_grid *out, sp_error *err);

/* Odometry as the robot reports it (nav_msgs/Odometry without the covariances). */
typedef struct sp_ros_odom {
    sp_ros_pose pose;             /* in frame_id (usually "odom") */
    double qx, qy, qz, qw;        /* the full orientation (yaw above is its heading) */
    double vx, vy, wz;            /* twist in child_frame_id: m/s, m/s, rad/s */
    double stamp_s;               /* header stamp, seconds since the epoch (robot clock) */
    char frame_id[128];
    char child_frame_id[128];
} sp_ros_odom;

/* ---- the bridge ------------------------------------------------------------------------------ */

typedef struct sp_ros_options {
    int domain_id;                   /* DDS domain = ROS_DOMAIN_ID, 0..232 (default 0) */
    sp_ros_distro distro;            /* default AUTO */
    const char *ns;                  /* ROS namespace, "" or "/robot1" (default "") */
    const char *node_name;           /* as `ros2 node list` shows it (default "semsplat") */
    const char *odom_topic;          /* default "odom" */
    const char *navigate_action;     /* default "navigate_to_pose" */
    const char *compute_path_action; /* default "compute_path_to_pose" */
    const char *map_topic;           /* where publish_map writes (default "semsplat/map") */
    const char *paths_topic;         /* publish_paths writes <paths_topic>_1 .. _k, best first
                                        (default "semsplat/path") */
    const char *map_frame;           /* frame of goals, maps and paths (default "map") */
    int loopback_only;               /* Cyclone on lo only, no multicast, peers 127.0.0.1
                                        (tests; one machine) */
    const char *dds_config;          /* Cyclone XML or file:// URI; NULL = $CYCLONEDDS_URI */
    double server_timeout_s;         /* waiting for an action server (default 5) */
    double odom_stale_s;             /* odometry older than this is stale (default 0.5) */
} sp_ros_options;

void sp_ros_options_default(sp_ros_options *o);

typedef struct sp_ros_bridge sp_ros_bridge;

/* Joins the DDS domain as a ROS node (it appears in `ros2 node list` once the distro is known),
 * subscribes to odometry and prepares the map and path writers. Action clients are created on
 * first use. Errors: SP_E_ARG (bad name or domain), SP_E_NET (DDS could not start). */
int sp_ros_bridge_create(sp_ros_bridge **out, const sp_ros_options *opt, sp_error *err);
void sp_ros_bridge_free(sp_ros_bridge *b);
/* The distro in use: the configured one, or the detected one, or AUTO while nothing decided. */
sp_ros_distro sp_ros_bridge_distro(sp_ros_bridge *b);

/* The newest odometry received so far and its age (seconds since it arrived here, by our
 * clock, so robot clock skew does not matter). Returns SP_E_NOTFOUND when none has arrived, and
 * SP_E_NET with *out and *age_s filled when the newest is older than odom_stale_s. age_s may be
 * NULL. */
int sp_ros_odom_latest(sp_ros_bridge *b, sp_ros_odom *out, double *age_s, sp_error *err);
/* Waits up to timeout_s for fresh odometry (then as sp_ros_odom_latest). */
int sp_ros_odom_wait(sp_ros_bridge *b, double timeout_s, sp_ros_odom *out, sp_error *err);
/* The robot's pose in the map frame, what goals and our maps use: the newest odometry composed
 * with the newest map -> <odometry frame> transform on tf (published by the localization, e.g.
 * AMCL or slam_toolbox), or the odometry itself when it is already in the map frame. age_s (may
 * be NULL) is the odometry's age. Errors as sp_ros_odom_latest, plus SP_E_NOTFOUND when no such
 * transform has been seen (is localization running?). */
int sp_ros_robot_pose(sp_ros_bridge *b, sp_ros_pose *map_pose, double *age_s, sp_error *err);

/* Goal states: action_msgs/GoalStatus codes 0..6, plus REJECTED (the server said no) and
 * LOST (the server vanished or stopped answering for this goal). */
typedef enum {
    SP_ROS_GOAL_UNKNOWN = 0,
    SP_ROS_GOAL_ACCEPTED = 1,
    SP_ROS_GOAL_EXECUTING = 2,
    SP_ROS_GOAL_CANCELING = 3,
    SP_ROS_GOAL_SUCCEEDED = 4,
    SP_ROS_GOAL_CANCELED = 5,
    SP_ROS_GOAL_ABORTED = 6,
    SP_ROS_GOAL_REJECTED = 7,
    SP_ROS_GOAL_LOST = 8
} sp_ros_goal_state;
const char *sp_ros_goal_state_name(sp_ros_goal_state s);
static inline int sp_ros_goal_state_terminal(sp_ros_goal_state s)
{
    return s >= SP_ROS_GOAL_SUCCEEDED;
}

/* NavigateToPose feedback (nav2_msgs/action/NavigateToPose Feedback). */
typedef struct sp_ros_nav_feedback {
    sp_ros_pose current_pose;     /* in current_frame */
    char current_frame[128];
    double navigation_time_s;
    double eta_s;                 /* estimated_time_remaining */
    int recoveries;               /* number_of_recoveries */
    double distance_remaining_m;
} sp_ros_nav_feedback;

typedef struct sp_ros_goal_status {
    sp_ros_goal_state state;
    long feedback_count;          /* feedback messages received for this goal */
    sp_ros_nav_feedback feedback; /* the latest (valid when feedback_count > 0) */
    int have_result;              /* the GetResult reply arrived */
    int error_code;               /* Jazzy result error_code (0 on Humble or none) */
    char error_msg[256];          /* Jazzy result error_msg, or why the goal was LOST/REJECTED */
    double age_s;                 /* seconds since anything was heard about this goal */
} sp_ros_goal_status;

typedef struct sp_ros_goal sp_ros_goal;

/* Sends a NavigateToPose goal (pose in the map frame; behavior_tree NULL or "" = the server's
 * default), waiting up to server_timeout_s for a server and then (up to 1 s more) for its
 * answer. On return 0,
 * *out is a goal whose state is ACCEPTED or REJECTED; an accepted goal's result has already been
 * requested (GetResult right after acceptance, as rclcpp_action does). Errors: SP_E_NOTFOUND (no
 * action server: the message names the action, domain and what to check), SP_E_UNSUPPORTED (a
 * server that is not rmw_cyclonedds, or of another distro than configured), SP_E_NET (no answer
 * in time), SP_E_ARG (non-finite pose). */
int sp_ros_navigate_to(sp_ros_bridge *b, const sp_ros_pose *goal, const char *behavior_tree,
                       sp_ros_goal **out, sp_error *err);
/* Takes what arrived (feedback, status, result) and reports it. Never blocks. */
int sp_ros_goal_poll(sp_ros_goal *g, sp_ros_goal_status *st, sp_error *err);
/* Polls until the goal is terminal or timeout_s passes (then returns 0 with a non-terminal st).
 * on_feedback, when given, is called for each poll that brought new feedback. */
int sp_ros_goal_wait(sp_ros_goal *g, double timeout_s, sp_ros_goal_status *st,
                     void (*on_feedback)(void *user, const sp_ros_goal_status *st), void *user,
                     sp_error *err);
/* Asks the server to cancel this goal and waits up to timeout_s for its answer. Returns 0 when
 * the server is canceling it (the state becomes CANCELED once the robot stopped) or it had
 * already finished; SP_E_NET without an answer; SP_E_ARG when the server refused. */
int sp_ros_goal_cancel(sp_ros_goal *g, double timeout_s, sp_error *err);
/* The goal's 16-byte UUID (as in action_msgs), e.g. for logs. */
void sp_ros_goal_uuid(const sp_ros_goal *g, uint8_t uuid[16]);
void sp_ros_goal_free(sp_ros_goal *g);

/* Asks the ComputePathToPose server for a path from start (NULL: the robot's current pose, as
 * Nav2 does with use_start = false) to goal, with planner_id (NULL or "" = the default), waiting
 * up to timeout_s. On success *path holds the poses (caller frees) and *planning_time_s (may be
 * NULL) the server's planning time. Errors as sp_ros_navigate_to, plus SP_E_NOTFOUND when the
 * server rejected the goal or found no path (the message says which, with Jazzy's error_code). */
int sp_ros_compute_path(sp_ros_bridge *b, const sp_ros_pose *start, const sp_ros_pose *goal,
                        const char *planner_id, double timeout_s, sp_ros_path *path,
                        double *planning_time_s, sp_error *err);

/* Publishes the grid on map_topic (transient local, reliable, depth 1: a late RViz still gets
 * it). The frame is the grid's frame_id, or map_frame when empty. Validates sizes and values. */
int sp_ros_publish_map(sp_ros_bridge *b, const sp_ros_grid *grid, sp_error *err);
/* Publishes n ranked paths (best first) on <paths_topic>_1 .. _n (transient local); topics of a
 * previous, longer call get an empty path so stale candidates disappear. n <= SP_ROS_MAX_PATHS. */
#define SP_ROS_MAX_PATHS 8
int sp_ros_publish_paths(sp_ros_bridge *b, const sp_ros_path *paths, int n, sp_error *err);

/* The DDS topic name a ROS name maps to under these options ("odom" -> "rt/robot1/odom"), for
 * messages and logs. kind: 't' topic, 'q' request, 'r' reply. Returns -1 on a bad name. */
int sp_ros_dds_topic_name(const sp_ros_options *opt, const char *ros_name, char kind, char *out,
                          size_t cap, sp_error *err);

/* ---- the simulated robot --------------------------------------------------------------------- */
/* It plans on the nav module's costmap (include/semsplat/nav.h): built from a model folder's
 * splat and training cameras (sp_costmap_build_model), read from a Nav2 map.yaml
 * (sp_costmap_read_map) or given in memory, inflated for robot_radius_m. Goals are checked
 * with sp_costmap_check_goal and planned with sp_plan_path. NavigateToPose goals that are
 * outside the map, occupied, unknown, closer than the robot radius to an obstacle or not
 * reachable are rejected; ComputePathToPose goals are accepted and then aborted with Nav2's
 * planner error codes (Jazzy: error_code 203..208 = 200 + sp_nav_status, error_msg saying why),
 * as Nav2's planner server does. The map is published on <ns>/map (transient local). */

struct sp_device;

typedef struct sp_ros_sim_options {
    sp_ros_options ros;        /* domain, distro (AUTO is taken as Jazzy), namespace, topics */
    const char *map_yaml;      /* a Nav2 map.yaml (+ its PGM), or */
    const char *model_dir;     /* a model folder (splat.ply, train.json naming its capture): the
                                * costmap is built from the splat, or */
    const struct sp_costmap *costmap; /* a costmap in memory (copied, re-inflated) */
    struct sp_device *device;  /* renders the carving for model_dir (borrowed; NULL = a CPU
                                * device made for it) */
    double start_x, start_y, start_yaw;
    double robot_radius_m;     /* inflation for planning (default 0.2) */
    double max_speed;          /* m/s (default 0.5) */
    double max_accel;          /* m/s^2 (default 0.5) */
    double max_yaw_rate;       /* rad/s (default 1.5) */
    double max_yaw_accel;      /* rad/s^2 (default 3.0) */
    double goal_tolerance_m;   /* xy tolerance of a reached goal (default 0.1) */
    double yaw_tolerance_rad;  /* heading tolerance at the goal (default 0.15) */
    double rate_hz;            /* odometry and control rate (default 20) */
    double time_scale;         /* simulated seconds per wall second (default 1) */
    double duration_s;         /* stop after this long (0 = until *stop) */
    const char *ready_file;    /* written once every endpoint exists (tests wait for it) */
} sp_ros_sim_options;

void sp_ros_sim_options_default(sp_ros_sim_options *o);

/* Runs the robot until *stop becomes non-zero (a signal handler sets it) or duration_s passes.
 * Logs goals and their outcomes through log (may be NULL). Errors: the costmap could not be
 * loaded or built, the start pose is outside the map, occupied or unknown, DDS could not
 * start. */
int sp_ros_sim_run(const sp_ros_sim_options *o, const volatile sig_atomic_t *stop,
                   const sp_log *log, sp_error *err);

/* ---- wire decoders --------------------------------------------------------------------------- */
/* Each takes one serialized sample as DDS carries it (the 4-byte encapsulation header, then
 * XCDR1 little- or big-endian) and fills plain structs. Bounds-checked: a short, oversized or
 * inconsistent sample (string without its NUL, a count beyond the bytes left, a non-finite
 * pose, an unknown encapsulation) fails with SP_E_FORMAT or SP_E_NUMERIC and a message naming
 * the type, field and offset; outputs that own memory are freed and zeroed on error. Trailing
 * bytes (Cyclone's padding to a multiple of 4) are allowed. These are the fuzzing entry points. */

/* The {guid, seq} rmw_cyclonedds puts in front of every request and reply. */
typedef struct sp_ros_rpc_header {
    uint64_t guid;
    int64_t seq;
} sp_ros_rpc_header;

typedef struct sp_ros_goal_request {     /* NavigateToPose / ComputePathToPose SendGoal request */
    sp_ros_rpc_header header;
    uint8_t goal_id[16];
    sp_ros_pose pose;                    /* NavigateToPose: pose; ComputePathToPose: goal */
    char frame_id[128];
    sp_ros_pose start;                   /* ComputePathToPose only */
    char start_frame_id[128];
    int use_start;                       /* ComputePathToPose only */
    char behavior_tree[256];             /* NavigateToPose: behavior_tree; CPTP: planner_id */
} sp_ros_goal_request;

typedef struct sp_ros_goal_response {    /* SendGoal response */
    sp_ros_rpc_header header;
    int accepted;
    double stamp_s;
} sp_ros_goal_response;

typedef struct sp_ros_goal_id_request {  /* GetResult request */
    sp_ros_rpc_header header;
    uint8_t goal_id[16];
} sp_ros_goal_id_request;

typedef struct sp_ros_result_response {  /* GetResult response */
    sp_ros_rpc_header header;
    int status;                          /* action_msgs GoalStatus code */
    int error_code;                      /* Jazzy */
    char error_msg[256];                 /* Jazzy (longer messages are cut, ending in "...") */
    sp_ros_path path;                    /* ComputePathToPose (owned) */
    double planning_time_s;              /* ComputePathToPose */
} sp_ros_result_response;

typedef struct sp_ros_feedback_message { /* NavigateToPose FeedbackMessage */
    uint8_t goal_id[16];
    sp_ros_nav_feedback feedback;
} sp_ros_feedback_message;

typedef struct sp_ros_goal_status_entry {
    uint8_t goal_id[16];
    double stamp_s;
    int status;
} sp_ros_goal_status_entry;

typedef struct sp_ros_status_array {     /* action_msgs/GoalStatusArray (entries owned) */
    size_t n;
    sp_ros_goal_status_entry *entries;
} sp_ros_status_array;
void sp_ros_status_array_free(sp_ros_status_array *a);

typedef struct sp_ros_cancel_request {   /* action_msgs/srv/CancelGoal request */
    sp_ros_rpc_header header;
    uint8_t goal_id[16];
    double stamp_s;
} sp_ros_cancel_request;

typedef struct sp_ros_cancel_response {  /* action_msgs/srv/CancelGoal response */
    sp_ros_rpc_header header;
    int return_code;                     /* 0 NONE, 1 REJECTED, 2 UNKNOWN_GOAL_ID, 3 TERMINATED */
    size_t n_canceling;
    uint8_t first_goal_id[16];           /* the first of goals_canceling, when n_canceling > 0 */
} sp_ros_cancel_response;

typedef struct sp_ros_transform {        /* the first transform of a tf2_msgs/TFMessage */
    size_t n_transforms;
    char frame_id[128], child_frame_id[128];
    double x, y, z, qx, qy, qz, qw;
} sp_ros_transform;

int sp_ros_decode_odometry(const uint8_t *bytes, size_t size, sp_ros_odom *out, sp_error *err);
int sp_ros_decode_path(const uint8_t *bytes, size_t size, sp_ros_path *out, sp_error *err);
int sp_ros_decode_occupancy_grid(const uint8_t *bytes, size_t size, sp_ros_grid *out,
                                 sp_error *err);
int sp_ros_decode_tf_message(const uint8_t *bytes, size_t size, sp_ros_transform *out,
                             sp_error *err);
/* The first parent -> child transform of a TFMessage (SP_E_NOTFOUND when it has none). */
int sp_ros_decode_tf_find(const uint8_t *bytes, size_t size, const char *parent,
                          const char *child, sp_ros_transform *out, sp_error *err);
int sp_ros_decode_nav_goal_request(const uint8_t *bytes, size_t size, sp_ros_goal_request *out,
                                   sp_error *err);
int sp_ros_decode_path_goal_request(const uint8_t *bytes, size_t size, sp_ros_goal_request *out,
                                    sp_error *err);
int sp_ros_decode_goal_response(const uint8_t *bytes, size_t size, sp_ros_goal_response *out,
                                sp_error *err);
int sp_ros_decode_goal_id_request(const uint8_t *bytes, size_t size, sp_ros_goal_id_request *out,
                                  sp_error *err);
/* The result layouts differ by distro (Humble: Empty; Jazzy: error_code, error_msg). */
int sp_ros_decode_nav_result_response(const uint8_t *bytes, size_t size, sp_ros_distro distro,
                                      sp_ros_result_response *out, sp_error *err);
int sp_ros_decode_path_result_response(const uint8_t *bytes, size_t size, sp_ros_distro distro,
                                       sp_ros_result_response *out, sp_error *err);
void sp_ros_result_response_free(sp_ros_result_response *r);
int sp_ros_decode_nav_feedback_message(const uint8_t *bytes, size_t size,
                                       sp_ros_feedback_message *out, sp_error *err);
int sp_ros_decode_goal_status_array(const uint8_t *bytes, size_t size, sp_ros_status_array *out,
                                    sp_error *err);
int sp_ros_decode_cancel_request(const uint8_t *bytes, size_t size, sp_ros_cancel_request *out,
                                 sp_error *err);
int sp_ros_decode_cancel_response(const uint8_t *bytes, size_t size, sp_ros_cancel_response *out,
                                  sp_error *err);

/* Quaternion <-> yaw for planar poses (yaw of the rotation's heading; roll/pitch ignored). The
 * quaternion need not be unit length; any finite one gives a finite yaw (0 for all zeros). */
double sp_ros_quat_yaw(double qx, double qy, double qz, double qw);
void sp_ros_yaw_quat(double yaw, double *qx, double *qy, double *qz, double *qw);

#ifdef __cplusplus
}
#endif

#endif
