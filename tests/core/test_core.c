/* Tests for core: errors, thread pool, linear algebra, cameras, splat buffers, files. */
#include "semsplat/core.h"
#include "test.h"

#include <unistd.h>

static void test_error_messages(void)
{
    sp_error err = {0};
    int rc = sp_error_set(&err, SP_E_FORMAT, "%s: record %d is short", "images.bin", 12);
    CHECK(rc == SP_E_FORMAT);
    CHECK(strcmp(err.msg, "images.bin: record 12 is short") == 0);
    sp_error_prefix(&err, "loading %s: ", "scene");
    CHECK(strcmp(err.msg, "loading scene: images.bin: record 12 is short") == 0);
    CHECK(strcmp(sp_strerror(SP_E_IO), "I/O error") == 0);
    CHECK(sp_error_set(NULL, SP_E_ARG, "x") == SP_E_ARG);
    sp_error_clear(&err);
    CHECK(err.code == 0 && err.msg[0] == 0);
}

typedef struct { long n; double *out; } sq_ctx;
static void square(void *ctx, long i, int tid)
{
    sq_ctx *c = ctx;
    (void)tid;
    c->out[i] = (double)i * (double)i;
}

static void test_pool(void)
{
    sp_error err = {0};
    sp_pool *pool = NULL;
    CHECK_OK(sp_pool_create(&pool, 4, &err), &err);
    CHECK(sp_pool_size(pool) == 4);
    double out[1000];
    sq_ctx c = {1000, out};
    for (int rep = 0; rep < 50; rep++) {
        memset(out, 0, sizeof out);
        sp_pool_for(pool, 1000, square, &c);
        int ok = 1;
        for (long i = 0; i < 1000; i++) ok &= out[i] == (double)i * (double)i;
        CHECK(ok);
    }
    sp_pool_for(pool, 0, square, &c); /* no items: returns at once */
    sp_pool_free(pool);
    /* NULL pool runs serially. */
    memset(out, 0, sizeof out);
    sp_pool_for(NULL, 10, square, &c);
    CHECK(out[9] == 81.0);
}

static void test_quat_roundtrip(void)
{
    test_rng rng = {42};
    double worst = 0;
    for (int k = 0; k < 200; k++) {
        float q[4] = {(float)test_range(&rng, -1, 1), (float)test_range(&rng, -1, 1),
                      (float)test_range(&rng, -1, 1), (float)test_range(&rng, -1, 1)};
        float R[9], q2[4], R2[9];
        sp_quat_to_mat3(q, R);
        /* R is orthonormal with det +1. */
        float Rt[9], I[9];
        sp_mat3_transpose(R, Rt);
        sp_mat3_mul(R, Rt, I);
        for (int i = 0; i < 9; i++) worst = fmax(worst, fabs(I[i] - (i % 4 == 0 ? 1.0 : 0.0)));
        sp_mat3_to_quat(R, q2);
        CHECK(q2[0] >= 0);
        sp_quat_to_mat3(q2, R2);
        for (int i = 0; i < 9; i++) worst = fmax(worst, fabs(R[i] - R2[i]));
    }
    CHECK_MSG(worst < 1e-5, "worst %g", worst);
}

static void test_camera(void)
{
    sp_camera cam = {0};
    cam.width = 640; cam.height = 480; cam.fx = cam.fy = 500; cam.cx = 320; cam.cy = 240;
    sp_vec3 eye = sp_v3(1, 2, 1.5f), target = sp_v3(4, -1, 0.5f);
    sp_camera_look_at(&cam, eye, target, sp_v3(0, 0, 1));
    sp_vec3 c = sp_camera_center(&cam);
    CHECK_NEAR(c.x, 1, 1e-5); CHECK_NEAR(c.y, 2, 1e-5); CHECK_NEAR(c.z, 1.5, 1e-5);
    /* The target projects to the principal point, in front of the camera. */
    sp_vec3 p = sp_v3_add(sp_mat3_apply(cam.R, target), sp_v3(cam.t[0], cam.t[1], cam.t[2]));
    CHECK(p.z > 0);
    CHECK_NEAR(p.x / p.z, 0, 1e-5);
    CHECK_NEAR(p.y / p.z, 0, 1e-5);
    /* World up maps to image up (negative y in the OpenCV camera frame). */
    sp_vec3 up = sp_mat3_apply(cam.R, sp_v3(0, 0, 1));
    CHECK(up.y < 0);
    /* Rigid inverse of the 4x4 gives back the identity. */
    float M[16], Mi[16], I[16];
    sp_camera_world_to_cam(&cam, M);
    sp_mat4_rigid_inverse(M, Mi);
    sp_mat4_mul(M, Mi, I);
    double worst = 0;
    for (int i = 0; i < 16; i++) worst = fmax(worst, fabs(I[i] - (i % 5 == 0 ? 1.0 : 0.0)));
    CHECK(worst < 1e-5);
    sp_camera_downscale(&cam, 2);
    CHECK(cam.width == 320 && cam.height == 240);
    CHECK_NEAR(cam.fx, 250, 1e-4);
    CHECK_NEAR(cam.cx, 160, 1e-4);
}

static void test_splat_buffers(void)
{
    sp_error err = {0};
    sp_splat s, c;
    CHECK_OK(sp_splat_alloc(&s, 10, 3, 16, &err), &err);
    CHECK(s.quats[4] == 1.0f && s.quats[5] == 0.0f);
    s.sh[10 * 16 * 3 - 1] = 7.0f;
    s.features[10 * 16 - 1] = 3.0f;
    CHECK_OK(sp_splat_copy(&c, &s, &err), &err);
    CHECK(c.sh[10 * 16 * 3 - 1] == 7.0f && c.features[159] == 3.0f);
    CHECK_OK(sp_splat_check_finite(&c, &err), &err);
    c.log_scales[7] = NAN;
    CHECK_FAILS(sp_splat_check_finite(&c, &err), SP_E_NUMERIC, &err, "Gaussian 2");
    sp_splat_free(&c); /* before the failing alloc, which zeroes c */
    CHECK_FAILS(sp_splat_alloc(&c, 1, 4, 0, &err), SP_E_ARG, &err, "SH degree 4");
    sp_splat_free(&s);
    sp_splat_free(&s); /* freeing twice is harmless: free zeroes the struct */
}

static void test_files(void)
{
    sp_error err = {0};
    const char *dir = test_tmpdir("core_files");
    char sub[1100], path[1200];
    CHECK(sp_path_join(sub, sizeof sub, dir, "a/b/c") == 0);
    CHECK_OK(sp_mkdirs(sub, &err), &err);
    CHECK(sp_path_join(path, sizeof path, sub, "x.txt") == 0);
    CHECK_OK(sp_write_file_atomic(path, "hello", 5, &err), &err);
    char *data;
    size_t n;
    CHECK_OK(sp_read_file(path, &data, &n, &err), &err);
    CHECK(n == 5 && strcmp(data, "hello") == 0);
    free(data);
    CHECK_FAILS(sp_read_file("/nonexistent/zzz", &data, &n, &err), SP_E_IO, &err, "/nonexistent/zzz");
    char small[8];
    CHECK(sp_path_join(small, sizeof small, "abcdef", "ghij") == -1);
    CHECK(sp_file_exists(path) && !sp_file_exists("/nonexistent/zzz"));
}

static void test_progress_quiet(void)
{
    /* A progress bar with no sink or fd does nothing and does not crash. */
    sp_progress p;
    sp_progress_begin(&p, NULL, "x", 10, "steps");
    for (int i = 0; i <= 10; i++) sp_progress_update(&p, i, NULL);
    sp_progress_end(&p, NULL);
    sp_log quiet = sp_log_stderr(SP_LOG_INFO, 1);
    sp_progress_begin(&p, &quiet, "x", 10, "steps");
    sp_progress_update(&p, 5, "loss 1");
    sp_progress_end(&p, NULL);
    CHECK(p.step == 5);
}

int main(void)
{
    RUN(test_error_messages);
    RUN(test_pool);
    RUN(test_quat_roundtrip);
    RUN(test_camera);
    RUN(test_splat_buffers);
    RUN(test_files);
    RUN(test_progress_quiet);
    return TEST_EXIT();
}
