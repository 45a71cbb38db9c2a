/* CUDA backend: first-surface (median) depth. Per pixel, the camera depth of the first Gaussian,
 * front to back, after which the accumulated alpha 1 - T reaches the threshold: the forward's walk
 * over the sorted tile list (same alpha rule, same T * (1 - alpha), same stop below 1e-4) with no
 * colours, so it keeps exactly what the forward composites, and what the CPU pass
 * (src/render/rasterize_surface.c) does, bit for bit. A separate kernel, so the forward's hot
 * loop is unchanged; it runs only when a caller asks for surface depth. */
#include "common.cuh"

#define BLOCK (SP_TILE_SIZE * SP_TILE_SIZE)

__global__ void __launch_bounds__(BLOCK)
k_raster_surface(int W, int H, int tiles_x, const int2 *__restrict__ ranges,
                 const uint32_t *__restrict__ ids, const float2 *__restrict__ means2d,
                 const float4 *__restrict__ conic_op, const float *__restrict__ depths,
                 float t_stop, float *__restrict__ out)
{
    __shared__ float4 s_conic[BLOCK];
    __shared__ float2 s_xy[BLOCK];
    __shared__ float s_z[BLOCK], s_cut[BLOCK];

    const int tid = threadIdx.y * SP_TILE_SIZE + threadIdx.x;
    const int px_i = blockIdx.x * SP_TILE_SIZE + threadIdx.x;
    const int py_i = blockIdx.y * SP_TILE_SIZE + threadIdx.y;
    const bool inside = px_i < W && py_i < H;
    const float px = px_i + 0.5f, py = py_i + 0.5f;
    const int2 range = ranges[blockIdx.y * tiles_x + blockIdx.x];

    float T = 1.f, surf = 0.f;
    bool done = !inside;
    for (int b0 = range.x; b0 < range.y; b0 += BLOCK) {
        if (__syncthreads_count(done) == BLOCK) break;
        const int cnt = min(BLOCK, range.y - b0);
        if (tid < cnt) {
            const int g = (int)ids[b0 + tid];
            s_xy[tid] = means2d[g];
            const float4 co = conic_op[g];
            s_conic[tid] = co;
            s_cut[tid] = sp_cu_sigma_cut(co.w);
            s_z[tid] = depths[g];
        }
        __syncthreads();
        for (int j = 0; j < cnt && !done; j++) {
            const float2 xy = s_xy[j];
            float vis;
            const float alpha = sp_cu_alpha(s_conic[j], s_cut[j], px - xy.x, py - xy.y, &vis);
            if (alpha == 0.f) continue;
            const float next_T = T * (1.f - alpha);
            if (next_T < SP_TRANSMITTANCE_MIN) {
                done = true;
                break;
            }
            if (next_T <= t_stop) {
                surf = s_z[j];
                done = true;
                break;
            }
            T = next_T;
        }
    }
    if (inside) out[(size_t)py_i * W + px_i] = surf;
}

int sp_cuda_rasterize_surface(sp_cuda_raster *r, const sp_cuda_view *v, float surface_alpha,
                              float *out, sp_error *err)
{
    dim3 grid(v->tiles_x, v->tiles_y, 1), block(SP_TILE_SIZE, SP_TILE_SIZE, 1);
    k_raster_surface<<<grid, block, 0, r->stream>>>(
        v->cam.width, v->cam.height, v->tiles_x, v->tile_ranges, v->sorted_ids, v->proj.means2d,
        v->proj.conic_op, v->proj.depths, 1.0f - surface_alpha, out);
    SP_CUDA_LAUNCHED(err, "surface depth");
    return 0;
}
