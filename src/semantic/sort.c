/* Stable radix sort of (64-bit key, index) pairs for the clustering (voxel keys of every
 * back-projected point, then coordinates per instance): linear in the count where qsort with a
 * comparator callback was most of the clustering's time. Only the span of bits that differ
 * between keys is sorted, in as few digits as cover it (a 24-bit dense voxel key of a long list:
 * 2 passes rather than 3 bytes). A stable sort's output is fixed by the keys, so the digit
 * width changes nothing but the time. */
#include <stdlib.h>
#include <string.h>

#include "sem_internal.h"

/* Digits of up to 12 bits (a 4096-entry histogram each) for long lists, 8 for short ones where
 * clearing and summing the histograms would cost more than a pass. */
#define SMALL_LIST 4096
#define STACK_COUNTS 2048 /* 8 passes of 8 bits: every short list, and a fallback */

void sem_sort_keyed(sem_keyed *a, sem_keyed *tmp, size_t m)
{
    if (m < 2) return;
    uint64_t diff = 0, k0 = a[0].key;
    for (size_t i = 0; i < m; i++) diff |= a[i].key ^ k0;
    if (!diff) return;
    int lo = __builtin_ctzll(diff), hi = 63 - __builtin_clzll(diff);
    int span = hi - lo + 1, digit_max = m < SMALL_LIST ? 8 : 12;
    size_t stack_cnt[STACK_COUNTS], *cnt = stack_cnt;
    int passes = (span + digit_max - 1) / digit_max, width = (span + passes - 1) / passes;
    if ((size_t)passes << width > STACK_COUNTS) {
        cnt = calloc((size_t)passes << width, sizeof *cnt);
        if (!cnt) { /* out of memory: bytes, as ever */
            cnt = stack_cnt;
            passes = (span + 7) / 8, width = (span + passes - 1) / passes;
        }
    }
    if (cnt == stack_cnt) memset(cnt, 0, sizeof *cnt * ((size_t)passes << width));
    const size_t nb = (size_t)1 << width;
    const uint64_t dmask = nb - 1;
    for (size_t i = 0; i < m; i++) {
        uint64_t k = a[i].key >> lo;
        for (int p = 0; p < passes; p++) cnt[p * nb + ((k >> (width * p)) & dmask)]++;
    }
    sem_keyed *src = a, *dst = tmp;
    for (int p = 0; p < passes; p++) {
        size_t sum = 0, *c = cnt + p * nb;
        for (size_t v = 0; v < nb; v++) {
            size_t n = c[v];
            c[v] = sum;
            sum += n;
        }
        const int shift = lo + width * p;
        for (size_t i = 0; i < m; i++) dst[c[(src[i].key >> shift) & dmask]++] = src[i];
        sem_keyed *t = src;
        src = dst, dst = t;
    }
    if (cnt != stack_cnt) free(cnt);
    if (src != a) memcpy(a, src, sizeof *a * m);
}
