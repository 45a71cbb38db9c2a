/* semsplat semantic: the language-embedded splat and the query engine.
 *
 * Semantic field: every Gaussian carries a d-dim feature (d = the scene PCA's dim, 16..64 in
 * practice, at most SP_FEATURE_DIM_MAX = 64 in core.h) that
 * decodes to the full text space as  mean + basis^T f  (basis rows orthonormal). It is made by
 *   - lifting: one pass over the training views; each Gaussian's feature is the compositing-weight
 *     average of the target features of the pixels it contributes to,
 *       f_i = sum_p w_ip t_p / sum_p w_ip,   w_ip = alpha_i(p) T_i(p),
 *     taken exactly from the rasterizer's backward (v_colors = sum_p w_ip v_image_p) with the
 *     targets and a channel of ones rendered together (D+1 channels, no new kernel);
 *   - distillation (semsplat distill, through the trainer's feature pass).
 * It is stored as f_sem_* fields in DIR/splat.ply plus the sidecar DIR/semantic.json and the PCA
 * files DIR/semantic_pca_mean.npy, DIR/semantic_pca_basis.npy.
 *
 * Relevancy (per Gaussian or per pixel, for a text embedding q in the full space):
 *   raw   s = cos(decode(f), q); a result's `confidence` is the largest raw cosine of the object
 *         (above ~0.25 a match, below ~0.15 noise) with the clip and exact text encoders, the
 *         calibrated lexical score with the lexical one (see "Text encoders");
 *   rel   = min_k exp(s/T) / (exp(s/T) + exp(s_k/T)) over canonical negatives k ("object",
 *         "things", "stuff", "texture"), T the temperature: LERF's calibrated relevancy, 0.5 =
 *         no preference, used for thresholds and heatmaps.
 * Localization: 3D-native (relevant Gaussians -> opacity-weighted voxel clustering of centres into
 * instances, 26-connected voxels of voxel_m) or multi-view (views that see the relevant Gaussians
 * unoccluded -> rendered features and expected depth at 1/render_downscale -> relevant pixels
 * with alpha > 0.9, eroded by one pixel, back-projected -> the same clustering). Things that are not there give low
 * confidence, valid = 0 and no position (NaN), never a random point.
 *
 * Ownership: sp_query_engine owns the splat, PCA, cameras and its raster; results own their
 * buffers (sp_query_result_free). Every function returns 0 or a negative SP_E_* code with err
 * filled; outputs are unchanged on error unless said otherwise. */
#ifndef SEMSPLAT_SEMANTIC_H
#define SEMSPLAT_SEMANTIC_H

#include "semsplat/core.h"
#include "semsplat/io.h"
#include "semsplat/render.h"
#include "semsplat/train.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- the decoder (PCA) and relevancy -------------------------------------------------------- */

/* The feature space: d-dim stored features decode to full_dim as mean + basis^T f. Owns both. */
typedef struct sp_sem_pca {
    int dim, full_dim;
    float *mean;  /* [full_dim] */
    float *basis; /* [dim][full_dim] */
} sp_sem_pca;

/* Reads mean [full_dim] and basis [dim][full_dim] .npy files (f32/f16/f64). */
int sp_sem_pca_read(const char *mean_path, const char *basis_path, sp_sem_pca *pca, sp_error *err);
void sp_sem_pca_free(sp_sem_pca *pca);

#define SP_SEM_MAX_NEGATIVES 8
#define SP_SEM_DEFAULT_NEGATIVES "object,things,stuff,texture" /* LERF's canonical phrases */
#define SP_SEM_DEFAULT_TEMPERATURE 0.1f                         /* LERF: softmax of 10 * cos */

/* A text prepared for scoring d-dim features without decoding them: with q unit-length,
 *   decode(f) . q = q0 + qb . f,  |decode(f)|^2 = m2 + 2 mb . f + f^T G f  (G = basis basis^T). */
typedef struct sp_sem_scorer {
    int dim;
    int n_neg;
    float temperature;
    float q0, qb[SP_FEATURE_DIM_MAX];                   /* the query */
    float n0[SP_SEM_MAX_NEGATIVES], nb[SP_SEM_MAX_NEGATIVES][SP_FEATURE_DIM_MAX]; /* the negatives */
    float m2, mb[SP_FEATURE_DIM_MAX];
    float G[SP_FEATURE_DIM_MAX * SP_FEATURE_DIM_MAX];
    int orthonormal; /* G == I within 1e-4: |decode(f)|^2 = m2 + 2 mb.f + |f|^2 */
} sp_sem_scorer;

/* Prepares a scorer. query [full_dim] and negatives [n_neg][full_dim] need not be unit length.
 * Fails with SP_E_ARG when dim > SP_FEATURE_DIM_MAX, n_neg > SP_SEM_MAX_NEGATIVES or a vector is
 * zero. */
int sp_sem_scorer_init(sp_sem_scorer *sc, const sp_sem_pca *pca, const float *query,
                       const float *negatives, int n_neg, float temperature, sp_error *err);
/* Raw cosine and calibrated relevancy of n features [n][dim] (either output may be NULL).
 * Runs across the pool when given. */
void sp_sem_score(const sp_sem_scorer *sc, sp_pool *pool, size_t n, const float *features,
                  float *raw_cos, float *relevancy);
/* The calibrated relevancy from a raw cosine and the negatives' raw cosines (reference form). */
float sp_sem_relevancy(float s_query, const float *s_neg, int n_neg, float temperature);

/* ---- lifting ---------------------------------------------------------------------------------- */

/* Supplies the target feature map of view v: [cam.height][cam.width][dim] host floats, and an
 * optional validity mask [H][W] (NULL = all valid; pixels with mask 0 are ignored). */
typedef int (*sp_lift_target_fn)(void *user, size_t view, float *target, uint8_t *mask,
                                 sp_error *err);

typedef struct sp_lift_opts {
    float min_weight; /* Gaussians whose total weight is below this keep zero features (1e-4) */
    int mask;         /* pass a mask buffer to the callback */
} sp_lift_opts;

sp_lift_opts sp_lift_opts_default(void);

/* Sets s->features (reallocated to dim) to the compositing-weight average of the targets over
 * n_views cameras. weight_out ([n], may be NULL) receives sum_p w_ip. Geometry unchanged. */
int sp_semantic_lift(sp_raster *r, sp_splat *s, int dim, const sp_camera *cams, size_t n_views,
                     sp_lift_target_fn target, void *user, const sp_lift_opts *opts,
                     float *weight_out, const sp_log *log, sp_error *err);

/* Lifts a feature folder (semsplat features) into the model folder DIR made by `train`: writes
 * f_sem_* into DIR/splat.ply and DIR/semantic.json with the PCA copied beside it (atomically).
 * colmap_dir NULL = the capture named in DIR/train.json, else the one in features.json. */
int sp_semantic_lift_model(const char *model_dir, const char *features_dir,
                           const char *colmap_dir, sp_device *dev, const sp_log *log,
                           sp_error *err);

/* The same in memory: lifts the feature folder's maps (matched to the COLMAP images by name,
 * rendered at the maps' resolution) into s->features. Maps of images with a distorted camera
 * (SIMPLE_RADIAL, RADIAL, OPENCV) are resampled into the pinhole camera the renderer uses
 * (sp_camera_remap_to_pinhole), pixels the image did not see left out. */
int sp_semantic_lift_features(sp_splat *s, const char *features_dir, const char *colmap_dir,
                              sp_device *dev, const sp_log *log, sp_error *err);

/* Writes DIR/semantic.json and the PCA copies for a splat whose features came from
 * features_dir by `method` ("lift" or "distill"). The text encoder recorded is the default for
 * the features: "lexical" for hashed label features (with their "classes"), else "clip". */
int sp_semantic_write_sidecar(const char *model_dir, const char *features_dir,
                              const char *colmap_dir, const char *method, sp_error *err);
/* Records the text encoder of a model folder in DIR/semantic.json ("clip", "lexical" or "exact";
 * see "Text encoders"). Refuses one that does not fit the folder's features (SP_E_UNSUPPORTED)
 * and lexical without class names (SP_E_NOTFOUND). */
int sp_semantic_set_encoder(const char *model_dir, const char *encoder, sp_error *err);

/* ---- distillation (what `semsplat distill` does) --------------------------------------------- */

typedef struct sp_distill_opts {
    const char *model_dir;    /* made by `train`: splat.ply is read and rewritten with f_sem_* */
    const char *features_dir; /* a feature folder (semsplat features) */
    const char *colmap_dir;   /* the capture (views and images) */
    const char *images_dir;   /* NULL: <colmap_dir>/images */
    int steps;                /* 3000 */
    float lambda;             /* feature loss weight (1) */
    int freeze_geometry;      /* train the features only (0) */
    int densify;              /* keep the trainer's clone/split schedule (0: off, already trained) */
    int init_from_lift;       /* start from the one-pass lift (1) or from zero (0) */
    int downscale;            /* image downscale (1) */
} sp_distill_opts;

sp_distill_opts sp_distill_opts_default(void);

typedef struct sp_distill_result {
    sp_train_result before, after; /* RGB metrics before distilling and the run's result after */
} sp_distill_result;

/* Continues training the model folder's splat with feature_lambda * MSE(rendered features, maps)
 * added to the RGB loss, then writes f_sem_* into DIR/splat.ply and DIR/semantic.json. Refuses
 * (SP_E_UNSUPPORTED) captures with distorted cameras: the maps are not resampled through the
 * lens here (lift does that). */
int sp_semantic_distill_model(sp_device *dev, const sp_distill_opts *o, sp_distill_result *res,
                              const sp_log *log, sp_error *err);

/* ---- the query engine ------------------------------------------------------------------------- */

/* Thread safety: an engine locks itself, so several threads may call any function on one engine
 * (calls run one at a time). The splat, cameras, frame and source an engine returns are fixed
 * at open and may be read from any thread without the lock. Each call takes its options
 * (NULL = the engine's defaults, given at open); nothing a call does changes the next one.
 *
 * Frames: every position, splat and camera the engine gives out is in the model folder's frame
 * (frame.json, see io.h): the world frame for synth captures and aligned models ("world"), else
 * COLMAP's own ("colmap"), and each result says which. */

typedef enum { SP_QUERY_3D = 0, SP_QUERY_MULTIVIEW = 1 } sp_query_method;

typedef struct sp_query_opts {
    int method;            /* sp_query_method */
    char negatives[256];   /* comma-separated canonical negatives ("" = SP_SEM_DEFAULT_NEGATIVES) */
    float temperature;     /* relevancy temperature (SP_SEM_DEFAULT_TEMPERATURE) */
    float min_confidence;  /* below this raw cosine the query is "not found" (0.2) */
    float keep_fraction;   /* relevant = raw cosine >= keep_fraction * confidence, and >= 0.1
                            * (0.6) */
    float min_relevancy;   /* ... and calibrated relevancy >= this (0.55) */
    float min_opacity;     /* Gaussians fainter than this are ignored (0.1) */
    float voxel_m;         /* clustering voxel edge in world units (0.12) */
    float min_instance_fraction; /* instances lighter than this share of the best are dropped
                                  * (0.1; multi-view uses a third of it: an instance seen from
                                  * few views sums fewer pixels) */
    int n_views;           /* multi-view: views rendered and back-projected, at least (4; up to
                            * three times as many while under 97% of the relevant set, by
                            * opacity, is seen) */
    int render_downscale;  /* renders for localization at 1/downscale resolution (2) */
    int heatmap;           /* render relevancy_image (1) */
    int heatmap_view;      /* -1 = best view, else an index into the cameras */
    int host_stages;       /* GPU engines: 1 = multi-view scoring, back-projection and heatmap
                            * colouring on the host, as CPU engines do (for comparisons; 0: on
                            * the GPU, copying back only the points and the final image) */
} sp_query_opts;

sp_query_opts sp_query_opts_default(void);

/* Text encoders: how an engine turns text into something its features can be compared with.
 * One is chosen per model folder (semantic.json "encoder", written by lift: `semsplat lift
 * --encoder`, sp_semantic_set_encoder) and may be overridden at open (sp_query_engine_open_with;
 * `semsplat query --encoder`, Python encoder=). Every result names the one that produced it.
 *   "clip"     CLIP's text tower (real weights). Features in CLIP's space (source clip, npy, or
 *              labels embedded through CLIP). Open vocabulary; confidence = the robust largest
 *              raw cosine, found at >= min_confidence.
 *   "lexical"  WordNet 3.0 matching of the text against the scene's own class names (the
 *              lexical section below), grounded in the scene: the matched classes are localized
 *              by their label embeddings, regions and relations resolved as sp_lex_query does.
 *              Needs hashed label features (source labels without weights), where it is the
 *              default. Confidence = the calibrated lexical score, found at >= SP_LEX_THRESHOLD
 *              (min_confidence is not applied). It is matching against KNOWN class names: it
 *              cannot find what the world's labels do not name.
 *   "exact"    the text's own hashed embedding (sp_label_embedding): only the exact class string
 *              (case and spaces aside) matches. Hashed label features; for tests and comparisons.
 * The class names of a label scene come from semantic.json "classes" (lift copies them from the
 * features), else from the labels.json beside the capture it names. A folder that records no
 * encoder gets lexical when its features are hashed labels and the classes and WordNet are there
 * (else exact, with a warning), clip otherwise. A recorded lexical that cannot be prepared (no
 * WordNet, no class names) falls back to exact with a warning; an encoder asked for at open
 * that cannot be prepared, or that does not fit the features, is an error. */
#define SP_ENCODER_CLIP "clip"
#define SP_ENCODER_LEXICAL "lexical"
#define SP_ENCODER_EXACT "exact"

typedef struct sp_encoder_opts {
    const char *encoder;      /* "clip", "lexical", "exact"; NULL or "" = the model folder's */
    const char *wordnet_dir;  /* lexical: WordNet's database files (NULL = SP_LEX_DEFAULT_WORDNET) */
    const char *regions_path; /* lexical: a region table (NULL = the bundled one, "" = none) */
} sp_encoder_opts;

/* What produced a result: the text encoder and the feature source, named (never a flag).
 *   encoder  "clip", "lexical" or "exact" (above)
 *   features "clip"   dense CLIP features of the images
 *            "npy"    imported maps (any extractor in the text space)
 *            "labels" ground-truth label images of a synthetic capture: results then measure
 *                     localization given a perfect 2D segmentation, not language understanding */
typedef struct sp_query_source {
    char encoder[16];
    char features[16];
    int ground_truth;  /* 1 when the features come from ground-truth label images */
} sp_query_source;

/* The caveat every output carries for this source ("" when there is none): with label
 * features, that the figures measure localization given a perfect 2D segmentation. */
const char *sp_query_source_note(const sp_query_source *s);

/* The frame a result's positions are in (frame.json of the model folder). */
typedef struct sp_query_frame {
    char name[16];   /* "world" or "colmap" */
    char source[16]; /* "synth", "align" or "colmap" */
    char units[16];  /* "m" or "unknown" */
    char up[8];      /* "+z" or "unknown" */
} sp_query_frame;

typedef struct sp_query_instance {
    float position[3];   /* in the result's frame */
    float extent_min[3]; /* robust bounds: the 5% and 95% weighted quantiles of its points per */
    float extent_max[3]; /* axis; position is their middle */
    float score;         /* summed weight of its points: 3D, opacity * (relevancy - 0.5);
                          * multi-view, (relevancy - 0.5) * alpha * the pixel's area at its depth */
    float confidence;    /* largest raw cosine inside it */
    int n_points;        /* Gaussians (3D) or pixels (multi-view) */
    char label[128];     /* the class it is an instance of, when the encoder knows ("" = unknown:
                          * clip, or a precomputed embedding) */
    float relation_m;    /* a relational query's cost of this instance to the anchor in metres
                          * (the gap between boxes, see sp_lex_query), NaN without one */
} sp_query_instance;

/* Why a text matched a class (encoders that match class names: lexical, exact). */
typedef struct sp_query_match {
    char label[128];       /* the class */
    char role[8];          /* "target", or "anchor" (the Y of "X near Y") */
    float score;           /* the encoder's confidence in this class, 0..1 (>= threshold: a match) */
    char kind[16];         /* "exact", "synonym", "hypernym", "hyponym", "part", "gloss",
                            * "modifier", "region" (sp_lex_kind_name) */
    char query_sense[64];  /* the WordNet lemma of the query sense used ("" for gloss matches) */
    char class_sense[64];  /* the lemma of the class sense used */
    char path[256];        /* taxonomy path, "armchair > chair > seat" */
    char gloss_words[192]; /* description words found in definitions, with where */
    char definition[192];  /* WordNet's definition of the class sense used */
} sp_query_match;

/* A region the text named ("the kitchen", "area with appliances"), or the anchor of a relation:
 * the extent of the instances that make it up, in the result's frame. */
typedef struct sp_query_region {
    int valid;
    char name[64];         /* "kitchen"; an anchor: its phrase */
    float extent_min[3], extent_max[3], centre[3];
    int n_instances;
} sp_query_region;

#define SP_QUERY_MAX_IGNORED 8

/* Stage times of one query in ms (host clock; a GPU stage is timed after waiting for it), 0 for
 * stages that did not run. Multi-view: pick (choosing the views), render (all views in one
 * batch), score (per-pixel relevancy and the relevant-pixel test), backproject (back-projection
 * and, on the GPU, compaction and the copy of the points), cluster. Heatmap: hm_pick (the best
 * view, when no view was given), hm_render (scores and RGB of the view), hm_colormap (relevancy
 * and colour overlay), hm_copy (the image and relevancy to the host; 0 on CPU engines). */
typedef struct sp_query_stages {
    double pick, render, score, backproject, cluster;
    double hm_pick, hm_render, hm_colormap, hm_copy;
} sp_query_stages;

typedef struct sp_query_result {
    char text[256];
    int method;          /* sp_query_method used */
    int valid;           /* 1 when confidence >= threshold and an instance was found */
    float position[3];   /* best instance (in `frame`); NaN when !valid */
    float confidence;    /* clip, exact: robust largest raw cosine, the 5th largest over Gaussians
                          * with opacity >= min_opacity; lexical: the calibrated lexical score of
                          * the text (0..1, found at >= threshold) */
    float relevancy_max; /* largest calibrated relevancy */
    int view_index;      /* camera used for the heatmap / best view, -1 = none */
    char view_name[256];
    int width, height;           /* of relevancy_image */
    uint8_t *relevancy_image;    /* [height][width][3] turbo overlay on RGB, NULL when not made;
                                  * in the pixels of image view_name: a distorted camera's
                                  * pinhole render is resampled through its lens */
    float *relevancy;            /* [height][width] calibrated relevancy of that view, or NULL */
    int n_instances;
    sp_query_instance *instances; /* best first */
    double ms_embed, ms_relevancy, ms_localize, ms_heatmap, ms_total;
    sp_query_source source;      /* what produced it */
    sp_query_frame frame;        /* the frame of position and instances */
    /* What the encoder understood (--explain, --json "matches", Python .explanation): */
    float threshold;             /* confidence at or above which this encoder reports a match
                                  * (clip, exact: min_confidence; lexical: SP_LEX_THRESHOLD) */
    int n_matches;
    sp_query_match *matches;     /* lexical: the target's classes at or above the threshold, then
                                  * the anchor's (when none matched, the nearest one below);
                                  * exact: the class named, if the engine knows it; clip: none */
    char relation[24];           /* "" or "near", "next to", "in", "on", "to", "above", ... */
    sp_query_region region;      /* valid: the text named a region; position is its centre */
    sp_query_region anchor;      /* valid: the anchor of the relation, as found */
    int n_ignored;
    char ignored[SP_QUERY_MAX_IGNORED][32]; /* attribute words it cannot see ("red", "wooden") */
    char *explanation;           /* human-readable: which classes matched and why (NULL = none) */
    sp_query_stages ms_stage;    /* where ms_localize and ms_heatmap went */
} sp_query_result;

void sp_query_result_free(sp_query_result *res);

typedef struct sp_query_engine sp_query_engine;

/* Opens a model folder (splat.ply with f_sem_*, semantic.json, PCA, frame.json, cameras from the
 * sidecar's COLMAP folder) once, and puts splat and cameras into the folder's frame; opts NULL =
 * defaults (kept as the engine's defaults). dev is borrowed (must outlive the engine). The text
 * encoder is the folder's (see "Text encoders" above). */
int sp_query_engine_open(sp_query_engine **out, const char *model_dir, const sp_query_opts *opts,
                         sp_device *dev, const sp_log *log, sp_error *err);
/* The same with the text encoder chosen here (enc NULL = as sp_query_engine_open). An encoder that
 * does not fit the features (clip on hashed labels, lexical or exact on CLIP features) or cannot
 * be prepared (no WordNet, no class names) fails with SP_E_UNSUPPORTED / SP_E_NOTFOUND. */
int sp_query_engine_open_with(sp_query_engine **out, const char *model_dir, const sp_encoder_opts *enc,
                              const sp_query_opts *opts, sp_device *dev, const sp_log *log,
                              sp_error *err);

/* An engine from memory (tests, tools): everything is copied. */
typedef struct sp_query_model {
    const sp_splat *splat;        /* with features [n][pca->dim], in model coordinates */
    const sp_sem_pca *pca;
    const sp_camera *cams;        /* [n_cams] in model coordinates (may be NULL with 0) */
    size_t n_cams;
    const char *const *cam_names; /* [n_cams] or NULL ("view <i>") */
    const sp_query_source *source; /* NULL = encoder "exact", features "labels" */
    const sp_frame *frame;        /* NULL = identity, source "colmap" */
    const char *clip_weights;     /* encoder "clip": the CLIP model.safetensors */
    const char *const *classes;   /* label scenes: the class names ([n_classes]; required for
                                   * encoder "lexical"; exact uses them to name its match) */
    int n_classes;
    const char *wordnet_dir;      /* lexical: NULL = SP_LEX_DEFAULT_WORDNET */
    const char *regions_path;     /* lexical: NULL = the bundled region table, "" = none */
} sp_query_model;

int sp_query_engine_create(sp_query_engine **out, const sp_query_model *m, const sp_query_opts *opts,
                           sp_device *dev, const sp_log *log, sp_error *err);
void sp_query_engine_free(sp_query_engine *e);

/* Answers the text through the engine's text encoder with opts (NULL = the engine's defaults):
 * clip and exact embed it and localize the embedding; lexical matches it against the scene's
 * classes and localizes what matched, resolving regions and relations (sp_lex_query). res is
 * filled (free with sp_query_result_free) even when nothing is found, with what the encoder
 * understood (matches, explanation); on an error it is left empty (nothing to free). */
int sp_query_engine_query(sp_query_engine *e, const char *text, const sp_query_opts *opts,
                          sp_query_result *res, sp_error *err);
/* Same with a precomputed full_dim embedding (need not be unit length); label names the result. */
int sp_query_engine_query_embedding(sp_query_engine *e, const float *embedding, const char *label,
                                    const sp_query_opts *opts, sp_query_result *res, sp_error *err);
/* Text -> full_dim unit embedding as the engine does it (out [full_dim]): clip the text tower,
 * exact the text's hash, lexical the score-weighted label embeddings of the classes it matches
 * (sp_lex_embed; the text's own hash, which matches nothing, when no class does). Relevancy and
 * heatmaps score this embedding. */
int sp_query_engine_embed(sp_query_engine *e, const char *text, float *out, sp_error *err);
/* Per-Gaussian calibrated relevancy [n] (0.5 = no preference .. 1) and, when raw_cos is not
 * NULL, raw cosine [n] of a text, with the engine's default negatives and temperature; n and the
 * order are those of sp_query_engine_splat(e). */
int sp_query_engine_relevancy(sp_query_engine *e, const char *text, float *relevancy,
                              float *raw_cos, sp_error *err);
/* The heatmap of a text seen from any camera (in the engine's frame, pinhole): rgb [H][W][3] the
 * turbo overlay on the rendered scene (as query heatmaps: stretched when the text is confidently
 * present, faded when not), relevancy [H][W] (may be NULL) the calibrated per-pixel relevancy
 * (0.5 where nothing is drawn). H, W = cam->height, cam->width. */
int sp_query_engine_heatmap(sp_query_engine *e, const char *text, const sp_camera *cam,
                            uint8_t *rgb, float *relevancy, sp_error *err);

const sp_query_opts *sp_query_engine_defaults(const sp_query_engine *e);
/* An empty, not-found result (position NaN, no instances) carrying the engine's source and frame,
 * for modules that compose answers from several queries (lexical, relations). */
void sp_query_engine_result_init(const sp_query_engine *e, const char *text, sp_query_result *res);
int sp_query_engine_full_dim(const sp_query_engine *e);
size_t sp_query_engine_n_cameras(const sp_query_engine *e);
/* The splat (with its semantic features) and cameras in the engine's frame (world for synth and
 * aligned models): what navigation, the agent and ROS plan and render on. */
const sp_splat *sp_query_engine_splat(const sp_query_engine *e);
/* Camera i with the lens COLMAP gives it (renders use its pinhole part), posed in the engine's
 * frame. */
const sp_camera *sp_query_engine_camera(const sp_query_engine *e, size_t i);
const char *sp_query_engine_camera_name(const sp_query_engine *e, size_t i);
const sp_frame *sp_query_engine_frame(const sp_query_engine *e);
const sp_query_source *sp_query_engine_source(const sp_query_engine *e);

/* The result as JSON text (malloc'd, caller frees with free()): text, encoder, method, found
 * (valid), position (array or null), confidence, threshold, relevancy_max, view, instances
 * [{position, extent_min, extent_max, score, confidence, points, class (or null), relation_m (or
 * null)}], heatmap (heatmap_path or null), timings_ms, source {encoder, features, ground_truth,
 * note}, frame {name, source, units, up}, matches [{class, role, score, kind, query_sense,
 * class_sense, path, gloss_words, definition}], relation (or null), region and anchor ({name,
 * extent_min, extent_max, centre, instances} or null), ignored [words], explanation (or null). */
char *sp_query_result_json(const sp_query_result *res, const char *heatmap_path);

/* ---- ABI (for bindings: the Python module checks these before any call) ---------------------- */

#define SP_SEMANTIC_ABI_VERSION 4 /* 4: sp_query_opts.host_stages, sp_query_result.ms_stage */
int sp_semantic_abi_version(void);
/* sizeof of a public struct by name ("sp_query_opts", "sp_query_result", "sp_query_instance",
 * "sp_query_source", "sp_query_frame", "sp_query_match", "sp_query_region", "sp_encoder_opts",
 * "sp_error", "sp_camera", "sp_image", "sp_splat"); 0 when unknown. */
size_t sp_semantic_abi_sizeof(const char *type_name);

/* ---- the lexical text encoder (WordNet 3.0) -------------------------------------------------- *
 *
 * Matches free text against a scene's own class names ("refrigerator", "kitchen counter", ...)
 * with WordNet 3.0 (Debian's wordnet-base, read directly from /usr/share/wordnet). It is
 * matching against KNOWN class names: it cannot find anything the world's labels do not name.
 *
 * A query is split into target and anchor at a spatial relation where both sides match ("X near
 * / next to / beside / by / in / on / to / above / under ... Y"), and each phrase into a head noun
 * (the longest WordNet collocation ending at its last noun: "coffee table", "tv set", "trash can";
 * closed compounds WordNet lacks are split, "nightstand" = "night" + "stand"), the modifiers
 * before it, and description words after a clause marker ("something TO sit on", "a seat FOR
 * two", "WHAT tells the time").
 * Names WordNet lacks or files under another sense ("shop vac", "telly", "trolley", "hob") are
 * read through an alias table (data/semantic/aliases.json, extendable by an aliases.json beside a
 * region table passed as regions_path): a query is also matched with each alias replaced by its
 * WordNet lemmas (up to three readings) and every class keeps its best reading; a class name that
 * is wholly an alias, or whose head WordNet lacks, is read through its first lemma.
 * Per class c, the confidence in 0..1 is, from the head h (all its senses; a word whose senses
 * are all taxonomic groups, "ficus", also its members' senses) and the class's head (its
 * physical senses that the tagged corpora attest, persons and named individuals (WordNet
 * instances) left out, persons, physical processes and rooms only when the name also names an
 * artifact (that is no room); when the attested ones are neither artifacts nor living things
 * and the name names artifacts ("radiator"), its artifact senses; when none is attested,
 * or the name has no tag counts at all, its physical senses closest to the other classes of the
 * scene, after Resnik 1999):
 *   T = 1                                   exact name (after plurals) or a shared synset
 *     = 2 dep(h) / (d + 2 dep(h))           h is a hypernym of c, d levels up (Wu & Palmer 1994)
 *     = 2 dep(c) / (d + 2 dep(c))           c is a hypernym of h, d levels up: a laptop is a
 *                                           computer however far down (no decay beyond WuP's)
 *     = 0.6                                 h (a commonly used sense) is a part of c
 *     = MU WuP(h, c)                        neither: siblings, cousins (MU 0.45: always < 0.5)
 * with depths counted from 'entity'; a class named by a noun modifier, or a word WordNet lacks
 * ("overbed"), and a head ("shoe cabinet") sits one level below its head, so the head alone is
 * its hypernym and another kind of the head ("dresser") its sibling; so does a query that is a
 * closed compound WordNet lacks ("nightstand"), unless the class's name has its first part. T is multiplied by
 *   (1 - BETA)                 per query modifier that names other classes and not this one (0.3)
 *   MU                         per query modifier naming another kind of thing than the class's
 *                              own modifier ("WINE rack" / magazine rack: a sibling, below 0.5):
 *                              both words' commonest senses attested and an animal, artifact,
 *                              communication, food or plant (WordNet's lexicographer files; not
 *                              a material, act, quality or person), neither a kind or sibling of
 *                              the other, neither's definitions naming the other, and no word of
 *                              the class's name in the query's modifiers or head
 *   (1 - EPS)                  per attribute its definitions do not mention (0.1; "red", "wooden":
 *                              reported in `ignored`)
 *   (1 - GAMMA + GAMMA G)      when a description stands beside the head (GAMMA 0.3).
 * Without a head noun (or with a placeholder: "something", "a place") the confidence is G:
 *   G = sum_d w_d m_d / sum_d w_d,  w_d = 1 / (1 + ln(1 + senses(d)))  (polysemy for frequency),
 *   m_d = 1 when d (a base form) is in the class's name, lemmas or definition, DELTA (0.8) in its
 *   hypernym's or in the lemmas and definitions of the verbs WordNet derives from it ("+"
 *   pointers: bicycle -> "ride a bicycle", refrigerator -> refrigerate), DELTA^2 two levels up,
 *   and 0.8 for a lemma of d's commonest sense, or a noun WordNet derives from that sense when
 *   it is a verb (type -> typewriter), found in the class's own definition (one weak step at
 *   most); when the description ends in a preposition ("something to write on": where
 *   the verb is done) a verb found only as a past participle ("a written work": what it acts on)
 *   counts DELTA times its weight, and a verb the thing itself does (a relative clause on it,
 *   "a lamp that sits on a table", or an -ing form right after a noun) DELTA^2 times it unless
 *   the description says what the thing does ("something that keeps food cold"); the
 *   definitions of the class sense's kinds (one level down, definitions only) count DELTA^2
 *   ("washbasin: ... where you can wash your hands" for the sink), not for a class one level
 *   below its sense and not as evidence for a modifier. Location words (room, area) describe
 *   nothing. A query sense defined as "any <kind> <condition>" ("light: any device serving as a
 *   source of illumination") also scores T(that kind, c) G(condition words, c) for classes c
 *   below its hypernym; a bare head whose commonest sense is an act ("storage") DELTA times the
 *   confidence of "something to V" for the verbs WordNet derives from it.
 * A compound whose modifier is itself a class name ("tv monitor") also scores
 * T(modifier, c) WuP(head, c)^2. A head that is the agent noun of a verb WordNet derives it from
 * ("dispenser" <- dispense, "cooker" <- cook: stem + -er/-or/-ar, from a physical sense that is
 * no person) also scores DELTA times the weighted share, head and modifiers, found in c's
 * definitions when c's own definition does the verb (base or -ing form, not a past participle):
 * "water dispenser" -> water cooler, "a device for cooling and dispensing drinking water".
 * Regions ("the kitchen", "bedroom", "the meeting room", "area with appliances", "the area that
 * looks like a kitchen") list the classes that define them: the region table's object phrases
 * (data/semantic/regions.json, extendable; a generic head with modifiers, "meeting room", is
 * looked up there whole), the nouns of the region's WordNet definition (for names WordNet has),
 * classes named after it ("kitchen counter"); a room needs two kinds of them, one alone is
 * scaled by MU. SP_LEX_THRESHOLD is the one threshold for every world.
 * Thread safety: an sp_lexicon and an sp_lex_vocab are immutable once made (the database files
 * are mapped read-only); any number of threads may match against them at once. Results are
 * plain structs with fixed arrays (no ownership). */

#define SP_LEX_THRESHOLD 0.5f           /* confidence at or above which a class matches */
#define SP_LEX_DEFAULT_WORDNET "/usr/share/wordnet"
#define SP_LEX_MAX_CLASSES 128
#define SP_LEX_MAX_IGNORED 8

typedef struct sp_lexicon sp_lexicon;
typedef struct sp_lex_vocab sp_lex_vocab;

/* Opens WordNet's database files in dir (NULL = SP_LEX_DEFAULT_WORDNET). Reads nothing else:
 * start-up is a few file opens and one synset read. Fails with SP_E_NOTFOUND naming the file and
 * the Debian package when the database is missing. */
int sp_lexicon_open(sp_lexicon **out, const char *wordnet_dir, sp_error *err);
void sp_lexicon_free(sp_lexicon *lx);

/* Prepares a scene's class names (n <= SP_LEX_MAX_CLASSES; each index keeps its name) against lx,
 * which must outlive the vocabulary. regions_path: a region table (JSON object: region name ->
 * array of object phrases), NULL = sp_data_dir()/semantic/regions.json ("" = none); the alias
 * table sp_data_dir()/semantic/aliases.json and the activity table .../semantic/uses.json are
 * always read, and an aliases.json or uses.json beside a given regions_path adds its entries.
 * Resolves the
 * table's regions once (house, 25 classes: about 60 ms). */
int sp_lex_vocab_create(sp_lex_vocab **out, const sp_lexicon *lx, const char *const *classes,
                        int n, const char *regions_path, sp_error *err);
void sp_lex_vocab_free(sp_lex_vocab *v);
int sp_lex_vocab_size(const sp_lex_vocab *v);
const char *sp_lex_vocab_class(const sp_lex_vocab *v, int i);

/* How a class matched (strongest evidence). */
typedef enum {
    SP_LEX_NONE = 0,
    SP_LEX_EXACT,     /* the class name itself (after plurals and inflections) */
    SP_LEX_SYNONYM,   /* the query's head shares a WordNet synset with the class */
    SP_LEX_HYPERNYM,  /* the query is more general ("appliance" -> refrigerator) */
    SP_LEX_HYPONYM,   /* the query is more specific ("clock" -> timepiece) */
    SP_LEX_PART,      /* the query names a part of the class */
    SP_LEX_RELATED,   /* siblings or cousins in the taxonomy: always below the threshold */
    SP_LEX_GLOSS,     /* description words found in the class's definitions */
    SP_LEX_MODIFIER,  /* through a modifier that is itself a class ("tv monitor") */
    SP_LEX_REGION     /* named after the region ("kitchen counter" in the kitchen) */
} sp_lex_kind;

const char *sp_lex_kind_name(int kind); /* "exact", "synonym", ... */

typedef struct sp_lex_class_match {
    int class_index;
    float score;          /* confidence 0..1; >= SP_LEX_THRESHOLD = match */
    int kind;             /* sp_lex_kind */
    char query_sense[64]; /* the WordNet lemma of the query sense used ("" for gloss matches) */
    char class_sense[64]; /* the lemma of the class sense used */
    char path[256];       /* taxonomy path, "armchair > chair > seat" (class to query or LCS) */
    char gloss_words[192];/* "sit (seat: furniture that is designed for sitting on)" */
    char definition[192]; /* WordNet definition of the class sense used */
} sp_lex_class_match;

/* One resolved phrase: every class scored, best first. For a region (is_region) the matches are
 * its member classes, each with how its member phrase matched. */
typedef struct sp_lex_phrase {
    char text[128];        /* the words of this phrase */
    char head[64];         /* head noun or collocation used ("" = description only) */
    int is_region;         /* the phrase names a region */
    char region[64];       /* its name ("kitchen", or the phrase defining a generic area) */
    int n_matches;         /* = number of classes */
    sp_lex_class_match matches[SP_LEX_MAX_CLASSES];
} sp_lex_phrase;

typedef struct sp_lex_result {
    char text[256];
    sp_lex_phrase target;  /* what to find (X of "X near Y", or the whole query) */
    char relation[24];     /* "" or "near", "next to", "in", "on", "to", "above", ... */
    sp_lex_phrase anchor;  /* Y when relation[0] */
    int n_ignored;
    char ignored[SP_LEX_MAX_IGNORED][32]; /* attribute words it cannot see ("red", "wooden") */
    float confidence;      /* the target's best score (0 when nothing matched) */
    int found;             /* confidence >= SP_LEX_THRESHOLD (and the anchor found, if any) */
} sp_lex_result;

/* Scores text against every class of v. The result is large (fixed arrays): allocate it on the
 * heap. Fails on empty text; a text with no known words gives found = 0, not an error. */
int sp_lex_match(const sp_lex_vocab *v, const char *text, sp_lex_result *res, sp_error *err);
/* The result as JSON (malloc'd, caller frees): text, found, confidence, target {head, region,
 * matches [{class, score, kind, query_sense, class_sense, path, gloss_words, definition}] above
 * min_score}, relation, anchor, ignored. */
char *sp_lex_result_json(const sp_lex_result *res, const sp_lex_vocab *v, float min_score);
/* A human-readable explanation (--explain) into out. */
void sp_lex_explain(const sp_lex_result *res, const sp_lex_vocab *v, char *out, size_t cap);

/* ---- lexical queries on a label-feature scene ------------------------------------------------- *
 *
 * The lexical encoder grounded through the query engine (label-feature scenes, whose classes'
 * features are sp_label_embedding vectors): the engine localizes the matched classes' label
 * embeddings, and the result's confidence is the lexical score (found = that score >=
 * SP_LEX_THRESHOLD and an instance was localized). A region
 * is each of its classes localized alone, their instances clustered in space (boxes within 2 m),
 * and the cluster holding most of the region's kinds taken: its extent and centre. A target too
 * is each matched class localized alone (the scene must show a cosine of 0.5 with the class's
 * embedding, else the class is named but not seen), instances of the best-scoring class first;
 * a text that is a class's own name (kind exact) means that class alone ("couch": not also the
 * bed WordNet calls a couch; "dining chair": not the armchair).
 * A relation then ranks them, within a class score, by their distance to the anchor's instances
 * (or region): the gap between boxes ("near", "to", "in", ...), or for "on"/"above"
 * ("under"/"below") the horizontal gap plus how far the target sits below (above) the anchor's
 * top (bottom), 0.3 m tolerance; for "between" the gaps to the two nearest anchor instances
 * summed. */

typedef struct sp_lex_extent {
    float extent_min[3], extent_max[3]; /* world frame */
    float centre[3];
    int n_instances;
} sp_lex_extent;

typedef struct sp_lex_answer {
    sp_lex_result lex;        /* what the text matched, and why */
    sp_query_result result;   /* the target's instances (ranked by the relation when there is one;
                               * a region's member instances); confidence = the lexical score;
                               * position = the best instance, or the region's centre */
    int is_region;
    sp_lex_extent region;     /* is_region: the extent of the region's objects */
    int has_anchor;
    sp_lex_extent anchor;     /* relation: the anchor instance nearest the best target, or region */
    int *instance_class;      /* [result.n_instances] the class (vocabulary index) of each */
    float *relation_m;        /* [result.n_instances] each instance's relation cost in metres
                               * (NULL without a relation or when the anchor is not found) */
} sp_lex_answer;

/* Answers text on engine e (a label-feature scene whose class names are v's). a is large: put it
 * on the heap; free with sp_lex_answer_free. The engine's default options are used, except that
 * the lexical score decides what is found (min_confidence is not applied). The engine's own
 * lexical encoder (sp_query_engine_query) runs exactly this with the call's options and hands
 * the answer back as a plain sp_query_result (matches, region, anchor, explanation). */
int sp_lex_query(sp_query_engine *e, const sp_lex_vocab *v, const char *text, sp_lex_answer *a,
                 sp_error *err);
void sp_lex_answer_free(sp_lex_answer *a);
/* The lexical encoder as a text embedding for a label-feature scene: the target's classes
 * matched at or above the threshold (only the exact ones when the text is a class's own name),
 * sum of score * sp_label_embedding(class, dim), normalised (all zeros when nothing matches);
 * *confidence (may be NULL) the lexical score. */
int sp_lex_embed(const sp_lex_vocab *v, const char *text, int dim, float *out, float *confidence,
                 sp_error *err);
/* The answer as JSON: sp_query_result_json's fields plus encoder ("lexical"), lexical (as
 * sp_lex_result_json), region and anchor (extents, relation, instance_cost_m). */
char *sp_lex_answer_json(const sp_lex_answer *a, const sp_lex_vocab *v, const char *heatmap_path);
/* A vocabulary of the classes of a capture's labels.json (synth's format; "background" and
 * repeats dropped). */
int sp_lex_vocab_from_labels(sp_lex_vocab **out, const sp_lexicon *lx, const char *labels_json,
                             const char *regions_path, sp_error *err);
/* The vocabulary of a label-feature model folder (semantic.json: source "labels", label_embedding
 * "hash"): its "classes", else the labels.json of the capture it names. Other models fail with
 * SP_E_UNSUPPORTED (their features live beside CLIP's text tower, not label embeddings). */
int sp_lex_vocab_for_model(sp_lex_vocab **out, const sp_lexicon *lx, const char *model_dir,
                           const char *regions_path, sp_error *err);

/* ---- heatmaps --------------------------------------------------------------------------------- */

/* (The Turbo colour map, sp_turbo, is in render.h.) */
/* Overlays relevancy [H][W] (0.5 = neutral .. 1) in turbo colours on rgb [H][W][3] floats,
 * writing out [H][W][3] uint8: a dimmed scene with the colour map fading in above 0.5. */
void sp_heatmap_overlay(const float *rgb, const float *relevancy, int width, int height,
                        uint8_t *out);

/* ---- frames (semsplat align) ------------------------------------------------------------------ */

/* Umeyama (1991) similarity dst ~ s R src + t from n >= 3 point pairs ([n][3] each); M gets the
 * 4x4 row-major transform [sR t; 0 1]. Fails on degenerate (collinear) input. */
int sp_umeyama(const double *src, const double *dst, size_t n, int with_scale, double M[16],
               double *rms, sp_error *err);
/* Matches between the COLMAP frame and the world (semsplat align --matches): src [n][3] a
 * COLMAP-frame point (a camera centre for image lines), dst [n][3] its world position, name [n]
 * the image ("" for a point match). Owns its arrays (sp_align_matches_free). */
typedef struct sp_align_matches {
    size_t n;
    double *src, *dst;
    char (*name)[256];
} sp_align_matches;

/* Reads lines 'IMAGE_NAME x y z' (that image's camera centre in colmap_dir's model -> the world
 * point) or 'x y z X Y Z'; '#' comments. colmap_dir may be NULL when no line names an image.
 * Errors name the file and line (bad numbers, an image the model does not have). */
int sp_align_read_matches(const char *path, const char *colmap_dir, sp_align_matches *out,
                          sp_error *err);
void sp_align_matches_free(sp_align_matches *m);

/* The robust frame fit refuses unless at least this many matches, and at least half of them,
 * agree: 3 matches fix a similarity, the 4th is the first that can contradict it; least median
 * of squares (the fit most matches agree with) has a breakdown point of one half, so with fewer
 * than half agreeing it cannot tell the right fit from one made by the wrong matches. */
#define SP_ALIGN_MIN_INLIERS 4
/* ... and, with the automatic bound, unless that bound is at most this fraction of the spread of
 * the matched world points (RMS distance from their mean): when more than half the matches are
 * wrong the median residual is a wrong match's and the bound grows with it; a frame whose
 * errors are a tenth of the scene is no frame. An explicit bound skips this test. */
#define SP_ALIGN_MAX_BOUND_FRACTION 0.1

/* A robust similarity fit. Owns inlier and residual (sp_align_fit_free). */
typedef struct sp_align_fit {
    double M[16];           /* world_from_colmap, row-major [sR t; 0 1], refitted on the inliers */
    size_t n, n_inliers;
    uint8_t *inlier;        /* [n] 1 = agrees with the fit */
    double *residual;       /* [n] |M src - dst| in world units */
    double rms_inliers;     /* RMS residual of the inliers */
    double rms_all;         /* RMS of plain least squares over all matches (for comparison) */
    double median_residual; /* the least median (of the best minimal-sample fit) */
    double threshold;       /* the inlier bound used (world units) */
} sp_align_fit;

/* Least median of squares over Umeyama fits of minimal samples (all triples up to 20000, else
 * 20000 random ones, deterministic), then inliers = residual <= threshold and a refit on them
 * (three rounds). threshold <= 0: automatic, 4.03 sigma (the 99.9% bound of the length of an
 * isotropic 3D Gaussian error) with sigma from the median residual (median / 1.538, times
 * Rousseeuw's 1 + 5/(n-3)), then from the inliers' RMS. Fails with SP_E_ARG below SP_ALIGN_MIN_INLIERS
 * matches or when all are collinear, and with SP_E_FORMAT (fit filled, so the outliers can be
 * reported) when fewer than max(SP_ALIGN_MIN_INLIERS, ceil(n/2)) agree or the automatic bound
 * exceeds SP_ALIGN_MAX_BOUND_FRACTION of the world points' spread. */
int sp_align_fit_robust(const double *src, const double *dst, size_t n, int with_scale,
                        double threshold, sp_align_fit *fit, sp_error *err);
void sp_align_fit_free(sp_align_fit *f);
/* The fit as JSON text (malloc'd, free()): method, with_scale, world_from_colmap (4x4), matches,
 * inliers, rms_inliers, rms_all_least_squares, median_residual, inlier_threshold, outliers
 * [{image (or match index), residual}]. m may be NULL (outliers by index). */
char *sp_align_fit_json(const sp_align_fit *fit, const sp_align_matches *m, int with_scale);

/* Applies a similarity [sR t] to a splat: means, quats, log_scales and SH (rotated per band). */
int sp_splat_transform(sp_splat *s, const double M[16], sp_error *err);
/* RANSAC floor plane on the lowest Gaussians (along the cameras' mean "up" = -y_cam) and a
 * transform M that maps it to z = 0 with +z up (pointing to the cameras). inliers: fraction. */
int sp_detect_floor(const sp_splat *s, const sp_camera *cams, size_t n_cams, double M[16],
                    double normal[3], double *inliers, sp_error *err);

#ifdef __cplusplus
}
#endif
#endif
