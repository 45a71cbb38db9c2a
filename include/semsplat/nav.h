/* semsplat nav: navigation on the splat. A 2D costmap with unknown space, a planner, k distinct
 * ranked trajectories with previews, exploration of a region in words, and scene descriptions.
 *
 * Costmap (sp_costmap): a grid in the world's xy plane (z up, metres; default 5 cm cells) built
 * from the splat alone:
 *   - the floor is detected (the heaviest band of flat, horizontal Gaussians below the cameras);
 *   - occupied: opacity-weighted Gaussian footprints (the 1.5-sigma ellipse of each Gaussian's
 *     xy marginal, not its centre), w_i = opacity x the share of its vertical mass inside the
 *     robot's height band above the floor; a cell is occupied when 1 - prod(1 - w_i) over the
 *     footprints that meet it reaches a threshold (0.5);
 *   - free: carved along the training cameras' rays to their rendered depth, where the ray passes
 *     through the height band (or ends on the floor), so space no camera saw stays UNKNOWN;
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

typedef struct sp_costmap_opts {
    float resolution_m;        /* cell edge (0.05) */
    float band_lo_m, band_hi_m;/* the robot's body, metres above the floor (0.05, 1.0) */
    float floor_z;             /* world z of the floor; NAN = detect from the splat */
    float robot_radius_m;      /* inscribed radius (0.2) */
    float inflation_radius_m;  /* costs decay to 0 here (1.0) */
    float cost_scaling_factor; /* Nav2's exponential decay rate, 1/m (3.0: a smooth potential) */
    int keep_clear_of_unknown; /* cells within the robot radius of unknown are INSCRIBED (1) */
    float min_opacity;         /* Gaussians fainter than this are ignored (0.15) */
    float footprint_sigmas;    /* footprint = the xy ellipse at this many std devs (1.5) */
    float occupied_evidence;   /* a cell is occupied when 1 - prod(1 - w_i) >= this (0.5) */
    int carve_downscale;       /* training views rendered at 1/this size for carving (4) */
    float carve_alpha;         /* rays with less accumulated alpha hit nothing: not carved (0.5) */
    float carve_stop_m;        /* carving stops this short of the surface hit (0.1) */
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
    float *dist;         /* metres from the cell centre to the nearest occupied cell's centre
                          * (INFINITY when there is none) */
    uint16_t *seen;      /* training-camera rays that carved the cell (NULL for maps read from
                          * files): how well the capture observed it */
    sp_costmap_opts opts;/* the settings it was built or inflated with */
} sp_costmap;

/* Builds the costmap of a splat in a z-up world frame. cams: the training cameras (at least
 * one), rendered through r (any device) at 1/carve_downscale size for the free-space carving.
 * Fails with SP_E_NOTFOUND when no floor can be found, SP_E_ARG on bad options, SP_E_UNSUPPORTED
 * when the map would exceed max_cells. */
int sp_costmap_build(sp_costmap *cm, const sp_splat *s, const sp_camera *cams, size_t n_cams,
                     const sp_costmap_opts *opts, sp_raster *r, const sp_log *log, sp_error *err);
void sp_costmap_free(sp_costmap *cm);
int sp_costmap_copy(sp_costmap *dst, const sp_costmap *src, sp_error *err);

/* Recomputes dist and cost from occ with opts (robot radius, inflation); opts NULL = cm->opts. */
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

#ifdef __cplusplus
}
#endif
#endif
