/* The CUDA device: one GPU with its own non-blocking stream (every copy and kernel of the device
 * is ordered on it), a cuBLAS handle bound to that stream (made on first use), and per-device
 * memory accounting: a small open-addressing table pointer -> size, so sp_device_peak_bytes
 * reports what semsplat itself holds on this device (cudaMemGetInfo would also count the CUDA
 * context and other processes). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "device/cuda/device_cuda.h"

struct mem_entry {
    void *p;
    size_t n;
};

struct cuda_ctx {
    int ordinal;
    cudaStream_t stream;
    cublasHandle_t blas;
    pthread_mutex_t tab_lock;
    mem_entry *tab;
    size_t tab_cap, tab_used;
};

static cuda_ctx *ctx_of(const sp_device *dev) { return (cuda_ctx *)dev->ctx; }

cudaStream_t sp_cuda_stream(const sp_device *dev) { return ctx_of(dev)->stream; }

cublasHandle_t sp_cuda_blas(sp_device *dev, sp_error *err)
{
    cuda_ctx *c = ctx_of(dev);
    if (c->blas) return c->blas;
    cublasHandle_t h = NULL;
    cublasStatus_t s = cublasCreate(&h);
    if (s != CUBLAS_STATUS_SUCCESS) {
        sp_error_set(err, SP_E_DEVICE, "cuBLAS: cannot create a handle (status %d)", (int)s);
        return NULL;
    }
    if ((s = cublasSetStream(h, c->stream)) != CUBLAS_STATUS_SUCCESS) {
        cublasDestroy(h);
        sp_error_set(err, SP_E_DEVICE, "cuBLAS: cannot bind the device's stream (status %d)", (int)s);
        return NULL;
    }
    c->blas = h;
    return h;
}

/* ---- allocation table (lock held by callers) ---------------------------------------------- */

static size_t tab_slot(void *p, size_t cap)
{
    uintptr_t h = (uintptr_t)p >> 8;
    h ^= h >> 17;
    h *= 0x9E3779B97F4A7C15ull;
    return (size_t)(h & (cap - 1));
}

/* Inserts (p, n). Returns 0 or -1 when the table cannot grow. */
static int tab_put(cuda_ctx *c, void *p, size_t n)
{
    if ((c->tab_used + 1) * 2 > c->tab_cap) {
        size_t ncap = c->tab_cap ? c->tab_cap * 2 : 256;
        mem_entry *nt = (mem_entry *)calloc(ncap, sizeof(*nt));
        if (!nt) return -1;
        for (size_t i = 0; i < c->tab_cap; i++)
            if (c->tab[i].p) {
                size_t s = tab_slot(c->tab[i].p, ncap);
                while (nt[s].p) s = (s + 1) & (ncap - 1);
                nt[s] = c->tab[i];
            }
        free(c->tab);
        c->tab = nt;
        c->tab_cap = ncap;
    }
    size_t s = tab_slot(p, c->tab_cap);
    while (c->tab[s].p) s = (s + 1) & (c->tab_cap - 1);
    c->tab[s].p = p;
    c->tab[s].n = n;
    c->tab_used++;
    return 0;
}

/* Removes p and returns its size (0 when unknown). Backward-shift deletion keeps the probe
 * chains intact. */
static size_t tab_take(cuda_ctx *c, void *p)
{
    if (!c->tab_cap) return 0;
    mem_entry *t = c->tab;
    size_t mask = c->tab_cap - 1, s = tab_slot(p, c->tab_cap);
    while (t[s].p && t[s].p != p) s = (s + 1) & mask;
    if (!t[s].p) return 0;
    size_t n = t[s].n;
    t[s].p = NULL;
    c->tab_used--;
    size_t i = s, j = s;
    for (;;) {
        j = (j + 1) & mask;
        if (!t[j].p) break;
        size_t k = tab_slot(t[j].p, c->tab_cap);
        if ((j > i && (k <= i || k > j)) || (j < i && (k <= i && k > j))) {
            t[i] = t[j];
            t[j].p = NULL;
            i = j;
        }
    }
    return n;
}

/* ---- operations ---------------------------------------------------------------------------- */

static void *cu_alloc(sp_device *dev, size_t bytes, int zero, sp_error *err)
{
    cuda_ctx *c = ctx_of(dev);
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
    if (zero && (e = cudaMemsetAsync(p, 0, bytes, c->stream)) != cudaSuccess) {
        cudaFree(p);
        sp_error_set(err, SP_E_DEVICE, "CUDA memset of %zu bytes failed: %s", bytes,
                     cudaGetErrorString(e));
        return NULL;
    }
    pthread_mutex_lock(&c->tab_lock);
    int tracked = tab_put(c, p, bytes) == 0;
    pthread_mutex_unlock(&c->tab_lock);
    if (tracked) sp_device_account(dev, (long long)bytes);
    return p;
}

static void cu_release(sp_device *dev, void *ptr)
{
    cuda_ctx *c = ctx_of(dev);
    pthread_mutex_lock(&c->tab_lock);
    size_t n = tab_take(c, ptr);
    pthread_mutex_unlock(&c->tab_lock);
    sp_device_account(dev, -(long long)n);
    cudaFree(ptr); /* synchronises with the device, so no kernel still uses the block */
}

static int cu_copy_kind(sp_device *dev, void *dst, const void *src, size_t bytes,
                        cudaMemcpyKind kind, const char *what, sp_error *err)
{
    cudaStream_t st = ctx_of(dev)->stream;
    SP_CUDA_CHECK(cudaMemcpyAsync(dst, src, bytes, kind, st), err, what);
    /* uploads and downloads return when the host buffer may be reused / holds the bytes, also
     * for pinned buffers (as the synchronous copies they replace did) */
    if (kind != cudaMemcpyDeviceToDevice) SP_CUDA_CHECK(cudaStreamSynchronize(st), err, what);
    return 0;
}

static int cu_upload(sp_device *dev, void *dst, const void *src, size_t bytes, sp_error *err)
{
    return cu_copy_kind(dev, dst, src, bytes, cudaMemcpyHostToDevice, "upload", err);
}
static int cu_download(sp_device *dev, void *dst, const void *src, size_t bytes, sp_error *err)
{
    return cu_copy_kind(dev, dst, src, bytes, cudaMemcpyDeviceToHost, "download", err);
}
static int cu_copy(sp_device *dev, void *dst, const void *src, size_t bytes, sp_error *err)
{
    return cu_copy_kind(dev, dst, src, bytes, cudaMemcpyDeviceToDevice, "device copy", err);
}
static int cu_zero(sp_device *dev, void *dst, size_t bytes, sp_error *err)
{
    SP_CUDA_CHECK(cudaMemsetAsync(dst, 0, bytes, ctx_of(dev)->stream), err, "memset");
    return 0;
}
static int cu_sync(sp_device *dev, sp_error *err)
{
    SP_CUDA_CHECK(cudaStreamSynchronize(ctx_of(dev)->stream), err, "synchronize (a kernel failed)");
    return 0;
}

static int cu_supports(const sp_device *dev, sp_stage stage, int channels)
{
    switch (stage) {
    case SP_STAGE_RASTER_FWD:
    case SP_STAGE_RASTER_BWD: return channels <= SP_CHANNELS_MAX; /* padded, then chunked */
    case SP_STAGE_SH: return channels == 0 || channels == 3;
    /* the scorer's query, mean and negatives projections travel as one kernel argument */
    case SP_STAGE_SEM_SCORE: return channels <= SP_FEATURE_DIM_MAX;
    default: return 1;
    }
}

static void cu_destroy(sp_device *dev)
{
    cuda_ctx *c = ctx_of(dev);
    if (!c) return;
    if (c->blas) cublasDestroy(c->blas);
    if (c->stream) {
        cudaStreamSynchronize(c->stream);
        cudaStreamDestroy(c->stream);
    }
    pthread_mutex_destroy(&c->tab_lock);
    free(c->tab);
    free(c);
    dev->ctx = NULL;
}

static const sp_device_ops cuda_ops = {cu_alloc, cu_release, cu_upload, cu_download, cu_copy,
                                       cu_zero, cu_sync, cu_supports, cu_destroy};

extern "C" int sp_device_cuda_probe(char *name, size_t cap)
{
    int count = 0;
    if (name && cap) name[0] = 0;
    if (cudaGetDeviceCount(&count) != cudaSuccess || count <= 0) {
        cudaGetLastError(); /* clear the sticky "no device" status */
        return 0;
    }
    cudaDeviceProp prop;
    if (cudaGetDeviceProperties(&prop, 0) != cudaSuccess) return 0;
    if (name && cap) snprintf(name, cap, "%s", prop.name);
    return 1;
}

extern "C" int sp_device_cuda_open(sp_device *dev, sp_error *err)
{
    char name[128];
    if (!sp_device_cuda_probe(name, sizeof name))
        return sp_error_set(err, SP_E_NODEVICE, "device cuda: no GPU answers (CUDA backend built, "
                                                "but no usable device)");
    cuda_ctx *c = (cuda_ctx *)calloc(1, sizeof *c);
    if (!c) return sp_error_set(err, SP_E_NOMEM, "device cuda: out of host memory");
    c->ordinal = 0;
    pthread_mutex_init(&c->tab_lock, NULL);
    cudaError_t e = cudaSetDevice(c->ordinal);
    if (e == cudaSuccess) e = cudaStreamCreateWithFlags(&c->stream, cudaStreamNonBlocking);
    if (e != cudaSuccess) {
        pthread_mutex_destroy(&c->tab_lock);
        free(c);
        return sp_error_set(err, SP_E_DEVICE, "device cuda: cannot start GPU 0 (%s)",
                            cudaGetErrorString(e));
    }
    dev->ops = &cuda_ops;
    dev->ctx = c;
    snprintf(dev->name, sizeof dev->name, "%s", name);
    return 0;
}
