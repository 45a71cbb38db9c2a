/* Built when nvcc is absent: the CUDA device does not exist. */
#include "device/device_impl.h"

int sp_device_cuda_probe(char *name, size_t cap)
{
    if (name && cap) name[0] = 0;
    return 0;
}

int sp_device_cuda_open(sp_device *dev, sp_error *err)
{
    return sp_error_set(err, SP_E_NODEVICE,
                        "device cuda: this build has no CUDA backend (nvcc not found or -DSP_CUDA=OFF)");
}
