/* 5.4, trajectory quality: nav's top trajectories to the refrigerator (or another target), their
 * length, clearance, localizability and ranking, and a visual quality measured on the previews a
 * user would look at before the robot moves: how much of each view the splat covers and how
 * sharp it is (sp_media_view_quality), 1-5. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval/eval_internal.h"
#include "semsplat/media.h"
#include "semsplat/nav.h"

/* nav renders its previews over this background (src/nav/scene.c, 0.12 0.12 0.14): pixels that
 * still show it exactly are ones no Gaussian covered. */
static const uint8_t PREVIEW_BG[3] = {31, 31, 36};

static int preview_quality(const sp_nav_preview *pv, sp_view_quality *q, sp_error *err)
{
    size_t n = (size_t)pv->width * pv->height;
    float *rgb = malloc(n * 3 * sizeof *rgb), *alpha = malloc(n * sizeof *alpha);
    int rc = 0;
    if (!rgb || !alpha) rc = sp_error_set(err, SP_E_NOMEM, "eval: out of memory");
    for (size_t i = 0; !rc && i < n; i++) {
        const uint8_t *p = pv->rgb + 3 * i;
        int bg = 1;
        for (int k = 0; k < 3; k++) {
            rgb[3 * i + k] = p[k] / 255.0f;
            bg &= abs((int)p[k] - PREVIEW_BG[k]) <= 1;
        }
        alpha[i] = bg ? 0.0f : 1.0f;
    }
    if (!rc) rc = sp_media_view_quality(rgb, alpha, pv->width, pv->height, q, err);
    free(rgb);
    free(alpha);
    return rc;
}

static int score_trajectory(const sp_nav_trajectory *t, const char *dir, sp_eval_trajectory *e, sp_error *err)
{
    memset(e, 0, sizeof *e);
    e->rank = t->rank;
    e->length_m = t->score.length_m;
    e->clearance_min_m = t->score.clearance_min_m;
    e->clearance_mean_m = t->score.clearance_mean_m;
    e->localizability = t->score.localizability;
    e->total = t->score.total;
    e->share = t->share;
    double cov = 0, sharp = 0, score = 0;
    for (int k = 0; k < t->n_previews; k++) {
        sp_view_quality q;
        int rc = preview_quality(&t->previews[k], &q, err);
        if (rc) return rc;
        cov += q.coverage, sharp += q.sharpness, score += q.score;
        e->n_previews++;
    }
    if (e->n_previews) {
        e->coverage = (float)(cov / e->n_previews);
        e->sharpness = (float)(sharp / e->n_previews);
        e->visual_score = (float)(score / e->n_previews);
        e->visual_grade = (int)lroundf(e->visual_score);
    }
    snprintf(e->sheet, sizeof e->sheet, "%s/previews/t%d_sheet.png", dir, t->rank);
    if (!sp_file_exists(e->sheet)) e->sheet[0] = 0;
    return 0;
}

int ev_trajectories(const sp_eval_run_opts *o, sp_eval_run *r, sp_error *err)
{
    const char *to = o->trajectory_target ? o->trajectory_target : "refrigerator";
    snprintf(r->traj_target, sizeof r->traj_target, "%s", to);
    char dir[1200];
    snprintf(dir, sizeof dir, "%s/trajectories", o->out_dir);
    sp_nav *nav = NULL;
    int rc = sp_nav_open(&nav, o->model_dir, NULL, o->dev, o->log, err);
    if (rc) return sp_error_prefix(err, "5.4: ");
    sp_nav_request req = sp_nav_request_default();
    req.to = to;
    req.k = 3;
    req.previews = 1;
    sp_nav_plan *plan = calloc(1, sizeof *plan);
    if (!plan) rc = sp_error_set(err, SP_E_NOMEM, "eval: out of memory");
    if (!rc) rc = sp_nav_plan_request(nav, &req, plan, err);
    if (rc == SP_E_NOTFOUND || (!rc && plan->n == 0)) {
        /* no such target, or no way there: a result, not a failure */
        snprintf(r->traj_note, sizeof r->traj_note, "no trajectory to \"%s\": %s", to,
                 rc ? err->msg : plan->note);
        sp_error_clear(err);
        rc = 0;
    } else if (!rc) {
        rc = sp_nav_plan_write(nav, plan, dir, err);
        for (int i = 0; !rc && i < plan->n && r->n_traj < 8; i++)
            rc = score_trajectory(&plan->traj[i], dir, &r->traj[r->n_traj++], err);
        snprintf(r->traj_note, sizeof r->traj_note, "%s", plan->note);
        snprintf(r->traj_map, sizeof r->traj_map, "%s/map.png", dir);
        if (!sp_file_exists(r->traj_map)) r->traj_map[0] = 0;
        r->traj_measured = !rc;
    }
    if (plan) sp_nav_plan_free(plan);
    free(plan);
    sp_nav_free(nav);
    return rc;
}
