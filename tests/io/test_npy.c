/* .npy: headers written by hand per the NumPy format spec (versions 1, 2, 3; C and Fortran
 * order), files written by NumPy itself (tests/fixtures/io/np_*.npy), half-float conversions
 * checked exhaustively against an independent double-precision decode, round trips for every
 * writable dtype, and malformed files. */
#include "io_fixture.h"
#include "semsplat/io.h"
#include "test.h"

/* Builds a .npy: magic, version, header length (2 bytes for v1, 4 for v2/3), dict padded with
 * spaces and a newline to a multiple of 64 bytes, then the raw data. */
static void npy_bytes(fx_buf *f, int version, const char *dict, const void *data, size_t nbytes)
{
    fx_put(f, "\x93NUMPY", 6);
    fx_u8(f, (uint8_t)version);
    fx_u8(f, 0);
    size_t pre = version == 1 ? 10 : 12, len = strlen(dict) + 1;
    size_t total = (pre + len + 63) / 64 * 64, hlen = total - pre;
    if (version == 1) {
        fx_u8(f, (uint8_t)hlen);
        fx_u8(f, (uint8_t)(hlen >> 8));
    } else {
        fx_u32(f, (uint32_t)hlen);
    }
    fx_str(f, dict);
    for (size_t i = len; i < hlen; i++) fx_u8(f, ' ');
    fx_u8(f, '\n');
    fx_put(f, data, nbytes);
}

static void test_handmade_versions(void)
{
    const char *dir = test_tmpdir("io_npy_hand");
    char p[1024];
    sp_error err = {0};
    float v[6] = {1, 2, 3, 4, 5, 6};
    for (int ver = 1; ver <= 3; ver++) {
        fx_buf f = {0};
        npy_bytes(&f, ver, "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3), }", v, sizeof v);
        snprintf(p, sizeof p, "%s/v%d.npy", dir, ver);
        fx_write_buf(p, &f);
        fx_free(&f);
        sp_npy a;
        CHECK_OK(sp_npy_read(p, &a, &err), &err);
        CHECK(a.dtype == SP_DTYPE_F32 && a.ndim == 2 && a.shape[0] == 2 && a.shape[1] == 3);
        CHECK(a.data && memcmp(a.data, v, sizeof v) == 0);
        sp_npy_free(&a);
    }
    /* Fortran order, shape (2, 3): memory holds column-major a[0,0], a[1,0], a[0,1], ... */
    double fd[6] = {0, 10, 1, 11, 2, 12}; /* a[i][j] = 10 i + j */
    fx_buf f = {0};
    npy_bytes(&f, 1, "{'descr': '<f8', 'fortran_order': True, 'shape': (2, 3), }", fd, sizeof fd);
    fx_write_buf(fx_path(p, sizeof p, dir, "fortran.npy"), &f);
    fx_free(&f);
    sp_npy a;
    CHECK_OK(sp_npy_read(p, &a, &err), &err);
    for (int i = 0; a.data && i < 2; i++)
        for (int j = 0; j < 3; j++) CHECK(((double *)a.data)[i * 3 + j] == 10 * i + j);
    float *f32 = NULL;
    CHECK_OK(sp_npy_to_f32(&a, &f32, &err), &err);
    if (f32) CHECK(f32[5] == 12.0f);
    free(f32);
    sp_npy_free(&a);
    /* 1-D with the trailing comma NumPy writes: (4,) */
    int32_t iv[4] = {-1, 0, 7, 2000000000};
    npy_bytes(&f, 1, "{'descr': '<i4', 'fortran_order': False, 'shape': (4,), }", iv, sizeof iv);
    fx_write_buf(fx_path(p, sizeof p, dir, "i4.npy"), &f);
    fx_free(&f);
    CHECK_OK(sp_npy_read(p, &a, &err), &err);
    CHECK(a.dtype == SP_DTYPE_I32 && a.ndim == 1 && a.shape[0] == 4 && ((int32_t *)a.data)[3] == 2000000000);
    sp_npy_free(&a);
}

static void test_numpy_written(void)
{
    sp_error err = {0};
    sp_npy a;
    char p[1024];
    snprintf(p, sizeof p, "%s/tests/fixtures/io/np_f4_2x3.npy", SP_SOURCE_DIR);
    CHECK_OK(sp_npy_read(p, &a, &err), &err);
    CHECK(a.ndim == 2 && a.shape[0] == 2 && a.shape[1] == 3 && a.dtype == SP_DTYPE_F32);
    for (int i = 0; a.data && i < 6; i++) CHECK(((float *)a.data)[i] == i * 0.5f - 1);
    sp_npy_free(&a);
    /* np.asfortranarray(np.arange(12).reshape(2,3,2)): C-order values must be 0..11. */
    snprintf(p, sizeof p, "%s/tests/fixtures/io/np_f8_fortran_2x3x2.npy", SP_SOURCE_DIR);
    CHECK_OK(sp_npy_read(p, &a, &err), &err);
    CHECK(a.ndim == 3 && a.shape[0] == 2 && a.shape[1] == 3 && a.shape[2] == 2 && a.dtype == SP_DTYPE_F64);
    for (int i = 0; a.data && i < 12; i++) CHECK(((double *)a.data)[i] == i);
    sp_npy_free(&a);
    snprintf(p, sizeof p, "%s/tests/fixtures/io/np_f2_5.npy", SP_SOURCE_DIR);
    CHECK_OK(sp_npy_read(p, &a, &err), &err);
    float *f = NULL;
    CHECK(a.dtype == SP_DTYPE_F16 && sp_npy_count(&a) == 5);
    CHECK_OK(sp_npy_to_f32(&a, &f, &err), &err);
    if (f) {
        CHECK(f[0] == 1.0f && f[1] == -2.5f && f[2] == 65504.0f);
        CHECK_NEAR(f[3], 5.96046448e-08, 1e-15); /* 6e-8 rounds to the smallest subnormal */
        CHECK_NEAR(f[4], 0.0999755859375, 1e-12);
    }
    free(f);
    sp_npy_free(&a);
    snprintf(p, sizeof p, "%s/tests/fixtures/io/np_u1_2x2x3.npy", SP_SOURCE_DIR);
    CHECK_OK(sp_npy_read(p, &a, &err), &err);
    CHECK(a.dtype == SP_DTYPE_U8 && a.ndim == 3 && ((uint8_t *)a.data)[11] == 11);
    sp_npy_free(&a);
    snprintf(p, sizeof p, "%s/tests/fixtures/io/np_i8_scalar.npy", SP_SOURCE_DIR);
    CHECK_OK(sp_npy_read(p, &a, &err), &err);
    CHECK(a.dtype == SP_DTYPE_I64 && a.ndim == 0 && sp_npy_count(&a) == 1 && ((int64_t *)a.data)[0] == 7);
    sp_npy_free(&a);
}

/* Independent binary16 decode: (-1)^s * 2^(e-15) * (1 + m/1024), subnormal 2^-14 * m/1024. */
static double half_ref(uint16_t h)
{
    int s = h >> 15, e = (h >> 10) & 31, m = h & 1023;
    double v = e == 0 ? ldexp(m / 1024.0, -14) : e == 31 ? (m ? NAN : INFINITY) : ldexp(1 + m / 1024.0, e - 15);
    return s ? -v : v;
}

static void test_half(void)
{
    int bad = 0;
    for (uint32_t h = 0; h < 65536; h++) {
        double r = half_ref((uint16_t)h);
        float f = sp_half_to_float((uint16_t)h);
        if (isnan(r)) {
            bad += !isnan(f);
            bad += !isnan(sp_half_to_float(sp_float_to_half(f)));
            continue;
        }
        bad += (double)f != r;
        bad += sp_float_to_half(f) != (uint16_t)h; /* every half survives a float round trip */
    }
    CHECK_MSG(bad == 0, "%d half conversions disagree with the reference", bad);
    /* Rounding to nearest, ties to even: 1 + 2^-11 is halfway between 1 and 1 + 2^-10. */
    CHECK(sp_float_to_half(1.0f + ldexpf(1, -11)) == 0x3C00);
    CHECK(sp_float_to_half(1.0f + 3 * ldexpf(1, -11)) == 0x3C02);
    CHECK(sp_float_to_half(70000.0f) == 0x7C00);   /* overflow -> Inf */
    CHECK(sp_float_to_half(65519.0f) == 0x7BFF);   /* just below the Inf rounding point */
    CHECK(sp_float_to_half(65520.0f) == 0x7C00);
    CHECK(sp_float_to_half(1e-9f) == 0x0000);
    CHECK(sp_float_to_half(-ldexpf(1, -25) * 1.5f) == 0x8001); /* rounds up to -2^-24 */
    CHECK(sp_bf16_to_float(0x3F80) == 1.0f && sp_bf16_to_float(0xC040) == -3.0f);
}

static void test_round_trip(void)
{
    const char *dir = test_tmpdir("io_npy_rt");
    char p[1024];
    sp_error err = {0};
    const sp_dtype types[] = {SP_DTYPE_F32, SP_DTYPE_F16, SP_DTYPE_U8, SP_DTYPE_I32, SP_DTYPE_U16, SP_DTYPE_F64, SP_DTYPE_I64};
    size_t shape[4] = {3, 1, 4, 5};
    unsigned char data[60 * 8];
    for (size_t i = 0; i < sizeof data; i++) data[i] = (unsigned char)(i * 37 + 11);
    for (size_t t = 0; t < sizeof types / sizeof types[0]; t++) {
        for (int nd = 0; nd <= 4; nd++) {
            snprintf(p, sizeof p, "%s/t%zu_%d.npy", dir, t, nd);
            CHECK_OK(sp_npy_write(p, types[t], nd, shape, data, &err), &err);
            sp_npy a;
            CHECK_OK(sp_npy_read(p, &a, &err), &err);
            size_t count = 1;
            for (int k = 0; k < nd; k++) count *= shape[k];
            CHECK(a.dtype == types[t] && a.ndim == nd && sp_npy_count(&a) == count);
            CHECK(a.data && memcmp(a.data, data, count * sp_dtype_size(types[t])) == 0);
            sp_npy_free(&a);
            /* Data starts on a 64-byte boundary, as NumPy's own writer does. */
            size_t n = 0;
            unsigned char *b = fx_slurp(p, &n);
            CHECK((n - count * sp_dtype_size(types[t])) % 64 == 0);
            free(b);
        }
    }
    CHECK_FAILS(sp_npy_write(p, SP_DTYPE_BF16, 1, shape, data, &err), SP_E_UNSUPPORTED, &err, "bfloat16");
    /* NumPy itself reads what we write (skipped where /usr/bin/python3 lacks numpy). */
    if (system("/usr/bin/python3 -c 'import numpy' 2>/dev/null") == 0) {
        float v[6] = {1.5f, -2, 3, 4, 5, 6.25f};
        size_t sh[2] = {2, 3};
        snprintf(p, sizeof p, "%s/fornumpy.npy", dir);
        CHECK_OK(sp_npy_write(p, SP_DTYPE_F32, 2, sh, v, &err), &err);
        char cmd[1300];
        snprintf(cmd, sizeof cmd, "/usr/bin/python3 -c \"import numpy as np; a=np.load('%s'); "
                 "assert a.shape==(2,3) and a.dtype==np.float32 and a[1,2]==6.25 and a[0,1]==-2\"", p);
        CHECK(system(cmd) == 0);
    }
}

static void test_bad(void)
{
    const char *dir = test_tmpdir("io_npy_bad");
    char p[1024];
    sp_error err = {0};
    sp_npy a;
    float v[6] = {0};
    fx_buf f = {0};
    struct { const char *name, *dict; int code; const char *needle; } cases[] = {
        {"nodescr.npy", "{'fortran_order': False, 'shape': (2, 3), }", SP_E_FORMAT, "descr"},
        {"noshape.npy", "{'descr': '<f4', 'fortran_order': False, }", SP_E_FORMAT, "shape"},
        {"complex.npy", "{'descr': '<c8', 'fortran_order': False, 'shape': (3,), }", SP_E_UNSUPPORTED, "<c8"},
        {"bigend.npy", "{'descr': '>f4', 'fortran_order': False, 'shape': (6,), }", SP_E_UNSUPPORTED, "big-endian"},
        {"trunc.npy", "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 4), }", SP_E_FORMAT, "truncated"},
        {"huge.npy", "{'descr': '<f4', 'fortran_order': False, 'shape': (1000000000000, 1000000000), }", SP_E_FORMAT, "overflows"},
        {"badshape.npy", "{'descr': '<f4', 'fortran_order': False, 'shape': (2, x), }", SP_E_FORMAT, "shape"},
        {"badfo.npy", "{'descr': '<f4', 'fortran_order': Maybe, 'shape': (2, 3), }", SP_E_FORMAT, "fortran_order"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        npy_bytes(&f, 1, cases[i].dict, v, sizeof v);
        fx_write_buf(fx_path(p, sizeof p, dir, cases[i].name), &f);
        fx_free(&f);
        CHECK_FAILS(sp_npy_read(p, &a, &err), cases[i].code, &err, cases[i].needle);
        CHECK_MSG(strstr(err.msg, cases[i].name) != NULL, "message '%s' lacks the file name", err.msg);
        CHECK(a.data == NULL);
    }
    fx_write_text(fx_path(p, sizeof p, dir, "magic.npy"), "NUMPY is not at the start");
    CHECK_FAILS(sp_npy_read(p, &a, &err), SP_E_FORMAT, &err, "bad magic");
    /* Header length pointing past the end of the file. */
    fx_put(&f, "\x93NUMPY\x01\x00\xff\xff{'descr'", 18);
    fx_write_buf(fx_path(p, sizeof p, dir, "hlen.npy"), &f);
    fx_free(&f);
    CHECK_FAILS(sp_npy_read(p, &a, &err), SP_E_FORMAT, &err, "past the end");
    fx_put(&f, "\x93NUMPY\x09\x00\x10\x00{}              ", 26);
    fx_write_buf(fx_path(p, sizeof p, dir, "ver.npy"), &f);
    fx_free(&f);
    CHECK_FAILS(sp_npy_read(p, &a, &err), SP_E_UNSUPPORTED, &err, "version 9");
}

int main(void)
{
    RUN(test_handmade_versions);
    RUN(test_numpy_written);
    RUN(test_half);
    RUN(test_round_trip);
    RUN(test_bad);
    return TEST_EXIT();
}
