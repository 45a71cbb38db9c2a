/* The device seam as backend implementers see it (ggml-backend-impl.h style): an sp_device is a
 * table of operations plus the backend's own context. src/device/ implements the CPU table
 * (cpu.c) and the CUDA table (cuda/device_cuda.cu; nocuda/ stands in when nvcc is absent);
 * modules with their own kernels (render, train, clip, semantic) include this header to reach the
 * device's pool or, from their cuda/ folders, device/cuda/device_cuda.h for its stream and cuBLAS
 * handle. Nothing outside src/ sees it. */
#ifndef SP_DEVICE_IMPL_H
#define SP_DEVICE_IMPL_H

#include <pthread.h>

#include "semsplat/device.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sp_device_ops {
    /* zero: clear the block (sp_device_alloc does; scratch that is overwritten need not) */
    void *(*alloc)(sp_device *dev, size_t bytes, int zero, sp_error *err);
    void (*release)(sp_device *dev, void *ptr);
    int (*upload)(sp_device *dev, void *dst, const void *src_host, size_t bytes, sp_error *err);
    /* returns when the bytes are in host memory */
    int (*download)(sp_device *dev, void *dst_host, const void *src, size_t bytes, sp_error *err);
    int (*copy)(sp_device *dev, void *dst, const void *src, size_t bytes, sp_error *err);
    int (*zero)(sp_device *dev, void *dst, size_t bytes, sp_error *err);
    int (*sync)(sp_device *dev, sp_error *err);
    int (*supports)(const sp_device *dev, sp_stage stage, int channels);
    void (*destroy)(sp_device *dev); /* releases ctx */
} sp_device_ops;

struct sp_device {
    const sp_device_ops *ops;
    void *ctx;           /* the backend's state (CUDA: stream, cuBLAS handle, allocation table) */
    sp_device_kind kind; /* CPU or CUDA, never AUTO after creation */
    sp_pool *pool;       /* host workers (CPU kernels; host-side work of a CUDA device) */
    char name[160];
    pthread_mutex_t mem_lock; /* guards the two counters below */
    size_t live_bytes, peak_bytes;
};

/* Records an allocation (delta > 0) or release (delta < 0) of device memory for
 * sp_device_peak_bytes. Thread safe. */
void sp_device_account(sp_device *dev, long long delta);

/* Device memory that need not be zeroed (scratch about to be overwritten); accounted like
 * sp_device_alloc. Release with sp_device_release. */
void *sp_device_alloc_scratch(sp_device *dev, size_t bytes, sp_error *err);

/* Grow-only scratch on a device: ensures *buf holds at least `bytes` (contents are NOT kept when
 * it grows; it grows by 1/16 more than asked, so slowly growing sizes do not reallocate every
 * call, while the slack, which counts in the device's peak memory, stays small). */
typedef struct sp_device_scratch {
    void *ptr;
    size_t cap;
} sp_device_scratch;
int sp_device_scratch_reserve(sp_device *dev, sp_device_scratch *s, size_t bytes, sp_error *err);
void sp_device_scratch_release(sp_device *dev, sp_device_scratch *s);

/* Backends: fill dev->ops, dev->ctx and dev->name (the kind and pool are set by the caller).
 * The CUDA one fails with SP_E_NODEVICE when no GPU answers or the build has no CUDA. */
int sp_device_cpu_open(sp_device *dev, sp_error *err);
int sp_device_cuda_open(sp_device *dev, sp_error *err);
/* 1 when the CUDA backend is built and a GPU answers (name filled when not NULL). */
int sp_device_cuda_probe(char *name, size_t cap);

#ifdef __cplusplus
}
#endif
#endif
