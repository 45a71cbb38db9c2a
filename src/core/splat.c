/* sp_splat: allocation, copying and validation of Gaussians stored as a struct of arrays. */
#include "semsplat/core.h"

#include <string.h>

int sp_feature_dim_check(int dim, int code, const char *what, sp_error *err)
{
    if (dim >= 1 && dim <= SP_FEATURE_DIM_MAX) return 0;
    return sp_error_set(err, code,
                        "%s: feature dim %d is outside 1..%d (the limit of %d, SP_FEATURE_DIM_MAX, is "
                        "what the query engine scores; choose --dim %d or less)",
                        what, dim, SP_FEATURE_DIM_MAX, SP_FEATURE_DIM_MAX, SP_FEATURE_DIM_MAX);
}

int sp_splat_alloc(sp_splat *s, size_t n, int sh_degree, int feat_dim, sp_error *err)
{
    memset(s, 0, sizeof *s);
    if (sh_degree < 0 || sh_degree > 3)
        return sp_error_set(err, SP_E_ARG, "splat: SH degree %d is not in 0..3", sh_degree);
    if (feat_dim < 0 || feat_dim > 4096)
        return sp_error_set(err, SP_E_ARG, "splat: feature dimension %d is not in 0..4096", feat_dim);
    s->n = n;
    s->sh_degree = sh_degree;
    s->feat_dim = feat_dim;
    if (n == 0) return SP_OK;
    size_t K = (size_t)sp_sh_coeffs(sh_degree);
    s->means = sp_calloc(n * 3, sizeof(float));
    s->quats = sp_calloc(n * 4, sizeof(float));
    s->log_scales = sp_calloc(n * 3, sizeof(float));
    s->opacity_logits = sp_calloc(n, sizeof(float));
    s->sh = sp_calloc(n * K * 3, sizeof(float));
    s->features = feat_dim > 0 ? sp_calloc(n * (size_t)feat_dim, sizeof(float)) : NULL;
    if (!s->means || !s->quats || !s->log_scales || !s->opacity_logits || !s->sh ||
        (feat_dim > 0 && !s->features)) {
        sp_splat_free(s);
        return sp_error_set(err, SP_E_NOMEM, "splat: cannot allocate %zu Gaussians", n);
    }
    for (size_t i = 0; i < n; i++) s->quats[i * 4] = 1.0f;
    return SP_OK;
}

void sp_splat_free(sp_splat *s)
{
    if (!s) return;
    sp_free(s->means);
    sp_free(s->quats);
    sp_free(s->log_scales);
    sp_free(s->opacity_logits);
    sp_free(s->sh);
    sp_free(s->features);
    memset(s, 0, sizeof *s);
}

int sp_splat_copy(sp_splat *dst, const sp_splat *src, sp_error *err)
{
    int rc = sp_splat_alloc(dst, src->n, src->sh_degree, src->feat_dim, err);
    if (rc) return rc;
    if (src->n == 0) return SP_OK;
    size_t n = src->n, K = (size_t)sp_sh_coeffs(src->sh_degree);
    memcpy(dst->means, src->means, n * 3 * sizeof(float));
    memcpy(dst->quats, src->quats, n * 4 * sizeof(float));
    memcpy(dst->log_scales, src->log_scales, n * 3 * sizeof(float));
    memcpy(dst->opacity_logits, src->opacity_logits, n * sizeof(float));
    memcpy(dst->sh, src->sh, n * K * 3 * sizeof(float));
    if (src->feat_dim)
        memcpy(dst->features, src->features, n * (size_t)src->feat_dim * sizeof(float));
    return SP_OK;
}

static int check(const float *v, size_t n, size_t stride, const char *field, sp_error *err)
{
    for (size_t i = 0; i < n * stride; i++)
        if (!isfinite(v[i]))
            return sp_error_set(err, SP_E_NUMERIC, "splat: Gaussian %zu has a non-finite %s (%g)",
                                i / stride, field, (double)v[i]);
    return SP_OK;
}

int sp_splat_check_finite(const sp_splat *s, sp_error *err)
{
    size_t K = (size_t)sp_sh_coeffs(s->sh_degree);
    int rc;
    if ((rc = check(s->means, s->n, 3, "mean", err))) return rc;
    if ((rc = check(s->quats, s->n, 4, "quaternion", err))) return rc;
    if ((rc = check(s->log_scales, s->n, 3, "log-scale", err))) return rc;
    if ((rc = check(s->opacity_logits, s->n, 1, "opacity logit", err))) return rc;
    if ((rc = check(s->sh, s->n, K * 3, "SH coefficient", err))) return rc;
    if (s->feat_dim && (rc = check(s->features, s->n, (size_t)s->feat_dim, "feature", err))) return rc;
    return SP_OK;
}
