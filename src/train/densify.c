/* Adaptive density control of 3DGS as gsplat's DefaultStrategy does it (grow: clone small /
 * split large Gaussians with a high mean screen-space gradient; prune: transparent or oversized;
 * periodic opacity reset). The decisions are a plan made on the host from the geometry and the
 * statistics (tr_densify_plan_make: which input row each output row copies, whether it keeps its
 * Adam moments, and the means and log-scales that split children change); the loop applies it
 * on the device, so only the geometry crosses, not the colours and moments; the host version
 * (sp_train_densify_host) applies the same plan to host copies. */
#include "train/train_internal.h"

#include <stdlib.h>
#include <string.h>

static void copy_one(sp_splat *d, size_t di, const sp_splat *s, size_t si)
{
    size_t K3 = (size_t)sp_sh_coeffs(s->sh_degree) * 3, F = (size_t)s->feat_dim;
    memcpy(d->means + di * 3, s->means + si * 3, 3 * sizeof(float));
    memcpy(d->quats + di * 4, s->quats + si * 4, 4 * sizeof(float));
    memcpy(d->log_scales + di * 3, s->log_scales + si * 3, 3 * sizeof(float));
    d->opacity_logits[di] = s->opacity_logits[si];
    memcpy(d->sh + di * K3, s->sh + si * K3, K3 * sizeof(float));
    if (F) memcpy(d->features + di * F, s->features + si * F, F * sizeof(float));
}

static void zero_one(sp_splat *d, size_t di)
{
    size_t K3 = (size_t)sp_sh_coeffs(d->sh_degree) * 3, F = (size_t)d->feat_dim;
    memset(d->means + di * 3, 0, 3 * sizeof(float));
    memset(d->quats + di * 4, 0, 4 * sizeof(float));
    memset(d->log_scales + di * 3, 0, 3 * sizeof(float));
    d->opacity_logits[di] = 0;
    memset(d->sh + di * K3, 0, K3 * sizeof(float));
    if (F) memset(d->features + di * F, 0, F * sizeof(float));
}

static float max_scale(const sp_splat *s, size_t i)
{
    const float *l = s->log_scales + i * 3;
    float m = l[0] > l[1] ? l[0] : l[1];
    return expf(m > l[2] ? m : l[2]);
}

typedef struct {
    float g;
    size_t i;
} cand;

static int cand_desc(const void *a, const void *b)
{
    float ga = ((const cand *)a)->g, gb = ((const cand *)b)->g;
    if (ga != gb) return ga < gb ? 1 : -1;
    size_t ia = ((const cand *)a)->i, ib = ((const cand *)b)->i;
    return ia < ib ? -1 : ia > ib;
}

void tr_densify_plan_free(tr_densify_plan *p)
{
    free(p->src), free(p->keep_moments), free(p->means), free(p->log_scales);
    memset(p, 0, sizeof *p);
}

int tr_densify_plan_make(const sp_splat *s, const float *grad2d_sum, const float *count,
                         const sp_train_options *opt, float scene_scale, int step, uint64_t *rng,
                         tr_densify_plan *plan, sp_densify_stats *st, sp_error *err)
{
    size_t n = s->n;
    memset(st, 0, sizeof *st);
    memset(plan, 0, sizeof *plan);
    /* 0 = keep, 1 = keep + clone, 2 = split (replaced by two children) */
    uint8_t *action = calloc(n ? n : 1, 1);
    cand *cands = malloc(sizeof(cand) * (n ? n : 1));
    if (!action || !cands) {
        free(action);
        free(cands);
        return sp_error_set(err, SP_E_NOMEM, "densify: out of memory for %zu Gaussians", n);
    }
    size_t nc = 0;
    const float grow = sp_train_grow_grad2d(opt);
    for (size_t i = 0; i < n; i++) {
        float g = grad2d_sum[i] / (count[i] > 1.0f ? count[i] : 1.0f);
        if (g > grow) cands[nc++] = (cand){g, i};
    }
    /* Each clone or split adds one Gaussian; at the cap, keep the highest gradients. */
    if (opt->max_gaussians > 0) {
        size_t budget = opt->max_gaussians > n ? opt->max_gaussians - n : 0;
        if (nc > budget) {
            qsort(cands, nc, sizeof(cand), cand_desc);
            nc = budget;
        }
    }
    float small = opt->grow_scale3d * scene_scale;
    for (size_t k = 0; k < nc; k++) {
        size_t i = cands[k].i;
        action[i] = max_scale(s, i) <= small ? 1 : 2;
        if (action[i] == 1) st->n_cloned++;
        else st->n_split++;
    }
    free(cands);

    size_t cap = n + st->n_cloned + st->n_split;
    plan->src = malloc(sizeof(int32_t) * (cap ? cap : 1));
    plan->keep_moments = malloc(cap ? cap : 1);
    plan->means = malloc(sizeof(float) * 3 * (cap ? cap : 1));
    plan->log_scales = malloc(sizeof(float) * 3 * (cap ? cap : 1));
    if (!plan->src || !plan->keep_moments || !plan->means || !plan->log_scales || n > (size_t)INT32_MAX) {
        free(action);
        tr_densify_plan_free(plan);
        return sp_error_set(err, SP_E_NOMEM, "densify: out of memory for %zu Gaussians", cap);
    }

    float prune_logit = sp_logit(opt->prune_opacity);
    int prune_big = opt->reset_every > 0 && step > opt->reset_every;
    float big = opt->prune_scale3d * scene_scale;
    size_t w = 0;
    /* Emission order follows gsplat: survivors in order, then clones, then split children; an
     * emitted row that the pruning drops is overwritten by the next. */
#define EMIT(i, keep)                                                                                  do {                                                                                                   const float *ls_ = plan->log_scales + 3 * w, m_ = ls_[0] > ls_[1] ? ls_[0] : ls_[1];              plan->src[w] = (int32_t)(i), plan->keep_moments[w] = (keep);                                       if (s->opacity_logits[i] < prune_logit || (prune_big && expf(m_ > ls_[2] ? m_ : ls_[2]) > big))             st->n_pruned++;                                                                                else                                                                                                   w++;                                                                                       } while (0)
    for (size_t i = 0; i < n; i++) {
        if (action[i] == 2) continue;
        memcpy(plan->means + 3 * w, s->means + 3 * i, 3 * sizeof(float));
        memcpy(plan->log_scales + 3 * w, s->log_scales + 3 * i, 3 * sizeof(float));
        EMIT(i, 1);
    }
    for (size_t i = 0; i < n; i++) {
        if (action[i] != 1) continue;
        memcpy(plan->means + 3 * w, s->means + 3 * i, 3 * sizeof(float));
        memcpy(plan->log_scales + 3 * w, s->log_scales + 3 * i, 3 * sizeof(float));
        EMIT(i, 0);
    }
    for (size_t i = 0; i < n; i++) {
        if (action[i] != 2) continue;
        float R[9], sc[3];
        sp_quat_to_mat3(s->quats + i * 4, R);
        for (int a = 0; a < 3; a++) sc[a] = expf(s->log_scales[i * 3 + a]);
        for (int child = 0; child < 2; child++) {
            float z[3] = {(float)tr_normal(rng) * sc[0], (float)tr_normal(rng) * sc[1],
                          (float)tr_normal(rng) * sc[2]};
            for (int a = 0; a < 3; a++) {
                plan->means[w * 3 + a] = s->means[i * 3 + a] + (R[a * 3] * z[0] + R[a * 3 + 1] * z[1] + R[a * 3 + 2] * z[2]);
                plan->log_scales[w * 3 + a] = logf(sc[a] / 1.6f);
            }
            EMIT(i, 0);
        }
    }
#undef EMIT
    free(action);
    plan->n_out = w;
    return SP_OK;
}

/* Row i of the plan from the host splats: the source's parameters with the plan's means and
 * log-scales, its moments or zeros. */
static void apply_row(const tr_densify_plan *p, size_t i, const sp_splat *s, sp_splat *o, const sp_splat *m,
                      sp_splat *om, const sp_splat *v, sp_splat *ov)
{
    size_t j = (size_t)p->src[i];
    copy_one(o, i, s, j);
    memcpy(o->means + 3 * i, p->means + 3 * i, 3 * sizeof(float));
    memcpy(o->log_scales + 3 * i, p->log_scales + 3 * i, 3 * sizeof(float));
    if (m) p->keep_moments[i] ? copy_one(om, i, m, j) : zero_one(om, i);
    if (v) p->keep_moments[i] ? copy_one(ov, i, v, j) : zero_one(ov, i);
}

int sp_train_densify_host(sp_splat *s, sp_splat *adam_m, sp_splat *adam_v,
                          const float *grad2d_sum, const float *count,
                          const sp_train_options *opt, float scene_scale, int step, uint64_t *rng,
                          sp_densify_stats *st, sp_error *err)
{
    tr_densify_plan plan;
    int rc = tr_densify_plan_make(s, grad2d_sum, count, opt, scene_scale, step, rng, &plan, st, err);
    if (rc) return rc;
    size_t w = plan.n_out;
    sp_splat o, om, ov;
    memset(&om, 0, sizeof om);
    memset(&ov, 0, sizeof ov);
    rc = sp_splat_alloc(&o, w, s->sh_degree, s->feat_dim, err);
    if (!rc && adam_m) rc = sp_splat_alloc(&om, w, s->sh_degree, s->feat_dim, err);
    if (!rc && adam_v) rc = sp_splat_alloc(&ov, w, s->sh_degree, s->feat_dim, err);
    if (rc) {
        tr_densify_plan_free(&plan);
        sp_splat_free(&o);
        sp_splat_free(&om);
        sp_splat_free(&ov);
        return rc;
    }
    for (size_t i = 0; i < w; i++) apply_row(&plan, i, s, &o, adam_m, &om, adam_v, &ov);
    tr_densify_plan_free(&plan);
    sp_splat_free(s);
    *s = o;
    if (adam_m) {
        sp_splat_free(adam_m);
        *adam_m = om;
    }
    if (adam_v) {
        sp_splat_free(adam_v);
        *adam_v = ov;
    }
    return SP_OK;
}

void sp_train_reset_opacity_host(sp_splat *s, sp_splat *adam_m, sp_splat *adam_v, float prune_opacity)
{
    float cap = sp_logit(2.0f * prune_opacity);
    for (size_t i = 0; i < s->n; i++) {
        if (s->opacity_logits[i] > cap) s->opacity_logits[i] = cap;
        if (adam_m) adam_m->opacity_logits[i] = 0;
        if (adam_v) adam_v->opacity_logits[i] = 0;
    }
}
