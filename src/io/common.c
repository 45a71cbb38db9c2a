/* Shared io plumbing: atomic writes through a temporary file, and small naming helpers. */
#include "io_internal.h"

#include <errno.h>
#include <unistd.h>

FILE *io_tmp_open(const char *path, char *tmp, size_t cap, sp_error *err)
{
    if (snprintf(tmp, cap, "%s.tmp.%ld", path, (long)getpid()) >= (int)cap) {
        sp_error_set(err, SP_E_ARG, "%s: path too long", path);
        return NULL;
    }
    FILE *f = fopen(tmp, "wb");
    if (!f) sp_error_set(err, SP_E_IO, "%s: cannot create: %s", tmp, strerror(errno));
    return f;
}

int io_tmp_commit(FILE *f, const char *tmp, const char *path, int ok, sp_error *err)
{
    /* A full disk shows at a write (the stream's error flag, errno still set by the failed write:
     * writers stop or only write more after it), at the flush, or at the close. */
    int bad = ferror(f), e = bad ? errno : 0;
    errno = 0;
    if (fflush(f) != 0) {
        if (!e) e = errno;
        bad = 1;
    }
    if (fclose(f) != 0) {
        if (!e) e = errno;
        bad = 1;
    }
    if (!ok) {
        remove(tmp);
        return err ? err->code : SP_E_IO;
    }
    if (bad) {
        remove(tmp);
        return sp_error_set(err, SP_E_IO, "%s: write failed: %s", path, e ? strerror(e) : "I/O error (disk full?)");
    }
    if (rename(tmp, path) != 0) {
        e = errno;
        remove(tmp);
        return sp_error_set(err, SP_E_IO, "%s: cannot rename into place: %s", path, strerror(e));
    }
    return SP_OK;
}

FILE *io_memstream(const void *data, size_t size, const char *name, const char *what, sp_error *err)
{
    if (!size) {
        sp_error_set(err, SP_E_FORMAT, "%s: not %s (empty)", name, what);
        return NULL;
    }
    FILE *f = fmemopen((void *)data, size, "rb");
    if (!f) sp_error_set(err, SP_E_NOMEM, "%s: cannot open a stream over %zu bytes", name, size);
    return f;
}

const char *io_basename(const char *path)
{
    const char *s = strrchr(path, '/');
    return s ? s + 1 : path;
}
