/* fp32 -> fp16 on the host for the GPU's fp16 inputs (half the bytes over PCIe): the F16C
 * instruction where the CPU has it (checked at run time, so the build stays portable), else
 * sp_float_to_half; both round to nearest even, as the device's __float2half does. */
#include "clip_internal.h"
#include "semsplat/io.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>

__attribute__((target("avx,f16c"))) static void to_half_f16c(const float *src, uint16_t *dst, size_t n)
{
    size_t i = 0;
    for (; i + 8 <= n; i += 8)
        _mm_storeu_si128((__m128i *)(dst + i), _mm256_cvtps_ph(_mm256_loadu_ps(src + i), _MM_FROUND_TO_NEAREST_INT));
    for (; i < n; i++) dst[i] = sp_float_to_half(src[i]);
}

static int have_f16c(void)
{
    __builtin_cpu_init();
    return __builtin_cpu_supports("f16c") && __builtin_cpu_supports("avx");
}
#else
static void to_half_f16c(const float *src, uint16_t *dst, size_t n)
{
    for (size_t i = 0; i < n; i++) dst[i] = sp_float_to_half(src[i]);
}
static int have_f16c(void) { return 0; }
#endif

void clip_floats_to_half(const float *src, uint16_t *dst, size_t n)
{
    if (have_f16c()) {
        to_half_f16c(src, dst, n);
        return;
    }
    for (size_t i = 0; i < n; i++) dst[i] = sp_float_to_half(src[i]);
}
