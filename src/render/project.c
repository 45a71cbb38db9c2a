/* CPU projection stage: every Gaussian -> 2D mean, conic, depth, effective opacity, radius and
 * the pixel box it can touch (sp_gm_project in gauss_math.h does the math). Backward: sums each
 * Gaussian's per-tile gradient slots in slot order (fixed, so the result does not depend on
 * thread count) and runs the projection's vjp. Both run in chunks of Gaussians over the pool. */
#include <string.h>

#include "render/gauss_math.h"
#include "render/render_internal.h"

#define CHUNK 2048

/* Inclusive pixel range whose centres lie within (rx, ry) of (mx, my), clipped to the image;
 * empty (x0 > x1) when none. */
static void pixel_box(float mx, float my, float rx, float ry, int W, int H, int32_t box[4])
{
    float fx0 = ceilf(mx - rx - 0.5f), fx1 = floorf(mx + rx - 0.5f);
    float fy0 = ceilf(my - ry - 0.5f), fy1 = floorf(my + ry - 0.5f);
    box[0] = fx0 < 0.f ? 0 : (fx0 > (float)W ? W : (int32_t)fx0);
    box[1] = fx1 > (float)(W - 1) ? W - 1 : (fx1 < -1.f ? -1 : (int32_t)fx1);
    box[2] = fy0 < 0.f ? 0 : (fy0 > (float)H ? H : (int32_t)fy0);
    box[3] = fy1 > (float)(H - 1) ? H - 1 : (fy1 < -1.f ? -1 : (int32_t)fy1);
}

static void project_chunk(void *ctx, long chunk, int thread_id)
{
    cpu_raster *r = ctx;
    const sp_raster_in *in = &r->in;
    size_t i0 = (size_t)chunk * CHUNK, i1 = i0 + CHUNK < r->n ? i0 + CHUNK : r->n;
    for (size_t i = i0; i < i1; i++) {
        int radius = 0;
        int32_t *box = r->pix_box + 4 * i;
        float *m2 = r->mean2d + 2 * i, *con = r->conic + 3 * i;
        float cov2[3];
        int vis = sp_gm_project_ex(in->means + 3 * i, in->quats + 4 * i, in->log_scales + 3 * i,
                                   in->opacity_logits[i], &r->cam, &r->cfg, m2, con, &r->depth[i],
                                   &r->opacity[i], &radius, cov2);
        if (vis) {
            /* Per-axis extent of the alpha >= 1/255 ellipse (tighter than the radius circle for
             * elongated Gaussians): extent * sqrt(cov_xx) of the blurred 2D covariance. */
            float ext = sqrtf(2.f * logf(r->opacity[i] * 255.f));
            float rx = ceilf(ext * sqrtf(cov2[0])), ry = ceilf(ext * sqrtf(cov2[2]));
            float rr = (float)radius;
            /* det(conic) = 1 / det(cov2) = conic_c / cov2_a (conic_c = cov2_a / det(cov2)) */
            r->conic_det[i] = con[2] / cov2[0];
            pixel_box(m2[0], m2[1], rx < rr ? rx : rr, ry < rr ? ry : rr, r->W, r->H, box);
            if (box[0] > box[1] || box[2] > box[3]) vis = 0, radius = 0;
        }
        if (!vis) {
            box[0] = 0, box[1] = -1, box[2] = 0, box[3] = -1;
            radius = 0;
        }
        r->radii[i] = radius;
    }
    (void)thread_id;
}

int cpu_project(cpu_raster *r, sp_error *err)
{
    size_t n = r->n;
    /* one block: mean2d 2, conic 3, depth 1, opacity 1, conic_det 1 floats; radii 1, box 4 int32 */
    size_t bytes = n * (8 * sizeof(float) + 5 * sizeof(int32_t)) + 64;
    int rc = sp_scratch_reserve(r->dev, &r->proj_buf, &r->proj_cap, bytes, err);
    if (rc) return rc;
    float *f = r->proj_buf;
    r->mean2d = f;
    r->conic = f + 2 * n;
    r->depth = f + 5 * n;
    r->opacity = f + 6 * n;
    r->conic_det = f + 7 * n;
    r->radii = (int32_t *)(f + 8 * n);
    r->pix_box = r->radii + n;
    sp_pool_for(r->dev->pool, (long)((n + CHUNK - 1) / CHUNK), project_chunk, r);
    return 0;
}

typedef struct {
    cpu_raster *r;
    const sp_raster_grads *g;
} bwd_ctx;

static void project_backward_chunk(void *ctx, long chunk, int thread_id)
{
    bwd_ctx *c = ctx;
    cpu_raster *r = c->r;
    const sp_raster_grads *g = c->g;
    const sp_raster_in *in = &r->in;
    int D = r->D, stride = SP_SLOT_FIXED + D;
    size_t i0 = (size_t)chunk * CHUNK, i1 = i0 + CHUNK < r->n ? i0 + CHUNK : r->n;
    for (size_t i = i0; i < i1; i++) {
        size_t s0 = r->pair_off[i], s1 = r->pair_off[i + 1];
        if (s0 == s1) continue; /* culled or never binned: no gradient */
        float acc[SP_SLOT_FIXED] = {0, 0, 0, 0, 0, 0, 0};
        float *vcol = g->v_colors ? g->v_colors + i * (size_t)D : NULL;
        for (size_t s = s0; s < s1; s++) {
            const float *slot = r->slots + s * (size_t)stride;
            for (int k = 0; k < SP_SLOT_FIXED; k++) acc[k] += slot[k];
        }
        /* colour gradients summed locally first, then added once (so "added into" means exactly
         * out + g, and two identical backward calls give exactly 2 g) */
        for (int c0 = 0; vcol && c0 < D; c0 += 256) {
            float part[256];
            int c1 = c0 + 256 < D ? c0 + 256 : D;
            for (int d = c0; d < c1; d++) part[d - c0] = 0.f;
            for (size_t s = s0; s < s1; s++) {
                const float *slot = r->slots + s * (size_t)stride + SP_SLOT_FIXED;
                for (int d = c0; d < c1; d++) part[d - c0] += slot[d];
            }
            for (int d = c0; d < c1; d++) vcol[d] += part[d - c0];
        }
        if (g->v_means2d) {
            g->v_means2d[2 * i] += acc[0];
            g->v_means2d[2 * i + 1] += acc[1];
        }
        if (!g->v_means && !g->v_quats && !g->v_log_scales && !g->v_opacity_logits) continue;
        float v_mean[3] = {0, 0, 0}, v_quat[4] = {0, 0, 0, 0}, v_ls[3] = {0, 0, 0}, v_logit = 0.f;
        sp_gm_project_vjp(in->means + 3 * i, in->quats + 4 * i, in->log_scales + 3 * i,
                          in->opacity_logits[i], &r->cam, &r->cfg, acc, acc + 2, acc[6], acc[5],
                          v_mean, v_quat, v_ls, &v_logit);
        if (g->v_means)
            for (int k = 0; k < 3; k++) g->v_means[3 * i + k] += v_mean[k];
        if (g->v_quats)
            for (int k = 0; k < 4; k++) g->v_quats[4 * i + k] += v_quat[k];
        if (g->v_log_scales)
            for (int k = 0; k < 3; k++) g->v_log_scales[3 * i + k] += v_ls[k];
        if (g->v_opacity_logits) g->v_opacity_logits[i] += v_logit;
    }
    (void)thread_id;
}

void cpu_project_backward(cpu_raster *r, const sp_raster_grads *grads)
{
    bwd_ctx c = {r, grads};
    sp_pool_for(r->dev->pool, (long)((r->n + CHUNK - 1) / CHUNK), project_backward_chunk, &c);
}
