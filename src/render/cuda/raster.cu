/* CUDA backend: device probe, memory (with live/peak accounting), copies, scratch buffers, and
 * the raster object's lifetime. The pipeline itself is in project.cu, tiles.cu,
 * rasterize_fwd.cu, rasterize_bwd.cu.
 *
 * Peak memory is counted by semsplat itself (every allocation goes through sp_cuda_malloc)
 * rather than from cudaMemGetInfo, which would also count the CUDA context and other processes. */
#include "common.cuh"

#include <pthread.h>
#include <stdlib.h>
#include <string.h>

/* ---- allocation accounting: a small open-addressing table pointer -> size ------------------ */

static pthread_mutex_t g_mem_lock = PTHREAD_MUTEX_INITIALIZER;
static size_t g_live, g_peak;
struct mem_entry {
    void *p;
    size_t n;
};
static mem_entry *g_tab;
static size_t g_tab_cap, g_tab_used;

static size_t tab_slot(void *p, size_t cap)
{
    uintptr_t h = (uintptr_t)p >> 8;
    h ^= h >> 17;
    h *= 0x9E3779B97F4A7C15ull;
    return (size_t)(h & (cap - 1));
}

/* Inserts (p, n); called with the lock held. Returns 0 or -1 when the table cannot grow. */
static int tab_put(void *p, size_t n)
{
    if ((g_tab_used + 1) * 2 > g_tab_cap) {
        size_t ncap = g_tab_cap ? g_tab_cap * 2 : 256;
        mem_entry *nt = (mem_entry *)calloc(ncap, sizeof(*g_tab));
        if (!nt) return -1;
        mem_entry *old = g_tab;
        size_t ocap = g_tab_cap;
        g_tab = nt;
        g_tab_cap = ncap;
        g_tab_used = 0;
        for (size_t i = 0; i < ocap; i++)
            if (old[i].p) {
                size_t s = tab_slot(old[i].p, ncap);
                while (g_tab[s].p) s = (s + 1) & (ncap - 1);
                g_tab[s] = old[i];
                g_tab_used++;
            }
        free(old);
    }
    size_t s = tab_slot(p, g_tab_cap);
    while (g_tab[s].p) s = (s + 1) & (g_tab_cap - 1);
    g_tab[s].p = p;
    g_tab[s].n = n;
    g_tab_used++;
    return 0;
}

/* Removes p and returns its size (0 when unknown); lock held. Backward-shift deletion keeps
 * the probe chains intact. */
static size_t tab_take(void *p)
{
    if (!g_tab_cap) return 0;
    size_t s = tab_slot(p, g_tab_cap);
    while (g_tab[s].p && g_tab[s].p != p) s = (s + 1) & (g_tab_cap - 1);
    if (!g_tab[s].p) return 0;
    size_t n = g_tab[s].n;
    g_tab[s].p = NULL;
    g_tab_used--;
    size_t i = s, j = s;
    for (;;) {
        j = (j + 1) & (g_tab_cap - 1);
        if (!g_tab[j].p) break;
        size_t k = tab_slot(g_tab[j].p, g_tab_cap);
        if ((j > i && (k <= i || k > j)) || (j < i && (k <= i && k > j))) {
            g_tab[i] = g_tab[j];
            g_tab[j].p = NULL;
            i = j;
        }
    }
    return n;
}

extern "C" int sp_cuda_probe(char *name, size_t cap)
{
    int count = 0;
    if (cudaGetDeviceCount(&count) != cudaSuccess || count <= 0) {
        cudaGetLastError(); /* clear the sticky "no device" status */
        return 0;
    }
    cudaDeviceProp prop;
    if (cudaGetDeviceProperties(&prop, 0) != cudaSuccess) return 0;
    if (name && cap) {
        strncpy(name, prop.name, cap - 1);
        name[cap - 1] = 0;
    }
    return 1;
}

extern "C" void *sp_cuda_malloc(size_t bytes, sp_error *err)
{
    if (bytes == 0) bytes = 1;
    void *p = NULL;
    cudaError_t e = cudaMalloc(&p, bytes);
    if (e != cudaSuccess) {
        cudaGetLastError();
        size_t free_b = 0, total_b = 0;
        cudaMemGetInfo(&free_b, &total_b);
        sp_error_set(err, e == cudaErrorMemoryAllocation ? SP_E_NOMEM : SP_E_DEVICE,
                     "CUDA malloc of %zu bytes failed: %s (%zu of %zu bytes free)", bytes,
                     cudaGetErrorString(e), free_b, total_b);
        return NULL;
    }
    e = cudaMemset(p, 0, bytes);
    if (e != cudaSuccess) {
        cudaFree(p);
        sp_error_set(err, SP_E_DEVICE, "CUDA memset of %zu bytes failed: %s", bytes,
                     cudaGetErrorString(e));
        return NULL;
    }
    pthread_mutex_lock(&g_mem_lock);
    if (tab_put(p, bytes) == 0) {
        g_live += bytes;
        if (g_live > g_peak) g_peak = g_live;
    }
    pthread_mutex_unlock(&g_mem_lock);
    return p;
}

extern "C" void sp_cuda_free(void *ptr)
{
    if (!ptr) return;
    pthread_mutex_lock(&g_mem_lock);
    g_live -= tab_take(ptr);
    pthread_mutex_unlock(&g_mem_lock);
    cudaFree(ptr);
}

extern "C" size_t sp_cuda_peak_bytes(void)
{
    pthread_mutex_lock(&g_mem_lock);
    size_t p = g_peak;
    pthread_mutex_unlock(&g_mem_lock);
    return p;
}

static int copy(void *dst, const void *src, size_t bytes, cudaMemcpyKind kind, const char *what,
                sp_error *err)
{
    if (bytes == 0) return 0;
    if (!dst || !src) return sp_error_set(err, SP_E_ARG, "CUDA %s: NULL pointer", what);
    SP_CUDA_CHECK(cudaMemcpy(dst, src, bytes, kind), err, what);
    return 0;
}

extern "C" int sp_cuda_memcpy_h2d(void *dst, const void *src, size_t bytes, sp_error *err)
{
    return copy(dst, src, bytes, cudaMemcpyHostToDevice, "upload", err);
}
extern "C" int sp_cuda_memcpy_d2h(void *dst, const void *src, size_t bytes, sp_error *err)
{
    return copy(dst, src, bytes, cudaMemcpyDeviceToHost, "download", err);
}
extern "C" int sp_cuda_memcpy_d2d(void *dst, const void *src, size_t bytes, sp_error *err)
{
    return copy(dst, src, bytes, cudaMemcpyDeviceToDevice, "device copy", err);
}
extern "C" int sp_cuda_memset0(void *dst, size_t bytes, sp_error *err)
{
    if (bytes == 0) return 0;
    if (!dst) return sp_error_set(err, SP_E_ARG, "CUDA memset: NULL pointer");
    SP_CUDA_CHECK(cudaMemsetAsync(dst, 0, bytes), err, "memset");
    return 0;
}
extern "C" int sp_cuda_sync(sp_error *err)
{
    SP_CUDA_CHECK(cudaDeviceSynchronize(), err, "synchronize (a kernel failed)");
    return 0;
}

/* ---- scratch ------------------------------------------------------------------------------- */

int sp_cu_scratch_reserve(sp_cu_scratch *s, size_t bytes, sp_error *err)
{
    if (bytes <= s->cap && s->ptr) return 0;
    size_t cap = bytes + bytes / 4 + 256;
    sp_cuda_free(s->ptr);
    s->ptr = NULL;
    s->cap = 0;
    s->ptr = sp_cuda_malloc(cap, err);
    if (!s->ptr) return err ? err->code : SP_E_NOMEM;
    s->cap = cap;
    return 0;
}

void sp_cu_scratch_release(sp_cu_scratch *s)
{
    sp_cuda_free(s->ptr);
    s->ptr = NULL;
    s->cap = 0;
}

/* ---- raster object ------------------------------------------------------------------------- */

extern "C" int sp_cuda_raster_create(sp_cuda_raster **out, sp_error *err)
{
    if (!out) return sp_error_set(err, SP_E_ARG, "sp_cuda_raster_create: out is NULL");
    if (!sp_cuda_probe(NULL, 0))
        return sp_error_set(err, SP_E_NODEVICE, "no CUDA GPU answers (cudaGetDeviceCount)");
    sp_cuda_raster *r = (sp_cuda_raster *)calloc(1, sizeof(*r));
    if (!r) return sp_error_set(err, SP_E_NOMEM, "sp_cuda_raster_create: out of host memory");
    *out = r;
    return 0;
}

extern "C" void sp_cuda_raster_free(sp_cuda_raster *r)
{
    if (!r) return;
    sp_cu_scratch *all[] = {&r->s_means2d, &r->s_conic_op, &r->s_depths, &r->s_radii,
                         &r->s_rect, &r->s_ntiles, &r->s_offsets, &r->s_keys[0],
                         &r->s_keys[1], &r->s_vals[0], &r->s_vals[1], &r->s_tile_ranges,
                         &r->s_cub, &r->s_tfinal, &r->s_last, &r->s_bg,
                         &r->s_vgeo};
    for (size_t i = 0; i < sizeof(all) / sizeof(all[0]); i++) sp_cu_scratch_release(all[i]);
    free(r);
}

extern "C" const int32_t *sp_cuda_raster_radii(const sp_cuda_raster *r)
{
    return r && r->have_forward ? r->proj.radii : NULL;
}

extern "C" size_t sp_cuda_raster_last_pairs(const sp_cuda_raster *r)
{
    return r ? r->n_pairs : 0;
}
