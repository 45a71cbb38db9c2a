/* File-system helpers: path joining, mkdir -p, whole-file reads, atomic writes. */
#include "semsplat/core.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int sp_path_join(char *out, size_t cap, const char *a, const char *b)
{
    size_t la = strlen(a);
    int n;
    if (la == 0 || a[la - 1] == '/')
        n = snprintf(out, cap, "%s%s", a, b);
    else
        n = snprintf(out, cap, "%s/%s", a, b);
    return (n < 0 || (size_t)n >= cap) ? -1 : 0;
}

int sp_mkdirs(const char *path, sp_error *err)
{
    char buf[4096];
    if (snprintf(buf, sizeof buf, "%s", path) >= (int)sizeof buf)
        return sp_error_set(err, SP_E_ARG, "path too long: %s", path);
    for (char *p = buf + 1; *p; p++) {
        if (*p != '/') continue;
        *p = 0;
        if (mkdir(buf, 0755) != 0 && errno != EEXIST)
            return sp_error_set(err, SP_E_IO, "%s: cannot create directory: %s", buf, strerror(errno));
        *p = '/';
    }
    if (mkdir(buf, 0755) != 0 && errno != EEXIST)
        return sp_error_set(err, SP_E_IO, "%s: cannot create directory: %s", buf, strerror(errno));
    struct stat st;
    if (stat(buf, &st) != 0 || !S_ISDIR(st.st_mode))
        return sp_error_set(err, SP_E_IO, "%s: exists and is not a directory", buf);
    return SP_OK;
}

int sp_file_exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

int sp_read_file(const char *path, char **data, size_t *size, sp_error *err)
{
    *data = NULL;
    if (size) *size = 0;
    FILE *f = fopen(path, "rb");
    if (!f) return sp_error_set(err, SP_E_IO, "%s: cannot open: %s", path, strerror(errno));
    /* A folder opens but reads nothing; a device such as /dev/zero never ends. Pipes are fine. */
    struct stat st;
    if (fstat(fileno(f), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISFIFO(st.st_mode)) {
        fclose(f);
        return sp_error_set(err, SP_E_IO, "%s: %s, not a file", path,
                            S_ISDIR(st.st_mode) ? "is a directory" : "is a device or socket");
    }
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap);
    while (buf) {
        size_t got = fread(buf + n, 1, cap - n - 1, f);
        n += got;
        if (n < cap - 1) break;
        char *nb = realloc(buf, cap * 2);
        if (!nb) {
            free(buf);
            buf = NULL;
            break;
        }
        buf = nb;
        cap *= 2;
    }
    int bad = ferror(f);
    fclose(f);
    if (!buf) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory reading the file", path);
    if (bad) {
        free(buf);
        return sp_error_set(err, SP_E_IO, "%s: read error", path);
    }
    buf[n] = 0;
    *data = buf;
    if (size) *size = n;
    return SP_OK;
}

int sp_write_file_atomic(const char *path, const void *data, size_t size, sp_error *err)
{
    char tmp[4200];
    /* A truncated temporary name could be the final name itself: refuse instead. */
    if (snprintf(tmp, sizeof tmp, "%s.tmp.%ld", path, (long)getpid()) >= (int)sizeof tmp)
        return sp_error_set(err, SP_E_ARG, "%s: path too long", path);
    FILE *f = fopen(tmp, "wb");
    if (!f) return sp_error_set(err, SP_E_IO, "%s: cannot create: %s", tmp, strerror(errno));
    size_t w = size ? fwrite(data, 1, size, f) : 0;
    int e = w != size ? errno : 0;
    if (fflush(f) != 0 && !e) e = errno ? errno : EIO;
    if (fclose(f) != 0 && !e) e = errno ? errno : EIO;
    if (w != size && !e) e = EIO;
    if (e) {
        remove(tmp);
        return sp_error_set(err, SP_E_IO, "%s: write failed: %s", path, strerror(e));
    }
    if (rename(tmp, path) != 0) {
        e = errno;
        remove(tmp);
        return sp_error_set(err, SP_E_IO, "%s: cannot rename into place: %s", path, strerror(e));
    }
    return SP_OK;
}

const char *sp_data_dir(void)
{
    const char *env = getenv("SEMSPLAT_DATA");
    if (env && *env) return env;
#ifdef SP_DATA_DIR
    return SP_DATA_DIR;
#else
    return "data";
#endif
}
