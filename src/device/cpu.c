/* The CPU device: host memory (a small header before each block remembers its size, so release
 * can account for it) and the worker pool; every stage runs here. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "device/device_impl.h"

/* 64 keeps sp_alloc's 64-byte alignment for the payload. */
#define HOST_HEADER 64

static void *cpu_alloc(sp_device *dev, size_t bytes, int zero, sp_error *err)
{
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
    if (zero) memset(p + HOST_HEADER, 0, bytes);
    memcpy(p, &bytes, sizeof bytes);
    sp_device_account(dev, (long long)bytes);
    return p + HOST_HEADER;
}

static void cpu_release(sp_device *dev, void *ptr)
{
    unsigned char *p = (unsigned char *)ptr - HOST_HEADER;
    size_t bytes;
    memcpy(&bytes, p, sizeof bytes);
    sp_device_account(dev, -(long long)bytes);
    sp_free(p);
}

static int cpu_upload(sp_device *dev, void *dst, const void *src, size_t bytes, sp_error *err)
{
    memcpy(dst, src, bytes);
    return 0;
}

static int cpu_copy(sp_device *dev, void *dst, const void *src, size_t bytes, sp_error *err)
{
    memmove(dst, src, bytes);
    return 0;
}

static int cpu_zero(sp_device *dev, void *dst, size_t bytes, sp_error *err)
{
    memset(dst, 0, bytes);
    return 0;
}

static int cpu_sync(sp_device *dev, sp_error *err) { return 0; }

static int cpu_supports(const sp_device *dev, sp_stage stage, int channels)
{
    switch (stage) {
    case SP_STAGE_RASTER_FWD:
    case SP_STAGE_RASTER_BWD: return channels <= SP_CHANNELS_MAX;
    case SP_STAGE_SH: return channels == 0 || channels == 3;
    case SP_STAGE_SEM_SCORE: return channels <= SP_FEATURE_DIM_MAX;
    default: return 1;
    }
}

static const sp_device_ops cpu_ops = {cpu_alloc, cpu_release, cpu_upload, cpu_upload, cpu_copy,
                                      cpu_zero, cpu_sync, cpu_supports, NULL};

int sp_device_cpu_open(sp_device *dev, sp_error *err)
{
    dev->ops = &cpu_ops;
    dev->ctx = NULL;
    int nt = sp_pool_size(dev->pool);
    snprintf(dev->name, sizeof dev->name, "CPU (%d thread%s)", nt, nt == 1 ? "" : "s");
    return 0;
}
