/* Ranking a plan's trajectories by an itemized score, and their previews. Per waypoint (every
 * loc_spacing_m, and the goal) a small view along the path is rendered with two channels per
 * Gaussian: coverage (min(1, training views that see it / loc_views_full)) and relevance (inside
 * an instance of a concept related to the goal). The mean coverage of a view is its
 * localizability: accumulated opacity of Gaussians the capture observed well; a path is as
 * localizable as its worst waypoint. Relevance seen along the way is the semantic term. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "nav_scene.h"

#define DEG ((float)M_PI / 180.0f)

static float cam_z(const sp_nav *nav) { return nav->cm.floor_z + nav->opts.camera_height_m; }

static int score_trajectory(sp_nav *nav, sp_nav_trajectory *t, sp_error *err)
{
    const sp_nav_opts *o = &nav->opts;
    const sp_path *p = &t->path;
    t->loc = malloc(sizeof(float) * (p->n ? p->n : 1));
    if (!t->loc) return sp_error_set(err, SP_E_NOMEM, "nav: out of memory");
    int step = (int)lroundf(o->loc_spacing_m / o->planner.waypoint_spacing_m);
    if (step < 1) step = 1;
    float worst = INFINITY;
    double rel_sum = 0;
    int n_eval = 0;
    for (int i = 0; i < p->n; i++) t->loc[i] = NAN;
    for (int i = 0; i < p->n; i++) {
        if (i % step && i != p->n - 1) continue; /* every step-th waypoint and the goal */
        const float *w = p->waypoints + 4 * i;
        float pos[3] = {w[0], w[1], cam_z(nav)}, loc, rel;
        int rc = nav_view_scores(nav, pos, w[3], -o->camera_pitch_deg * DEG, &loc, &rel, err);
        if (rc) return rc;
        t->loc[i] = loc;
        if (loc < worst) worst = loc, t->score.weakest_waypoint = i;
        rel_sum += rel;
        n_eval++;
    }
    sp_nav_score *sc = &t->score;
    sc->length_m = p->length_m;
    sp_path_clearance(&nav->cm, p, &sc->clearance_min_m, &sc->clearance_mean_m);
    sc->localizability = isfinite(worst) ? worst : 0;
    sc->semantic = n_eval ? (float)(rel_sum / n_eval) : 0;
    return SP_OK;
}

static int by_total(const void *a, const void *b)
{
    float x = ((const sp_nav_trajectory *)a)->score.total, y = ((const sp_nav_trajectory *)b)->score.total;
    return (x < y) - (x > y);
}

int nav_rank(sp_nav *nav, sp_nav_plan *p, sp_error *err)
{
    const sp_rank_weights *w = &nav->opts.weights;
    float shortest = INFINITY, best_sem = 0;
    for (int i = 0; i < p->n; i++) {
        int rc = score_trajectory(nav, &p->traj[i], err);
        if (rc) return rc;
        shortest = fminf(shortest, p->traj[i].score.length_m);
        best_sem = fmaxf(best_sem, p->traj[i].score.semantic);
    }
    float wsum = w->length + w->clearance_min + w->clearance_mean + w->localizability + w->semantic;
    if (!(wsum > 0)) wsum = 1;
    float ref = nav->opts.clearance_ref_m;
    for (int i = 0; i < p->n; i++) {
        sp_nav_score *s = &p->traj[i].score;
        s->t_length = s->length_m > 0 ? shortest / s->length_m : 1;
        s->t_clearance_min = fminf(1.0f, s->clearance_min_m / ref);
        s->t_clearance_mean = fminf(1.0f, s->clearance_mean_m / (2 * ref));
        s->t_localizability = fminf(1.0f, fmaxf(0.0f, s->localizability));
        s->t_semantic = best_sem > 1e-6f ? s->semantic / best_sem : 0;
        s->total = (w->length * s->t_length + w->clearance_min * s->t_clearance_min +
                    w->clearance_mean * s->t_clearance_mean + w->localizability * s->t_localizability +
                    w->semantic * s->t_semantic) / wsum;
    }
    qsort(p->traj, (size_t)p->n, sizeof *p->traj, by_total);
    for (int i = 0; i < p->n; i++) {
        p->traj[i].rank = i + 1;
        snprintf(p->traj[i].id, sizeof p->traj[i].id, "%s.%d", p->id, i + 1);
    }
    return SP_OK;
}

void nav_preview_free(sp_nav_preview *pv)
{
    if (pv) free(pv->rgb), pv->rgb = NULL;
}

/* Pitch that looks from the camera at the middle of the target instance nearest to xy. */
static float pitch_to_target(const sp_nav *nav, const sp_nav_target *t, const float xy[2])
{
    float def = -nav->opts.camera_pitch_deg * DEG;
    if (!t || !t->found) return def;
    int best = -1;
    float bd = INFINITY;
    for (int k = 0; k < t->n; k++) {
        float d = nav_box_dist(&t->inst[k].box, xy);
        if (d < bd) bd = d, best = k;
    }
    const sp_nav_instance *in = &t->inst[best];
    float cx = 0.5f * (in->box.min[0] + in->box.max[0]), cy = 0.5f * (in->box.min[1] + in->box.max[1]);
    float h = hypotf(cx - xy[0], cy - xy[1]), dz = 0.5f * (in->z_min + in->z_max) - cam_z(nav);
    float pitch = atan2f(dz, fmaxf(h, 0.3f));
    return fminf(20 * DEG, fmaxf(-45 * DEG, pitch));
}

int nav_make_previews(sp_nav *nav, sp_nav_trajectory *t, const sp_nav_target *target, sp_error *err)
{
    const sp_path *p = &t->path;
    int np = nav->opts.n_previews;
    if (np <= 0 || p->n < 1) return SP_OK;
    if (np > p->n) np = p->n;
    t->previews = calloc((size_t)np, sizeof *t->previews);
    float *along = malloc(sizeof(float) * p->n);
    if (!t->previews || !along) {
        free(along);
        return sp_error_set(err, SP_E_NOMEM, "nav: out of memory");
    }
    along[0] = 0;
    for (int i = 1; i < p->n; i++)
        along[i] = along[i - 1] + hypotf(p->waypoints[4 * i] - p->waypoints[4 * i - 4],
                                         p->waypoints[4 * i + 1] - p->waypoints[4 * i - 3]);
    int rc = 0, last = -1;
    for (int j = 0; j < np && !rc; j++) {
        float want = np > 1 ? along[p->n - 1] * j / (np - 1) : along[p->n - 1];
        int idx = 0;
        while (idx + 1 < p->n && along[idx + 1] <= want + 1e-4f) idx++;
        if (j == np - 1) idx = p->n - 1;
        if (idx <= last) idx = last + 1 < p->n ? last + 1 : last;
        last = idx;
        const float *w = p->waypoints + 4 * idx;
        float pos[3] = {w[0], w[1], cam_z(nav)};
        float pitch = idx == p->n - 1 ? pitch_to_target(nav, target, w) : -nav->opts.camera_pitch_deg * DEG;
        sp_nav_preview *pv = &t->previews[t->n_previews];
        pv->waypoint = idx;
        pv->distance_m = along[idx];
        rc = nav_render_preview(nav, pos, w[3], pitch, pv, err);
        if (!rc) rc = nav_view_scores(nav, pos, w[3], pitch, &pv->localizability, NULL, err);
        if (!rc) t->n_previews++;
    }
    free(along);
    return rc;
}
