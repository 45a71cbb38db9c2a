/* CUDA backend, stage 3: forward compositing, and sp_cuda_raster_forward (the whole pipeline).
 *
 * One 16x16 thread block per tile and channel chunk: each thread owns a pixel, the block walks
 * the tile's depth-sorted list in batches of 256 Gaussians staged in shared memory (position,
 * conic, opacity, depth, the chunk's colour values), and composites front to back with the 3DGS
 * bounds. Kernels are specialised on the chunk width CH in SP_CHANNEL_WIDTHS (device.h: 1, 2, 3,
 * 4, 8, 12, 16, 24, 32, 40, 48, 64; the in-between widths keep RGB + 32 features = 35 from paying
 * for 64); a channel count that
 * is not one of those is padded up to the next (padded channels read as zero and are never
 * written), and wider ones run as several chunks (blockIdx.z), each recomputing the cheap
 * per-pixel alpha so registers hold only CH accumulators. The first chunk also writes
 * depth, alpha, the final transmittance and the per-pixel end of the list for backward. */
#include "common.cuh"

#define BLOCK (SP_TILE_SIZE * SP_TILE_SIZE)

template <int CH>
__global__ void __launch_bounds__(BLOCK)
k_raster_fwd(int W, int H, int tiles_x, const int2 *__restrict__ ranges,
             const uint32_t *__restrict__ ids, const float2 *__restrict__ means2d,
             const float4 *__restrict__ conic_op, const float *__restrict__ depths,
             const float *__restrict__ colors, int D, int c_base, const float *__restrict__ bg,
             float *__restrict__ image, float *__restrict__ depth_out,
             float *__restrict__ alpha_out, float *__restrict__ t_final,
             int32_t *__restrict__ last_idx, int aux)
{
    extern __shared__ float4 smem_f4[];
    float4 *s_conic = smem_f4;                        /* [BLOCK] */
    float2 *s_xy = (float2 *)(s_conic + BLOCK);       /* [BLOCK] */
    float *s_z = (float *)(s_xy + BLOCK);             /* [BLOCK] */
    float *s_cut = s_z + BLOCK;                       /* [BLOCK] */
    int *s_id = (int *)(s_cut + BLOCK);               /* [BLOCK] */
    float *s_col = (float *)(s_id + BLOCK);           /* [BLOCK][CH] */

    const int c0 = c_base + blockIdx.z * CH;
    const int tid = threadIdx.y * SP_TILE_SIZE + threadIdx.x;
    const int px_i = blockIdx.x * SP_TILE_SIZE + threadIdx.x;
    const int py_i = blockIdx.y * SP_TILE_SIZE + threadIdx.y;
    const bool inside = px_i < W && py_i < H;
    const float px = px_i + 0.5f, py = py_i + 0.5f;
    const int2 range = ranges[blockIdx.y * tiles_x + blockIdx.x];

    float acc[CH];
#pragma unroll
    for (int c = 0; c < CH; c++) acc[c] = 0.f;
    float acc_z = 0.f, T = 1.f;
    int last = range.x;
    bool done = !inside;

    for (int b0 = range.x; b0 < range.y; b0 += BLOCK) {
        if (__syncthreads_count(done) == BLOCK) break;
        const int cnt = min(BLOCK, range.y - b0);
        if (tid < cnt) {
            int g = (int)ids[b0 + tid];
            s_id[tid] = g;
            s_xy[tid] = means2d[g];
            const float4 co = conic_op[g];
            s_conic[tid] = co;
            s_cut[tid] = sp_cu_sigma_cut(co.w);
            s_z[tid] = depths[g];
        }
        __syncthreads();
        /* colours: neighbouring threads read neighbouring channels of one Gaussian */
        for (int k = tid; k < cnt * CH; k += BLOCK) {
            int j = k / CH, c = k - j * CH;
            s_col[k] = (c0 + c < D) ? colors[(size_t)s_id[j] * D + c0 + c] : 0.f;
        }
        __syncthreads();
        for (int j = 0; j < cnt && !done; j++) {
            const float4 co = s_conic[j];
            const float2 xy = s_xy[j];
            const float dx = px - xy.x, dy = py - xy.y;
            float vis;
            const float alpha = sp_cu_alpha(co, s_cut[j], dx, dy, &vis);
            if (alpha == 0.f) continue;
            const float next_T = T * (1.f - alpha);
            if (next_T < SP_TRANSMITTANCE_MIN) {
                done = true;
                break;
            }
            const float w = alpha * T;
            const float *col = s_col + j * CH;
#pragma unroll
            for (int c = 0; c < CH; c++) acc[c] += col[c] * w;
            acc_z += s_z[j] * w;
            T = next_T;
            last = b0 + j + 1;
        }
    }
    if (!inside) return;
    const size_t pix = (size_t)py_i * W + px_i;
#pragma unroll
    for (int c = 0; c < CH; c++)
        if (c0 + c < D) image[pix * D + c0 + c] = acc[c] + T * (bg ? bg[c0 + c] : 0.f);
    if (aux && blockIdx.z == 0) {
        t_final[pix] = T;
        last_idx[pix] = last;
        if (depth_out) depth_out[pix] = acc_z;
        if (alpha_out) alpha_out[pix] = 1.f - T;
    }
}

static size_t fwd_smem(int ch)
{
    return (size_t)BLOCK * (sizeof(float4) + sizeof(float2) + 2 * sizeof(float) + sizeof(int) +
                            sizeof(float) * ch);
}

template <int CH>
static int launch_fwd(const sp_cuda_raster *r, const sp_cuda_view *v, const sp_cuda_pass *p,
                      int c_base, int n_chunks, int aux, sp_error *err)
{
    size_t smem = fwd_smem(CH);
    SP_CUDA_CHECK(cudaFuncSetAttribute(k_raster_fwd<CH>, cudaFuncAttributeMaxDynamicSharedMemorySize,
                                       (int)smem),
                  err, "forward shared memory");
    dim3 grid(v->tiles_x, v->tiles_y, n_chunks), block(SP_TILE_SIZE, SP_TILE_SIZE, 1);
    k_raster_fwd<CH><<<grid, block, smem, r->stream>>>(
        v->cam.width, v->cam.height, v->tiles_x, v->tile_ranges, v->sorted_ids, v->proj.means2d,
        v->proj.conic_op, v->proj.depths, p->colors, p->D, c_base, p->bg_dev, p->image,
        p->depth, p->alpha, v->t_final, v->last_idx, aux);
    SP_CUDA_LAUNCHED(err, "forward rasterization");
    return 0;
}

/* Launches the kernel specialised for width `ch` (one of SP_CHANNEL_WIDTHS). */
static int dispatch_fwd(int ch, const sp_cuda_raster *r, const sp_cuda_view *v,
                        const sp_cuda_pass *p, int c_base, int n_chunks, int aux, sp_error *err)
{
    switch (ch) {
#define SP_WIDTH_CASE(w) case w: return launch_fwd<w>(r, v, p, c_base, n_chunks, aux, err);
    SP_CHANNEL_WIDTHS(SP_WIDTH_CASE)
#undef SP_WIDTH_CASE
    default: return sp_error_set(err, SP_E_ARG, "no forward kernel for chunk width %d", ch);
    }
}

/* D channels as full chunks of max_ch plus one narrower launch for the rest; aux: write depth,
 * alpha, the final transmittance and the list ends (once, from the first chunk). */
int sp_cuda_rasterize_fwd(sp_cuda_raster *r, const sp_cuda_view *v, const sp_cuda_pass *p,
                          int max_ch, int aux, sp_error *err)
{
    int D = p->D, rc;
    int full = D / max_ch, rem = D % max_ch;
    if (full > 0 && (rc = dispatch_fwd(max_ch, r, v, p, 0, full, aux, err))) return rc;
    if (rem > 0 && (rc = dispatch_fwd(sp_channel_width(rem, max_ch), r, v, p, full * max_ch,
                                      1, aux && full == 0, err)))
        return rc;
    return 0;
}

/* Uploads a host background of D floats into the raster's scratch (NULL: none). */
int sp_cuda_upload_background(sp_cuda_raster *r, const float *bg, int D, float **out, sp_error *err)
{
    *out = NULL;
    if (!bg) return 0;
    int rc = sp_cu_reserve(r, &r->s_bg, (size_t)D * sizeof(float), err);
    if (rc) return rc;
    SP_CUDA_CHECK(cudaMemcpyAsync(r->s_bg.ptr, bg, (size_t)D * sizeof(float), cudaMemcpyHostToDevice,
                                  r->stream),
                  err, "uploading the background");
    *out = (float *)r->s_bg.ptr;
    return 0;
}

/* ---- the whole forward --------------------------------------------------------------------- */

int sp_cuda_raster_forward(void *state, const sp_camera *cam, const sp_raster_cfg *cfg,
                                      const sp_raster_in *in, sp_raster_out *out, sp_error *err)
{
    sp_cuda_raster *r = (sp_cuda_raster *)state;
    sp_cuda_view *v = &r->view;
    int rc;
    r->have_forward = 0;
    v->cam = *cam;
    r->cfg = *cfg;
    r->in = *in;
    r->in.background = NULL; /* host pointer; kept on the device in bg_dev */
    v->tiles_x = (cam->width + SP_TILE_SIZE - 1) / SP_TILE_SIZE;
    v->tiles_y = (cam->height + SP_TILE_SIZE - 1) / SP_TILE_SIZE;
    v->box_tiles = cfg->box_tiles;
    size_t npix = (size_t)cam->width * cam->height;

    if ((rc = sp_cuda_upload_background(r, in->background, in->D, &r->bg_dev, err))) return rc;
    if ((rc = sp_cu_reserve(r, &r->s_tfinal, npix * sizeof(float), err))) return rc;
    if ((rc = sp_cu_reserve(r, &r->s_last, npix * sizeof(int32_t), err))) return rc;
    v->t_final = (float *)r->s_tfinal.ptr;
    v->last_idx = (int32_t *)r->s_last.ptr;

    if ((rc = sp_cuda_reserve_proj(r, in->n, &v->proj, err))) return rc;
    r->prof_fwd = r->prof_bwd = 0;
    r->profiling = cfg->profile;
    if (r->profiling && (rc = sp_cuda_make_events(r, err))) return rc;
    sp_cu_mark(r, SP_EV_START);
    if ((rc = sp_cuda_project(r, v, cfg, in, err))) return rc;
    sp_cu_mark(r, SP_EV_PROJECTED);
    if ((rc = sp_cuda_bin_and_sort(r, v, in->n, err))) return rc;
    sp_cu_mark(r, SP_EV_SORTED);
    sp_cuda_pass pass = {in->colors, in->D, r->bg_dev, out->image, out->depth, out->alpha};
    int max_ch = cfg->chunk_fwd ? cfg->chunk_fwd : SP_CHANNEL_CHUNK_MAX;
    if ((rc = sp_cuda_rasterize_fwd(r, v, &pass, max_ch, 1, err))) return rc;
    sp_cu_mark(r, SP_EV_FWD_DONE);
    r->prof_fwd = r->profiling;
    if (out->surface_depth &&
        (rc = sp_cuda_rasterize_surface(r, v, cfg->surface_alpha, out->surface_depth, err)))
        return rc;
    r->have_forward = 1;
    return 0;
}
