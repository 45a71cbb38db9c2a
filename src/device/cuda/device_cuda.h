/* The CUDA device as the modules' CUDA code sees it (included from src/<module>/cuda/*.cu only):
 * every kernel launch, copy and cuBLAS call of a device goes to that device's own stream, so two
 * devices (or two threads with a device each) never share ordering or a handle. */
#ifndef SP_DEVICE_CUDA_H
#define SP_DEVICE_CUDA_H

#include <cublas_v2.h>
#include <cuda_runtime.h>

#include "device/device_impl.h"

#define SP_CUDA_CHECK(call, err, what)                                                        \
    do {                                                                                      \
        cudaError_t sp_e_ = (call);                                                           \
        if (sp_e_ != cudaSuccess)                                                             \
            return sp_error_set((err), SP_E_DEVICE, "CUDA %s: %s (%s)", (what),              \
                                cudaGetErrorString(sp_e_), cudaGetErrorName(sp_e_));         \
    } while (0)

/* Checks the last kernel launch (configuration errors show up here, faults at the next sync). */
#define SP_CUDA_LAUNCHED(err, what) SP_CUDA_CHECK(cudaGetLastError(), err, what)

/* The device's stream (dev must be a CUDA device). */
cudaStream_t sp_cuda_stream(const sp_device *dev);
/* The device's cuBLAS handle, bound to its stream; made on first use (NULL and err set when
 * cuBLAS cannot start). */
cublasHandle_t sp_cuda_blas(sp_device *dev, sp_error *err);

#endif
