/* semsplat synth: renders Gazebo-style SDF worlds into captures with exact ground truth.
 *
 * sp_synth_load_world reads an SDF 1.6+ world (models, nested models, links, visuals, poses with
 * relative_to, model:// includes through a model path, box/cylinder/sphere/plane/mesh geometry,
 * materials, lights) into one flat triangle soup in world coordinates (sp_world). Every top-level
 * model is one labelled instance; its class is the included model's name (else its own), with
 * vendor tokens, variant suffixes and trailing _<number> removed ("dining_chair_2" -> "dining
 * chair", "aws_robomaker_retail_BookshelfB_01" -> "bookshelf").
 * sp_synth_render rasterizes one pinhole view on the CPU (z-buffer, supersampling, textures,
 * procedural surface detail, Lambert + ambient) into RGB, metric depth and instance labels.
 * sp_synth_capture plans robot-like views and writes a COLMAP capture (sparse/0, images, depth,
 * labels, labels.json, ground_truth.json).
 * Ownership: sp_world and sp_synth_frame own their buffers; free them with the *_free calls. */
#ifndef SEMSPLAT_SYNTH_H
#define SEMSPLAT_SYNTH_H

#include "semsplat/core.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Procedural surface detail for untextured surfaces, chosen from the material's script name
 * (Gazebo/Wood, .../WoodFloor, .../Tiles, .../Carpet, .../Bricks) or the visual's names. */
typedef enum {
    SP_PATTERN_PLASTER = 0, /* low-amplitude mottled noise: walls, plastic, paint */
    SP_PATTERN_WOOD,        /* growth rings along the longest axis */
    SP_PATTERN_PLANKS,      /* wooden floor boards */
    SP_PATTERN_TILES,       /* square tiles with grout */
    SP_PATTERN_FABRIC,      /* woven cloth */
    SP_PATTERN_CARPET,      /* fine fibre noise */
    SP_PATTERN_BRICKS,
    SP_PATTERN_METAL,       /* brushed streaks */
    SP_PATTERN_GLASS,       /* smooth, slight gradient (windows, screens) */
    SP_PATTERN_COUNT
} sp_pattern;

#define SP_SYNTH_MAX_MIP 16

typedef struct sp_synth_texture {
    char path[512];
    int width, height;
    uint8_t *rgb; /* [height][width][3], row 0 = top of the image */
    /* mip pyramid for minification (level 0 is rgb; each next level halves by a 2x2 box filter) */
    int n_levels;
    int level_w[SP_SYNTH_MAX_MIP], level_h[SP_SYNTH_MAX_MIP];
    uint8_t *level[SP_SYNTH_MAX_MIP];
} sp_synth_texture;

typedef struct sp_synth_material {
    float diffuse[3]; /* albedo in [0,1] (multiplies the texture when there is one) */
    float ambient[3];
    float emissive[3];
    int texture;      /* index into sp_world.textures, -1 = none */
    int pattern;      /* sp_pattern, used when texture < 0 */
} sp_synth_material;

typedef enum { SP_LIGHT_DIRECTIONAL = 0, SP_LIGHT_POINT = 1, SP_LIGHT_SPOT = 2 } sp_light_type;

typedef struct sp_synth_light {
    char name[128];
    int type;
    float position[3];  /* world (point, spot) */
    float direction[3]; /* world, unit, direction the light travels (directional, spot) */
    float diffuse[3];
    float att_constant, att_linear, att_quadratic, range;
    float spot_cos_inner, spot_cos_outer, spot_falloff; /* spot cone (cosines of the half angles) */
} sp_synth_light;

/* One labelled instance (a top-level model). Label id in label images = index + 1. */
typedef struct sp_synth_object {
    char name[128];       /* model name in the world, e.g. "dining_chair_2" */
    char source[256];     /* model it was included from ("dining_chair"), else its own name */
    char class_name[128]; /* "dining chair" */
    int is_structure;     /* walls, floors, ceilings, ground (sp_synth_is_structure): labelled,
                           * listed under "structure" in ground_truth.json, not an object */
    float pose[16];       /* model frame in world, row-major 4x4 */
    float aabb_min[3], aabb_max[3]; /* world-frame box of its visual triangles */
    size_t n_triangles;
    int sdf_line;         /* line of its <model>/<include> in the world file */
} sp_synth_object;

/* A run of triangles of one visual, for frustum culling. */
typedef struct sp_synth_chunk {
    size_t tri_begin, tri_end;
    float aabb_min[3], aabb_max[3];
} sp_synth_chunk;

/* A world as a triangle soup in world coordinates (metres, z up).
 *   positions [n_vertices][3]  world
 *   normals   [n_vertices][3]  world, unit (flat for primitives, smooth for meshes)
 *   uvs       [n_vertices][2]  texture coordinates (v = 0 at the image bottom, OpenGL style)
 *   pattern   [n_vertices][3]  object-local coordinates for procedural detail (metres)
 *   tris      [n_triangles][3] vertex indices
 *   tri_material, tri_object [n_triangles]  material index, object index (label - 1) */
typedef struct sp_world {
    char path[1024];
    char name[128];
    size_t n_vertices, n_triangles;
    float *positions, *normals, *uvs, *pattern;
    uint32_t *tris;
    uint16_t *tri_material, *tri_object;
    uint8_t *tri_axis; /* dominant axis of the pattern-space normal, for 2D patterns */
    size_t n_materials, n_textures, n_objects, n_lights, n_chunks;
    sp_synth_material *materials;
    sp_synth_texture *textures;
    sp_synth_object *objects;
    sp_synth_light *lights; /* a default light is added when the world has none */
    sp_synth_chunk *chunks;
    float ambient[3];       /* <scene><ambient> */
    float background[3];    /* <scene><background> */
    float exposure;         /* scales lighting so a typical surface is well exposed (set at load) */
    size_t n_missing;       /* models and meshes skipped under skip_missing */
    size_t n_missing_textures; /* textures not found: their meshes are drawn in the material
                                * colour with a warning, as Gazebo does (never an error) */
} sp_world;

typedef struct sp_synth_load_opts {
    const char *model_path; /* extra model dirs, ':'-separated (may be NULL) */
    int skip_missing;       /* warn and continue on a missing model or mesh (a missing texture
                             * is always a warning) */
    int no_env;             /* ignore GAZEBO_MODEL_PATH / GZ_SIM_RESOURCE_PATH (tests) */
    const sp_log *log;
} sp_synth_load_opts;

/* Loads an SDF world (or a single-model .sdf). The model path is <dir>/<stem>_models (the world's
 * own models, e.g. house_models beside house.world), opts->model_path, GAZEBO_MODEL_PATH,
 * GZ_SIM_RESOURCE_PATH and IGN_GAZEBO_RESOURCE_PATH, then <dir>/models and <dir>/../models. Errors name the file and line (malformed
 * XML, bad numbers), the missing model:// and the dirs searched, or the missing mesh. */
int sp_synth_load_world(const char *path, const sp_synth_load_opts *opts, sp_world *w,
                        sp_error *err);
void sp_world_free(sp_world *w);

/* Class from a model name: vendor tokens (aws, robomaker, retail, residential, ...) dropped,
 * CamelCase split, trailing _<number> and variant letters removed, '_' read as a space,
 * lower case: "aws_robomaker_retail_BookshelfB_01" -> "bookshelf", "dining_chair_2" -> "dining
 * chair". */
void sp_synth_class_name(const char *model_name, char *out, size_t cap);
/* 1 when a top-level model is structure (walls, floors, ceilings, the ground): the last word of
 * its class, or of the class read from its instance name, is wall(s), floor(s), flooring,
 * ceiling(s) or ground, or the class ends in "ground plane" / "floor plane". Words before the
 * last only modify it: "shop wall" is structure, "floor lamp", "wall clock" and "ceiling fan" are
 * objects. */
int sp_synth_is_structure(const char *model_name, const char *class_name);

/* ---- rendering ------------------------------------------------------------------------------- */

typedef struct sp_synth_render_opts {
    int supersample; /* samples per pixel along each axis (1..4); 0 = 4 */
    int no_detail;   /* 1 = flat material colours (no procedural detail, no textures) */
    float psf_px;    /* camera blur: Gaussian sigma in pixels applied to the colour image after
                        the per-pixel box integration (lens and sensor); 0 = 0.5, < 0 = none */
} sp_synth_render_opts;

/* One rendered view.
 *   rgb    [height][width][3] linear-ish display colours in [0,1]
 *   depth  [height][width] metres along the optical axis (camera z), 0 where nothing was hit
 *   labels [height][width] object index + 1, 0 = background
 * Depth and label of a pixel come from the surface covering most of its samples, evaluated at
 * the pixel centre, so they are exact away from edges. */
typedef struct sp_synth_frame {
    int width, height;
    float *rgb;
    float *depth;
    uint16_t *labels;
} sp_synth_frame;

/* Renders cam (pinhole, distortion ignored) into out (allocated here when out->rgb is NULL,
 * else reused; sizes must match). pool may be NULL. Bytes are independent of the pool size. */
int sp_synth_render(const sp_world *w, const sp_camera *cam, const sp_synth_render_opts *opts,
                    sp_pool *pool, sp_synth_frame *out, sp_error *err);
void sp_synth_frame_free(sp_synth_frame *f);

/* ---- captures -------------------------------------------------------------------------------- */

/* How a capture's views are chosen (recorded in capture.json as "plan"). */
typedef enum {
    SP_SYNTH_PLAN_MIXED = 0, /* "walk+objects": spins at waypoints over the free floor (about 70%)
                                and short arcs of views aimed at the world's objects (30%) */
    SP_SYNTH_PLAN_WALK = 1,  /* "walk": the spins only; no view is aimed at a ground-truth object,
                                so what is measured on it does not lean on the world's labels */
    SP_SYNTH_PLAN_DRIVE = 2  /* "drive": one continuous robot drive through every reachable room,
                                frames at a camera's rate (see drive_* below) */
} sp_synth_plan_kind;

typedef struct sp_synth_capture_opts {
    int n_views;        /* total views (walk + object views); for a drive, at most this many
                           frames are kept (every k-th frame of the drive, k as small as fits) */
    int width, height;
    float fov_deg;      /* horizontal field of view; 0 = 70 */
    float min_height_m, max_height_m; /* camera heights above the floor; 0,0 = 0.3, 1.5 */
    int supersample;    /* 0 = 4 */
    float psf_px;       /* camera blur sigma in pixels (sp_synth_render_opts); 0 = 0.5, < 0 = none */
    int n_points;       /* points3D sampled on visible surfaces; 0 = 30000 */
    unsigned seed;      /* view planning and point sampling */
    int n_threads;      /* 0: all CPUs (negative: an error) */
    const sp_log *log;  /* progress and warnings (may be NULL) */
    int plan;           /* sp_synth_plan_kind */
    /* The drive (SP_SYNTH_PLAN_DRIVE): a differential-drive robot with its camera at a fixed
     * height (the middle of min/max_height_m) looking ahead 0.1 rad down. It visits waypoints
     * spread over the reachable free floor in a nearest-neighbour tour, on the shortest paths
     * that keep a robot's clearance, steering smoothly towards the path 0.6 m ahead (turning at
     * most drive_turn_rad_s, on the spot when more than 45 degrees off). No spins on the spot:
     * a camera turning in front of a blank wall breaks structure-from-motion's chain of views. */
    float drive_speed_mps; /* 0 = 0.4 */
    float drive_turn_rad_s;/* 0 = 0.5 */
    float drive_rate_hz;   /* camera frame rate; 0 = 10 */
} sp_synth_capture_opts;

/* What a plan made, for capture.json and the reports. */
typedef struct sp_synth_plan_info {
    int plan;                 /* sp_synth_plan_kind; drives on a world without floor orbit */
    const char *name;         /* "walk+objects", "walk", "drive", "orbit" (static string) */
    size_t n_views;
    /* drives only (0 otherwise) */
    size_t n_frames_driven;   /* frames at drive_rate_hz before keeping every keep_every-th */
    int keep_every;
    double rate_hz;           /* drive_rate_hz / keep_every */
    double speed_mps, turn_rad_s, camera_height_m;
    double path_length_m, duration_s;
    int n_waypoints, n_segments; /* segments > 1: parts of the floor no path joins (teleports) */
    double reachable_fraction;   /* free floor cells the drive could reach */
    double max_step_m, max_turn_rad; /* largest baseline and rotation between kept frames */
    double *t_s;              /* [n_views] time of each kept frame (owned; sp_synth_plan_info_free) */
} sp_synth_plan_info;

void sp_synth_plan_info_free(sp_synth_plan_info *info);

/* Plans the views of opts->plan: a walk over the free floor of every room (heights between min
 * and max, looking around), then (SP_SYNTH_PLAN_MIXED) views around objects; or the drive.
 * cams is malloc'd [*n]; caller frees with free(). A world without floor gets an orbit. */
int sp_synth_plan_views(const sp_world *w, const sp_synth_capture_opts *opts, sp_camera **cams,
                        size_t *n, sp_error *err);
/* The same, and what the plan made (info may be NULL; free it with sp_synth_plan_info_free). */
int sp_synth_plan(const sp_world *w, const sp_synth_capture_opts *opts, sp_camera **cams,
                  size_t *n, sp_synth_plan_info *info, sp_error *err);

/* Renders the planned views and writes under out_dir:
 *   sparse/0/{cameras,images,points3D}.bin  PINHOLE, exact poses, points on visible surfaces
 *   images/NNNNN.png  depth/NNNNN.npy (float32 metres [h][w])  labels/NNNNN.png (16-bit ids)
 *   labels.json  (id -> model name, class, is_structure)
 *   ground_truth.json  (world path; each object's name, class, world pose and AABB under
 *                       "objects", walls, floors, ceilings and the ground under "structure")
 *   frame.json  (source "synth": the model frame is the world frame; see sp_frame in io.h)
 *   capture.json  (the plan used and its settings: sp_synth_plan_info; a drive's frame times) */
int sp_synth_capture(const sp_world *w, const char *out_dir, const sp_synth_capture_opts *opts,
                     sp_error *err);

/* ---- ground truth for navigation ------------------------------------------------------------ */

/* Ground-truth occupancy of the world between heights z_lo and z_hi (world z) on a grid of nx x ny
 * cells of res metres whose cell (0,0) has its lower-left corner at origin (row 0 at the origin's
 * y): occ[iy * nx + ix] = 1 when any triangle, clipped to the band, overlaps the cell's interior
 * (touching its border does not count), else 0. */
int sp_synth_floor_plan(const sp_world *w, float z_lo, float z_hi, float res, const float origin[2],
                        int nx, int ny, uint8_t *occ, sp_error *err);

#ifdef __cplusplus
}
#endif
#endif
