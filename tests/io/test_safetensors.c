/* safetensors: a file assembled by hand from the format description (u64 header length, JSON
 * header with __metadata__, tensors listed out of offset order, unpadded header), a writer round
 * trip for every dtype, and one test per way the header can lie about the data. */
#include "io_fixture.h"
#include "semsplat/io.h"
#include "test.h"

static void st_file(const char *path, const char *header, const void *data, size_t n)
{
    fx_buf f = {0};
    fx_u64(&f, strlen(header));
    fx_str(&f, header);
    fx_put(&f, data, n);
    fx_write_buf(path, &f);
    fx_free(&f);
}

static unsigned char DATA[41];

static void init_data(void)
{
    float a[6] = {1, 2, 3, 4, 5, -6.5f};
    uint16_t b[2] = {0x3C00, 0xC000}; /* half 1, -2 */
    uint16_t c = 0x4049;              /* bf16 3.140625 */
    int64_t d = -1234567890123LL;
    uint8_t e[3] = {7, 8, 9};
    memcpy(DATA, a, 24);
    memcpy(DATA + 24, b, 4);
    memcpy(DATA + 28, &c, 2);
    memcpy(DATA + 30, &d, 8);
    memcpy(DATA + 38, e, 3);
}

static const char *GOOD =
    "{\"__metadata__\":{\"format\":\"pt\"},"
    "\"e\":{\"dtype\":\"U8\",\"shape\":[3],\"data_offsets\":[38,41]},"
    "\"a\":{\"dtype\":\"F32\",\"shape\":[2,3],\"data_offsets\":[0,24]},"
    "\"c\":{\"dtype\":\"BF16\",\"shape\":[],\"data_offsets\":[28,30]},"
    "\"b\":{\"dtype\":\"F16\",\"shape\":[2],\"data_offsets\":[24,28]},"
    "\"f\":{\"dtype\":\"I32\",\"shape\":[0,4],\"data_offsets\":[41,41]},"
    "\"d\":{\"dtype\":\"I64\",\"shape\":[1],\"data_offsets\":[30,38]}}";

static void test_handmade(void)
{
    const char *dir = test_tmpdir("io_st_hand");
    char p[1024];
    sp_error err = {0};
    init_data();
    st_file(fx_path(p, sizeof p, dir, "hand.safetensors"), GOOD, DATA, sizeof DATA);
    sp_safetensors st;
    CHECK_OK(sp_safetensors_open(p, &st, &err), &err);
    CHECK(st.n == 6);
    const sp_tensor_info *a = sp_safetensors_find(&st, "a"), *b = sp_safetensors_find(&st, "b"),
                         *c = sp_safetensors_find(&st, "c"), *d = sp_safetensors_find(&st, "d"),
                         *e = sp_safetensors_find(&st, "e"), *f = sp_safetensors_find(&st, "f");
    CHECK(a && b && c && d && e && f && !sp_safetensors_find(&st, "__metadata__") && !sp_safetensors_find(&st, "z"));
    if (a && b && c && d && e && f) {
        float av[6];
        memcpy(av, a->data, 24);
        CHECK(a->dtype == SP_DTYPE_F32 && a->ndim == 2 && a->shape[1] == 3 && a->nbytes == 24 && av[5] == -6.5f);
        uint16_t bv[2], cv;
        memcpy(bv, b->data, 4);
        memcpy(&cv, c->data, 2);
        CHECK(b->dtype == SP_DTYPE_F16 && sp_half_to_float(bv[1]) == -2.0f);
        CHECK(c->dtype == SP_DTYPE_BF16 && c->ndim == 0 && sp_bf16_to_float(cv) == 3.140625f);
        int64_t dv;
        memcpy(&dv, d->data, 8);
        CHECK(d->dtype == SP_DTYPE_I64 && dv == -1234567890123LL);
        CHECK(e->dtype == SP_DTYPE_U8 && ((const uint8_t *)e->data)[2] == 9);
        CHECK(f->dtype == SP_DTYPE_I32 && f->nbytes == 0 && f->shape[1] == 4);
        /* Listed in file (offset) order. */
        CHECK(!strcmp(st.tensors[0].name, "a") && !strcmp(st.tensors[4].name, "e") && !strcmp(st.tensors[5].name, "f"));
    }
    sp_safetensors_close(&st);
    sp_safetensors_close(&st);
}

static void test_round_trip(void)
{
    const char *dir = test_tmpdir("io_st_rt");
    char p[1024];
    sp_error err = {0};
    const sp_dtype types[] = {SP_DTYPE_F32, SP_DTYPE_F16, SP_DTYPE_BF16, SP_DTYPE_I64, SP_DTYPE_I32, SP_DTYPE_U8, SP_DTYPE_F64, SP_DTYPE_U16};
    unsigned char buf[8][5 * 7 * 8];
    sp_tensor_info ti[8];
    memset(ti, 0, sizeof ti);
    for (int i = 0; i < 8; i++) {
        snprintf(ti[i].name, sizeof ti[i].name, "layer.%d.weight", i);
        ti[i].dtype = types[i];
        ti[i].ndim = 1 + i % 3;
        ti[i].shape[0] = 5;
        ti[i].shape[1] = 7;
        ti[i].shape[2] = 1;
        for (size_t k = 0; k < sizeof buf[i]; k++) buf[i][k] = (unsigned char)(k * 13 + i);
        ti[i].data = buf[i];
    }
    snprintf(p, sizeof p, "%s/rt.safetensors", dir);
    CHECK_OK(sp_safetensors_write(p, ti, 8, &err), &err);
    sp_safetensors st;
    CHECK_OK(sp_safetensors_open(p, &st, &err), &err);
    CHECK(st.n == 8);
    uint64_t hl = 0;
    if (st.map) memcpy(&hl, st.map, 8);
    CHECK(hl % 8 == 0);
    for (int i = 0; i < 8; i++) {
        const sp_tensor_info *t = sp_safetensors_find(&st, ti[i].name);
        CHECK(t && t->dtype == types[i] && t->ndim == ti[i].ndim);
        size_t count = 1;
        for (int k = 0; k < ti[i].ndim; k++) count *= ti[i].shape[k];
        if (t) CHECK(t->nbytes == count * sp_dtype_size(types[i]) && !memcmp(t->data, buf[i], t->nbytes));
    }
    sp_safetensors_close(&st);
    strcpy(ti[1].name, ti[0].name);
    CHECK_FAILS(sp_safetensors_write(p, ti, 2, &err), SP_E_ARG, &err, "given twice");
}

static void test_bad(void)
{
    const char *dir = test_tmpdir("io_st_bad");
    char p[1024];
    sp_error err = {0};
    sp_safetensors st;
    init_data();
    struct { const char *name, *header; size_t ndata; int code; const char *needle; } cases[] = {
        {"notjson", "[1,2]", 0, SP_E_FORMAT, "not a JSON object"},
        {"malformed", "{\"a\":{\"dtype\":\"F32\",", 0, SP_E_FORMAT, "malformed"},
        {"dtype", "{\"a\":{\"dtype\":\"C64\",\"shape\":[1],\"data_offsets\":[0,8]}}", 8, SP_E_UNSUPPORTED, "'a' has dtype C64"},
        {"shape", "{\"a\":{\"dtype\":\"F32\",\"shape\":[2,3],\"data_offsets\":[0,20]}}", 20, SP_E_FORMAT,
         "'a' (F32, 6 values) needs 24 bytes but data_offsets span 20"},
        {"past", "{\"a\":{\"dtype\":\"F32\",\"shape\":[2,3],\"data_offsets\":[0,24]}}", 16, SP_E_FORMAT, "run past the data (16 bytes"},
        {"overlap", "{\"a\":{\"dtype\":\"F32\",\"shape\":[2],\"data_offsets\":[0,8]},\"b\":{\"dtype\":\"F32\",\"shape\":[2],\"data_offsets\":[4,12]}}",
         12, SP_E_FORMAT, "'b' [4, 12] overlaps"},
        {"gap", "{\"a\":{\"dtype\":\"F32\",\"shape\":[2],\"data_offsets\":[4,12]}}", 12, SP_E_FORMAT, "4 unused bytes before tensor 'a'"},
        {"trailing", "{\"a\":{\"dtype\":\"F32\",\"shape\":[2],\"data_offsets\":[0,8]}}", 12, SP_E_FORMAT, "4 bytes after the last tensor"},
        {"backwards", "{\"a\":{\"dtype\":\"U8\",\"shape\":[2],\"data_offsets\":[8,6]}}", 12, SP_E_FORMAT, "end before they begin"},
        {"nooffs", "{\"a\":{\"dtype\":\"U8\",\"shape\":[2]}}", 2, SP_E_FORMAT, "'a' has no 'data_offsets'"},
        {"negshape", "{\"a\":{\"dtype\":\"U8\",\"shape\":[-2],\"data_offsets\":[0,2]}}", 2, SP_E_FORMAT, "shape entry 0"},
        {"dup", "{\"a\":{\"dtype\":\"U8\",\"shape\":[2],\"data_offsets\":[0,2]},\"a\":{\"dtype\":\"U8\",\"shape\":[2],\"data_offsets\":[2,4]}}",
         4, SP_E_FORMAT, "'a' appears twice"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char name[64];
        snprintf(name, sizeof name, "%s.safetensors", cases[i].name);
        st_file(fx_path(p, sizeof p, dir, name), cases[i].header, DATA, cases[i].ndata);
        CHECK_FAILS(sp_safetensors_open(p, &st, &err), cases[i].code, &err, cases[i].needle);
        CHECK_MSG(strstr(err.msg, name) != NULL, "'%s' does not name %s", err.msg, name);
        CHECK(st.map == NULL && st.tensors == NULL);
    }
    /* Header length larger than the file, and a file shorter than the length field. */
    fx_buf f = {0};
    fx_u64(&f, 1000);
    fx_str(&f, "{}");
    fx_write_buf(fx_path(p, sizeof p, dir, "hlen.safetensors"), &f);
    fx_free(&f);
    CHECK_FAILS(sp_safetensors_open(p, &st, &err), SP_E_FORMAT, &err, "header length 1000 exceeds the file");
    fx_write_text(fx_path(p, sizeof p, dir, "tiny.safetensors"), "abc");
    CHECK_FAILS(sp_safetensors_open(p, &st, &err), SP_E_FORMAT, &err, "too short");
    CHECK_FAILS(sp_safetensors_open(fx_path(p, sizeof p, dir, "none.safetensors"), &st, &err), SP_E_IO, &err, "none.safetensors");
    /* An empty header is a valid file with no tensors. */
    st_file(fx_path(p, sizeof p, dir, "empty.safetensors"), "{}", NULL, 0);
    CHECK_OK(sp_safetensors_open(p, &st, &err), &err);
    CHECK(st.n == 0);
    sp_safetensors_close(&st);
}

int main(void)
{
    RUN(test_handmade);
    RUN(test_round_trip);
    RUN(test_bad);
    return TEST_EXIT();
}
