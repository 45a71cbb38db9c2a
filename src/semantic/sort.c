/* Stable radix sort of (64-bit key, index) pairs for the clustering (voxel keys of every
 * back-projected point, then coordinates per instance): linear in the count where qsort with a
 * comparator callback was most of the clustering's time. */
#include <string.h>

#include "sem_internal.h"

void sem_sort_keyed(sem_keyed *a, sem_keyed *tmp, size_t m)
{
    if (m < 2) return;
    /* the eight byte histograms in one pass; bytes equal in every key need no pass */
    static const int B = 8;
    size_t cnt[8][256];
    memset(cnt, 0, sizeof cnt);
    uint64_t diff = 0, k0 = a[0].key;
    for (size_t i = 0; i < m; i++) {
        uint64_t k = a[i].key;
        diff |= k ^ k0;
        for (int b = 0; b < B; b++) cnt[b][(k >> (8 * b)) & 255]++;
    }
    sem_keyed *src = a, *dst = tmp;
    for (int b = 0; b < B; b++) {
        if (!((diff >> (8 * b)) & 255)) continue;
        size_t sum = 0, *c = cnt[b];
        for (int v = 0; v < 256; v++) {
            size_t n = c[v];
            c[v] = sum;
            sum += n;
        }
        const int shift = 8 * b;
        for (size_t i = 0; i < m; i++) dst[c[(src[i].key >> shift) & 255]++] = src[i];
        sem_keyed *t = src;
        src = dst, dst = t;
    }
    if (src != a) memcpy(a, src, sizeof *a * m);
}
