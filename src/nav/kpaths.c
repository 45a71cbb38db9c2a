/* k genuinely different paths by the penalty method (as road routers build alternatives): after
 * each planner run the corridor around the route it found costs more, so the next run looks
 * elsewhere; a route is kept when it is at most max_length_ratio x the best's length and shares
 * at most max_share of its length with every kept route, in both directions. Also the share and
 * clearance measures the ranking reports. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "nav_internal.h"

#define SHARE_STEP_M 0.05f /* sampling step of the share measure */

float sp_path_share(const float *a, int na, int stride_a, const float *b, int nb, int stride_b,
                    float radius_m)
{
    double total = 0, shared = 0;
    for (int k = 0; k + 1 < na; k++) {
        const float *p0 = a + k * stride_a, *p1 = a + (k + 1) * stride_a;
        float l = hypotf(p1[0] - p0[0], p1[1] - p0[1]);
        int sub = (int)ceilf(l / SHARE_STEP_M);
        for (int s = 0; s < sub; s++) {
            float t = (s + 0.5f) / sub, p[2] = {p0[0] + t * (p1[0] - p0[0]), p0[1] + t * (p1[1] - p0[1])};
            float d = INFINITY;
            for (int j = 0; j + 1 < nb && d > radius_m; j++) {
                float q0[2] = {b[j * stride_b], b[j * stride_b + 1]};
                float q1[2] = {b[(j + 1) * stride_b], b[(j + 1) * stride_b + 1]};
                d = fminf(d, nav_point_segment_dist(p, q0, q1));
            }
            if (nb == 1) d = hypotf(p[0] - b[0], p[1] - b[1]);
            total += l / sub;
            if (d <= radius_m) shared += l / sub;
        }
    }
    return total > 0 ? (float)(shared / total) : 0.0f;
}

void sp_path_clearance(const sp_costmap *cm, const sp_path *p, float *min_m, float *mean_m)
{
    double sum = 0, len = 0;
    float mn = INFINITY;
    for (int k = 0; k + 1 < p->n; k++) {
        const float *a = p->waypoints + 4 * k, *b = a + 4;
        float l = hypotf(b[0] - a[0], b[1] - a[1]);
        int sub = (int)ceilf(l / (0.5f * cm->res));
        for (int s = 0; s <= sub; s++) {
            float t = sub ? (float)s / sub : 0;
            int ix, iy;
            if (sp_costmap_cell(cm, a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), &ix, &iy)) continue;
            /* to the obstacle cell's edge rather than its centre */
            float d = fmaxf(0.0f, cm->dist[nav_idx(cm, ix, iy)] - 0.5f * cm->res);
            mn = fminf(mn, d);
            if (s < sub) {
                sum += (double)d * l / sub;
                len += l / sub;
            }
        }
    }
    *min_m = mn;
    *mean_m = len > 0 ? (float)(sum / len) : mn;
}

/* Adds amount to every cell within radius of the polyline (once per cell). */
static void add_corridor(const sp_costmap *cm, const sp_path *p, float radius, float amount,
                         float *penalty, uint8_t *stamp)
{
    size_t n = (size_t)cm->nx * cm->ny;
    memset(stamp, 0, n);
    for (int k = 0; k + 1 < p->n_corners || (k == 0 && p->n_corners == 1); k++) {
        const float *a = p->corners + 2 * k, *b = p->n_corners > 1 ? a + 2 : a;
        int x0, y0, x1, y1;
        sp_costmap_cell(cm, fminf(a[0], b[0]) - radius, fminf(a[1], b[1]) - radius, &x0, &y0);
        sp_costmap_cell(cm, fmaxf(a[0], b[0]) + radius, fmaxf(a[1], b[1]) + radius, &x1, &y1);
        x0 = x0 < 0 ? 0 : x0, y0 = y0 < 0 ? 0 : y0;
        x1 = x1 >= cm->nx ? cm->nx - 1 : x1, y1 = y1 >= cm->ny ? cm->ny - 1 : y1;
        for (int iy = y0; iy <= y1; iy++)
            for (int ix = x0; ix <= x1; ix++) {
                long i = nav_idx(cm, ix, iy);
                if (stamp[i]) continue;
                float c[2];
                sp_costmap_cell_center(cm, ix, iy, c);
                if (nav_point_segment_dist(c, a, b) <= radius) {
                    stamp[i] = 1;
                    penalty[i] += amount;
                }
            }
    }
}

void sp_path_set_free(sp_path_set *s)
{
    if (!s) return;
    for (int i = 0; i < s->n; i++) sp_path_free(&s->paths[i]);
    free(s->paths);
    free(s->share);
    memset(s, 0, sizeof *s);
}

/* Largest share either way between cand and the kept paths. */
static float max_share(const sp_path_set *set, const sp_path *cand, float radius)
{
    float worst = 0;
    for (int i = 0; i < set->n; i++) {
        const sp_path *q = &set->paths[i];
        float s1 = sp_path_share(cand->corners, cand->n_corners, 2, q->corners, q->n_corners, 2, radius);
        float s2 = sp_path_share(q->corners, q->n_corners, 2, cand->corners, cand->n_corners, 2, radius);
        worst = fmaxf(worst, fmaxf(s1, s2));
    }
    return worst;
}

int sp_plan_k(const sp_costmap *cm, const float start[3], const sp_nav_goal *goal, int k,
              const sp_planner_opts *opts, sp_path_set *out, sp_error *err)
{
    double t0 = sp_time_now();
    memset(out, 0, sizeof *out);
    if (k < 1 || k > 64) return sp_error_set(err, SP_E_ARG, "plan: k = %d not in 1..64", k);
    sp_planner_opts o = opts ? *opts : sp_planner_opts_default();
    uint8_t *mask;
    int status, rc = nav_goal_prepare(cm, start, goal, &o, &mask, &status, err);
    if (rc) return rc;
    size_t n = (size_t)cm->nx * cm->ny;
    float *penalty = calloc(n, sizeof(float));
    uint8_t *stamp = malloc(n);
    out->paths = calloc((size_t)k, sizeof(sp_path));
    out->share = calloc((size_t)k, sizeof(float));
    out->requested = k;
    if (!penalty || !stamp || !out->paths || !out->share) {
        rc = sp_error_set(err, SP_E_NOMEM, "plan: out of memory");
        goto done;
    }
    if ((rc = nav_plan_once(cm, start, goal, &o, NULL, mask, &out->paths[0], err))) goto done;
    out->n = 1;
    out->rounds = 1;
    const sp_path *last = &out->paths[0];
    sp_path cand;
    memset(&cand, 0, sizeof cand);
    int too_long = 0, too_similar = 0, no_route = 0;
    int budget = o.max_rounds * (k - 1);
    for (int r = 0; r < budget && out->n < k; r++) {
        add_corridor(cm, last, o.penalty_radius_m, o.penalty, penalty, stamp);
        sp_path_free(&cand);
        sp_error e2 = {0};
        out->rounds++;
        if (nav_plan_once(cm, start, goal, &o, penalty, mask, &cand, &e2)) {
            no_route = 1;
            break;
        }
        last = &cand;
        if (cand.length_m > o.max_length_ratio * out->paths[0].length_m) {
            too_long++;
            continue;
        }
        float sh = max_share(out, &cand, o.share_radius_m);
        if (sh > o.max_share) {
            too_similar++;
            continue;
        }
        out->share[out->n] = sh;
        out->paths[out->n++] = cand;
        last = &out->paths[out->n - 1];
        memset(&cand, 0, sizeof cand);
    }
    sp_path_free(&cand);
    if (out->n < k)
        snprintf(out->note, sizeof out->note,
                 "%d of %d distinct trajectories: in %d planner runs the other routes %s "
                 "(%d longer than %.2gx the best, %d sharing over %.0f%% of their length with a "
                 "better one)", out->n, k, out->rounds,
                 no_route ? "ran out (the penalties closed every other way)" : "failed the rules",
                 too_long, o.max_length_ratio, too_similar, 100.0 * o.max_share);
    /* costs without the penalties, for comparison */
    for (int i = 1; i < out->n; i++) out->paths[i].cost = nav_path_cost(cm, &o, &out->paths[i]);
done:
    free(mask), free(penalty), free(stamp);
    if (rc) sp_path_set_free(out);
    else out->ms = 1e3 * (sp_time_now() - t0);
    return rc;
}
