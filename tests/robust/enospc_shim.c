/* A full disk for one folder, for tests only (LD_PRELOAD; built as libsp_enospc_shim.so, never
 * linked into the library). Every fopen for writing or appending of a path under
 * $SP_ENOSPC_DIR returns a stream whose writes succeed until $SP_ENOSPC_BYTES bytes have been
 * written by the whole process, then write what still fits and fail with ENOSPC, as a full
 * disk does (including at a later fflush/fclose of buffered data). With $SP_ENOSPC_REPORT set,
 * the number of bytes asked for is written there at exit (the budget a run needs). With
 * $SP_SLOW_WRITE_US, such streams are unbuffered and each write first sleeps that long, so that writing takes
 * most of a run and a kill (tests/robust/test_kill.c) lands inside a write. Every writer
 * of the library opens its temporary file with fopen (io_tmp_open, sp_write_file_atomic), so this
 * reaches them all; libpng and libjpeg write through those streams. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static long long budget = -1, asked, written;
static long slow_us = -1;

typedef struct { int fd; } cookie;

static ssize_t c_write(void *p, const char *buf, size_t n)
{
    cookie *c = p;
    if (slow_us > 0) usleep((useconds_t)slow_us);
    __atomic_add_fetch(&asked, (long long)n, __ATOMIC_RELAXED);
    long long before = __atomic_fetch_add(&written, (long long)n, __ATOMIC_RELAXED);
    size_t fits = n;
    if (budget >= 0 && before + (long long)n > budget) fits = before >= budget ? 0 : (size_t)(budget - before);
    size_t done = 0;
    while (done < fits) {
        ssize_t w = write(c->fd, buf + done, fits - done);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return (ssize_t)done;
        done += (size_t)w;
    }
    if (fits < n) errno = ENOSPC;
    return (ssize_t)done; /* short = error for stdio */
}

static int c_seek(void *p, off64_t *off, int whence)
{
    off_t r = lseek(((cookie *)p)->fd, (off_t)*off, whence);
    if (r < 0) return -1;
    *off = r;
    return 0;
}

static int c_close(void *p)
{
    cookie *c = p;
    int r = close(c->fd);
    free(c);
    return r;
}

static int targeted(const char *path, const char *mode)
{
    const char *dir = getenv("SP_ENOSPC_DIR");
    if (!dir || !*dir || !(strchr(mode, 'w') || strchr(mode, 'a'))) return 0;
    if (budget < 0 && getenv("SP_ENOSPC_BYTES")) budget = atoll(getenv("SP_ENOSPC_BYTES"));
    if (slow_us < 0) slow_us = getenv("SP_SLOW_WRITE_US") ? atol(getenv("SP_SLOW_WRITE_US")) : 0;
    return !strncmp(path, dir, strlen(dir));
}

static FILE *shim_open(const char *path, const char *mode, const char *real_name)
{
    FILE *(*real)(const char *, const char *) = (FILE * (*)(const char *, const char *)) dlsym(RTLD_NEXT, real_name);
    if (!targeted(path, mode)) return real(path, mode);
    int flags = O_WRONLY | O_CREAT | (strchr(mode, 'a') ? O_APPEND : O_TRUNC) | O_CLOEXEC;
    int fd = open(path, flags, 0666);
    if (fd < 0) return NULL;
    cookie *c = malloc(sizeof *c);
    if (!c) {
        close(fd);
        return NULL;
    }
    c->fd = fd;
    cookie_io_functions_t io = {.read = NULL, .write = c_write, .seek = c_seek, .close = c_close};
    FILE *f = fopencookie(c, mode, io);
    if (!f) c_close(c);
    else if (slow_us > 0) setvbuf(f, NULL, _IONBF, 0); /* every fwrite is a (slow) write */
    return f;
}

FILE *fopen(const char *path, const char *mode) { return shim_open(path, mode, "fopen"); }
FILE *fopen64(const char *path, const char *mode) { return shim_open(path, mode, "fopen64"); }

__attribute__((destructor)) static void report(void)
{
    const char *p = getenv("SP_ENOSPC_REPORT");
    if (!p || !*p) return;
    int fd = open(p, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) return;
    char s[32];
    int n = snprintf(s, sizeof s, "%lld\n", asked);
    if (write(fd, s, (size_t)n) < 0) {
    }
    close(fd);
}
