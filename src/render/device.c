/* sp_device: where raster buffers live. CPU = host memory plus a worker pool; CUDA = one GPU
 * through the seam in cuda_api.h (compiled only with SP_HAVE_CUDA); AUTO picks CUDA when a GPU
 * answers. The CPU kind tracks live and peak bytes itself (a small header before each block
 * remembers its size), the CUDA kind asks the backend. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render/render_internal.h"
#ifdef SP_HAVE_CUDA
#include "render/cuda_api.h"
#endif

/* Host blocks carry their size in front so release can account for it; 64 keeps sp_alloc's
 * 64-byte alignment for the payload. */
#define HOST_HEADER 64

int sp_cuda_available(void)
{
#ifdef SP_HAVE_CUDA
    char name[128];
    return sp_cuda_probe(name, sizeof name);
#else
    return 0;
#endif
}

int sp_device_create(sp_device **out, sp_device_kind kind, int n_threads, sp_error *err)
{
    *out = NULL;
    if (kind != SP_DEVICE_CPU && kind != SP_DEVICE_CUDA && kind != SP_DEVICE_AUTO)
        return sp_error_set(err, SP_E_ARG, "sp_device_create: unknown device kind %d", (int)kind);
    char gpu_name[128] = "";
    int have_gpu = 0;
#ifdef SP_HAVE_CUDA
    if (kind != SP_DEVICE_CPU) have_gpu = sp_cuda_probe(gpu_name, sizeof gpu_name);
#endif
    if (kind == SP_DEVICE_CUDA && !have_gpu) {
#ifdef SP_HAVE_CUDA
        return sp_error_set(err, SP_E_NODEVICE, "device cuda: no GPU answers (CUDA backend built, "
                                                "but no usable device)");
#else
        return sp_error_set(err, SP_E_NODEVICE,
                            "device cuda: this build has no CUDA backend (nvcc not found or -DSP_CUDA=OFF)");
#endif
    }
    sp_device *d = calloc(1, sizeof *d);
    if (!d) return sp_error_set(err, SP_E_NOMEM, "sp_device_create: out of memory");
    d->kind = have_gpu ? SP_DEVICE_CUDA : SP_DEVICE_CPU;
    int rc = sp_pool_create(&d->pool, n_threads, err);
    if (rc) {
        free(d);
        return rc;
    }
    if (d->kind == SP_DEVICE_CUDA)
        snprintf(d->name, sizeof d->name, "%s", gpu_name);
    else
        snprintf(d->name, sizeof d->name, "CPU (%d thread%s)", sp_pool_size(d->pool),
                 sp_pool_size(d->pool) == 1 ? "" : "s");
    *out = d;
    return 0;
}

void sp_device_free(sp_device *dev)
{
    if (!dev) return;
    sp_pool_free(dev->pool);
    free(dev);
}

sp_device_kind sp_device_kind_of(const sp_device *dev) { return dev->kind; }
const char *sp_device_name(const sp_device *dev) { return dev->name; }
sp_pool *sp_device_pool(sp_device *dev) { return dev->pool; }

void sp_device_account(sp_device *dev, long long delta)
{
    if (!dev) return;
    if (delta < 0 && (size_t)(-delta) > dev->cur_bytes)
        dev->cur_bytes = 0;
    else
        dev->cur_bytes = (size_t)((long long)dev->cur_bytes + delta);
    if (dev->cur_bytes > dev->peak_bytes) dev->peak_bytes = dev->cur_bytes;
}

int sp_scratch_reserve(sp_device *dev, void **buf, size_t *cap, size_t bytes, sp_error *err)
{
    if (bytes <= *cap && *buf) return 0;
    size_t want = bytes + bytes / 4 + 256; /* headroom: views of similar size reuse the block */
    void *p = sp_alloc(want);
    if (!p) return sp_error_set(err, SP_E_NOMEM, "rasterizer scratch: cannot allocate %zu bytes", want);
    sp_free(*buf);
    sp_device_account(dev, (long long)want - (long long)*cap);
    *buf = p;
    *cap = want;
    return 0;
}

void sp_scratch_release(sp_device *dev, void **buf, size_t *cap)
{
    sp_free(*buf);
    sp_device_account(dev, -(long long)*cap);
    *buf = NULL;
    *cap = 0;
}

void *sp_device_alloc(sp_device *dev, size_t bytes, sp_error *err)
{
    if (bytes == 0) bytes = 1;
#ifdef SP_HAVE_CUDA
    if (dev->kind == SP_DEVICE_CUDA) return sp_cuda_malloc(bytes, err);
#endif
    if (bytes > SIZE_MAX - HOST_HEADER) {
        sp_error_set(err, SP_E_NOMEM, "sp_device_alloc: %zu bytes is too large", bytes);
        return NULL;
    }
    unsigned char *p = sp_alloc(bytes + HOST_HEADER);
    if (!p) {
        sp_error_set(err, SP_E_NOMEM, "sp_device_alloc: cannot allocate %zu bytes on %s", bytes,
                     dev->name);
        return NULL;
    }
    memset(p, 0, bytes + HOST_HEADER);
    memcpy(p, &bytes, sizeof bytes);
    sp_device_account(dev, (long long)bytes);
    return p + HOST_HEADER;
}

void sp_device_release(sp_device *dev, void *ptr)
{
    if (!ptr) return;
#ifdef SP_HAVE_CUDA
    if (dev->kind == SP_DEVICE_CUDA) {
        sp_cuda_free(ptr);
        return;
    }
#endif
    unsigned char *p = (unsigned char *)ptr - HOST_HEADER;
    size_t bytes;
    memcpy(&bytes, p, sizeof bytes);
    sp_device_account(dev, -(long long)bytes);
    sp_free(p);
}

int sp_device_upload(sp_device *dev, void *dst, const void *src_host, size_t bytes, sp_error *err)
{
    if (bytes == 0) return 0;
    if (!dst || !src_host) return sp_error_set(err, SP_E_ARG, "sp_device_upload: NULL buffer");
#ifdef SP_HAVE_CUDA
    if (dev->kind == SP_DEVICE_CUDA) return sp_cuda_memcpy_h2d(dst, src_host, bytes, err);
#endif
    memcpy(dst, src_host, bytes);
    return 0;
}

int sp_device_download(sp_device *dev, void *dst_host, const void *src, size_t bytes, sp_error *err)
{
    if (bytes == 0) return 0;
    if (!dst_host || !src) return sp_error_set(err, SP_E_ARG, "sp_device_download: NULL buffer");
#ifdef SP_HAVE_CUDA
    if (dev->kind == SP_DEVICE_CUDA) return sp_cuda_memcpy_d2h(dst_host, src, bytes, err);
#endif
    memcpy(dst_host, src, bytes);
    return 0;
}

int sp_device_copy(sp_device *dev, void *dst, const void *src, size_t bytes, sp_error *err)
{
    if (bytes == 0) return 0;
    if (!dst || !src) return sp_error_set(err, SP_E_ARG, "sp_device_copy: NULL buffer");
#ifdef SP_HAVE_CUDA
    if (dev->kind == SP_DEVICE_CUDA) return sp_cuda_memcpy_d2d(dst, src, bytes, err);
#endif
    memmove(dst, src, bytes);
    return 0;
}

int sp_device_zero(sp_device *dev, void *dst, size_t bytes, sp_error *err)
{
    if (bytes == 0) return 0;
    if (!dst) return sp_error_set(err, SP_E_ARG, "sp_device_zero: NULL buffer");
#ifdef SP_HAVE_CUDA
    if (dev->kind == SP_DEVICE_CUDA) return sp_cuda_memset0(dst, bytes, err);
#endif
    memset(dst, 0, bytes);
    return 0;
}

int sp_device_sync(sp_device *dev, sp_error *err)
{
#ifdef SP_HAVE_CUDA
    if (dev->kind == SP_DEVICE_CUDA) return sp_cuda_sync(err);
#endif
    (void)dev;
    (void)err;
    return 0;
}

size_t sp_device_peak_bytes(const sp_device *dev)
{
#ifdef SP_HAVE_CUDA
    if (dev->kind == SP_DEVICE_CUDA) return sp_cuda_peak_bytes();
#endif
    return dev->peak_bytes;
}
