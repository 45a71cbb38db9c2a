/* sp_device: creation (CPU, CUDA, or AUTO = CUDA when a GPU answers), the public buffer calls,
 * which dispatch through the device's table of operations (device_impl.h), per-device memory
 * accounting, and the supports() query. */
#include <stdlib.h>
#include <string.h>

#include "device/device_impl.h"

int sp_cuda_available(void) { return sp_device_cuda_probe(NULL, 0); }

int sp_device_create(sp_device **out, sp_device_kind kind, int n_threads, sp_error *err)
{
    *out = NULL;
    if (kind != SP_DEVICE_CPU && kind != SP_DEVICE_CUDA && kind != SP_DEVICE_AUTO)
        return sp_error_set(err, SP_E_ARG, "sp_device_create: unknown device kind %d", (int)kind);
    if (kind == SP_DEVICE_AUTO) kind = sp_device_cuda_probe(NULL, 0) ? SP_DEVICE_CUDA : SP_DEVICE_CPU;
    sp_device *d = calloc(1, sizeof *d);
    if (!d) return sp_error_set(err, SP_E_NOMEM, "sp_device_create: out of memory");
    d->kind = kind;
    pthread_mutex_init(&d->mem_lock, NULL);
    int rc = sp_pool_create(&d->pool, n_threads, err);
    if (!rc) rc = kind == SP_DEVICE_CUDA ? sp_device_cuda_open(d, err) : sp_device_cpu_open(d, err);
    if (rc) {
        sp_pool_free(d->pool);
        pthread_mutex_destroy(&d->mem_lock);
        free(d);
        return rc;
    }
    *out = d;
    return 0;
}

void sp_device_free(sp_device *dev)
{
    if (!dev) return;
    if (dev->ops && dev->ops->destroy) dev->ops->destroy(dev);
    sp_pool_free(dev->pool);
    pthread_mutex_destroy(&dev->mem_lock);
    free(dev);
}

sp_device_kind sp_device_kind_of(const sp_device *dev) { return dev->kind; }
const char *sp_device_name(const sp_device *dev) { return dev->name; }
sp_pool *sp_device_pool(sp_device *dev) { return dev->pool; }

void sp_device_account(sp_device *dev, long long delta)
{
    if (!dev) return;
    pthread_mutex_lock(&dev->mem_lock);
    if (delta < 0 && (size_t)(-delta) > dev->live_bytes)
        dev->live_bytes = 0;
    else
        dev->live_bytes = (size_t)((long long)dev->live_bytes + delta);
    if (dev->live_bytes > dev->peak_bytes) dev->peak_bytes = dev->live_bytes;
    pthread_mutex_unlock(&dev->mem_lock);
}

static size_t read_counter(const sp_device *dev, int peak)
{
    sp_device *d = (sp_device *)dev; /* the lock is not part of the device's logical state */
    pthread_mutex_lock(&d->mem_lock);
    size_t v = peak ? d->peak_bytes : d->live_bytes;
    pthread_mutex_unlock(&d->mem_lock);
    return v;
}

size_t sp_device_peak_bytes(const sp_device *dev) { return read_counter(dev, 1); }
size_t sp_device_live_bytes(const sp_device *dev) { return read_counter(dev, 0); }

void *sp_device_alloc(sp_device *dev, size_t bytes, sp_error *err)
{
    return dev->ops->alloc(dev, bytes ? bytes : 1, 1, err);
}

void *sp_device_alloc_scratch(sp_device *dev, size_t bytes, sp_error *err)
{
    return dev->ops->alloc(dev, bytes ? bytes : 1, 0, err);
}

void sp_device_release(sp_device *dev, void *ptr)
{
    if (ptr) dev->ops->release(dev, ptr);
}

int sp_device_upload(sp_device *dev, void *dst, const void *src_host, size_t bytes, sp_error *err)
{
    if (bytes == 0) return 0;
    if (!dst || !src_host) return sp_error_set(err, SP_E_ARG, "sp_device_upload: NULL buffer");
    return dev->ops->upload(dev, dst, src_host, bytes, err);
}

int sp_device_download(sp_device *dev, void *dst_host, const void *src, size_t bytes, sp_error *err)
{
    if (bytes == 0) return 0;
    if (!dst_host || !src) return sp_error_set(err, SP_E_ARG, "sp_device_download: NULL buffer");
    return dev->ops->download(dev, dst_host, src, bytes, err);
}

int sp_device_copy(sp_device *dev, void *dst, const void *src, size_t bytes, sp_error *err)
{
    if (bytes == 0) return 0;
    if (!dst || !src) return sp_error_set(err, SP_E_ARG, "sp_device_copy: NULL buffer");
    return dev->ops->copy(dev, dst, src, bytes, err);
}

int sp_device_zero(sp_device *dev, void *dst, size_t bytes, sp_error *err)
{
    if (bytes == 0) return 0;
    if (!dst) return sp_error_set(err, SP_E_ARG, "sp_device_zero: NULL buffer");
    return dev->ops->zero(dev, dst, bytes, err);
}

int sp_device_sync(sp_device *dev, sp_error *err) { return dev->ops->sync(dev, err); }

int sp_device_supports(const sp_device *dev, sp_stage stage, int channels)
{
    if (!dev || (unsigned)stage >= SP_STAGE_COUNT || channels < 0) return 0;
    return dev->ops->supports(dev, stage, channels);
}

const char *sp_stage_name(sp_stage stage)
{
    static const char *const names[SP_STAGE_COUNT] = {
        "projection", "rasterize forward", "rasterize backward", "spherical harmonics",
        "training step", "CLIP matrix products", "CLIP attention", "semantic scoring"};
    return (unsigned)stage < SP_STAGE_COUNT ? names[stage] : "unknown stage";
}

int sp_channel_width(int d, int max_width)
{
#define SP_WIDTH_TRY(w) if ((w) >= d || (w) >= max_width) return (w) < max_width ? (w) : max_width;
    SP_CHANNEL_WIDTHS(SP_WIDTH_TRY)
#undef SP_WIDTH_TRY
    return max_width;
}

int sp_device_scratch_reserve(sp_device *dev, sp_device_scratch *s, size_t bytes, sp_error *err)
{
    if (bytes <= s->cap && s->ptr) return 0;
    size_t cap = bytes + bytes / 16 + 256;
    sp_device_release(dev, s->ptr);
    s->ptr = NULL;
    s->cap = 0;
    s->ptr = sp_device_alloc_scratch(dev, cap, err);
    if (!s->ptr) return err && err->code ? err->code : SP_E_NOMEM;
    s->cap = cap;
    return 0;
}

void sp_device_scratch_release(sp_device *dev, sp_device_scratch *s)
{
    sp_device_release(dev, s->ptr);
    s->ptr = NULL;
    s->cap = 0;
}
