/* Camera paths for captures, like a robot's: a 2D grid of the free floor (floor surfaces minus
 * everything between ankle and head height, kept a robot radius away), waypoints spread over it
 * by farthest-point sampling and visited in a nearest-neighbour tour, a full spin of overlapping
 * views at each, then short arcs of views around each object with a clear line of sight. */
#include "internal.h"

#include <stdlib.h>
#include <string.h>

#define FLOOR_MAX_Z 0.3f     /* up-facing surfaces below this are floor */
#define OBST_MIN_Z 0.06f     /* obstacles: anything between these heights above the floor */
#define OBST_MAX_Z 1.9f
#define CLEARANCE_M 0.35f    /* a camera stays this far from obstacles */
#define MAX_CELLS 700        /* grid side limit */
#define SPIN_VIEWS 12        /* headings per waypoint: 30 degrees apart */
#define ARC_VIEWS 3          /* views per arc around an object */
#define ARC_STEP_RAD 0.26f   /* 15 degrees between arc views */

/* The floor plan: core's sp_grid2 holds the geometry and the clearance layer, beside it the
 * floor mask and which object occupies each cell. */
typedef struct grid {
    sp_grid2 clear;   /* distance to the nearest obstacle or floor edge (m), chamfer */
    uint8_t *floor;   /* 1 = floor below */
    int32_t *occ;     /* -1 free, -2 unknown/structure, else object index */
} grid;

typedef struct rng { uint64_t s; } rng;
static double rnd(rng *r)
{
    r->s ^= r->s >> 12;
    r->s ^= r->s << 25;
    r->s ^= r->s >> 27;
    return (double)((r->s * 2685821657736338717ULL) >> 11) * (1.0 / 9007199254740992.0);
}

static void tri_normal(const sp_world *w, size_t t, float n[3])
{
    const float *a = &w->positions[w->tris[t * 3] * 3], *b = &w->positions[w->tris[t * 3 + 1] * 3];
    const float *c = &w->positions[w->tris[t * 3 + 2] * 3];
    float e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    float l = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (l > 0) for (int k = 0; k < 3; k++) n[k] /= l;
}

static int is_floor_tri(const sp_world *w, size_t t)
{
    float n[3];
    tri_normal(w, t, n);
    if (fabsf(n[2]) < 0.9f) return 0;
    for (int i = 0; i < 3; i++) {
        float z = w->positions[w->tris[t * 3 + i] * 3 + 2];
        if (z > FLOOR_MAX_Z || z < -FLOOR_MAX_Z) return 0;
    }
    return 1;
}

/* Clearance from obstacles and non-floor cells: a two-pass 3x3 chamfer (steps 1 and sqrt 2),
 * which overstates diagonal distances by up to 8% against the exact transform (core's sp_edt2).
 * Kept on purpose: every capture, and what is measured on them, rests on these plans; with the
 * exact transform the CPU demo's 48-view house plan moves a waypoint out of the bedroom
 * (wardrobe, nightstand and a window unseen for every seed 1..10). Changing the plan is a
 * capture-planning decision (coverage-aware planning), not a refactor. */
static void chamfer_clearance(grid *g)
{
    const int nx = g->clear.nx, ny = g->clear.ny;
    const size_t nc = (size_t)nx * ny;
    float *cl = g->clear.data;
    const float big = 1e9f, d1 = g->clear.res, d2 = g->clear.res * 1.41421356f;
    for (size_t i = 0; i < nc; i++) cl[i] = (g->floor[i] && g->occ[i] == -1) ? big : 0;
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            float *c = &cl[(size_t)j * nx + i];
            if (i > 0) *c = fminf(*c, c[-1] + d1);
            if (j > 0) {
                *c = fminf(*c, c[-nx] + d1);
                if (i > 0) *c = fminf(*c, c[-nx - 1] + d2);
                if (i + 1 < nx) *c = fminf(*c, c[-nx + 1] + d2);
            }
        }
    for (int j = ny - 1; j >= 0; j--)
        for (int i = nx - 1; i >= 0; i--) {
            float *c = &cl[(size_t)j * nx + i];
            if (i + 1 < nx) *c = fminf(*c, c[1] + d1);
            if (j + 1 < ny) {
                *c = fminf(*c, c[nx] + d1);
                if (i + 1 < nx) *c = fminf(*c, c[nx + 1] + d2);
                if (i > 0) *c = fminf(*c, c[nx - 1] + d2);
            }
        }
}

static int build_grid(const sp_world *w, grid *g)
{
    /* Bounds: the floor surfaces, cut to everything else (a ground plane can be 100 m wide). */
    float fmin[2] = {INFINITY, INFINITY}, fmax[2] = {-INFINITY, -INFINITY};
    float omin[2] = {INFINITY, INFINITY}, omax[2] = {-INFINITY, -INFINITY};
    for (size_t t = 0; t < w->n_triangles; t++) {
        int fl = is_floor_tri(w, t);
        for (int i = 0; i < 3; i++) {
            const float *p = &w->positions[w->tris[t * 3 + i] * 3];
            if (fabsf(p[0]) > 1e4f || fabsf(p[1]) > 1e4f || p[2] > 3.0f || p[2] < -1.0f) continue;
            float *mn = fl ? fmin : omin, *mx = fl ? fmax : omax;
            for (int k = 0; k < 2; k++) {
                if (p[k] < mn[k]) mn[k] = p[k];
                if (p[k] > mx[k]) mx[k] = p[k];
            }
        }
    }
    if (!(fmin[0] < fmax[0]) || !(fmin[1] < fmax[1])) return -1;
    if (omin[0] < omax[0])
        for (int k = 0; k < 2; k++) {
            fmin[k] = fmaxf(fmin[k], omin[k] - 1.0f);
            fmax[k] = fminf(fmax[k], omax[k] + 1.0f);
        }
    float ext = fmaxf(fmax[0] - fmin[0], fmax[1] - fmin[1]);
    float res = fmaxf(0.05f, ext / MAX_CELLS);
    int gnx = (int)ceilf((fmax[0] - fmin[0]) / res) + 1, gny = (int)ceilf((fmax[1] - fmin[1]) / res) + 1;
    if (sp_grid2_alloc(&g->clear, gnx, gny, res, fmin[0], fmin[1], NULL)) return -2;
    const float x0 = g->clear.origin[0], y0 = g->clear.origin[1];
    const int nx = g->clear.nx, ny = g->clear.ny;
    size_t nc = (size_t)nx * ny;
    g->floor = calloc(nc, 1);
    g->occ = malloc(nc * sizeof(int32_t));
    if (!g->floor || !g->occ) return -2;
    for (size_t i = 0; i < nc; i++) g->occ[i] = -1;
    /* floor: cell centres inside floor triangles (xy) */
    for (size_t t = 0; t < w->n_triangles; t++) {
        if (!is_floor_tri(w, t)) continue;
        const float *a = &w->positions[w->tris[t * 3] * 3], *b = &w->positions[w->tris[t * 3 + 1] * 3];
        const float *c = &w->positions[w->tris[t * 3 + 2] * 3];
        float xmn = fminf(a[0], fminf(b[0], c[0])), xmx = fmaxf(a[0], fmaxf(b[0], c[0]));
        float ymn = fminf(a[1], fminf(b[1], c[1])), ymx = fmaxf(a[1], fmaxf(b[1], c[1]));
        int i0 = (int)floorf((xmn - x0) / res), i1 = (int)ceilf((xmx - x0) / res);
        int j0 = (int)floorf((ymn - y0) / res), j1 = (int)ceilf((ymx - y0) / res);
        if (i0 < 0) i0 = 0;
        if (j0 < 0) j0 = 0;
        if (i1 >= nx) i1 = nx - 1;
        if (j1 >= ny) j1 = ny - 1;
        float d = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
        if (fabsf(d) < 1e-12f) continue;
        for (int j = j0; j <= j1; j++)
            for (int i = i0; i <= i1; i++) {
                float x = x0 + (i + 0.5f) * res, y = y0 + (j + 0.5f) * res;
                float l1 = ((x - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (y - a[1])) / d;
                float l2 = ((b[0] - a[0]) * (y - a[1]) - (x - a[0]) * (b[1] - a[1])) / d;
                if (l1 >= -1e-4f && l2 >= -1e-4f && l1 + l2 <= 1.0001f) g->floor[(size_t)j * nx + i] = 1;
            }
    }
    /* obstacles: points sampled densely on every other triangle within the height band */
    float step = res * 0.5f;
    for (size_t t = 0; t < w->n_triangles; t++) {
        if (is_floor_tri(w, t)) continue;
        const float *a = &w->positions[w->tris[t * 3] * 3], *b = &w->positions[w->tris[t * 3 + 1] * 3];
        const float *c = &w->positions[w->tris[t * 3 + 2] * 3];
        float zmn = fminf(a[2], fminf(b[2], c[2])), zmx = fmaxf(a[2], fmaxf(b[2], c[2]));
        if (zmx < OBST_MIN_Z || zmn > OBST_MAX_Z) continue;
        float e = fmaxf(fmaxf(fabsf(b[0] - a[0]) + fabsf(b[1] - a[1]) + fabsf(b[2] - a[2]),
                              fabsf(c[0] - a[0]) + fabsf(c[1] - a[1]) + fabsf(c[2] - a[2])),
                        fabsf(c[0] - b[0]) + fabsf(c[1] - b[1]) + fabsf(c[2] - b[2]));
        int n = (int)ceilf(e / step);
        if (n < 1) n = 1;
        if (n > 4000) n = 4000;
        int obj = w->tri_object[t];
        int32_t id = w->objects[obj].is_structure ? -2 : obj;
        for (int i = 0; i <= n; i++)
            for (int j = 0; i + j <= n; j++) {
                float u = (float)i / n, v = (float)j / n, s = 1 - u - v;
                float p[3] = {s * a[0] + u * b[0] + v * c[0], s * a[1] + u * b[1] + v * c[1],
                              s * a[2] + u * b[2] + v * c[2]};
                if (p[2] < OBST_MIN_Z || p[2] > OBST_MAX_Z) continue;
                int ci = (int)floorf((p[0] - x0) / res), cj = (int)floorf((p[1] - y0) / res);
                if (ci < 0 || cj < 0 || ci >= nx || cj >= ny) continue;
                int32_t *o = &g->occ[(size_t)cj * nx + ci];
                if (*o == -1 || id == -2) *o = id;
            }
    }
    chamfer_clearance(g);
    return 0;
}

static void grid_free(grid *g)
{
    free(g->floor);
    free(g->occ);
    sp_grid2_free(&g->clear);
}

static int cell_of(const grid *g, float x, float y, int *i, int *j)
{
    return sp_grid2_cell(&g->clear, x, y, i, j);
}

/* Line of sight from (x, y) towards object o: no other object or structure in between. */
static int clear_line(const grid *g, float x, float y, float tx, float ty, int o, const sp_synth_object *ob)
{
    float dx = tx - x, dy = ty - y, L = sqrtf(dx * dx + dy * dy);
    for (float s = 0; s < L; s += g->clear.res * 0.5f) {
        float px = x + dx * s / L, py = y + dy * s / L;
        if (px >= ob->aabb_min[0] && px <= ob->aabb_max[0] && py >= ob->aabb_min[1] && py <= ob->aabb_max[1])
            return 1;
        int i, j;
        if (!cell_of(g, px, py, &i, &j)) return 0;
        int32_t id = g->occ[(size_t)j * g->clear.nx + i];
        if (id != -1 && id != o) return 0;
    }
    return 1;
}

static void set_cam(sp_camera *c, const sp_synth_capture_opts *o, float fov_deg)
{
    memset(c, 0, sizeof *c);
    c->width = o->width;
    c->height = o->height;
    c->fx = c->fy = (float)(0.5 * o->width / tan(0.5 * fov_deg * M_PI / 180.0));
    c->cx = 0.5f * o->width;
    c->cy = 0.5f * o->height;
}

static void look(sp_camera *c, float x, float y, float z, float yaw, float pitch)
{
    sp_vec3 eye = sp_v3(x, y, z);
    sp_vec3 dir = sp_v3(cosf(yaw) * cosf(pitch), sinf(yaw) * cosf(pitch), sinf(pitch));
    sp_camera_look_at(c, eye, sp_v3_add(eye, dir), sp_v3(0, 0, 1));
}

int sp_synth_plan_views(const sp_world *w, const sp_synth_capture_opts *o, sp_camera **cams,
                        size_t *n_out, sp_error *err)
{
    if (o->plan == SP_SYNTH_PLAN_DRIVE) return sp_synth_plan(w, o, cams, n_out, NULL, err);
    *cams = NULL;
    *n_out = 0;
    if (o->n_views <= 0 || o->n_views > 100000 || o->width <= 0 || o->height <= 0 || o->width > 16384 ||
        o->height > 16384)
        return sp_error_set(err, SP_E_ARG, "capture: %d views of %dx%d: expected 1..100000 views of 1..16384 pixels",
                            o->n_views, o->width, o->height);
    if (o->n_points < 0 || o->n_points > 100000000)
        return sp_error_set(err, SP_E_ARG, "capture: points %d outside 1..100000000 (0: 30000)", o->n_points);
    if (!(o->fov_deg >= 0 && o->fov_deg < 170))
        return sp_error_set(err, SP_E_ARG, "fov %g degrees: expected 0 (70) or less than 170", o->fov_deg);
    float fov = o->fov_deg > 0 ? o->fov_deg : 70.0f;
    float hmin = o->min_height_m, hmax = o->max_height_m;
    if (!(hmin >= 0 && hmax >= 0 && hmax <= 100))
        return sp_error_set(err, SP_E_ARG, "camera heights %g..%g m: expected 0..100", hmin, hmax);
    if (hmin <= 0 && hmax <= 0) { hmin = 0.3f; hmax = 1.5f; }
    if (hmax < hmin) return sp_error_set(err, SP_E_ARG, "camera heights %g..%g: max below min", hmin, hmax);
    size_t n = (size_t)o->n_views;
    sp_camera *out = calloc(n, sizeof *out);
    if (!out) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    rng r = {0x9e3779b97f4a7c15ULL ^ ((uint64_t)o->seed * 0x100000001b3ULL + 1)};
    grid g;
    memset(&g, 0, sizeof g);
    int grc = build_grid(w, &g);
    if (grc == -2) {
        grid_free(&g);
        free(out);
        return sp_error_set(err, SP_E_NOMEM, "out of memory");
    }
    size_t nc = grc == 0 ? (size_t)g.clear.nx * g.clear.ny : 0, n_free = 0;
    float need = CLEARANCE_M;
    for (int pass = 0; pass < 3 && grc == 0; pass++) {
        n_free = 0;
        for (size_t i = 0; i < nc; i++) n_free += g.clear.data[i] >= need;
        if (n_free >= 4) break;
        need *= 0.5f; /* a tight world: accept less clearance rather than no walk */
    }
    size_t k = 0;
    if (grc != 0 || n_free < 4) {
        /* No floor to walk on: orbit the scene's box. */
        float mn[3] = {INFINITY, INFINITY, INFINITY}, mx[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (size_t i = 0; i < w->n_objects; i++)
            for (int a = 0; a < 3; a++) {
                mn[a] = fminf(mn[a], w->objects[i].aabb_min[a]);
                mx[a] = fmaxf(mx[a], w->objects[i].aabb_max[a]);
            }
        if (!(mn[0] <= mx[0])) for (int a = 0; a < 3; a++) { mn[a] = -1; mx[a] = 1; }
        sp_vec3 c = sp_v3((mn[0] + mx[0]) / 2, (mn[1] + mx[1]) / 2, (mn[2] + mx[2]) / 2);
        float rad = 0.5f * sqrtf((mx[0] - mn[0]) * (mx[0] - mn[0]) + (mx[1] - mn[1]) * (mx[1] - mn[1]) +
                                 (mx[2] - mn[2]) * (mx[2] - mn[2]));
        float dist = fmaxf(rad / tanf(0.5f * fov * (float)M_PI / 180.0f), rad + 0.5f) * 1.1f;
        for (k = 0; k < n; k++) {
            float a = (float)(2 * M_PI * k / n), el = (float)(0.15 + 0.35 * rnd(&r));
            sp_vec3 eye = sp_v3(c.x + dist * cosf(a) * cosf(el), c.y + dist * sinf(a) * cosf(el), c.z + dist * sinf(el));
            set_cam(&out[k], o, fov);
            sp_camera_look_at(&out[k], eye, c, sp_v3(0, 0, 1));
        }
        grid_free(&g);
        *cams = out;
        *n_out = n;
        return 0;
    }
    /* objects worth a look: not structure, with a footprint on the grid, not floating far away */
    int *objs = malloc((w->n_objects + 1) * sizeof(int));
    size_t n_objs = 0;
    for (size_t i = 0; objs && i < w->n_objects; i++) {
        const sp_synth_object *ob = &w->objects[i];
        float cx = 0.5f * (ob->aabb_min[0] + ob->aabb_max[0]), cy = 0.5f * (ob->aabb_min[1] + ob->aabb_max[1]);
        float cz = 0.5f * (ob->aabb_min[2] + ob->aabb_max[2]);
        int ci, cj;
        if (ob->is_structure || !ob->n_triangles || cz > 2.2f || cz < -0.5f || !cell_of(&g, cx, cy, &ci, &cj)) continue;
        objs[n_objs++] = (int)i;
    }
    /* A robot records video: consecutive frames overlap. The walk is a full spin of SPIN_VIEWS
     * headings at each waypoint (30 degrees apart, so with a 70-degree lens every frame is also
     * seen by its neighbours and held-out frames are true novel views of seen content), and object
     * views come as short arcs. Scattered single views made held-out PSNR 7 dB below training. */
    size_t n_obj_views = n_objs && o->plan != SP_SYNTH_PLAN_WALK ? (size_t)(0.3 * n) : 0;
    size_t n_walk = n - n_obj_views;
    /* waypoints: farthest-point sampling over the free cells */
    size_t n_wp = (n_walk + SPIN_VIEWS - 1) / SPIN_VIEWS;
    if (n_wp < 1) n_wp = 1;
    size_t *wp = malloc(n_wp * sizeof(size_t));
    float *mind = malloc(nc * sizeof(float));
    int *order = malloc(n_wp * sizeof(int));
    if (!wp || !mind || !order || !objs) {
        free(wp); free(mind); free(order); free(objs);
        grid_free(&g);
        free(out);
        return sp_error_set(err, SP_E_NOMEM, "out of memory");
    }
    size_t first = 0;
    float bestc = -1;
    for (size_t i = 0; i < nc; i++)
        if (g.clear.data[i] > bestc) { bestc = g.clear.data[i]; first = i; }
    /* farthest-point sampling weighted by clearance (synth_farthest_points) */
    for (size_t i = 0; i < nc; i++) mind[i] = g.clear.data[i] >= need ? INFINITY : -1;
    synth_farthest_points(&g.clear, mind, first, (int)n_wp, wp);
    /* nearest-neighbour tour */
    {
        uint8_t *used = calloc(n_wp, 1);
        int cur = 0;
        for (size_t q = 0; q < n_wp; q++) {
            order[q] = cur;
            if (used) used[cur] = 1;
            float bd = INFINITY;
            int nx = -1;
            for (size_t t = 0; used && t < n_wp; t++) {
                if (used[t]) continue;
                float dx = (float)(wp[t] % g.clear.nx) - (float)(wp[cur] % g.clear.nx), dy = (float)(wp[t] / g.clear.nx) - (float)(wp[cur] / g.clear.nx);
                if (dx * dx + dy * dy < bd) { bd = dx * dx + dy * dy; nx = (int)t; }
            }
            if (nx < 0) nx = (int)((q + 1) % n_wp);
            cur = nx;
        }
        free(used);
    }
    /* looking around at each waypoint: a full spin at one camera height, as a robot turning on
     * the spot; the pitch tilts down more the higher the camera */
    for (size_t q = 0; q < n_wp && k < n_walk; q++) {
        size_t cell = wp[order[q]];
        float x, y;
        sp_grid2_center(&g.clear, (int)(cell % g.clear.nx), (int)(cell / g.clear.nx), &x, &y);
        float yaw0 = (float)(rnd(&r) * 2 * M_PI);
        float h = hmin + (float)rnd(&r) * (hmax - hmin);
        float pitch = (float)(-0.05 - 0.3 * (h - hmin) / fmaxf(hmax - hmin, 1e-3f));
        for (int v = 0; v < SPIN_VIEWS && k < n_walk; v++) {
            float yaw = yaw0 + v * (float)(2 * M_PI / SPIN_VIEWS);
            set_cam(&out[k], o, fov);
            look(&out[k], x, y, h, yaw, pitch);
            k++;
        }
    }
    /* around objects, round robin: arcs of ARC_VIEWS views ARC_STEP_RAD apart at one height */
    size_t tries = 0;
    for (size_t v = 0; k < n && n_objs && tries < 64 * n; tries++, v++) {
        int oi = objs[v % n_objs];
        const sp_synth_object *ob = &w->objects[oi];
        float cx = 0.5f * (ob->aabb_min[0] + ob->aabb_max[0]), cy = 0.5f * (ob->aabb_min[1] + ob->aabb_max[1]);
        float cz = 0.5f * (ob->aabb_min[2] + ob->aabb_max[2]);
        float size = fmaxf(ob->aabb_max[0] - ob->aabb_min[0], fmaxf(ob->aabb_max[1] - ob->aabb_min[1], ob->aabb_max[2] - ob->aabb_min[2]));
        float dist = fminf(fmaxf(0.9f + 1.1f * size, 1.0f), 3.2f) * (float)(0.85 + 0.3 * rnd(&r));
        float ang0 = (float)(rnd(&r) * 2 * M_PI);
        float h = hmin + (float)rnd(&r) * (hmax - hmin);
        float tz = fmaxf(cz, 0.15f);
        int ok = 1;
        for (int a = 0; a < ARC_VIEWS && ok; a++) {
            float ang = ang0 + (a - (ARC_VIEWS - 1) * 0.5f) * ARC_STEP_RAD;
            float x = cx + dist * cosf(ang), y = cy + dist * sinf(ang);
            int ci, cj;
            ok = cell_of(&g, x, y, &ci, &cj) && g.clear.data[(size_t)cj * g.clear.nx + ci] >= need * 0.7f &&
                 clear_line(&g, x, y, cx, cy, oi, ob);
        }
        if (!ok) continue;
        for (int a = 0; a < ARC_VIEWS && k < n; a++) {
            float ang = ang0 + (a - (ARC_VIEWS - 1) * 0.5f) * ARC_STEP_RAD;
            float x = cx + dist * cosf(ang), y = cy + dist * sinf(ang);
            float yaw = atan2f(cy - y, cx - x), pitch = atan2f(tz - h, dist);
            set_cam(&out[k], o, fov);
            look(&out[k], x, y, h, yaw, pitch);
            k++;
        }
    }
    /* anything left (objects unreachable): more walk views at random waypoints */
    for (; k < n; k++) {
        size_t cell = wp[(size_t)(rnd(&r) * n_wp) % n_wp];
        float x, y;
        sp_grid2_center(&g.clear, (int)(cell % g.clear.nx), (int)(cell / g.clear.nx), &x, &y);
        float h = hmin + (float)rnd(&r) * (hmax - hmin);
        set_cam(&out[k], o, fov);
        look(&out[k], x, y, h, (float)(rnd(&r) * 2 * M_PI), -0.15f);
    }
    free(wp);
    free(mind);
    free(order);
    free(objs);
    grid_free(&g);
    *cams = out;
    *n_out = n;
    return 0;
}

/* The floor plan for synth's other planner (drive.c): clearance in metres from obstacles and
 * the floor's edge (0 off the floor). Fails with SP_E_NOTFOUND when the world has no floor. */
int synth_floor_clearance(const sp_world *w, sp_grid2 *clear, sp_error *err)
{
    memset(clear, 0, sizeof *clear);
    grid g;
    memset(&g, 0, sizeof g);
    int rc = build_grid(w, &g);
    if (rc == -1) rc = sp_error_set(err, SP_E_NOTFOUND, "%s: no floor to drive on", w->path);
    else if (rc) rc = sp_error_set(err, SP_E_NOMEM, "out of memory");
    else {
        *clear = g.clear; /* handed over */
        memset(&g.clear, 0, sizeof g.clear);
    }
    grid_free(&g);
    return rc;
}

/* One pinhole view of the capture's intrinsics at (x, y, z) looking along yaw, pitched up by
 * pitch radians (drive.c's frames, the same cameras as the walk's). */
void synth_view(sp_camera *c, const sp_synth_capture_opts *o, float fov_deg, float x, float y,
                float z, float yaw, float pitch)
{
    set_cam(c, o, fov_deg);
    look(c, x, y, z, yaw, pitch);
}
