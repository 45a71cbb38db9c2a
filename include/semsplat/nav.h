/* semsplat nav: navigation on the splat. A 2D costmap with unknown space, a planner, k distinct
 * ranked trajectories with previews, exploration of a region in words, and scene descriptions.
 *
 * Costmap (sp_costmap): a grid in the world's xy plane (z up, metres; default 5 cm cells) built
 * from the splat alone:
 *   - the floor is detected (the heaviest band of flat, horizontal Gaussians below the cameras);
 *   - scans: every training view's rendered first-surface depth, views from one standpoint one
 *     scan; per voxel (cells x 10 cm slices of the robot's height band above the floor) the
 *     scans that hit it and that only saw through it;
 *   - occupied (occupancy): by default opacity-weighted Gaussian footprints (each Gaussian's xy
 *     marginal over its extent, not its centre) fused per voxel, evidence 1 - prod(1 - w_i) over
 *     a threshold, unless the scans saw through it (a floater); or the scans alone as log-odds;
 *     a cell when one of its voxels is;
 *   - free: every voxel of the column observed by some scan and none occupied, so space no
 *     camera saw stays UNKNOWN; pockets enclosed by obstacles are filled;
 *   - costs: Nav2's inflation (LETHAL 254 on obstacles, INSCRIBED 253 within the robot radius,
 *     252 exp(-cost_scaling_factor (d - r)) out to the inflation radius, NO_INFORMATION 255 for
 *     unknown), from an exact Euclidean distance transform.
 * Maps are exported exactly as Nav2's map_server reads them (PGM trinary: free 254, occupied 0,
 * unknown 205, YAML with origin at the lower-left pixel and free_thresh 0.19, below 205's 0.196,
 * so unknown is not read back as free) and read back through the YAML's own thresholds.
 *
 * Planner: 8-connected cost-aware A* on the inflated costmap (step cost = length x (w_euc +
 * w_trav (cost/252)^2), Nav2 Theta*'s form), then string pulling with line of sight that never
 * raises the cost: any-angle paths that never enter a lethal, inscribed or unknown cell. Goals:
 * a point, a pose, or a region (object footprints: reach a free cell within approach_m of one,
 * facing it). Paths are [x, y, z, yaw] waypoints in the world frame. k alternatives by the
 * penalty method: each accepted or tried route makes its corridor dearer, and a candidate is
 * kept only when it shares at most max_share of its length with every better one and is at
 * most max_length_ratio times the best's length; fewer are returned, with a note saying why,
 * when the map allows fewer.
 *
 * Scene (sp_nav): a model folder's splat, cameras and query engine with its costmap. Goals in
 * words resolve to the engine's instances; k trajectories are ranked by an itemized score
 * (length, minimum and mean clearance, localizability: the worst waypoint's rendered coverage by
 * well-observed Gaussians, semantic relevance: related concepts in view along the way), with
 * previews rendered from the splat and a top-down map drawn with Cairo. Exploration covers a
 * region in words with views, preferring poorly reconstructed ones, in a short tour.
 * Descriptions list the household objects near an anchor with distances and relations.
 * The scene is not thread safe (one per thread); plans it issued are kept under their ids.
 *
 * Ownership: sp_costmap and sp_path own their arrays (free with the *_free calls, which accept
 * zeroed structs). Functions return 0 or a negative SP_E_* code with err filled; outputs are
 * zeroed on error. Nothing here prints; progress goes through the sp_log passed in. */
#ifndef SEMSPLAT_NAV_H
#define SEMSPLAT_NAV_H

#include "semsplat/core.h"
#include "semsplat/render.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- costmap ---------------------------------------------------------------------------------- */

/* Occupancy layer values (the map_server / OccupancyGrid meaning, unknown stored as 255). */
enum { SP_CELL_FREE = 0, SP_CELL_OCCUPIED = 100, SP_CELL_UNKNOWN = 255 };

/* Cost layer values: nav2_costmap_2d's cost_values.hpp. */
enum {
    SP_COST_FREE = 0,
    SP_COST_MAX_NON_OBSTACLE = 252,
    SP_COST_INSCRIBED = 253,
    SP_COST_LETHAL = 254,
    SP_COST_UNKNOWN = 255
};

enum { SP_OCCUPANCY_FOOTPRINTS = 0, SP_OCCUPANCY_SCANS = 1 };

typedef struct sp_costmap_opts {
    float resolution_m;        /* cell edge (0.05) */
    float band_lo_m, band_hi_m;/* the robot's body, metres above the floor (0.05, 1.0); the
                                * bottom rises to twice the floor's roughness in the splat when
                                * that is higher (cm->band and cm->opts say what was used) */
    float floor_z;             /* world z of the floor; NAN = detect from the splat */
    float robot_radius_m;      /* inscribed radius (0.2) */
    float inflation_radius_m;  /* costs decay to 0 here (1.0) */
    float cost_scaling_factor; /* Nav2's exponential decay rate, 1/m (3.0: a smooth potential) */
    int keep_clear_of_unknown; /* cells within the robot radius of unknown are INSCRIBED (0, as
                                * Nav2's inflate_around_unknown: the path itself never enters unknown) */
    float min_opacity;         /* Gaussians fainter than this are ignored (0.15) */
    /* The training views as depth sensors: each view's rendered first-surface depth is a depth
     * image; views from one standpoint (centres within 0.1 m) are one scan. Per voxel (cell x
     * slice of the band) a scan hit it (a ray's surface ended there), saw through it (rays
     * crossed it, none ended there) or did not observe it. What makes a voxel occupied: */
    int occupancy;             /* SP_OCCUPANCY_FOOTPRINTS (default) or SP_OCCUPANCY_SCANS */
    /* SP_OCCUPANCY_FOOTPRINTS: opacity-weighted Gaussian footprints, 1 - prod(1 - w_i) >=
     * occupied_evidence, unless more than pass_veto x (1 + scans that hit it) scans saw through
     * it (a floater the cameras saw past); the splat's floor Gaussians count as floor seen */
    float footprint_sigmas;    /* footprints are evaluated out to this many std devs (3) */
    float occupied_evidence;   /* (0.9: against 0.5, known-cell agreement +4..+14 points and
                                * false free down on every trained and ideal splat measured,
                                * docs/DESIGN.md, issue 18's seventh round) */
    float pass_veto;           /* (1) */
    int veto_beside;           /* for a voxel some scan hit, a scan that saw through it but hit
                                * one of the 8 beside it (same slice) does not count as seeing
                                * through it: a rendered surface point (a Gaussian's depth) is
                                * good to about a cell, and rays pass beside a thin leg through
                                * the cell it stands in (1; 0: every such scan counts) */
    int lowest_needs_hit;      /* the lowest slice's footprints count only where some scan hit the
                                * voxel: a trained floor is a haze centimetres to decimetres thick
                                * whose rendered surface is the floor (1) */
    int hit_blocks_free;       /* a free column that is not occupied but has a voxel, from the
                                * first slice wholly above twice the floor tolerance (a hazy
                                * floor's rendered surface spreads past it), that this many scans
                                * hit and the veto above did not clear is unknown, and so are the
                                * free columns within hit_grow_tol floor tolerances of it unless
                                * it lies beside an obstacle or the capture stood there: a
                                * rendered surface too faint in the footprints (a trained table
                                * top of a few large translucent Gaussians), never seen past (1;
                                * 0 = off; footprints only) */
    float hit_grow_tol;        /* (2: the rendered floor's thickness, the floor tolerance, is this
                                * splat's error on rendered surfaces: an ideal splat's 0.05 m grows
                                * a surface by 0.1 m, a hazy trained one's 0.15 m by 0.3 m, where a
                                * table top's rendered edge lies decimetres inside the true one) */
    float faint_blocks_free;   /* a free column with footprint evidence at least this in a voxel
                                * from the same slice as hit_blocks_free's is unknown, and so are
                                * the free columns within faint_grow_tol floor tolerances of it,
                                * unless it lies beside an obstacle (whose footprint spills over):
                                * a thin surface the training views rendered faintly and saw
                                * through, held by a few faint Gaussians (the ideal splats have
                                * none over free floor) (0.1; 0 = off; footprints only) */
    float faint_grow_tol;      /* (1) */
    float hit_above_m;         /* surface points up to this far above the band's top are hits of
                                * its top slice: a trained splat renders a surface centimetres off
                                * the true one, and a desk top just under the band's top renders
                                * above it (0.05) */
    int unseen_unknown;        /* 1 (default): footprints in a voxel no scan observed make its
                                * column unknown, not occupied (nobody saw it: the inside of a wall
                                * or a cabinet, haze behind furniture), and cm->hidden marks it for
                                * the inflation, so the robot keeps clear of it as of an obstacle
                                * (measured: +3 to +5 points of agreement on the trained splats,
                                * the same false free and objects reached) */
    /* SP_OCCUPANCY_SCANS: the scans alone, fused as log-odds (OctoMap's sensor model) */
    float prob_hit;            /* P(occupied) from one scan's hit (0.7, OctoMap's) */
    float prob_miss;           /* P(occupied) from one scan seeing through (0.4, OctoMap's) */
    float occupied_prob;       /* a voxel is occupied at this fused probability (0.5) ... */
    int min_hit_scans;         /* ... with this many scans hitting it, or all that observed it
                                * when fewer did (2) */
    /* Free columns: no voxel occupied and every voxel observed by some scan (a ray passing above
     * a table top that no ray ended on does not make the table free), */
    int free_needs_floor;      /* ... and, with 1, the floor seen there (0) */
    int free_from_floor;       /* with 1 a column whose floor was seen and that some scan observed
                                * is free too (0: measured, it frees the undersides of tables) */
    int cameras_stand;         /* the robot radius under every training camera is free: the
                                * capture stood there (1; 0 for cameras held above furniture) */
    int despeckle_cells;       /* occupied specks of at most this many cells amid free space are
                                * floaters and become free (0 = keep everything) */
    float fill_max_area_m2;    /* free pockets enclosed by obstacles up to this area are the
                                * insides of furniture and become occupied (4) */
    float slice_m;             /* the band is fused in slices this tall (0.1; at most 32 slices) */
    int carve_downscale;       /* training views rendered at 1/this size for carving (0 = about
                                * 160 pixels wide) */
    float carve_min_fresh;     /* a view of a scan (shared centre) is carved only when this share
                                * of its directions (sampled every 8 px) is not shown by the views
                                * of its scan kept before it, most new first (0: every view that
                                * adds anything, which with the captures measured is all of them) */
    float carve_alpha;         /* first-surface depth: where the accumulated alpha reaches this
                                * (0.5); rays that never reach it end on nothing */
    float carve_stop_m;        /* carving stops this short of the surface hit (0.03) */
    int carve_discretize;      /* k: rays of one scan whose carved stretches end in one k x k
                                * part of a voxel's cell are traced once (OctoMap's discretized
                                * scan insertion, finer; 2; 0 = every ray, at most 4) */
    float floor_tolerance_m;   /* a rendered surface this close to the floor is the floor (at
                                * most 0.15: rendered depth is that of Gaussian centres, several
                                * cm off on a hazy trained floor seen at a slant) ... */
    int measure_floor_tolerance; /* ... and, with 1 (default), no more than the rendered floor's
                                * own thickness: the height from the floor within which 99 % of the
                                * rendered surface points in excess of the walls' and furniture's
                                * (counted 1-2 x the cap above the floor) lie; a sharp floor leaves
                                * a window sill or a low frame 5 cm up in the band, a hazy one keeps
                                * the cap (cm->opts says what was used) */
    float max_range_m;         /* rays longer than this are cut (8) */
    float margin_m;            /* map bounds: observed space plus this (0.5) */
    int max_cells;             /* largest nx or ny accepted (4096) */
} sp_costmap_opts;

sp_costmap_opts sp_costmap_opts_default(void);

/* A costmap. Cell (ix, iy) covers [origin + i res, origin + (i+1) res) in x and y; layers are
 * [ny][nx], row 0 at the origin's y (the OccupancyGrid layout; PGM rows are flipped on export).
 * Owns occ, cost, dist, seen. */
typedef struct sp_costmap {
    int nx, ny;
    float res;
    float origin[2];     /* world x, y of cell (0,0)'s lower-left corner */
    float floor_z;       /* world z of the floor (detected or given) */
    float band[2];       /* world z range of the robot's body: floor + band_lo .. floor + band_hi */
    uint8_t *occ;        /* SP_CELL_FREE / OCCUPIED / UNKNOWN */
    uint8_t *cost;       /* SP_COST_*: 0..252 inflation, 253 inscribed, 254 lethal, 255 unknown */
    float *dist;         /* metres from the cell centre to the nearest occupied (or hidden)
                          * cell's centre (INFINITY when there is none) */
    uint16_t *seen;      /* training-camera rays that crossed the cell's band, summed over its
                          * slices, plus those that ended on its floor (NULL for maps read from
                          * files): how well the capture observed it */
    uint8_t *hidden;     /* 1: an unknown cell where Gaussians stand that no training ray observed
                          * (unseen_unknown): inflated as an obstacle is, so the robot's body keeps
                          * clear of it; NULL when there are none (maps read from files) */
    sp_costmap_opts opts;/* the settings it was built or inflated with */
} sp_costmap;

/* Builds the costmap of a splat in a z-up world frame. cams: the training cameras (at least
 * one), rendered through r (any device) at 1/carve_downscale size for the free-space carving.
 * Fails with SP_E_NOTFOUND when no floor can be found, SP_E_ARG on bad options, SP_E_UNSUPPORTED
 * when the map would exceed max_cells. */
int sp_costmap_build(sp_costmap *cm, const sp_splat *s, const sp_camera *cams, size_t n_cams,
                     const sp_costmap_opts *opts, sp_raster *r, const sp_log *log, sp_error *err);
/* The same from a model folder (splat.ply and the capture train.json names), geometry only:
 * what a robot-side process (the simulated robot) loads. */
int sp_costmap_build_model(sp_costmap *cm, const char *model_dir, const sp_costmap_opts *opts,
                           sp_device *dev, const sp_log *log, sp_error *err);
void sp_costmap_free(sp_costmap *cm);
int sp_costmap_copy(sp_costmap *dst, const sp_costmap *src, sp_error *err);

/* Recomputes dist and cost from occ (and hidden) with opts (robot radius, inflation); opts NULL =
 * cm->opts. */
int sp_costmap_inflate(sp_costmap *cm, const sp_costmap_opts *opts, sp_error *err);

/* Writes <stem>.pgm (trinary: free 254, occupied 0, unknown 205) and yaml_path (image, mode
 * trinary, resolution, origin [x, y, 0], negate 0, occupied_thresh 0.65, free_thresh 0.19). */
int sp_costmap_write_map(const sp_costmap *cm, const char *yaml_path, sp_error *err);
/* Reads a map_server YAML and its image (PGM P5/P2 or PNG; relative paths against the YAML's
 * folder) with map_server's rules (trinary, scale and raw modes, negate, strict thresholds),
 * then inflates with opts (NULL = defaults). floor_z is 0 and band from opts. */
int sp_costmap_read_map(sp_costmap *cm, const char *yaml_path, const sp_costmap_opts *opts,
                        sp_error *err);

/* World point -> cell; returns 0 when inside the map, -1 outside (ix, iy still written). */
int sp_costmap_cell(const sp_costmap *cm, float x, float y, int *ix, int *iy);
/* Centre of cell (ix, iy) in world x, y. */
void sp_costmap_cell_center(const sp_costmap *cm, int ix, int iy, float xy[2]);
/* 1 when a robot centre may stand in the cell: known free and cost below INSCRIBED. */
int sp_costmap_traversable(const sp_costmap *cm, int ix, int iy);

/* As nav_msgs/OccupancyGrid data ([ny][nx] int8, row 0 at the origin): with use_costs 0 the
 * map (free 0, occupied 100, unknown -1); with 1 the inflated costs through Nav2's costmap
 * publisher table (0 -> 0, 1..252 -> 1 + 97 (c - 1) / 251, 253 -> 99, 254 -> 100, 255 -> -1). */
void sp_costmap_to_occupancy_grid(const sp_costmap *cm, int use_costs, int8_t *data);

/* Why a goal can or cannot be driven to (mirrors nav2_msgs ComputePathToPose error codes). */
typedef enum {
    SP_NAV_OK = 0,
    SP_NAV_START_OUTSIDE_MAP = 3,
    SP_NAV_GOAL_OUTSIDE_MAP = 4,
    SP_NAV_START_OCCUPIED = 5,
    SP_NAV_GOAL_OCCUPIED = 6, /* occupied, unknown, or within the robot radius of either */
    SP_NAV_TIMEOUT = 7,
    SP_NAV_NO_VALID_PATH = 8  /* both fine, but not connected through traversable cells */
} sp_nav_status;

const char *sp_nav_status_name(int status); /* "ok", "goal occupied", ... */

/* Is goal (world x, y) a traversable cell connected to start through traversable cells? The
 * start may lie within the robot radius of an obstacle (the robot is there), not on one or in
 * unknown space. Returns the status; why (may be NULL, cap bytes) gets a sentence. */
int sp_costmap_check_goal(const sp_costmap *cm, const float start[2], const float goal[2],
                          char *why, size_t cap);

/* Agreement with a ground-truth floor plan on the same grid (truth [ny][nx]: 1 occupied, 0 free;
 * e.g. sp_synth_floor_plan of the world in the same height band). */
typedef struct sp_costmap_agreement {
    long cells;            /* all cells */
    long known;            /* cells marked free or occupied */
    long agree;            /* known cells matching the truth */
    long truth_occupied;   /* truly occupied cells */
    long occupied_as_free; /* truly occupied, marked free: the unsafe error */
    long free_as_occupied; /* truly free, marked occupied */
    double agreement;      /* agree / known */
    double occupied_free_rate; /* occupied_as_free / truth_occupied */
    double known_fraction; /* known / cells */
} sp_costmap_agreement;

void sp_costmap_compare(const sp_costmap *cm, const uint8_t *truth, sp_costmap_agreement *out);

/* ---- planning --------------------------------------------------------------------------------- */

typedef enum { SP_GOAL_POINT = 0, SP_GOAL_POSE = 1, SP_GOAL_REGION = 2 } sp_goal_kind;

#define SP_NAV_MAX_BOXES 16

/* An axis-aligned footprint in the xy plane (an object's extent). */
typedef struct sp_nav_box {
    float min[2], max[2];
} sp_nav_box;

typedef struct sp_nav_goal {
    int kind;            /* sp_goal_kind */
    float xy[2];         /* POINT, POSE: the goal position */
    float yaw;           /* POSE: final heading (radians about +z from +x) */
    int n_boxes;         /* REGION: footprints; the path ends at a traversable cell within */
    sp_nav_box boxes[SP_NAV_MAX_BOXES]; /* approach_m of one of them, facing it */
    float approach_m;    /* REGION: (0.5) */
    float tolerance_m;   /* POINT, POSE: accept the nearest traversable cell this close (0) */
} sp_nav_goal;

/* Goal helpers: a point, a pose, and a region of one box. */
sp_nav_goal sp_nav_goal_point(float x, float y);
sp_nav_goal sp_nav_goal_pose(float x, float y, float yaw);
sp_nav_goal sp_nav_goal_box(const float min_xy[2], const float max_xy[2], float approach_m);

typedef struct sp_planner_opts {
    float w_euc, w_trav;       /* step cost weights (1, 2) */
    float waypoint_spacing_m;  /* waypoints along the path at most this far apart (0.25) */
    float z;                   /* waypoint z; NAN = the costmap's floor */
    long max_expansions;       /* A* budget (0 = the number of cells) */
    /* k alternatives */
    float max_share;           /* of a candidate's length near a better path (0.6) */
    float max_length_ratio;    /* to the best path's length (1.4) */
    float share_radius_m;      /* two paths share a stretch where they are this close (0.4) */
    float penalty;             /* corridor cost added per round, x the step cost (1.0) */
    float penalty_radius_m;    /* corridor half-width (0.5) */
    int max_rounds;            /* penalty replans per requested path (6) */
} sp_planner_opts;

sp_planner_opts sp_planner_opts_default(void);

/* A path. waypoints [n][4]: x, y, z, yaw (world; yaw along the path, the last one the goal's
 * heading). corners [n_corners][2]: the any-angle polyline the waypoints sample. */
typedef struct sp_path {
    int n;
    float *waypoints;
    int n_corners;
    float *corners;
    float length_m;
    float cost;          /* planner cost (w_euc x length + the cost terms) */
    int status;          /* sp_nav_status */
    double ms;           /* planning time */
} sp_path;

void sp_path_free(sp_path *p);
int sp_path_copy(sp_path *dst, const sp_path *src, sp_error *err);

/* start: x, y, yaw. Fails with SP_E_NOTFOUND (path->status says why, err names the cells)
 * when there is no path; SP_E_ARG on a bad goal. */
int sp_plan_path(const sp_costmap *cm, const float start[3], const sp_nav_goal *goal,
                 const sp_planner_opts *opts, sp_path *path, sp_error *err);

typedef struct sp_path_set {
    int n, requested;
    sp_path *paths;      /* [n], best (cheapest) first */
    float *share;        /* [n] largest share of length with a better path (0 for the first) */
    int rounds;          /* planner runs spent */
    char note[256];      /* why fewer than requested ("" when all were found) */
    double ms;           /* total planning time */
} sp_path_set;

void sp_path_set_free(sp_path_set *s);

/* Up to k distinct paths (penalty method, the rules above). Fails like sp_plan_path when not
 * even one exists. */
int sp_plan_k(const sp_costmap *cm, const float start[3], const sp_nav_goal *goal, int k,
              const sp_planner_opts *opts, sp_path_set *out, sp_error *err);

/* Fraction of a's length lying within radius_m of polyline b (corners or waypoints, [n][stride]
 * floats with x, y first). */
float sp_path_share(const float *a, int na, int stride_a, const float *b, int nb, int stride_b,
                    float radius_m);

/* Distance from the path's cells to the nearest occupied cell: minimum and length-weighted mean
 * over the waypoint polyline sampled at half a cell (metres). */
void sp_path_clearance(const sp_costmap *cm, const sp_path *p, float *min_m, float *mean_m);

/* ---- the navigation scene: a model folder's splat, semantics, cameras and costmap ------------- */

/* Weights of the ranking's terms (any scale; the total is their weighted mean). */
typedef struct sp_rank_weights {
    float length;          /* shortest / this path's length (0.35) */
    float clearance_min;   /* min(1, smallest clearance / clearance_ref_m) (0.20) */
    float clearance_mean;  /* min(1, mean clearance / (2 clearance_ref_m)) (0.10) */
    float localizability;  /* the worst waypoint's localizability, 0..1 (0.20) */
    float semantic;        /* related concepts seen along the way, relative to the best (0.15) */
} sp_rank_weights;

sp_rank_weights sp_rank_weights_default(void);

typedef struct sp_nav_opts {
    sp_costmap_opts costmap;
    sp_planner_opts planner;
    sp_rank_weights weights;
    int k;                     /* trajectories asked for by default (3) */
    float approach_m;          /* object goals end within this of the footprint (0.55) */
    float camera_height_m;     /* previews and localizability views, above the floor (0.8) */
    float camera_pitch_deg;    /* downward tilt of views along the path (10) */
    float preview_hfov_deg;    /* 70 */
    int preview_width, preview_height; /* 320 x 240 */
    int n_previews;            /* key waypoints per trajectory, the last at the goal (4) */
    float loc_spacing_m;       /* localizability is evaluated at waypoints this far apart (0.5) */
    int loc_width, loc_height; /* renders for localizability (64 x 48) */
    int loc_views_full;        /* training views that make a Gaussian fully covered (3) */
    float clearance_ref_m;     /* clearance worth a full score (0.5) */
    float min_confidence;      /* instances below this confidence are not found (0.25) */
    float near_m;              /* describe: objects this close to the anchor's footprint (1.5) */
    float region_margin_m;     /* a region in words extends this far around its objects (1.0) */
    int max_tour_poses;        /* explore: at most this many views (12) */
    float tour_coverage;       /* explore: stop once this share of the region is seen (0.9) */
    const char *vocabulary;    /* comma-separated household vocabulary; NULL = built in */
} sp_nav_opts;

sp_nav_opts sp_nav_opts_default(void);

typedef struct sp_nav sp_nav;
struct sp_query_engine;

/* Opens a model folder: splat.ply, its cameras (the capture of semantic.json or train.json),
 * the query engine when the folder has a semantic field, and builds the costmap (1 s or so on 2
 * cores for a house). dev is borrowed and must outlive the scene. */
int sp_nav_open(sp_nav **out, const char *model_dir, const sp_nav_opts *opts, sp_device *dev,
                const sp_log *log, sp_error *err);
/* The same from memory: engine (borrowed, may be NULL) supplies the splat and cameras, else
 * splat and cams (copied) do; no phrases without an engine. */
int sp_nav_create(sp_nav **out, struct sp_query_engine *engine, const sp_splat *splat,
                  const sp_camera *cams, size_t n_cams, const sp_nav_opts *opts, sp_device *dev,
                  const sp_log *log, sp_error *err);
void sp_nav_free(sp_nav *nav);
const sp_costmap *sp_nav_costmap(const sp_nav *nav);
const sp_nav_opts *sp_nav_options(const sp_nav *nav);
/* The default start: a training camera's position on the floor (snapped to the nearest
 * traversable cell within 2 m) and its heading, x, y, yaw: the first camera's unless another
 * stands in a larger connected free region (the one that reaches the most of the map). */
int sp_nav_default_start(const sp_nav *nav, float start[3], sp_error *err);

/* ---- targets in words ---- */

/* A phrase resolved into footprints: the query engine's instances (extent_min/max as the
 * footprint); a region word the engine does not find (kitchen, bedroom, ...) resolves through
 * the objects a household keeps there, and source says so. */
typedef struct sp_nav_instance {
    char label[48];        /* what it is: the phrase, or for a region the object found */
    float position[3];
    float z_min, z_max;
    sp_nav_box box;
    float confidence;
    float score;           /* the engine's weight of the instance (sp_query_instance.score): how
                            * much of the scene it is; comparable within one query */
} sp_nav_instance;

typedef struct sp_nav_target {
    char text[256];
    int found;
    float confidence;
    int n;
    sp_nav_instance inst[SP_NAV_MAX_BOXES];
    char source[256];  /* "query", or "region: kitchen = refrigerator, sink, stove found" */
} sp_nav_target;

int sp_nav_resolve(sp_nav *nav, const char *phrase, sp_nav_target *t, sp_error *err);

/* The region of the home a point is in, in words ("kitchen"; "" when none is near or the model
 * has no semantic field): each region's objects (as sp_nav_resolve finds the region's name) seed
 * the free cells inside their rectangle hull and beside them, and every other free cell takes the
 * region nearest on foot (4-connected over free cells, at most 5 m: past a doorway into a room
 * without such objects it stays none). Open plans split where the walks meet.
 * A point off free floor (inside furniture) takes the label of the nearest free cell within 1 m.
 * The regions are resolved once, on the first call. */
int sp_nav_region_of(sp_nav *nav, float x, float y, char *out, size_t cap, sp_error *err);

/* ---- k ranked trajectories with previews ---- */

typedef struct sp_nav_score {
    float length_m, clearance_min_m, clearance_mean_m, localizability, semantic; /* raw */
    float t_length, t_clearance_min, t_clearance_mean, t_localizability, t_semantic; /* 0..1 */
    float total;           /* weighted mean of the terms */
    int weakest_waypoint;  /* the least localizable waypoint */
} sp_nav_score;

typedef struct sp_nav_preview {
    int waypoint;          /* index into the path's waypoints */
    float distance_m;      /* along the path */
    float localizability;
    float pose[5];         /* camera x, y, z, yaw, pitch */
    int width, height;
    uint8_t *rgb;          /* [height][width][3] */
    char file[256];        /* written PNG (relative to the output folder), "" until written */
} sp_nav_preview;

typedef struct sp_nav_trajectory {
    char id[48];           /* "<plan id>.<rank>" */
    int rank;              /* 1 = best */
    sp_path path;
    sp_nav_score score;
    float *loc;            /* [path.n] localizability per waypoint, NAN where not evaluated */
    int n_previews;
    sp_nav_preview *previews;
    float share;           /* largest share of length with a better-planned route */
} sp_nav_trajectory;

typedef struct sp_nav_request {
    const float *start;    /* x, y, yaw; NULL = sp_nav_default_start */
    const char *to;        /* a phrase ("refrigerator"), or NULL for goal */
    sp_nav_goal goal;      /* used when to is NULL */
    int k;                 /* 0 = opts.k */
    int instance;          /* with to: -1 = any instance (the path picks), else its index */
    int previews;          /* 1 = render previews */
} sp_nav_request;

sp_nav_request sp_nav_request_default(void);

typedef struct sp_nav_plan {
    char id[32];           /* "plan-<n>", unique within the sp_nav */
    sp_nav_target target;  /* when the request had a phrase */
    sp_nav_goal goal;
    float start[3];
    int k, n;
    sp_nav_trajectory *traj; /* [n] by rank */
    int n_related;
    char related[8][64];   /* concepts behind the semantic term, found ones first */
    int related_found[8];
    char note[320];        /* why fewer than k, or "" */
    double ms_plan, ms_rank, ms_previews;
} sp_nav_plan;

int sp_nav_plan_request(sp_nav *nav, const sp_nav_request *req, sp_nav_plan *out, sp_error *err);
void sp_nav_plan_free(sp_nav_plan *p);
/* Writes out_dir/plan.json (every trajectory's waypoints, score terms, previews), map.pgm +
 * map.yaml (Nav2 map_server), map.png (top-down: costmap, objects found, start, ranked paths,
 * legend) and previews/ (views and one contact sheet per trajectory). Drawing needs Cairo:
 * without it map.png and the sheets are skipped and the JSON says so. */
int sp_nav_plan_write(sp_nav *nav, sp_nav_plan *p, const char *out_dir, sp_error *err);
/* plan.json's text (malloc'd). */
char *sp_nav_plan_json(const sp_nav *nav, const sp_nav_plan *p);
/* A plan issued by this scene, by trajectory id ("plan-3.1"); NULL when unknown. The agent's
 * commitments go through this: a goal is a trajectory this scene planned. */
const sp_path *sp_nav_lookup(const sp_nav *nav, const char *trajectory_id);

/* ---- exploration ---- */

typedef struct sp_nav_tour {
    sp_nav_target target;
    sp_nav_box area;       /* the region explored */
    int n;
    float *poses;          /* [n][4] x, y, z, yaw in visiting order */
    float *quality;        /* [n] how well the splat reconstructs each view (0..1: low = poor) */
    float *gain;           /* [n] share of the region first seen from this pose */
    float coverage;        /* share of the region's cells the tour sees */
    sp_path path;          /* start -> every pose, as one path */
    int n_previews;
    sp_nav_preview *previews; /* one per pose */
    char note[256];
} sp_nav_tour;

/* Views covering a region in words, preferring poses the splat reconstructs poorly, ordered into
 * a short tour from start (NULL = default). */
int sp_nav_explore(sp_nav *nav, const char *region, const float *start, sp_nav_tour *out,
                   sp_error *err);
void sp_nav_tour_free(sp_nav_tour *t);
/* out_dir/tour.json, map.png, previews/. */
int sp_nav_tour_write(sp_nav *nav, sp_nav_tour *t, const char *out_dir, sp_error *err);
char *sp_nav_tour_json(const sp_nav_tour *t);

/* ---- scene descriptions ---- */

typedef struct sp_nav_object {
    char name[64];         /* vocabulary term */
    sp_nav_instance inst;
    float distance_m;      /* footprint to the anchor's footprint */
    int left;              /* as seen from the robot: 1 left of the anchor, -1 right, 0 in line */
    int front;             /* 1 nearer the robot than the anchor, -1 behind it, 0 beside */
    char region[32];       /* "kitchen", "" when none */
} sp_nav_object;

typedef struct sp_nav_description {
    sp_nav_target anchor;
    char anchor_region[32];
    float robot[3];        /* the viewpoint of left / right */
    int n;
    sp_nav_object *objects; /* nearest first */
    int n_queried;         /* vocabulary terms asked */
    int n_walled_off;      /* instances within the radius but far on foot: behind a wall (left out) */
    char *sentence;        /* malloc'd plain-language answer */
} sp_nav_description;

/* "What objects are near the dining table?": every vocabulary term's confident instances within
 * radius_m (<= 0: opts.near_m) of the anchor's footprint and not behind a wall from it, with
 * distances and relations. */
int sp_nav_describe(sp_nav *nav, const char *anchor, float radius_m, const float *robot,
                    sp_nav_description *out, sp_error *err);
/* The same around one instance of an anchor the caller resolved (sp_nav_resolve): instance is its
 * index in anchor->inst (the one a user chose among several); out->anchor is a copy with that
 * instance first. */
int sp_nav_describe_target(sp_nav *nav, const sp_nav_target *anchor, int instance, float radius_m,
                           const float *robot, sp_nav_description *out, sp_error *err);
void sp_nav_description_free(sp_nav_description *d);
char *sp_nav_description_json(const sp_nav_description *d);

/* The built-in household vocabulary (COCO's 80 classes and common household objects), n terms. */
const char *const *sp_nav_vocabulary(int *n);
/* COCO 2017's 80 detection class names (Lin et al. 2014): the vocabulary's first n terms. */
const char *const *sp_nav_coco_classes(int *n);

#ifdef __cplusplus
}
#endif
#endif
