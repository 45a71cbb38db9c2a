/* The costmap from the splat: floor detection, map bounds, then occupancy from the training views
 * used as depth sensors (carve.c: per voxel of the robot's height band, the scans that hit it and
 * that saw through it) fused as log-odds, columns classified, pockets filled, and Nav2-style
 * inflation (inflate.c). First stage of navigation, fed by the model folder's splat.ply. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "nav_internal.h"

#define FLOOR_BIN_M 0.02f     /* floor histogram bin */
#define FLOOR_FLATNESS 0.5f   /* smallest scale / middle scale below this is a flat Gaussian */
#define FLOOR_NZ 0.9f         /* its normal within ~25 degrees of vertical */
#define BOUNDS_QUANTILE 0.001 /* robust map bounds: drop this share of band Gaussians per side */

sp_costmap_opts sp_costmap_opts_default(void)
{
    sp_costmap_opts o;
    memset(&o, 0, sizeof o);
    o.resolution_m = 0.05f;
    o.band_lo_m = 0.05f;
    o.band_hi_m = 1.0f;
    o.floor_z = NAN;
    o.robot_radius_m = 0.2f;
    o.inflation_radius_m = 1.0f;
    o.cost_scaling_factor = 3.0f;
    o.keep_clear_of_unknown = 0;
    o.min_opacity = 0.15f;
    o.occupancy = SP_OCCUPANCY_FOOTPRINTS;
    o.footprint_sigmas = 3.0f;
    o.occupied_evidence = 0.9f;
    o.pass_veto = 1.0f;
    o.veto_beside = 1;
    o.lowest_needs_hit = 1;
    o.hit_blocks_free = 1;
    o.hit_grow_tol = 2.0f;
    o.faint_blocks_free = 0.1f;
    o.faint_grow_tol = 1.0f;
    o.hit_above_m = 0.05f;
    o.unseen_unknown = 1;
    o.prob_hit = 0.7f;
    o.prob_miss = 0.4f;
    o.occupied_prob = 0.5f;
    o.min_hit_scans = 2;
    o.free_needs_floor = 0;
    o.free_from_floor = 0;
    o.slice_m = 0.1f;
    o.fill_max_area_m2 = 4.0f;
    o.cameras_stand = 1;
    o.despeckle_cells = 0;
    o.carve_downscale = 0;
    o.carve_alpha = 0.5f;
    o.carve_min_fresh = 0.0f;
    o.carve_stop_m = 0.03f;
    o.carve_discretize = 2;
    o.floor_tolerance_m = 0.15f;
    o.measure_floor_tolerance = 1;
    o.max_range_m = 8.0f;
    o.margin_m = 0.5f;
    o.max_cells = 4096;
    return o;
}

void sp_costmap_free(sp_costmap *cm)
{
    if (!cm) return;
    free(cm->occ);
    free(cm->cost);
    free(cm->dist);
    free(cm->seen);
    free(cm->hidden);
    memset(cm, 0, sizeof *cm);
}

int sp_costmap_copy(sp_costmap *dst, const sp_costmap *src, sp_error *err)
{
    memset(dst, 0, sizeof *dst);
    size_t n = (size_t)src->nx * src->ny;
    *dst = *src;
    dst->occ = malloc(n);
    dst->cost = malloc(n);
    dst->dist = malloc(n * sizeof(float));
    dst->seen = src->seen ? malloc(n * sizeof(uint16_t)) : NULL;
    dst->hidden = src->hidden ? malloc(n) : NULL;
    if (!dst->occ || !dst->cost || !dst->dist || (src->seen && !dst->seen) || (src->hidden && !dst->hidden)) {
        sp_costmap_free(dst);
        return sp_error_set(err, SP_E_NOMEM, "costmap: out of memory copying %zu cells", n);
    }
    memcpy(dst->occ, src->occ, n);
    memcpy(dst->cost, src->cost, n);
    memcpy(dst->dist, src->dist, n * sizeof(float));
    if (src->seen) memcpy(dst->seen, src->seen, n * sizeof(uint16_t));
    if (src->hidden) memcpy(dst->hidden, src->hidden, n);
    return SP_OK;
}

int sp_costmap_cell(const sp_costmap *cm, float x, float y, int *ix, int *iy)
{
    *ix = (int)floorf((x - cm->origin[0]) / cm->res);
    *iy = (int)floorf((y - cm->origin[1]) / cm->res);
    return nav_inside(cm, *ix, *iy) ? 0 : -1;
}

void sp_costmap_cell_center(const sp_costmap *cm, int ix, int iy, float xy[2])
{
    xy[0] = cm->origin[0] + ((float)ix + 0.5f) * cm->res;
    xy[1] = cm->origin[1] + ((float)iy + 0.5f) * cm->res;
}

int sp_costmap_traversable(const sp_costmap *cm, int ix, int iy)
{
    if (!nav_inside(cm, ix, iy)) return 0;
    long i = nav_idx(cm, ix, iy);
    return cm->occ[i] == SP_CELL_FREE && cm->cost[i] < SP_COST_INSCRIBED;
}

/* ---- Gaussian geometry ------------------------------------------------------------------------ */

/* |z component| of the axis of Gaussian i's smallest scale, and flatness (smallest / middle). */
static void gauss_normal(const sp_splat *s, size_t i, float *nz, float *flat)
{
    const float *ls = s->log_scales + 3 * i;
    int a = 0;
    for (int k = 1; k < 3; k++)
        if (ls[k] < ls[a]) a = k;
    float mid = INFINITY;
    for (int k = 0; k < 3; k++)
        if (k != a && ls[k] < mid) mid = ls[k];
    float R[9];
    sp_quat_to_mat3(s->quats + 4 * i, R);
    *nz = fabsf(R[6 + a]); /* column a of R is the axis; its z component is row 2 */
    *flat = expf(ls[a] - mid);
}

static int cmp_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* An opaque, flat, horizontal Gaussian: a piece of floor or of a table top. */
static int flat_horizontal(const sp_splat *s, size_t i, float *op)
{
    float nz, flat;
    *op = sp_sigmoid(s->opacity_logits[i]);
    if (*op < NAV_FLOOR_MIN_OPACITY) return 0;
    gauss_normal(s, i, &nz, &flat);
    return nz >= FLOOR_NZ && flat <= FLOOR_FLATNESS;
}

/* The floor: the heaviest 10 cm window of flat, horizontal, opaque Gaussians below the lowest
 * cameras, weighted by area x opacity; refined to the opacity-weighted mean z within it, whose
 * standard deviation is the floor's roughness in this splat. */
static int detect_floor(const sp_splat *s, const sp_camera *cams, size_t n_cams, float *floor_z,
                        float *floor_sd, sp_error *err)
{
    float *zc = malloc(sizeof(float) * n_cams);
    if (!zc) return sp_error_set(err, SP_E_NOMEM, "costmap: out of memory");
    for (size_t c = 0; c < n_cams; c++) zc[c] = sp_camera_center(&cams[c]).z;
    /* The floor lies below the cameras: below the lowest of them (the 5th percentile, so that one
     * stray pose cannot decide), which keeps table and shelf tops out when cameras stood low. */
    qsort(zc, n_cams, sizeof(float), cmp_float);
    float z_top = zc[n_cams / 20] - 0.05f;
    free(zc);
    float z_min = INFINITY;
    for (size_t i = 0; i < s->n; i++)
        if (s->means[3 * i + 2] < z_min && s->means[3 * i + 2] > z_top - 20.0f) z_min = s->means[3 * i + 2];
    if (!(z_min < z_top))
        return sp_error_set(err, SP_E_NOTFOUND, "costmap: no Gaussians below the cameras (the lowest "
                            "at %.2f m): cannot find the floor (give floor_z)", z_top + 0.05f);
    int nb = (int)ceilf((z_top - z_min) / FLOOR_BIN_M) + 1;
    double *hist = calloc((size_t)nb, sizeof(double));
    if (!hist) return sp_error_set(err, SP_E_NOMEM, "costmap: out of memory");
    for (size_t i = 0; i < s->n; i++) {
        float z = s->means[3 * i + 2], op;
        if (!(z >= z_min && z < z_top) || !flat_horizontal(s, i, &op)) continue;
        const float *ls = s->log_scales + 3 * i;
        float area = expf(ls[0] + ls[1] + ls[2] - fminf(ls[0], fminf(ls[1], ls[2])));
        hist[(int)((z - z_min) / FLOOR_BIN_M)] += (double)op * area;
    }
    /* the heaviest 10 cm window (a trained floor is often smeared over several bins) */
    int best = -1;
    double best_w = 0;
    for (int b = 0; b < nb; b++) {
        double w = 0;
        for (int k = b - 2; k <= b + 2; k++) w += k >= 0 && k < nb ? hist[k] : 0;
        if (w > best_w) best_w = w, best = b;
    }
    free(hist);
    if (best < 0)
        return sp_error_set(err, SP_E_NOTFOUND, "costmap: no flat horizontal Gaussians below the "
                            "cameras: cannot find the floor (give floor_z)");
    float lo = z_min + (best - 2) * FLOOR_BIN_M, hi = z_min + (best + 3) * FLOOR_BIN_M;
    double sw = 0, sz = 0, szz = 0;
    for (size_t i = 0; i < s->n; i++) {
        float z = s->means[3 * i + 2], op;
        if (!(z >= lo && z < hi) || !flat_horizontal(s, i, &op)) continue;
        sw += op;
        sz += (double)op * z;
        szz += (double)op * z * z;
    }
    *floor_z = (float)(sz / sw);
    *floor_sd = (float)sqrt(fmax(0.0, szz / sw - (sz / sw) * (sz / sw)));
    return SP_OK;
}

/* Bounds: the band Gaussians (robust quantiles) and the cameras, plus the margin. */
static int map_bounds(sp_costmap *cm, const sp_splat *s, const sp_camera *cams, size_t n_cams,
                      const sp_costmap_opts *o, sp_error *err)
{
    size_t n = 0;
    float *xs = malloc(sizeof(float) * (s->n + 1)), *ys = malloc(sizeof(float) * (s->n + 1));
    if (!xs || !ys) {
        free(xs), free(ys);
        return sp_error_set(err, SP_E_NOMEM, "costmap: out of memory");
    }
    for (size_t i = 0; i < s->n; i++) {
        float z = s->means[3 * i + 2];
        if (z < cm->band[0] || z > cm->band[1]) continue;
        if (sp_sigmoid(s->opacity_logits[i]) < o->min_opacity) continue;
        xs[n] = s->means[3 * i], ys[n] = s->means[3 * i + 1];
        n++;
    }
    float lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    if (n > 0) {
        qsort(xs, n, sizeof(float), cmp_float);
        qsort(ys, n, sizeof(float), cmp_float);
        size_t a = (size_t)(BOUNDS_QUANTILE * n), b = n - 1 - a;
        lo[0] = xs[a], hi[0] = xs[b], lo[1] = ys[a], hi[1] = ys[b];
    }
    free(xs), free(ys);
    for (size_t c = 0; c < n_cams; c++) {
        sp_vec3 p = sp_camera_center(&cams[c]);
        lo[0] = fminf(lo[0], p.x), hi[0] = fmaxf(hi[0], p.x);
        lo[1] = fminf(lo[1], p.y), hi[1] = fmaxf(hi[1], p.y);
    }
    /* Cell borders sit half a cell off round coordinates: built worlds put walls and furniture
     * faces on round numbers, and a face on a border would touch two cells. */
    float res = o->resolution_m;
    for (int k = 0; k < 2; k++) {
        lo[k] = floorf((lo[k] - o->margin_m) / res) * res - 0.5f * res;
        hi[k] = ceilf((hi[k] + o->margin_m) / res) * res + 0.5f * res;
    }
    double nx = ceil((hi[0] - lo[0]) / res), ny = ceil((hi[1] - lo[1]) / res);
    if (nx > o->max_cells || ny > o->max_cells)
        return sp_error_set(err, SP_E_UNSUPPORTED,
                            "costmap: the observed space spans %.1f x %.1f m, %.0f x %.0f cells at "
                            "%.3f m, over max_cells %d: use a coarser resolution",
                            hi[0] - lo[0], hi[1] - lo[1], nx, ny, res, o->max_cells);
    cm->nx = (int)nx, cm->ny = (int)ny;
    cm->res = res;
    cm->origin[0] = lo[0], cm->origin[1] = lo[1];
    return SP_OK;
}

/* Where the capture stood: a disk of the robot's radius under every training camera is free
 * (the robot or person carrying it was there), though no camera saw that floor: cameras look
 * away from their own feet. Occupancy evidence still wins (a camera held above a table). */
static void mark_stands(const sp_costmap *cm, const sp_camera *cams, size_t n_cams, float radius,
                        uint8_t *stood)
{
    int r = (int)ceilf(radius / cm->res);
    for (size_t c = 0; c < n_cams; c++) {
        sp_vec3 p = sp_camera_center(&cams[c]);
        int cx, cy;
        sp_costmap_cell(cm, p.x, p.y, &cx, &cy);
        for (int y = cy - r; y <= cy + r; y++)
            for (int x = cx - r; x <= cx + r; x++) {
                float q[2];
                if (!nav_inside(cm, x, y)) continue;
                sp_costmap_cell_center(cm, x, y, q);
                if (hypotf(q[0] - p.x, q[1] - p.y) <= radius) stood[nav_idx(cm, x, y)] = 1;
            }
    }
}

/* Log-odds of a probability. */
static inline float logit(float p) { return logf(p / (1.0f - p)); }

/* Did more scans see through voxel k than pass_veto x (1 + the scans that hit it)? (With
 * veto_beside, once some scan hit it, those that saw through it but hit a voxel beside it do not
 * count.) */
static int voxel_vetoed(const sp_costmap_opts *o, const nav_carve_out *co, long k)
{
    int H = co->hit_scans[k], M = co->miss_scans[k];
    return M - (o->veto_beside && H > 0 ? co->near_scans[k] : 0) > o->pass_veto * (1.0f + H);
}

/* Is voxel k occupied? SP_OCCUPANCY_SCANS fuses the scans as OctoMap does (Hornung et al.
 * 2013): every scan that hit the voxel adds logit(prob_hit), every scan that only saw through it
 * logit(prob_miss); occupied when the sum reaches logit(occupied_prob) and min_hit_scans scans
 * hit it (fewer when fewer observed it at all): an obstacle is where several standpoints'
 * rendered surfaces end, not where one view's floater sits. OctoMap's clamping (0.12 .. 0.97)
 * only matters to incremental updates; every scan is fused at once here, so the sum decides.
 * SP_OCCUPANCY_FOOTPRINTS: the Gaussians' footprint evidence, unless the scans saw through the
 * voxel more than pass_veto x (1 + the scans that hit it) times; with veto_beside, once some scan
 * hit the voxel, the scans that saw through it but hit a voxel beside it do not count (the
 * surface may be theirs: surface points are good to a cell; measured, counting them also for
 * voxels no scan hit turns the cells beside walls, where footprints spill over, occupied). (Surface points alone are
 * weak evidence on a trained splat: its rendered surfaces stand centimetres off the true ones.)
 * With lowest_needs_hit, footprints in the lowest slice count only where some scan hit it. */
static int voxel_occupied(const sp_costmap_opts *o, const nav_carve_out *co, const float *log_free, int slice, long k)
{
    int H = co->hit_scans[k], M = co->miss_scans[k];
    if (log_free)
        return log_free[k] <= logf(1.0f - o->occupied_evidence) && !voxel_vetoed(o, co, k) &&
               (slice > 0 || H > 0 || !o->lowest_needs_hit);
    float l_hit = logit(o->prob_hit), l_miss = logit(o->prob_miss), l_occ = logit(o->occupied_prob);
    int need = H + M < o->min_hit_scans ? H + M : o->min_hit_scans;
    return H > 0 && H >= need && (float)H * l_hit + (float)M * l_miss >= l_occ;
}

/* The first slice wholly above height h over the floor. */
static int first_slice_above(const sp_costmap *cm, const nav_slices *sl, float h)
{
    int v = 0;
    while (v < sl->n - 1 && sl->z0 + v * sl->dz < cm->floor_z + h - 1e-4f) v++;
    return v;
}

enum { SURF_NONE, SURF_HIT, SURF_FAINT, SURF_BESIDE };

/* What blocks free column i (not occupied), from slice v0 up: SURF_HIT, a voxel that at least
 * hit_blocks_free scans hit and the veto did not clear (a surface some view rendered there);
 * SURF_FAINT, a voxel with footprint evidence of at least faint_blocks_free (a thin surface the
 * views rendered too faintly to stop a ray); SURF_NONE. */
static int surface_kind(const sp_costmap_opts *o, const nav_carve_out *co, const float *log_free, long i, int v0)
{
    const nav_slices *sl = &co->sl;
    float faint = o->faint_blocks_free > 0 ? logf(1.0f - o->faint_blocks_free) : -INFINITY;
    int kind = SURF_NONE;
    for (int v = v0; v < sl->n; v++) {
        long k = v * sl->cells + i;
        if (o->hit_blocks_free > 0 && co->hit_scans[k] >= o->hit_blocks_free && !voxel_vetoed(o, co, k)) return SURF_HIT;
        if (log_free[k] <= faint) kind = SURF_FAINT;
    }
    return kind;
}

/* Marks the free cells within r cells (a disk) of cell (x, y) in grow. */
static void grow_disk(const sp_costmap *cm, int x, int y, int r, uint8_t *grow)
{
    for (int dy = -r; dy <= r; dy++)
        for (int dx = -r; dx <= r; dx++)
            if (dx * dx + dy * dy <= r * r && nav_inside(cm, x + dx, y + dy)) grow[nav_idx(cm, x + dx, y + dy)] = 1;
}

/* hit_blocks_free and faint_blocks_free: a free column with a rendered surface (some scan's
 * surface point ended in the band) or a faint one (footprint evidence the views saw through)
 * becomes unknown unless the capture stood there, and so do the free columns within hit_grow_tol /
 * faint_grow_tol floor tolerances of it (the rendered floor's thickness: this splat's error on
 * rendered surfaces) (a trained table top's rendered edge lies decimetres inside the true one, its
 * middle may be missing) when it is not itself beside an obstacle (there the surface points are
 * the obstacle's, a cell off; measured, growing those too takes the ideal house from 95.06 to
 * 94.86 %). Both count from the first slice wholly above twice the floor tolerance: a hazy
 * floor's rendered surface and its faint Gaussians spread past the tolerance (measured on the
 * trained bookstore, in the first slice above it the haze's fringe is hit over free floor 13756
 * times to 5625 over furniture; faint evidence counted from there, 16 of 44 objects reached
 * instead of 23). surface [cells] and grow [cells] are scratch. */
static void block_surfaces(sp_costmap *cm, const sp_costmap_opts *o, const nav_carve_out *co, const float *log_free,
                           const uint8_t *stood, uint8_t *surface, uint8_t *grow)
{
    const nav_slices *sl = &co->sl;
    float tol = o->floor_tolerance_m;
    int v0 = first_slice_above(cm, sl, 2 * tol);
    int g_hit = (int)lroundf(o->hit_grow_tol * tol / cm->res), g_faint = (int)lroundf(o->faint_grow_tol * tol / cm->res);
    size_t n = (size_t)cm->nx * cm->ny;
    memset(grow, 0, n);
    for (int y = 0; y < cm->ny; y++)
        for (int x = 0; x < cm->nx; x++) {
            long i = nav_idx(cm, x, y);
            surface[i] = cm->occ[i] == SP_CELL_OCCUPIED ? SURF_NONE : (uint8_t)surface_kind(o, co, log_free, i, v0);
            int kind = surface[i];
            for (int dy = -1; dy <= 1 && kind != SURF_NONE && surface[i] == kind; dy++)
                for (int dx = -1; dx <= 1 && surface[i] == kind; dx++)
                    if (nav_inside(cm, x + dx, y + dy) && cm->occ[nav_idx(cm, x + dx, y + dy)] == SP_CELL_OCCUPIED)
                        surface[i] = kind == SURF_HIT ? SURF_BESIDE : SURF_NONE; /* faint: the obstacle's footprint */
            if (surface[i] == SURF_HIT || surface[i] == SURF_FAINT)
                grow_disk(cm, x, y, surface[i] == SURF_HIT ? g_hit : g_faint, grow);
        }
    for (size_t i = 0; i < n; i++)
        if (cm->occ[i] == SP_CELL_FREE && !(stood && stood[i]) && (surface[i] != SURF_NONE || grow[i]))
            cm->occ[i] = SP_CELL_UNKNOWN;
}

/* A column is occupied when one of its voxels is; free when none is and every one of its voxels
 * was observed (with free_needs_floor, its floor seen too), or (free_from_floor) its floor was
 * seen and some voxel observed: a ray passing above a table top that no ray ended on does not
 * make the table free; unknown otherwise (block_surfaces then takes more free columns back); with
 * unseen_unknown, footprints in voxels no scan observed make a column unknown, not occupied.
 * log_free: the footprint evidence, or NULL (scans). */
static void classify(sp_costmap *cm, const sp_costmap_opts *o, const nav_carve_out *co, const float *log_free,
                     const uint8_t *stood)
{
    const nav_slices *sl = &co->sl;
    for (long i = 0; i < sl->cells; i++) {
        int occ = 0, observed = 0, hidden = 0;
        unsigned seen = co->floor_scans[i];
        for (int v = 0; v < sl->n && !occ; v++) {
            long k = v * sl->cells + i;
            int obs = co->hit_scans[k] + co->miss_scans[k] > 0;
            seen += (unsigned)(co->hit_scans[k] + co->miss_scans[k]);
            observed += obs;
            int o_k = voxel_occupied(o, co, log_free, v, k);
            if (o_k && !obs && o->unseen_unknown) hidden = 1; /* evidence no scan observed */
            else occ = o_k;
        }
        int floor = co->floor_scans[i] > 0;
        int free_ok = (observed == sl->n && (!o->free_needs_floor || floor)) || (o->free_from_floor && floor && observed);
        free_ok = (free_ok || (stood && stood[i])) && !hidden; /* evidence wins over a stand, seen or not */
        cm->seen[i] = seen > UINT16_MAX ? UINT16_MAX : (uint16_t)seen;
        cm->occ[i] = occ ? SP_CELL_OCCUPIED : free_ok ? SP_CELL_FREE : SP_CELL_UNKNOWN;
        if (cm->hidden) cm->hidden[i] = (uint8_t)(hidden && !occ);
    }
}

/* One filling pass: with close, walls are the obstacles grown by one cell (and the closing ring
 * around a filled pocket is filled too); without, the obstacles themselves, so that holes of a
 * cell or two inside a table, which the grown walls swallow whole, are filled as well. */
static void fill_pass(sp_costmap *cm, long max_cells, int close, int32_t *queue, uint8_t *wall, uint8_t *mark)
{
    size_t n = (size_t)cm->nx * cm->ny;
    memset(wall, 0, n), memset(mark, 0, n);
    for (int y = 0; y < cm->ny; y++)
        for (int x = 0; x < cm->nx; x++) {
            if (cm->occ[nav_idx(cm, x, y)] != SP_CELL_OCCUPIED) continue;
            for (int dy = -close; dy <= close; dy++)
                for (int dx = -close; dx <= close; dx++)
                    if (nav_inside(cm, x + dx, y + dy)) wall[nav_idx(cm, x + dx, y + dy)] = 1;
        }
    for (size_t seed = 0; seed < n; seed++) {
        if (wall[seed] || mark[seed]) continue;
        long head = 0, tail = 0;
        int open = 0, any_free = 0;
        queue[tail++] = (int32_t)seed;
        mark[seed] = 1;
        while (head < tail) {
            long c = queue[head++];
            any_free |= cm->occ[c] == SP_CELL_FREE;
            int cx = (int)(c % cm->nx), cy = (int)(c / cm->nx);
            for (int k = 0; k < 4; k++) {
                int x = cx + (k == 0) - (k == 1), y = cy + (k == 2) - (k == 3);
                if (!nav_inside(cm, x, y)) {
                    open = 1;
                    continue;
                }
                long j = nav_idx(cm, x, y);
                if (wall[j] || mark[j]) continue;
                mark[j] = 1;
                queue[tail++] = (int32_t)j;
            }
        }
        if (open || (any_free && tail > max_cells)) continue;
        /* the pocket and the closing ring around it that is not an obstacle yet */
        for (long q = 0; q < tail; q++) {
            long c = queue[q];
            cm->occ[c] = SP_CELL_OCCUPIED;
            int cx = (int)(c % cm->nx), cy = (int)(c / cm->nx);
            for (int k = 0; k < 4 && close; k++) {
                int x = cx + (k == 0) - (k == 1), y = cy + (k == 2) - (k == 3);
                if (nav_inside(cm, x, y) && wall[nav_idx(cm, x, y)]) cm->occ[nav_idx(cm, x, y)] = SP_CELL_OCCUPIED;
            }
        }
    }
}

/* Pockets enclosed by obstacles are the insides of solid things: a 4-connected component of
 * non-occupied cells that does not reach the map's border, with every cell unknown (the inside
 * of a wall or a cabinet, which no ray reaches and no Gaussian covers) or with an area of at most
 * fill_max_area_m2 (a bed or table whose top the splat reconstructs too thinly, rays passing above
 * and below it). Walls are closed by one cell first so a one-cell gap does not open a pocket. A
 * robot could never reach such a pocket, so filling it changes no plan. */
static int fill_pockets(sp_costmap *cm, float max_area_m2)
{
    size_t n = (size_t)cm->nx * cm->ny;
    int32_t *queue = malloc(sizeof(int32_t) * n);
    uint8_t *wall = malloc(n), *mark = malloc(n);
    if (!queue || !wall || !mark) {
        free(queue), free(wall), free(mark);
        return -1;
    }
    long max_cells = (long)(max_area_m2 / (cm->res * cm->res));
    fill_pass(cm, max_cells, 1, queue, wall, mark);
    fill_pass(cm, max_cells, 0, queue, wall, mark);
    free(queue), free(wall), free(mark);
    return 0;
}

/* Speckle: 8-connected occupied components of at most max_cells cells with free cells all
 * around (no unknown neighbour) are floaters the cameras saw past, not furniture; they become
 * free. A thin pole of the world is larger than a cell in a well-trained splat. */
static int despeckle(sp_costmap *cm, int max_cells)
{
    if (max_cells <= 0) return 0;
    size_t n = (size_t)cm->nx * cm->ny;
    int32_t *comp = malloc(sizeof(int32_t) * (size_t)(max_cells + 1));
    uint8_t *mark = calloc(n, 1);
    long *stack = malloc(sizeof(long) * n);
    if (!comp || !mark || !stack) {
        free(comp), free(mark), free(stack);
        return -1;
    }
    for (size_t seed = 0; seed < n; seed++) {
        if (cm->occ[seed] != SP_CELL_OCCUPIED || mark[seed]) continue;
        long top = 0, size = 0;
        int touches_unknown = 0;
        stack[top++] = (long)seed;
        mark[seed] = 1;
        while (top > 0) {
            long c = stack[--top];
            if (size <= max_cells) comp[size] = (int32_t)c;
            size++;
            int cx = (int)(c % cm->nx), cy = (int)(c / cm->nx);
            for (int dy = -1; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++) {
                    int x = cx + dx, y = cy + dy;
                    if (!nav_inside(cm, x, y)) {
                        touches_unknown = 1;
                        continue;
                    }
                    long j = nav_idx(cm, x, y);
                    if (cm->occ[j] == SP_CELL_UNKNOWN) touches_unknown = 1;
                    if (cm->occ[j] != SP_CELL_OCCUPIED || mark[j]) continue;
                    mark[j] = 1;
                    stack[top++] = j;
                }
        }
        if (size <= max_cells && !touches_unknown)
            for (long k = 0; k < size; k++) cm->occ[comp[k]] = SP_CELL_FREE;
    }
    free(comp), free(mark), free(stack);
    return 0;
}

static int check_opts(const sp_costmap_opts *o, sp_error *err)
{
    if (!(o->resolution_m > 0.001f && o->resolution_m < 10.0f))
        return sp_error_set(err, SP_E_ARG, "costmap: resolution_m %g not in (0.001, 10)", o->resolution_m);
    if (!(o->band_hi_m > o->band_lo_m))
        return sp_error_set(err, SP_E_ARG, "costmap: height band [%g, %g] m is empty", o->band_lo_m, o->band_hi_m);
    if (!(o->robot_radius_m >= 0) || !(o->inflation_radius_m >= o->robot_radius_m))
        return sp_error_set(err, SP_E_ARG, "costmap: robot radius %g m and inflation radius %g m "
                            "(need 0 <= robot <= inflation)", o->robot_radius_m, o->inflation_radius_m);
    if (!(o->cost_scaling_factor >= 0))
        return sp_error_set(err, SP_E_ARG, "costmap: cost_scaling_factor %g < 0", o->cost_scaling_factor);
    if (!(o->slice_m > 0))
        return sp_error_set(err, SP_E_ARG, "costmap: slice_m %g must be positive", o->slice_m);
    if (o->occupancy != SP_OCCUPANCY_FOOTPRINTS && o->occupancy != SP_OCCUPANCY_SCANS)
        return sp_error_set(err, SP_E_ARG, "costmap: occupancy %d is neither footprints (%d) nor scans (%d)",
                            o->occupancy, SP_OCCUPANCY_FOOTPRINTS, SP_OCCUPANCY_SCANS);
    if (!(o->occupied_evidence > 0 && o->occupied_evidence < 1) || !(o->pass_veto >= 0) || !(o->footprint_sigmas > 0))
        return sp_error_set(err, SP_E_ARG, "costmap: footprints: occupied_evidence %g (in (0, 1)), pass_veto %g "
                            "(>= 0), footprint_sigmas %g (> 0)", o->occupied_evidence, o->pass_veto, o->footprint_sigmas);
    if (!(o->prob_hit > 0.5f && o->prob_hit < 1) || !(o->prob_miss > 0 && o->prob_miss < 0.5f) ||
        !(o->occupied_prob > 0 && o->occupied_prob < 1) || o->min_hit_scans < 1)
        return sp_error_set(err, SP_E_ARG, "costmap: sensor model prob_hit %g (in (0.5, 1)), prob_miss %g "
                            "(in (0, 0.5)), occupied_prob %g (in (0, 1)), min_hit_scans %d (>= 1)",
                            o->prob_hit, o->prob_miss, o->occupied_prob, o->min_hit_scans);
    if (!(o->hit_grow_tol >= 0 && o->hit_grow_tol <= 10) || !(o->faint_grow_tol >= 0 && o->faint_grow_tol <= 10) ||
        !(o->faint_blocks_free >= 0 && o->faint_blocks_free < 1) || !(o->hit_above_m >= 0 && o->hit_above_m <= 1))
        return sp_error_set(err, SP_E_ARG, "costmap: hit_grow_tol %g and faint_grow_tol %g (in [0, 10]), "
                            "faint_blocks_free %g (in [0, 1)), hit_above_m %g (in [0, 1] m)", o->hit_grow_tol,
                            o->faint_grow_tol, o->faint_blocks_free, o->hit_above_m);
    if (o->carve_discretize < 0 || o->carve_discretize > 4)
        return sp_error_set(err, SP_E_ARG, "costmap: carve_discretize %d not in 0..4 (0: every ray traced)",
                            o->carve_discretize);
    if (!(o->carve_min_fresh >= 0 && o->carve_min_fresh <= 1))
        return sp_error_set(err, SP_E_ARG, "costmap: carve_min_fresh %g not in [0, 1]", o->carve_min_fresh);
    if (!(o->floor_tolerance_m >= 0 && o->floor_tolerance_m <= 1))
        return sp_error_set(err, SP_E_ARG, "costmap: floor_tolerance_m %g not in [0, 1]", o->floor_tolerance_m);
    if (o->carve_downscale < 0 || !(o->carve_alpha > 0 && o->carve_alpha <= 1) || !(o->max_range_m > 0) ||
        o->max_cells < 1)
        return sp_error_set(err, SP_E_ARG, "costmap: carve_downscale %d (>= 0), carve_alpha %g (in (0, 1]), "
                            "max_range_m %g and max_cells %d (positive)", o->carve_downscale, o->carve_alpha,
                            o->max_range_m, o->max_cells);
    return SP_OK;
}

int nav_costmap_build(sp_costmap *cm, const sp_splat *s, const sp_camera *cams, size_t n_cams,
                      const sp_costmap_opts *opts, sp_raster *r, uint16_t *view_counts,
                      const sp_log *log, sp_error *err)
{
    memset(cm, 0, sizeof *cm);
    sp_costmap_opts o = opts ? *opts : sp_costmap_opts_default();
    int rc = check_opts(&o, err);
    if (rc) return rc;
    if (!s || !s->n || !cams || !n_cams || !r)
        return sp_error_set(err, SP_E_ARG, "costmap: needs a splat with Gaussians, at least one "
                            "training camera and a raster (got %zu Gaussians, %zu cameras)",
                            s ? s->n : 0, n_cams);
    if ((rc = sp_splat_check_finite(s, err))) return sp_error_prefix(err, "costmap: ");
    for (size_t c = 0; c < n_cams; c++) {
        const sp_camera *k = &cams[c];
        int ok = k->width > 0 && k->height > 0 && k->fx > 0 && k->fy > 0 && isfinite(k->cx) && isfinite(k->cy);
        for (int j = 0; j < 9; j++) ok &= isfinite(k->R[j]);
        for (int j = 0; j < 3; j++) ok &= isfinite(k->t[j]);
        if (!ok)
            return sp_error_set(err, SP_E_ARG, "costmap: training camera %zu has a non-finite pose or bad "
                                "intrinsics (%dx%d, fx %g)", c, k->width, k->height, k->fx);
    }
    double t0 = sp_time_now();
    float floor_z = o.floor_z, floor_sd = 0;
    if (isnan(floor_z) && (rc = detect_floor(s, cams, n_cams, &floor_z, &floor_sd, err))) return rc;
    /* Nothing lower than twice the floor's own roughness can be told from the floor: the band
     * starts there when that is above band_lo_m (a trained floor is centimetres thick). */
    if (o.band_lo_m < 2 * floor_sd && 2 * floor_sd < o.band_hi_m - o.slice_m) {
        sp_logf(log, SP_LOG_INFO, "costmap: the floor's Gaussians spread %.3f m: the band starts at %.2f m, not %.2f",
                floor_sd, 2 * floor_sd, o.band_lo_m);
        o.band_lo_m = 2 * floor_sd;
    }
    cm->floor_z = floor_z;
    cm->band[0] = floor_z + o.band_lo_m;
    cm->band[1] = floor_z + o.band_hi_m;
    cm->opts = o;
    if ((rc = map_bounds(cm, s, cams, n_cams, &o, err))) return rc;
    size_t n = (size_t)cm->nx * cm->ny;
    nav_carve_out co;
    memset(&co, 0, sizeof co);
    co.sl.n = (int)ceilf((o.band_hi_m - o.band_lo_m) / o.slice_m - 1e-4f);
    if (co.sl.n < 1) co.sl.n = 1;
    if (co.sl.n > NAV_MAX_SLICES) co.sl.n = NAV_MAX_SLICES;
    co.sl.z0 = cm->band[0];
    co.sl.dz = (cm->band[1] - cm->band[0]) / co.sl.n;
    co.sl.cells = (long)n;
    size_t nv = n * co.sl.n;
    co.hit_scans = calloc(nv, sizeof(uint16_t));
    co.miss_scans = calloc(nv, sizeof(uint16_t));
    co.near_scans = calloc(nv, sizeof(uint16_t));
    co.floor_scans = calloc(n, sizeof(uint16_t));
    co.view_counts = view_counts;
    cm->occ = malloc(n);
    cm->cost = malloc(n);
    cm->dist = malloc(n * sizeof(float));
    cm->seen = calloc(n, sizeof(uint16_t));
    cm->hidden = o.unseen_unknown ? calloc(n, 1) : NULL;
    uint8_t *stood = o.cameras_stand ? calloc(n, 1) : NULL;
    float *log_free = o.occupancy == SP_OCCUPANCY_FOOTPRINTS ? calloc(nv, sizeof(float)) : NULL;
    int blocks = log_free && (o.hit_blocks_free > 0 || o.faint_blocks_free > 0);
    uint8_t *surface = blocks ? malloc(2 * n) : NULL;
    if (!co.hit_scans || !co.miss_scans || !co.near_scans || !co.floor_scans || !cm->occ || !cm->cost || !cm->dist || !cm->seen || (o.unseen_unknown && !cm->hidden) ||
        (o.cameras_stand && !stood) || (o.occupancy == SP_OCCUPANCY_FOOTPRINTS && !log_free) || (blocks && !surface)) {
        rc = sp_error_set(err, SP_E_NOMEM, "costmap: out of memory for %dx%d cells x %d slices",
                          cm->nx, cm->ny, co.sl.n);
        goto done;
    }
    if (view_counts) memset(view_counts, 0, s->n * sizeof(uint16_t));
    double t1 = nav_cpu_now();
    if ((rc = nav_carve(cm, s, cams, n_cams, &o, r, &co, log, err))) goto done;
    o.floor_tolerance_m = cm->opts.floor_tolerance_m = co.floor_tol; /* the one the scans used */
    double t2 = nav_cpu_now(), w2 = sp_time_now();
    if (log_free) {
        if (nav_footprints(sp_device_pool(sp_raster_device(r)), cm, s, &o, &co.sl, log_free)) {
            rc = sp_error_set(err, SP_E_NOMEM, "costmap: out of memory for the footprints of %zu Gaussians", s->n);
            goto done;
        }
        nav_mark_floor(cm, s, &o, co.floor_scans);
    }
    if (stood) mark_stands(cm, cams, n_cams, o.robot_radius_m, stood);
    classify(cm, &o, &co, log_free, stood);
    if (surface) block_surfaces(cm, &o, &co, log_free, stood, surface, surface + n);
    if (despeckle(cm, o.despeckle_cells) || fill_pockets(cm, o.fill_max_area_m2)) {
        rc = sp_error_set(err, SP_E_NOMEM, "costmap: out of memory");
        goto done;
    }
    long n_hidden = 0;
    for (size_t i = 0; cm->hidden && i < n; i++) /* a filled pocket is an obstacle now */
        n_hidden += cm->hidden[i] = cm->hidden[i] && cm->occ[i] == SP_CELL_UNKNOWN;
    if (cm->hidden && !n_hidden) free(cm->hidden), cm->hidden = NULL;
    if ((rc = sp_costmap_inflate(cm, &o, err))) goto done;
    long n_occ = 0, n_free = 0;
    for (size_t i = 0; i < n; i++) n_occ += cm->occ[i] == SP_CELL_OCCUPIED, n_free += cm->occ[i] == SP_CELL_FREE;
    sp_logf(log, SP_LOG_INFO,
            "costmap: %dx%d cells at %.3f m, floor z %.3f, band %.2f..%.2f m: %ld occupied, %ld "
            "free, %ld unknown (%.0f ms)", cm->nx, cm->ny, cm->res, cm->floor_z, o.band_lo_m,
            o.band_hi_m, n_occ, n_free, (long)n - n_occ - n_free, 1e3 * (sp_time_now() - t0));
    sp_logf(log, SP_LOG_DEBUG, "costmap: CPU time: carving %.0f ms, fusion and inflation %.0f ms (wall %.0f ms)",
            1e3 * (t2 - t1), 1e3 * (nav_cpu_now() - t2), 1e3 * (sp_time_now() - w2));
done:
    free(co.hit_scans), free(co.miss_scans), free(co.near_scans), free(co.floor_scans), free(stood), free(log_free), free(surface);
    if (rc) sp_costmap_free(cm);
    return rc;
}

int sp_costmap_build(sp_costmap *cm, const sp_splat *s, const sp_camera *cams, size_t n_cams,
                     const sp_costmap_opts *opts, sp_raster *r, const sp_log *log, sp_error *err)
{
    return nav_costmap_build(cm, s, cams, n_cams, opts, r, NULL, log, err);
}
