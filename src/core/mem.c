/* Aligned allocation: 64-byte alignment suits AVX-512 loads and cache lines. */
#include "semsplat/core.h"

#include <stdint.h>
#include <stdlib.h>

void *sp_alloc(size_t bytes)
{
    if (bytes == 0) return NULL;
    void *p = NULL;
    size_t rounded = (bytes + 63) & ~(size_t)63;
    if (posix_memalign(&p, 64, rounded) != 0) return NULL;
    return p;
}

void *sp_calloc(size_t count, size_t size)
{
    if (count == 0 || size == 0) return NULL;
    if (count > SIZE_MAX / size) return NULL;
    void *p = sp_alloc(count * size);
    if (p) {
        unsigned char *b = p;
        for (size_t i = 0; i < count * size; i++) b[i] = 0;
    }
    return p;
}

void sp_free(void *p) { free(p); }
