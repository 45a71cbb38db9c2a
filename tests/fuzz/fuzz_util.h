/* Shared by the fuzz harnesses (tests/fuzz/fuzz_*.c). Each harness defines LLVMFuzzerTestOneInput
 * (and may define LLVMFuzzerInitialize / LLVMFuzzerCustomMutator); it is built twice:
 *   - with libFuzzer (SP_FUZZ=ON, clang): build-fuzz/fuzz/fuzz_<name>, run by scripts/fuzz.sh;
 *   - with replay_main.c in every build: fuzz_<name>_replay, the CTest test fuzz/<name>, which runs
 *     every file of tests/fuzz/corpus/<name>/ (seeds and past crashes) once.
 * Parsers that only take a path get their bytes through a private scratch folder on tmpfs
 * (/dev/shm when present), made on first use and removed at exit. */
#ifndef SP_FUZZ_UTIL_H
#define SP_FUZZ_UTIL_H

#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "semsplat/core.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
size_t LLVMFuzzerMutate(uint8_t *data, size_t size, size_t max_size);

static char fz_dir_path[256];

static inline void fz_cleanup(void)
{
    if (!fz_dir_path[0]) return;
    /* One level of files plus one level of sub-folders (maps/, models/...): all a harness makes. */
    DIR *d = opendir(fz_dir_path);
    struct dirent *e;
    char p[1024];
    while (d && (e = readdir(d))) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
        snprintf(p, sizeof p, "%s/%s", fz_dir_path, e->d_name);
        DIR *s = opendir(p);
        struct dirent *f;
        char q[1400];
        while (s && (f = readdir(s))) {
            if (!strcmp(f->d_name, ".") || !strcmp(f->d_name, "..")) continue;
            snprintf(q, sizeof q, "%s/%s", p, f->d_name);
            unlink(q);
        }
        if (s) closedir(s);
        if (rmdir(p) != 0) unlink(p);
    }
    if (d) closedir(d);
    rmdir(fz_dir_path);
}

/* The harness's scratch folder. */
static inline const char *fz_dir(void)
{
    if (fz_dir_path[0]) return fz_dir_path;
    struct stat st;
    const char *base = stat("/dev/shm", &st) == 0 && S_ISDIR(st.st_mode) ? "/dev/shm" : "/tmp";
    snprintf(fz_dir_path, sizeof fz_dir_path, "%s/sp-fuzz-XXXXXX", base);
    if (!mkdtemp(fz_dir_path)) {
        perror("fuzz: mkdtemp");
        abort();
    }
    atexit(fz_cleanup);
    return fz_dir_path;
}

/* <scratch>/<name> into out (cap >= 1024). */
static inline const char *fz_path(const char *name, char *out)
{
    snprintf(out, 1024, "%s/%s", fz_dir(), name);
    return out;
}

/* Writes bytes to <scratch>/<name> (sub-folders made as needed); returns the path in out. */
static inline const char *fz_write(const char *name, const void *data, size_t size, char *out)
{
    fz_path(name, out);
    char *slash = strrchr(out, '/');
    if (slash && slash > out + strlen(fz_dir())) {
        *slash = 0;
        mkdir(out, 0700);
        *slash = '/';
    }
    FILE *f = fopen(out, "wb");
    if (!f || (size && fwrite(data, 1, size, f) != size) || fclose(f) != 0) {
        perror(out);
        abort();
    }
    return out;
}

/* The file's bytes into a new buffer (the harness frees it), or NULL. */
static inline unsigned char *fz_slurp(const char *path, size_t *size)
{
    char *d = NULL;
    if (sp_read_file(path, &d, size, NULL)) return NULL;
    return (unsigned char *)d;
}

/* A fixture under the source tree (SP_SOURCE_DIR is set by CMake). */
static inline const char *fz_source(const char *rel, char *out)
{
    snprintf(out, 1024, "%s/%s", SP_SOURCE_DIR, rel);
    return out;
}

/* The error contract every reader keeps: a failure returns a negative code, the same code in
 * err, and a message. A harness aborts (a finding) when a reader breaks it. */
static inline void fz_check_error(int rc, const sp_error *err, const char *what)
{
    if (rc >= 0 || err->code != rc || !err->msg[0]) {
        fprintf(stderr, "%s: failed with rc %d but err says code %d, message '%s'\n", what, rc, err->code,
                err->msg);
        abort();
    }
}

/* A property the harness checks did not hold: report it and abort (a finding). */
#define FZ_ASSERT(cond, ...)                                                                         \
    do {                                                                                             \
        if (!(cond)) {                                                                               \
            fprintf(stderr, "fuzz: %s:%d: %s: ", __FILE__, __LINE__, #cond);                         \
            fprintf(stderr, __VA_ARGS__);                                                            \
            fputc('\n', stderr);                                                                     \
            abort();                                                                                 \
        }                                                                                            \
    } while (0)

/* Little-endian field access for the structure-aware mutators. */
static inline uint64_t fz_get_u64(const uint8_t *p)
{
    uint64_t v;
    memcpy(&v, p, 8);
    return v;
}
static inline void fz_put_u64(uint8_t *p, uint64_t v) { memcpy(p, &v, 8); }
static inline uint32_t fz_get_u32(const uint8_t *p)
{
    uint32_t v;
    memcpy(&v, p, 4);
    return v;
}
static inline void fz_put_u32(uint8_t *p, uint32_t v) { memcpy(p, &v, 4); }

#endif
