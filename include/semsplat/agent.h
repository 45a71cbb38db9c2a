/* semsplat agent: natural-language commands to tool calls on the semantic splat, with commitments
 * the model cannot talk its way around.
 *
 * A session holds a "brain" that turns what the user says into tool calls, the tools, a world
 * (the query engine and navigation on a model folder) and a robot (offline simulation or ROS 2):
 *   user text -> brain (built-in parser | OpenAI-compatible chat completions | Anthropic Messages)
 *             -> tool calls, each validated in C against the tool's JSON schema
 *             -> the tool runs on the world / robot -> a JSON result (data, never instructions)
 *             -> back to the brain, until it answers in text (a bounded number of steps).
 * Safety lives in C, not in the prompt: a motion goal is accepted only for the end of a plan that
 * this session issued (from the robot's current pose, ending in a free cell); the robot's speed
 * and the distance of a goal are clamped; with `confirm` a callback must approve every motion; a
 * running goal can always be cancelled (sp_agent_session_cancel is async-signal-safe).
 *
 * The parts are usable alone: the tool registry and its validator, the built-in intent parser,
 * the decoders of LLM responses (which take bytes and a size and fail cleanly on anything), and
 * the robot interface with its offline implementation.
 *
 * Keys: the API key is read only from OPENAI_API_KEY / ANTHROPIC_API_KEY, sent only in the
 * request header and never logged or written to a trace. Base URLs come from the config, else
 * OPENAI_BASE_URL / ANTHROPIC_BASE_URL, else the hosted default; a server without a key works.
 *
 * Ownership: the session owns its brain, world, robot and conversation; an answer owns its
 * strings (sp_agent_answer_free); decoded replies own theirs (sp_agent_reply_free). Functions
 * return 0 or a negative SP_E_* code and fill err. Positions are metres in the model's world
 * frame (z up), yaw in radians counter-clockwise from +x. */
#ifndef SEMSPLAT_AGENT_H
#define SEMSPLAT_AGENT_H

#include "semsplat/core.h"
#include "semsplat/device.h"
#include "semsplat/ros.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sp_agent_pose {
    double x, y, z, yaw;
} sp_agent_pose;

/* ---- tools: names, JSON schemas, validation -------------------------------------------------- */

typedef enum {
    SP_AGENT_TOOL_QUERY_OBJECT = 0,   /* query_object_location(object_name) */
    SP_AGENT_TOOL_GET_POSE,           /* get_robot_pose() */
    SP_AGENT_TOOL_PLAN_PATH,          /* plan_path(start, goal[, tolerance_m]) */
    SP_AGENT_TOOL_RENDER_VIEW,        /* render_view_from_splat(pose) */
    SP_AGENT_TOOL_SEND_GOAL,          /* send_nav2_goal(x, y, yaw[, plan_id]) */
    SP_AGENT_TOOL_SHOW_TRAJECTORIES,  /* show_trajectories(target[, k][, instance]) */
    SP_AGENT_TOOL_DESCRIBE,           /* describe_surroundings(object_name[, radius][, instance]) */
    SP_AGENT_TOOL_EXPLORE,            /* explore_region(region[, max_waypoints]) */
    SP_AGENT_TOOL_CANCEL,             /* cancel_nav2_goal() */
    SP_AGENT_N_TOOLS
} sp_agent_tool_id;

typedef struct sp_agent_tool {
    const char *name;        /* ^[a-zA-Z0-9_-]{1,64}$, as both APIs require */
    const char *description;
    const char *schema;      /* JSON Schema of the arguments object (draft 2020-12 subset) */
} sp_agent_tool;

const sp_agent_tool *sp_agent_tool_get(int id);  /* NULL when out of range */
int sp_agent_tool_find(const char *name);        /* id, or -1 */

/* The arguments (bytes, size: any bytes, need not be NUL-terminated) checked against the tool's
 * schema. The subset enforced: type (also a list of types), properties, required,
 * additionalProperties: false, enum, minimum/maximum, minLength/maxLength, minItems/maxItems,
 * items. Fails with SP_E_FORMAT (not JSON) or SP_E_ARG naming the argument and the rule. */
int sp_agent_validate_args(int tool, const char *bytes, size_t size, sp_error *err);

#define SP_AGENT_MAX_PHRASE 200
#define SP_AGENT_MAX_K 5

/* Typed arguments, filled by sp_agent_decode_tool_args (after validation; defaults applied). */
typedef struct sp_agent_args {
    int tool;
    char text[SP_AGENT_MAX_PHRASE + 1]; /* object_name, target or region */
    double start[4], goal[4];           /* plan_path: x, y, z, yaw (z, yaw NaN when not given) */
    int start_n, goal_n;                /* how many numbers were given (2..4) */
    double tolerance_m;                 /* plan_path (default SP_AGENT_DEFAULT_TOLERANCE_M) */
    double pose[4];                     /* render_view_from_splat: x, y, z, yaw */
    double x, y, yaw;                   /* send_nav2_goal */
    char plan_id[32];                   /* send_nav2_goal, "" when not given */
    int k;                              /* show_trajectories (default 3) */
    int instance;                       /* 1-based instance, 0 = not given */
    double radius_m;                    /* describe_surroundings (default 1.5) */
    int max_waypoints;                  /* explore_region (default 8) */
} sp_agent_args;

#define SP_AGENT_DEFAULT_TOLERANCE_M 1.0
#define SP_AGENT_DEFAULT_RADIUS_M 1.5

/* Decodes and validates the arguments of `tool` (bytes, size). On error *out is zeroed. */
int sp_agent_decode_tool_args(int tool, const char *bytes, size_t size, sp_agent_args *out,
                              sp_error *err);

/* ---- LLM replies (both wire formats decode into one shape) ----------------------------------- */

typedef enum {
    SP_AGENT_STOP_END = 0,     /* a final answer: OpenAI "stop", Anthropic "end_turn"/"stop_sequence" */
    SP_AGENT_STOP_TOOL_USE,    /* "tool_calls", "tool" (llama.cpp), "function_call", "tool_use" */
    SP_AGENT_STOP_MAX_TOKENS,  /* "length", "max_tokens" */
    SP_AGENT_STOP_REFUSAL,     /* "content_filter", "refusal" */
    SP_AGENT_STOP_PAUSE,       /* "pause_turn" */
    SP_AGENT_STOP_OTHER
} sp_agent_stop;

typedef struct sp_agent_call {
    char id[96];          /* as sent, or "call_<n>" when the server sent none (then synthesized = 1) */
    int synthesized;
    char name[65];
    char *arguments;      /* the arguments object as compact JSON (from a string or an object), or
                           * NULL when it could not be decoded (then args_error says why) */
    char args_error[200];
} sp_agent_call;

typedef struct sp_agent_reply {
    int stop;             /* sp_agent_stop */
    char stop_raw[32];    /* the server's word for it */
    char *text;           /* text of the turn (text blocks joined), NULL when none */
    int n_calls;
    sp_agent_call *calls;
    char *content_json;   /* Anthropic: the content array to send back as is (thinking blocks
                           * included), with synthesized ids filled in; NULL for OpenAI */
    long input_tokens, output_tokens;
} sp_agent_reply;

void sp_agent_reply_free(sp_agent_reply *r);

/* A chat-completions response body (OpenAI, llama.cpp, Ollama /v1, vLLM): choices[0].message with
 * content and tool_calls; tolerates arguments as an object, calls without ids or without the
 * `function` wrapper, and finish_reason tool_calls / tool / stop. Any bytes: fails with
 * SP_E_FORMAT naming the field; an error body ({"error": ...}) fails with its message. */
int sp_agent_decode_openai(const char *bytes, size_t size, sp_agent_reply *out, sp_error *err);
/* A Messages response body: content blocks (text, tool_use with an input object; others kept
 * for the echo), stop_reason; an error body ({"type":"error",...}) fails with its message. */
int sp_agent_decode_anthropic(const char *bytes, size_t size, sp_agent_reply *out, sp_error *err);

/* An HTTP error body of either API: error type and code ("rate_limit_error",
 * "insufficient_quota", "enforced_spend_limit_reached"...) and message. Returns 0 when the body
 * was an error object, SP_E_FORMAT otherwise (outputs then empty strings). */
int sp_agent_decode_error_body(const char *bytes, size_t size, char *type, size_t type_cap,
                               char *code, size_t code_cap, char *message, size_t message_cap);

/* ---- the built-in intent parser -------------------------------------------------------------- */

typedef enum {
    SP_AGENT_INTENT_ASK = 0,      /* not understood, or nothing named: the parser asks back */
    SP_AGENT_INTENT_GOTO,         /* "go to the refrigerator" */
    SP_AGENT_INTENT_TRAJECTORIES, /* "show me the top trajectories to the refrigerator" */
    SP_AGENT_INTENT_DESCRIBE,     /* "what objects are near the dining table?" */
    SP_AGENT_INTENT_EXPLORE,      /* "explore the area around the kitchen" */
    SP_AGENT_INTENT_LOCATE,       /* "where is the couch?" */
    SP_AGENT_INTENT_CANCEL,       /* "stop", "cancel the goal" */
    SP_AGENT_INTENT_SELECT        /* a bare choice answering a question: "the second one" */
} sp_agent_intent_kind;

typedef enum {
    SP_AGENT_SELECT_NONE = 0,
    SP_AGENT_SELECT_NEAREST,  /* "nearest", "closest" */
    SP_AGENT_SELECT_ANY,      /* "any", "whichever", "a chair" with "any" */
    SP_AGENT_SELECT_FARTHEST,
    SP_AGENT_SELECT_INDEX     /* "the second", "chair 2", "number 3" */
} sp_agent_selector;

typedef struct sp_agent_intent {
    int kind;                             /* sp_agent_intent_kind */
    char target[SP_AGENT_MAX_PHRASE + 1]; /* "red mug on the counter" (determiners dropped) */
    char head[64];                        /* the object noun: "mug" */
    char anchor[64];                      /* the object of a relation: "counter", or "" */
    char relation[16];                    /* "on", "near", "in", ... or "" */
    int selector;                         /* sp_agent_selector */
    int index;                            /* 1-based, with SP_AGENT_SELECT_INDEX */
    int k;                                /* trajectories asked for (3 when not said) */
    double radius_m;                      /* describe radius (SP_AGENT_DEFAULT_RADIUS_M) */
    int pronoun;                          /* the target was "it" / "there": use the last one */
    char question[512];                   /* with SP_AGENT_INTENT_ASK: what to ask the user */
} sp_agent_intent;

/* Parses one utterance (any bytes up to NUL; at most 1000 are read). Deterministic and offline;
 * never fails: nonsense and empty targets give SP_AGENT_INTENT_ASK with a question. */
void sp_agent_parse(const char *text, sp_agent_intent *out);
const char *sp_agent_intent_name(int kind); /* "goto", "trajectories", ... */

/* ---- the robot ------------------------------------------------------------------------------- */

typedef enum {
    SP_AGENT_GOAL_NONE = 0,
    SP_AGENT_GOAL_ACTIVE,
    SP_AGENT_GOAL_SUCCEEDED,
    SP_AGENT_GOAL_CANCELED,
    SP_AGENT_GOAL_ABORTED,
    SP_AGENT_GOAL_REJECTED
} sp_agent_goal_status;

const char *sp_agent_goal_status_name(int status); /* "active", "succeeded", ... */

typedef struct sp_agent_feedback {
    int status;                 /* sp_agent_goal_status */
    sp_agent_pose pose;         /* current pose */
    double distance_remaining_m;
    double eta_s;               /* estimated time remaining */
    double elapsed_s;           /* since the goal was accepted */
    long feedback_count;        /* feedback messages the robot sent for this goal (the offline
                                 * robot: its simulation steps) */
    int recoveries;
    char message[200];          /* why a goal was rejected or aborted */
} sp_agent_feedback;

/* A goal as the robot receives it: the final pose and the plan it belongs to. */
typedef struct sp_agent_goal {
    sp_agent_pose pose;
    const double *waypoints;    /* [n][4] x, y, z, yaw: the issued plan (followed offline) */
    int n_waypoints;
    double max_speed_mps;       /* already clamped by the session */
} sp_agent_goal;

/* The robot side. Every op returns 0 or SP_E_*; `realtime` says whether the session must wait in
 * wall-clock time between polls (a real robot) or not (the offline simulation). */
typedef struct sp_agent_robot_ops {
    const char *name;
    int realtime;
    int (*get_pose)(void *ctx, sp_agent_pose *pose, sp_error *err);
    int (*send_goal)(void *ctx, const sp_agent_goal *goal, sp_error *err);
    int (*poll)(void *ctx, sp_agent_feedback *fb, sp_error *err);
    int (*cancel)(void *ctx, sp_error *err);
    void (*close)(void *ctx);
} sp_agent_robot_ops;

typedef struct sp_agent_robot {
    const sp_agent_robot_ops *ops;
    void *ctx;
} sp_agent_robot;

/* The offline robot: starts at `start`, and on a goal drives the issued plan's waypoints at up to
 * max_speed (a trapezoid in speed with accel_mps2, turning in place at yaw_rate_rps where the path
 * turns sharply), advancing step_s of simulated time per poll. No sleeping, deterministic. */
typedef struct sp_agent_offline_opts {
    sp_agent_pose start;
    double accel_mps2;     /* 0.5 */
    double yaw_rate_rps;   /* 1.0 */
    double step_s;         /* 0.25 */
} sp_agent_offline_opts;

sp_agent_offline_opts sp_agent_offline_opts_default(void);
int sp_agent_robot_offline(sp_agent_robot *out, const sp_agent_offline_opts *opts, sp_error *err);
void sp_agent_robot_close(sp_agent_robot *r);

/* ---- the session ----------------------------------------------------------------------------- */

typedef enum { SP_AGENT_BRAIN_BUILTIN = 0, SP_AGENT_BRAIN_OPENAI, SP_AGENT_BRAIN_ANTHROPIC } sp_agent_brain_kind;

/* LLM endpoint settings. Strings may be NULL (= environment or preset). */
typedef struct sp_agent_llm_config {
    const char *preset;      /* "openai", "llama.cpp", "ollama", "vllm" or NULL (OpenAI client) */
    const char *base_url;    /* NULL = $OPENAI_BASE_URL / $ANTHROPIC_BASE_URL / preset / hosted */
    const char *model;       /* required for hosted endpoints; local presets default to "local" */
    double timeout_s;        /* per request (60) */
    double connect_timeout_s;/* (10) */
    int max_retries;         /* on 408, 409, 429, 5xx, 529 and connection errors (2) */
    double retry_base_s;     /* backoff base: base * 2^attempt * jitter in [0.5, 1] (0.5) */
    double retry_max_s;      /* longest wait honoured, Retry-After included (30) */
    int max_tokens;          /* Anthropic requires it (1024) */
    int max_steps;           /* model turns per command before giving up (8) */
    const char *anthropic_version; /* header value ("2023-06-01") */
    unsigned seed;           /* jitter */
} sp_agent_llm_config;

/* Asked before every motion when confirm is set; return 1 to go ahead. */
typedef int (*sp_agent_confirm_fn)(void *user, const char *what);

typedef struct sp_agent_config {
    const char *model_dir;    /* the model folder; NULL only with a world given internally (tests) */
    const char *out_dir;      /* answers, traces and images (NULL = no files) */
    int brain;                /* sp_agent_brain_kind */
    sp_agent_llm_config llm;
    int confirm;
    sp_agent_confirm_fn confirm_fn;
    void *confirm_user;
    double max_speed_mps;     /* clamped to [0.05, SP_AGENT_SPEED_LIMIT] (0.4) */
    double max_goal_distance_m; /* plans longer than this are not driven, clamped to 100 (30) */
    double goal_match_m;      /* send_nav2_goal must be within this of a plan's end (0.25) */
    double goal_match_rad;    /* ... and its yaw within this (0.35) */
    double plan_start_m;      /* a plan is stale when the robot is further than this from its start (0.5) */
    double goal_timeout_s;    /* how long a goal is followed before the session stops waiting (300) */
    int use_ros;              /* the ROS 2 bridge instead of the offline robot */
    sp_ros_options ros;       /* with use_ros: domain, distro, namespace, topics, loopback
                               * (sp_ros_options_default; the strings are read at open only) */
    double ros_wait_s;        /* with use_ros: how long open waits for the robot's first pose
                               * (odometry and the map -> odom transform) (10) */
    sp_agent_pose start;      /* the offline robot's start pose */
    int have_start;
    sp_device *device;        /* where the map is queried and rendered (borrowed, outlives the
                               * session); NULL = a CPU device of the session's own */
    const sp_log *log;
} sp_agent_config;

#define SP_AGENT_SPEED_LIMIT 1.0 /* m/s: no configuration drives faster */

sp_agent_config sp_agent_config_default(void);

/* One entry of an answer's trace. Strings are owned by the answer. */
typedef struct sp_agent_trace_item {
    char *tool;
    char *call_id;
    char *arguments;   /* as the brain sent them (may be invalid JSON) */
    char *result;      /* the JSON the brain got back */
    int is_error;
    double ms;
} sp_agent_trace_item;

typedef struct sp_agent_answer {
    char *command;          /* what the user said */
    char *text;             /* the answer */
    int intent;             /* the built-in parser's reading (also for LLM brains, as a note) */
    int asked_back;         /* the answer is a question for the user */
    int n_trace;
    sp_agent_trace_item *trace;
    int n_images;
    char **images;          /* paths of images the tools wrote (previews, renders, maps) */
    int steps;              /* brain turns used */
    int llm_requests, llm_retries;
    char json_path[1024];   /* where the answer was written ("" when no out_dir) */
} sp_agent_answer;

void sp_agent_answer_free(sp_agent_answer *a);

typedef struct sp_agent_session sp_agent_session;

/* Opens a session: the world from cfg->model_dir, the robot (offline at cfg->start, or ROS 2),
 * and the brain. The LLM brains read their URL and key here; nothing is sent until a command. */
int sp_agent_session_open(sp_agent_session **out, const sp_agent_config *cfg, sp_error *err);
/* Same with a robot the caller built (ownership moves to the session, also on error). */
int sp_agent_session_open_with_robot(sp_agent_session **out, const sp_agent_config *cfg,
                                     sp_agent_robot robot, sp_error *err);
void sp_agent_session_close(sp_agent_session *s);

/* Runs one command to an answer (text, trace, images) and, with an out_dir, writes it as
 * <out_dir>/answer_<n>.json. A failure of the brain (unreachable server, malformed reply) is an
 * error return with the reason in err; the answer is still filled with what happened. */
int sp_agent_session_ask(sp_agent_session *s, const char *text, sp_agent_answer *answer,
                         sp_error *err);
/* Asks the robot to stop: the goal being followed is cancelled at the next poll. Safe to call
 * from a signal handler or another thread. */
void sp_agent_session_cancel(sp_agent_session *s);
/* The answer as JSON text (malloc'd; free with free()). */
char *sp_agent_answer_json(const sp_agent_answer *a);

#ifdef __cplusplus
}
#endif
#endif
