/* CPU backward compositing: one tile per pool item, walking the tile's list back to front from
 * the last contributor of any of its pixels. Per pixel it rebuilds the transmittance before each
 * Gaussian (T_i = T_{i+1} / (1 - alpha_i)) and keeps S = sum of the channels composited behind
 * it (starting from T_final * background), which gives
 *   dC/dc_i = alpha_i T_i,  dC/dalpha_i = T_i c_i - S / (1 - alpha_i),
 *   d(sum w)/dalpha_i = T_final / (1 - alpha_i),  and the same for depth with z_i.
 * Alphas come from cpu_alpha4, the forward's own function, so both make the same decisions.
 * Each (Gaussian, tile) pair writes its gradient sums to its own slot, never shared, so the
 * result does not depend on which thread ran which tile; project.c sums the slots per Gaussian
 * in slot order. */
#include <string.h>

#include "render/gauss_math.h"
#include "render/render_internal.h"


typedef struct {
    cpu_raster *r;
    const sp_raster_grad_in *gin;
} bwd_ctx;


/* Horizontal sum in a fixed order (deterministic). */
static inline float hsum(cpu_v4f v) { return (v[0] + v[1]) + (v[2] + v[3]); }

/* Four pixels of a row per step, like the forward; per-Gaussian sums are kept per lane and
 * added up in a fixed order at the end. Tile-local copies of the incoming gradients are
 * channel-major so the lanes are contiguous. */
static inline __attribute__((always_inline)) void tile_backward(cpu_raster *r,
                                                                const sp_raster_grad_in *gin,
                                                                long tile, float *scratch, const int D)
{
    const int W = r->W;
    const cpu_rect tr = cpu_tile_rect(r, tile);
    const int tx0 = tr.x0, tx1 = tr.x1, ty0 = tr.y0, ty1 = tr.y1;
    const int stride = SP_SLOT_FIXED + D;
    const size_t TS = TILE_STRIDE;

    float *T = scratch;         /* [TS] transmittance behind */
    float *S_d = T + TS;        /* [TS] depth composited behind */
    float *VD = S_d + TS;       /* [TS] v_depth (0 without) */
    float *VA = VD + TS;        /* [TS] v_alpha * T_final (0 without) */
    int32_t *last = (int32_t *)(VA + TS);
    float *S = (float *)(last + TS); /* [D][TS] channels behind */
    float *VI = S + (size_t)D * TS;  /* [D][TS] v_image */
    cpu_v4f *v_col = (cpu_v4f *)(VI + (size_t)D * TS); /* [D] per-lane colour gradients */
    for (size_t p = 0; p < TS; p++) T[p] = 1.f;
    memset(S_d, 0, 3 * TS * sizeof(float)); /* S_d, VD, VA */
    memset(last, 0, TS * sizeof(int32_t));
    memset(S, 0, 2 * (size_t)D * TS * sizeof(float));

    const float *bg = r->background;
    const float *v_image = gin->v_image, *v_depth = gin->v_depth, *v_alpha = gin->v_alpha;
    int32_t max_last = 0;
    for (int py = ty0; py <= ty1; py++)
        for (int px = tx0; px <= tx1; px++) {
            const int p = (py - ty0) * SP_TILE_SIZE + (px - tx0);
            const size_t pix = (size_t)py * W + px;
            T[p] = r->final_T[pix];
            for (int c = 0; c < D; c++) {
                S[c * TS + p] = T[p] * bg[c];
                VI[c * TS + p] = v_image[pix * D + c];
            }
            if (v_depth) VD[p] = v_depth[pix];
            if (v_alpha) VA[p] = v_alpha[pix] * T[p];
            last[p] = r->n_contrib[pix];
            if (last[p] > max_last) max_last = last[p];
        }

    const uint32_t start = r->tile_start[tile], end = r->tile_start[tile + 1];
    /* Gaussians behind every pixel's last contributor get zero from this tile. */
    for (uint32_t j = start + (uint32_t)max_last; j < end; j++)
        memset(r->slots + (size_t)r->tile_slot[j] * stride, 0, (size_t)stride * sizeof(float));

    const float *colors = r->in.colors;
    const cpu_v4i lane = {0, 1, 2, 3};
    const cpu_v4f zero = cpu_v4_splat(0.f), one = cpu_v4_splat(1.f);
    for (uint32_t j = start + (uint32_t)max_last; j-- > start;) {
        const cpu_gauss *rec = r->tile_rec + j;
        const int32_t g = rec->g;
        const cpu_rect bx = cpu_box_in_tile(rec, tr);
        const int x0 = bx.x0, x1 = bx.x1, y0 = bx.y0, y1 = bx.y1;
        const float mx = rec->mx, my = rec->my;
        const float con[3] = {rec->con[0], rec->con[1], rec->con[2]};
        const float op = rec->op, z = rec->z, cut = rec->cut, det_con = rec->det_con;
        const float half_a = 0.5f * con[0];
        float fcs, fsn; /* the conic gradient is summed in the conic's frame (gauss_math.h) */
        sp_gm_conic_frame(con, &fcs, &fsn);
        const cpu_v4f v_fcs = cpu_v4_splat(fcs), v_fsn = cpu_v4_splat(fsn);
        const cpu_v4f v_half_a = cpu_v4_splat(half_a), v_opac = cpu_v4_splat(op), v_cut = cpu_v4_splat(cut);
        const float *restrict col = colors + (size_t)g * D;
        const int32_t pos1 = (int32_t)(j - start); /* contributes where pos < last[p] */
        const cpu_v4i pos = {pos1, pos1, pos1, pos1};
        const cpu_v4f vz = cpu_v4_splat(z), vop = cpu_v4_splat(op);
        cpu_v4f v_mx = zero, v_my = zero, v_ca = zero, v_cb = zero, v_cc = zero, v_op = zero, v_z = zero;
        for (int c = 0; c < D; c++) v_col[c] = zero;
        for (int py = y0; py <= y1; py++) {
            const float dy = (float)py + 0.5f - my;
            float by, hy;
            sp_gm_row_terms(con, dy, &by, &hy);
            const cpu_v4f v_by = cpu_v4_splat(by), v_hy = cpu_v4_splat(hy);
            const cpu_v4f vdy = cpu_v4_splat(dy);
            int rx0, rx1;
            cpu_row_range(con, det_con, cut, mx, dy, x0, x1, &rx0, &rx1);
            for (int px = rx0; px <= rx1; px += 4) {
                const int p = (py - ty0) * SP_TILE_SIZE + (px - tx0);
                cpu_v4f gv;
                const cpu_v4f dx = cpu_dx4(px, mx);
                const cpu_v4f a = cpu_alpha4(v_half_a, v_by, v_hy, v_opac, v_cut, dx, &gv);
                const cpu_v4i in_row = lane <= (cpu_v4i){rx1 - px, rx1 - px, rx1 - px, rx1 - px};
                const cpu_v4i valid = in_row & (pos < load4i(last + p)) & (a > zero);
                if (!cpu_v4_any(valid)) continue;
                const cpu_v4f Tv = load4(T + p);
                const cpu_v4f ra = one / (one - a);
                const cpu_v4f Ti = Tv * ra;
                const cpu_v4f w = cpu_v4_select(valid, a * Ti, zero);
                /* dC/dalpha . v = Ti (v . c) - ra (v . S) for the channels, same for depth */
                cpu_v4f dc = zero, ds = zero;
                for (int c = 0; c < D; c++) {
                    const cpu_v4f vi = load4(VI + c * TS + p);
                    const cpu_v4f sc = load4(S + c * TS + p);
                    const cpu_v4f cc = cpu_v4_splat(col[c]);
                    dc += vi * cc;
                    ds += vi * sc;
                    v_col[c] += w * vi;
                    store4(S + c * TS + p, sc + w * cc);
                }
                const cpu_v4f vd = load4(VD + p), sd = load4(S_d + p);
                cpu_v4f v_a = Ti * dc - ra * ds + vd * (Ti * vz - sd * ra) + load4(VA + p) * ra;
                v_z += w * vd;
                store4(S_d + p, sd + w * vz);
                store4(T + p, cpu_v4_select(valid, Ti, Tv));
                /* alpha = op g: no gradient where it was capped at SP_ALPHA_MAX */
                const cpu_v4i live = valid & (vop * gv <= cpu_v4_splat(SP_ALPHA_MAX));
                const cpu_v4f gva = cpu_v4_select(live, gv * v_a, zero);
                v_op += gva;
                const cpu_v4f v_sigma = -vop * gva;
                const cpu_v4f hs = cpu_v4_splat(0.5f) * v_sigma;
                const cpu_v4f d0 = v_fcs * dx + v_fsn * vdy, d1 = v_fcs * vdy - v_fsn * dx;
                v_ca += hs * d0 * d0;
                v_cb += hs * d0 * d1;
                v_cc += hs * d1 * d1;
                /* d = centre - mean2d: d sigma / d mean2d = -(conic d) */
                v_mx -= v_sigma * (cpu_v4_splat(con[0]) * dx + cpu_v4_splat(con[1]) * vdy);
                v_my -= v_sigma * (cpu_v4_splat(con[1]) * dx + cpu_v4_splat(con[2]) * vdy);
            }
        }
        float *s = r->slots + (size_t)r->tile_slot[j] * stride;
        s[0] = hsum(v_mx);
        s[1] = hsum(v_my);
        s[2] = hsum(v_ca);
        s[3] = hsum(v_cb);
        s[4] = hsum(v_cc);
        s[5] = hsum(v_op);
        s[6] = hsum(v_z);
        for (int c = 0; c < D; c++) s[SP_SLOT_FIXED + c] = hsum(v_col[c]);
    }
}

static void backward_item(void *vctx, long tile, int thread_id)
{
    bwd_ctx *c = vctx;
    cpu_raster *r = c->r;
    float *scratch = r->scratch[thread_id].buf;
    switch (r->D) { /* a constant D for each specialised width (device.h), so loops unroll */
#define SP_WIDTH_CASE(w) case w: tile_backward(r, c->gin, tile, scratch, w); break;
    SP_CHANNEL_WIDTHS(SP_WIDTH_CASE)
#undef SP_WIDTH_CASE
    default: tile_backward(r, c->gin, tile, scratch, r->D); break;
    }
}

int cpu_rasterize_backward(cpu_raster *r, const sp_raster_grad_in *gin, sp_error *err)
{
    size_t stride = SP_SLOT_FIXED + (size_t)r->D;
    if (r->pairs > SIZE_MAX / sizeof(float) / stride)
        return sp_error_set(err, SP_E_NOMEM, "rasterizer backward: %zu pairs x %zu floats overflow",
                            r->pairs, stride);
    int rc = sp_scratch_reserve(r->dev, &r->slot_buf, &r->slot_cap,
                                r->pairs * stride * sizeof(float) + 64, err);
    if (rc) return rc;
    r->slots = r->slot_buf;
    rc = cpu_reserve_thread_scratch(r, err);
    if (rc) return rc;
    bwd_ctx c = {r, gin};
    sp_pool_for(r->dev->pool, (long)r->tiles_x * r->tiles_y, backward_item, &c);
    return 0;
}
