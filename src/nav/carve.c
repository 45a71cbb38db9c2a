/* The training views as depth sensors. Each view is rendered (first-surface depth) at reduced
 * size and every ray is traced through the voxels (cell x height slice of the robot's band): the
 * voxels it crosses, up to a little before its surface, are misses, the voxel of its surface
 * point and those along the depth image's continuous surface between neighbouring pixels are
 * hits (near the floor: floor sightings). Views taken from one standpoint (a panorama) share
 * their rays' origin, so they see nothing of depth that one of them does not (no parallax): they
 * are one scan, and each voxel is updated once per scan, a hit taking precedence over misses
 * (OctoMap's discretized scan insertion). Each voxel ends with the number of scans that hit it
 * and the number that only saw through it: the evidence costmap.c fuses as log-odds. Space no
 * ray crossed stays unknown. Scans are carved in parallel, each thread with its own counters.
 * With view counts asked for, the same renders tell per Gaussian in how many views it is visible
 * (the coverage behind localizability). */
#include <stdlib.h>
#include <string.h>

#include "nav_internal.h"

#define VIS_DEPTH_REL 1.05f    /* a Gaussian in front of rendered depth x this + VIS_DEPTH_ABS */
#define VIS_DEPTH_ABS 0.05f
#define SCAN_RADIUS_M 0.1f     /* views whose centres lie this close are one scan */
#define CULL_MARGIN_M 0.1f     /* Gaussians this far above the highest camera (and the band) */

#define MINF(a, b) ((a) < (b) ? (a) : (b)) /* fminf is a library call without -ffast-math */
#define MAXF(a, b) ((a) > (b) ? (a) : (b))

int nav_traverse(const sp_costmap *cm, const float a[2], const float b[2], nav_cell_fn fn,
                 void *ctx)
{
    return nav_traverse_inline(cm, a, b, fn, ctx);
}

enum { FLAG_MISS = 1, FLAG_HIT = 2, FLAG_END = 4 /* a traced ray of this scan ended in it */ };

/* One thread's counters and the flags of the scan it is carving. */
typedef struct carve_thread {
    uint8_t *flag;         /* [voxels + cells] this scan: FLAG_MISS / FLAG_HIT per voxel, then
                            * 1 per cell whose floor a ray ended on */
    int32_t *touched;      /* indices of flag set in this scan */
    uint16_t *ends;        /* [voxels] parts of the voxel's cell where a traced ray of this scan
                            * ended (carve_discretize) */
    long n_touched;
    float *pts;            /* [pixels][4] a view's surface points */
    size_t cap_pts;
    uint16_t *hit_scans, *miss_scans, *near_scans; /* [voxels] */
    uint16_t *floor_scans; /* [cells] */
    uint16_t *view_counts; /* [n Gaussians] or NULL */
    int failed;            /* out of memory */
} carve_thread;

/* A batch: views rendered together, in runs of one scan each. */
typedef struct carve_job {
    const sp_costmap *cm;
    const sp_splat *s;     /* the full splat (visibility counts) */
    const sp_costmap_opts *o;
    const nav_slices *sl;
    const sp_camera *views;  /* [views] as rendered (downscaled, cropped) */
    float *const *depth;     /* [views] their first-surface depth */
    const int *run_start;    /* [n_runs + 1] first view of each run (one scan, or a part of one) */
    const uint8_t *keep;     /* [views] 1: traced (select_views); others are rendered only for view counts */
    float floor_tol;         /* surface points this close to the floor are floor sightings */
    carve_thread *th;        /* [threads] */
} carve_job;

static inline void bump(uint16_t *c)
{
    if (*c < UINT16_MAX) (*c)++;
}

static inline void set_flag(carve_thread *t, long i, uint8_t f)
{
    if (!t->flag[i]) t->touched[t->n_touched++] = (int32_t)i;
    t->flag[i] |= f;
}

typedef struct ray_ctx {
    carve_thread *t;
    const nav_slices *sl;
    float z0, dz;      /* z(t) = z0 + t dz along the traversed stretch */
    float band_lo, band_hi;
    int discretize;    /* sp_costmap_opts.carve_discretize */
    float t_prev;      /* the last stretch's end and the slice of its height: the next stretch */
    int v_prev;        /* starts there (nav_traverse hands on t), so its slice is known */
} ray_ctx;

/* Marks every slice of the cell the ray's stretch inside it overlaps as missed. The stretch's
 * heights clipped to the band, [max(min(za, zb), lo), min(max(za, zb), hi)], are empty exactly
 * when both ends lie beyond one side of the band, and nav_slice_of clamps to the band like the
 * clipping, so the slices are those of the two ends (nav_slice_of is monotonic). */
static inline int carve_cell(void *vctx, long cell, float t0, float t1)
{
    ray_ctx *c = vctx;
    float za = c->z0 + t0 * c->dz, zb = c->z0 + t1 * c->dz;
    if ((za > c->band_hi && zb > c->band_hi) || (za < c->band_lo && zb < c->band_lo)) return 0;
    int va = t0 == c->t_prev ? c->v_prev : nav_slice_of(c->sl, za), vb = nav_slice_of(c->sl, zb);
    c->t_prev = t1, c->v_prev = vb;
    int v0 = va < vb ? va : vb, v1 = va < vb ? vb : va;
    uint8_t *flag = c->t->flag + cell;
    for (int v = v0; v <= v1; v++) {
        long i = v * c->sl->cells;
        if (!flag[i]) c->t->touched[c->t->n_touched++] = (int32_t)(i + cell);
        flag[i] |= FLAG_MISS;
    }
    return 0;
}

/* Misses along C + s (E - C), s in [0, s_end], clipped to the band's heights first: most of a
 * ray from a camera above the band never enters it. */
static void carve_ray(const sp_costmap *cm, ray_ctx *rc, sp_vec3 C, sp_vec3 E, float s_end)
{
    float dz = E.z - C.z, s0 = 0, s1 = s_end;
    if (dz > 1e-9f || dz < -1e-9f) {
        float a = (cm->band[0] - C.z) / dz, b = (cm->band[1] - C.z) / dz;
        s0 = MAXF(s0, MINF(a, b)), s1 = MINF(s1, MAXF(a, b));
    } else if (C.z < cm->band[0] || C.z > cm->band[1]) {
        return;
    }
    if (!(s1 > s0)) return;
    float a[2] = {C.x + s0 * (E.x - C.x), C.y + s0 * (E.y - C.y)};
    float b[2] = {C.x + s1 * (E.x - C.x), C.y + s1 * (E.y - C.y)};
    int ix, iy, k = rc->discretize;
    if (k > 0 && !sp_costmap_cell(cm, b[0], b[1], &ix, &iy)) {
        /* OctoMap's discretized scan insertion, finer: rays from one centre whose stretches end
         * in one k x k part of a voxel's cell run within that part's width of each other near
         * their end and closer before it, so the first one traced stands for the others */
        long end = nav_slice_of(rc->sl, C.z + s1 * dz) * rc->sl->cells + nav_idx(cm, ix, iy);
        int qx = (int)(((b[0] - cm->origin[0]) / cm->res - (float)ix) * (float)k);
        int qy = (int)(((b[1] - cm->origin[1]) / cm->res - (float)iy) * (float)k);
        qx = qx < 0 ? 0 : qx >= k ? k - 1 : qx, qy = qy < 0 ? 0 : qy >= k ? k - 1 : qy;
        uint16_t bit = (uint16_t)(1u << (qy * k + qx));
        if (rc->t->ends[end] & bit) return;
        rc->t->ends[end] |= bit;
        set_flag(rc->t, end, FLAG_END); /* listed in touched, so count_scan clears ends[] */
    }
    rc->z0 = C.z + s0 * dz, rc->dz = (s1 - s0) * dz;
    rc->t_prev = -1.0f; /* no stretch yet (t >= 0) */
    nav_traverse_inline(cm, a, b, carve_cell, rc); /* carve_cell inlined: the rays are most of the time */
}

/* Where a surface point counts: the flag index of its floor sighting (near the floor) or of its
 * voxel's hit (in the band, or up to hit_above_m above it: the top slice), -1 for neither. Each
 * class is a height interval of one cell. */
static long surface_key(const carve_job *j, const float P[3])
{
    const sp_costmap *cm = j->cm;
    int ix, iy;
    if (sp_costmap_cell(cm, P[0], P[1], &ix, &iy)) return -1;
    long cell = nav_idx(cm, ix, iy);
    float dz = P[2] - cm->floor_z;
    if (dz < j->floor_tol && dz > -j->floor_tol) return j->sl->n * j->sl->cells + cell;
    if (P[2] >= cm->band[0] && P[2] <= cm->band[1] + j->o->hit_above_m) return nav_slice_of(j->sl, P[2]) * j->sl->cells + cell;
    return -1;
}

/* A surface point in the voxels: a hit in the band, a floor sighting near the floor. */
static void mark_surface(const carve_job *j, carve_thread *t, const float P[3])
{
    long k = surface_key(j, P);
    if (k >= 0) set_flag(t, k, k >= j->sl->n * j->sl->cells ? 1 : FLAG_HIT);
}

/* The depth image is a 2.5-D surface: between two neighbouring pixels' surface points that lie
 * on one surface (depths within SEG_DEPTH_REL of each other and at most SEG_MAX_CELLS cells
 * apart) the surface continues, so the voxels along the segment are hit too. A table top seen
 * at a slant has its pixels' points rows of cells apart, and without this the cells between
 * them would be hit by no view while the rays above them miss. */
#define SEG_DEPTH_REL 0.1f
#define SEG_MAX_CELLS 4
static void mark_segment(const carve_job *j, carve_thread *t, const float *a, const float *b)
{
    if (!(a[3] > 0) || !(b[3] > 0)) return;
    float dd = a[3] - b[3];
    if (dd > SEG_DEPTH_REL * MINF(a[3], b[3]) || -dd > SEG_DEPTH_REL * MINF(a[3], b[3])) return;
    float d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    float len = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), res = j->cm->res;
    if (len > SEG_MAX_CELLS * res) return;
    /* both ends in one cell and one height class: the segment between them is too (convex), and
     * mark_surface marks the ends themselves */
    long ka = surface_key(j, a);
    if (ka >= 0 && ka == surface_key(j, b)) return;
    int steps = (int)ceilf(len / (0.5f * res));
    for (int k = 1; k < steps; k++) {
        float f = (float)k / steps, P[3] = {a[0] + f * d[0], a[1] + f * d[1], a[2] + f * d[2]};
        mark_surface(j, t, P);
    }
}

/* Traces one rendered view into the thread's flags: misses along every ray up to carve_stop_m
 * before its surface, then the surface points and the segments between them. A ray with no
 * surface that rises leaves the band with nothing in it (what it would meet lies above the
 * cameras, culled from the carving scene, or is nothing at all) and carves the band; one that
 * falls or runs level into nothing says nothing (an unreconstructed hole). */
static void trace_view(const carve_job *j, const sp_camera *cam, const float *depth, carve_thread *t)
{
    const sp_costmap *cm = j->cm;
    const sp_costmap_opts *o = j->o;
    sp_vec3 C = sp_camera_center(cam);
    ray_ctx rc = {t, j->sl, 0, 0, cm->band[0], cm->band[1], o->carve_discretize, -1.0f, 0};
    float Rt[9];
    sp_mat3_transpose(cam->R, Rt);
    float *pts = t->pts; /* [H][W] x, y, z, depth (0: no surface point) */
    for (int v = 0; v < cam->height; v++)
        for (int u = 0; u < cam->width; u++) {
            long p = (long)v * cam->width + u;
            float *q = pts + 4 * p;
            q[3] = 0;
            float d = depth[p]; /* first-surface depth along the optical axis, 0 = none */
            sp_vec3 dc = sp_v3((u + 0.5f - cam->cx) / cam->fx, (v + 0.5f - cam->cy) / cam->fy, 1.0f);
            sp_vec3 dw = sp_mat3_apply(Rt, dc);
            float n = sp_v3_norm(dw);
            if (!(d > 0)) {
                if (dw.z > 0) carve_ray(cm, &rc, C, sp_v3_add(C, sp_v3_scale(dw, o->max_range_m / n)), 1.0f);
                continue;
            }
            float len = d * n;
            int cut = len > o->max_range_m;
            if (cut) d *= o->max_range_m / len, len = o->max_range_m;
            sp_vec3 P = sp_v3_add(C, sp_v3_scale(dw, d));
            carve_ray(cm, &rc, C, P, cut ? 1.0f : MAXF(0.0f, 1.0f - o->carve_stop_m / len));
            if (!cut) q[0] = P.x, q[1] = P.y, q[2] = P.z, q[3] = d;
        }
    for (int v = 0; v < cam->height; v++)
        for (int u = 0; u < cam->width; u++) {
            const float *q = pts + 4 * ((long)v * cam->width + u);
            if (!(q[3] > 0)) continue;
            mark_surface(j, t, q);
            if (u + 1 < cam->width) mark_segment(j, t, q, q + 4);
            if (v + 1 < cam->height) mark_segment(j, t, q, q + 4 * cam->width);
        }
}

/* Does the scan hit one of the 8 voxels beside voxel i (same slice)? */
static int hit_beside(const sp_costmap *cm, const nav_slices *sl, const uint8_t *flag, long i)
{
    long cell = i % sl->cells, base = i - cell;
    int cx = (int)(cell % cm->nx), cy = (int)(cell / cm->nx);
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++)
            if ((dx || dy) && nav_inside(cm, cx + dx, cy + dy) && (flag[base + nav_idx(cm, cx + dx, cy + dy)] & FLAG_HIT))
                return 1;
    return 0;
}

/* One scan's flags into the thread's counters (a voxel hit in this scan counts as a hit only; a
 * missed one beside a hit voxel counts as near too), then clears them for the next scan. */
static void count_scan(const sp_costmap *cm, const nav_slices *sl, carve_thread *t)
{
    long nv = (long)sl->n * sl->cells;
    for (long k = 0; k < t->n_touched; k++) {
        long i = t->touched[k];
        if (i >= nv) bump(&t->floor_scans[i - nv]);
        else if (t->flag[i] & FLAG_HIT) bump(&t->hit_scans[i]);
        else if (t->flag[i] & FLAG_MISS) {
            bump(&t->miss_scans[i]);
            if (hit_beside(cm, sl, t->flag, i)) bump(&t->near_scans[i]);
        }
    }
    for (long k = 0; k < t->n_touched; k++) {
        long i = t->touched[k];
        t->flag[i] = 0;
        if (i < nv) t->ends[i] = 0;
    }
    t->n_touched = 0;
}

/* Counts the view for every opaque Gaussian whose centre projects into it in front of the
 * rendered surface: the deepest surface of the 3 x 3 pixels around it (a low-resolution pixel on
 * a floor seen at a slant spans tens of centimetres of depth), with 5 % + 5 cm to spare. */
static void count_visible(const carve_job *j, const sp_camera *cam, const float *depth, uint16_t *counts)
{
    const sp_splat *s = j->s;
    for (size_t i = 0; i < s->n; i++) {
        if (counts[i] == UINT16_MAX || sp_sigmoid(s->opacity_logits[i]) < j->o->min_opacity) continue;
        const float *m = s->means + 3 * i;
        sp_vec3 pc = sp_v3_add(sp_mat3_apply(cam->R, sp_v3(m[0], m[1], m[2])), sp_v3(cam->t[0], cam->t[1], cam->t[2]));
        if (pc.z < 0.05f) continue;
        int u = (int)floorf(cam->fx * pc.x / pc.z + cam->cx), v = (int)floorf(cam->fy * pc.y / pc.z + cam->cy);
        if (u < 0 || v < 0 || u >= cam->width || v >= cam->height) continue;
        float deepest = -1;
        for (int dv = -1; dv <= 1; dv++)
            for (int du = -1; du <= 1; du++) {
                int x = u + du, y = v + dv;
                if (x >= 0 && y >= 0 && x < cam->width && y < cam->height) deepest = MAXF(deepest, depth[(long)y * cam->width + x]);
            }
        if (deepest > 0 && pc.z <= deepest * VIS_DEPTH_REL + VIS_DEPTH_ABS) counts[i]++;
    }
}

static void carve_run(void *ctx, long r, int thread_id)
{
    const carve_job *j = ctx;
    carve_thread *t = &j->th[thread_id];
    for (int k = j->run_start[r]; k < j->run_start[r + 1]; k++) {
        size_t np = (size_t)j->views[k].width * j->views[k].height;
        if (np > t->cap_pts) {
            free(t->pts);
            t->pts = malloc(sizeof(float) * 4 * np);
            t->cap_pts = t->pts ? np : 0;
        }
        if (!t->pts) {
            t->failed = 1;
            return;
        }
        if (j->keep[k]) trace_view(j, &j->views[k], j->depth[k], t);
        if (t->view_counts) count_visible(j, &j->views[k], j->depth[k], t->view_counts);
    }
    count_scan(j->cm, j->sl, t);
}

static inline void add_sat(uint16_t *dst, const uint16_t *src, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        unsigned v = (unsigned)dst[i] + src[i];
        dst[i] = v > UINT16_MAX ? UINT16_MAX : (uint16_t)v;
    }
}

static void threads_free(carve_thread *th, int T)
{
    for (int t = 0; th && t < T; t++) {
        free(th[t].flag), free(th[t].touched), free(th[t].pts), free(th[t].ends);
        if (t == 0) continue; /* thread 0 counts into the outputs */
        free(th[t].hit_scans), free(th[t].miss_scans), free(th[t].near_scans), free(th[t].floor_scans);
        free(th[t].view_counts);
    }
    free(th);
}

/* Thread 0 counts straight into out; the others into their own counters, merged at the end. */
static carve_thread *threads_alloc(int T, const nav_carve_out *out, size_t n_gauss)
{
    size_t nv = (size_t)out->sl.cells * out->sl.n, nc = (size_t)out->sl.cells;
    carve_thread *th = calloc((size_t)T, sizeof *th);
    int ok = th != NULL;
    for (int t = 0; t < T && ok; t++) {
        carve_thread *c = &th[t];
        c->flag = calloc(nv + nc, 1);
        c->ends = calloc(nv, sizeof(uint16_t));
        c->touched = malloc(sizeof(int32_t) * (nv + nc));
        c->hit_scans = t ? calloc(nv, sizeof(uint16_t)) : out->hit_scans;
        c->miss_scans = t ? calloc(nv, sizeof(uint16_t)) : out->miss_scans;
        c->near_scans = t ? calloc(nv, sizeof(uint16_t)) : out->near_scans;
        c->floor_scans = t ? calloc(nc, sizeof(uint16_t)) : out->floor_scans;
        c->view_counts = !out->view_counts ? NULL : t ? calloc(n_gauss + 1, sizeof(uint16_t)) : out->view_counts;
        ok = c->flag && c->ends && c->touched && c->hit_scans && c->miss_scans && c->near_scans && c->floor_scans &&
             (c->view_counts || !out->view_counts);
    }
    if (!ok) threads_free(th, T), th = NULL;
    return th;
}

/* Scans: each view joins the scan of the first earlier view whose centre lies within
 * SCAN_RADIUS_M. order[] lists the views scan by scan (in order of first appearance), scan_of[]
 * the scan of each; returns the number of scans. */
static int group_scans(const sp_camera *cams, size_t n, int *order, int *scan_of)
{
    int n_scans = 0;
    for (size_t i = 0; i < n; i++) {
        sp_vec3 c = sp_camera_center(&cams[i]);
        scan_of[i] = -1;
        for (size_t k = 0; k < i && scan_of[i] < 0; k++)
            if (sp_v3_norm(sp_v3_sub(c, sp_camera_center(&cams[k]))) <= SCAN_RADIUS_M) scan_of[i] = scan_of[k];
        if (scan_of[i] < 0) scan_of[i] = n_scans++;
    }
    size_t at = 0;
    for (int s = 0; s < n_scans; s++)
        for (size_t i = 0; i < n; i++)
            if (scan_of[i] == s) order[at++] = (int)i;
    return n_scans;
}

/* Per carving-splat Gaussian, what the per-view culling reads: rows x, y, z (the mean) and
 * sigma_max^2 (its largest variance), each of stride floats (padded for four-wide reads). */
typedef struct cull_geo {
    float *rows;
    size_t stride;
} cull_geo;

/* The splat the views are rendered from for carving: geometry only (depth needs no colours),
 * without the Gaussians wholly above the highest camera and the band: a ray can meet those only
 * after it has risen out of the band (a rising ray with no surface carves the band). Also each
 * kept Gaussian's cull geometry (cull_geo). */
static int carving_splat(const sp_splat *s, const sp_camera *cams, size_t n, float band_hi, sp_splat *c,
                         cull_geo *geo, sp_error *err)
{
    float z_cut = band_hi;
    for (size_t i = 0; i < n; i++) z_cut = MAXF(z_cut, sp_camera_center(&cams[i]).z);
    z_cut += CULL_MARGIN_M;
    int rc = sp_splat_alloc(c, s->n, 0, 0, err);
    if (rc) return rc;
    size_t stride = geo->stride = s->n + 4;
    float *rows = geo->rows = calloc(4 * stride, sizeof(float));
    if (!rows) {
        sp_splat_free(c);
        return sp_error_set(err, SP_E_NOMEM, "costmap: out of memory for %zu Gaussians", s->n);
    }
    size_t m = 0;
    for (size_t i = 0; i < s->n; i++) {
        float R[9], sz2 = 0;
        const float *ls = s->log_scales + 3 * i;
        sp_quat_to_mat3(s->quats + 4 * i, R);
        for (int k = 0; k < 3; k++) sz2 += R[6 + k] * R[6 + k] * expf(2.0f * ls[k]);
        if (s->means[3 * i + 2] - 3.0f * sqrtf(sz2) > z_cut) continue;
        memcpy(c->means + 3 * m, s->means + 3 * i, 3 * sizeof(float));
        memcpy(c->quats + 4 * m, s->quats + 4 * i, 4 * sizeof(float));
        memcpy(c->log_scales + 3 * m, ls, 3 * sizeof(float));
        c->opacity_logits[m] = s->opacity_logits[i];
        memcpy(c->sh + 3 * m, s->sh + (size_t)i * 3 * sp_sh_coeffs(s->sh_degree), 3 * sizeof(float));
        float sg = expf(MAXF(ls[0], MAXF(ls[1], ls[2])));
        for (int k = 0; k < 3; k++) rows[k * stride + m] = s->means[3 * i + k];
        rows[3 * stride + m] = sg * sg;
        m++;
    }
    c->n = m;
    return SP_OK;
}

/* The Gaussians of src the renderer can draw in view cam, into dst (src's order kept, so the
 * render is the same as of all of src). A bound on the renderer's own culling (near plane, then
 * the 2D mean +- the radius of the alpha >= 1/255 ellipse against the image): the 2D covariance
 * J W Sigma W^T J^T has its largest eigenvalue below |J|_F^2 sigma_max^2 (rotations keep norms;
 * the renderer's clamped Jacobian is smaller still), plus the screen dilation; the radius is at
 * most sqrt(2 ln 255) = 3.33 of its square root. A Gaussian it keeps that the renderer culls is
 * harmless; none it drops is drawn. Most of a view's Gaussians lie behind it or beside it, and
 * the renderer's projection of each of them is what rendering costs at carving sizes. */
#define CULL_EXTENT 3.34f
#define CULL_NEAR 0.009f  /* the renderer's near plane is 0.01 m */
#define CULL_CHUNKS 64    /* the culling's parallel chunks */
typedef struct cull_job {
    const sp_splat *src;
    const float *geo;             /* carving_splat's cull geometry: x, y, z, sigma_max^2 rows */
    size_t stride;                /* of those rows */
    const sp_camera *cam;
    float eps;
    sp_splat *dst;
    size_t chunk;                 /* Gaussians per chunk */
    size_t count[CULL_CHUNKS];    /* kept per chunk */
} cull_job;

typedef float cull_v4 __attribute__((vector_size(16)));
typedef int32_t cull_v4i __attribute__((vector_size(16)));

static inline cull_v4 v4_load(const float *p)
{
    cull_v4 v;
    memcpy(&v, p, sizeof v);
    return v;
}

static inline cull_v4 v4_splat(float x) { return (cull_v4){x, x, x, x}; }

/* Which of Gaussians i .. i + 3 the bound keeps (bit l: Gaussian i + l), four at a time. */
static inline unsigned cull_keeps4(const cull_job *c, size_t i)
{
    const sp_camera *cam = c->cam;
    const float *R = cam->R, *t = cam->t;
    const cull_v4 px = v4_load(c->geo + i), py = v4_load(c->geo + c->stride + i), pz = v4_load(c->geo + 2 * c->stride + i);
    const cull_v4 s2 = v4_load(c->geo + 3 * c->stride + i);
    cull_v4 z = v4_splat(R[6]) * px + v4_splat(R[7]) * py + v4_splat(R[8]) * pz + v4_splat(t[2]);
    cull_v4i front = z >= v4_splat(CULL_NEAR);
    unsigned any = 0;
    for (int l = 0; l < 4; l++) any |= front[l] ? 1u << l : 0u;
    if (!any) return 0; /* most of a view's Gaussians lie behind it */
    z = (cull_v4)((cull_v4i)z & front) + (cull_v4)((cull_v4i)v4_splat(1.0f) & ~front); /* no division by 0 */
    cull_v4 x = v4_splat(R[0]) * px + v4_splat(R[1]) * py + v4_splat(R[2]) * pz + v4_splat(t[0]);
    cull_v4 y = v4_splat(R[3]) * px + v4_splat(R[4]) * py + v4_splat(R[5]) * pz + v4_splat(t[1]);
    const float fx = cam->fx, fy = cam->fy;
    cull_v4 iz = v4_splat(1.0f) / z, u = v4_splat(fx) * x * iz + v4_splat(cam->cx), v = v4_splat(fy) * y * iz + v4_splat(cam->cy);
    cull_v4 j2 = (v4_splat(fx * fx + fy * fy) + (v4_splat(fx * fx) * x * x + v4_splat(fy * fy) * y * y) * iz * iz) * iz * iz;
    cull_v4 q = j2 * s2 + v4_splat(c->eps);
    unsigned keep = 0;
    for (int l = 0; l < 4; l++) {
        if (!(any >> l & 1u)) continue;
        float r = CULL_EXTENT * sqrtf(q[l]) + 2.0f;
        keep |= !(u[l] + r <= 0.f || u[l] - r >= (float)cam->width || v[l] + r <= 0.f || v[l] - r >= (float)cam->height)
                ? 1u << l : 0u;
    }
    return keep;
}

/* Chunk k's kept Gaussians to dst from the chunk's own start (so chunks never overlap). */
static void cull_chunk(void *ctx, long k, int thread_id)
{
    (void)thread_id;
    cull_job *c = ctx;
    const sp_splat *src = c->src;
    sp_splat *dst = c->dst;
    size_t i0 = (size_t)k * c->chunk, i1 = i0 + c->chunk < src->n ? i0 + c->chunk : src->n, m = i0;
    for (size_t i4 = i0; i4 < i1; i4 += 4) {
        unsigned keep = cull_keeps4(c, i4); /* the rows are padded: i4 + 3 is readable */
        for (size_t i = i4; keep && i < i4 + 4 && i < i1; i++, keep >>= 1) {
            if (!(keep & 1u)) continue;
            memcpy(dst->means + 3 * m, src->means + 3 * i, 3 * sizeof(float));
            memcpy(dst->quats + 4 * m, src->quats + 4 * i, 4 * sizeof(float));
            memcpy(dst->log_scales + 3 * m, src->log_scales + 3 * i, 3 * sizeof(float));
            dst->opacity_logits[m] = src->opacity_logits[i];
            m++;
        }
    }
    c->count[k] = m - i0;
}

/* In parallel over chunks, each into its own stretch of dst (which holds all of src), then the
 * stretches moved together in order. */
static size_t cull_view(sp_pool *pool, const sp_splat *src, const cull_geo *geo, const sp_camera *cam, sp_splat *dst)
{
    cull_job c = {src, geo->rows, geo->stride, cam, sp_raster_cfg_default().eps2d, dst, (src->n + CULL_CHUNKS - 1) / CULL_CHUNKS, {0}};
    if (c.chunk == 0) return dst->n = 0;
    long n_chunks = (long)((src->n + c.chunk - 1) / c.chunk);
    sp_pool_for(pool, n_chunks, cull_chunk, &c);
    size_t at = 0;
    for (long k = 0; k < n_chunks; k++) {
        size_t from = (size_t)k * c.chunk, m = c.count[k];
        if (from != at && m) {
            memmove(dst->means + 3 * at, dst->means + 3 * from, 3 * m * sizeof(float));
            memmove(dst->quats + 4 * at, dst->quats + 4 * from, 4 * m * sizeof(float));
            memmove(dst->log_scales + 3 * at, dst->log_scales + 3 * from, 3 * m * sizeof(float));
            memmove(dst->opacity_logits + at, dst->opacity_logits + from, m * sizeof(float));
        }
        at += m;
    }
    dst->n = at;
    return at;
}

/* Crops a carving view to the rows that can tell the band anything. From a camera above the
 * band, a ray that does not fall never enters it, and its surface point lies above the camera:
 * no miss, no hit, no floor sighting (carve_ray, mark_surface). The rows whose pixels all rise
 * (at least one end of each is enough: the ray's rise is linear across a row) are dropped but
 * one, which keeps the segments between it and the first falling row (mark_segment): the
 * carving is the same, with fewer pixels rendered. Rows must come off the top or the bottom
 * (a rolled camera whose rising rows sit in the middle keeps them). Only without view counts,
 * which every pixel's depth feeds. */
static void crop_to_band(sp_camera *cam, float band_hi)
{
    if (!(sp_camera_center(cam).z > band_hi) || cam->height < 3) return;
    const float *R = cam->R; /* dw.z = row 2 of R^T . dc = column 2 of R . dc */
    int H = cam->height, lo = H, hi = -1; /* the rows none of whose rays falls */
    for (int v = 0; v < H; v++) {
        float dy = ((float)v + 0.5f - cam->cy) / cam->fy, falls = 0;
        for (int e = 0; e < 2; e++) {
            float dx = ((e ? (float)cam->width - 0.5f : 0.5f) - cam->cx) / cam->fx;
            falls += R[2] * dx + R[5] * dy + R[8] < 0;
        }
        if (!falls) lo = v < lo ? v : lo, hi = v;
    }
    if (hi < 0) return;
    if (lo == 0 && hi < H - 1) { /* rising rows on top: keep from row hi (the guard row) down */
        cam->cy -= (float)hi;
        cam->height = H - hi;
    } else if (hi == H - 1 && lo > 0) {
        cam->height = lo + 1;
    }
}

#define CARVE_BATCH 16 /* at most this many views of one scan are a run (the rest a run of their own) */

/* The runs from order[at]: whole scans while they fit in CARVE_BATCH views (a scan of more views
 * is split, its parts then counting as scans of their own); runs[] gets each scan's first view
 * within the batch and the end. Returns the batch's view count. */
static int next_batch(const int *order, const int *scan_of, size_t n, size_t at, int *runs, int *n_runs)
{
    int nb = 0;
    *n_runs = 0;
    while (at + nb < n) {
        int s = scan_of[order[at + nb]], len = 0;
        while (at + nb + len < n && scan_of[order[at + nb + len]] == s) len++;
        if (nb > 0 && nb + len > CARVE_BATCH) break;
        runs[(*n_runs)++] = nb;
        if (len > CARVE_BATCH) len = CARVE_BATCH;
        nb += len;
        if (nb >= CARVE_BATCH) break;
    }
    runs[*n_runs] = nb;
    return nb;
}

/* All runs over the views in order[]: run_start[0..n_runs] (first view of each, then n). */
static int split_runs(const int *order, const int *scan_of, size_t n, int *run_start)
{
    int n_runs = 0, runs[CARVE_BATCH + 1], nr;
    for (size_t at = 0; at < n;) {
        int nb = next_batch(order, scan_of, n, at, runs, &nr);
        for (int k = 0; k < nr; k++) run_start[n_runs++] = (int)at + runs[k];
        at += (size_t)nb;
    }
    run_start[n_runs] = (int)n;
    return n_runs;
}

/* The rendered floor's thickness. Surface heights above the floor in 1 cm bins: the walls and
 * furniture give a background that varies slowly with height, counted (its median bin) between
 * the cap and twice it; the floor's points are the excess over it below the cap (and all points
 * below the floor, where nothing else is). The tolerance is the height within which 99 % of that
 * excess lies, one bin more, at most the cap: an ideal or well-trained floor renders within a few
 * centimetres, so a window sill or a frame 5 cm up is a hit in the band and not floor; a hazy
 * trained floor keeps the cap. */
#define FT_BIN_M 0.01f
#define FT_MAX_BINS 100
#define FT_SHARE 0.99
static float floor_tolerance(const sp_costmap *cm, const sp_costmap_opts *o, const sp_camera *views,
                             float *const *depth, const uint8_t *keep, size_t n, long *excess_out)
{
    float cap = o->floor_tolerance_m;
    int nb = (int)ceilf(cap / FT_BIN_M - 1e-4f);
    if (!o->measure_floor_tolerance || nb < 2) return cap;
    if (nb > FT_MAX_BINS / 2) nb = FT_MAX_BINS / 2;
    long up[FT_MAX_BINS] = {0}, down[FT_MAX_BINS] = {0};
    for (size_t k = 0; k < n; k++) {
        if (!keep[k]) continue;
        const sp_camera *cam = &views[k];
        const float *R = cam->R, cz = sp_camera_center(cam).z; /* world dz per unit depth: column 2 of R . dc */
        for (int v = 0; v < cam->height; v++) {
            float dy = ((float)v + 0.5f - cam->cy) / cam->fy;
            for (int u = 0; u < cam->width; u++) {
                float d = depth[k][(long)v * cam->width + u];
                if (!(d > 0)) continue;
                float dx = ((float)u + 0.5f - cam->cx) / cam->fx;
                float h = (cz + d * (R[2] * dx + R[5] * dy + R[8]) - cm->floor_z) / FT_BIN_M;
                if (h >= 0 && h < 2 * nb) up[(int)h]++;
                else if (h < 0 && h > -nb) down[(int)-h]++;
            }
        }
    }
    long bg[FT_MAX_BINS / 2], total = 0, ex[FT_MAX_BINS / 2];
    for (int b = 0; b < nb; b++) bg[b] = up[nb + b];
    for (int i = 1; i < nb; i++) /* insertion sort for the median */
        for (int k = i; k > 0 && bg[k - 1] > bg[k]; k--) {
            long x = bg[k];
            bg[k] = bg[k - 1], bg[k - 1] = x;
        }
    long back = bg[nb / 2];
    for (int b = 0; b < nb; b++) total += ex[b] = (up[b] > back ? up[b] - back : 0) + down[b];
    *excess_out = total;
    if (total <= 0) return cap; /* no floor in sight: nothing to measure */
    long acc = 0;
    int b = 0;
    while (b < nb - 1 && (acc += ex[b]) < FT_SHARE * (double)total) b++;
    float t = (float)(b + 2) * FT_BIN_M;
    return t < cap ? t : cap;
}

/* Views of one scan share their rays' origin: where two overlap they sample the same rays, and
 * a voxel is updated once per scan, so a view whose directions the scan's other views already
 * show adds (up to the pixel grid's sampling) nothing. Sample directions every SEL_STEP pixels
 * of each view (edges included); greedy set cover (the view showing most of the samples not yet
 * shown, until every sample is shown) keeps views [a, b) in keep[]. Returns how many. */
#define SEL_STEP 8
#define SEL_MAX_SAMPLES 8192
static int sees(const sp_camera *cam, sp_vec3 d)
{
    sp_vec3 c = sp_mat3_apply(cam->R, d);
    if (!(c.z > 1e-6f)) return 0;
    float u = cam->fx * c.x / c.z + cam->cx, v = cam->fy * c.y / c.z + cam->cy;
    return u >= 0.f && v >= 0.f && u <= (float)cam->width && v <= (float)cam->height;
}

static int view_samples(const sp_camera *cam, sp_vec3 *out, int cap)
{
    float Rt[9];
    sp_mat3_transpose(cam->R, Rt);
    int nu = (cam->width - 1) / SEL_STEP + 2, nv = (cam->height - 1) / SEL_STEP + 2, m = 0;
    for (int j = 0; j < nv; j++)
        for (int i = 0; i < nu && m < cap; i++) {
            float u = i < nu - 1 ? (float)(i * SEL_STEP) + 0.5f : (float)cam->width - 0.5f;
            float v = j < nv - 1 ? (float)(j * SEL_STEP) + 0.5f : (float)cam->height - 0.5f;
            out[m++] = sp_mat3_apply(Rt, sp_v3((u - cam->cx) / cam->fx, (v - cam->cy) / cam->fy, 1.0f));
        }
    return m;
}

static int select_views(const sp_camera *views, int a, int b, float min_fresh, uint8_t *keep)
{
    for (int k = a; k < b; k++) keep[k] = 1;
    if (b - a < 2) return b - a;
    sp_vec3 *d = malloc(sizeof(sp_vec3) * SEL_MAX_SAMPLES);
    uint8_t *shown = calloc(SEL_MAX_SAMPLES, 1);
    int own[CARVE_BATCH];
    if (!d || !shown || b - a > CARVE_BATCH) { /* keep them all */
        free(d), free(shown);
        return b - a;
    }
    int n = 0;
    for (int k = a; k < b && n < SEL_MAX_SAMPLES; k++) n += own[k - a] = view_samples(&views[k], d + n, SEL_MAX_SAMPLES - n);
    for (int k = a; k < b; k++) keep[k] = 0;
    int kept = 0;
    for (;;) {
        int best = -1, best_new = 0;
        for (int k = a; k < b; k++) {
            if (keep[k]) continue;
            int fresh = 0;
            for (int i = 0; i < n; i++) fresh += !shown[i] && sees(&views[k], d[i]);
            if (fresh > best_new && fresh >= min_fresh * own[k - a]) best = k, best_new = fresh;
        }
        if (best < 0) break;
        keep[best] = 1, kept++;
        for (int i = 0; i < n; i++) shown[i] |= sees(&views[best], d[i]);
    }
    free(d), free(shown);
    return kept;
}

/* A training view as the carving renders it: at carving size, undistorted (depth needs no
 * distortion model), cropped to the band when crop is set (not with view counts). */
static sp_camera carving_view(const sp_costmap *cm, const sp_costmap_opts *o, const sp_camera *cam, int crop)
{
    sp_camera v = *cam;
    v.distortion = SP_DIST_NONE;
    int ds = nav_carve_downscale(o, &v);
    if (ds > 1) sp_camera_downscale(&v, ds);
    if (crop) crop_to_band(&v, cm->band[1]);
    return v;
}

/* One view's first-surface depth from the Gaussians it can show (culled into sub), through
 * *scene (made here the first time) on raster r; pool runs the culling. Adds the Gaussians drawn
 * to *drawn. */
static int render_view(sp_pool *pool, const sp_splat *host, const cull_geo *geo, sp_scene **scene, sp_splat *sub,
                       sp_raster *r, const sp_costmap_opts *o, const sp_camera *view, float *depth, size_t *drawn,
                       sp_error *err)
{
    size_t m = cull_view(pool, host, geo, view, sub);
    *drawn += m;
    if (m == 0) { /* nothing in view: no surface anywhere */
        memset(depth, 0, sizeof(float) * (size_t)view->width * (size_t)view->height);
        return SP_OK;
    }
    /* first-surface depth where the accumulated alpha reaches carve_alpha: expected depth blends a
     * surface's edge with what lies behind it */
    sp_render_request q = {.depth = depth, .depth_mode = SP_DEPTH_SURFACE, .depth_alpha = o->carve_alpha};
    int rc = *scene ? sp_scene_update(*scene, sub, SP_SCENE_CHANGED_GEOMETRY, err)
                    : sp_scene_create(scene, sp_raster_device(r), sub, 0, err); /* made on first use */
    if (!rc) rc = sp_render_views(r, *scene, view, 1, &q, err);
    return rc ? sp_error_prefix(err, "costmap: rendering training views for carving: ") : SP_OK;
}

/* A thread's own renderer (a one-thread CPU device, its raster and scene, its culled splat): on
 * the CPU, carving views are small (160 x 120) and a view's stages split over the pool wait on
 * each other and run their sort and scans serially, so whole views go to the threads instead.
 * The CPU renderer's output does not depend on its thread count: the depth is the same. */
static int use_lanes(sp_device *dev)
{
    return sp_device_kind_of(dev) == SP_DEVICE_CPU && sp_pool_size(sp_device_pool(dev)) > 1;
}

typedef struct render_lane {
    sp_device *dev;
    sp_raster *r;
    sp_scene *scene;
    sp_splat sub;
    size_t drawn;
    int rc;
    sp_error err;
} render_lane;

typedef struct lanes_job {
    render_lane *lane;          /* [threads] */
    const sp_splat *host;
    const cull_geo *geo;
    const sp_costmap_opts *o;
    const sp_camera *views;
    float *const *depth;
    const long *todo;           /* [n_todo] the views to render */
} lanes_job;

static void lanes_view(void *ctx, long i, int thread_id)
{
    const lanes_job *j = ctx;
    render_lane *l = &j->lane[thread_id];
    long k = j->todo[i];
    if (!l->rc)
        l->rc = render_view(sp_device_pool(l->dev), j->host, j->geo, &l->scene, &l->sub, l->r, j->o, &j->views[k],
                            j->depth[k], &l->drawn, &l->err);
}

static void lanes_free(render_lane *lane, int T)
{
    for (int t = 0; lane && t < T; t++) {
        sp_scene_free(lane[t].scene);
        sp_raster_free(lane[t].r);
        sp_device_free(lane[t].dev);
        sp_splat_free(&lane[t].sub);
    }
    free(lane);
}

static int lanes_alloc(render_lane **out, int T, const sp_splat *host, sp_error *err)
{
    render_lane *lane = calloc((size_t)T, sizeof *lane);
    int rc = lane ? SP_OK : sp_error_set(err, SP_E_NOMEM, "costmap: out of memory for %d render lanes", T);
    for (int t = 0; t < T && !rc; t++) {
        if (!(rc = sp_device_create(&lane[t].dev, SP_DEVICE_CPU, 1, err)) && !(rc = sp_raster_create(&lane[t].r, lane[t].dev, err)))
            rc = sp_splat_alloc(&lane[t].sub, host->n, 0, 0, err);
    }
    if (rc) lanes_free(lane, T), lane = NULL;
    *out = lane;
    return rc;
}

/* Renders the views render[] asks for, side by side on the CPU (render lanes), one after the
 * other on a GPU (whose passes fill the device) through *scene and sub. */
static int render_views(const sp_splat *host, const cull_geo *geo, sp_scene **scene, sp_splat *sub, sp_raster *r,
                        const sp_costmap_opts *o, sp_camera *views, float *const *depth, const uint8_t *render,
                        size_t n, size_t *drawn, const sp_log *log, sp_error *err)
{
    sp_device *dev = sp_raster_device(r);
    sp_pool *pool = sp_device_pool(dev);
    int T = sp_pool_size(pool), rc = SP_OK;
    sp_progress pr;
    sp_progress_begin(&pr, log, "carve", (long)n, "views");
    if (use_lanes(dev)) {
        long *todo = malloc(sizeof(long) * (n ? n : 1)), n_todo = 0;
        render_lane *lane = NULL;
        if (!todo) rc = sp_error_set(err, SP_E_NOMEM, "costmap: out of memory for %zu carving views", n);
        if (!rc) rc = lanes_alloc(&lane, T, host, err);
        /* in batches, for the progress line */
        for (size_t k0 = 0; k0 < n && !rc; k0 += 4 * CARVE_BATCH) {
            n_todo = 0;
            for (size_t k = k0; k < n && k < k0 + 4 * CARVE_BATCH; k++)
                if (render[k]) todo[n_todo++] = (long)k;
            lanes_job job = {lane, host, geo, o, views, depth, todo};
            sp_pool_for(pool, n_todo, lanes_view, &job);
            for (int t = 0; t < T && !rc; t++)
                if (lane[t].rc) rc = lane[t].rc, *err = lane[t].err;
            sp_progress_update(&pr, (long)(k0 + 4 * CARVE_BATCH < n ? k0 + 4 * CARVE_BATCH : n), NULL);
        }
        for (int t = 0; lane && t < T; t++) *drawn += lane[t].drawn;
        lanes_free(lane, T);
        free(todo);
    } else {
        for (size_t k = 0; k < n && !rc; k++) {
            if (render[k]) rc = render_view(pool, host, geo, scene, sub, r, o, &views[k], depth[k], drawn, err);
            if (k % CARVE_BATCH == CARVE_BATCH - 1 || k + 1 == n) sp_progress_update(&pr, (long)k + 1, NULL);
        }
    }
    sp_progress_end(&pr, NULL);
    return rc;
}

/* Views, depth buffers and runs of the carving, rendered; freed by carving_free. */
typedef struct carving {
    sp_camera *views;
    float **depth;
    float *pixels;
    int *order, *run_start;
    uint8_t *keep, *render; /* [views] traced; rendered (the kept, or all for view counts) */
    int n_scans, n_runs, n_kept;
} carving;

static void carving_free(carving *c)
{
    free(c->views), free(c->depth), free(c->pixels), free(c->order), free(c->run_start);
    free(c->keep), free(c->render);
}

static int carving_alloc(carving *c, const sp_costmap *cm, const sp_costmap_opts *o, const sp_camera *cams, size_t n,
                         int counts, sp_error *err)
{
    memset(c, 0, sizeof *c);
    c->views = malloc(sizeof(sp_camera) * n);
    c->depth = malloc(sizeof(float *) * n);
    c->order = malloc(sizeof(int) * n * 2);
    c->run_start = malloc(sizeof(int) * (n + 1));
    c->keep = malloc(n ? n : 1);
    c->render = malloc(n ? n : 1);
    if (!c->views || !c->depth || !c->order || !c->run_start || !c->keep || !c->render)
        return sp_error_set(err, SP_E_NOMEM, "costmap: out of memory for %zu carving views", n);
    c->n_scans = group_scans(cams, n, c->order, c->order + n);
    c->n_runs = split_runs(c->order, c->order + n, n, c->run_start);
    size_t px = 0;
    for (size_t k = 0; k < n; k++) {
        c->views[k] = carving_view(cm, o, &cams[c->order[k]], !counts);
        px += (size_t)c->views[k].width * (size_t)c->views[k].height;
    }
    c->n_kept = 0;
    for (int r = 0; r < c->n_runs; r++)
        c->n_kept += select_views(c->views, c->run_start[r], c->run_start[r + 1], o->carve_min_fresh, c->keep);
    for (size_t k = 0; k < n; k++) c->render[k] = c->keep[k] || counts;
    if (!(c->pixels = malloc(sizeof(float) * (px ? px : 1))))
        return sp_error_set(err, SP_E_NOMEM, "costmap: out of memory for %zu carving pixels", px);
    px = 0;
    for (size_t k = 0; k < n; k++) {
        c->depth[k] = c->pixels + px;
        px += (size_t)c->views[k].width * (size_t)c->views[k].height;
    }
    return SP_OK;
}

/* All views are rendered first (their depth kept: 4 bytes a pixel, 11 MB for 150 views of
 * 160 x 120), the floor tolerance measured on them, then every run carved in one parallel loop. */
int nav_carve(const sp_costmap *cm, const sp_splat *s, const sp_camera *cams, size_t n_cams,
              const sp_costmap_opts *o, sp_raster *r, nav_carve_out *out, const sp_log *log,
              sp_error *err)
{
    sp_device *dev = sp_raster_device(r);
    sp_scene *scene = NULL;
    sp_splat host, sub;
    cull_geo geo = {NULL, 0};
    memset(&sub, 0, sizeof sub);
    int rc = carving_splat(s, cams, n_cams, cm->band[1], &host, &geo, err);
    if (rc) return sp_error_prefix(err, "costmap: ");
    size_t kept = host.n, drawn = 0;
    if (!use_lanes(dev)) rc = sp_splat_alloc(&sub, kept, 0, 0, err); /* the lanes have their own */
    if (rc) {
        sp_splat_free(&host), sp_splat_free(&sub), free(geo.rows);
        return sp_error_prefix(err, "costmap: ");
    }
    sp_pool *pool = sp_device_pool(dev);
    int T = sp_pool_size(pool);
    carving c = {0};
    carve_thread *th = threads_alloc(T, out, s->n);
    if (!th) rc = sp_error_set(err, SP_E_NOMEM, "costmap: out of memory for %d carving threads", T);
    if (!rc) rc = carving_alloc(&c, cm, o, cams, n_cams, out->view_counts != NULL, err);
    double t0 = nav_cpu_now(), w0 = sp_time_now();
    if (!rc) rc = render_views(&host, &geo, &scene, &sub, r, o, c.views, c.depth, c.render, n_cams, &drawn, log, err);
    double t1 = nav_cpu_now(), w1 = sp_time_now();
    long excess = 0;
    out->floor_tol = rc ? o->floor_tolerance_m : floor_tolerance(cm, o, c.views, c.depth, c.keep, n_cams, &excess);
    if (!rc) {
        carve_job job = {cm, s, o, &out->sl, c.views, c.depth, c.run_start, c.keep, out->floor_tol, th};
        sp_pool_for(pool, c.n_runs, carve_run, &job);
        for (int t = 0; t < T; t++)
            if (th[t].failed) rc = sp_error_set(err, SP_E_NOMEM, "costmap: out of memory carving");
    }
    double t2 = nav_cpu_now(), w2 = sp_time_now();
    size_t n_rendered = 0;
    for (size_t k = 0; c.render && k < n_cams; k++) n_rendered += c.render[k];
    sp_logf(log, SP_LOG_DEBUG, "carve: %zu views in %d scans, %d traced (the rest shown by their scan's), %zu of "
            "%zu Gaussians below the cameras, %.0f per rendered view in its frustum; floor tolerance %.2f m (%ld "
            "floor points); CPU / wall time: renders %.0f / %.0f ms, rays %.0f / %.0f ms", n_cams, c.n_scans,
            c.n_kept, kept, s->n, n_rendered ? (double)drawn / (double)n_rendered : 0.0, out->floor_tol, excess, 1e3 * (t1 - t0), 1e3 * (w1 - w0),
            1e3 * (t2 - t1), 1e3 * (w2 - w1));
    size_t nv = (size_t)out->sl.cells * out->sl.n, nc = (size_t)out->sl.cells;
    for (int t = 1; th && t < T; t++) {
        add_sat(out->hit_scans, th[t].hit_scans, nv);
        add_sat(out->miss_scans, th[t].miss_scans, nv);
        add_sat(out->near_scans, th[t].near_scans, nv);
        add_sat(out->floor_scans, th[t].floor_scans, nc);
        if (out->view_counts) add_sat(out->view_counts, th[t].view_counts, s->n);
    }
    threads_free(th, T);
    carving_free(&c);
    sp_scene_free(scene);
    sp_splat_free(&host), sp_splat_free(&sub), free(geo.rows);
    return rc;
}
