/* A naive double-precision reference of the 3DGS rasterizer for the render tests, written
 * independently of src/render/gauss_math.h: every Gaussian is evaluated at every pixel (no tiles,
 * no radii), in depth order (ties by index), with the same culling and compositing rules
 * (near/far, alpha <= 0.99, skip alpha < 1/255, stop before T < 1e-4).
 *
 * For finite differences the reference can RECORD, per pixel, which Gaussians contributed (and
 * whether their alpha was capped) and then REPLAY that exact set in that order on perturbed
 * parameters, which differentiates the smooth piece the analytic gradient belongs to (a
 * threshold crossing inside +-h would otherwise make the difference quotient meaningless). */
#ifndef SP_TEST_RENDER_REF_H
#define SP_TEST_RENDER_REF_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/render.h"

typedef struct ref_scene {
    size_t n;
    int D;
    double *means, *quats, *log_scales, *opacity_logits, *colors; /* [n][3], [n][4], [n][3], [n], [n][D] */
    double *mean2d_offset; /* [n][2] added to projected means (for d/d mean2d), may be NULL */
    double *bg;            /* [D] or NULL */
} ref_scene;

typedef struct ref_proj {
    int visible;
    double mean2d[2], conic[3], depth, opacity;
} ref_proj;

typedef struct ref_record {
    int W, H;
    int32_t *start; /* [W*H + 1] */
    int32_t *gauss; /* contributor list per pixel, front to back */
    uint8_t *capped;
    size_t cap, len;
} ref_record;

static inline void ref_mat3_mul(const double *A, const double *B, double *C)
{
    double T[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            T[i * 3 + j] = 0;
            for (int k = 0; k < 3; k++) T[i * 3 + j] += A[i * 3 + k] * B[k * 3 + j];
        }
    memcpy(C, T, sizeof T);
}

static inline void ref_mat3_T(const double *A, double *T)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) T[j * 3 + i] = A[i * 3 + j];
}

static inline void ref_project(const ref_scene *s, size_t i, const sp_camera *cam, const sp_raster_cfg *cfg,
                        ref_proj *o)
{
    memset(o, 0, sizeof *o);
    const double *m = s->means + 3 * i;
    double Rc[9], tc[3];
    for (int k = 0; k < 9; k++) Rc[k] = cam->R[k];
    for (int k = 0; k < 3; k++) tc[k] = cam->t[k];
    double p[3];
    for (int r = 0; r < 3; r++) p[r] = Rc[r * 3] * m[0] + Rc[r * 3 + 1] * m[1] + Rc[r * 3 + 2] * m[2] + tc[r];
    if (p[2] < cfg->near_plane || p[2] > cfg->far_plane) return;
    /* rotation from the normalised quaternion */
    const double *q = s->quats + 4 * i;
    double qn = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    double w = q[0] / qn, x = q[1] / qn, y = q[2] / qn, z = q[3] / qn;
    double R[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
                   2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                   2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)};
    double S2[9] = {0};
    for (int k = 0; k < 3; k++) S2[k * 4] = exp(2 * s->log_scales[3 * i + k]);
    double RT[9], Sig[9], A[9], RcT[9], Sc[9];
    ref_mat3_T(R, RT);
    ref_mat3_mul(R, S2, A);
    ref_mat3_mul(A, RT, Sig);
    ref_mat3_T(Rc, RcT);
    ref_mat3_mul(Rc, Sig, A);
    ref_mat3_mul(A, RcT, Sc);
    /* Jacobian with gsplat's clamp of x/z, y/z to the tan-fov limits + 0.3 tan(fov/2) */
    double fx = cam->fx, fy = cam->fy, cx = cam->cx, cy = cam->cy, Wd = cam->width, Hd = cam->height;
    double tfx = 0.5 * Wd / fx, tfy = 0.5 * Hd / fy;
    double lxp = (Wd - cx) / fx + 0.3 * tfx, lxn = cx / fx + 0.3 * tfx;
    double lyp = (Hd - cy) / fy + 0.3 * tfy, lyn = cy / fy + 0.3 * tfy;
    double u = fmin(lxp, fmax(-lxn, p[0] / p[2])), v = fmin(lyp, fmax(-lyn, p[1] / p[2]));
    double J[6] = {fx / p[2], 0, -fx * u / p[2], 0, fy / p[2], -fy * v / p[2]};
    double C2[4];
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2; b++) {
            double acc = 0;
            for (int k = 0; k < 3; k++)
                for (int l = 0; l < 3; l++) acc += J[a * 3 + k] * Sc[k * 3 + l] * J[b * 3 + l];
            C2[a * 2 + b] = acc;
        }
    double det0 = C2[0] * C2[3] - C2[1] * C2[2];
    C2[0] += cfg->eps2d;
    C2[3] += cfg->eps2d;
    double det = C2[0] * C2[3] - C2[1] * C2[2];
    if (!(det > 0)) return;
    double op = 1.0 / (1.0 + exp(-s->opacity_logits[i]));
    if (cfg->antialiased) op *= sqrt(fmax(0.0, det0 / det));
    if (!(op * 255.0 > 1.0)) return;
    o->visible = 1;
    o->mean2d[0] = fx * p[0] / p[2] + cx;
    o->mean2d[1] = fy * p[1] / p[2] + cy;
    if (s->mean2d_offset) {
        o->mean2d[0] += s->mean2d_offset[2 * i];
        o->mean2d[1] += s->mean2d_offset[2 * i + 1];
    }
    o->conic[0] = C2[3] / det;
    o->conic[1] = -0.5 * (C2[1] + C2[2]) / det;
    o->conic[2] = C2[0] / det;
    o->depth = p[2];
    o->opacity = op;
}

static const ref_proj *ref_sort_proj;
static inline int ref_cmp_depth(const void *a, const void *b)
{
    size_t i = *(const size_t *)a, j = *(const size_t *)b;
    double di = ref_sort_proj[i].depth, dj = ref_sort_proj[j].depth;
    if (di < dj) return -1;
    if (di > dj) return 1;
    return i < j ? -1 : (i > j);
}

static inline void ref_record_push(ref_record *rec, int32_t g, int capped)
{
    if (rec->len == rec->cap) {
        rec->cap = rec->cap ? rec->cap * 2 : 1024;
        rec->gauss = realloc(rec->gauss, rec->cap * sizeof *rec->gauss);
        rec->capped = realloc(rec->capped, rec->cap);
    }
    rec->gauss[rec->len] = g;
    rec->capped[rec->len] = (uint8_t)capped;
    rec->len++;
}

static inline void ref_record_free(ref_record *rec)
{
    free(rec->start);
    free(rec->gauss);
    free(rec->capped);
    memset(rec, 0, sizeof *rec);
}

/* Renders image [H][W][D], depth and alpha (either may be NULL). mode 0: plain; 1: also record
 * into rec; 2: replay rec (no thresholds, capped alphas stay at 0.99). */
static inline void ref_render(const ref_scene *s, const sp_camera *cam, const sp_raster_cfg *cfg, double *image,
                       double *depth, double *alpha, int mode, ref_record *rec)
{
    int W = cam->width, H = cam->height, D = s->D;
    ref_proj *pr = calloc(s->n ? s->n : 1, sizeof *pr);
    size_t *order = calloc(s->n ? s->n : 1, sizeof *order);
    size_t m = 0;
    for (size_t i = 0; i < s->n; i++) {
        ref_project(s, i, cam, cfg, &pr[i]);
        if (pr[i].visible || mode == 2) order[m++] = i;
    }
    ref_sort_proj = pr;
    qsort(order, m, sizeof *order, ref_cmp_depth);
    if (mode == 1) {
        ref_record_free(rec);
        rec->W = W;
        rec->H = H;
        rec->start = calloc((size_t)W * H + 1, sizeof *rec->start);
    }
    for (int py = 0; py < H; py++)
        for (int px = 0; px < W; px++) {
            size_t pix = (size_t)py * W + px;
            double T = 1, acc_d = 0, acc_a = 0;
            double *out = image + pix * D;
            for (int c = 0; c < D; c++) out[c] = 0;
            if (mode == 1) rec->start[pix] = (int32_t)rec->len;
            size_t kn = mode == 2 ? (size_t)(rec->start[pix + 1] - rec->start[pix]) : m;
            for (size_t k = 0; k < kn; k++) {
                size_t g = mode == 2 ? (size_t)rec->gauss[rec->start[pix] + k] : order[k];
                const ref_proj *p = &pr[g];
                double dx = px + 0.5 - p->mean2d[0], dy = py + 0.5 - p->mean2d[1];
                double sigma = 0.5 * (p->conic[0] * dx * dx + p->conic[2] * dy * dy) + p->conic[1] * dx * dy;
                double a = p->opacity * exp(-sigma);
                int capped;
                if (mode == 2) {
                    capped = rec->capped[rec->start[pix] + k];
                    if (capped) a = SP_ALPHA_MAX;
                } else {
                    if (sigma < 0) continue;
                    capped = a > SP_ALPHA_MAX;
                    if (capped) a = SP_ALPHA_MAX;
                    if (a < SP_ALPHA_MIN) continue;
                    if (T * (1 - a) < SP_TRANSMITTANCE_MIN) break;
                }
                double wgt = a * T;
                for (int c = 0; c < D; c++) out[c] += wgt * s->colors[g * D + c];
                acc_d += wgt * p->depth;
                acc_a += wgt;
                T *= 1 - a;
                if (mode == 1) ref_record_push(rec, (int32_t)g, capped);
            }
            if (s->bg)
                for (int c = 0; c < D; c++) out[c] += T * s->bg[c];
            if (depth) depth[pix] = acc_d;
            if (alpha) alpha[pix] = acc_a;
        }
    if (mode == 1) rec->start[(size_t)W * H] = (int32_t)rec->len;
    free(pr);
    free(order);
}

/* First-surface depth in double: per pixel, walking the Gaussians front to back with the rules
 * above, the depth of the first contributor after which 1 - T >= thr (0 when none). margin[pix]
 * gets how close the pixel came to a decision float could make differently: the transmittance
 * before and after the crossing (or at the end) against 1 - thr, an alpha against 1/255, the
 * transmittance against the stop (the latter two scaled by 10). Callers skip tiny margins. */
static inline void ref_surface_depth(const ref_scene *s, const sp_camera *cam, const sp_raster_cfg *cfg,
                                     double thr, double *out, double *margin)
{
    int W = cam->width, H = cam->height;
    ref_proj *pr = calloc(s->n ? s->n : 1, sizeof *pr);
    size_t *order = calloc(s->n ? s->n : 1, sizeof *order);
    size_t m = 0;
    for (size_t i = 0; i < s->n; i++) {
        ref_project(s, i, cam, cfg, &pr[i]);
        if (pr[i].visible) order[m++] = i;
    }
    ref_sort_proj = pr;
    qsort(order, m, sizeof *order, ref_cmp_depth);
    double t_stop = 1.0 - thr;
    for (int py = 0; py < H; py++)
        for (int px = 0; px < W; px++) {
            size_t pix = (size_t)py * W + px;
            double T = 1, mg = 1, z = 0;
            int crossed = 0;
            for (size_t k = 0; k < m; k++) {
                const ref_proj *p = &pr[order[k]];
                double dx = px + 0.5 - p->mean2d[0], dy = py + 0.5 - p->mean2d[1];
                double sigma = 0.5 * (p->conic[0] * dx * dx + p->conic[2] * dy * dy) + p->conic[1] * dx * dy;
                if (sigma < 0) continue;
                double a = fmin(SP_ALPHA_MAX, p->opacity * exp(-sigma));
                mg = fmin(mg, 10 * fabs(a - SP_ALPHA_MIN));
                if (a < SP_ALPHA_MIN) continue;
                double next = T * (1 - a);
                mg = fmin(mg, 10 * fabs(next - SP_TRANSMITTANCE_MIN));
                if (next < SP_TRANSMITTANCE_MIN) break;
                if (next <= t_stop) {
                    mg = fmin(mg, fmin(T - t_stop, t_stop - next));
                    z = p->depth;
                    crossed = 1;
                    break;
                }
                T = next;
            }
            if (!crossed) mg = fmin(mg, T - t_stop);
            out[pix] = z;
            margin[pix] = mg;
        }
    free(pr);
    free(order);
}

#endif
