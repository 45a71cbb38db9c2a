/* Localization of a text query: 3D-native (relevant Gaussians clustered into instances) and
 * multi-view (relevant pixels of rendered views back-projected with rendered depth, then the same
 * clustering). Both share a voxel clustering that separates instances (several chairs) and gives
 * each a robust centre (middle of the 5%..95% weighted extent) rather than a mean that one stray
 * Gaussian could drag. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sem_cuda.h"
#include "sem_internal.h"

/* ---- voxel clustering -------------------------------------------------------------------------- */

typedef sem_keyed keyed;

#define KEY_BITS 21
#define KEY_OFF (1 << (KEY_BITS - 1))

static uint64_t pack(long ix, long iy, long iz)
{
    return ((uint64_t)(ix + KEY_OFF) << (2 * KEY_BITS)) | ((uint64_t)(iy + KEY_OFF) << KEY_BITS) |
           (uint64_t)(iz + KEY_OFF);
}

static long find_root(long *parent, long i)
{
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

typedef struct {
    float v, w;
} vw;

/* Weighted quantile of sorted values. */
static float wquantile(const vw *s, size_t m, double total, double q)
{
    double acc = 0, target = q * total;
    for (size_t i = 0; i < m; i++) {
        acc += s[i].w;
        if (acc >= target) return s[i].v;
    }
    return s[m - 1].v;
}

int sem_cluster(const float *pts, const float *w, const float *conf, size_t m, float voxel,
                float min_fraction, float min_voxel_weight, sp_query_instance **out, int *n_out,
                sp_error *err)
{
    *out = NULL;
    *n_out = 0;
    if (m == 0) return 0;
    if (!(voxel > 0)) return sp_error_set(err, SP_E_ARG, "cluster: voxel size %g must be > 0", (double)voxel);
    float lo[3] = {FLT_MAX, FLT_MAX, FLT_MAX}, hi[3] = {-FLT_MAX, -FLT_MAX, -FLT_MAX};
    for (size_t i = 0; i < m; i++)
        for (int a = 0; a < 3; a++) {
            if (pts[i * 3 + a] < lo[a]) lo[a] = pts[i * 3 + a];
            if (pts[i * 3 + a] > hi[a]) hi[a] = pts[i * 3 + a];
        }
    for (int a = 0; a < 3; a++) /* keep the grid inside the key range for huge scenes */
        while ((hi[a] - lo[a]) / voxel > (float)(KEY_OFF - 2)) voxel *= 2;
    keyed *k = malloc(sizeof *k * m), *tmp = malloc(sizeof *tmp * 2 * m); /* sort scratch */
    long *parent = NULL, *vox_of = NULL, *comp = NULL;
    double *cw = NULL;
    sp_query_instance *inst = NULL;
    vw *buf = NULL;
    uint32_t *members = NULL;
    size_t *start = NULL;
    int rc = 0;
    if (!k || !tmp) goto nomem;
    /* Sorted by a dense key (the three cell indices side by side in only the bits they need),
     * which orders like pack()'s key (x, then y, then z) in fewer radix passes; floorf is
     * monotonic, so each axis's largest index is that of hi. */
    int bits[3];
    for (int a = 0; a < 3; a++) {
        uint64_t top = (uint64_t)floorf((hi[a] - lo[a]) / voxel);
        bits[a] = 0;
        while (top >> bits[a]) bits[a]++;
    }
    const int sy = bits[2], sx = bits[1] + bits[2];
    for (size_t i = 0; i < m; i++) {
        uint64_t ix = (uint64_t)floorf((pts[i * 3] - lo[0]) / voxel);
        uint64_t iy = (uint64_t)floorf((pts[i * 3 + 1] - lo[1]) / voxel);
        uint64_t iz = (uint64_t)floorf((pts[i * 3 + 2] - lo[2]) / voxel);
        k[i].key = ix << sx | iy << sy | iz;
        k[i].idx = (uint32_t)i;
    }
    sem_sort_keyed(k, tmp, m); /* k was in index order: now by (key, index) */
    /* unique voxels: vox_of[j] = voxel id of sorted entry j; voxel v starts at first[v] */
    vox_of = malloc(sizeof(long) * m);
    if (!vox_of) goto nomem;
    long nv = 0;
    for (size_t j = 0; j < m; j++) {
        if (j > 0 && k[j].key == k[j - 1].key) vox_of[j] = nv - 1;
        else vox_of[j] = nv++;
    }
    uint64_t *vkey = malloc(sizeof(uint64_t) * (size_t)nv);
    parent = malloc(sizeof(long) * (size_t)nv);
    if (!vkey || !parent) {
        free(vkey);
        goto nomem;
    }
    for (size_t j = 0; j < m; j++)
        if (j == 0 || k[j].key != k[j - 1].key) {
            uint64_t d = k[j].key;
            vkey[vox_of[j]] = pack((long)(d >> sx), (long)((d >> sy) & (((uint64_t)1 << bits[1]) - 1)),
                                   (long)(d & (((uint64_t)1 << bits[2]) - 1)));
        }
    for (long v = 0; v < nv; v++) parent[v] = v;
    /* sparse voxels (stray points that would bridge two instances) take no part */
    double *vweight = calloc((size_t)nv, sizeof(double));
    if (!vweight) {
        free(vkey);
        goto nomem;
    }
    for (size_t j = 0; j < m; j++) vweight[vox_of[j]] += w[k[j].idx];
    /* The 13 neighbours after a voxel in key order: (0,0,+1), then (dx,dy) = (0,1), (1,-1),
     * (1,0), (1,1) with dz = -1..1, three consecutive keys each (pack() is linear in the cell
     * indices, which never leave their fields). Their keys grow with v, so one forward cursor
     * per (dx,dy) finds them in a single sweep, in the same order as a search per neighbour. */
    const uint64_t X = (uint64_t)1 << (2 * KEY_BITS), Y = (uint64_t)1 << KEY_BITS;
    const uint64_t step[4] = {Y - 1, X - Y - 1, X - 1, X + Y - 1};
    long cur[4] = {0, 0, 0, 0};
    for (long v = 0; v < nv; v++) {
        if (vweight[v] < min_voxel_weight) continue;
        long hits[13], nh = 0;
        if (v + 1 < nv && vkey[v + 1] == vkey[v] + 1) hits[nh++] = v + 1;
        for (int g = 0; g < 4; g++) {
            uint64_t base = vkey[v] + step[g];
            long c = cur[g];
            while (c < nv && vkey[c] < base) c++;
            cur[g] = c;
            for (long h = c; h < nv && vkey[h] <= base + 2; h++) hits[nh++] = h;
        }
        for (long t = 0; t < nh; t++) {
            long hit = hits[t];
            if (vweight[hit] < min_voxel_weight) continue;
            long ra = find_root(parent, v), rb = find_root(parent, hit);
            if (ra != rb) parent[ra > rb ? ra : rb] = ra < rb ? ra : rb;
        }
    }
    free(vkey);
    /* components: comp id per root (-1 for sparse voxels), weights */
    comp = malloc(sizeof(long) * (size_t)nv);
    cw = calloc((size_t)nv, sizeof(double));
    if (!comp || !cw) goto nomem;
    long nc = 0;
    for (long v = 0; v < nv; v++) comp[v] = -1;
    for (long v = 0; v < nv; v++) {
        if (vweight[v] < min_voxel_weight) continue;
        long r = find_root(parent, v);
        if (comp[r] < 0) comp[r] = nc++;
        comp[v] = comp[r];
    }
    free(vweight);
    for (size_t j = 0; j < m; j++)
        if (comp[vox_of[j]] >= 0) cw[comp[vox_of[j]]] += w[k[j].idx];
    double best = 0;
    for (long c = 0; c < nc; c++)
        if (cw[c] > best) best = cw[c];
    if (!(best > 0)) goto done;
    int n_keep = 0;
    for (long c = 0; c < nc; c++)
        if (cw[c] >= min_fraction * best) n_keep++;
    inst = calloc((size_t)n_keep, sizeof *inst);
    buf = malloc(sizeof(vw) * m);
    members = malloc(sizeof(uint32_t) * m);
    if (!inst || !buf || !members) goto nomem;
    /* each kept component's points, in sorted (voxel) order, bucketed in one pass: start[c] is
     * where component c's run begins in members (dropped components get none) */
    start = calloc((size_t)nc + 1, sizeof *start);
    if (!start) goto nomem;
    for (size_t j = 0; j < m; j++) {
        long c = comp[vox_of[j]];
        if (c >= 0 && cw[c] >= min_fraction * best) start[c + 1]++;
    }
    for (long c = 0; c < nc; c++) start[c + 1] += start[c];
    for (size_t j = 0; j < m; j++) {
        long c = comp[vox_of[j]];
        if (c >= 0 && cw[c] >= min_fraction * best) members[start[c]++] = k[j].idx;
    }
    int ni = 0;
    size_t run = 0; /* start[c] now ends component c's run */
    for (long c = 0; c < nc; c++) {
        if (cw[c] < min_fraction * best) continue;
        sp_query_instance *I = &inst[ni++];
        I->score = (float)cw[c];
        I->confidence = -1;
        const uint32_t *mem = members + run;
        size_t cnt = start[c] - run;
        run = start[c];
        for (size_t t = 0; conf && t < cnt; t++)
            if (conf[mem[t]] > I->confidence) I->confidence = conf[mem[t]];
        for (int a = 0; a < 3; a++) {
            /* values by size, ties in member order (a stable sort) */
            for (size_t t = 0; t < cnt; t++) {
                tmp[t].key = sem_float_order(pts[mem[t] * 3 + a]);
                tmp[t].idx = mem[t];
            }
            sem_sort_keyed(tmp, tmp + cnt, cnt);
            for (size_t t = 0; t < cnt; t++) buf[t].v = pts[tmp[t].idx * 3 + a], buf[t].w = w[tmp[t].idx];
            I->extent_min[a] = wquantile(buf, cnt, cw[c], 0.05);
            I->extent_max[a] = wquantile(buf, cnt, cw[c], 0.95);
            I->position[a] = 0.5f * (I->extent_min[a] + I->extent_max[a]);
            I->n_points = (int)cnt;
        }
    }
    /* heaviest first, ties in component order: a stable sort on descending score. Many
     * instances (stray points kept by a low cut) by radix on the scores' order keys (scores are
     * sums from +0, never -0); a few, or any NaN, by insertion as before. */
    int nan_score = 0;
    for (int i = 0; i < ni; i++) nan_score |= isnan(inst[i].score);
    if (ni > 16 && !nan_score) {
        sp_query_instance *sorted = malloc(sizeof *sorted * (size_t)ni);
        if (!sorted) goto nomem;
        for (int i = 0; i < ni; i++) {
            tmp[i].key = ~sem_float_order(inst[i].score) & 0xffffffffu;
            tmp[i].idx = (uint32_t)i;
        }
        sem_sort_keyed(tmp, tmp + ni, (size_t)ni);
        for (int i = 0; i < ni; i++) sorted[i] = inst[tmp[i].idx];
        free(inst);
        inst = sorted;
    }
    for (int i = 1; i < ni; i++) {
        sp_query_instance t = inst[i];
        int j = i - 1;
        while (j >= 0 && inst[j].score < t.score) {
            inst[j + 1] = inst[j];
            j--;
        }
        inst[j + 1] = t;
    }
    *out = inst;
    *n_out = ni;
    inst = NULL;
    goto done;
nomem:
    rc = sp_error_set(err, SP_E_NOMEM, "cluster: out of memory for %zu points", m);
done:
    free(k);
    free(parent);
    free(vox_of);
    free(comp);
    free(cw);
    free(inst);
    free(buf);
    free(members);
    free(start);
    free(tmp);
    return rc;
}

/* ---- 3D-native ----------------------------------------------------------------------------------- */

static void set_best(sp_query_result *res, float min_conf)
{
    if (res->n_instances > 0 && res->confidence >= min_conf) {
        res->valid = 1;
        memcpy(res->position, res->instances[0].position, sizeof res->position);
    } else {
        res->valid = 0;
        res->position[0] = res->position[1] = res->position[2] = NAN;
    }
}

int sem_localize_3d(sp_query_engine *e, const sp_sem_scorer *sc, const sem_thresholds *th,
                    sp_query_result *res, sp_error *err)
{
    (void)sc;
    const sp_splat *s = &e->splat;
    size_t m = 0;
    for (size_t i = 0; i < s->n; i++)
        if (e->raw[i] >= th->thr_raw && e->rel[i] >= th->thr_rel && e->opacity[i] >= th->min_op) m++;
    if (m == 0) {
        set_best(res, th->opts->min_confidence);
        return 0;
    }
    float *pts = malloc(sizeof(float) * 3 * m), *w = malloc(sizeof(float) * m),
          *cf = malloc(sizeof(float) * m);
    if (!pts || !w || !cf) {
        free(pts), free(w), free(cf);
        return sp_error_set(err, SP_E_NOMEM, "3D localization: out of memory");
    }
    size_t j = 0;
    for (size_t i = 0; i < s->n; i++) {
        if (!(e->raw[i] >= th->thr_raw && e->rel[i] >= th->thr_rel && e->opacity[i] >= th->min_op))
            continue;
        memcpy(pts + 3 * j, s->means + 3 * i, sizeof(float) * 3);
        /* opacity-weighted, times how far above neutral the relevancy is */
        w[j] = e->opacity[i] * (e->rel[i] - 0.5f + 1e-3f);
        cf[j] = e->raw[i];
        j++;
    }
    int rc = sem_cluster(pts, w, cf, m, th->opts->voxel_m, th->opts->min_instance_fraction, 0.0f,
                         &res->instances, &res->n_instances, err);
    free(pts), free(w), free(cf);
    if (rc) return rc;
    set_best(res, th->opts->min_confidence);
    return 0;
}

/* ---- views ---------------------------------------------------------------------------------------- */

int sem_score_pixels(sp_query_engine *e, const sp_sem_scorer *sc, const float *feat,
                     const float *alpha, size_t npix, float *raw, float *rel, sp_error *err)
{
    int D = sc->dim;
    /* Scoring the un-normalised composite instead would be another computation (decode(f)
     * includes the PCA mean, so scaling f by alpha changes the cosine): fail instead. */
    float *norm = malloc(sizeof(float) * npix * (size_t)D);
    if (!norm)
        return sp_error_set(err, SP_E_NOMEM, "query: out of memory scoring %zu pixels x %d features",
                            npix, D);
    for (size_t p = 0; p < npix; p++) {
        float a = alpha[p] > 1e-6f ? alpha[p] : 1.0f;
        for (int c = 0; c < D; c++) norm[p * D + c] = feat[p * D + c] / a;
    }
    sp_sem_score(sc, sp_device_pool(e->dev), npix, norm, raw, rel);
    for (size_t p = 0; p < npix; p++)
        if (!(alpha[p] > 0.5f)) {
            if (raw) raw[p] = -1;
            if (rel) rel[p] = 0.5f;
        }
    free(norm);
    return 0;
}

/* The engine's splat as a scene (RGB and features), uploaded once on first use. */
static int ensure_scene(sp_query_engine *e, sp_error *err)
{
    if (e->scene) return 0;
    return sp_scene_create(&e->scene, e->dev, &e->splat, SP_SCENE_RGB | SP_SCENE_FEATURES, err);
}

int sem_device_stages(const sp_query_engine *e, int host_stages)
{
    return e->d_feat && e->dev_scores && !host_stages;
}

int sem_scores_scene(sp_query_engine *e, sp_error *err)
{
    const sp_splat *s = &e->splat;
    int dev = e->d_scores2 && e->dev_scores;
    if (!e->scores_scene || !dev)
        for (size_t i = 0; i < s->n; i++) e->scores2[2 * i] = e->raw[i], e->scores2[2 * i + 1] = e->rel[i];
    /* a view of the splat whose "features" are the scores: its scene keeps the geometry and SH
     * and takes only the new scores with every query */
    sp_splat view = *s;
    view.features = e->scores2;
    view.feat_dim = 2;
    if (!e->scores_scene)
        return sp_scene_create(&e->scores_scene, e->dev, &view, SP_SCENE_RGB | SP_SCENE_FEATURES, err);
    if (!dev) return sp_scene_update(e->scores_scene, &view, SP_SCENE_CHANGED_FEATURES, err);
    int rc = sem_cuda_interleave(e->dev, s->n, e->d_raw, e->d_rel, e->d_scores2, err);
    return rc ? rc : sp_scene_copy_features(e->scores_scene, e->d_scores2, err);
}

int sem_render_scores(sp_query_engine *e, const sp_camera *cam, float *raw, float *rel, float *rgb,
                      sp_error *err)
{
    size_t np = (size_t)cam->width * cam->height;
    float *two = malloc(sizeof(float) * np * 2), *alpha = malloc(sizeof(float) * np);
    if (!two || !alpha) {
        free(two), free(alpha);
        return sp_error_set(err, SP_E_NOMEM, "query: out of memory rendering %dx%d", cam->width, cam->height);
    }
    /* scores and RGB of one projection and sort */
    sp_render_request req = {.rgb = rgb, .features = two, .alpha = alpha};
    int rc = sem_scores_scene(e, err);
    if (!rc) rc = sp_render_views(e->raster, e->scores_scene, cam, 1, &req, err);
    if (!rc)
        for (size_t p = 0; p < np; p++) {
            int ok = alpha[p] > 0.5f;
            raw[p] = ok ? two[2 * p] / alpha[p] : -1.0f;
            rel[p] = ok ? two[2 * p + 1] / alpha[p] : 0.5f;
        }
    free(two), free(alpha);
    return rc;
}

/* Renders view v at 1/ds resolution; returns the camera used and buffers (caller frees). */
static int render_view(sp_query_engine *e, int v, int ds, sp_camera *cam, float **feat,
                       float **depth, float **alpha, float **rgb, sp_error *err)
{
    *cam = e->cams[v];
    if (ds > 1) sp_camera_downscale(cam, ds);
    size_t np = (size_t)cam->width * cam->height;
    int D = e->splat.feat_dim;
    *feat = malloc(sizeof(float) * np * (size_t)D);
    *alpha = malloc(sizeof(float) * np);
    if (depth) *depth = malloc(sizeof(float) * np);
    if (rgb) *rgb = malloc(sizeof(float) * np * 3);
    if (!*feat || !*alpha || (depth && !*depth) || (rgb && !*rgb))
        return sp_error_set(err, SP_E_NOMEM, "query: out of memory rendering view %d", v);
    int rc = ensure_scene(e, err);
    sp_render_request req = {.rgb = rgb ? *rgb : NULL, .features = *feat,
                             .depth = depth ? *depth : NULL, .alpha = *alpha};
    return rc ? rc : sp_render_views(e->raster, e->scene, cam, 1, &req, err);
}

/* Occupancy of opaque Gaussian centres on a grid of <= 256^3 voxels (core's sp_grid3, 1 =
 * occupied): a cheap occlusion test for choosing views (a wall between a camera and the object),
 * instead of rendering candidates. */
static int build_occupancy(sp_query_engine *e, sp_error *err)
{
    const sp_splat *s = &e->splat;
    float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
    for (size_t i = 0; i < s->n; i++)
        for (int a = 0; a < 3; a++) {
            lo[a] = fminf(lo[a], s->means[3 * i + a]);
            hi[a] = fmaxf(hi[a], s->means[3 * i + a]);
        }
    float ext = fmaxf(hi[0] - lo[0], fmaxf(hi[1] - lo[1], hi[2] - lo[2]));
    float vox = fmaxf(0.05f, ext / 255.0f);
    int dim[3];
    for (int a = 0; a < 3; a++) dim[a] = (int)((hi[a] - lo[a]) / vox) + 1;
    int rc = sp_grid3_alloc(&e->occ, dim[0], dim[1], dim[2], vox, lo, err);
    if (rc) return sp_error_prefix(err, "query: occupancy grid: ");
    for (size_t i = 0; i < s->n; i++) {
        int c[3];
        if (e->opacity[i] >= 0.5f && sp_grid3_cell(&e->occ, s->means + 3 * i, c))
            e->occ.data[((size_t)c[2] * dim[1] + c[1]) * dim[0] + c[0]] = 1.0f;
    }
    return 0;
}

/* 1 when nothing opaque lies between the camera centre and p (the last ~2 voxels before p and
 * the first 0.2 m are not tested: p's own surface and the camera's surroundings). */
/* sp_grid3_cell's arithmetic for one axis, inlined: the ray march below calls it about a
 * million times a query (same float operations, so the same cells). */
static inline int occ_axis(float v, float origin, float res, int n, int *i)
{
    float f = floorf((v - origin) / res);
    if (!(f > -1e9f)) f = -1e9f;
    if (f > 1e9f) f = 1e9f;
    *i = (int)f;
    return *i >= 0 && *i < n;
}

static int visible(const sp_query_engine *e, sp_vec3 c, sp_vec3 p)
{
    const sp_grid3 *g = &e->occ;
    sp_vec3 d = sp_v3_sub(p, c);
    float len = sp_v3_norm(d), step = 0.5f * g->res;
    if (len < 1e-6f) return 1;
    d = sp_v3_scale(d, 1.0f / len);
    for (float t = 0.2f; t < len - 2.5f * g->res; t += step) {
        sp_vec3 x = sp_v3_add(c, sp_v3_scale(d, t));
        int qx, qy, qz;
        if (!occ_axis(x.x, g->origin[0], g->res, g->nx, &qx) || !occ_axis(x.y, g->origin[1], g->res, g->ny, &qy) ||
            !occ_axis(x.z, g->origin[2], g->res, g->nz, &qz))
            continue;
        if (g->data[((size_t)qz * g->ny + qy) * g->nx + qx] != 0) return 0;
    }
    return 1;
}

/* Per camera (one pool task each): which samples it sees unoccluded in the image, and a framing
 * factor (the object framed rather than filling the image: projected box <= 35% of it, near the
 * centre, seen from within a few metres). */
typedef struct {
    const sp_query_engine *e;
    const size_t *sel;
    size_t n_smp;
    uint8_t *vis;  /* [n_cams][n_smp] */
    float *frame;  /* [n_cams] */
} frame_job;

static void frame_camera(void *ctx, long ci, int tid)
{
    (void)tid;
    const frame_job *J = ctx;
    const sp_query_engine *e = J->e;
    const sp_splat *s = &e->splat;
    size_t c = (size_t)ci, n_smp = J->n_smp;
    const size_t *sel = J->sel;
    uint8_t *vis = J->vis;
    const sp_camera *cam = &e->cams[c];
    sp_vec3 o = sp_camera_center(cam);
    float u0 = 1e30f, u1 = -1e30f, v0 = 1e30f, v1 = -1e30f, zsum = 0;
    int any = 0;
    for (size_t j = 0; j < n_smp; j++) {
        size_t i = sel[j];
        sp_vec3 p = sp_v3(s->means[3 * i], s->means[3 * i + 1], s->means[3 * i + 2]);
        sp_vec3 x = sp_mat3_apply(cam->R, p);
        float z = x.z + cam->t[2];
        if (z < 0.2f) continue;
        float u = cam->fx * (x.x + cam->t[0]) / z + cam->cx, vv = cam->fy * (x.y + cam->t[1]) / z + cam->cy;
        if (u < 0 || vv < 0 || u >= cam->width || vv >= cam->height) continue;
        if (!visible(e, o, p)) continue;
        vis[c * n_smp + j] = 1;
        any++;
        zsum += z;
        u0 = fminf(u0, u), u1 = fmaxf(u1, u), v0 = fminf(v0, vv), v1 = fmaxf(v1, vv);
    }
    if (any) {
        float area = (u1 - u0) * (v1 - v0) / ((float)cam->width * cam->height);
        float du = 0.5f * (u0 + u1) / cam->width - 0.5f, dv = 0.5f * (v0 + v1) / cam->height - 0.5f;
        /* and near: rendered depth (and so back-projection) gets noisier with distance */
        float zm = zsum / (float)any / 3.5f;
        J->frame[c] = (area > 0.35f ? 0.35f / area : 1.0f) * (1.0f - sqrtf(du * du + dv * dv)) / (1.0f + zm * zm);
    }
}

int sem_pick_views(sp_query_engine *e, const sp_sem_scorer *sc, const sem_thresholds *th,
                   const uint8_t *mask, int k_min, int k, int *views, float *scores, sp_error *err)
{
    (void)sc;
    const sp_splat *s = &e->splat;
    if (e->n_cams == 0 || k <= 0) return 0;
    if (!e->occ.data) {
        int rc = build_occupancy(e, err);
        if (rc) return rc;
    }
    size_t *sel = malloc(sizeof(size_t) * (s->n ? s->n : 1));
    if (!sel) return sp_error_set(err, SP_E_NOMEM, "query: out of memory ranking views");
    size_t n_sel = 0;
    for (size_t i = 0; i < s->n; i++)
        if (mask ? mask[i]
                 : (e->raw[i] >= th->thr_raw && e->rel[i] >= th->thr_rel && e->opacity[i] >= th->min_op))
            sel[n_sel++] = i;
    /* at most 256 evenly spaced samples of the relevant set */
    size_t stride = n_sel > 256 ? n_sel / 256 : 1, n_smp = 0;
    for (size_t j = 0; j < n_sel; j += stride) sel[n_smp++] = sel[j];
    /* per camera, in parallel: what it sees of the samples and how well it frames them */
    double tot = 0;
    uint8_t *vis = calloc(e->n_cams * (n_smp ? n_smp : 1), 1);
    float *frame = calloc(e->n_cams, sizeof(float)), *wsmp = malloc(sizeof(float) * (n_smp ? n_smp : 1));
    uint8_t *covered = calloc(n_smp ? n_smp : 1, 1);
    if (!vis || !frame || !covered || !wsmp) {
        free(vis), free(frame), free(covered), free(wsmp), free(sel);
        return sp_error_set(err, SP_E_NOMEM, "query: out of memory ranking views");
    }
    frame_job fj = {e, sel, n_smp, vis, frame};
    sp_pool_for(sp_device_pool(e->dev), (long)e->n_cams, frame_camera, &fj);
    for (size_t j = 0; j < n_smp; j++) wsmp[j] = e->opacity[sel[j]], tot += wsmp[j];
    free(sel);
    /* Greedy set cover: each pick scores what it adds (samples no chosen view saw count fully,
     * seen ones a twentieth: another side still helps, but an unseen small instance wins over
     * a third look at a large one), so several instances (chairs around a table, windows
     * around the house) all get views; near-duplicate directions (< 25 degrees) count half. */
    int got = 0;
    while (got < k) {
        if (got >= k_min) { /* past the minimum, stop once 97% of the relevant set is seen */
            double seen = 0;
            for (size_t j = 0; j < n_smp; j++) seen += covered[j] ? wsmp[j] : 0;
            if (seen >= 0.97 * tot) break;
        }
        int best = -1;
        float best_score = 0;
        for (size_t c = 0; c < e->n_cams; c++) {
            if (frame[c] <= 0) continue;
            int taken = 0;
            float dup = 1.0f;
            for (int q = 0; q < got; q++) {
                if (views[q] == (int)c) taken = 1;
                const float *Ra = e->cams[views[q]].R, *Rb = e->cams[c].R;
                if (Ra[6] * Rb[6] + Ra[7] * Rb[7] + Ra[8] * Rb[8] > 0.906f) dup = 0.5f;
            }
            if (taken) continue;
            double acc = 0;
            for (size_t j = 0; j < n_smp; j++)
                if (vis[c * n_smp + j]) acc += wsmp[j] * (covered[j] ? 0.05 : 1.0);
            float sc_ = (float)(acc / (tot > 0 ? tot : 1)) * frame[c] * dup;
            if (sc_ > best_score) best_score = sc_, best = (int)c;
        }
        if (best < 0) break;
        views[got] = best;
        if (scores) scores[got] = best_score;
        got++;
        for (size_t j = 0; j < n_smp; j++)
            if (vis[(size_t)best * n_smp + j]) covered[j] = 1;
    }
    free(vis), free(frame), free(covered), free(wsmp);
    return got;
}

/* Back-projected pixels weigh the surface area they cover (z^2 / (fx fy)), so near views do not
 * outweigh far ones by pixel count; a real surface fills a good part of a voxel's face, while
 * depth noise between objects covers little of it. */
#define MV_MIN_VOXEL_COVER 0.1f

/* ---- multi-view ----------------------------------------------------------------------------------- */

/* Relevant points of the views, as a growing array. */
typedef struct {
    float *pts, *w, *cf;
    size_t m, cap;
} mv_points;

static int mv_grow(mv_points *P, sp_error *err)
{
    size_t cap = P->cap ? P->cap * 2 : 4096;
    float *np_ = realloc(P->pts, sizeof(float) * 3 * cap), *nw = np_ ? realloc(P->w, sizeof(float) * cap) : NULL,
          *nc = nw ? realloc(P->cf, sizeof(float) * cap) : NULL;
    if (np_) P->pts = np_;
    if (nw) P->w = nw;
    if (nc) P->cf = nc;
    if (!np_ || !nw || !nc) return sp_error_set(err, SP_E_NOMEM, "multi-view: out of memory");
    P->cap = cap;
    return 0;
}

/* Relevant pixels of one scored view, eroded by one pixel (at object borders the expected depth
 * blends the object with what is behind it and would back-project into the gap), back-projected
 * with the rendered (expected) depth into P. */
static int mv_backproject(const sem_thresholds *th, const sp_camera *cam, const float *depth,
                          const float *alpha, const float *raw, const float *rel, mv_points *P,
                          sp_error *err)
{
    size_t np = (size_t)cam->width * cam->height;
    uint8_t *keep = calloc(np, 1);
    if (!keep) return sp_error_set(err, SP_E_NOMEM, "multi-view: out of memory");
    for (size_t p = 0; p < np; p++)
        keep[p] = raw[p] >= th->thr_raw && rel[p] >= th->thr_rel && alpha[p] > 0.9f && depth[p] > 0;
    float Rt[9];
    sp_mat3_transpose(cam->R, Rt);
    int rc = 0;
    for (int y = 1; y + 1 < cam->height && !rc; y++)
        for (int x = 1; x + 1 < cam->width; x++) {
            size_t p = (size_t)y * cam->width + x;
            if (!keep[p] || !keep[p - 1] || !keep[p + 1] || !keep[p - cam->width] || !keep[p + cam->width])
                continue;
            if (P->m == P->cap && (rc = mv_grow(P, err))) break;
            /* back-project the pixel centre with the rendered (expected) depth */
            float z = depth[p];
            sp_vec3 xc = sp_v3(((float)x + 0.5f - cam->cx) / cam->fx * z - cam->t[0],
                               ((float)y + 0.5f - cam->cy) / cam->fy * z - cam->t[1], z - cam->t[2]);
            sp_vec3 xw = sp_mat3_apply(Rt, xc);
            size_t m = P->m++;
            P->pts[3 * m] = xw.x, P->pts[3 * m + 1] = xw.y, P->pts[3 * m + 2] = xw.z;
            P->w[m] = (rel[p] - 0.5f + 1e-3f) * 2.0f * alpha[p] * (z / cam->fx) * (z / cam->fy);
            P->cf[m] = raw[p];
        }
    free(keep);
    return rc;
}

/* Host stages: each view rendered to host buffers, scored and back-projected in turn. */
static int mv_points_host(sp_query_engine *e, const sp_sem_scorer *sc, const sem_thresholds *th,
                          const int *views, int got, int ds, mv_points *P, sp_query_stages *st,
                          sp_error *err)
{
    int rc = 0;
    for (int q = 0; q < got && !rc; q++) {
        sp_camera cam;
        float *feat = NULL, *depth = NULL, *alpha = NULL, *raw = NULL, *rel = NULL;
        double t0 = sp_time_now();
        rc = render_view(e, views[q], ds, &cam, &feat, &depth, &alpha, NULL, err);
        double t1 = sp_time_now();
        size_t np = (size_t)cam.width * cam.height;
        if (!rc) {
            raw = malloc(sizeof(float) * np);
            rel = malloc(sizeof(float) * np);
            if (!raw || !rel) rc = sp_error_set(err, SP_E_NOMEM, "multi-view: out of memory");
        }
        if (!rc) rc = sem_score_pixels(e, sc, feat, alpha, np, raw, rel, err);
        double t2 = sp_time_now();
        if (!rc) rc = mv_backproject(th, &cam, depth, alpha, raw, rel, P, err);
        st->render += (t1 - t0) * 1e3;
        st->score += (t2 - t1) * 1e3;
        st->backproject += (sp_time_now() - t2) * 1e3;
        free(feat), free(depth), free(alpha), free(raw), free(rel);
    }
    return rc;
}

/* Device stages: every view rendered in one batch into device buffers, scored, selected,
 * back-projected and compacted there; only the points come back. */
static int mv_points_device(sp_query_engine *e, const sp_sem_scorer *sc, const sem_thresholds *th,
                            const int *views, int got, int ds, mv_points *P, sp_query_stages *st,
                            sp_error *err)
{
    int D = e->splat.feat_dim, rc = 0;
    sp_camera *cams = malloc(sizeof *cams * (size_t)got);
    sp_render_request *reqs = calloc((size_t)got, sizeof *reqs);
    if (!cams || !reqs) rc = sp_error_set(err, SP_E_NOMEM, "multi-view: out of memory");
    size_t total = 0;
    for (int q = 0; q < got && !rc; q++) {
        cams[q] = e->cams[views[q]];
        if (ds > 1) sp_camera_downscale(&cams[q], ds);
        total += (size_t)cams[q].width * cams[q].height;
    }
    /* features [total][D], depth [total], alpha [total]: view q from its first pixel on */
    size_t o_depth = sem_align64(total * (size_t)D), o_alpha = o_depth + sem_align64(total);
    if (!rc) rc = ensure_scene(e, err);
    if (!rc) rc = sp_device_scratch_reserve(e->dev, &e->mv_out, (o_alpha + total) * sizeof(float), err);
    double t0 = sp_time_now();
    if (!rc) {
        float *b = e->mv_out.ptr;
        for (int q = 0, at = 0; q < got; at += cams[q].width * cams[q].height, q++)
            reqs[q] = (sp_render_request){.features = b + (size_t)at * D, .depth = b + o_depth + at,
                                          .alpha = b + o_alpha + at, .on_device = 1};
        rc = sp_render_views(e->raster, e->scene, cams, (size_t)got, reqs, err);
        if (!rc) rc = sp_device_sync(e->dev, err);
    }
    st->render = (sp_time_now() - t0) * 1e3;
    double ms[2] = {0, 0};
    if (!rc) {
        float *b = e->mv_out.ptr;
        rc = sem_cuda_view_points(e->dev, &e->mv_work, sc, th->thr_raw, th->thr_rel, cams, got, b,
                                  b + o_depth, b + o_alpha, &P->pts, &P->w, &P->cf, &P->m, ms, err);
        P->cap = P->m;
    }
    st->score = ms[0], st->backproject = ms[1];
    free(cams), free(reqs);
    return rc;
}

int sem_localize_multiview(sp_query_engine *e, const sp_sem_scorer *sc, const sem_thresholds *th,
                           sp_query_result *res, sp_error *err)
{
    /* n_views views at least; up to three times that while the relevant set is not covered
     * (instances spread over the house: windows, chairs on both sides of a table). With twice,
     * small instances far from the rest (a window, one chair) went unseen on the house. */
    int k = th->opts->n_views > 0 ? th->opts->n_views : 4;
    int *views = malloc(sizeof(int) * (size_t)(3 * k));
    if (!views) return sp_error_set(err, SP_E_NOMEM, "multi-view: out of memory");
    double t0 = sp_time_now();
    int got = sem_pick_views(e, sc, th, NULL, k, 3 * k, views, NULL, err);
    res->ms_stage.pick = (sp_time_now() - t0) * 1e3;
    if (got < 0) {
        free(views);
        return got;
    }
    res->view_index = got > 0 ? views[0] : -1;
    mv_points P = {0};
    int ds = th->opts->render_downscale > 0 ? th->opts->render_downscale : 1, rc = 0;
    if (got > 0)
        rc = sc->orthonormal && sem_device_stages(e, th->opts->host_stages)
                 ? mv_points_device(e, sc, th, views, got, ds, &P, &res->ms_stage, err)
                 : mv_points_host(e, sc, th, views, got, ds, &P, &res->ms_stage, err);
    free(views);
    /* A cluster's weight here sums every view that saw it, so an instance seen from one or two
     * views weighs a fraction of one seen from many: the relative cut is a third of the 3D one. */
    double t1 = sp_time_now();
    if (!rc && P.m > 0)
        rc = sem_cluster(P.pts, P.w, P.cf, P.m, th->opts->voxel_m, th->opts->min_instance_fraction / 3.0f,
                         MV_MIN_VOXEL_COVER * th->opts->voxel_m * th->opts->voxel_m, &res->instances,
                         &res->n_instances, err);
    res->ms_stage.cluster = (sp_time_now() - t1) * 1e3;
    free(P.pts), free(P.w), free(P.cf);
    if (rc) return rc;
    set_best(res, th->opts->min_confidence);
    return 0;
}
