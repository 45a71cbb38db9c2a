/* A minimal test harness: CHECK macros that count failures, SKIP for missing hardware.
 * Each test_*.c is one executable; main() calls RUN(test_fn) for each case and returns
 * TEST_EXIT(). Exit code 77 means skipped (CTest SKIP_RETURN_CODE).
 *
 * GPU cases inside a CPU test: main(argc, argv) calls TEST_ARGS(argc, argv) first and
 * RUN_GPU(fn) for them. CMake registers such a file twice: as <mod>/<name> (plain run: the CPU
 * cases; GPU cases are not run and not counted) and as <mod>/<name>:gpu (run with --gpu: only the
 * GPU cases, exit 77 = skipped when no GPU answers), so a GPU case that did not run shows as
 * skipped in CTest, never as passed. */
#ifndef SEMSPLAT_TEST_H
#define SEMSPLAT_TEST_H

/* What a shell command running python on this build's library starts with: a sanitizer build's
 * library needs its runtime loaded first (CMake defines SP_ASAN_RUNTIME), and python leaks by
 * design, so leak checks are off there. */
#ifdef SP_ASAN_RUNTIME
#define TEST_PYTHON_ENV "LD_PRELOAD='" SP_ASAN_RUNTIME "' ASAN_OPTIONS=detect_leaks=0 "
#else
#define TEST_PYTHON_ENV ""
#endif

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

__attribute__((unused)) static int t_failures = 0, t_checks = 0, t_cases = 0, t_case_failed = 0;
__attribute__((unused)) static int t_gpu_mode = 0; /* --gpu: run only the RUN_GPU cases */

int sp_cuda_available(void); /* semsplat/device.h: 1 when a GPU answers */

#define CHECK(cond)                                                                    \
    do {                                                                               \
        t_checks++;                                                                    \
        if (!(cond)) {                                                                 \
            t_failures++;                                                              \
            t_case_failed = 1;                                                         \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond);  \
        }                                                                              \
    } while (0)

#define CHECK_MSG(cond, ...)                                                           \
    do {                                                                               \
        t_checks++;                                                                    \
        if (!(cond)) {                                                                 \
            t_failures++;                                                              \
            t_case_failed = 1;                                                         \
            fprintf(stderr, "%s:%d: CHECK failed: %s: ", __FILE__, __LINE__, #cond);   \
            fprintf(stderr, __VA_ARGS__);                                              \
            fprintf(stderr, "\n");                                                     \
        }                                                                              \
    } while (0)

#define CHECK_NEAR(a, b, tol)                                                          \
    do {                                                                               \
        double t_a = (double)(a), t_b = (double)(b);                                   \
        CHECK_MSG(fabs(t_a - t_b) <= (tol), "%s = %.9g, %s = %.9g, tol %g", #a, t_a,   \
                  #b, t_b, (double)(tol));                                             \
    } while (0)

/* Checks that an sp_* call succeeded, printing the error message otherwise. */
#define CHECK_OK(call, errp)                                                           \
    do {                                                                               \
        int t_rc = (call);                                                             \
        CHECK_MSG(t_rc == 0, "%s returned %d: %s", #call, t_rc, (errp)->msg);          \
    } while (0)

/* Checks that a call failed with `code` and that the message mentions `needle`. */
#define CHECK_FAILS(call, code, errp, needle)                                          \
    do {                                                                               \
        int t_rc = (call);                                                             \
        CHECK_MSG(t_rc == (code), "%s returned %d, expected %d (%s)", #call, t_rc,     \
                  (int)(code), (errp)->msg);                                           \
        CHECK_MSG(strstr((errp)->msg, (needle)) != NULL,                               \
                  "message '%s' does not mention '%s'", (errp)->msg, (needle));        \
    } while (0)

#define RUN_CASE(fn)                                                                   \
    do {                                                                               \
        t_case_failed = 0;                                                             \
        t_cases++;                                                                     \
        fn();                                                                          \
        fprintf(stderr, "%s %s\n", t_case_failed ? "FAIL" : "ok  ", #fn);              \
    } while (0)

#define RUN(fn)                                                                        \
    do {                                                                               \
        if (!t_gpu_mode) RUN_CASE(fn);                                                 \
    } while (0)

/* A case that needs the GPU: runs only under --gpu, where no GPU means the whole run is
 * skipped (77). */
#define RUN_GPU(fn)                                                                    \
    do {                                                                               \
        if (t_gpu_mode) {                                                              \
            if (!sp_cuda_available()) TEST_SKIP("no GPU answers: GPU cases not run");  \
            RUN_CASE(fn);                                                              \
        }                                                                              \
    } while (0)

/* Reads --gpu; under it, no GPU skips at once (before any set-up). */
#define TEST_ARGS(argc, argv)                                                          \
    do {                                                                               \
        t_gpu_mode = (argc) > 1 && strcmp((argv)[1], "--gpu") == 0;                    \
        if (t_gpu_mode && !sp_cuda_available()) TEST_SKIP("no GPU answers: GPU cases not run"); \
    } while (0)

#define TEST_EXIT()                                                                    \
    (fprintf(stderr, "%d cases, %d checks, %d failed\n", t_cases, t_checks,            \
             t_failures),                                                              \
     t_failures ? 1 : 0)

#define TEST_SKIP(why)                                                                 \
    do {                                                                               \
        fprintf(stderr, "SKIP: %s\n", why);                                            \
        exit(77);                                                                      \
    } while (0)

/* A scratch directory under the build tree for a test's files. */
static inline const char *test_tmpdir(const char *name)
{
    static char buf[1024];
    snprintf(buf, sizeof buf, "%s/test-tmp/%s", SP_BUILD_DIR, name);
    char cmd[1200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s' && mkdir -p '%s'", buf, buf);
    if (system(cmd) != 0) fprintf(stderr, "cannot make %s\n", buf);
    return buf;
}

/* Runs `SP_BUILD_DIR/semsplat args` (stderr too) and returns its exit status (-1 when it did not
 * exit), its output in out. */
static inline int test_run_cli(const char *args, char *out, size_t cap)
{
    char cmd[8192];
    snprintf(cmd, sizeof cmd, "'%s/semsplat' %s 2>&1", SP_BUILD_DIR, args);
    FILE *p = popen(cmd, "r");
    if (!p) return -1;
    size_t n = fread(out, 1, cap - 1, p);
    out[n] = 0;
    int st = pclose(p);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* Deterministic random numbers (xorshift64*), independent of libc. */
typedef struct { unsigned long long s; } test_rng;
static inline double test_uniform(test_rng *r)
{
    r->s ^= r->s >> 12;
    r->s ^= r->s << 25;
    r->s ^= r->s >> 27;
    return (double)((r->s * 2685821657736338717ULL) >> 11) * (1.0 / 9007199254740992.0);
}
static inline double test_range(test_rng *r, double lo, double hi) { return lo + (hi - lo) * test_uniform(r); }

#endif
