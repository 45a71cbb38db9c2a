/* Private helpers of the nav module: grid indexing, the distance transform, the free-space
 * carving pass, segment traversal and the planner's cost terms. */
#ifndef SP_NAV_INTERNAL_H
#define SP_NAV_INTERNAL_H

#include <math.h>
#include <stdint.h>
#include <time.h>

#include "semsplat/nav.h"

static inline int nav_inside(const sp_costmap *cm, int ix, int iy)
{
    return ix >= 0 && iy >= 0 && ix < cm->nx && iy < cm->ny;
}
static inline long nav_idx(const sp_costmap *cm, int ix, int iy) { return (long)iy * cm->nx + ix; }

#define NAV_MAX_SLICES 32

/* The height band is split into n_slices slices of (band height / n_slices); voxel (slice v,
 * cell i) is index v * cells + i. */
typedef struct nav_slices {
    int n;
    float z0, dz;          /* world z of slice 0's bottom, slice height */
    long cells;            /* nx * ny */
} nav_slices;

static inline int nav_slice_of(const nav_slices *sl, float z)
{
    int v = (int)floorf((z - sl->z0) / sl->dz);
    return v < 0 ? 0 : v >= sl->n ? sl->n - 1 : v;
}

/* What the carving renders measure, per voxel and per Gaussian (saturating counts). */
typedef struct nav_carve_out {
    nav_slices sl;
    uint16_t *hit_scans;     /* [slices][cells] scans with a surface point in the voxel */
    uint16_t *miss_scans;    /* [slices][cells] scans whose rays crossed it, none ending there */
    uint16_t *near_scans;    /* [slices][cells] of those, the scans that hit a voxel beside it (the
                              * 8 around it in its slice): a rendered surface point is good to about
                              * a cell, so such a scan may have seen this voxel's surface */
    uint16_t *floor_scans;   /* [cells] scans with a surface point on the floor there */
    uint16_t *view_counts;   /* [n Gaussians] training views that see each Gaussian, or NULL */
    float floor_tol;         /* out: the floor tolerance the scans used (measure_floor_tolerance) */
} nav_carve_out;

#define NAV_FLOOR_MIN_OPACITY 0.5f /* floor Gaussians at least this opaque */

/* Footprint evidence (footprints.c): adds log(1 - w) per voxel (log_free [slices][cells]) over
 * the band Gaussians' footprints, on the pool's threads (SP_E_NOMEM: out of memory); nav_mark_floor bumps floor_seen [cells] under the splat's own
 * floor Gaussians. */
int nav_footprints(sp_pool *pool, const sp_costmap *cm, const sp_splat *s, const sp_costmap_opts *o,
                   const nav_slices *sl, float *log_free);
void nav_mark_floor(const sp_costmap *cm, const sp_splat *s, const sp_costmap_opts *o, uint16_t *floor_seen);

/* Process CPU time in seconds (all threads): what the build costs on a shared machine. */
static inline double nav_cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Renders for carving are about this wide when carve_downscale is 0 (auto). */
#define NAV_CARVE_WIDTH 160

static inline int nav_carve_downscale(const sp_costmap_opts *o, const sp_camera *cam)
{
    if (o->carve_downscale > 0) return o->carve_downscale;
    int d = (int)lroundf((float)cam->width / NAV_CARVE_WIDTH);
    return d < 1 ? 1 : d;
}

/* Traces the training views' rendered first-surface depth into out (the grid of cm and out->sl
 * must be set up, the counters zeroed): per voxel the scans that hit it and that only saw
 * through it, per cell the scans that saw its floor, and (when out->view_counts is not NULL) per
 * Gaussian the views in which it is visible. */
int nav_carve(const sp_costmap *cm, const sp_splat *s, const sp_camera *cams, size_t n_cams,
              const sp_costmap_opts *o, sp_raster *r, nav_carve_out *out, const sp_log *log,
              sp_error *err);

/* The costmap build with the carving outputs exposed (view_counts may be NULL). */
int nav_costmap_build(sp_costmap *cm, const sp_splat *s, const sp_camera *cams, size_t n_cams,
                      const sp_costmap_opts *opts, sp_raster *r, uint16_t *view_counts,
                      const sp_log *log, sp_error *err);

/* The default start: the training cameras' positions on the floor (snapped to the nearest
 * traversable cell within NAV_START_SNAP_M), the one in the largest traversable region (the
 * earliest camera among equals, so the first camera's when the free space is one piece), with
 * that camera's heading: x, y, yaw. */
#define NAV_START_SNAP_M 2.0f
int nav_pick_start(const sp_costmap *cm, const sp_camera *cams, size_t n_cams, float start[3], sp_error *err);

/* Cost-term of a cell for the planner: (cost/252)^2 (Nav2 Theta*'s traversal term). */
static inline float nav_cost_term(uint8_t c)
{
    float q = (float)c / 252.0f;
    return q * q;
}

/* Calls fn(ctx, cell, t0, t1) for every cell of the map the segment a -> b (world xy) passes
 * through, in order, with the segment's parameter interval inside it (t in [0, 1]); at an exact
 * corner crossing both side cells are visited (with an empty interval). Stops early when fn
 * returns nonzero and returns that value. */
typedef int (*nav_cell_fn)(void *ctx, long cell, float t0, float t1);
int nav_traverse(const sp_costmap *cm, const float a[2], const float b[2], nav_cell_fn fn,
                 void *ctx);
/* The same as an inline function: where fn is a known static inline function the compiler
 * inlines it into the loop (the carving's rays call it for every cell they cross). */
static inline int nav_traverse_inline(const sp_costmap *cm, const float a[2], const float b[2],
                                      nav_cell_fn fn, void *ctx)
{
    double gx = (a[0] - cm->origin[0]) / cm->res, gy = (a[1] - cm->origin[1]) / cm->res;
    double dx = (b[0] - cm->origin[0]) / cm->res - gx, dy = (b[1] - cm->origin[1]) / cm->res - gy;
    int ix = (int)floor(gx), iy = (int)floor(gy);
    int sx = dx > 0 ? 1 : -1, sy = dy > 0 ? 1 : -1;
    double tdx = dx != 0 ? fabs(1.0 / dx) : INFINITY, tdy = dy != 0 ? fabs(1.0 / dy) : INFINITY;
    double tmx = dx != 0 ? ((sx > 0 ? ix + 1 - gx : gx - ix) * tdx) : INFINITY;
    double tmy = dy != 0 ? ((sy > 0 ? iy + 1 - gy : gy - iy) * tdy) : INFINITY;
    double t = 0;
    long steps = (long)(fabs(dx) + fabs(dy)) + 4;
    for (long k = 0; k <= steps; k++) {
        double tn = tmx < tmy ? tmx : tmy; /* fmin is a library call without -ffast-math */
        if (!(tn < 1.0)) tn = 1.0;
        if (nav_inside(cm, ix, iy)) {
            int rc = fn(ctx, nav_idx(cm, ix, iy), (float)t, (float)tn);
            if (rc) return rc;
        }
        if (tn >= 1.0) break;
        t = tn;
        if (fabs(tmx - tmy) < 1e-9) { /* through a corner: both side cells touch the segment */
            int rc = 0;
            if (nav_inside(cm, ix + sx, iy)) rc = fn(ctx, nav_idx(cm, ix + sx, iy), (float)t, (float)t);
            if (!rc && nav_inside(cm, ix, iy + sy)) rc = fn(ctx, nav_idx(cm, ix, iy + sy), (float)t, (float)t);
            if (rc) return rc;
            ix += sx, iy += sy;
            tmx += tdx, tmy += tdy;
        } else if (tmx < tmy) {
            ix += sx;
            tmx += tdx;
        } else {
            iy += sy;
            tmy += tdy;
        }
    }
    return 0;
}


/* Distance from point p to segment a-b and to an axis-aligned box (0 inside). */
float nav_point_segment_dist(const float p[2], const float a[2], const float b[2]);
float nav_box_dist(const sp_nav_box *b, const float p[2]);
/* The point of box b nearest to p. */
void nav_box_nearest(const sp_nav_box *b, const float p[2], float out[2]);

/* A cell mask of the goal (traversable cells that satisfy it); returns the count. */
long nav_goal_mask(const sp_costmap *cm, const sp_nav_goal *g, uint8_t *mask);
/* Admissible lower bound (metres) from a point to the goal. */
float nav_goal_bound(const sp_nav_goal *g, const float p[2]);

/* One planner run: A* with an additive per-cell penalty [n cells] (or NULL), then string
 * pulling and waypoints. */
int nav_plan_once(const sp_costmap *cm, const float start[3], const sp_nav_goal *goal,
                  const sp_planner_opts *o, const float *penalty, const uint8_t *goal_mask,
                  sp_path *path, sp_error *err);

/* The path's cost without penalties (INFINITY when a segment lost its line of sight). */
float nav_path_cost(const sp_costmap *cm, const sp_planner_opts *o, const sp_path *p);
int nav_check_planner_opts(const sp_planner_opts *o, sp_error *err);
/* Validates start, goal and options and builds the goal mask (*mask_out, caller frees); on a
 * goal no cell satisfies, fails with SP_E_NOTFOUND and *status saying why. */
int nav_goal_prepare(const sp_costmap *cm, const float start[3], const sp_nav_goal *goal,
                     const sp_planner_opts *o, uint8_t **mask_out, int *status, sp_error *err);

#endif
