/* Stable radix sort of (64-bit key, index) pairs for the clustering (voxel keys of every
 * back-projected point, then coordinates per instance): linear in the count where qsort with a
 * comparator callback was most of the clustering's time. */
#include <string.h>

#include "sem_internal.h"

void sem_sort_keyed(sem_keyed *a, sem_keyed *tmp, size_t m)
{
    sem_keyed *src = a, *dst = tmp;
    for (int shift = 0; shift < 64 && m > 1; shift += 8) {
        size_t cnt[256] = {0};
        for (size_t i = 0; i < m; i++) cnt[(src[i].key >> shift) & 255]++;
        if (cnt[(src[0].key >> shift) & 255] == m) continue; /* this byte is the same for all */
        size_t sum = 0;
        for (int b = 0; b < 256; b++) {
            size_t c = cnt[b];
            cnt[b] = sum;
            sum += c;
        }
        for (size_t i = 0; i < m; i++) dst[cnt[(src[i].key >> shift) & 255]++] = src[i];
        sem_keyed *t = src;
        src = dst, dst = t;
    }
    if (src != a) memcpy(a, src, sizeof *a * m);
}

uint64_t sem_float_order(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u >> 31 ? ~u : u | 0x80000000u; /* negatives reversed below the positives */
}
