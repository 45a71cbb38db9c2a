/* Splat PLY: files built by hand as the 3DGS save_ply writes them (text header + packed
 * little-endian floats, channel-major f_rest), shuffled property order with double/uchar types and
 * extra elements, ascii, round trips for SH degrees 0-3 with features, and one test per failure
 * mode (truncated, oversized count, missing property, bad f_rest count, NaN, ...). */
#include "io_fixture.h"
#include "semsplat/io.h"
#include "test.h"

/* The 3DGS header for n vertices with n_rest f_rest properties and n_sem features. */
static void header_3dgs(fx_buf *f, size_t n, int n_rest, int n_sem)
{
    char line[128];
    fx_str(f, "ply\nformat binary_little_endian 1.0\n");
    snprintf(line, sizeof line, "element vertex %zu\n", n);
    fx_str(f, line);
    const char *fixed[] = {"x", "y", "z", "nx", "ny", "nz", "f_dc_0", "f_dc_1", "f_dc_2"};
    for (int k = 0; k < 9; k++) {
        snprintf(line, sizeof line, "property float %s\n", fixed[k]);
        fx_str(f, line);
    }
    for (int k = 0; k < n_rest; k++) {
        snprintf(line, sizeof line, "property float f_rest_%d\n", k);
        fx_str(f, line);
    }
    fx_str(f, "property float opacity\nproperty float scale_0\nproperty float scale_1\nproperty float scale_2\n"
              "property float rot_0\nproperty float rot_1\nproperty float rot_2\nproperty float rot_3\n");
    for (int k = 0; k < n_sem; k++) {
        snprintf(line, sizeof line, "property float f_sem_%d\n", k);
        fx_str(f, line);
    }
    fx_str(f, "end_header\n");
}

/* Vertex i of the hand-made degree-1 file: every field a distinct, recognisable value. */
static void vertex_3dgs(fx_buf *f, int i, int n_rest, int n_sem)
{
    fx_f32(f, 1.0f + i); fx_f32(f, 2.0f + i); fx_f32(f, 3.0f + i);
    fx_f32(f, 9); fx_f32(f, 9); fx_f32(f, 9); /* normals: ignored */
    fx_f32(f, 0.1f * i); fx_f32(f, 0.2f); fx_f32(f, 0.3f);
    for (int j = 0; j < n_rest; j++) fx_f32(f, 100.0f * (i + 1) + j);
    fx_f32(f, -0.5f * i);
    fx_f32(f, -1); fx_f32(f, -2); fx_f32(f, -3);
    fx_f32(f, 0.5f); fx_f32(f, 0.5f); fx_f32(f, -0.5f); fx_f32(f, 0.25f * i);
    for (int j = 0; j < n_sem; j++) fx_f32(f, 1000.0f * i + j);
}

static void test_handmade_3dgs(void)
{
    const char *dir = test_tmpdir("io_ply_hand");
    char p[1024];
    sp_error err = {0};
    fx_buf f = {0};
    header_3dgs(&f, 2, 9, 2);
    vertex_3dgs(&f, 0, 9, 2);
    vertex_3dgs(&f, 1, 9, 2);
    fx_write_buf(fx_path(p, sizeof p, dir, "deg1.ply"), &f);
    fx_free(&f);
    sp_splat s;
    CHECK_OK(sp_ply_read_splat(p, &s, &err), &err);
    CHECK(s.n == 2 && s.sh_degree == 1 && s.feat_dim == 2);
    if (s.n == 2 && s.sh_degree == 1) {
        CHECK(s.means[3] == 2 && s.means[5] == 4);
        CHECK(s.sh[0] == 0.0f && s.sh[1] == 0.2f && s.sh[2] == 0.3f);
        CHECK(s.sh[4 * 3 + 0] == 0.1f); /* vertex 1 DC red */
        /* f_rest is channel-major: f_rest[c*3 + (k-1)] -> sh[i][k][c]. */
        for (int i = 0; i < 2; i++)
            for (int k = 1; k < 4; k++)
                for (int c = 0; c < 3; c++)
                    CHECK(s.sh[(i * 4 + k) * 3 + c] == 100.0f * (i + 1) + c * 3 + (k - 1));
        CHECK(s.opacity_logits[1] == -0.5f && s.log_scales[5] == -3);
        CHECK(s.quats[4] == 0.5f && s.quats[6] == -0.5f && s.quats[7] == 0.25f);
        CHECK(s.features[0] == 0 && s.features[3] == 1001);
    }
    sp_splat_free(&s);
}

/* gsplat-like export with a different property order, doubles, a uchar colour the reader must
 * ignore, an element before the vertex element and a face list after it. */
static void test_any_order_and_types(void)
{
    const char *dir = test_tmpdir("io_ply_order");
    char p[1024];
    sp_error err = {0};
    fx_buf f = {0};
    fx_str(&f, "ply\r\nformat binary_little_endian 1.0\r\ncomment made by hand\r\nobj_info x\r\n"
               "element camera 2\r\nproperty float fov\r\nproperty uchar id\r\n"
               "element vertex 3\r\n"
               "property double rot_3\r\nproperty float opacity\r\nproperty uchar red\r\nproperty double x\r\n"
               "property float f_dc_2\r\nproperty float scale_2\r\nproperty float y\r\nproperty float f_dc_0\r\n"
               "property float scale_0\r\nproperty float rot_0\r\nproperty float z\r\nproperty float f_dc_1\r\n"
               "property float scale_1\r\nproperty float rot_2\r\nproperty float rot_1\r\n"
               "element face 1\r\nproperty list uchar int vertex_indices\r\nend_header\r\n");
    for (int c = 0; c < 2; c++) {
        fx_f32(&f, 1.0f);
        fx_u8(&f, 7);
    }
    for (int i = 0; i < 3; i++) {
        fx_f64(&f, 0.125 * i);       /* rot_3 */
        fx_f32(&f, 2.0f + i);         /* opacity */
        fx_u8(&f, 200);               /* red */
        fx_f64(&f, 1.0 / 3.0 + i);    /* x */
        fx_f32(&f, 0.3f);             /* f_dc_2 */
        fx_f32(&f, -3.0f);            /* scale_2 */
        fx_f32(&f, 10.0f * i);        /* y */
        fx_f32(&f, 0.1f);             /* f_dc_0 */
        fx_f32(&f, -1.0f);            /* scale_0 */
        fx_f32(&f, 1.0f);             /* rot_0 */
        fx_f32(&f, 5.0f);             /* z */
        fx_f32(&f, 0.2f);             /* f_dc_1 */
        fx_f32(&f, -2.0f);            /* scale_1 */
        fx_f32(&f, 0.0f);             /* rot_2 */
        fx_f32(&f, 0.0f);             /* rot_1 */
    }
    fx_u8(&f, 3); fx_i32(&f, 0); fx_i32(&f, 1); fx_i32(&f, 2);
    fx_write_buf(fx_path(p, sizeof p, dir, "order.ply"), &f);
    fx_free(&f);
    sp_splat s;
    CHECK_OK(sp_ply_read_splat(p, &s, &err), &err);
    CHECK(s.n == 3 && s.sh_degree == 0 && s.feat_dim == 0);
    if (s.n == 3) {
        CHECK(s.means[6] == (float)(1.0 / 3.0 + 2) && s.means[7] == 20 && s.means[8] == 5);
        CHECK(s.sh[6] == 0.1f && s.sh[7] == 0.2f && s.sh[8] == 0.3f);
        CHECK(s.quats[8] == 1 && s.quats[11] == 0.25f && s.opacity_logits[2] == 4);
        CHECK(s.log_scales[3] == -1 && s.log_scales[4] == -2 && s.log_scales[5] == -3);
    }
    sp_splat_free(&s);
}

static void test_ascii(void)
{
    const char *dir = test_tmpdir("io_ply_ascii");
    char p[1024];
    sp_error err = {0};
    fx_write_text(fx_path(p, sizeof p, dir, "a.ply"),
                  "ply\nformat ascii 1.0\nelement camera 1\nproperty float fov\nproperty uchar id\nelement vertex 2\n"
                  "property float x\nproperty float y\nproperty float z\n"
                  "property float f_dc_0\nproperty float f_dc_1\nproperty float f_dc_2\nproperty float opacity\n"
                  "property float scale_0\nproperty float scale_1\nproperty float scale_2\n"
                  "property float rot_0\nproperty float rot_1\nproperty float rot_2\nproperty float rot_3\n"
                  "property float f_sem_0\n"
                  "element face 1\nproperty list uchar int vertex_indices\n"
                  "end_header\n"
                  "0.9 3\n"
                  "1 2 3 0.5 0.25 0.125 -1 -2 -2 -2 1 0 0 0 7\n"
                  "\n"
                  "-1e-3 4.5 6 0 0 0 3 0 0 0 0.7071 0.7071 0 0 -7\n"
                  "3 0 1 1\n");
    sp_splat s;
    CHECK_OK(sp_ply_read_splat(p, &s, &err), &err);
    CHECK(s.n == 2 && s.feat_dim == 1 && s.sh_degree == 0);
    if (s.n == 2) {
        CHECK(s.means[0] == 1 && s.means[3] == -1e-3f && s.sh[2] == 0.125f && s.opacity_logits[1] == 3);
        CHECK(s.quats[5] == 0.7071f && s.features[1] == -7);
    }
    sp_splat_free(&s);
}

static void fill_random(sp_splat *s, test_rng *r)
{
    size_t K = (size_t)sp_sh_coeffs(s->sh_degree);
    for (size_t i = 0; i < s->n * 3; i++) s->means[i] = (float)test_range(r, -10, 10);
    for (size_t i = 0; i < s->n * 4; i++) s->quats[i] = (float)test_range(r, -1, 1);
    for (size_t i = 0; i < s->n * 3; i++) s->log_scales[i] = (float)test_range(r, -6, 0);
    for (size_t i = 0; i < s->n; i++) s->opacity_logits[i] = (float)test_range(r, -5, 5);
    for (size_t i = 0; i < s->n * K * 3; i++) s->sh[i] = (float)test_range(r, -1, 1);
    for (size_t i = 0; i < s->n * (size_t)s->feat_dim; i++) s->features[i] = (float)test_range(r, -1, 1);
}

static void test_round_trip(void)
{
    const char *dir = test_tmpdir("io_ply_rt");
    char p[1024];
    sp_error err = {0};
    test_rng rng = {99};
    for (int deg = 0; deg <= 3; deg++) {
        int D = deg == 2 ? 0 : 3 + deg * 5;
        size_t n = deg == 3 ? 5000 : 17; /* 5000 crosses the reader's chunk size */
        sp_splat s, b;
        CHECK_OK(sp_splat_alloc(&s, n, deg, D, &err), &err);
        fill_random(&s, &rng);
        snprintf(p, sizeof p, "%s/deg%d.ply", dir, deg);
        CHECK_OK(sp_ply_write_splat(p, &s, &err), &err);
        CHECK_OK(sp_ply_read_splat(p, &b, &err), &err);
        size_t K = (size_t)sp_sh_coeffs(deg);
        CHECK(b.n == n && b.sh_degree == deg && b.feat_dim == D);
        if (b.n == n && b.sh_degree == deg && b.feat_dim == D) {
            CHECK(!memcmp(s.means, b.means, n * 12) && !memcmp(s.quats, b.quats, n * 16));
            CHECK(!memcmp(s.log_scales, b.log_scales, n * 12) && !memcmp(s.opacity_logits, b.opacity_logits, n * 4));
            CHECK(!memcmp(s.sh, b.sh, n * K * 12));
            CHECK(D == 0 || !memcmp(s.features, b.features, n * (size_t)D * 4));
        }
        /* Layout check on the raw bytes: after the header, vertex 0 is x y z 0 0 0 dc0..2 then
         * f_rest_0 = sh[0][1][red]. */
        size_t len = 0;
        unsigned char *raw = fx_slurp(p, &len);
        const char *eh = raw ? strstr((const char *)raw, "end_header\n") : NULL;
        if (eh) {
            float v[10];
            memcpy(v, eh + 11, sizeof v);
            CHECK(v[0] == s.means[0] && v[3] == 0 && v[5] == 0 && v[6] == s.sh[0] && v[8] == s.sh[2]);
            if (deg > 0) CHECK(v[9] == s.sh[3]);
            size_t stride = (9 + 3 * (K - 1) + 8 + (size_t)D) * 4;
            CHECK(len - (size_t)(eh + 11 - (const char *)raw) == n * stride);
        }
        free(raw);
        sp_splat_free(&s);
        sp_splat_free(&b);
    }
    /* An empty splat round trips too. */
    sp_splat e = {0}, b;
    snprintf(p, sizeof p, "%s/empty.ply", dir);
    CHECK_OK(sp_ply_write_splat(p, &e, &err), &err);
    CHECK_OK(sp_ply_read_splat(p, &b, &err), &err);
    CHECK(b.n == 0);
    sp_splat_free(&b);
    /* The writer refuses NaN. */
    sp_splat s;
    sp_splat_alloc(&s, 2, 0, 0, &err);
    s.log_scales[4] = NAN;
    CHECK_FAILS(sp_ply_write_splat(p, &s, &err), SP_E_NUMERIC, &err, "empty.ply");
    sp_splat_free(&s);
}

static void test_bad(void)
{
    const char *dir = test_tmpdir("io_ply_bad");
    char p[1024], q[1024];
    sp_error err = {0};
    sp_splat s;
    fx_buf f = {0};
    header_3dgs(&f, 3, 9, 0);
    for (int i = 0; i < 3; i++) vertex_3dgs(&f, i, 9, 0);
    fx_write_buf(fx_path(p, sizeof p, dir, "good.ply"), &f);
    CHECK_OK(sp_ply_read_splat(p, &s, &err), &err);
    sp_splat_free(&s);
    fx_truncate_copy(p, fx_path(q, sizeof q, dir, "trunc.ply"), f.n - 10);
    CHECK_FAILS(sp_ply_read_splat(q, &s, &err), SP_E_FORMAT, &err, "trunc.ply");
    CHECK(strstr(err.msg, "header says 3 vertices") != NULL && s.means == NULL);
    fx_free(&f);

    header_3dgs(&f, 1000000000000ull, 0, 0);
    vertex_3dgs(&f, 0, 0, 0);
    fx_write_buf(fx_path(p, sizeof p, dir, "count.ply"), &f);
    fx_free(&f);
    CHECK_FAILS(sp_ply_read_splat(p, &s, &err), SP_E_FORMAT, &err, "header says 1000000000000 vertices");
    CHECK(strstr(err.msg, "count.ply") != NULL);

    header_3dgs(&f, 1, 10, 0);
    vertex_3dgs(&f, 0, 10, 0);
    fx_write_buf(fx_path(p, sizeof p, dir, "rest10.ply"), &f);
    fx_free(&f);
    CHECK_FAILS(sp_ply_read_splat(p, &s, &err), SP_E_FORMAT, &err, "10 f_rest_* properties");
    CHECK(strstr(err.msg, "rest10.ply") != NULL);

    header_3dgs(&f, 2, 0, 0);
    vertex_3dgs(&f, 0, 0, 0);
    fx_f32(&f, 1); fx_f32(&f, NAN);
    for (int k = 0; k < 15; k++) fx_f32(&f, 0);
    fx_write_buf(fx_path(p, sizeof p, dir, "nan.ply"), &f);
    fx_free(&f);
    CHECK_FAILS(sp_ply_read_splat(p, &s, &err), SP_E_NUMERIC, &err, "vertex 1 has a non-finite y");
    CHECK(strstr(err.msg, "nan.ply") != NULL);

    struct { const char *name, *text; int code; const char *needle; } cases[] = {
        {"norot3.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                       "property float z\nproperty float f_dc_0\nproperty float f_dc_1\nproperty float f_dc_2\n"
                       "property float opacity\nproperty float scale_0\nproperty float scale_1\nproperty float scale_2\n"
                       "property float rot_0\nproperty float rot_1\nproperty float rot_2\nend_header\n",
         SP_E_FORMAT, "vertex property 'rot_3' is missing"},
        {"noop.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
                     "end_header\n", SP_E_FORMAT, "'f_dc_0' is missing"},
        {"dup.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float x\nend_header\n",
         SP_E_FORMAT, "'x' appears twice"},
        {"magic.ply", "plyx\nformat ascii 1.0\n", SP_E_FORMAT, "not a PLY file"},
        {"big.ply", "ply\nformat binary_big_endian 1.0\nelement vertex 0\nend_header\n", SP_E_UNSUPPORTED, "binary_big_endian"},
        {"noend.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\n", SP_E_FORMAT, "without 'end_header'"},
        {"novert.ply", "ply\nformat ascii 1.0\nelement face 0\nend_header\n", SP_E_FORMAT, "no 'element vertex'"},
        {"list.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty list uchar float x\nend_header\n",
         SP_E_UNSUPPORTED, "list property"},
        {"type.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float128 x\nend_header\n", SP_E_FORMAT,
         "bad property line"},
        {"kw.ply", "ply\nformat ascii 1.0\nbogus line\nend_header\n", SP_E_FORMAT, "header line 3: unknown keyword 'bogus'"},
        {"count.ply", "ply\nformat ascii 1.0\nelement vertex -5\nend_header\n", SP_E_FORMAT, "bad element line"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        fx_write_text(fx_path(p, sizeof p, dir, cases[i].name), cases[i].text);
        CHECK_FAILS(sp_ply_read_splat(p, &s, &err), cases[i].code, &err, cases[i].needle);
        CHECK_MSG(strstr(err.msg, cases[i].name) != NULL, "'%s' does not name %s", err.msg, cases[i].name);
    }
    /* f_rest_* with a gap: 9 properties but f_rest_9 instead of f_rest_8. */
    const char *props = "property float x\nproperty float y\nproperty float z\n"
                        "property float f_dc_0\nproperty float f_dc_1\nproperty float f_dc_2\nproperty float opacity\n"
                        "property float scale_0\nproperty float scale_1\nproperty float scale_2\nproperty float rot_0\n"
                        "property float rot_1\nproperty float rot_2\nproperty float rot_3\n";
    const char *line23 = "0 0 0 0 0 0 0 0 0 0 1 0 0 0 0 0 0 0 0 0 0 0 0\n";
    for (int variant = 0; variant < 5; variant++) {
        const char *names5[] = {"gap.ply", "ok_ascii.ply", "short.ply", "lines.ply", "junk.ply"};
        fx_str(&f, "ply\nformat ascii 1.0\n");
        fx_str(&f, variant <= 1 ? "element vertex 0\n" : "element vertex 2\n");
        fx_str(&f, props);
        for (int k = 0; k < 9; k++) {
            char line[64];
            snprintf(line, sizeof line, "property float f_rest_%d\n", k == 8 && variant == 0 ? 9 : k);
            fx_str(&f, line);
        }
        fx_str(&f, "end_header\n");
        fx_str(&f, line23);
        if (variant == 2) fx_str(&f, "0 0 0 0 0 0 0 0 0 0                                                 \n");
        if (variant == 3) fx_str(&f, "\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n");
        if (variant == 4) fx_str(&f, "0 0 0 0 0 0 0 0 0 0 1 0 0 0 0 0 0 0 0 0 0 0 0 zz\n");
        fx_write_buf(fx_path(p, sizeof p, dir, names5[variant]), &f);
        fx_free(&f);
    }
    CHECK_FAILS(sp_ply_read_splat(fx_path(p, sizeof p, dir, "gap.ply"), &s, &err), SP_E_FORMAT, &err,
                "f_rest_9 is out of sequence");
    CHECK_OK(sp_ply_read_splat(fx_path(p, sizeof p, dir, "ok_ascii.ply"), &s, &err), &err);
    CHECK(s.n == 0 && s.sh_degree == 1); /* vertex count 0: the data line is not read */
    sp_splat_free(&s);
    CHECK_FAILS(sp_ply_read_splat(fx_path(p, sizeof p, dir, "short.ply"), &s, &err), SP_E_FORMAT, &err,
                "(vertex 1): expected 23 numbers");
    CHECK(strstr(err.msg, "short.ply") != NULL);
    CHECK_FAILS(sp_ply_read_splat(fx_path(p, sizeof p, dir, "lines.ply"), &s, &err), SP_E_FORMAT, &err,
                "truncated: 1 of 2 vertices");
    CHECK_FAILS(sp_ply_read_splat(fx_path(p, sizeof p, dir, "junk.ply"), &s, &err), SP_E_FORMAT, &err, "found 'zz'");
    CHECK_FAILS(sp_ply_read_splat(fx_path(p, sizeof p, dir, "none.ply"), &s, &err), SP_E_IO, &err, "none.ply");
}

int main(void)
{
    RUN(test_handmade_3dgs);
    RUN(test_any_order_and_types);
    RUN(test_ascii);
    RUN(test_round_trip);
    RUN(test_bad);
    return TEST_EXIT();
}
