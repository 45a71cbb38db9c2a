/* Out of memory in the query engine: every allocation the library makes during a query is made
 * to fail in turn (malloc, calloc and realloc are interposed for calls from libsemsplat only),
 * and each such query must fail with SP_E_NOMEM and an "out of memory" message, never succeed
 * through another computation (pixel scoring used to fall back to un-normalised features) nor
 * crash; afterwards the engine answers as before. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <link.h>
#include <stdint.h>

#include "scene.h"
#include "semsplat/render.h"
#include "semsplat/semantic.h"
#include "test.h"

#if defined(__SANITIZE_ADDRESS__)
#define OOM_SKIP "AddressSanitizer owns malloc"
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define OOM_SKIP "AddressSanitizer owns malloc"
#endif
#endif

/* The injector (test-only state: one thread runs the queries). */
static uintptr_t lib_lo, lib_hi; /* libsemsplat's mapped range */
static int armed;
static long n_calls, fail_at, n_failed;

static __attribute__((unused)) int inject(void *ret)
{
    uintptr_t a = (uintptr_t)ret;
    if (!armed || a < lib_lo || a >= lib_hi) return 0;
    if (++n_calls != fail_at) return 0;
    n_failed++;
    return 1;
}

#ifndef OOM_SKIP /* (under AddressSanitizer these would replace its allocator at start-up) */
/* glibc's allocator under its own names, so the wrappers below can reach it. */
extern void *__libc_malloc(size_t);
extern void *__libc_calloc(size_t, size_t);
extern void *__libc_realloc(void *, size_t);

void *malloc(size_t n)
{
    return inject(__builtin_return_address(0)) ? NULL : __libc_malloc(n);
}

void *calloc(size_t n, size_t s)
{
    return inject(__builtin_return_address(0)) ? NULL : __libc_calloc(n, s);
}

void *realloc(void *p, size_t n)
{
    return inject(__builtin_return_address(0)) ? NULL : __libc_realloc(p, n);
}
#endif

static int find_lib(struct dl_phdr_info *info, size_t size, void *user)
{
    (void)size, (void)user;
    if (!strstr(info->dlpi_name, "libsemsplat")) return 0;
    for (int i = 0; i < info->dlpi_phnum; i++) {
        const ElfW(Phdr) *ph = &info->dlpi_phdr[i];
        if (ph->p_type != PT_LOAD) continue;
        uintptr_t lo = info->dlpi_addr + ph->p_vaddr, hi = lo + ph->p_memsz;
        if (!lib_lo || lo < lib_lo) lib_lo = lo;
        if (hi > lib_hi) lib_hi = hi;
    }
    return 1;
}

enum { NCAM = 8, CW = 64, CH = 48 };

static sp_device *g_dev;
static sp_query_engine *g_eng;

/* one thread: the allocations happen in the same order every run */
static void setup(void) { sc_make_engine(NCAM, CW, CH, 1, NULL, &g_dev, &g_eng); }

static int same_result(const sp_query_result *a, const sp_query_result *b)
{
    if (a->valid != b->valid || a->n_instances != b->n_instances || a->view_index != b->view_index) return 0;
    for (int k = 0; k < 3; k++)
        if (a->valid && a->position[k] != b->position[k]) return 0;
    return a->confidence == b->confidence;
}

/* Fails each library allocation of one query in turn. */
static void sweep(int method, const char *text)
{
    sp_query_opts qo = sp_query_opts_default();
    qo.method = method;
    sp_query_result ref, res;
    sp_error err = {0};
    CHECK_OK(sp_query_engine_query(g_eng, text, &qo, &ref, &err), &err);
    /* count the library's allocations in one query */
    armed = 1, n_calls = 0, fail_at = 0;
    CHECK_OK(sp_query_engine_query(g_eng, text, &qo, &res, &err), &err);
    armed = 0;
    long total = n_calls;
    CHECK(same_result(&ref, &res));
    sp_query_result_free(&res);
    CHECK_MSG(total > 10, "only %ld allocations seen: is the injector reaching libsemsplat?", total);
    long wrong = 0;
    for (long k = 1; k <= total; k++) {
        sp_error_clear(&err);
        armed = 1, n_calls = 0, fail_at = k, n_failed = 0;
        int rc = sp_query_engine_query(g_eng, text, &qo, &res, &err);
        armed = 0;
        if (n_failed == 0) { /* fewer allocations this time (a cache filled earlier) */
            sp_query_result_free(&res);
            continue;
        }
        if (rc != SP_E_NOMEM || !strstr(err.msg, "out of memory")) {
            if (wrong++ < 5)
                fprintf(stderr, "  %s '%s': allocation %ld of %ld failed -> rc %d (%s)\n",
                        method == SP_QUERY_3D ? "3d" : "multiview", text, k, total, rc,
                        rc ? err.msg : "succeeded anyway");
        }
        sp_query_result_free(&res);
    }
    CHECK_MSG(wrong == 0, "%ld of %ld injected failures did not end in SP_E_NOMEM", wrong, total);
    /* the engine is intact: the same answer as before */
    CHECK_OK(sp_query_engine_query(g_eng, text, &qo, &res, &err), &err);
    CHECK(same_result(&ref, &res));
    sp_query_result_free(&res);
    sp_query_result_free(&ref);
}

static void test_multiview_oom(void) { sweep(SP_QUERY_MULTIVIEW, "table"); }
static void test_3d_oom(void) { sweep(SP_QUERY_3D, "chair"); }

int main(void)
{
#ifdef OOM_SKIP
    TEST_SKIP(OOM_SKIP);
#endif
    dl_iterate_phdr(find_lib, NULL);
    if (!lib_lo) TEST_SKIP("libsemsplat is not a shared library here");
    setup();
    RUN(test_multiview_oom);
    RUN(test_3d_oom);
    sp_query_engine_free(g_eng);
    sp_device_free(g_dev);
    return TEST_EXIT();
}
