/* For the minimal GPU-machine build only (tests/clip/device_check.sh): the few sp_device calls the
 * clip tests use, without the render module (whose CPU code needs the full build's flags). */
#include <stdlib.h>

#include <cuda_runtime_api.h>

#include "semsplat/render.h"

struct sp_device {
    sp_device_kind kind;
    sp_pool *pool;
};

int sp_cuda_available(void)
{
    int n = 0;
    return cudaGetDeviceCount(&n) == cudaSuccess && n > 0;
}

int sp_device_create(sp_device **out, sp_device_kind kind, int n_threads, sp_error *err)
{
    sp_device *d = calloc(1, sizeof *d);
    if (!d) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    if (kind == SP_DEVICE_AUTO) kind = sp_cuda_available() ? SP_DEVICE_CUDA : SP_DEVICE_CPU;
    if (kind == SP_DEVICE_CUDA && !sp_cuda_available()) {
        free(d);
        return sp_error_set(err, SP_E_NODEVICE, "no GPU");
    }
    d->kind = kind;
    if (sp_pool_create(&d->pool, n_threads, err)) {
        free(d);
        return err ? err->code : SP_E_NOMEM;
    }
    *out = d;
    return 0;
}

void sp_device_free(sp_device *d)
{
    if (!d) return;
    sp_pool_free(d->pool);
    free(d);
}

sp_device_kind sp_device_kind_of(const sp_device *d) { return d->kind; }
sp_pool *sp_device_pool(sp_device *d) { return d->pool; }
const char *sp_device_name(const sp_device *d) { return d->kind == SP_DEVICE_CUDA ? "GPU (minimal build)" : "CPU"; }
