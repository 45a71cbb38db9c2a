/* The PCA's covariance on the GPU: (X - mean)^T (X - mean) over the sampled features, chunk by
 * chunk (centred on the device, summed by cuBLAS SGEMM in fp32: the same arithmetic as the CPU
 * path's float SGEMM, about 13 GFLOP for 50,000 samples of 512). */
#include "clip_gpu.cuh"

__global__ void k_center(float *x, size_t total, int F, const float *mean)
{
    for (size_t i = blockIdx.x * (size_t)blockDim.x + threadIdx.x; i < total; i += (size_t)gridDim.x * blockDim.x)
        x[i] -= mean[i % F];
}

extern "C" int clip_gpu_gram(sp_device *dev, const float *x, size_t n, int F, const float *mean, float *C, sp_error *err)
{
    cudaStream_t st = sp_cuda_stream(dev);
    cublasHandle_t h = sp_cuda_blas(dev, err);
    if (!h) return sp_error_prefix(err, "PCA on the GPU: ");
    size_t chunk = ((size_t)64 << 20) / ((size_t)F * sizeof(float));
    if (chunk < 1) chunk = 1;
    if (chunk > n) chunk = n;
    size_t bytes = (chunk * F + F + (size_t)F * F) * sizeof(float);
    float *dx = (float *)sp_device_alloc_scratch(dev, bytes, err), *dm = dx + chunk * F, *dc = dm + F;
    if (!dx) return sp_error_prefix(err, "PCA on the GPU: ");
    int rc = 0;
    if (cudaMemcpyAsync(dm, mean, F * sizeof(float), cudaMemcpyHostToDevice, st) != cudaSuccess)
        rc = sp_error_set(err, SP_E_DEVICE, "PCA on the GPU: upload failed");
    for (size_t i0 = 0; i0 < n && !rc; i0 += chunk) {
        size_t nb = n - i0 < chunk ? n - i0 : chunk;
        float one = 1.f, beta = i0 ? 1.f : 0.f;
        if (cudaMemcpyAsync(dx, x + i0 * F, nb * F * sizeof(float), cudaMemcpyHostToDevice, st) != cudaSuccess) {
            rc = sp_error_set(err, SP_E_DEVICE, "PCA on the GPU: upload failed");
            break;
        }
        k_center<<<1024, 256, 0, st>>>(dx, nb * F, F, dm);
        /* column-major: the F x F result of X^T X is (F x nb) (nb x F) */
        if (cublasSgemm(h, CUBLAS_OP_N, CUBLAS_OP_T, F, F, (int)nb, &one, dx, F, dx, F, &beta, dc, F) !=
            CUBLAS_STATUS_SUCCESS)
            rc = sp_error_set(err, SP_E_DEVICE, "PCA on the GPU: cuBLAS SGEMM failed");
    }
    if (!rc && (cudaMemcpyAsync(C, dc, (size_t)F * F * sizeof(float), cudaMemcpyDeviceToHost, st) != cudaSuccess ||
                cudaStreamSynchronize(st) != cudaSuccess))
        rc = sp_error_set(err, SP_E_DEVICE, "PCA on the GPU: %s", cudaGetErrorString(cudaGetLastError()));
    sp_device_release(dev, dx);
    return rc;
}
