/* CPU first-surface (median) depth: per pixel, the camera depth of the first Gaussian, front to
 * back, after which the accumulated alpha 1 - T reaches the threshold. It walks the same tile
 * lists with the forward's own alpha rule (cpu_alpha4), row ranges and stopping rule, so it keeps
 * and skips exactly what the forward composites (and what the CUDA pass does, bit for bit): the
 * transmittance after each contribution is the forward's T * (1 - alpha), and "reaches" is
 * T <= 1 - threshold with that float T. A separate pass, so the forward's hot loop is unchanged.
 * Pixels end early here (at alpha 0.5, not 1 - 1e-4), so a tile's list is walked long after most
 * of its pixels are done: a bit per done pixel and row (the only record of which are done) lets a
 * Gaussian skip done rows and done groups of four without computing their alpha. */
#include "render/gauss_math.h"
#include "render/render_internal.h"

typedef struct {
    cpu_raster *r;
    float t_stop; /* 1 - threshold */
    float *out;
} surf_ctx;

static void tile_surface(const surf_ctx *c, long tile, float *scratch)
{
    const cpu_raster *r = c->r;
    const int W = r->W;
    const cpu_rect tr = cpu_tile_rect(r, tile);
    const int tx0 = tr.x0, tx1 = tr.x1, ty0 = tr.y0, ty1 = tr.y1;
    const int npix = (tx1 - tx0 + 1) * (ty1 - ty0 + 1);

    float *T = scratch;                         /* [TILE_STRIDE] */
    float *surf = T + TILE_STRIDE;              /* [TILE_STRIDE] */
    for (int p = 0; p < TILE_STRIDE; p++) T[p] = 1.f;
    memset(surf, 0, TILE_STRIDE * sizeof(float));

    const uint32_t start = r->tile_start[tile], end = r->tile_start[tile + 1];
    const cpu_v4i lane = {0, 1, 2, 3};
    const cpu_v4f zero = cpu_v4_splat(0.f), one = cpu_v4_splat(1.f), v_stop = cpu_v4_splat(c->t_stop);
    int ndone = 0;
    uint32_t row_done[SP_TILE_SIZE] = {0}; /* bit px - tx0 of row py - ty0: that pixel is done */
    const uint32_t row_full = (2u << (tx1 - tx0)) - 1u;
    for (uint32_t j = start; j < end && ndone < npix; j++) {
        const cpu_gauss *rec = r->tile_rec + j;
        const cpu_rect bx = cpu_box_in_tile(rec, tr);
        const int x0 = bx.x0, x1 = bx.x1, y0 = bx.y0, y1 = bx.y1;
        const float mx = rec->mx, my = rec->my;
        const float con[3] = {rec->con[0], rec->con[1], rec->con[2]};
        const cpu_v4f v_half_a = cpu_v4_splat(0.5f * con[0]), v_opac = cpu_v4_splat(rec->op);
        const cpu_v4f v_cut = cpu_v4_splat(rec->cut), vz = cpu_v4_splat(rec->z);
        for (int py = y0; py <= y1; py++) {
            if (row_done[py - ty0] == row_full) continue; /* the whole row is done */
            const float dy = (float)py + 0.5f - my;
            float by, hy;
            sp_gm_row_terms(con, dy, &by, &hy);
            const cpu_v4f v_by = cpu_v4_splat(by), v_hy = cpu_v4_splat(hy);
            int rx0, rx1;
            cpu_row_range(con, rec->det_con, rec->cut, mx, dy, x0, x1, &rx0, &rx1);
            if (rx1 < rx0) continue;
            uint32_t *rd = &row_done[py - ty0];
            const uint32_t span = (2u << (rx1 - tx0)) - (1u << (rx0 - tx0));
            if ((*rd & span) == span) continue; /* every pixel of the row's range is done */
            for (int px = rx0; px <= rx1; px += 4) {
                const int p = (py - ty0) * SP_TILE_SIZE + (px - tx0);
                const unsigned done4 = (*rd >> (px - tx0)) & 15u;
                if (done4 == 15u) continue; /* four done pixels */
                cpu_v4f gv;
                const cpu_v4f a = cpu_alpha4(v_half_a, v_by, v_hy, v_opac, v_cut, cpu_dx4(px, mx), &gv);
                const cpu_v4i in_row = lane <= (cpu_v4i){rx1 - px, rx1 - px, rx1 - px, rx1 - px};
                const cpu_v4i dn = cpu_v4_mask(done4);
                const cpu_v4i valid = in_row & ~dn & (a > zero);
                if (!cpu_v4_any(valid)) continue;
                const cpu_v4f Tv = load4(T + p);
                const cpu_v4f next_T = Tv * (one - a);
                const cpu_v4i stop = valid & (next_T < cpu_v4_splat(SP_TRANSMITTANCE_MIN));
                const cpu_v4i use = valid & ~stop;
                const cpu_v4i hit = use & (next_T <= v_stop);
                const cpu_v4i ended = stop | hit;
                ndone += cpu_v4_count(ended);
                *rd |= cpu_v4_bits(ended) << (px - tx0);
                store4(surf + p, cpu_v4_select(hit, vz, load4(surf + p)));
                store4(T + p, cpu_v4_select(use, next_T, Tv));
            }
        }
    }
    for (int py = ty0; py <= ty1; py++)
        for (int px = tx0; px <= tx1; px++)
            c->out[(size_t)py * W + px] = surf[(py - ty0) * SP_TILE_SIZE + (px - tx0)];
}

static void surface_item(void *vctx, long tile, int thread_id)
{
    const surf_ctx *c = vctx;
    tile_surface(c, tile, c->r->scratch[thread_id].buf);
}

int cpu_rasterize_surface(cpu_raster *r, float surface_alpha, float *out, sp_error *err)
{
    int rc = cpu_reserve_thread_scratch(r, err);
    if (rc) return rc;
    surf_ctx c = {r, 1.0f - surface_alpha, out};
    sp_pool_for(r->dev->pool, (long)r->tiles_x * r->tiles_y, surface_item, &c);
    return 0;
}
