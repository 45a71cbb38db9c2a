/* fp32 -> fp16 on the host for the GPU's fp16 inputs (half the bytes over PCIe): the F16C
 * instruction where the CPU has it (checked at run time, so the build stays portable), else
 * sp_float_to_half; both round to nearest even, as the device's __float2half does. */
#include "clip_internal.h"
#include "semsplat/io.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <cpuid.h>
#include <immintrin.h>

__attribute__((target("avx,f16c"))) static void to_half_f16c(const float *src, uint16_t *dst, size_t n)
{
    size_t i = 0;
    for (; i + 8 <= n; i += 8)
        _mm_storeu_si128((__m128i *)(dst + i), _mm256_cvtps_ph(_mm256_loadu_ps(src + i), _MM_FROUND_TO_NEAREST_INT));
    for (; i < n; i++) dst[i] = sp_float_to_half(src[i]);
}

/* CPUID leaf 1: F16C (ecx 29), AVX (ecx 28), OSXSAVE (ecx 27); and the OS saves the YMM state
 * (XCR0 bits 1 and 2). Through cpuid.h and xgetbv, which GCC and clang both take. */
static int have_f16c(void)
{
    unsigned a, b, c, d, lo, hi;
    if (!__get_cpuid(1, &a, &b, &c, &d)) return 0;
    if (!(c & (1u << 29)) || !(c & (1u << 28)) || !(c & (1u << 27))) return 0;
    __asm__ volatile("xgetbv" : "=a"(lo), "=d"(hi) : "c"(0));
    (void)hi;
    return (lo & 6u) == 6u;
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
