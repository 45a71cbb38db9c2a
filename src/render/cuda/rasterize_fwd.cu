/* CUDA backend, stage 3: forward compositing, and sp_cuda_raster_forward (the whole pipeline).
 *
 * One 16x16 thread block per tile and channel chunk: each thread owns a pixel, the block walks
 * the tile's depth-sorted list in batches of 256 Gaussians staged in shared memory (position,
 * conic, opacity, depth, the chunk's colour values), and composites front to back with the 3DGS
 * bounds. Kernels are specialised on the chunk width CH in {1,2,3,4,8,12,16,24,32,40,48,64}
 * (the in-between widths keep RGB + 32 features = 35 from paying for 64); a channel count that
 * is not one of those is padded up to the next (padded channels read as zero and are never
 * written), and wider ones run as several chunks (blockIdx.z), each recomputing the cheap
 * per-pixel alpha so registers hold only CH accumulators. The first chunk also writes
 * depth, alpha, the final transmittance and the per-pixel end of the list for backward. */
#include "common.cuh"

#include <stdlib.h>
#include <string.h>

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
static int launch_fwd(sp_cuda_raster *r, sp_raster_out *out, int c_base, int n_chunks, int aux,
                      sp_error *err)
{
    size_t smem = fwd_smem(CH);
    SP_CUDA_CHECK(cudaFuncSetAttribute(k_raster_fwd<CH>, cudaFuncAttributeMaxDynamicSharedMemorySize,
                                       (int)smem),
                  err, "forward shared memory");
    dim3 grid(r->tiles_x, r->tiles_y, n_chunks), block(SP_TILE_SIZE, SP_TILE_SIZE, 1);
    k_raster_fwd<CH><<<grid, block, smem>>>(
        r->cam.width, r->cam.height, r->tiles_x, r->tile_ranges, r->sorted_ids, r->proj.means2d,
        r->proj.conic_op, r->proj.depths, r->in.colors, r->in.D, c_base, r->bg_dev, out->image,
        out->depth, out->alpha, r->t_final, r->last_idx, aux);
    SP_CUDA_LAUNCHED(err, "forward rasterization");
    return 0;
}

/* Launches the kernel specialised for width `ch` (a member of the set). */
static int dispatch_fwd(int ch, sp_cuda_raster *r, sp_raster_out *out, int c_base, int n_chunks,
                        int aux, sp_error *err)
{
    switch (ch) {
    case 1: return launch_fwd<1>(r, out, c_base, n_chunks, aux, err);
    case 2: return launch_fwd<2>(r, out, c_base, n_chunks, aux, err);
    case 3: return launch_fwd<3>(r, out, c_base, n_chunks, aux, err);
    case 4: return launch_fwd<4>(r, out, c_base, n_chunks, aux, err);
    case 8: return launch_fwd<8>(r, out, c_base, n_chunks, aux, err);
    case 12: return launch_fwd<12>(r, out, c_base, n_chunks, aux, err);
    case 16: return launch_fwd<16>(r, out, c_base, n_chunks, aux, err);
    case 24: return launch_fwd<24>(r, out, c_base, n_chunks, aux, err);
    case 32: return launch_fwd<32>(r, out, c_base, n_chunks, aux, err);
    case 40: return launch_fwd<40>(r, out, c_base, n_chunks, aux, err);
    case 48: return launch_fwd<48>(r, out, c_base, n_chunks, aux, err);
    case 64: return launch_fwd<64>(r, out, c_base, n_chunks, aux, err);
    default: return sp_error_set(err, SP_E_ARG, "no forward kernel for chunk width %d", ch);
    }
}

int sp_cuda_chunk_width(int d, int max_ch)
{
    static const int widths[] = {1, 2, 3, 4, 8, 12, 16, 24, 32, 40, 48, 64};
    for (size_t i = 0; i < sizeof(widths) / sizeof(widths[0]); i++)
        if (widths[i] >= d || widths[i] >= max_ch) return widths[i] < max_ch ? widths[i] : max_ch;
    return max_ch;
}

int sp_cuda_env_chunk(const char *name, int dflt)
{
    const char *s = getenv(name);
    if (!s) return dflt;
    int v = atoi(s);
    return (v == 8 || v == 16 || v == 32 || v == 64) ? v : dflt;
}

int sp_cuda_rasterize_fwd(sp_cuda_raster *r, sp_raster_out *out, sp_error *err)
{
    int D = r->in.D, rc;
    int max_ch = sp_cuda_env_chunk("SP_CUDA_FWD_CHUNK", 64);
    int full = D / max_ch, rem = D % max_ch;
    if (full > 0 && (rc = dispatch_fwd(max_ch, r, out, 0, full, 1, err))) return rc;
    if (rem > 0 &&
        (rc = dispatch_fwd(sp_cuda_chunk_width(rem, max_ch), r, out, full * max_ch, 1, full == 0, err)))
        return rc;
    return 0;
}

/* ---- the whole forward --------------------------------------------------------------------- */

extern "C" int sp_cuda_raster_forward(sp_cuda_raster *r, const sp_camera *cam,
                                      const sp_raster_cfg *cfg, const sp_raster_in *in,
                                      sp_raster_out *out, sp_error *err)
{
    if (!r || !cam || !in || !out)
        return sp_error_set(err, SP_E_ARG, "sp_cuda_raster_forward: NULL argument");
    if (cam->width <= 0 || cam->height <= 0)
        return sp_error_set(err, SP_E_ARG, "camera size %dx%d is not positive", cam->width,
                            cam->height);
    if (in->D < 1) return sp_error_set(err, SP_E_ARG, "channel count D = %d (must be >= 1)", in->D);
    if (!out->image) return sp_error_set(err, SP_E_ARG, "out->image is NULL (required)");
    if (in->n > 0 && (!in->means || !in->quats || !in->log_scales || !in->opacity_logits ||
                      !in->colors))
        return sp_error_set(err, SP_E_ARG, "sp_raster_in has a NULL buffer for %zu Gaussians",
                            in->n);
    if (in->n > 0x7fffffff)
        return sp_error_set(err, SP_E_ARG, "%zu Gaussians exceed the 2^31 the backend indexes",
                            in->n);
    int rc;
    r->have_forward = 0;
    r->cam = *cam;
    r->cfg = cfg ? *cfg : sp_raster_cfg_default();
    r->in = *in;
    r->in.background = NULL; /* host pointer; kept on the device in bg_dev */
    r->tiles_x = (cam->width + SP_TILE_SIZE - 1) / SP_TILE_SIZE;
    r->tiles_y = (cam->height + SP_TILE_SIZE - 1) / SP_TILE_SIZE;
    size_t npix = (size_t)cam->width * cam->height;

    r->bg_dev = NULL;
    if (in->background) {
        if ((rc = sp_cu_scratch_reserve(&r->s_bg, (size_t)in->D * sizeof(float), err))) return rc;
        SP_CUDA_CHECK(cudaMemcpy(r->s_bg.ptr, in->background, (size_t)in->D * sizeof(float),
                                 cudaMemcpyHostToDevice),
                      err, "uploading the background");
        r->bg_dev = (float *)r->s_bg.ptr;
    }
    if ((rc = sp_cu_scratch_reserve(&r->s_tfinal, npix * sizeof(float), err))) return rc;
    if ((rc = sp_cu_scratch_reserve(&r->s_last, npix * sizeof(int32_t), err))) return rc;
    r->t_final = (float *)r->s_tfinal.ptr;
    r->last_idx = (int32_t *)r->s_last.ptr;

    if ((rc = sp_cuda_project(r, err))) return rc;
    if ((rc = sp_cuda_bin_and_sort(r, err))) return rc;
    if ((rc = sp_cuda_rasterize_fwd(r, out, err))) return rc;
    r->have_forward = 1;
    return 0;
}
