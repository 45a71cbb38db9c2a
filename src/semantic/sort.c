/* Stable radix sort of (64-bit key, index) pairs for the clustering (voxel keys of every
 * back-projected point, then coordinates per instance): linear in the count where qsort with a
 * comparator callback was most of the clustering's time. Only the span of bits that differ
 * between keys is sorted, in as few digits of at most 11 bits as cover it (a 32-bit float key:
 * 3 passes rather than 4 bytes). A stable sort's output is fixed by the keys, so the digit
 * width changes nothing but the time. */
#include <string.h>

#include "sem_internal.h"

#define DIGIT_MAX 11
#define PASS_MAX 6 /* ceil(64 / 11) */

void sem_sort_keyed(sem_keyed *a, sem_keyed *tmp, size_t m)
{
    if (m < 2) return;
    uint64_t diff = 0, k0 = a[0].key;
    for (size_t i = 0; i < m; i++) diff |= a[i].key ^ k0;
    if (!diff) return;
    int lo = __builtin_ctzll(diff), hi = 63 - __builtin_clzll(diff);
    int span = hi - lo + 1, passes = (span + DIGIT_MAX - 1) / DIGIT_MAX;
    int width = (span + passes - 1) / passes;
    uint64_t dmask = ((uint64_t)1 << width) - 1;
    size_t cnt[PASS_MAX][1 << DIGIT_MAX];
    memset(cnt, 0, sizeof(cnt[0]) * (size_t)passes);
    for (size_t i = 0; i < m; i++) {
        uint64_t k = a[i].key >> lo;
        for (int p = 0; p < passes; p++) cnt[p][(k >> (width * p)) & dmask]++;
    }
    sem_keyed *src = a, *dst = tmp;
    for (int p = 0; p < passes; p++) {
        size_t sum = 0, *c = cnt[p];
        for (size_t v = 0; v <= dmask; v++) {
            size_t n = c[v];
            c[v] = sum;
            sum += n;
        }
        const int shift = lo + width * p;
        for (size_t i = 0; i < m; i++) dst[c[(src[i].key >> shift) & dmask]++] = src[i];
        sem_keyed *t = src;
        src = dst, dst = t;
    }
    if (src != a) memcpy(a, src, sizeof *a * m);
}
