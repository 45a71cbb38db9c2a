/* A fake world for the agent's tests, laid out like data/worlds/house.world: a 10 x 8 m house at
 * 10 cm cells with walls and doorways, five rooms, the furniture (occupied footprints), two mugs
 * (one on the kitchen counter, one on the dining table), an unknown patch in the bedroom corner,
 * label-matching queries, Dijkstra planning with a robot radius, tiny PNG "renders". It stands in
 * for the query engine and the nav module so the dialogue loop, validation and commitments are
 * tested without them; it is not a model of their accuracy. */
#ifndef SEMSPLAT_TEST_FAKE_WORLD_H
#define SEMSPLAT_TEST_FAKE_WORLD_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "agent/agent_internal.h"
#include "semsplat/io.h"

#define FW_RES 0.1
#define FW_X0 (-0.5)
#define FW_Y0 (-0.5)
#define FW_W 110
#define FW_H 90
#define FW_ROBOT_R 0.2

typedef struct fw_object {
    const char *label;
    double x, y, z, hx, hy, h; /* centre, half extents, height */
    int floor;                 /* occupies the floor */
} fw_object;

static const fw_object fw_objects[] = {
    {"refrigerator", 0.45, 7.55, 0.9, 0.35, 0.35, 1.8, 1},
    {"kitchen counter", 1.0, 7.62, 0.45, 0.45, 0.3, 0.9, 1},
    {"kitchen counter", 0.38, 5.6, 0.45, 0.3, 0.45, 0.9, 1},
    {"sink", 2.1, 7.62, 0.45, 0.45, 0.3, 0.9, 1},
    {"stove", 2.97, 7.61, 0.45, 0.38, 0.3, 0.9, 1},
    {"tv stand", 1.5, 4.2, 0.25, 0.7, 0.2, 0.5, 1},
    {"tv", 1.5, 4.27, 0.9, 0.6, 0.05, 0.7, 0},
    {"couch", 1.5, 1.05, 0.4, 1.0, 0.45, 0.8, 1},
    {"armchair", 3.25, 2.55, 0.4, 0.4, 0.4, 0.8, 1},
    {"bookshelf", 0.25, 3.3, 0.9, 0.2, 0.5, 1.8, 1},
    {"dining table", 5.0, 6.3, 0.38, 0.8, 0.45, 0.76, 1},
    {"dining chair", 4.6, 5.58, 0.45, 0.2, 0.2, 0.9, 1},
    {"dining chair", 5.4, 5.58, 0.45, 0.2, 0.2, 0.9, 1},
    {"dining chair", 4.6, 7.02, 0.45, 0.2, 0.2, 0.9, 1},
    {"dining chair", 5.4, 7.02, 0.45, 0.2, 0.2, 0.9, 1},
    {"bed", 8.95, 6.0, 0.3, 1.0, 0.8, 0.6, 1},
    {"wardrobe", 6.87, 6.4, 1.0, 0.3, 0.6, 2.0, 1},
    {"red mug", 1.0, 7.62, 0.95, 0.05, 0.05, 0.1, 0},
    {"blue mug", 5.2, 6.3, 0.81, 0.05, 0.05, 0.1, 0},
};
#define FW_N_OBJECTS ((int)(sizeof fw_objects / sizeof fw_objects[0]))

typedef struct fw_region {
    const char *name;
    double x0, y0, x1, y1;
} fw_region;

static const fw_region fw_regions[] = {
    {"living room", 0, 0, 6.5, 4.5}, {"kitchen", 0, 4.5, 3.5, 8},   {"dining room", 3.5, 4.5, 6.5, 8},
    {"hall", 6.5, 0, 10, 3},         {"bedroom", 6.5, 3, 10, 8},
};

/* Walls as boxes (x0, y0, x1, y1), doorways left open. */
static const double fw_walls[][4] = {
    {-0.1, -0.1, 10.1, 0.0}, {-0.1, 8.0, 10.1, 8.1}, {-0.1, -0.1, 0.0, 8.1}, {10.0, -0.1, 10.1, 8.1},
    {0, 4.45, 2.6, 4.55},    {3.4, 4.45, 4.0, 4.55}, {6.2, 4.45, 6.5, 4.55}, /* living | kitchen, dining */
    {3.45, 4.5, 3.55, 5.3},  {3.45, 7.0, 3.55, 8.0},                         /* kitchen | dining */
    {6.45, 0, 6.55, 1.0},    {6.45, 1.9, 6.55, 8.0},                         /* living, dining | hall, bedroom */
    {6.5, 2.95, 8.0, 3.05},  {8.95, 2.95, 10, 3.05},                         /* hall | bedroom */
};

typedef struct fake_world {
    unsigned char cell[FW_H][FW_W]; /* agent_cell */
    float clear[FW_H][FW_W];        /* metres to the nearest non-free cell */
    int n_queries, n_plans, n_renders;
    char last_query[256];
} fake_world;

static int fw_ix(double x) { return (int)floor((x - FW_X0) / FW_RES); }
static int fw_iy(double y) { return (int)floor((y - FW_Y0) / FW_RES); }
static double fw_cx(int i) { return FW_X0 + (i + 0.5) * FW_RES; }
static double fw_cy(int j) { return FW_Y0 + (j + 0.5) * FW_RES; }

static void fw_fill(fake_world *w, double x0, double y0, double x1, double y1, int v)
{
    for (int j = 0; j < FW_H; j++)
        for (int i = 0; i < FW_W; i++)
            if (fw_cx(i) >= x0 && fw_cx(i) <= x1 && fw_cy(j) >= y0 && fw_cy(j) <= y1) w->cell[j][i] = (unsigned char)v;
}

static void fw_build(fake_world *w)
{
    memset(w, 0, sizeof *w);
    fw_fill(w, -1, -1, 11, 9, AGENT_CELL_OUTSIDE);
    fw_fill(w, 0, 0, 10, 8, AGENT_CELL_FREE);
    for (size_t k = 0; k < sizeof fw_walls / sizeof fw_walls[0]; k++)
        fw_fill(w, fw_walls[k][0], fw_walls[k][1], fw_walls[k][2], fw_walls[k][3], AGENT_CELL_OCCUPIED);
    for (int k = 0; k < FW_N_OBJECTS; k++) {
        const fw_object *o = &fw_objects[k];
        if (o->floor) fw_fill(w, o->x - o->hx, o->y - o->hy, o->x + o->hx, o->y + o->hy, AGENT_CELL_OCCUPIED);
    }
    fw_fill(w, 9.4, 7.3, 10, 8, AGENT_CELL_UNKNOWN);
    /* brute-force clearance (fine at this size) */
    for (int j = 0; j < FW_H; j++)
        for (int i = 0; i < FW_W; i++) {
            float best = 99;
            for (int dj = -6; dj <= 6; dj++)
                for (int di = -6; di <= 6; di++) {
                    int a = i + di, b = j + dj;
                    int bad = a < 0 || b < 0 || a >= FW_W || b >= FW_H || w->cell[b][a] != AGENT_CELL_FREE;
                    float d = (float)(hypot(di, dj) * FW_RES);
                    if (bad && d < best) best = d;
                }
            w->clear[j][i] = w->cell[j][i] == AGENT_CELL_FREE ? best : 0;
        }
}

static int fw_cell_at(const fake_world *w, double x, double y)
{
    int i = fw_ix(x), j = fw_iy(y);
    if (!isfinite(x) || !isfinite(y) || i < 0 || j < 0 || i >= FW_W || j >= FW_H) return AGENT_CELL_OUTSIDE;
    return w->cell[j][i];
}

static int fw_drivable(const fake_world *w, int i, int j)
{
    return i >= 0 && j >= 0 && i < FW_W && j < FW_H && w->cell[j][i] == AGENT_CELL_FREE &&
           w->clear[j][i] > FW_ROBOT_R;
}

/* ---- world ops ---- */

static const char *fw_canonical(const char *word)
{
    static const char *const syn[][2] = {{"fridge", "refrigerator"}, {"sofa", "couch"},
                                         {"television", "tv"},       {"monitor", "tv"},
                                         {"chair", "dining chair"},  {"table", "dining table"},
                                         {"counter", "kitchen counter"}, {"cup", "mug"}};
    for (size_t k = 0; k < sizeof syn / sizeof syn[0]; k++)
        if (!strcmp(word, syn[k][0])) return syn[k][1];
    return word;
}

/* A label matches when the text's last word (or its synonym) is the label's last word, and every
 * other word of the text that names a colour matches too. */
static int fw_matches(const char *text, const char *label)
{
    char t[256];
    snprintf(t, sizeof t, "%s", text);
    char *last = strrchr(t, ' ');
    const char *head = fw_canonical(last ? last + 1 : t);
    const char *lh = strrchr(label, ' ');
    const char *hl = strrchr(head, ' ');
    if (strcmp(hl ? hl + 1 : head, lh ? lh + 1 : label) && strcmp(head, label)) return 0;
    static const char *const colours[] = {"red", "blue", "green", "white", "black"};
    for (size_t k = 0; k < 5; k++)
        if (strstr(t, colours[k]) && !strstr(label, colours[k])) return 0;
    return 1;
}

static int fw_query(void *ctx, const char *text, agent_found *out, sp_error *err)
{
    fake_world *w = ctx;
    w->n_queries++;
    snprintf(w->last_query, sizeof w->last_query, "%s", text);
    out->min_confidence = 0.2;
    out->confidence = 0.11;
    snprintf(out->source, sizeof out->source, "fake world (test): label match");
    for (int k = 0; k < FW_N_OBJECTS && out->n < AGENT_MAX_INSTANCES; k++) {
        const fw_object *o = &fw_objects[k];
        if (!fw_matches(text, o->label)) continue;
        agent_instance *in = &out->inst[out->n++];
        in->position[0] = o->x, in->position[1] = o->y, in->position[2] = o->z;
        in->extent_min[0] = o->x - o->hx, in->extent_min[1] = o->y - o->hy, in->extent_min[2] = o->z - o->h / 2;
        in->extent_max[0] = o->x + o->hx, in->extent_max[1] = o->y + o->hy, in->extent_max[2] = o->z + o->h / 2;
        in->confidence = 0.31;
        in->score = 1.0;
    }
    out->found = out->n > 0;
    if (out->found) out->confidence = 0.31;
    return SP_OK;
}

/* Dijkstra from the start cell over drivable cells (8-connected, cost + penalty), binary heap. */
typedef struct { float d; int c; } fw_hn;
static void fw_push(fw_hn *h, int *n, fw_hn v)
{
    int i = (*n)++;
    while (i > 0 && h[(i - 1) / 2].d > v.d) h[i] = h[(i - 1) / 2], i = (i - 1) / 2;
    h[i] = v;
}
static fw_hn fw_pop(fw_hn *h, int *n)
{
    fw_hn top = h[0], last = h[--(*n)];
    int i = 0;
    for (;;) {
        int c = 2 * i + 1;
        if (c >= *n) break;
        if (c + 1 < *n && h[c + 1].d < h[c].d) c++;
        if (h[c].d >= last.d) break;
        h[i] = h[c], i = c;
    }
    h[i] = last;
    return top;
}

static void fw_dijkstra(const fake_world *w, int si, int sj, const float *penalty, float *dist, int *prev)
{
    int n = FW_W * FW_H, hn = 0;
    for (int k = 0; k < n; k++) dist[k] = INFINITY, prev[k] = -1;
    fw_hn *heap = malloc((size_t)n * 8 * sizeof *heap);
    dist[sj * FW_W + si] = 0;
    fw_push(heap, &hn, (fw_hn){0, sj * FW_W + si});
    while (hn > 0) {
        fw_hn t = fw_pop(heap, &hn);
        if (t.d > dist[t.c]) continue;
        int bi = t.c % FW_W, bj = t.c / FW_W;
        for (int dj = -1; dj <= 1; dj++)
            for (int di = -1; di <= 1; di++) {
                int a = bi + di, b = bj + dj;
                if ((!di && !dj) || !fw_drivable(w, a, b)) continue;
                float c = t.d + (float)(hypot(di, dj) * FW_RES) * (1 + (penalty ? penalty[b * FW_W + a] : 0));
                if (c < dist[b * FW_W + a] && hn < n * 8) {
                    dist[b * FW_W + a] = c, prev[b * FW_W + a] = t.c;
                    fw_push(heap, &hn, (fw_hn){c, b * FW_W + a});
                }
            }
    }
    free(heap);
}

static int fw_write_png(const char *path, int width, int height, unsigned char shade, sp_error *err)
{
    sp_image img = {0};
    img.width = width, img.height = height, img.channels = 3, img.bit_depth = 8;
    img.data = malloc((size_t)width * height * 3);
    if (!img.data) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    memset(img.data, shade, (size_t)width * height * 3);
    int rc = sp_image_write_png(path, &img, err);
    free(img.data);
    return rc;
}

static int fw_plan(void *ctx, const sp_agent_pose *start, const agent_goalspec *g, int k,
                   const char *target, const char *out_dir, agent_plans *out, sp_error *err)
{
    fake_world *w = ctx;
    w->n_plans++;
    int si = fw_ix(start->x), sj = fw_iy(start->y);
    if (!fw_drivable(w, si, sj)) {
        snprintf(out->error, sizeof out->error, "START_OCCUPIED");
        snprintf(out->note, sizeof out->note, "the start (%.2f, %.2f) is not free", start->x, start->y);
        return SP_OK;
    }
    int n = FW_W * FW_H;
    float *dist = malloc(n * sizeof *dist), *pen = calloc(n, sizeof *pen);
    int *prev = malloc(n * sizeof *prev);
    for (int p = 0; p < k && p < SP_AGENT_MAX_K; p++) {
        fw_dijkstra(w, si, sj, pen, dist, prev);
        int goal = -1;
        double gd = INFINITY;
        for (int c = 0; c < n; c++) {
            if (!isfinite(dist[c])) continue;
            double d = hypot(fw_cx(c % FW_W) - g->point[0], fw_cy(c / FW_W) - g->point[1]);
            if (d <= g->tolerance_m + 1e-9 && d < gd - 1e-9) gd = d, goal = c;
        }
        if (goal < 0) {
            if (p == 0) {
                int cell = fw_cell_at(w, g->point[0], g->point[1]);
                snprintf(out->error, sizeof out->error, "%s", cell == AGENT_CELL_FREE ? "NO_VALID_PATH" : "GOAL_OCCUPIED");
                snprintf(out->note, sizeof out->note, "no free pose within %.2f m of (%.2f, %.2f) is reachable",
                         g->tolerance_m, g->point[0], g->point[1]);
            }
            break;
        }
        int cells[FW_W * FW_H / 2], m = 0;
        for (int c = goal; c >= 0 && m < FW_W * FW_H / 2; c = prev[c]) cells[m++] = c;
        agent_path *ap = &out->paths[out->n];
        int nw = (m + 4) / 5 + 1;
        ap->wp = malloc((size_t)nw * 4 * sizeof *ap->wp);
        ap->n = 0;
        for (int q = m - 1; q >= 0; q -= 5) {
            ap->wp[ap->n * 4] = fw_cx(cells[q] % FW_W), ap->wp[ap->n * 4 + 1] = fw_cy(cells[q] / FW_W);
            ap->wp[ap->n * 4 + 2] = 0, ap->n++;
        }
        if (ap->wp[(ap->n - 1) * 4] != fw_cx(goal % FW_W) || ap->wp[(ap->n - 1) * 4 + 1] != fw_cy(goal / FW_W)) {
            ap->wp[ap->n * 4] = fw_cx(goal % FW_W), ap->wp[ap->n * 4 + 1] = fw_cy(goal / FW_W), ap->wp[ap->n * 4 + 2] = 0;
            ap->n++;
        }
        for (int q = 0; q < ap->n; q++) {
            double *a = ap->wp + q * 4, *b = q + 1 < ap->n ? a + 4 : a;
            a[3] = q + 1 < ap->n ? atan2(b[1] - a[1], b[0] - a[0]) : (q ? ap->wp[(q - 1) * 4 + 3] : start->yaw);
        }
        double *e = ap->wp + (ap->n - 1) * 4;
        e[3] = isfinite(g->yaw) ? g->yaw : atan2(g->point[1] - e[1], g->point[0] - e[0]);
        ap->length_m = agent_path_length(ap->wp, ap->n);
        ap->min_clearance_m = 0.3 + 0.05 * p, ap->mean_clearance_m = 0.5;
        ap->localizability = 0.8, ap->semantic = 0.5, ap->score = 1.0 - 0.1 * p;
        if (out_dir && target) {
            char dir[1100];
            snprintf(dir, sizeof dir, "%s/previews", out_dir);
            sp_mkdirs(dir, err);
            ap->n_previews = 2;
            for (int v = 0; v < 2; v++) {
                snprintf(ap->previews[v], sizeof ap->previews[v], "%s/traj%d_view%d.png", dir, out->n + 1, v);
                if (fw_write_png(ap->previews[v], 16, 12, (unsigned char)(80 + 40 * v), err)) return err->code;
            }
        }
        out->n++;
        for (int q = 0; q < m; q++) /* push later paths away from this one */
            for (int dj = -4; dj <= 4; dj++)
                for (int di = -4; di <= 4; di++) {
                    int a = cells[q] % FW_W + di, b = cells[q] / FW_W + dj;
                    if (a >= 0 && b >= 0 && a < FW_W && b < FW_H) pen[b * FW_W + a] = 3;
                }
    }
    if (out_dir && target && out->n) {
        snprintf(out->map_image, sizeof out->map_image, "%s/map.png", out_dir);
        if (fw_write_png(out->map_image, FW_W, FW_H, 200, err)) return err->code;
    }
    if (out->n && out->n < k) snprintf(out->note, sizeof out->note, "only %d distinct trajectories", out->n);
    free(dist), free(pen), free(prev);
    return SP_OK;
}

static int fw_render(void *ctx, const sp_agent_pose *pose, const char *png, sp_error *err)
{
    ((fake_world *)ctx)->n_renders++;
    return fw_write_png(png, 32, 24, 128, err);
}

static int fw_describe(void *ctx, const agent_instance *an, const char *name, double radius,
                       const sp_agent_pose *robot, agent_scene *out, sp_error *err)
{
    for (int k = 0; k < FW_N_OBJECTS && out->n < AGENT_MAX_SCENE; k++) {
        const fw_object *o = &fw_objects[k];
        if (fabs(o->x - an->position[0]) < 1e-6 && fabs(o->y - an->position[1]) < 1e-6 && !strstr(o->label, "mug")) continue;
        agent_scene_item *it = &out->items[out->n];
        snprintf(it->name, sizeof it->name, "%s", o->label);
        it->position[0] = o->x, it->position[1] = o->y, it->position[2] = o->z;
        it->confidence = 0.3;
        it->distance_m = NAN;
        if (agent_dist_to_footprint(an, o->x, o->y) <= radius + 1) out->n++;
    }
    snprintf(out->source, sizeof out->source, "fake world (test)");
    return SP_OK;
}

static void fw_region_of(void *ctx, double x, double y, char *out, size_t cap)
{
    out[0] = 0;
    for (size_t k = 0; k < sizeof fw_regions / sizeof fw_regions[0]; k++)
        if (x >= fw_regions[k].x0 && x <= fw_regions[k].x1 && y >= fw_regions[k].y0 && y <= fw_regions[k].y1) {
            snprintf(out, cap, "%s", fw_regions[k].name);
            return;
        }
}

static int fw_explore(void *ctx, const char *region, const sp_agent_pose *robot, int max_wp,
                      const char *out_dir, agent_tour *out, sp_error *err)
{
    fake_world *w = ctx;
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int found = 0;
    for (size_t k = 0; k < sizeof fw_regions / sizeof fw_regions[0] && !found; k++)
        if (strstr(fw_regions[k].name, region) || strstr(region, fw_regions[k].name))
            x0 = fw_regions[k].x0, y0 = fw_regions[k].y0, x1 = fw_regions[k].x1, y1 = fw_regions[k].y1, found = 1;
    for (int k = 0; k < FW_N_OBJECTS && !found; k++)
        if (fw_matches(region, fw_objects[k].label))
            x0 = fw_objects[k].x - 1.5, y0 = fw_objects[k].y - 1.5, x1 = fw_objects[k].x + 1.5, y1 = fw_objects[k].y + 1.5, found = 1;
    if (!found) return sp_error_set(err, SP_E_NOTFOUND, "no region or object called '%s' on this map", region);
    snprintf(out->region, sizeof out->region, "%s", region);
    for (int a = 1; a <= 3 && out->n < max_wp; a++)
        for (int b = 1; b <= 3 && out->n < max_wp; b++) {
            double x = x0 + (x1 - x0) * a / 4, y = y0 + (y1 - y0) * b / 4;
            if (!fw_drivable(w, fw_ix(x), fw_iy(y))) continue;
            double *p = out->wp[out->n++];
            p[0] = fw_cx(fw_ix(x)), p[1] = fw_cy(fw_iy(y)), p[2] = 0, p[3] = 0;
        }
    return SP_OK;
}

static int fw_cell(void *ctx, double x, double y) { return fw_cell_at(ctx, x, y); }

static int fw_suggest(void *ctx, const char *text, char (*names)[64], int max)
{
    /* the labels sharing the most letters with the text, as a crude "did you mean" */
    int n = 0;
    static const char *const pick[] = {"refrigerator", "couch", "dining table"};
    for (int k = 0; k < 3 && n < max; k++) snprintf(names[n++], 64, "%s", pick[k]);
    return n;
}

static void fw_close(void *ctx) { free(ctx); }

static const agent_world_ops fw_ops = {"fake", fw_query, fw_plan, fw_render, fw_describe, fw_explore,
                                       fw_cell, fw_region_of, fw_suggest, fw_close, NULL};

static agent_world fw_world(fake_world **handle)
{
    fake_world *w = malloc(sizeof *w);
    fw_build(w);
    if (handle) *handle = w;
    agent_world aw = {&fw_ops, w};
    return aw;
}

#endif
