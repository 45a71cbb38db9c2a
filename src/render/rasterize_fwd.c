/* CPU forward compositing: one 16x16 tile per pool item. The loop runs Gaussian-outer over the
 * tile's front-to-back list and pixel-inner over the part of the Gaussian's pixel box inside the
 * tile, so each Gaussian's parameters are loaded once per tile and small Gaussians touch few
 * pixels. Per pixel it keeps the transmittance T, the accumulated channels and the position of
 * the last contributor (for the backward), and stops by the 3DGS rules (sp_gm_alpha skips
 * alpha < 1/255 and caps at 0.99; a Gaussian that would take T below 1e-4 ends the pixel and
 * does not contribute). The tile stops when all its pixels are done. */
#include <stdlib.h>
#include <string.h>

#include "render/gauss_math.h"
#include "render/render_internal.h"

#define TILE_PIX (SP_TILE_SIZE * SP_TILE_SIZE)

typedef struct {
    cpu_raster *r;
    sp_raster_out *out;
} fwd_ctx;

/* Always inlined so each call site below gets a constant D and the channel loops unroll. */
static inline __attribute__((always_inline)) void tile_forward(cpu_raster *r, sp_raster_out *out,
                                                               long tile, float *scratch, const int D)
{
    const int W = r->W, H = r->H;
    const int tx0 = (int)(tile % r->tiles_x) * SP_TILE_SIZE, ty0 = (int)(tile / r->tiles_x) * SP_TILE_SIZE;
    const int tx1 = tx0 + SP_TILE_SIZE - 1 < W - 1 ? tx0 + SP_TILE_SIZE - 1 : W - 1;
    const int ty1 = ty0 + SP_TILE_SIZE - 1 < H - 1 ? ty0 + SP_TILE_SIZE - 1 : H - 1;
    const int npix = (tx1 - tx0 + 1) * (ty1 - ty0 + 1);

    float *T = scratch;                 /* [TILE_PIX] */
    float *acc_d = T + TILE_PIX;        /* [TILE_PIX] */
    float *acc = acc_d + TILE_PIX;      /* [TILE_PIX][D] */
    int32_t *last = (int32_t *)(acc + (size_t)TILE_PIX * D);
    unsigned char *done = (unsigned char *)(last + TILE_PIX);
    for (int p = 0; p < TILE_PIX; p++) T[p] = 1.f;
    memset(acc_d, 0, TILE_PIX * sizeof(float));
    memset(acc, 0, (size_t)TILE_PIX * D * sizeof(float));
    memset(last, 0, TILE_PIX * sizeof(int32_t));
    memset(done, 0, TILE_PIX);

    const uint32_t start = r->tile_start[tile], end = r->tile_start[tile + 1];
    const float *colors = r->in.colors;
    int ndone = 0;
    for (uint32_t j = start; j < end && ndone < npix; j++) {
        const cpu_gauss *rec = r->tile_rec + j;
        const int32_t g = rec->g;
        const int32_t *b = rec->box;
        const int x0 = b[0] > tx0 ? b[0] : tx0, x1 = b[1] < tx1 ? b[1] : tx1;
        const int y0 = b[2] > ty0 ? b[2] : ty0, y1 = b[3] < ty1 ? b[3] : ty1;
        const float mx = rec->mx, my = rec->my;
        const float con[3] = {rec->con[0], rec->con[1], rec->con[2]};
        const float op = rec->op, z = rec->z, cut = rec->cut, det_con = rec->det_con;
        const float *restrict col = colors + (size_t)g * D;
        const int32_t pos = (int32_t)(j - start) + 1;
        for (int py = y0; py <= y1; py++) {
            const float dy = (float)py + 0.5f - my;
            int rx0, rx1;
            cpu_row_range(con, det_con, cut, mx, dy, x0, x1, &rx0, &rx1);
            for (int px = rx0; px <= rx1; px++) {
                const int p = (py - ty0) * SP_TILE_SIZE + (px - tx0);
                if (done[p]) continue;
                float gauss;
                const float alpha = sp_gm_alpha_g(con, op, cut, (float)px + 0.5f - mx, dy, &gauss);
                if (alpha == 0.f) continue;
                const float next_T = T[p] * (1.f - alpha);
                if (next_T < SP_TRANSMITTANCE_MIN) {
                    done[p] = 1;
                    ndone++;
                    continue;
                }
                const float w = alpha * T[p];
                float *restrict a = acc + (size_t)p * D;
                for (int c = 0; c < D; c++) a[c] += w * col[c];
                acc_d[p] += w * z;
                T[p] = next_T;
                last[p] = pos;
            }
        }
    }

    const float *bg = r->background;
    for (int py = ty0; py <= ty1; py++)
        for (int px = tx0; px <= tx1; px++) {
            const int p = (py - ty0) * SP_TILE_SIZE + (px - tx0);
            const size_t pix = (size_t)py * W + px;
            float *o = out->image + pix * D;
            const float *a = acc + (size_t)p * D;
            for (int c = 0; c < D; c++) o[c] = a[c] + T[p] * bg[c];
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
    switch (r->D) {
    case 1: tile_forward(r, c->out, tile, scratch, 1); break;
    case 3: tile_forward(r, c->out, tile, scratch, 3); break;
    case 4: tile_forward(r, c->out, tile, scratch, 4); break;
    case 8: tile_forward(r, c->out, tile, scratch, 8); break;
    case 16: tile_forward(r, c->out, tile, scratch, 16); break;
    case 32: tile_forward(r, c->out, tile, scratch, 32); break;
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
    size_t bytes = (size_t)TILE_PIX * (4 + 2 * (size_t)r->D) * sizeof(float) + 4096 +
                   (size_t)(SP_SLOT_FIXED + r->D) * sizeof(float);
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
