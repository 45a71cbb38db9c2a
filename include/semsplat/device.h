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
/* Peak bytes allocated through sp_device_alloc plus the rasterizer's and CLIP's scratch and
 * weights on this device, since creation; and the bytes held now. Counted per device. */
size_t sp_device_peak_bytes(const sp_device *dev);
size_t sp_device_live_bytes(const sp_device *dev);

/* ---- what a device runs ----------------------------------------------------------------------- */

/* Pipeline stages a backend may implement. Callers ask sp_device_supports before choosing where
 * to run a stage (e.g. the query engine scores on the GPU when the device says so, else on the
 * host), instead of testing the build or the device kind. */
typedef enum {
    SP_STAGE_PROJECT = 0,    /* Gaussian projection to the image, forward and backward */
    SP_STAGE_RASTER_FWD,     /* compositing `channels` channels, forward */
    SP_STAGE_RASTER_BWD,     /* and backward */
    SP_STAGE_SH,             /* spherical harmonics -> RGB, forward and backward */
    SP_STAGE_TRAIN,          /* per-element training work: losses, Adam, densification statistics */
    SP_STAGE_CLIP_GEMM,      /* CLIP's matrix products */
    SP_STAGE_CLIP_ATTENTION, /* CLIP's attention; channels = width of one head */
    SP_STAGE_SEM_SCORE,      /* per-Gaussian relevancy of a text; channels = feature dim */
    SP_STAGE_COUNT
} sp_stage;

/* 1 when dev runs `stage` itself for `channels` channels (0 = the stage's natural width), else
 * 0 (an unknown stage, or a width the backend does not take: the caller falls back or refuses). */
int sp_device_supports(const sp_device *dev, sp_stage stage, int channels);
const char *sp_stage_name(sp_stage stage); /* "rasterize forward", ... */

/* Channel counts the compositing kernels are specialised for, on both backends: the one list,
 * which kernel dispatch, padding and the tests expand (X is a macro taking one width). On CUDA a
 * count not in the list is padded up to the next one (padded channels read zero and are never
 * written) and counts above SP_CHANNEL_CHUNK_MAX run as chunks of at most that width; the CPU
 * runs other counts with its generic loop. */
#define SP_CHANNEL_WIDTHS(X) X(1) X(2) X(3) X(4) X(8) X(12) X(16) X(24) X(32) X(40) X(48) X(64)
#define SP_CHANNEL_CHUNK_MAX 64 /* the widest specialised width */
#define SP_CHANNELS_MAX 4096    /* the most channels one raster call takes */
/* The smallest specialised width >= d, or max_width when that is smaller (max_width must be a
 * specialised width). */
int sp_channel_width(int d, int max_width);

#ifdef __cplusplus
}
#endif
#endif
