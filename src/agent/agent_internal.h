/* Private seams of the agent module: the world the tools run on (query engine + navigation, or a
 * fake in tests), the brain interface the three intent backends implement, the neutral
 * conversation they all read, HTTP, and the session's state. */
#ifndef SEMSPLAT_AGENT_INTERNAL_H
#define SEMSPLAT_AGENT_INTERNAL_H

#include <signal.h>
#include <stddef.h>

#include "semsplat/agent.h"

struct cJSON;

/* ---- JSON helpers (json_util.c) -------------------------------------------------------------- */

/* Parses exactly one JSON value from bytes[0..size) (no NUL needed; trailing whitespace allowed,
 * anything else is an error naming the byte offset). what names the input in messages. */
struct cJSON *agent_json_parse(const char *bytes, size_t size, const char *what, sp_error *err);
/* Copies s into out (cap), replacing control characters with spaces: strings from the world or
 * a server go to the model and the terminal as data. Returns out. */
char *agent_clean_copy(char *out, size_t cap, const char *s);
char *agent_strdup(const char *s);
char *agent_strndup(const char *s, size_t n);
/* Appends printf output to a growing buffer (*buf, *len, *cap); returns 0 or SP_E_NOMEM. */
int agent_appendf(char **buf, size_t *len, size_t *cap, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* cJSON number array from n doubles, rounded to 4 decimals (millimetres, 0.006 degrees). */
struct cJSON *agent_json_numbers(const double *v, int n);
double agent_round4(double v);

/* ---- schema validation (schema.c) ------------------------------------------------------------ */

/* Checks value against schema (both parsed). path names the value in messages ("" = top). */
int agent_schema_check(const struct cJSON *schema, const struct cJSON *value, const char *path,
                       sp_error *err);
/* The parsed schema of a tool (parsed once per call; caller deletes). */
struct cJSON *agent_tool_schema_json(int tool, sp_error *err);
/* The tool list as each API wants it: OpenAI [{type:function, function:{name, description,
 * parameters}}], Anthropic [{name, description, input_schema}]. Caller deletes. */
struct cJSON *agent_tools_openai(void);
struct cJSON *agent_tools_anthropic(void);

/* ---- the world (query engine + navigation) --------------------------------------------------- */

#define AGENT_MAX_INSTANCES 16
#define AGENT_MAX_SCENE 32
#define AGENT_MAX_TOUR 20
#define AGENT_MAX_PREVIEWS 8
#define AGENT_PATH_CAP 1024

typedef struct agent_instance {
    double position[3];
    double extent_min[3], extent_max[3]; /* NaN when the world does not know */
    double confidence;
    double score;         /* the world's weight of the instance (relative; NaN = unknown) */
    char region[48];      /* "" when unknown (the tool fills it from region_of) */
    double distance_m;    /* from the robot (filled by the tool) */
} agent_instance;

typedef struct agent_found {
    int found;            /* confident enough to act on */
    double confidence;    /* best raw cosine (or the world's score) */
    double min_confidence;/* the threshold the world used */
    int n;                /* instances, best first */
    agent_instance inst[AGENT_MAX_INSTANCES];
    char source[320];     /* what produced it: encoder, feature source, ground-truth caveat */
    char heatmap[AGENT_PATH_CAP]; /* image path or "" */
} agent_found;

typedef struct agent_goalspec {
    double point[3];
    double yaw;           /* NaN = face the point */
    double tolerance_m;   /* a free pose within this of the point is acceptable */
} agent_goalspec;

typedef struct agent_path {
    int n;
    double *wp;           /* [n][4] x, y, z, yaw (owned; agent_plans_free) */
    double length_m;
    double min_clearance_m, mean_clearance_m; /* NaN when unknown */
    double localizability, semantic, score;   /* NaN when unknown */
    int n_previews;
    char previews[AGENT_MAX_PREVIEWS][AGENT_PATH_CAP];
    char sheet[AGENT_PATH_CAP];
} agent_path;

typedef struct agent_plans {
    int n;
    agent_path paths[SP_AGENT_MAX_K];
    char map_image[AGENT_PATH_CAP];
    char error[32];       /* when n == 0: Nav2's vocabulary (NO_VALID_PATH, GOAL_OCCUPIED, ...) */
    char note[256];       /* e.g. "only 2 distinct trajectories: the map allows no third" */
} agent_plans;

void agent_plans_free(agent_plans *p);

typedef struct agent_scene_item {
    char name[64];
    double position[3];
    double confidence;
    double distance_m;    /* to the anchor's footprint (NaN: the tool computes it) */
    char relation[48];    /* "left of the dining table as seen from the robot" ("" = tool fills) */
    char region[48];
} agent_scene_item;

typedef struct agent_scene {
    int n;
    agent_scene_item items[AGENT_MAX_SCENE];
    char sentence[1024];  /* "" = the tool writes one */
    char source[320];
} agent_scene;

typedef struct agent_tour {
    int n;
    double wp[AGENT_MAX_TOUR][4];
    double length_m;
    char region[64];
    char note[256];
    char map_image[AGENT_PATH_CAP];
} agent_tour;

typedef enum { AGENT_CELL_FREE = 0, AGENT_CELL_OCCUPIED, AGENT_CELL_UNKNOWN, AGENT_CELL_OUTSIDE } agent_cell;
const char *agent_cell_name(int cell);

/* What the tools need from the map. Every op returns 0 or SP_E_* with err; out_dir is where
 * images go (may be NULL: none). */
typedef struct agent_world_ops {
    const char *name;
    int (*query)(void *ctx, const char *text, agent_found *out, sp_error *err);
    /* k paths from start to a free pose within goal->tolerance_m of goal->point, ranked; a failure
     * to find any is a return of 0 with out->n == 0 and out->error set. */
    int (*plan)(void *ctx, const sp_agent_pose *start, const agent_goalspec *goal, int k,
                const char *target, const char *out_dir, agent_plans *out, sp_error *err);
    int (*render)(void *ctx, const sp_agent_pose *pose, const char *png_path, sp_error *err);
    int (*describe)(void *ctx, const agent_instance *anchor, const char *anchor_name,
                    double radius_m, const sp_agent_pose *robot, agent_scene *out, sp_error *err);
    int (*explore)(void *ctx, const char *region, const sp_agent_pose *robot, int max_waypoints,
                   const char *out_dir, agent_tour *out, sp_error *err);
    int (*cell)(void *ctx, double x, double y); /* agent_cell */
    void (*region_of)(void *ctx, double x, double y, char *out, size_t cap);
    /* Up to max names the map holds that are closest to text (for "did you mean"). */
    int (*suggest)(void *ctx, const char *text, char (*names)[64], int max);
    void (*close)(void *ctx);
    /* Where a robot starts when nobody says (the capture's first standpoint); may be NULL. */
    int (*default_start)(void *ctx, sp_agent_pose *pose, sp_error *err);
} agent_world_ops;

typedef struct agent_world {
    const agent_world_ops *ops;
    void *ctx;
} agent_world;

/* The real world on a model folder (world_model.c, world_nav.c): the query engine and the nav
 * scene on cfg->model_dir, images written under cfg->out_dir, on cfg->device (NULL: a CPU device
 * of its own). On a label-feature model the user's words are matched to the scene's class names
 * with WordNet (the lexical encoder) when /usr/share/wordnet is there. */
int agent_world_open_model(agent_world *out, const sp_agent_config *cfg, sp_error *err);

struct sp_query_engine;
struct sp_nav_opts;

/* The same world from an engine in memory (tests). */
typedef struct agent_world_parts {
    struct sp_query_engine *engine; /* required; its splat and cameras in the world frame */
    int own_engine;                 /* 1: the world frees it (also on error) */
    sp_device *dev;                 /* borrowed: must outlive the world */
    const char *const *classes;     /* label scenes: the class names WordNet matches words to
                                     * (NULL: the engine's own text encoder only) */
    int n_classes;
    const struct sp_nav_opts *nav;  /* NULL = sp_nav_opts_default() */
    const char *out_dir;            /* images (NULL: none) */
    const sp_log *log;
} agent_world_parts;

int agent_world_from_parts(agent_world *out, const agent_world_parts *p, sp_error *err);
/* The ROS 2 robot (robot_ros.c). */
int agent_robot_open_ros(sp_agent_robot *out, const sp_agent_config *cfg, sp_error *err);

/* Reads a noun phrase ("the red mug on the counter") as the parser reads a target: the cleaned
 * target, head noun, relation and anchor, selector. */
void agent_parse_phrase(const char *phrase, sp_agent_intent *out);

/* ---- the conversation every brain reads ------------------------------------------------------ */

typedef enum { AGENT_MSG_USER = 0, AGENT_MSG_ASSISTANT, AGENT_MSG_TOOL } agent_role;

typedef struct agent_msg {
    int role;
    char *text;            /* user: the command; assistant: its text (may be NULL); tool: result JSON */
    int n_calls;           /* assistant */
    sp_agent_call *calls;
    char *content_json;    /* assistant, Anthropic: the content array to echo */
    char call_id[96];      /* tool */
    char tool[65];
    int is_error;
} agent_msg;

typedef struct agent_convo {
    int n, cap;
    agent_msg *m;
} agent_convo;

int agent_convo_user(agent_convo *c, const char *text);
/* Takes the reply's calls and content (the reply is left empty). */
int agent_convo_assistant(agent_convo *c, sp_agent_reply *reply);
int agent_convo_tool(agent_convo *c, const char *call_id, const char *tool, const char *result,
                     int is_error);
/* Drops whole exchanges from the front while there are more than max messages. */
void agent_convo_trim(agent_convo *c, int max);
void agent_convo_free(agent_convo *c);
void agent_call_free(sp_agent_call *call);

/* ---- brains ---------------------------------------------------------------------------------- */

typedef struct agent_stats {
    int requests, retries;
} agent_stats;

typedef struct agent_brain {
    const char *name;
    /* The next assistant turn given the conversation so far (last message: the user's or tool
     * results). */
    int (*next)(void *ctx, const agent_convo *c, sp_agent_reply *out, agent_stats *st,
                sp_error *err);
    void (*close)(void *ctx);
    void *ctx;
} agent_brain;

int agent_brain_builtin(agent_brain *out, sp_error *err);
/* dialect: SP_AGENT_BRAIN_OPENAI or SP_AGENT_BRAIN_ANTHROPIC. */
int agent_brain_llm(agent_brain *out, int dialect, const sp_agent_llm_config *cfg,
                    const sp_log *log, sp_error *err);

extern const char agent_system_prompt[]; /* read-only */

/* Request bodies (openai.c, anthropic.c). model, max_tokens and flags come from the client. */
typedef struct agent_llm_wire {
    const char *model;
    int max_tokens;
    int parallel_tool_calls; /* -1 = do not send the field */
} agent_llm_wire;

char *agent_openai_request(const agent_llm_wire *w, const agent_convo *c, sp_error *err);
char *agent_anthropic_request(const agent_llm_wire *w, const agent_convo *c, sp_error *err);

/* ---- retries (retry.c) ----------------------------------------------------------------------- */

typedef enum { AGENT_NET_OK = 0, AGENT_NET_TIMEOUT, AGENT_NET_CONNECT, AGENT_NET_TRUNCATED, AGENT_NET_OTHER } agent_net_kind;

/* Whether to retry after an attempt, and how long to wait first. status: HTTP status (0 when the
 * transport failed, with net saying how); retry_after_s < 0 when the header was absent.
 * why gets a sentence for the log and the final error. */
int agent_retry_decide(long status, int net, const char *body, size_t size, double retry_after_s,
                       int attempt, const sp_agent_llm_config *cfg, unsigned *seed,
                       double *delay_s, char *why, size_t why_cap);
/* Retry-After: delta-seconds or an HTTP-date (relative to now_epoch); -1 when unparseable. */
double agent_parse_retry_after(const char *value, double now_epoch);

/* ---- HTTP (curl/http.c, or nocurl/http.c) ---------------------------------------------------- */

typedef struct agent_http_response {
    long status;
    char *body;            /* NUL-terminated, size bytes (owned) */
    size_t size;
    double retry_after_s;  /* -1 = no header */
    int net;               /* agent_net_kind */
    char net_msg[256];
} agent_http_response;

#define AGENT_HTTP_MAX_BODY (16u << 20)

int agent_http_available(void);
/* POSTs body to url with the given header lines. A transport failure is not an error return: it
 * is reported in resp->net (so retries can decide); errors are only bad arguments / no memory /
 * libcurl missing. Never follows redirects; never uses a proxy for loopback hosts. */
int agent_http_post(const char *url, const char *const *headers, int n_headers, const char *body,
                    size_t body_len, double timeout_s, double connect_timeout_s,
                    agent_http_response *resp, sp_error *err);
void agent_http_response_free(agent_http_response *r);

/* ---- the session ----------------------------------------------------------------------------- */

#define AGENT_MAX_PLANS 64

typedef struct agent_plan_rec {
    char id[16];
    int n;
    double *wp;            /* [n][4] (owned) */
    sp_agent_pose start;   /* the robot pose it was planned from */
    double length_m;
} agent_plan_rec;

struct sp_agent_session {
    sp_agent_config cfg;
    char out_dir[AGENT_PATH_CAP];
    char model_dir[AGENT_PATH_CAP];
    agent_world world;
    sp_agent_robot robot;
    agent_brain brain;
    agent_convo convo;
    agent_plan_rec plans[AGENT_MAX_PLANS];
    int n_plans_issued;    /* ids are plan_<n>, never reused */
    int n_answers;
    int n_images_made;
    volatile sig_atomic_t cancel_requested;
    int goal_active;
    /* the answer being built (images the tools wrote) */
    sp_agent_answer *cur;
    /* ambiguity guard: a query in this command matched several instances, and whether the
     * command (or the question it answers) chose among them */
    int amb_active, amb_n, user_chose, last_asked_back;
    double amb_xy[AGENT_MAX_INSTANCES][2];
    char amb_phrase[SP_AGENT_MAX_PHRASE + 1];
};

/* AMBIGUOUS error result when a goal near (x, y) (or an instance pick, x NaN) picks one of the
 * instances an ambiguous query of this command returned while the user has not chosen; NULL
 * when the call may go ahead. */
char *agent_ambiguity_guard(sp_agent_session *s, int tool, double x, double y);

/* Opens a session on a world and robot the caller built (both move into the session, also on
 * error). Used by sp_agent_session_open and by tests with a fake world. */
int agent_session_open_world(sp_agent_session **out, const sp_agent_config *cfg, agent_world world,
                             sp_agent_robot robot, sp_error *err);

/* Tool execution (tools_exec.c): validates, runs, and returns the result envelope
 * {"tool", "ok", "data"} or {"tool", "ok": false, "error": {code, message, hint}} (malloc'd). */
char *agent_tool_run(sp_agent_session *s, const sp_agent_call *call, int *is_error);
int agent_answer_add_image(sp_agent_answer *a, const char *path);

/* Commitments (commit.c). */
const agent_plan_rec *agent_commit_register(sp_agent_session *s, const agent_path *p,
                                            const sp_agent_pose *start);
/* The plan a goal (x, y, yaw, plan_id) belongs to, or NULL with code/message/hint filled. */
const agent_plan_rec *agent_commit_match(sp_agent_session *s, const sp_agent_args *a,
                                         const sp_agent_pose *robot, char *code, size_t code_cap,
                                         char *msg, size_t msg_cap, char *hint, size_t hint_cap);
double agent_clamp_speed(double mps);
void agent_commit_free(sp_agent_session *s);

/* Geometry helpers shared by tools and the offline robot (geom.c). */
double agent_wrap_angle(double a);
double agent_path_length(const double *wp, int n);
double agent_dist2d(double ax, double ay, double bx, double by);
/* Distance from (x, y) to an axis-aligned footprint (0 inside), or to the point when the extent
 * is unknown (NaN). */
double agent_dist_to_footprint(const agent_instance *in, double x, double y);

#endif
