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
} sp_eval_opts;

/* Runs every query of the report through the engine with both methods (engine defaults otherwise)
 * and scores them. Fails (SP_E_ARG) when the engine's frame is not a world frame. */
int sp_eval_localization(sp_query_engine *e, const sp_ground_truth *gt, const sp_eval_opts *o,
                         sp_eval_report *rep, sp_error *err);

/* The report as a console table + summary lines, as Markdown (report.md), and as JSON; malloc'd
 * (free with free(); cJSON_Delete for the JSON), NULL on allocation failure. */
char *sp_eval_report_text(const sp_eval_report *rep);
char *sp_eval_report_markdown(const sp_eval_report *rep, const char *title);
struct cJSON *sp_eval_report_json(const sp_eval_report *rep);

/* ---- the demo ------------------------------------------------------------------------------------- */

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
    int skip_missing;        /* synth: render without missing assets */
    int reuse;               /* skip stages whose outputs exist in out_dir */
    float match_radius_m;    /* scoring (0: 0.5) */
    const sp_log *log;
} sp_demo_opts;

sp_demo_opts sp_demo_opts_default(void);

typedef struct sp_demo_result {
    char capture_dir[1100], model_dir[1100], features_dir[1100], heatmap_dir[1100];
    char device[128];
    int views, steps, width, height;
    int trained;             /* 1 when training ran (train holds its result) */
    sp_train_result train;
    int scored;              /* 0: the capture has no ground_truth.json; the model is ready */
    sp_eval_report report;
    double t_synth, t_train, t_features, t_lift, t_queries, t_total;
} sp_demo_result;

/* synth (unless o->capture) -> train -> features (labels, or CLIP with o->clip) -> lift ->
 * sp_eval_localization, each stage a library call; writes <out>/{capture,model,features,
 * heatmaps}/, <out>/demo.json and <out>/report.md (when scored). Progress goes to o->log. */
int sp_demo_run(const sp_demo_opts *o, sp_demo_result *res, sp_error *err);
void sp_demo_result_free(sp_demo_result *res);

#ifdef __cplusplus
}
#endif
#endif
