/* Scene descriptions: "what objects are near the dining table?". The anchor phrase resolves to
 * its best instance; every vocabulary term is asked for, its confident instances within the
 * radius of the anchor's footprint kept (one object per place: where two terms claim the same
 * footprint, the more confident one stays; one whose surroundings are far on foot is behind a
 * wall, in the next room, not near),
 * with the distance between footprints, left of /
 * right of and in front of / behind the anchor as seen from the robot, and the region of the
 * home it belongs to; answered as a sentence and as JSON. */
#include <cjson/cJSON.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "nav_scene.h"

#define SIDE_RAD 0.09f     /* within 5 degrees of the line of sight: neither left nor right */
#define DEPTH_MARGIN_M 0.3f
#define SEARCH_M 1.0f      /* free cells beside a footprint are looked for this far from it */
#define WALK_FACTOR 2.0f   /* beyond this x the radius on foot, an object is in the next room */

void sp_nav_description_free(sp_nav_description *d)
{
    if (!d) return;
    free(d->objects);
    free(d->sentence);
    memset(d, 0, sizeof *d);
}

static float box_box_dist(const sp_nav_box *a, const sp_nav_box *b)
{
    float dx = fmaxf(0.0f, fmaxf(a->min[0] - b->max[0], b->min[0] - a->max[0]));
    float dy = fmaxf(0.0f, fmaxf(a->min[1] - b->max[1], b->min[1] - a->max[1]));
    return hypotf(dx, dy);
}

static float box_iou(const sp_nav_box *a, const sp_nav_box *b)
{
    float ix = fminf(a->max[0], b->max[0]) - fmaxf(a->min[0], b->min[0]);
    float iy = fminf(a->max[1], b->max[1]) - fmaxf(a->min[1], b->min[1]);
    if (ix <= 0 || iy <= 0) return 0;
    float i = ix * iy, ua = (a->max[0] - a->min[0]) * (a->max[1] - a->min[1]);
    float ub = (b->max[0] - b->min[0]) * (b->max[1] - b->min[1]);
    return i / fmaxf(ua + ub - i, 1e-9f);
}

static void centre(const sp_nav_box *b, float c[2])
{
    c[0] = 0.5f * (b->min[0] + b->max[0]), c[1] = 0.5f * (b->min[1] + b->max[1]);
}

/* The free cells nearest to a footprint (within 1.5 cells of the nearest one, up to SEARCH_M):
 * where one stands beside it. A fixed margin would reach across a wall thinner than itself. */
float nav_nearest_free(const sp_costmap *cm, const sp_nav_box *b, int *x0, int *y0, int *x1, int *y1)
{
    sp_costmap_cell(cm, b->min[0] - SEARCH_M, b->min[1] - SEARCH_M, x0, y0);
    sp_costmap_cell(cm, b->max[0] + SEARCH_M, b->max[1] + SEARCH_M, x1, y1);
    *x0 = *x0 < 0 ? 0 : *x0, *y0 = *y0 < 0 ? 0 : *y0;
    *x1 = *x1 >= cm->nx ? cm->nx - 1 : *x1, *y1 = *y1 >= cm->ny ? cm->ny - 1 : *y1;
    float d_min = INFINITY;
    for (int y = *y0; y <= *y1; y++)
        for (int x = *x0; x <= *x1; x++) {
            if (cm->occ[nav_idx(cm, x, y)] != SP_CELL_FREE) continue;
            float c[2];
            sp_costmap_cell_center(cm, x, y, c);
            d_min = fminf(d_min, nav_box_dist(b, c));
        }
    return d_min + 1.5f * cm->res;
}

/* Walking distance (metres, 4-connected over cells that are not obstacles) from where one
 * stands beside the anchor: objects far on foot are in the next room, however close their
 * footprints (a wall between). Unknown cells are walked over: a wall is an obstacle, and the
 * unknown patches a trained splat's costmap leaves beside furniture are no wall. field [cells]. */
static int walk_field(const sp_costmap *cm, const sp_nav_box *anchor, float *field)
{
    long n = (long)cm->nx * cm->ny, head = 0, tail = 0;
    long *queue = malloc(sizeof(long) * n);
    if (!queue) return -1;
    for (long i = 0; i < n; i++) field[i] = INFINITY;
    int x0, y0, x1, y1;
    float around = nav_nearest_free(cm, anchor, &x0, &y0, &x1, &y1);
    for (int y = y0; y <= y1; y++)
        for (int x = x0; x <= x1; x++) {
            long i = nav_idx(cm, x, y);
            float c[2];
            sp_costmap_cell_center(cm, x, y, c);
            if (cm->occ[i] == SP_CELL_FREE && nav_box_dist(anchor, c) <= around) field[i] = 0, queue[tail++] = i;
        }
    while (head < tail) { /* breadth first: all steps cost one cell */
        long c = queue[head++];
        int cx = (int)(c % cm->nx), cy = (int)(c / cm->nx);
        for (int k = 0; k < 4; k++) {
            int x = cx + (k == 0) - (k == 1), y = cy + (k == 2) - (k == 3);
            if (!nav_inside(cm, x, y)) continue;
            long j = nav_idx(cm, x, y);
            if (cm->occ[j] == SP_CELL_OCCUPIED || isfinite(field[j])) continue;
            field[j] = field[c] + cm->res;
            queue[tail++] = j;
        }
    }
    free(queue);
    return 0;
}

/* The walking distance to where one stands beside box b (INFINITY when out of reach). */
static float walk_to(const sp_costmap *cm, const float *field, const sp_nav_box *b)
{
    int x0, y0, x1, y1;
    float best = INFINITY, around = nav_nearest_free(cm, b, &x0, &y0, &x1, &y1);
    for (int y = y0; y <= y1; y++)
        for (int x = x0; x <= x1; x++) {
            float c[2];
            sp_costmap_cell_center(cm, x, y, c);
            if (nav_box_dist(b, c) <= around) best = fminf(best, field[nav_idx(cm, x, y)]);
        }
    return best;
}

static void relations(const float robot[3], const sp_nav_box *anchor, sp_nav_object *o)
{
    float a[2], p[2];
    centre(anchor, a);
    centre(&o->inst.box, p);
    float va[2] = {a[0] - robot[0], a[1] - robot[1]}, vo[2] = {p[0] - robot[0], p[1] - robot[1]};
    float ang = atan2f(va[0] * vo[1] - va[1] * vo[0], va[0] * vo[0] + va[1] * vo[1]);
    o->left = ang > SIDE_RAD ? 1 : ang < -SIDE_RAD ? -1 : 0;
    float da = hypotf(va[0], va[1]), dp = hypotf(vo[0], vo[1]);
    o->front = dp < da - DEPTH_MARGIN_M ? 1 : dp > da + DEPTH_MARGIN_M ? -1 : 0;
}

/* The term's region from the table; else that of the nearest described object with one. */
static void regions(sp_nav_description *d)
{
    for (int i = 0; i < d->n; i++) {
        int r = nav_region_of_object(d->objects[i].name);
        snprintf(d->objects[i].region, sizeof d->objects[i].region, "%s", r >= 0 ? nav_region_name(r) : "");
    }
    for (int i = 0; i < d->n; i++) {
        if (d->objects[i].region[0]) continue;
        float best = 2.0f;
        for (int j = 0; j < d->n; j++) {
            if (!d->objects[j].region[0] || nav_region_of_object(d->objects[j].name) < 0) continue;
            float dd = box_box_dist(&d->objects[i].inst.box, &d->objects[j].inst.box);
            if (dd < best && j != i) best = dd, memcpy(d->objects[i].region, d->objects[j].region, sizeof d->objects[i].region);
        }
    }
}

static int by_distance(const void *a, const void *b)
{
    float x = ((const sp_nav_object *)a)->distance_m, y = ((const sp_nav_object *)b)->distance_m;
    return (x > y) - (x < y);
}

/* Appends with clamping (a long list is cut, not overrun). */
static void put(char *buf, size_t cap, size_t *n, const char *fmt, ...) __attribute__((format(printf, 4, 5)));
static void put(char *buf, size_t cap, size_t *n, const char *fmt, ...)
{
    if (*n + 1 >= cap) return;
    va_list ap;
    va_start(ap, fmt);
    int w = vsnprintf(buf + *n, cap - *n, fmt, ap);
    va_end(ap);
    if (w > 0) *n = *n + (size_t)w < cap - 1 ? *n + (size_t)w : cap - 1;
}

/* "Near the dining table (5.0, 6.3; dining room): 4 dining chairs, 0.0 to 0.1 m away (2 on its
 * left, 2 on its right as seen from the robot); a painting 0.9 m away, behind it." */
static char *sentence(const sp_nav_description *d, float radius)
{
    size_t cap = 4096, n = 0;
    char *s = malloc(cap);
    if (!s) return NULL;
    const sp_nav_instance *a = &d->anchor.inst[0];
    put(s, cap, &n, "Near the %s (at %.1f, %.1f%s%s)", d->anchor.text, a->position[0], a->position[1],
        d->anchor_region[0] ? ", in the " : "", d->anchor_region);
    if (d->n == 0) {
        put(s, cap, &n, " nothing else of the %d household objects asked for is within %.1f m.", d->n_queried, radius);
        return s;
    }
    put(s, cap, &n, ":");
    uint8_t done[512] = {0};
    int groups = 0;
    for (int i = 0; i < d->n && i < 512; i++) {
        if (done[i]) continue;
        int count = 0, left = 0, right = 0, front = 0, behind = 0;
        float lo = INFINITY, hi = 0;
        for (int j = i; j < d->n && j < 512; j++) {
            if (strcmp(d->objects[j].name, d->objects[i].name)) continue;
            done[j] = 1, count++;
            lo = fminf(lo, d->objects[j].distance_m), hi = fmaxf(hi, d->objects[j].distance_m);
            left += d->objects[j].left > 0, right += d->objects[j].left < 0;
            front += d->objects[j].front > 0, behind += d->objects[j].front < 0;
        }
        put(s, cap, &n, "%s ", groups++ ? ";" : "");
        if (count == 1) put(s, cap, &n, "a %s %.1f m away", d->objects[i].name, lo);
        else if (hi - lo < 0.05f) put(s, cap, &n, "%d %ss, %.1f m away", count, d->objects[i].name, lo);
        else put(s, cap, &n, "%d %ss, %.1f to %.1f m away", count, d->objects[i].name, lo, hi);
        const char *parts[4];
        char b[4][48];
        int np = 0;
        if (left) snprintf(b[np], sizeof b[np], count > 1 ? "%d on its left" : "on its left", left), parts[np] = b[np], np++;
        if (right) snprintf(b[np], sizeof b[np], count > 1 ? "%d on its right" : "on its right", right), parts[np] = b[np], np++;
        if (front) snprintf(b[np], sizeof b[np], count > 1 ? "%d in front of it" : "in front of it", front), parts[np] = b[np], np++;
        if (behind) snprintf(b[np], sizeof b[np], count > 1 ? "%d behind it" : "behind it", behind), parts[np] = b[np], np++;
        if (np) {
            put(s, cap, &n, " (");
            for (int k = 0; k < np; k++) put(s, cap, &n, "%s%s", k ? ", " : "", parts[k]);
            put(s, cap, &n, ")");
        }
    }
    put(s, cap, &n, ". Left and right as seen from the robot at (%.1f, %.1f).", d->robot[0], d->robot[1]);
    return s;
}

int sp_nav_describe(sp_nav *nav, const char *anchor, float radius_m, const float *robot,
                    sp_nav_description *out, sp_error *err)
{
    memset(out, 0, sizeof *out);
    if (!(radius_m <= 100)) /* before the anchor is resolved: the option is wrong whatever it finds */
        return sp_error_set(err, SP_E_ARG, "describe: radius %g m: expected at most 100", radius_m);
    sp_nav_target t;
    int rc = sp_nav_resolve(nav, anchor, &t, err);
    if (rc) return rc;
    return sp_nav_describe_target(nav, &t, 0, radius_m, robot, out, err);
}

int sp_nav_describe_target(sp_nav *nav, const sp_nav_target *anchor, int instance, float radius_m,
                           const float *robot, sp_nav_description *out, sp_error *err)
{
    memset(out, 0, sizeof *out);
    if (!(radius_m <= 100)) /* NaN too; <= 0 picks the default */
        return sp_error_set(err, SP_E_ARG, "describe: radius %g m: expected at most 100", radius_m);
    float radius = radius_m > 0 ? radius_m : nav->opts.near_m;
    int rc = 0;
    out->anchor = *anchor;
    if (!out->anchor.found || out->anchor.n < 1)
        return sp_error_set(err, SP_E_NOTFOUND, "describe: nothing in this model matches '%s' (best "
                            "confidence %.2f)", out->anchor.text, out->anchor.confidence);
    if (instance < 0 || instance >= out->anchor.n)
        return sp_error_set(err, SP_E_ARG, "describe: '%s' has %d instances, not %d", out->anchor.text,
                            out->anchor.n, instance + 1);
    sp_nav_instance chosen = out->anchor.inst[instance]; /* the anchor instance goes first */
    out->anchor.inst[instance] = out->anchor.inst[0];
    out->anchor.inst[0] = chosen;
    if (robot) memcpy(out->robot, robot, sizeof out->robot);
    else if ((rc = sp_nav_default_start(nav, out->robot, err))) return rc;
    int ar = nav_region_of_object(out->anchor.text);
    snprintf(out->anchor_region, sizeof out->anchor_region, "%s", ar >= 0 ? nav_region_name(ar) : "");
    const sp_nav_box *abox = &out->anchor.inst[0].box;
    int cap = 64;
    out->objects = malloc(sizeof *out->objects * cap);
    float *field = malloc(sizeof(float) * nav->cm.nx * nav->cm.ny);
    if (!out->objects || !field || walk_field(&nav->cm, abox, field)) {
        free(field);
        sp_nav_description_free(out);
        return sp_error_set(err, SP_E_NOMEM, "describe: out of memory");
    }
    for (int v = 0; v < nav->n_vocab && !rc; v++) {
        const char *term = nav->vocab[v];
        if (!strcasecmp(term, out->anchor.text)) continue;
        sp_nav_target t;
        if ((rc = sp_nav_resolve(nav, term, &t, err))) break;
        out->n_queried++;
        if (!t.found || strcmp(t.source, "query")) continue;
        for (int k = 0; k < t.n; k++) {
            float dist = box_box_dist(&t.inst[k].box, abox);
            if (dist > radius || box_iou(&t.inst[k].box, abox) > 0.5f) continue; /* the anchor itself */
            if (walk_to(&nav->cm, field, &t.inst[k].box) > WALK_FACTOR * radius) {
                out->n_walled_off++; /* near, but in the next room */
                continue;
            }
            int dup = -1;
            for (int j = 0; j < out->n && dup < 0; j++)
                if (box_iou(&out->objects[j].inst.box, &t.inst[k].box) > 0.5f) dup = j;
            if (dup >= 0 && out->objects[dup].inst.confidence >= t.inst[k].confidence) continue;
            if (dup < 0 && out->n == cap) {
                sp_nav_object *o2 = realloc(out->objects, sizeof *o2 * cap * 2);
                if (!o2) {
                    rc = sp_error_set(err, SP_E_NOMEM, "describe: out of memory");
                    break;
                }
                out->objects = o2, cap *= 2;
            }
            sp_nav_object *o = &out->objects[dup >= 0 ? dup : out->n++];
            memset(o, 0, sizeof *o);
            snprintf(o->name, sizeof o->name, "%s", term);
            o->inst = t.inst[k];
            o->distance_m = dist;
            relations(out->robot, abox, o);
        }
    }
    free(field);
    if (rc) {
        sp_nav_description_free(out);
        return rc;
    }
    qsort(out->objects, (size_t)out->n, sizeof *out->objects, by_distance);
    regions(out);
    out->sentence = sentence(out, radius);
    if (!out->sentence) {
        sp_nav_description_free(out);
        return sp_error_set(err, SP_E_NOMEM, "describe: out of memory");
    }
    return SP_OK;
}

char *sp_nav_description_json(const sp_nav_description *d)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "frame", "world (the model's frame: z up, metres)");
    cJSON_AddItemToObject(o, "anchor", nav_json_target(&d->anchor));
    cJSON_AddStringToObject(o, "anchor_region", d->anchor_region);
    cJSON_AddItemToObject(o, "robot", nav_json_floats(d->robot, 3));
    cJSON_AddNumberToObject(o, "terms_queried", d->n_queried);
    cJSON_AddNumberToObject(o, "near_but_behind_a_wall", d->n_walled_off);
    cJSON *arr = cJSON_AddArrayToObject(o, "objects");
    for (int i = 0; i < d->n; i++) {
        const sp_nav_object *b = &d->objects[i];
        cJSON *e = cJSON_CreateObject();
        cJSON_AddStringToObject(e, "name", b->name);
        cJSON_AddItemToObject(e, "position", nav_json_floats(b->inst.position, 3));
        float f[4] = {b->inst.box.min[0], b->inst.box.min[1], b->inst.box.max[0], b->inst.box.max[1]};
        cJSON_AddItemToObject(e, "footprint_xy", nav_json_floats(f, 4));
        cJSON_AddNumberToObject(e, "confidence", b->inst.confidence);
        cJSON_AddNumberToObject(e, "distance_m", b->distance_m);
        cJSON *rel = cJSON_AddArrayToObject(e, "relations");
        cJSON_AddItemToArray(rel, cJSON_CreateString("near"));
        if (b->left) cJSON_AddItemToArray(rel, cJSON_CreateString(b->left > 0 ? "left of" : "right of"));
        if (b->front) cJSON_AddItemToArray(rel, cJSON_CreateString(b->front > 0 ? "in front of" : "behind"));
        cJSON_AddStringToObject(e, "region", b->region);
        cJSON_AddItemToArray(arr, e);
    }
    cJSON_AddStringToObject(o, "sentence", d->sentence ? d->sentence : "");
    char *s = cJSON_Print(o);
    cJSON_Delete(o);
    return s;
}
