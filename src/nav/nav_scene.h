/* Private to src/nav: the navigation scene (sp_nav) and the stages built on it: resolving
 * phrases, rendering views from poses, ranking, the built-in word tables, and drawing. */
#ifndef SP_NAV_SCENE_H
#define SP_NAV_SCENE_H

#include "nav_internal.h"
#include "semsplat/semantic.h"

typedef struct nav_issued {
    char id[48];
    sp_path path;
} nav_issued;

struct sp_nav {
    sp_nav_opts opts;
    sp_device *dev;
    sp_log log;
    int has_log;
    sp_query_engine *engine;  /* may be NULL: geometry only */
    int own_engine;
    sp_splat own_splat;       /* the splat when there is no engine */
    const sp_splat *splat;    /* the engine's or own_splat */
    sp_camera *cams;          /* copies, pinhole */
    size_t n_cams;
    sp_costmap cm;
    uint16_t *view_counts;    /* [n Gaussians] training views that see each */
    sp_raster *raster;        /* renders (scratch) */
    sp_scene *scene_rgb;      /* the splat's colours, for previews */
    sp_scene *scene_aux;      /* coverage and relevance channels */
    sp_splat aux;             /* the splat's geometry with features [n][2]: coverage, relevance */
    int plan_seq;
    nav_issued *issued;
    int n_issued, cap_issued;
    uint8_t *region_label;    /* [cells] region index per free cell, 255 = none (sp_nav_region_of) */
    int regions_built;
    char vocab_buf[4096];     /* opts.vocabulary, split */
    const char *vocab[512];
    int n_vocab;
};

static inline const sp_log *nav_log(const sp_nav *nav) { return nav->has_log ? &nav->log : NULL; }

/* A pinhole camera at pos (world) looking along yaw (about +z from +x) and pitch (up positive)
 * with a horizontal field of view (core's sp_camera_intrinsics_fov + sp_camera_from_pose). */
void nav_pose_camera(sp_camera *cam, int width, int height, float hfov_rad, const float pos[3],
                     float yaw, float pitch);

/* Renders the aux channels from a pose: mean coverage (localizability) and mean relevance. */
int nav_view_scores(sp_nav *nav, const float pos[3], float yaw, float pitch, float *loc,
                    float *relevance, sp_error *err);
/* Renders RGB (uint8) from a pose into pv (allocates pv->rgb). */
int nav_render_preview(sp_nav *nav, const float pos[3], float yaw, float pitch, sp_nav_preview *pv,
                       sp_error *err);
/* Sets the aux relevance channel for some found targets: the engine's per-Gaussian relevancy of
 * their texts, or (no engine) their instances' 3D boxes. */
int nav_set_relevance(sp_nav *nav, const sp_nav_target *targets, int n, sp_error *err);

/* Word tables (vocab.c). */
int nav_region_index(const char *text);       /* region named in text, -1 */
const char *nav_region_name(int r);
int nav_region_objects(int r, const char *const **objects);
int nav_region_of_object(const char *object); /* the region that keeps this object, -1 */
int nav_n_regions(void);
int nav_related_concepts(const char *goal, char out[][64], int cap);

/* The free cells where one stands beside footprint b: within 1.5 cells of the nearest free
 * cell's distance (returned) and inside the window [x0..x1] x [y0..y1] (1 m around b). */
float nav_nearest_free(const sp_costmap *cm, const sp_nav_box *b, int *x0, int *y0, int *x1, int *y1);

/* Remembers a trajectory under its id (copies the path). */
int nav_issue(sp_nav *nav, const char *id, const sp_path *path, sp_error *err);

/* Ranking and previews of a plan's trajectories (rank.c). */
int nav_rank(sp_nav *nav, sp_nav_plan *p, sp_error *err);
int nav_make_previews(sp_nav *nav, sp_nav_trajectory *t, const sp_nav_target *target, sp_error *err);
void nav_preview_free(sp_nav_preview *pv);

/* JSON helpers shared by plan, tour and description output (output.c). */
struct cJSON;
struct cJSON *nav_json_target(const sp_nav_target *t);
struct cJSON *nav_json_floats(const float *v, int n);
int nav_write_previews(sp_nav_preview *pv, int n, const char *out_dir, const char *stem,
                       sp_error *err);

/* Drawing (cairo/draw.c; nocairo/draw.c when Cairo is missing). */
typedef struct nav_map_layers {
    const sp_costmap *cm;
    const char *title;
    const float *start;                 /* x, y, yaw or NULL */
    int n_paths;
    const sp_path *const *paths;
    const char (*path_labels)[128];
    int n_objects;
    const sp_nav_box *boxes;
    const char (*object_labels)[64];
    const int *object_is_target;
    int n_poses;                        /* tour poses, numbered */
    const float *poses;                 /* [n][4] */
    const sp_nav_box *area;             /* a highlighted region, or NULL */
} nav_map_layers;

int nav_draw_available(const char **why);
int nav_draw_map(const nav_map_layers *layers, const char *png_path, sp_error *err);
int nav_draw_sheet(const char *title, const sp_nav_preview *pv, int n, const char *png_path,
                   sp_error *err);

#endif
