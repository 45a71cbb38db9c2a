/* semsplat eval: how well the query engine localizes the objects of a world, measured against the
 * capture's ground truth, and the bundled demo that runs the whole pipeline through library calls
 * (synth -> train -> features -> lift -> queries -> this scoring).
 *
 * Scoring (one implementation, used by `semsplat demo`, scripts/eval_house.sh and `eval`):
 *   - every class of the ground truth is queried by its name, with both localization methods
 *     (3D-native and multi-view), and so are control queries for things the world does not have;
 *   - the instances a query returns are matched ONE-TO-ONE to the objects of that class: an
 *     instance may match an object when its position lies inside the object's box (its
 *     footprint and height) grown by match_radius_m on every side; among those pairs the
 *     assignment with the most matches, and then the least summed error, is taken (Hungarian
 *     algorithm). Error = distance from the instance's position to the box centre;
 *   - recall = matched objects / objects; precision = matched instances / instances returned by
 *     found queries (absent controls that are "found" count as false instances); mean and median
 *     error over matched objects; and, so that misses count in a mean, the mean over every object
 *     with a miss counted as the largest error a match could have had (centre to a corner of its
 *     grown box);
 *   - per class: found, the best answer's error to the nearest object of the class (what a robot
 *     would drive to), and whether that answer matches an object of the class.
 * Positions must be in the world frame (frame.json "synth" or "align"); a "colmap"-frame model is
 * refused. Results from label features say so (sp_query_source_note), and with the "exact" encoder
 * an absent name is a random vector, so rejecting it is by construction, not a test; the report
 * says that too.
 *
 * Ownership: sp_ground_truth, sp_eval_report and sp_demo_result own their arrays (*_free). */
#ifndef SEMSPLAT_EVAL_H
#define SEMSPLAT_EVAL_H

#include "semsplat/core.h"
#include "semsplat/semantic.h"
#include "semsplat/train.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- ground truth (a capture's ground_truth.json, as synth writes it) ------------------------ */

typedef struct sp_gt_object {
    char name[128];  /* the model's name in the world ("dining_chair_2") */
    char cls[128];   /* the class people ask for ("dining chair") */
    float center[3]; /* world box centre */
    float aabb_min[3], aabb_max[3];
} sp_gt_object;

typedef struct sp_ground_truth {
    size_t n;
    sp_gt_object *objects;
    char world[1024]; /* the world file it came from ("" when not recorded) */
} sp_ground_truth;

/* Reads {"world", "objects": [{name, class, aabb_min, aabb_max, aabb_center}]}; errors name the
 * file and the object at fault (missing fields, non-finite numbers, min > max). */
int sp_ground_truth_read(const char *path, sp_ground_truth *gt, sp_error *err);
void sp_ground_truth_free(sp_ground_truth *gt);
/* The ground truth of a world file (.world/.sdf through synth's loader, model:// through
 * model_path): every top-level model that is not structure, its class and world box. Fails with
 * SP_E_UNSUPPORTED when synth is not built, SP_E_FORMAT when the world has no objects. */
int sp_ground_truth_from_world(const char *world, const char *model_path, int skip_missing,
                               const sp_log *log, sp_ground_truth *gt, sp_error *err);

/* ---- one-to-one matching ------------------------------------------------------------------------ */

/* 1 when position p lies in o's box grown by radius on every side. */
int sp_eval_admissible(const sp_gt_object *o, const float p[3], float radius);
/* The largest error a match with o can have: box centre to a corner of the grown box. */
float sp_eval_miss_penalty(const sp_gt_object *o, float radius);
/* Matches n_obj objects to n_inst positions ([n_inst][3]) one-to-one (see the header comment):
 * instance_of[n_obj] gets the matched position's index or -1, error[n_obj] (may be NULL) the
 * centre distance or NaN. Returns the number of matches, or a negative error. */
int sp_eval_match(const sp_gt_object *objs, int n_obj, const float *positions, int n_inst,
                  float radius, int *instance_of, float *error, sp_error *err);

/* ---- the localization report --------------------------------------------------------------------- */

#define SP_EVAL_METHODS 2 /* [0] 3D-native, [1] multi-view (SP_QUERY_3D, SP_QUERY_MULTIVIEW) */

typedef struct sp_eval_object {
    char name[128], cls[128];
    float truth[3];
    float miss_penalty_m;
    int instance[SP_EVAL_METHODS];       /* matched instance of its class's query, -1 = missed */
    float error_m[SP_EVAL_METHODS];      /* NaN when missed */
    float estimate[SP_EVAL_METHODS][3];  /* NaN when missed */
} sp_eval_object;

typedef struct sp_eval_query {
    char text[128];
    int present;   /* a class of the ground truth; 0 = a control the world does not have */
    int n_objects; /* objects of the class */
    int scored[SP_EVAL_METHODS];
    int found[SP_EVAL_METHODS];
    float confidence[SP_EVAL_METHODS];
    int n_instances[SP_EVAL_METHODS];  /* instances returned (0 when not found) */
    float *instance_pos[SP_EVAL_METHODS]; /* [n_instances][3], best first (owned by the report) */
    int matched[SP_EVAL_METHODS];      /* of them, matched to an object */
    float position[SP_EVAL_METHODS][3]; /* the best answer, NaN when not found */
    float query_error_m[SP_EVAL_METHODS]; /* best answer to the nearest object of the class (NaN) */
    int correct[SP_EVAL_METHODS];      /* the best answer is admissible for an object of the class */
    double ms[SP_EVAL_METHODS];        /* query time without the heatmap */
    char heatmap[1024];                /* heatmap PNG ("" when none) */
} sp_eval_query;

typedef struct sp_eval_summary {
    int objects, matched;          /* recall = matched / objects */
    int instances, true_instances; /* precision = true_instances / instances */
    double recall, precision;      /* NaN when the denominator is 0 */
    double mean_error_m, median_error_m; /* over matched objects (NaN when none) */
    double mean_error_with_misses_m;     /* over every object, a miss = its miss penalty */
    int classes, classes_found, classes_correct;
    double mean_query_error_m;     /* over found classes */
    int absent, absent_rejected;
    double mean_ms;
} sp_eval_summary;

typedef struct sp_eval_report {
    sp_query_source source;
    sp_query_frame frame;
    float match_radius_m;
    size_t n_objects;
    sp_eval_object *objects;  /* ground-truth order */
    size_t n_queries;
    sp_eval_query *queries;   /* the classes in ground-truth order, then the absent controls */
    sp_eval_summary summary[SP_EVAL_METHODS];
    int finished;
} sp_eval_report;

/* Controls the house and bookstore do not contain (NULL-terminated). */
extern const char *const sp_eval_default_absent[];

/* Sets up a report: the ground truth's classes and the absent controls (NULL = the default list;
 * a control that is a class of the ground truth is refused). radius <= 0 = 0.5 m. */
int sp_eval_report_init(sp_eval_report *rep, const sp_ground_truth *gt, const char *const *absent,
                        float radius, sp_error *err);
/* Scores one query result (query index into rep->queries, method 0/1). */
int sp_eval_report_add(sp_eval_report *rep, const sp_ground_truth *gt, size_t query, int method,
                       const sp_query_result *res, sp_error *err);
/* Totals per method (recall, precision, means, medians); call after the last add. */
void sp_eval_report_finish(sp_eval_report *rep);
void sp_eval_report_free(sp_eval_report *rep);

typedef struct sp_eval_opts {
    float match_radius_m;          /* <= 0: 0.5 */
    const char *const *absent;     /* NULL-terminated; NULL = sp_eval_default_absent */
    const char *heatmap_dir;       /* when set, <dir>/<class>.png from the 3D query */
    const sp_log *log;
    float merge_gap_m;             /* instances of one query whose extents come this close are
                                      one object (sp_eval_merge_fragments); 0 = 0.15, < 0 = off */
} sp_eval_opts;

#define SP_EVAL_MERGE_GAP_M 0.15f

/* A large object (bed, sofa, counter) often comes back as several instances, one per part the
 * clustering split off. Instances whose extents, each grown by gap_m / 2, overlap on all three
 * axes are merged (transitively) into one: extent the union, position its middle (as the
 * engine's own positions are), score and points summed, confidence the largest; then re-sorted
 * best first and res->position set to the best. No ground truth is used. Returns the number of
 * instances left, or a negative error (out of memory; res unchanged). */
int sp_eval_merge_fragments(sp_query_result *res, float gap_m, sp_error *err);

/* Runs every query of the report through the engine with both methods (engine defaults otherwise)
 * and scores them. Fails (SP_E_ARG) when the engine's frame is not a world frame. */
int sp_eval_localization(sp_query_engine *e, const sp_ground_truth *gt, const sp_eval_opts *o,
                         sp_eval_report *rep, sp_error *err);

/* The report as a console table + summary lines, as Markdown (report.md), and as JSON; malloc'd
 * (free with free(); cJSON_Delete for the JSON), NULL on allocation failure. */
char *sp_eval_report_text(const sp_eval_report *rep);
char *sp_eval_report_markdown(const sp_eval_report *rep, const char *title);
struct cJSON *sp_eval_report_json(const sp_eval_report *rep);

/* ---- navigation commands end to end, the demo video, 5.3 ------------------------------------------ */
/* A command runs through the agent (the built-in parser brain) and a simulated robot: with Cyclone
 * DDS the ros module's simulated robot (sp_ros_sim_run, in a thread of this process, on loopback,
 * a domain reserved on this machine and a namespace of its own), reached through the agent's ROS
 * robot exactly as `agent --ros` reaches it; without DDS (or with SP_DEMO_ROBOT_OFFLINE) the
 * agent's offline robot, and everything that shows the run says so. */

struct sp_nav_opts;

typedef enum { SP_DEMO_ROBOT_AUTO = 0, SP_DEMO_ROBOT_DDS, SP_DEMO_ROBOT_OFFLINE } sp_demo_robot;

typedef struct sp_drive_opts {
    const char *model_dir;   /* the model folder (splat with semantics, its capture) */
    const char *out_dir;     /* the agent's answers and images go to <out_dir>/agent */
    int robot;               /* sp_demo_robot; AUTO = DDS when this build has Cyclone */
    double time_scale;       /* the simulated robot's seconds per wall second (0: 3) */
    double max_speed_mps;    /* the simulated robot's top speed (0: 0.5) */
    const struct sp_nav_opts *nav; /* the map's settings for the agent and the robot (NULL: nav's
                              * defaults) */
    sp_device *dev;          /* borrowed */
    const sp_log *log;
} sp_drive_opts;

/* The map settings the demo and 5.3 drive with (nav's defaults with more carving, specks dropped
 * and the body band from 0.15 m: small CPU-trained splats otherwise leave the start cut off). */
void sp_eval_drive_map_opts(struct sp_nav_opts *o);

/* One pose report of the robot while it follows a goal (t: seconds since the goal was sent, in
 * the robot's time: wall time for DDS, simulated time offline). */
typedef struct sp_drive_sample {
    double t, x, y, yaw, remaining_m;
    int status;              /* sp_agent_goal_status */
} sp_drive_sample;

typedef struct sp_demo_video_opts {
    sp_drive_opts drive;
    const char *out_path;    /* the MP4 (NULL: <drive.out_dir>/demo.mp4) */
    const char *const *commands; /* "go to" commands; before each, the demo asks for the top 3
                              * trajectories to its target (NULL: three commands on the house) */
    int n_commands;
    int width, height;       /* video size (0: 1280x720) */
    int fps;                 /* (0: 10) */
    int drive_frames;        /* most rendered frames per drive (0: 60) */
    int view_width, view_height; /* the splat view rendered from the robot's pose (0: 480x360) */
} sp_demo_video_opts;

typedef struct sp_demo_video_result {
    char path[1100];
    char robot[300];         /* which robot drove, and why when it is the offline one */
    int n_commands, n_arrived;
    long frames;
    double seconds;          /* length of the video */
    double t_wall;           /* seconds it took */
} sp_demo_video_result;

sp_demo_video_opts sp_demo_video_opts_default(void);
/* Runs the commands and writes the video: per command a title card with the commands as typed,
 * the agent's tool calls, the query heatmap, the ranked trajectories on the map with previews,
 * the drive (the splat from the robot's pose beside the top-down map with robot, path, distance
 * remaining from the robot's feedback) and the arrival. */
int sp_demo_video(const sp_demo_video_opts *o, sp_demo_video_result *res, sp_error *err);

/* 5.3: navigation commands, each scored per stage. */
typedef struct sp_nav_success_row {
    char command[200];
    char expect[64];         /* the ground-truth class the command means */
    char intent[24];
    int parsed;              /* the parser's intent is the expected one and it did not ask back */
    int valid;               /* the located goal lies within match radius of an object of the class */
    int reached;             /* the robot reported success within 0.3 m of the goal */
    int useful;              /* mean view score along the driven path >= 2.5 (grade 3 rounded) */
    double grade;            /* that mean (sp_media_view_quality, 1..5; 0 when no view) */
    double error_m;          /* located goal to the nearest object of the class (NAN: none) */
    char views[1100];        /* a PNG with the graded views */
    char note[300];
} sp_nav_success_row;

typedef struct sp_nav_success {
    int n;
    sp_nav_success_row rows[16];
    int count[4];            /* parsed, valid, reached, useful */
    char robot[300];
    char plot[1100];         /* success per stage (PNG) */
} sp_nav_success;

/* Runs the ten commands of 5.3 (or cmds[n], n <= 16, each "command|class") on the model with
 * ground truth gt (may be NULL: valid then means a path was planned) and writes
 * <drive.out_dir>/nav_success.{json,png} and the graded views. */
int sp_eval_nav_success(const sp_drive_opts *o, const sp_ground_truth *gt, const char *const *cmds,
                        int n, float match_radius_m, sp_nav_success *out, sp_error *err);

/* ---- semsplat eval: the whole evaluation (the users' task 5.1 - 5.4) --------------------------- *
 *
 * sp_eval_run scores a model folder against a world file and writes <out>/report.md,
 * report.html (the same with its pictures inline) and report.json, with figures/:
 *   5.1 localization: every object of the world (sp_ground_truth_from_world), both methods,
 *       fragments merged, one-to-one matching (sp_eval_localization); per-object error bars.
 *   5.2 open vs closed vocabulary: each query answered by the semantic splat (the lexical encoder
 *       on a label-feature scene, else the engine's own text encoder) and by a closed-vocabulary
 *       baseline: the same map restricted to the 80 COCO class names, i.e. the query is replaced
 *       by the COCO class WordNet matches best (or none) and that class is looked up. Either is
 *       "found" when its answer lies on an object the query means (its target classes; a region
 *       query anywhere in the box spanning them), grown by the match radius.
 *   5.4 trajectory quality: nav's top 3 trajectories to the refrigerator (length, clearances,
 *       localizability, ranking score) with a visual quality 1-5 measured on their previews
 *       (coverage and sharpness, sp_media_view_quality), the top-down map and contact sheets.
 *   5.3 query success rate: ten navigation commands through the agent and the simulated robot
 *       (sp_eval_nav_success: over DDS when built with Cyclone), the rate of each stage, a plot
 *       and the graded views; with no_navigation it is reported as not measured.
 *   A written analysis made from the numbers, headed by the feature source, the text encoder, the
 *   capture plan and the poses the model was trained on, and what they mean.
 * Queries come from a JSON file ({"vocabulary": [{"text", "coco": bool, "targets": [classes],
 * "region": bool, "near": [classes], "near_m": m}]}) or the task's ten (sp_eval_default_vocab). */

#define SP_EVAL_MAX_TARGETS 10

typedef struct sp_eval_query_spec {
    char text[128];
    int coco;                 /* 1 in COCO, 0 not, -1 = decide by WordNet against the COCO names */
    int region;               /* a region: scored inside the box spanning its target objects */
    int n_targets;
    char targets[SP_EVAL_MAX_TARGETS][64]; /* classes of the world that answer the query */
    int n_near;
    char near[4][64];         /* only targets within near_m of an object of these classes */
    float near_m;
} sp_eval_query_spec;

/* The task's ten queries (5 in COCO, 5 outside) and their targets; n gets the count. */
const sp_eval_query_spec *sp_eval_default_vocab(size_t *n);
/* Reads {"vocabulary": [...]} (see above); errors name the file and the entry. specs malloc'd. */
int sp_eval_read_queries(const char *path, sp_eval_query_spec **specs, size_t *n, sp_error *err);
/* 5.3 commands from the same file: {"navigation": [{"text": "go to the desk", "targets": ["desk"]}]}
 * (at most 16; targets: the world's classes a right goal is near). No "navigation" key: *n = 0.
 * Free with sp_eval_free_nav_commands. */
int sp_eval_read_nav_commands(const char *path, char ***cmds, int *n, sp_error *err);
void sp_eval_free_nav_commands(char **cmds, int n);

typedef struct sp_eval_vocab_row {
    sp_eval_query_spec spec;
    int in_coco;              /* as given, or decided */
    int n_targets;            /* objects of the world that answer it (0: the world lacks them) */
    char coco_class[64];      /* the closed baseline's class ("" = no COCO class matched) */
    float coco_score;         /* WordNet's score for it */
    int closed_found;
    float closed_error_m;     /* its answer to the nearest target (NaN: no answer or no target) */
    int open_found;
    float open_confidence;
    float open_error_m;
    float open_position[3];   /* NaN when nothing was answered */
    char matched[160];        /* the classes the text matched (semantic splat), for the report */
} sp_eval_vocab_row;

typedef struct sp_eval_trajectory { /* 5.4: one of the top trajectories */
    int rank;
    float length_m, clearance_min_m, clearance_mean_m;
    float localizability;     /* nav's: the least localizable waypoint, 0..1 */
    float total;              /* nav's ranking score */
    float share;              /* largest share of its length with a better route */
    int n_previews;
    float coverage, sharpness;/* means over its previews (sp_media_view_quality) */
    float visual_score;       /* mean preview score, 1..5 */
    int visual_grade;         /* rounded: the table's "visual quality (1-5)" */
    char sheet[1100];         /* its contact sheet (PNG), "" when not drawn */
} sp_eval_trajectory;

typedef struct sp_eval_run_opts {
    const char *model_dir;
    const char *world;        /* the ground truth */
    const char *model_path;   /* model:// folders of the world (may be NULL) */
    const char *queries;      /* 5.2 queries (JSON), NULL = the task's ten; its "navigation" list, if any,
                               * replaces 5.3's ten house commands */
    const char *out_dir;
    const char *title;        /* NULL: "semsplat evaluation: <world>" */
    int skip_missing;         /* the world's missing assets skipped */
    sp_device *dev;           /* borrowed */
    float match_radius_m;     /* 0 = 0.5 */
    const char *trajectory_target; /* 5.4's goal; NULL = "refrigerator" */
    int no_navigation;        /* skip 5.3 */
    int robot;                /* 5.3's robot: sp_demo_robot */
    const sp_log *log;
} sp_eval_run_opts;

typedef struct sp_eval_run {
    char world[1024], model_dir[1024], capture_dir[1024];
    char plan[32];            /* capture plan: "walk", "walk+objects", "drive", or "unknown" */
    char poses[256];          /* "exact (rendered from the world)" or COLMAP's with its residual */
    double sfm_ate_rms_m;     /* COLMAP poses: camera error after alignment (NaN otherwise) */
    int sfm_registered, sfm_images;
    double train_psnr;        /* held-out PSNR from train.json (NaN when absent) */
    long n_gaussians;
    sp_ground_truth gt;
    sp_eval_report loc;       /* 5.1 */
    size_t n_vocab;
    sp_eval_vocab_row *vocab; /* 5.2 */
    char vocab_encoder[32];   /* how 5.2 was answered: "lexical" or the engine's encoder */
    char traj_target[128];
    int traj_measured;        /* 5.4 ran (0: note says why) */
    char traj_note[400];      /* nav's note (fewer than k and why), or why 5.4 did not run */
    int n_traj;
    sp_eval_trajectory traj[8];
    char traj_map[1100];      /* the top-down map with the ranked paths (PNG) */
    int nav_measured;         /* 5.3 ran (0: nav_note says why) */
    char nav_note[400];
    sp_nav_success nav;       /* 5.3 */
    char analysis[8192];      /* the written analysis (Markdown) */
    double seconds;
} sp_eval_run;

/* Runs the evaluation and writes the report (see above). */
int sp_eval_run_report(const sp_eval_run_opts *o, sp_eval_run *r, sp_error *err);
void sp_eval_run_free(sp_eval_run *r);

/* ---- the demo ------------------------------------------------------------------------------------- */

/* The demo's capture plan (sp_demo_opts.plan; synth's plans, see synth.h). */
enum { SP_DEMO_PLAN_AUTO = 0, SP_DEMO_PLAN_MIXED, SP_DEMO_PLAN_WALK, SP_DEMO_PLAN_DRIVE };

typedef struct sp_demo_opts {
    const char *out_dir;     /* "demo" when NULL */
    const char *world;       /* NULL: <data>/worlds/house.world */
    const char *model_path;  /* synth's model path (may be NULL) */
    const char *capture;     /* an existing capture: no synth */
    const char *clip;        /* CLIP weights: features from CLIP (else from labels/) */
    sp_device_kind device;
    int threads;             /* CPU threads (0 = all) */
    int views, steps;        /* 0: GPU 150 views, 7000 steps; CPU 48 views, 2000 steps */
    int width, height;       /* 0: GPU 640x480, CPU 320x240 */
    int dim;                 /* feature PCA dim (0: 32) */
    int points;              /* synth's points3D (0: 30000) */
    int downscale;           /* training image downscale (0: 1) */
    float depth_lambda;      /* depth supervision weight (sp_train_options.depth_lambda) when the
                              * capture has depth/ (synth's always has): default SP_DEMO_DEPTH_LAMBDA
                              * (DESIGN.md's nav section, sixth round), 0 = RGB only */
    int skip_missing;        /* synth: render without missing assets */
    int walk_only;           /* synth's walk-only plan (no view aimed at a ground-truth object) */
    int plan;                /* SP_DEMO_PLAN_*: AUTO = walk_only ? WALK : MIXED (spins and arcs at
                              * objects); DRIVE: one robot drive through the rooms (the CPU house
                              * demo's 48 views: 47 standpoints instead of 4 spins, a better map and
                              * better queries; a small room's 24 views: nothing matched; see
                              * DESIGN.md's nav section) */
    int reuse;               /* skip stages whose outputs exist in out_dir */
    float match_radius_m;    /* scoring (0: 0.5) */
    const char *model;       /* an existing model folder: no pipeline, only the video */
    int no_video;            /* skip the video */
    int robot;               /* sp_demo_robot for the video */
    double time_scale;       /* the simulated robot's (0: 3) */
    int video_width, video_height, fps, drive_frames; /* 0: 1280x720, 10 fps, 60 frames a drive */
    int view_width, view_height;                      /* the drive's splat view (0: 480x360) */
    const sp_log *log;
} sp_demo_opts;

#define SP_DEMO_DEPTH_LAMBDA 0.5f

sp_demo_opts sp_demo_opts_default(void);

typedef struct sp_demo_result {
    char capture_dir[1100], model_dir[1100], features_dir[1100], heatmap_dir[1100];
    char device[128];
    int views, steps, width, height;
    int plan;                /* the capture plan synth used (SP_DEMO_PLAN_*, never AUTO) */
    int trained;             /* 1 when training ran (train holds its result) */
    sp_train_result train;
    int scored;              /* 0: the capture has no ground_truth.json; the model is ready */
    sp_eval_report report;
    int have_video;
    sp_demo_video_result video;
    char video_error[1024];  /* why there is no video (a warning: the report stands) */
    double t_synth, t_train, t_features, t_lift, t_queries, t_video, t_total;
} sp_demo_result;

/* synth (unless o->capture) -> train -> features (labels, or CLIP with o->clip) -> lift ->
 * sp_eval_localization -> the video (sp_demo_video: three commands driven end to end), each stage
 * a library call; writes <out>/{capture,model,features,heatmaps,agent}/, <out>/demo.json,
 * <out>/report.md and <out>/demo.mp4 (when scored: a capture without ground truth only makes the
 * model; o->model makes only the video). Progress goes to o->log. */
int sp_demo_run(const sp_demo_opts *o, sp_demo_result *res, sp_error *err);
void sp_demo_result_free(sp_demo_result *res);

#ifdef __cplusplus
}
#endif
#endif
