/* Exploration of a region in words: the region's footprints (its objects, or the objects a
 * household keeps there) grown by region_margin_m make an area; candidate views stand on
 * reachable free cells around it, 8 headings each; a view covers the area's cells it sees
 * (2-D line of sight through the costmap, within range and field of view), weighted toward
 * cells the capture observed poorly (few carving rays: what the splat reconstructs least).
 * Views are chosen greedily until the area is covered, then ordered into a short tour
 * (nearest neighbour over path distances, improved by 2-opt) and joined by planned paths. */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "nav_scene.h"

#define VIEW_RANGE_M 4.0f
#define CANDIDATE_STEP_M 0.5f
#define WELL_SEEN_RAYS 20.0f /* carving rays that make a cell fully observed */
#define POOR_BONUS 1.0f      /* utility x (1 + this x poorness of the view) */
#define MIN_GAIN 0.01f       /* stop when a view adds less than this share of the area */

void sp_nav_tour_free(sp_nav_tour *t)
{
    if (!t) return;
    free(t->poses), free(t->quality), free(t->gain);
    sp_path_free(&t->path);
    for (int i = 0; i < t->n_previews; i++) nav_preview_free(&t->previews[i]);
    free(t->previews);
    memset(t, 0, sizeof *t);
}

typedef struct explore_ctx {
    const sp_costmap *cm;
    sp_nav_box area;
    uint8_t *target;      /* [cells] cells to cover */
    long n_target;
    float *poor;          /* [cells] 1 - observation of the cell */
} explore_ctx;

static int in_box(const sp_nav_box *b, const float p[2])
{
    return p[0] >= b->min[0] && p[0] <= b->max[0] && p[1] >= b->min[1] && p[1] <= b->max[1];
}

/* The area's cells worth seeing: free or unknown, and obstacle cells on a free or unknown cell's
 * side (surfaces), not the insides of walls. */
static void make_targets(explore_ctx *x)
{
    const sp_costmap *cm = x->cm;
    for (int iy = 0; iy < cm->ny; iy++)
        for (int ix = 0; ix < cm->nx; ix++) {
            float c[2];
            sp_costmap_cell_center(cm, ix, iy, c);
            long i = nav_idx(cm, ix, iy);
            if (!in_box(&x->area, c)) continue;
            int t = cm->occ[i] != SP_CELL_OCCUPIED;
            for (int k = 0; k < 4 && !t; k++) {
                int nx = ix + (k == 0) - (k == 1), ny = iy + (k == 2) - (k == 3);
                t = nav_inside(cm, nx, ny) && cm->occ[nav_idx(cm, nx, ny)] != SP_CELL_OCCUPIED;
            }
            if (!t) continue;
            x->target[i] = 1;
            x->n_target++;
            float seen = cm->seen ? cm->seen[i] / WELL_SEEN_RAYS : (cm->occ[i] == SP_CELL_UNKNOWN ? 0.0f : 1.0f);
            x->poor[i] = cm->occ[i] == SP_CELL_UNKNOWN ? 1.0f : 1.0f - fminf(1.0f, seen);
        }
}

typedef struct los_ctx {
    const sp_costmap *cm;
    long goal;
} los_ctx;

static int los_cell(void *v, long cell, float t0, float t1)
{
    los_ctx *c = v;
    (void)t0, (void)t1;
    return cell != c->goal && c->cm->occ[cell] == SP_CELL_OCCUPIED;
}

/* A standpoint and the target cells visible from it (any heading), with their bearings. */
typedef struct stand {
    float p[2];
    long n;
    int32_t *cells;
    float *bearing;
} stand;

/* Visible target cells from p: within range, line of sight through non-occupied cells. */
static int visible_from(const explore_ctx *x, const float p[2], stand *st)
{
    const sp_costmap *cm = x->cm;
    int r = (int)ceilf(VIEW_RANGE_M / cm->res), cx, cy;
    sp_costmap_cell(cm, p[0], p[1], &cx, &cy);
    long cap = 256;
    st->p[0] = p[0], st->p[1] = p[1], st->n = 0;
    st->cells = malloc(sizeof(int32_t) * cap);
    st->bearing = malloc(sizeof(float) * cap);
    if (!st->cells || !st->bearing) return -1;
    for (int iy = cy - r; iy <= cy + r; iy++)
        for (int ix = cx - r; ix <= cx + r; ix++) {
            if (!nav_inside(cm, ix, iy)) continue;
            long i = nav_idx(cm, ix, iy);
            if (!x->target[i]) continue;
            float c[2];
            sp_costmap_cell_center(cm, ix, iy, c);
            float dx = c[0] - p[0], dy = c[1] - p[1], d = hypotf(dx, dy);
            if (d > VIEW_RANGE_M || d < 0.3f) continue;
            los_ctx lc = {cm, i};
            if (nav_traverse(cm, p, c, los_cell, &lc)) continue;
            if (st->n == cap) {
                cap *= 2;
                int32_t *a = realloc(st->cells, sizeof(int32_t) * cap);
                float *b = realloc(st->bearing, sizeof(float) * cap);
                if (a) st->cells = a;
                if (b) st->bearing = b;
                if (!a || !b) return -1;
            }
            st->cells[st->n] = (int32_t)i;
            st->bearing[st->n++] = atan2f(dy, dx);
        }
    return 0;
}

/* Uncovered target cells a view from st along yaw sees: count and summed poorness; marks them
 * covered when mark is set. */
static long view_gain(const explore_ctx *x, const stand *st, float yaw, float hfov, uint8_t *covered,
                      float *poor_sum, int mark)
{
    long n = 0;
    *poor_sum = 0;
    for (long k = 0; k < st->n; k++) {
        long i = st->cells[k];
        if (covered[i] || fabsf(remainderf(st->bearing[k] - yaw, 2 * (float)M_PI)) > 0.5f * hfov) continue;
        n++;
        *poor_sum += x->poor[i];
        if (mark) covered[i] = 1;
    }
    return n;
}

/* Path lengths between tour stops by Dijkstra over traversable cells (8-connected). */
static int geodesic(const sp_costmap *cm, const float *from, float *dist_out)
{
    long n = (long)cm->nx * cm->ny;
    for (long i = 0; i < n; i++) dist_out[i] = INFINITY;
    int sx, sy;
    if (sp_costmap_cell(cm, from[0], from[1], &sx, &sy)) return 0;
    long s = nav_idx(cm, sx, sy);
    long *heap = malloc(sizeof(long) * (8 * n + 8));
    float *key = malloc(sizeof(float) * (8 * n + 8));
    if (!heap || !key) {
        free(heap), free(key);
        return -1;
    }
    long hn = 0;
    dist_out[s] = 0;
    heap[hn] = s, key[hn++] = 0;
    static const int dx[8] = {1, -1, 0, 0, 1, 1, -1, -1}, dy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
    while (hn > 0) {
        long c = heap[0];
        float kc = key[0];
        hn--;
        long i = 0; /* sift the last item down from the root */
        for (;;) {
            long ch = 2 * i + 1;
            if (ch >= hn) break;
            if (ch + 1 < hn && key[ch + 1] < key[ch]) ch++;
            if (key[ch] >= key[hn]) break;
            heap[i] = heap[ch], key[i] = key[ch];
            i = ch;
        }
        heap[i] = heap[hn], key[i] = key[hn];
        if (kc > dist_out[c]) continue;
        int cx = (int)(c % cm->nx), cy = (int)(c / cm->nx);
        for (int k = 0; k < 8; k++) {
            int x = cx + dx[k], y = cy + dy[k];
            if (!sp_costmap_traversable(cm, x, y)) continue;
            if (k >= 4 && (!sp_costmap_traversable(cm, cx + dx[k], cy) || !sp_costmap_traversable(cm, cx, cy + dy[k]))) continue;
            long j = nav_idx(cm, x, y);
            float nd = kc + (k >= 4 ? 1.41421356f : 1.0f) * cm->res;
            if (nd >= dist_out[j] || hn >= 8 * n) continue;
            dist_out[j] = nd;
            long q = hn++; /* sift up */
            while (q > 0 && key[(q - 1) / 2] > nd) {
                heap[q] = heap[(q - 1) / 2], key[q] = key[(q - 1) / 2];
                q = (q - 1) / 2;
            }
            heap[q] = j, key[q] = nd;
        }
    }
    free(heap), free(key);
    return 0;
}

static float tour_length(const float *D, int m, const int *order)
{
    float l = D[0 * m + order[0]];
    for (int k = 0; k + 1 < m - 1; k++) l += D[order[k] * m + order[k + 1]];
    return l;
}

/* Open tour from stop 0 through stops 1..m-1: nearest neighbour, then 2-opt. D is m x m. */
static void order_tour(const float *D, int m, int *order)
{
    int n = m - 1, cur = 0;
    uint8_t used[64] = {0};
    for (int k = 0; k < n; k++) {
        int best = -1;
        for (int j = 1; j < m; j++)
            if (!used[j] && (best < 0 || D[cur * m + j] < D[cur * m + best])) best = j;
        order[k] = best, used[best] = 1, cur = best;
    }
    for (int improved = 1, guard = 0; improved && guard < 100; guard++) {
        improved = 0;
        for (int a = 0; a < n - 1; a++)
            for (int b = a + 1; b < n; b++) {
                float before = tour_length(D, m, order);
                for (int i = a, j = b; i < j; i++, j--) {
                    int t = order[i];
                    order[i] = order[j], order[j] = t;
                }
                if (tour_length(D, m, order) + 1e-4f < before) improved = 1;
                else
                    for (int i = a, j = b; i < j; i++, j--) {
                        int t = order[i];
                        order[i] = order[j], order[j] = t;
                    }
            }
    }
}

static int area_of(sp_nav *nav, sp_nav_tour *t)
{
    const sp_costmap *cm = &nav->cm;
    sp_nav_box a = {{INFINITY, INFINITY}, {-INFINITY, -INFINITY}};
    for (int k = 0; k < t->target.n; k++)
        for (int d = 0; d < 2; d++) {
            a.min[d] = fminf(a.min[d], t->target.inst[k].box.min[d] - nav->opts.region_margin_m);
            a.max[d] = fmaxf(a.max[d], t->target.inst[k].box.max[d] + nav->opts.region_margin_m);
        }
    a.min[0] = fmaxf(a.min[0], cm->origin[0]), a.min[1] = fmaxf(a.min[1], cm->origin[1]);
    a.max[0] = fminf(a.max[0], cm->origin[0] + cm->nx * cm->res);
    a.max[1] = fminf(a.max[1], cm->origin[1] + cm->ny * cm->res);
    t->area = a;
    return a.min[0] < a.max[0] && a.min[1] < a.max[1];
}

/* Greedy choice of views from standpoints on reachable free floor around the area (every
 * CANDIDATE_STEP_M, 8 headings); poses [max][4] out, returns how many (-1: out of memory). */
static int choose_views(sp_nav *nav, explore_ctx *x, sp_nav_tour *t, const float *dist)
{
    const sp_costmap *cm = x->cm;
    const sp_nav_opts *o = &nav->opts;
    float hfov = o->preview_hfov_deg * (float)M_PI / 180.0f;
    int step = (int)ceilf(CANDIDATE_STEP_M / cm->res), n = 0, n_st = 0, rc = 0;
    sp_nav_box reach = x->area;
    for (int d = 0; d < 2; d++) reach.min[d] -= 1.0f, reach.max[d] += 1.0f;
    long max_st = (long)(cm->nx / step + 1) * (cm->ny / step + 1);
    stand *st = calloc((size_t)max_st, sizeof *st);
    uint8_t *covered = calloc((size_t)cm->nx * cm->ny, 1);
    if (!st || !covered) rc = -1;
    for (int iy = 0; iy < cm->ny && !rc; iy += step)
        for (int ix = 0; ix < cm->nx && !rc; ix += step) {
            float c[2];
            sp_costmap_cell_center(cm, ix, iy, c);
            if (!in_box(&reach, c) || !isfinite(dist[nav_idx(cm, ix, iy)])) continue;
            rc = visible_from(x, c, &st[n_st++]);
        }
    long seen_total = 0;
    while (!rc && n < o->max_tour_poses && seen_total < o->tour_coverage * x->n_target) {
        float best_u = 0, best_yaw = 0;
        long best_gain = 0;
        int best = -1;
        for (int k = 0; k < n_st; k++)
            for (int h = 0; h < 8; h++) {
                float yaw = h * (float)M_PI / 4, poor;
                long g = view_gain(x, &st[k], yaw, hfov, covered, &poor, 0);
                if (g == 0) continue;
                float u = (float)g / x->n_target * (1.0f + POOR_BONUS * poor / g);
                if (u > best_u) best_u = u, best_gain = g, best = k, best_yaw = yaw;
            }
        if (best < 0 || best_gain < MIN_GAIN * x->n_target) break;
        float poor;
        view_gain(x, &st[best], best_yaw, hfov, covered, &poor, 1);
        float *p = t->poses + 4 * n;
        p[0] = st[best].p[0], p[1] = st[best].p[1], p[2] = cm->floor_z, p[3] = best_yaw;
        t->gain[n] = (float)best_gain / x->n_target;
        seen_total += best_gain;
        n++;
    }
    t->coverage = x->n_target ? (float)seen_total / x->n_target : 0;
    for (int k = 0; st && k < n_st; k++) free(st[k].cells), free(st[k].bearing);
    free(st), free(covered);
    return rc ? -1 : n;
}

/* Visits the chosen views in a short order and joins them with planned paths. */
static int make_tour(sp_nav *nav, sp_nav_tour *t, const float *start, sp_error *err)
{
    const sp_costmap *cm = &nav->cm;
    int m = t->n + 1;
    float *D = malloc(sizeof(float) * m * m), *field = malloc(sizeof(float) * cm->nx * cm->ny);
    int *order = malloc(sizeof(int) * m);
    if (!D || !field || !order) {
        free(D), free(field), free(order);
        return sp_error_set(err, SP_E_NOMEM, "explore: out of memory");
    }
    for (int a = 0; a < m; a++) {
        const float *from = a ? t->poses + 4 * (a - 1) : start;
        geodesic(cm, from, field);
        for (int b = 0; b < m; b++) {
            const float *to = b ? t->poses + 4 * (b - 1) : start;
            int ix, iy;
            D[a * m + b] = sp_costmap_cell(cm, to[0], to[1], &ix, &iy) ? INFINITY : field[nav_idx(cm, ix, iy)];
        }
    }
    order_tour(D, m, order);
    float *poses = malloc(sizeof(float) * 4 * t->n), *gain = malloc(sizeof(float) * t->n);
    int rc = poses && gain ? 0 : sp_error_set(err, SP_E_NOMEM, "explore: out of memory");
    for (int k = 0; k < t->n && !rc; k++) {
        memcpy(poses + 4 * k, t->poses + 4 * (order[k] - 1), sizeof(float) * 4);
        gain[k] = t->gain[order[k] - 1];
    }
    if (!rc) {
        memcpy(t->poses, poses, sizeof(float) * 4 * t->n);
        memcpy(t->gain, gain, sizeof(float) * t->n);
    }
    free(D), free(field), free(order), free(poses), free(gain);
    /* the legs, as one path */
    float from[3] = {start[0], start[1], start[2]};
    sp_path all;
    memset(&all, 0, sizeof all);
    for (int k = 0; k < t->n && !rc; k++) {
        const float *q = t->poses + 4 * k;
        sp_nav_goal g = sp_nav_goal_pose(q[0], q[1], q[3]);
        sp_path leg;
        if ((rc = sp_plan_path(cm, from, &g, &nav->opts.planner, &leg, err))) {
            sp_error_prefix(err, "explore: leg %d of the tour: ", k + 1);
            break;
        }
        int skip = all.n ? 1 : 0; /* the leg's first waypoint is the previous one's end */
        float *w = realloc(all.waypoints, sizeof(float) * 4 * (all.n + leg.n - skip));
        float *c = realloc(all.corners, sizeof(float) * 2 * (all.n_corners + leg.n_corners - skip));
        if (!w || !c) {
            free(w ? w : all.waypoints), free(c ? c : all.corners);
            sp_path_free(&leg);
            return sp_error_set(err, SP_E_NOMEM, "explore: out of memory");
        }
        all.waypoints = w, all.corners = c;
        memcpy(w + 4 * all.n, leg.waypoints + 4 * skip, sizeof(float) * 4 * (leg.n - skip));
        memcpy(c + 2 * all.n_corners, leg.corners + 2 * skip, sizeof(float) * 2 * (leg.n_corners - skip));
        all.n += leg.n - skip, all.n_corners += leg.n_corners - skip;
        all.length_m += leg.length_m;
        all.cost += leg.cost;
        from[0] = q[0], from[1] = q[1], from[2] = q[3];
        sp_path_free(&leg);
    }
    all.status = rc ? SP_NAV_NO_VALID_PATH : SP_NAV_OK;
    t->path = all;
    return rc;
}

int sp_nav_explore(sp_nav *nav, const char *region, const float *start, sp_nav_tour *out,
                   sp_error *err)
{
    memset(out, 0, sizeof *out);
    int rc = sp_nav_resolve(nav, region, &out->target, err);
    if (rc) return rc;
    if (!out->target.found)
        return sp_error_set(err, SP_E_NOTFOUND, "explore: nothing in this model matches '%s' (best "
                            "confidence %.2f)", out->target.text, out->target.confidence);
    float s[3];
    if (start) memcpy(s, start, sizeof s);
    else if ((rc = sp_nav_default_start(nav, s, err))) return rc;
    if (!area_of(nav, out)) return sp_error_set(err, SP_E_NOTFOUND, "explore: '%s' lies outside the map", out->target.text);
    const sp_costmap *cm = &nav->cm;
    size_t n = (size_t)cm->nx * cm->ny;
    int M = nav->opts.max_tour_poses;
    explore_ctx x = {cm, out->area, calloc(n, 1), 0, calloc(n, sizeof(float))};
    float *dist = malloc(sizeof(float) * n);
    out->poses = calloc((size_t)M, 4 * sizeof(float));
    out->quality = calloc((size_t)M, sizeof(float));
    out->gain = calloc((size_t)M, sizeof(float));
    if (!x.target || !x.poor || !dist || !out->poses || !out->quality || !out->gain) {
        rc = sp_error_set(err, SP_E_NOMEM, "explore: out of memory");
        goto done;
    }
    make_targets(&x);
    if (geodesic(cm, s, dist)) {
        rc = sp_error_set(err, SP_E_NOMEM, "explore: out of memory");
        goto done;
    }
    out->n = choose_views(nav, &x, out, dist);
    if (out->n < 0) {
        out->n = 0;
        rc = sp_error_set(err, SP_E_NOMEM, "explore: out of memory");
        goto done;
    }
    if (out->n == 0) {
        rc = sp_error_set(err, SP_E_NOTFOUND, "explore: no reachable free floor from (%.2f, %.2f) sees "
                          "the area around '%s'", s[0], s[1], out->target.text);
        goto done;
    }
    if ((rc = make_tour(nav, out, s, err))) goto done;
    out->previews = calloc((size_t)out->n, sizeof *out->previews);
    if (!out->previews) {
        rc = sp_error_set(err, SP_E_NOMEM, "explore: out of memory");
        goto done;
    }
    float pitch = -nav->opts.camera_pitch_deg * (float)M_PI / 180.0f;
    for (int k = 0; k < out->n && !rc; k++) {
        const float *q = out->poses + 4 * k;
        float pos[3] = {q[0], q[1], cm->floor_z + nav->opts.camera_height_m};
        rc = nav_view_scores(nav, pos, q[3], pitch, &out->quality[k], NULL, err);
        if (!rc) rc = nav_render_preview(nav, pos, q[3], pitch, &out->previews[k], err);
        if (!rc) {
            out->previews[k].localizability = out->quality[k];
            out->previews[k].waypoint = k;
            out->n_previews++;
        }
    }
    if (!rc && out->coverage < nav->opts.tour_coverage)
        snprintf(out->note, sizeof out->note, "%d views see %.0f %% of the area around '%s' (asked %.0f %%): "
                 "the rest is not visible from reachable free floor", out->n, 100 * out->coverage,
                 out->target.text, 100 * nav->opts.tour_coverage);
done:
    free(x.target), free(x.poor), free(dist);
    if (rc) sp_nav_tour_free(out);
    return rc;
}

char *sp_nav_tour_json(const sp_nav_tour *t)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "frame", "world (the model's frame: z up, metres; yaw about +z from +x)");
    cJSON_AddItemToObject(o, "region", nav_json_target(&t->target));
    float a[4] = {t->area.min[0], t->area.min[1], t->area.max[0], t->area.max[1]};
    cJSON_AddItemToObject(o, "area_xy", nav_json_floats(a, 4));
    cJSON_AddNumberToObject(o, "coverage", t->coverage);
    cJSON_AddStringToObject(o, "note", t->note);
    cJSON *views = cJSON_AddArrayToObject(o, "views");
    for (int k = 0; k < t->n; k++) {
        cJSON *e = cJSON_CreateObject();
        cJSON_AddNumberToObject(e, "order", k + 1);
        cJSON_AddItemToObject(e, "pose", nav_json_floats(t->poses + 4 * k, 4));
        cJSON_AddNumberToObject(e, "reconstruction_quality", t->quality[k]);
        cJSON_AddNumberToObject(e, "new_coverage", t->gain[k]);
        if (k < t->n_previews && t->previews[k].file[0]) cJSON_AddStringToObject(e, "preview", t->previews[k].file);
        cJSON_AddItemToArray(views, e);
    }
    cJSON *path = cJSON_AddObjectToObject(o, "tour");
    cJSON_AddNumberToObject(path, "length_m", t->path.length_m);
    cJSON *wp = cJSON_AddArrayToObject(path, "waypoints");
    for (int i = 0; i < t->path.n; i++) cJSON_AddItemToArray(wp, nav_json_floats(t->path.waypoints + 4 * i, 4));
    char *s = cJSON_Print(o);
    cJSON_Delete(o);
    return s;
}

int sp_nav_tour_write(sp_nav *nav, sp_nav_tour *t, const char *out_dir, sp_error *err)
{
    char dir[4096], file[4096];
    sp_path_join(dir, sizeof dir, out_dir, "previews");
    int rc = sp_mkdirs(dir, err);
    if (!rc) rc = nav_write_previews(t->previews, t->n_previews, out_dir, "view", err);
    if (rc) return rc;
    if (nav_draw_available(NULL)) {
        const sp_path *paths[1] = {&t->path};
        char labels[1][128], title[320];
        snprintf(labels[0], sizeof labels[0], "tour  %.1f m  %d views  covers %.0f %%", t->path.length_m, t->n,
                 100 * t->coverage);
        snprintf(title, sizeof title, "exploring %s (%s)", t->target.text, t->target.source);
        sp_nav_box boxes[SP_NAV_MAX_BOXES];
        char obj[SP_NAV_MAX_BOXES][64];
        int tgt[SP_NAV_MAX_BOXES];
        for (int k = 0; k < t->target.n; k++) {
            boxes[k] = t->target.inst[k].box;
            snprintf(obj[k], sizeof obj[k], "%s", t->target.inst[k].label);
            tgt[k] = 1;
        }
        float start[3] = {t->path.n ? t->path.waypoints[0] : 0, t->path.n ? t->path.waypoints[1] : 0,
                          t->path.n ? t->path.waypoints[3] : 0};
        nav_map_layers L = {&nav->cm, title, t->path.n ? start : NULL, 1, paths, (const char(*)[128])labels,
                            t->target.n, boxes, (const char(*)[64])obj, tgt, t->n, t->poses, &t->area};
        sp_path_join(file, sizeof file, out_dir, "map.png");
        if ((rc = nav_draw_map(&L, file, err))) return rc;
    }
    char *js = sp_nav_tour_json(t);
    if (!js) return sp_error_set(err, SP_E_NOMEM, "explore: out of memory");
    sp_path_join(file, sizeof file, out_dir, "tour.json");
    rc = sp_write_file_atomic(file, js, strlen(js), err);
    free(js);
    return rc;
}
