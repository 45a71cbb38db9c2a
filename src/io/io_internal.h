/* Private helpers shared by the io readers and writers: a bounds-checked little-endian cursor over
 * a file held in memory, and atomic writes through a FILE* opened on a temporary name. */
#ifndef SP_IO_INTERNAL_H
#define SP_IO_INTERNAL_H

#include <stdio.h>
#include <string.h>

#include "semsplat/core.h"
#include "semsplat/io.h"

/* A read cursor over [data, data + size). Every take_* checks the remaining bytes first, so a
 * truncated file becomes an error, never an over-read. Multi-byte values are little-endian on
 * disk; every platform we build for is little-endian, so memcpy is the decode. */
typedef struct io_cursor {
    const unsigned char *data;
    size_t size, pos;
} io_cursor;

static inline size_t io_left(const io_cursor *c) { return c->size - c->pos; }
static inline int io_take(io_cursor *c, void *dst, size_t n)
{
    if (io_left(c) < n) return -1;
    memcpy(dst, c->data + c->pos, n);
    c->pos += n;
    return 0;
}

/* Opens `<path>.tmp.<pid>` for writing; tmp (size cap) receives the name. */
FILE *io_tmp_open(const char *path, char *tmp, size_t cap, sp_error *err);
/* Flushes and closes f, then renames tmp to path; on any failure removes tmp. `ok` = 0 means the
 * caller already failed: the file is discarded and SP_E_IO is not reported over its error. */
int io_tmp_commit(FILE *f, const char *tmp, const char *path, int ok, sp_error *err);

/* A read-only stream over bytes in memory, so an in-memory reader is the file reader unchanged;
 * NULL with an error naming `name` (what = the format, for "not a PLY file (empty)"). */
FILE *io_memstream(const void *data, size_t size, const char *name, const char *what, sp_error *err);

/* Last path component, for messages that name a file inside a model folder. */
const char *io_basename(const char *path);

/* Dtype names shared by .npy and safetensors messages ("float32", ...). */
const char *io_dtype_name(sp_dtype t);

#endif
