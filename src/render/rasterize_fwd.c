/* CPU forward compositing: one 16x16 tile per pool item. The loop runs Gaussian-outer over the
 * tile's front-to-back list and pixel-inner over the part of the Gaussian's pixel box inside the
 * tile (narrowed per row to the ellipse where alpha can reach 1/255), four pixels of a row at a
 * time, so each Gaussian's record (one cache line, streamed from the tile list) is read once per
 * tile. Per pixel it keeps the transmittance T, the accumulated channels and the position of the
 * last contributor (for the backward), and follows the 3DGS rules (cpu_alpha4 in
 * render_internal.h skips alpha < 1/255 and caps at 0.99; a Gaussian that would take T below
 * 1e-4 ends the pixel and does not contribute). The tile stops when all its pixels are done. */
#include <stdlib.h>
#include <string.h>

#include "render/gauss_math.h"
#include "render/render_internal.h"


typedef struct {
    cpu_raster *r;
    sp_raster_out *out;
} fwd_ctx;



/* Always inlined so each call site below gets a constant D and the channel loops unroll.
 * Four pixels of a row per step: lanes past the row's range or already finished are masked out
 * and written back unchanged, so each pixel sees exactly the scalar rule's operations. */
static inline __attribute__((always_inline)) void tile_forward(cpu_raster *r, sp_raster_out *out,
                                                               long tile, float *scratch, const int D)
{
    const int W = r->W;
    const cpu_rect tr = cpu_tile_rect(r, tile);
    const int tx0 = tr.x0, tx1 = tr.x1, ty0 = tr.y0, ty1 = tr.y1;
    const int npix = (tx1 - tx0 + 1) * (ty1 - ty0 + 1);

    float *T = scratch;                          /* [TILE_STRIDE] */
    float *acc_d = T + TILE_STRIDE;              /* [TILE_STRIDE] */
    int32_t *last = (int32_t *)(acc_d + TILE_STRIDE); /* [TILE_STRIDE] */
    int32_t *done = last + TILE_STRIDE;          /* [TILE_STRIDE] 0 or -1 */
    float *acc = (float *)(done + TILE_STRIDE);  /* [D][TILE_STRIDE] */
    for (int p = 0; p < TILE_STRIDE; p++) T[p] = 1.f;
    memset(acc_d, 0, TILE_STRIDE * sizeof(float));
    memset(last, 0, TILE_STRIDE * sizeof(int32_t));
    memset(done, 0, TILE_STRIDE * sizeof(int32_t));
    memset(acc, 0, (size_t)TILE_STRIDE * D * sizeof(float));

    const uint32_t start = r->tile_start[tile], end = r->tile_start[tile + 1];
    const float *colors = r->in.colors;
    const cpu_v4i lane = {0, 1, 2, 3};
    const cpu_v4f zero = cpu_v4_splat(0.f), one = cpu_v4_splat(1.f);
    int ndone = 0;
    for (uint32_t j = start; j < end && ndone < npix; j++) {
        const cpu_gauss *rec = r->tile_rec + j;
        const int32_t g = rec->g;
        const cpu_rect bx = cpu_box_in_tile(rec, tr);
        const int x0 = bx.x0, x1 = bx.x1, y0 = bx.y0, y1 = bx.y1;
        const float mx = rec->mx, my = rec->my;
        const float con[3] = {rec->con[0], rec->con[1], rec->con[2]};
        const float op = rec->op, z = rec->z, cut = rec->cut, det_con = rec->det_con;
        const float half_a = 0.5f * con[0];
        const cpu_v4f v_half_a = cpu_v4_splat(half_a), v_opac = cpu_v4_splat(op), v_cut = cpu_v4_splat(cut);
        const float *restrict col = colors + (size_t)g * D;
        const cpu_v4i pos = {(int32_t)(j - start) + 1, (int32_t)(j - start) + 1,
                             (int32_t)(j - start) + 1, (int32_t)(j - start) + 1};
        const cpu_v4f vz = cpu_v4_splat(z);
        for (int py = y0; py <= y1; py++) {
            const float dy = (float)py + 0.5f - my;
            float by, hy;
            sp_gm_row_terms(con, dy, &by, &hy);
            const cpu_v4f v_by = cpu_v4_splat(by), v_hy = cpu_v4_splat(hy);
            int rx0, rx1;
            cpu_row_range(con, det_con, cut, mx, dy, x0, x1, &rx0, &rx1);
            for (int px = rx0; px <= rx1; px += 4) {
                const int p = (py - ty0) * SP_TILE_SIZE + (px - tx0);
                cpu_v4f gv;
                const cpu_v4f dx = cpu_dx4(px, mx);
                const cpu_v4f a = cpu_alpha4(v_half_a, v_by, v_hy, v_opac, v_cut, dx, &gv);
                const cpu_v4i in_row = lane <= (cpu_v4i){rx1 - px, rx1 - px, rx1 - px, rx1 - px};
                const cpu_v4i dn = load4i(done + p);
                const cpu_v4i valid = in_row & ~dn & (a > zero);
                if (!cpu_v4_any(valid)) continue;
                const cpu_v4f Tv = load4(T + p);
                const cpu_v4f next_T = Tv * (one - a);
                const cpu_v4i stop = valid & (next_T < cpu_v4_splat(SP_TRANSMITTANCE_MIN));
                const cpu_v4i use = valid & ~stop;
                ndone += cpu_v4_count(stop);
                store4i(done + p, dn | stop);
                const cpu_v4f w = a * Tv;
                for (int c = 0; c < D; c++) {
                    float *ac = acc + (size_t)c * TILE_STRIDE + p;
                    store4(ac, load4(ac) + cpu_v4_select(use, w * cpu_v4_splat(col[c]), zero));
                }
                store4(acc_d + p, load4(acc_d + p) + cpu_v4_select(use, w * vz, zero));
                store4(T + p, cpu_v4_select(use, next_T, Tv));
                store4i(last + p, (use & pos) | (~use & load4i(last + p)));
            }
        }
    }

    const float *bg = r->background;
    for (int py = ty0; py <= ty1; py++)
        for (int px = tx0; px <= tx1; px++) {
            const int p = (py - ty0) * SP_TILE_SIZE + (px - tx0);
            const size_t pix = (size_t)py * W + px;
            float *o = out->image + pix * D;
            for (int c = 0; c < D; c++) o[c] = acc[(size_t)c * TILE_STRIDE + p] + T[p] * bg[c];
            if (out->depth) out->depth[pix] = acc_d[p];
            if (out->alpha) out->alpha[pix] = 1.f - T[p];
            r->final_T[pix] = T[p];
            r->n_contrib[pix] = last[p];
        }
}

static void forward_item(void *vctx, long tile, int thread_id)
{
    fwd_ctx *c = vctx;
    cpu_raster *r = c->r;
    float *scratch = r->scratch[thread_id].buf;
    switch (r->D) { /* a constant D for each specialised width (device.h), so loops unroll */
#define SP_WIDTH_CASE(w) case w: tile_forward(r, c->out, tile, scratch, w); break;
    SP_CHANNEL_WIDTHS(SP_WIDTH_CASE)
#undef SP_WIDTH_CASE
    default: tile_forward(r, c->out, tile, scratch, r->D); break;
    }
}

/* Per-thread scratch big enough for either pass at this D. */
int cpu_reserve_thread_scratch(cpu_raster *r, sp_error *err)
{
    int nt = sp_pool_size(r->dev->pool);
    if (r->n_scratch < nt) {
        cpu_tile_scratch *s = realloc(r->scratch, (size_t)nt * sizeof *s);
        if (!s) return sp_error_set(err, SP_E_NOMEM, "rasterizer: out of memory for thread scratch");
        for (int i = r->n_scratch; i < nt; i++) s[i].buf = NULL, s[i].cap = 0;
        r->scratch = s;
        r->n_scratch = nt;
    }
    /* forward: T, acc_d, acc[D], last, done; backward: T, S_d, S[D], v_col[D], ... */
    /* backward: 5 + 2 D per-pixel arrays of TILE_PIX + 4, then D vectors of 4 floats */
    size_t bytes = (size_t)(TILE_PIX + 16) * (8 + 2 * (size_t)r->D) * sizeof(float) + 4096 +
                   (size_t)r->D * 4 * sizeof(float);
    for (int i = 0; i < nt; i++) {
        int rc = sp_scratch_reserve(r->dev, &r->scratch[i].buf, &r->scratch[i].cap, bytes, err);
        if (rc) return rc;
    }
    return 0;
}

int cpu_rasterize_forward(cpu_raster *r, sp_raster_out *out, sp_error *err)
{
    size_t npix = (size_t)r->W * r->H;
    int rc = sp_scratch_reserve(r->dev, &r->pix_buf, &r->pix_cap, npix * 2 * sizeof(float) + 64, err);
    if (rc) return rc;
    r->final_T = r->pix_buf;
    r->n_contrib = (int32_t *)(r->final_T + npix);
    rc = cpu_reserve_thread_scratch(r, err);
    if (rc) return rc;
    fwd_ctx c = {r, out};
    sp_pool_for(r->dev->pool, (long)r->tiles_x * r->tiles_y, forward_item, &c);
    return 0;
}
