/* semsplat device: the backend seam. An sp_device is where buffers live and kernels run: the CPU
 * (host memory and a worker pool) or one CUDA GPU (device memory, its own stream and cuBLAS
 * handle, and its own memory accounting). Every module that computes (render, train, clip,
 * semantic) takes an sp_device and asks it, through sp_device_supports, whether a stage runs
 * there; buffers are moved with sp_device_alloc / upload / download.
 *
 * Ownership: sp_device_create makes the device, sp_device_free releases it (after every buffer
 * and every object created on it, such as an sp_raster or an sp_clip, has been freed). Buffers
 * from sp_device_alloc belong to the caller until sp_device_release.
 *
 * Threads: one device may be used from one thread at a time (the CUDA stream orders its work);
 * give each thread its own device. sp_device_create itself is thread safe. */
#ifndef SEMSPLAT_DEVICE_H
#define SEMSPLAT_DEVICE_H

#include "semsplat/core.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    SP_DEVICE_CPU = 0,
    SP_DEVICE_CUDA = 1,
    SP_DEVICE_AUTO = 2 /* CUDA when a GPU is usable, else CPU */
} sp_device_kind;

/* Parses a device name: exactly "cpu", "cuda" or "auto" (lower case). Anything else fails with
 * SP_E_ARG and a message naming the value and the accepted ones; *out is unchanged on error. */
int sp_device_kind_parse(const char *s, sp_device_kind *out, sp_error *err);
/* "cpu", "cuda" or "auto". */
const char *sp_device_kind_name(sp_device_kind kind);

typedef struct sp_device sp_device;

/* n_threads: CPU worker threads (<= 0: all cores). CUDA: fails with SP_E_NODEVICE when the
 * backend is not built or no GPU is present. */
int sp_device_create(sp_device **out, sp_device_kind kind, int n_threads, sp_error *err);
void sp_device_free(sp_device *dev);
sp_device_kind sp_device_kind_of(const sp_device *dev);
const char *sp_device_name(const sp_device *dev); /* "CPU (2 threads)", "NVIDIA H100 ..." */
sp_pool *sp_device_pool(sp_device *dev);          /* CPU worker pool (also used by CUDA for host work) */
int sp_cuda_available(void);                       /* 1 when the CUDA backend is built and a GPU answers */

void *sp_device_alloc(sp_device *dev, size_t bytes, sp_error *err); /* zeroed; NULL on error */
void sp_device_release(sp_device *dev, void *ptr);
int sp_device_upload(sp_device *dev, void *dst, const void *src_host, size_t bytes, sp_error *err);
int sp_device_download(sp_device *dev, void *dst_host, const void *src, size_t bytes, sp_error *err);
int sp_device_copy(sp_device *dev, void *dst, const void *src, size_t bytes, sp_error *err);
int sp_device_zero(sp_device *dev, void *dst, size_t bytes, sp_error *err);
int sp_device_sync(sp_device *dev, sp_error *err);
/* Peak bytes allocated through sp_device_alloc plus the rasterizer's scratch, since creation. */
size_t sp_device_peak_bytes(const sp_device *dev);

#ifdef __cplusplus
}
#endif
#endif
