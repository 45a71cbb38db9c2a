/* Private pieces of the semantic module shared between the engine, localization and heatmaps. */
#ifndef SP_SEM_INTERNAL_H
#define SP_SEM_INTERNAL_H

#include <pthread.h>
#include <string.h>

#include "device/device_impl.h" /* sp_device_scratch */
#include "semsplat/semantic.h"

struct sp_clip;
struct cJSON;
typedef struct sem_encoder sem_encoder;

struct sp_query_engine {
    pthread_mutex_t mu;        /* every public call holds it: scratch, caches and rasters below */
    int has_mutex;
    sp_device *dev;
    sp_raster *raster;
    sp_log log;
    int has_log;
    sp_splat splat;            /* in the engine's frame (world_from_model applied at open) */
    sp_sem_pca pca;
    size_t n_cams;
    sp_camera *cams;           /* in the engine's frame */
    char (*cam_names)[256];
    sp_query_source source;    /* encoder ("exact": sp_label_embedding, "clip": the text tower,
                                * "lexical": WordNet against the classes) */
    const sem_encoder *enc;    /* the encoder's operations (source.encoder names it) */
    int n_classes;
    char (*classes)[128];      /* label scenes: the class names (NULL when unknown) */
    sp_lexicon *lx;            /* lexical: WordNet and the classes prepared against it */
    sp_lex_vocab *vocab;
    sp_frame frame;
    sp_query_frame qframe;     /* the frame as results carry it */
    char clip_path[1024];
    struct sp_clip *clip;      /* loaded on the first text query */
    sp_query_opts defaults;    /* options of calls that pass NULL */
    char neg_key[256];         /* negatives string the cached embeddings belong to */
    int n_neg;
    float *neg_emb;            /* [n_neg][full_dim] */
    float *opacity;            /* [n] sigmoid(logit) */
    float *raw, *rel;          /* [n] scratch: per-Gaussian raw cosine and relevancy */
    float *scores2;            /* [n][2] (raw, rel) rendered as two channels */
    sp_scene *scene;           /* the splat's RGB and features on the device (made on first render) */
    sp_scene *scores_scene;    /* the same geometry with scores2 as 2-channel features, updated
                                * per query (made on first use) */
    float *d_feat, *d_raw, *d_rel; /* CUDA engines: features [n][d] and scores [n] on the GPU */
    int dev_scores;            /* d_raw, d_rel hold the last scoring (else it ran on the host) */
    float *d_scores2;          /* CUDA engines: [n][2] (raw, rel) for scores_scene, on the GPU */
    sp_device_scratch mv_out;  /* device stages: the multi-view renders (features, depth, alpha) */
    sp_device_scratch mv_work; /* device stages: per-pixel scores, flags, scan, points */
    sp_device_scratch hm_out;  /* device stages: the heatmap's render, relevancy and image */
    sp_grid3 occ;              /* occupancy of opaque Gaussian centres (1), built on first use */
};

/* Every numeric query option in its range (opts.c); SP_E_ARG naming the option otherwise. */
int sem_check_opts(const sp_query_opts *o, sp_error *err);
/* ---- text encoders (encoder.c): one table of operations per encoder ---------------------------
 * Every function is called with the engine's lock held. */
struct sem_encoder {
    const char *name;
    int label_space; /* its features are sp_label_embedding vectors (exact, lexical) */
    /* text -> full_dim unit embedding */
    int (*embed)(sp_query_engine *e, const char *text, float *out, sp_error *err);
    /* the whole query (lexical), or NULL: embed, localize, then explain */
    int (*query)(sp_query_engine *e, const char *text, const sp_query_opts *o, sp_query_result *res,
                 sp_error *err);
    /* fills threshold, matches and explanation of an embed-and-localize result */
    int (*explain)(sp_query_engine *e, const sp_query_opts *o, sp_query_result *res, sp_error *err);
};

/* The encoder of that name, or NULL. */
const sem_encoder *sem_encoder_find(const char *name);
/* Prepares the engine's encoder `name` (lexical: the lexicon and the vocabulary of e->classes);
 * wordnet_dir / regions_path as in sp_encoder_opts. Sets e->enc and e->source.encoder. */
int sem_encoder_prepare(sp_query_engine *e, const char *name, const char *wordnet_dir,
                        const char *regions_path, sp_error *err);
/* Text embeddings in the feature space itself: hashed names for label features, CLIP's text tower
 * otherwise (what the canonical negatives are embedded with, for every encoder). */
int sem_embed_base(sp_query_engine *e, const char *const *texts, int n, float *out, sp_error *err);
/* sp_query_engine_query_embedding without the lock (callers hold it): options checked, res empty
 * on error. */
int sem_query_embedding(sp_query_engine *e, const float *embedding, const char *label,
                        const sp_query_opts *o, sp_query_result *res, sp_error *err);
/* The lexical encoder's whole query on the engine (lex_ground.c): sp_lex_query with options o,
 * turned into a query result with its matches, regions, relation and explanation. */
int sem_lex_engine_query(sp_query_engine *e, const char *text, const sp_query_opts *o,
                         sp_query_result *res, sp_error *err);
/* The class names of a model folder whose sidecar is js (semantic.json "classes", else the
 * labels.json beside the capture it names; "background" and repeats dropped): *names malloc'd,
 * *n their count; 0 with *n = 0 when it has none. */
int sem_model_classes(const char *model_dir, const struct cJSON *sidecar, char (**names)[128], int *n,
                      sp_error *err);

/* One match as JSON (result.c): class, role, score, match (score >= threshold), kind, senses,
 * path, gloss_words, definition. */
struct cJSON *sem_match_json(const sp_query_match *m, float threshold);

/* Points with weights clustered on a voxel grid (26-connected components) into instances,
 * heaviest first, lighter than min_fraction of the heaviest dropped; voxels whose points weigh
 * less than min_voxel_weight in total are ignored. conf [m] may be NULL. */
int sem_cluster(const float *pts, const float *w, const float *conf, size_t m, float voxel,
                float min_fraction, float min_voxel_weight, sp_query_instance **out, int *n_out,
                sp_error *err);

/* A sort key and the index of what it belongs to. */
typedef struct {
    uint64_t key;
    uint32_t idx;
} sem_keyed;
/* Sorts a [m] by key, stably (equal keys keep their order: a list made in index order comes out
 * ordered by (key, idx)); tmp [m] is scratch (sort.c). */
void sem_sort_keyed(sem_keyed *a, sem_keyed *tmp, size_t m);
/* A key whose unsigned order is f's order (not NaN; -0 sorts just before +0): negatives
 * reversed below the positives. */
static inline uint64_t sem_float_order(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u >> 31 ? ~u : u | 0x80000000u;
}

/* Relevant-set thresholds of a query: raw >= thr_raw && rel >= thr_rel && opacity >= min_op,
 * and the options of the call they belong to. */
typedef struct {
    float thr_raw, thr_rel, min_op;
    const sp_query_opts *opts;
} sem_thresholds;

/* Localizations: fill res->instances / position / valid / view_index. raw, rel per Gaussian
 * already in e->raw, e->rel. */
int sem_localize_3d(sp_query_engine *e, const sp_sem_scorer *sc, const sem_thresholds *th,
                    sp_query_result *res, sp_error *err);
int sem_localize_multiview(sp_query_engine *e, const sp_sem_scorer *sc, const sem_thresholds *th,
                           sp_query_result *res, sp_error *err);
/* Chooses cameras that see the relevant set (mask [n], or the thresholds when mask is NULL)
 * unoccluded (occupancy-grid test) and well framed, greedily covering what earlier picks did not
 * see: at least k_min views (when they add anything), then more up to k until 97% of the
 * relevant set (weighted by opacity) is covered.
 * Writes indices best first; returns the count or a negative error. */
int sem_pick_views(sp_query_engine *e, const sp_sem_scorer *sc, const sem_thresholds *th,
                   const uint8_t *mask, int k_min, int k, int *views, float *scores, sp_error *err);
/* Renders view `v` at full size with the heatmap overlay into res. */
int sem_heatmap(sp_query_engine *e, const sem_thresholds *th, int v, sp_query_result *res,
                sp_error *err);
/* The overlay of the last scoring through any camera: img [H][W][3], rel [H][W] (may be NULL).
 * found: stretch the visible relevancy to the full colour range; else fade it by how far
 * confidence is below min_confidence. */
int sem_heatmap_render(sp_query_engine *e, const sp_camera *cam, int found, float confidence,
                       float min_confidence, int host_stages, uint8_t *img, float *rel,
                       sp_query_stages *st, sp_error *err);
/* The scores scene (the splat's geometry and SH, with the per-Gaussian (raw, rel) of the last
 * scoring as 2 feature channels) made or brought up to date: from d_scores2 on the device when
 * the scoring ran there, else from the host scores. */
int sem_scores_scene(sp_query_engine *e, sp_error *err);
/* Renders the per-Gaussian (raw, rel) of the last scoring through camera cam (2 channels, cheap
 * next to D feature channels) with the RGB in the same pass: raw/rel [H][W] of the
 * alpha-normalised composite where alpha > 0.5 (else -1 / 0.5); rgb [H][W][3] too when not NULL. */
int sem_render_scores(sp_query_engine *e, const sp_camera *cam, float *raw, float *rel, float *rgb,
                      sp_error *err);
/* Float counts rounded up to 64 (256-byte aligned pieces of one device scratch block). */
static inline size_t sem_align64(size_t floats) { return (floats + 63) & ~(size_t)63; }
/* 1 when the semantic stages run on the device: a GPU engine whose last scoring ran there, unless
 * host_stages asks for the host. */
int sem_device_stages(const sp_query_engine *e, int host_stages);
/* Per-pixel raw cosine / relevancy of a rendered feature image (feat [npix][dim], alpha [npix])
 * where alpha > 0.5 (else -1 / 0.5). SP_E_NOMEM when the normalised copy cannot be made. */
int sem_score_pixels(sp_query_engine *e, const sp_sem_scorer *sc, const float *feat,
                     const float *alpha, size_t npix, float *raw, float *rel, sp_error *err);

#endif
