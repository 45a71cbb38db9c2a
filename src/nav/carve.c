/* Free space from the training cameras: each view is rendered (first-surface depth and alpha)
 * at reduced size, and every ray that hits a surface marks the voxels (cell x height slice of
 * the robot's band) it crosses as passed, up to a little before the surface; the surface point
 * itself is a hit (or a floor sighting). Space no ray crossed stays unknown. The same renders
 * count, per Gaussian, the training views that see it (the coverage behind localizability). */
#include <stdlib.h>
#include <string.h>

#include "nav_internal.h"

#define VIS_MIN_ALPHA 0.3f     /* pixels with less alpha have no usable depth for visibility */
#define VIS_DEPTH_REL 1.05f    /* a Gaussian in front of rendered depth x this + VIS_DEPTH_ABS */
#define VIS_DEPTH_ABS 0.05f

int nav_traverse(const sp_costmap *cm, const float a[2], const float b[2], nav_cell_fn fn,
                 void *ctx)
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
        double tn = fmin(fmin(tmx, tmy), 1.0);
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

typedef struct ray_ctx {
    uint16_t *passes;
    const nav_slices *sl;
    float z0, dz;      /* z(t) = z0 + t dz */
    float t_stop;      /* carve up to here */
    float band_lo, band_hi;
} ray_ctx;

static inline void bump(uint16_t *c)
{
    if (*c < UINT16_MAX) (*c)++;
}

/* Marks every slice of the cell the ray's stretch inside it overlaps. */
static int carve_cell(void *vctx, long cell, float t0, float t1)
{
    ray_ctx *c = vctx;
    if (t0 >= c->t_stop) return 1;
    float te = fminf(t1, c->t_stop);
    float za = c->z0 + t0 * c->dz, zb = c->z0 + te * c->dz;
    float lo = fmaxf(fminf(za, zb), c->band_lo), hi = fminf(fmaxf(za, zb), c->band_hi);
    if (hi < lo) return 0;
    int v0 = nav_slice_of(c->sl, lo), v1 = nav_slice_of(c->sl, hi);
    for (int v = v0; v <= v1; v++) bump(&c->passes[v * c->sl->cells + cell]);
    return 0;
}

/* The counters one thread carves into (merged after the last view). */
typedef struct carve_bufs {
    uint16_t *passes, *hits, *floor_seen;
} carve_bufs;

typedef struct view_job {
    const sp_costmap *cm;
    const sp_camera *cam;
    const float *depth, *alpha;
    const sp_costmap_opts *o;
    const nav_slices *sl;
    carve_bufs *bufs;   /* [threads] */
    int rows_per_item;
    const sp_splat *s;
    uint16_t *counts;   /* visibility */
    size_t per_item;
} view_job;

/* Carves the rays of rows [v0, v1) of one rendered view (first-surface depth and alpha). */
static void carve_rows(const view_job *j, int v0, int v1, carve_bufs *b)
{
    const sp_costmap *cm = j->cm;
    const sp_camera *cam = j->cam;
    const sp_costmap_opts *o = j->o;
    sp_vec3 C = sp_camera_center(cam);
    ray_ctx rc = {b->passes, j->sl, C.z, 0, 1, cm->band[0], cm->band[1]};
    float Rt[9];
    sp_mat3_transpose(cam->R, Rt);
    for (int v = v0; v < v1; v++)
        for (int u = 0; u < cam->width; u++) {
            long p = (long)v * cam->width + u;
            if (!(j->alpha[p] >= o->carve_alpha)) continue;
            float d = j->depth[p]; /* first-surface depth along the optical axis */
            if (!(d > 0)) continue;
            sp_vec3 dc = sp_v3((u + 0.5f - cam->cx) / cam->fx, (v + 0.5f - cam->cy) / cam->fy, 1.0f);
            sp_vec3 dw = sp_mat3_apply(Rt, dc);
            float len = d * sp_v3_norm(dw);
            int cut = len > o->max_range_m;
            if (cut) d *= o->max_range_m / len, len = o->max_range_m;
            sp_vec3 P = sp_v3_add(C, sp_v3_scale(dw, d));
            rc.dz = P.z - C.z;
            rc.t_stop = cut ? 1.0f : fmaxf(0.0f, 1.0f - o->carve_stop_m / len);
            float a[2] = {C.x, C.y}, e[2] = {P.x, P.y};
            nav_traverse(cm, a, e, carve_cell, &rc);
            int ix, iy;
            if (cut || sp_costmap_cell(cm, P.x, P.y, &ix, &iy)) continue;
            long cell = nav_idx(cm, ix, iy);
            if (fabsf(P.z - cm->floor_z) < o->floor_tolerance_m) bump(&b->floor_seen[cell]);
            else if (P.z >= cm->band[0] && P.z <= cm->band[1])
                bump(&b->hits[nav_slice_of(j->sl, P.z) * j->sl->cells + cell]);
        }
}

static void carve_item(void *ctx, long i, int thread_id)
{
    const view_job *j = ctx;
    int v0 = (int)i * j->rows_per_item, v1 = v0 + j->rows_per_item;
    carve_rows(j, v0, v1 < j->cam->height ? v1 : j->cam->height, &j->bufs[thread_id]);
}

/* Counts the view for every opaque Gaussian whose centre projects into it in front of the
 * rendered surface: the deepest surface of the 3 x 3 pixels around it (a low-resolution pixel on
 * a floor seen at a slant spans tens of centimetres of depth), with 5 % + 5 cm to spare. */
static void count_visible(const sp_splat *s, const sp_camera *cam, const float *depth,
                          const float *alpha, float min_opacity, uint16_t *counts, size_t i0, size_t i1)
{
    for (size_t i = i0; i < i1; i++) {
        if (counts[i] == UINT16_MAX || sp_sigmoid(s->opacity_logits[i]) < min_opacity) continue;
        const float *m = s->means + 3 * i;
        sp_vec3 pc = sp_v3_add(sp_mat3_apply(cam->R, sp_v3(m[0], m[1], m[2])),
                               sp_v3(cam->t[0], cam->t[1], cam->t[2]));
        if (pc.z < 0.05f) continue;
        int u = (int)floorf(cam->fx * pc.x / pc.z + cam->cx), v = (int)floorf(cam->fy * pc.y / pc.z + cam->cy);
        if (u < 0 || v < 0 || u >= cam->width || v >= cam->height) continue;
        float deepest = -1;
        for (int dv = -1; dv <= 1; dv++)
            for (int du = -1; du <= 1; du++) {
                int x = u + du, y = v + dv;
                if (x < 0 || y < 0 || x >= cam->width || y >= cam->height) continue;
                long p = (long)y * cam->width + x;
                if (alpha[p] >= VIS_MIN_ALPHA && depth[p] > deepest) deepest = depth[p];
            }
        if (deepest > 0 && pc.z <= deepest * VIS_DEPTH_REL + VIS_DEPTH_ABS) counts[i]++;
    }
}

static void visible_item(void *ctx, long i, int thread_id)
{
    const view_job *j = ctx;
    size_t i0 = (size_t)i * j->per_item, i1 = i0 + j->per_item;
    (void)thread_id;
    count_visible(j->s, j->cam, j->depth, j->alpha, j->o->min_opacity, j->counts, i0, i1 < j->s->n ? i1 : j->s->n);
}

static inline void add_sat(uint16_t *dst, const uint16_t *src, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        unsigned v = (unsigned)dst[i] + src[i];
        dst[i] = v > UINT16_MAX ? UINT16_MAX : (uint16_t)v;
    }
}

#define CARVE_BATCH 16 /* views rendered per sp_render_views call */

int nav_carve(const sp_costmap *cm, const sp_splat *s, const sp_camera *cams, size_t n_cams,
              const sp_costmap_opts *o, sp_raster *r, nav_carve_out *out, const sp_log *log,
              sp_error *err)
{
    /* geometry only: depth and alpha need no colours, so no SH is evaluated per view */
    sp_scene *scene = NULL;
    int rc = sp_scene_create(&scene, sp_raster_device(r), s, 0, err);
    if (rc) return sp_error_prefix(err, "costmap: ");
    sp_pool *pool = sp_device_pool(sp_raster_device(r));
    int T = sp_pool_size(pool);
    size_t nv = (size_t)out->sl.cells * out->sl.n, nc = (size_t)out->sl.cells;
    carve_bufs *bufs = calloc((size_t)T, sizeof *bufs);
    if (!bufs) rc = sp_error_set(err, SP_E_NOMEM, "costmap: out of memory");
    for (int t = 0; t < T && !rc; t++) {
        bufs[t].passes = t ? calloc(nv, sizeof(uint16_t)) : out->passes;
        bufs[t].hits = t ? calloc(nv, sizeof(uint16_t)) : out->hits;
        bufs[t].floor_seen = t ? calloc(nc, sizeof(uint16_t)) : out->floor_seen;
        if (!bufs[t].passes || !bufs[t].hits || !bufs[t].floor_seen)
            rc = sp_error_set(err, SP_E_NOMEM, "costmap: out of memory for %d carving threads", T);
    }
    sp_camera view[CARVE_BATCH];
    sp_render_request req[CARVE_BATCH];
    float *buf[CARVE_BATCH] = {NULL};
    size_t cap[CARVE_BATCH] = {0};
    double t_render = 0, t_rays = 0, t_vis = 0;
    sp_progress pr;
    sp_progress_begin(&pr, log, "carve", (long)n_cams, "views");
    for (size_t c0 = 0; c0 < n_cams && !rc; c0 += CARVE_BATCH) {
        size_t nb = n_cams - c0 < CARVE_BATCH ? n_cams - c0 : CARVE_BATCH;
        for (size_t k = 0; k < nb && !rc; k++) {
            view[k] = cams[c0 + k];
            view[k].distortion = SP_DIST_NONE;
            if (o->carve_downscale > 1) sp_camera_downscale(&view[k], o->carve_downscale);
            size_t np = (size_t)(view[k].width > 0 ? view[k].width : 1) * (view[k].height > 0 ? view[k].height : 1);
            if (np > cap[k]) {
                free(buf[k]);
                buf[k] = malloc(sizeof(float) * 2 * np);
                cap[k] = np;
                if (!buf[k]) rc = sp_error_set(err, SP_E_NOMEM, "costmap: out of memory for %zu-pixel renders", np);
            }
            /* first-surface depth where the accumulated alpha reaches carve_alpha: expected depth
             * blends a surface's edge with what lies behind it */
            memset(&req[k], 0, sizeof req[k]);
            req[k].depth = buf[k];
            req[k].alpha = buf[k] ? buf[k] + np : NULL;
            req[k].depth_mode = SP_DEPTH_SURFACE;
            req[k].depth_alpha = o->carve_alpha;
        }
        double t0 = sp_time_now();
        if (!rc && (rc = sp_render_views(r, scene, view, nb, req, err))) {
            sp_error_prefix(err, "costmap: rendering training views %zu..%zu for carving: ", c0, c0 + nb - 1);
            break;
        }
        t_render += sp_time_now() - t0;
        for (size_t k = 0; k < nb && !rc; k++) {
            double t1 = sp_time_now();
            view_job job = {cm, &view[k], req[k].depth, req[k].alpha, o, &out->sl, bufs, 0, s, out->view_counts, 0};
            job.rows_per_item = (view[k].height + 4 * T - 1) / (4 * T);
            if (job.rows_per_item > 0)
                sp_pool_for(pool, (view[k].height + job.rows_per_item - 1) / job.rows_per_item, carve_item, &job);
            double t2 = sp_time_now();
            job.per_item = (s->n + 16 * T - 1) / (16 * T);
            if (out->view_counts && s->n)
                sp_pool_for(pool, (long)((s->n + job.per_item - 1) / job.per_item), visible_item, &job);
            t_rays += t2 - t1, t_vis += sp_time_now() - t2;
        }
        sp_progress_update(&pr, (long)(c0 + nb), NULL);
    }
    sp_progress_end(&pr, NULL);
    sp_logf(log, SP_LOG_DEBUG, "carve: renders %.0f ms, rays %.0f ms, visibility %.0f ms", 1e3 * t_render,
            1e3 * t_rays, 1e3 * t_vis);
    for (int t = 1; bufs && t < T; t++) {
        if (bufs[t].passes) add_sat(out->passes, bufs[t].passes, nv);
        if (bufs[t].hits) add_sat(out->hits, bufs[t].hits, nv);
        if (bufs[t].floor_seen) add_sat(out->floor_seen, bufs[t].floor_seen, nc);
        free(bufs[t].passes), free(bufs[t].hits), free(bufs[t].floor_seen);
    }
    free(bufs);
    for (int k = 0; k < CARVE_BATCH; k++) free(buf[k]);
    sp_scene_free(scene);
    return rc;
}
