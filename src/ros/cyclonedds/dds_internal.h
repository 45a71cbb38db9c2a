/* Private to the ros module's DDS side: the node (a Cyclone participant that looks like an
 * rmw_cyclonedds node), the type table, QoS, raw sample access, services with the rmw_cyclonedds
 * request header, and the action client/server pieces built on them. */
#ifndef SP_ROS_DDS_INTERNAL_H
#define SP_ROS_DDS_INTERNAL_H

#include <dds/dds.h>

#include "action_msgs.h"
#include "builtin_interfaces.h"
#include "geometry_msgs.h"
#include "humble.h"
#include "jazzy.h"
#include "nav2_msgs.h"
#include "ros/cdr.h"
#include "ros/ros_internal.h"

/* ---- types ---- */
typedef enum {
    RT_ODOMETRY, RT_PATH, RT_OCCUPANCY_GRID, RT_TF, RT_STATUS_ARRAY, RT_CANCEL_REQ, RT_CANCEL_REP,
    RT_NAV_GOAL_REQ, RT_NAV_GOAL_REP, RT_NAV_RESULT_REQ, RT_NAV_FEEDBACK,
    RT_PATH_GOAL_REQ, RT_PATH_GOAL_REP, RT_PATH_RESULT_REQ, RT_PATH_FEEDBACK,
    RT_NAV_RESULT_REP_HUMBLE, RT_NAV_RESULT_REP_JAZZY,
    RT_PATH_RESULT_REP_HUMBLE, RT_PATH_RESULT_REP_JAZZY,
    RT_DISCOVERY_HUMBLE, RT_DISCOVERY_JAZZY,
    RT_COUNT
} ros_type;

/* The distro variant of a type that has one (RT_NAV_RESULT_REP_HUMBLE + distro, ...). */
ros_type ros_type_for(ros_type humble_variant, sp_ros_distro d);

/* The two request/reply bodies both actions share (identical layouts under both names). */
typedef struct {
    uint64_t guid;
    int64_t seq;
    struct unique_identifier_msgs_msg_dds__UUID_ goal_id;
} ros_goal_id_request;

/* ---- QoS ---- */
typedef struct ros_qos {
    int reliable;        /* else best effort */
    int transient_local; /* else volatile */
    int depth;           /* KEEP_LAST depth; 0 = KEEP_ALL */
} ros_qos;
/* rmw_qos_profile_services_default / rmw_qos_profile_default: reliable, volatile, depth 10. */
#define ROS_QOS_DEFAULT ((ros_qos){1, 0, 10})
/* Action status, maps and discovery info: reliable, transient local, depth 1. */
#define ROS_QOS_LATCHED ((ros_qos){1, 1, 1})
/* Best effort matches both reliable and best-effort writers (drivers publish odometry either
 * way); only the newest sample matters. */
#define ROS_QOS_SENSOR ((ros_qos){0, 0, 5})

/* ---- the node ---- */
#define ROS_MAX_ENDPOINTS 64

typedef struct ros_node {
    dds_entity_t pp;
    int domain_id;
    sp_ros_distro distro;           /* configured or detected; AUTO while undecided */
    int configured;                 /* distro came from the options */
    char ns[ROS_NAME_MAX];          /* namespace as given ("" = root) */
    char name[128];
    dds_guid_t guid;                /* the participant's */
    dds_entity_t builtin_pub, builtin_sub; /* discovery readers for distro detection */
    int seen_jazzy, seen_humble;    /* distro evidence from peers' USER_DATA */
    dds_entity_t disc_writer;       /* ros_discovery_info, once the distro is known */
    dds_entity_t topics[2 * ROS_MAX_ENDPOINTS];
    int n_topics;
    dds_guid_t readers[ROS_MAX_ENDPOINTS], writers[ROS_MAX_ENDPOINTS];
    int n_readers, n_writers;
    unsigned csid_counter;          /* clientid / serviceid numbering */
    dds_topic_descriptor_t *renamed[RT_COUNT]; /* distro variants under their ROS names */
} ros_node;

int ros_node_create(ros_node **out, const sp_ros_options *o, sp_error *err);
void ros_node_free(ros_node *n);
/* The distro in force: the configured one, else what the peers showed so far, else AUTO. */
sp_ros_distro ros_node_distro(ros_node *n);
/* Fixes the distro (after detection) and announces the node. */
int ros_node_set_distro(ros_node *n, sp_ros_distro d, sp_error *err);
/* Publishes ros_discovery_info (the node with its endpoints) when the distro is known. */
int ros_node_announce(ros_node *n, sp_error *err);
/* A fresh "clientid=<id>;" / "serviceid=<id>;" value for USER_DATA. */
void ros_node_csid(ros_node *n, char *out, size_t cap);
/* The distro an endpoint's USER_DATA reveals: JAZZY for typehash= (Iron and later) or our
 * semsplat_distro=jazzy; HUMBLE for semsplat_distro=humble; AUTO when it does not say. */
sp_ros_distro ros_qos_distro(const dds_qos_t *qos);
/* The value of key in USER_DATA "k=v;k2=v2;" (0 found, -1 not). */
int ros_qos_user_data_key(const dds_qos_t *qos, const char *key, char *out, size_t cap);

/* Readers and writers on a DDS topic name, with the QoS rules of rmw_cyclonedds
 * (create_readwrite_qos) and USER_DATA extra (may be NULL) + our distro marker. Returns the
 * entity (> 0) or a negative SP_E_* code with err set. */
dds_entity_t ros_reader(ros_node *n, ros_type t, const char *topic, ros_qos q, const char *extra,
                        sp_error *err);
dds_entity_t ros_writer(ros_node *n, ros_type t, const char *topic, ros_qos q, const char *extra,
                        sp_error *err);
/* Deletes a reader or writer made above (and forgets it for discovery info). */
void ros_endpoint_delete(ros_node *n, dds_entity_t e);

/* Takes up to max samples as serialized bytes (encapsulation header first) and calls fn for each
 * valid one; returns how many were taken. */
typedef void (*ros_sample_fn)(void *ctx, const uint8_t *bytes, size_t n,
                              const dds_sample_info_t *info);
int ros_take_raw(dds_entity_t reader, ros_sample_fn fn, void *ctx, int max);
/* Matched counts (0 on error). */
int ros_matched_writers(dds_entity_t reader);
int ros_matched_readers(dds_entity_t writer);
/* Sleeps a little while waiting for something (10 ms). */
void ros_nap(void);
/* Monotonic seconds. */
static inline double ros_now(void) { return sp_time_now(); }

/* ---- services with the rmw_cyclonedds request header (service.c) ---- */
typedef struct ros_client {
    dds_entity_t req_w, rep_r;
    uint64_t guid;            /* header.guid: the request writer's instance handle, as rmw */
    int64_t seq;              /* last sequence number sent */
    char fq[ROS_NAME_MAX];
} ros_client;

int ros_client_init(ros_client *c, ros_node *n, const char *service_fq, ros_type req,
                    ros_type rep, const char *clientid, sp_error *err);
void ros_client_fini(ros_client *c, ros_node *n);
int ros_client_ready(const ros_client *c);
/* Takes the replies whose header.guid is ours, calling fn for each (other clients' replies are
 * taken and dropped, as rmw_take_response does). */
int ros_client_take(ros_client *c, ros_sample_fn fn, void *ctx);
/* What the matched server's request reader says about itself: whether it carries serviceid=
 * (rmw_cyclonedds does; Fast DDS does not) and the distro its USER_DATA shows. */
int ros_client_server_info(const ros_client *c, int *has_serviceid, sp_ros_distro *distro);

typedef struct ros_server {
    dds_entity_t req_r, rep_w;
    char fq[ROS_NAME_MAX];
} ros_server;

int ros_server_init(ros_server *s, ros_node *n, const char *service_fq, ros_type req,
                    ros_type rep, const char *serviceid, sp_error *err);
void ros_server_fini(ros_server *s, ros_node *n);
int ros_server_take(ros_server *s, ros_sample_fn fn, void *ctx);
/* Writes a reply once the requesting client's reply reader is matched (its clientid= names it),
 * waiting up to ROS_REPLY_WAIT_S for it (rmw_send_response waits 100 ms; the simulated robot
 * gives a loaded machine's discovery more room, blocking only while the reader is missing); a
 * client without clientid is answered at once. Returns 0, or SP_E_NET when the client never
 * showed its reader or is gone. */
#define ROS_REPLY_WAIT_S 0.5
int ros_server_reply(ros_server *s, dds_instance_handle_t request_writer, const void *sample);

/* The {guid, seq} at the front of a request or reply body. */
int ros_peek_header(const uint8_t *bytes, size_t n, sp_ros_rpc_header *h);

/* ---- actions (action.c): the five topics of <action>/_action/... ---- */
typedef enum { ROS_ACTION_NAV = 0, ROS_ACTION_PATH = 1 } ros_action_kind;
const char *ros_action_type_name(ros_action_kind k); /* "NavigateToPose" ... */
/* The ROS names of an action's parts: part is "send_goal", "feedback", ... */
int ros_action_part(const char *action_fq, const char *part, char kind, char *out, size_t cap,
                    sp_error *err);

typedef struct ros_action_client {
    ros_action_kind kind;
    char fq[ROS_NAME_MAX];
    sp_ros_distro distro;     /* AUTO until the result client exists */
    ros_client send_goal, get_result, cancel;
    dds_entity_t feedback_r, status_r;
    int have_result_client;
} ros_action_client;

/* Creates what does not depend on the distro: send_goal, cancel_goal, feedback, status. */
int ros_action_client_init(ros_action_client *a, ros_node *n, ros_action_kind kind,
                           const char *action_fq, sp_error *err);
/* Waits (until deadline, monotonic seconds) for the server, checks it is rmw_cyclonedds of a
 * compatible distro, creates the get_result client for that distro and waits for it too. */
int ros_action_client_connect(ros_action_client *a, ros_node *n, double deadline,
                              int domain_id, sp_error *err);
void ros_action_client_fini(ros_action_client *a, ros_node *n);

typedef struct ros_action_server {
    ros_action_kind kind;
    char fq[ROS_NAME_MAX];
    ros_server send_goal, get_result, cancel;
    dds_entity_t feedback_w, status_w;
} ros_action_server;

int ros_action_server_init(ros_action_server *a, ros_node *n, ros_action_kind kind,
                           const char *action_fq, sp_ros_distro distro, sp_error *err);
void ros_action_server_fini(ros_action_server *a, ros_node *n);

/* ---- filling the IDL structs from plain values (fill.c); strings point into the inputs ---- */
void ros_fill_time(struct builtin_interfaces_msg_dds__Time_ *t, double seconds);
void ros_fill_pose(struct geometry_msgs_msg_dds__Pose_ *p, const sp_ros_pose *pose);
void ros_fill_pose_stamped(struct geometry_msgs_msg_dds__PoseStamped_ *p, const sp_ros_pose *pose,
                           const char *frame, double stamp_s);
void ros_fill_odometry(nav_msgs_msg_dds__Odometry_ *m, const sp_ros_odom *o,
                       const double pose_cov[36], const double twist_cov[36]);
/* Path and grid allocate their sequence buffers: free with ros_unfill_*. */
int ros_fill_path(nav_msgs_msg_dds__Path_ *m, const sp_ros_path *p, const char *frame,
                  double stamp_s);
void ros_unfill_path(nav_msgs_msg_dds__Path_ *m);
void ros_fill_occupancy_grid(nav_msgs_msg_dds__OccupancyGrid_ *m, const sp_ros_grid *g,
                             const char *frame, double stamp_s);
void ros_fill_nav_goal_request(nav2_msgs_action_dds__NavigateToPose_SendGoal_Request_ *m,
                               const sp_ros_goal_request *r, double stamp_s);
void ros_fill_nav_feedback_message(nav2_msgs_action_dds__NavigateToPose_FeedbackMessage_ *m,
                                   const sp_ros_feedback_message *f, double stamp_s);
void ros_fill_tf(tf2_msgs_msg_dds__TFMessage_ *m,
                 struct geometry_msgs_msg_dds__TransformStamped_ *one, const sp_ros_transform *t,
                 double stamp_s);
/* GetResult responses (distro layouts); path results allocate like ros_fill_path. */
void ros_fill_nav_result_humble(humble_nav2_msgs_action_dds__NavigateToPose_GetResult_Response_ *m,
                                const sp_ros_result_response *r);
void ros_fill_nav_result_jazzy(jazzy_nav2_msgs_action_dds__NavigateToPose_GetResult_Response_ *m,
                               const sp_ros_result_response *r);
int ros_fill_path_result_humble(
    humble_nav2_msgs_action_dds__ComputePathToPose_GetResult_Response_ *m,
    const sp_ros_result_response *r, double stamp_s);
int ros_fill_path_result_jazzy(jazzy_nav2_msgs_action_dds__ComputePathToPose_GetResult_Response_ *m,
                               const sp_ros_result_response *r, double stamp_s);
/* GoalStatusArray with n entries (allocated; free with ros_unfill_status_array). */
int ros_fill_status_array(action_msgs_msg_dds__GoalStatusArray_ *m, const sp_ros_status_array *a);
void ros_unfill_status_array(action_msgs_msg_dds__GoalStatusArray_ *m);

/* Serializes a filled sample with Cyclone's own serializer (the ops idlc generated), XCDR1,
 * little-endian, behind the header 00 01 00 00. */
int ros_serialize(const dds_topic_descriptor_t *desc, const void *sample, uint8_t **out,
                  size_t *n, sp_error *err);
const dds_topic_descriptor_t *ros_type_descriptor(ros_type t);

#endif
