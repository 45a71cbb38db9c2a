/* Training checkpoints (parameters, Adam moments, step, RNG state in one little-endian binary
 * file, written atomically so a crash or a NaN never leaves a half-written or bad one) and
 * train.json, the run's settings and held-out metrics. */
#include <cjson/cJSON.h>

#include "semsplat/io.h"
#include "train/train_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CK_MAGIC "SPCKPT01"

typedef struct {
    int32_t step, sh_degree, feat_dim, pad;
    uint64_t rng, n;
} ck_header;

static size_t splat_floats(size_t n, int sh_degree, int F)
{
    return n * (3 + 4 + 3 + 1 + (size_t)sp_sh_coeffs(sh_degree) * 3 + (size_t)F);
}

static void pack(float **w, const sp_splat *s, int unpack)
{
    size_t n = s->n, K3 = (size_t)sp_sh_coeffs(s->sh_degree) * 3, F = (size_t)s->feat_dim;
    float *fields[6] = {s->means, s->quats, s->log_scales, s->opacity_logits, s->sh, s->features};
    size_t widths[6] = {3, 4, 3, 1, K3, F};
    for (int k = 0; k < 6; k++) {
        size_t c = n * widths[k];
        if (!c) continue;
        if (unpack) memcpy(fields[k], *w, c * sizeof(float));
        else memcpy(*w, fields[k], c * sizeof(float));
        *w += c;
    }
}

int tr_checkpoint_write(const char *path, int step, uint64_t rng, const sp_splat *params,
                        const sp_splat *m, const sp_splat *v, sp_error *err)
{
    size_t nf = splat_floats(params->n, params->sh_degree, params->feat_dim);
    size_t bytes = 8 + sizeof(ck_header) + 3 * nf * sizeof(float);
    char *buf = malloc(bytes);
    if (!buf) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory for the checkpoint", path);
    memcpy(buf, CK_MAGIC, 8);
    ck_header h = {step, params->sh_degree, params->feat_dim, 0, rng, params->n};
    memcpy(buf + 8, &h, sizeof h);
    float *w = (float *)(void *)(buf + 8 + sizeof h);
    pack(&w, params, 0);
    pack(&w, m, 0);
    pack(&w, v, 0);
    int rc = sp_write_file_atomic(path, buf, bytes, err);
    free(buf);
    return rc;
}

int tr_checkpoint_read(const char *path, tr_checkpoint *ck, sp_error *err)
{
    memset(ck, 0, sizeof *ck);
    char *data;
    size_t size;
    int rc = sp_read_file(path, &data, &size, err);
    if (rc) return rc;
    ck_header h;
    if (size < 8 + sizeof h || memcmp(data, CK_MAGIC, 8) != 0) {
        free(data);
        return sp_error_set(err, SP_E_FORMAT, "%s: not a semsplat training checkpoint", path);
    }
    memcpy(&h, data + 8, sizeof h);
    if (h.sh_degree < 0 || h.sh_degree > 3 || h.feat_dim < 0 || h.feat_dim > 4096 || h.step < 0 ||
        h.n > ((size_t)1 << 32)) {
        free(data);
        return sp_error_set(err, SP_E_FORMAT, "%s: corrupt checkpoint header", path);
    }
    size_t nf = splat_floats(h.n, h.sh_degree, h.feat_dim);
    if (size != 8 + sizeof h + 3 * nf * sizeof(float)) {
        free(data);
        return sp_error_set(err, SP_E_FORMAT, "%s: checkpoint is %zu bytes, expected %zu (truncated?)",
                            path, size, 8 + sizeof h + 3 * nf * sizeof(float));
    }
    sp_splat *dst[3] = {&ck->params, &ck->m, &ck->v};
    float *r = (float *)(void *)(data + 8 + sizeof h);
    for (int k = 0; k < 3; k++) {
        if ((rc = sp_splat_alloc(dst[k], h.n, h.sh_degree, h.feat_dim, err))) {
            tr_checkpoint_free(ck);
            free(data);
            return rc;
        }
        pack(&r, dst[k], 1);
    }
    free(data);
    ck->step = h.step;
    ck->rng = h.rng;
    /* Adam's moments too: a NaN or a negative second moment poisons the first resumed step. */
    rc = sp_splat_check_finite(&ck->params, err);
    if (!rc && (rc = sp_splat_check_finite(&ck->m, err))) sp_error_prefix(err, "first moments: ");
    if (!rc && (rc = sp_splat_check_finite(&ck->v, err))) sp_error_prefix(err, "second moments: ");
    const float *vf[6] = {ck->v.means, ck->v.quats, ck->v.log_scales, ck->v.opacity_logits, ck->v.sh, ck->v.features};
    size_t vn[6] = {3, 4, 3, 1, (size_t)sp_sh_coeffs(h.sh_degree) * 3, (size_t)h.feat_dim};
    for (int k = 0; k < 6 && !rc; k++)
        for (size_t i = 0; i < h.n * vn[k] && !rc; i++)
            if (vf[k][i] < 0) rc = sp_error_set(err, SP_E_FORMAT, "second moment %zu of field %d is negative", i, k);
    if (rc) {
        tr_checkpoint_free(ck);
        return sp_error_prefix(err, "%s: ", path);
    }
    return SP_OK;
}

void tr_checkpoint_free(tr_checkpoint *ck)
{
    sp_splat_free(&ck->params);
    sp_splat_free(&ck->m);
    sp_splat_free(&ck->v);
}

int sp_train_write_json(const char *path, const sp_train_options *o, const sp_train_result *res,
                        const char *colmap_dir, const char *images_dir, int downscale,
                        sp_error *err)
{
    cJSON *j = cJSON_CreateObject();
    if (!j) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    cJSON_AddNumberToObject(j, "psnr", res->psnr);
    cJSON_AddNumberToObject(j, "ssim", res->ssim);
    cJSON_AddNumberToObject(j, "l1", res->l1);
    cJSON_AddNumberToObject(j, "gaussians", (double)res->gaussians);
    cJSON_AddNumberToObject(j, "steps", res->steps);
    cJSON_AddNumberToObject(j, "seconds", res->seconds);
    cJSON_AddNumberToObject(j, "seconds_steps", res->seconds_steps);
    cJSON_AddStringToObject(j, "device", res->device);
    cJSON_AddNumberToObject(j, "eval_views", res->n_eval_views);
    cJSON_AddStringToObject(j, "eval_split", res->eval_on_train ? "train (no held-out views)" : "held-out");
    if (o->feature_dim) cJSON_AddNumberToObject(j, "feature_mse", res->feature_mse);
    if (res->depth_eval_pixels > 0) { /* same split as psnr; metres for a synth capture */
        cJSON_AddNumberToObject(j, "depth_l1", res->depth_l1);
        cJSON_AddNumberToObject(j, "surface_depth_l1", res->surface_depth_l1);
        cJSON_AddNumberToObject(j, "depth_hole_share", res->depth_hole_share);
    }
    cJSON *s = cJSON_AddObjectToObject(j, "settings");
    if (colmap_dir) cJSON_AddStringToObject(s, "colmap", colmap_dir);
    if (images_dir) cJSON_AddStringToObject(s, "images", images_dir);
    cJSON_AddNumberToObject(s, "downscale", downscale);
    cJSON_AddNumberToObject(s, "steps", o->steps);
    cJSON_AddNumberToObject(s, "sh_degree", o->sh_degree);
    cJSON_AddNumberToObject(s, "sh_degree_interval", o->sh_degree_interval);
    cJSON_AddNumberToObject(s, "ssim_lambda", o->ssim_lambda);
    cJSON_AddNumberToObject(s, "depth_lambda", o->depth_lambda);
    cJSON_AddBoolToObject(s, "random_background", o->random_background);
    cJSON_AddNumberToObject(s, "seed", (double)o->seed);
    cJSON *lr = cJSON_AddObjectToObject(s, "lr");
    cJSON_AddNumberToObject(lr, "means", o->lr_means);
    cJSON_AddNumberToObject(lr, "means_final_factor", o->lr_means_final_factor);
    cJSON_AddNumberToObject(lr, "scales", o->lr_scales);
    cJSON_AddNumberToObject(lr, "quats", o->lr_quats);
    cJSON_AddNumberToObject(lr, "opacities", o->lr_opacities);
    cJSON_AddNumberToObject(lr, "sh0", o->lr_sh0);
    cJSON_AddNumberToObject(lr, "shN", o->lr_shN);
    if (o->feature_dim) cJSON_AddNumberToObject(lr, "features", o->lr_features);
    cJSON *dn = cJSON_AddObjectToObject(s, "densify");
    cJSON_AddBoolToObject(dn, "enabled", o->densify);
    cJSON_AddNumberToObject(dn, "refine_start", o->refine_start);
    cJSON_AddNumberToObject(dn, "refine_stop", o->refine_stop);
    cJSON_AddNumberToObject(dn, "refine_every", o->refine_every);
    cJSON_AddNumberToObject(dn, "reset_every", o->reset_every);
    cJSON_AddNumberToObject(dn, "grow_grad2d", sp_train_grow_grad2d(o)); /* the one used */
    cJSON_AddNumberToObject(dn, "grow_scale3d", o->grow_scale3d);
    cJSON_AddNumberToObject(dn, "prune_opacity", o->prune_opacity);
    cJSON_AddNumberToObject(dn, "prune_scale3d", o->prune_scale3d);
    cJSON_AddNumberToObject(dn, "max_gaussians", (double)o->max_gaussians);
    if (o->feature_dim) {
        cJSON_AddNumberToObject(s, "feature_dim", o->feature_dim);
        cJSON_AddNumberToObject(s, "feature_lambda", o->feature_lambda);
        cJSON_AddBoolToObject(s, "freeze_geometry", o->freeze_geometry);
    }
    int rc = sp_json_write_file(path, j, err);
    cJSON_Delete(j);
    return rc;
}
