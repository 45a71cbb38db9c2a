/* frame.json: round trip, refusal of what is not a similarity (naming the field), the capture and
 * model look-ups (frame.json at the capture root when given sparse/0, synth's older captures by
 * their ground truth, plain COLMAP otherwise), and the model -> world maps for points and cameras
 * against a double-precision reference: a world point projects where its model point did. */
#include <math.h>

#include "semsplat/io.h"
#include "test.h"

/* world = 2 Rz(30 deg) Rx(10 deg) model + (1, -2, 3) */
static void make_similarity(double M[16])
{
    double a = 30 * M_PI / 180, b = 10 * M_PI / 180, s = 2;
    double Rz[9] = {cos(a), -sin(a), 0, sin(a), cos(a), 0, 0, 0, 1};
    double Rx[9] = {1, 0, 0, 0, cos(b), -sin(b), 0, sin(b), cos(b)};
    double t[3] = {1, -2, 3};
    memset(M, 0, 16 * sizeof(double));
    for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 3; c++) {
            double v = 0;
            for (int k = 0; k < 3; k++) v += Rz[r * 3 + k] * Rx[k * 3 + c];
            M[r * 4 + c] = s * v;
        }
        M[r * 4 + 3] = t[r];
    }
    M[15] = 1;
}

static void test_round_trip_and_checks(void)
{
    const char *dir = test_tmpdir("io_frame");
    char path[1200];
    snprintf(path, sizeof path, "%s/frame.json", dir);
    sp_error err = {0};
    sp_frame f, g;
    sp_frame_init(&f, "align");
    make_similarity(f.world_from_model);
    f.residual_m = 0.04;
    snprintf(f.note, sizeof f.note, "test");
    CHECK_OK(sp_frame_write(path, &f, &err), &err);
    CHECK_OK(sp_frame_read(path, &g, &err), &err);
    for (int i = 0; i < 16; i++) CHECK_NEAR(g.world_from_model[i], f.world_from_model[i], 1e-12);
    CHECK(!strcmp(g.source, "align") && !strcmp(g.up, "+z") && !strcmp(g.units, "m") && g.residual_m == 0.04);
    CHECK(sp_frame_is_world(&g) && !strcmp(sp_frame_name(&g), "world"));
    CHECK_NEAR(sp_frame_scale(&g), 2.0, 1e-12);
    sp_frame_init(&g, "colmap");
    CHECK(!sp_frame_is_world(&g) && !strcmp(g.units, "unknown"));
    /* the fit that made it rides along under "fit"; the reader takes the frame as before */
    CHECK_OK(sp_frame_write_fit(path, &f, "{\"inliers\": 44, \"outliers\": [{\"image\": \"a.png\"}]}", &err), &err);
    CHECK_OK(sp_frame_read(path, &g, &err), &err);
    CHECK(!strcmp(g.source, "align"));
    char *text = NULL;
    size_t tn = 0;
    CHECK_OK(sp_read_file(path, &text, &tn, &err), &err);
    CHECK(text && strstr(text, "\"fit\"") && strstr(text, "a.png"));
    free(text);
    CHECK_FAILS(sp_frame_write_fit(path, &f, "{not json", &err), SP_E_ARG, &err, "not JSON");
    /* what is not a similarity is refused before writing */
    sp_frame bad = f;
    bad.world_from_model[1] += 0.3; /* shear */
    CHECK_FAILS(sp_frame_write(path, &bad, &err), SP_E_FORMAT, &err, "not a similarity");
    bad = f;
    for (int c = 0; c < 3; c++) bad.world_from_model[c] = -bad.world_from_model[c]; /* a mirror */
    CHECK_FAILS(sp_frame_check(&bad, "f", &err), SP_E_FORMAT, &err, "determinant");
    bad = f;
    bad.world_from_model[14] = 1;
    CHECK_FAILS(sp_frame_check(&bad, "f", &err), SP_E_FORMAT, &err, "last row");
    bad = f;
    bad.world_from_model[7] = NAN;
    CHECK_FAILS(sp_frame_check(&bad, "f", &err), SP_E_FORMAT, &err, "world_from_model[1][3]");
    bad = f;
    bad.world_from_model[3] = 8.9e23; /* a float cannot carry it: refused, not inf later */
    CHECK_FAILS(sp_frame_check(&bad, "f", &err), SP_E_FORMAT, &err, "1000 km");
    /* every bit survives a write and a read (cJSON's 15-digit printing can move the last one) */
    bad = f;
    bad.world_from_model[7] = 0.1 + 0.2;
    CHECK_OK(sp_frame_write(path, &bad, &err), &err);
    CHECK_OK(sp_frame_read(path, &g, &err), &err);
    CHECK(!memcmp(g.world_from_model, bad.world_from_model, sizeof g.world_from_model));
    bad = f;
    snprintf(bad.source, sizeof bad.source, "gps");
    CHECK_FAILS(sp_frame_check(&bad, "f", &err), SP_E_FORMAT, &err, "gps");
    /* malformed files name the field */
    const char *texts[3] = {"{\"source\": \"align\", \"up\": \"+z\", \"units\": \"m\"}",
                            "{\"source\": \"align\", \"up\": \"+z\", \"units\": \"m\", \"world_from_model\": [[1,0,0,0],[0,1,0,0],[0,0,1,0]]}",
                            "{\"source\": 3, \"world_from_model\": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]}"};
    const char *needle[3] = {"world_from_model", "world_from_model", "source"};
    for (int k = 0; k < 3; k++) {
        CHECK_OK(sp_write_file_atomic(path, texts[k], strlen(texts[k]), &err), &err);
        CHECK_FAILS(sp_frame_read(path, &g, &err), SP_E_FORMAT, &err, needle[k]);
    }
}

static void touch(const char *dir, const char *name)
{
    char p[1400];
    sp_error err = {0};
    snprintf(p, sizeof p, "%s/%s", dir, name);
    CHECK_OK(sp_mkdirs(dir, &err), &err);
    CHECK_OK(sp_write_file_atomic(p, "{}", 2, &err), &err);
}

static void test_lookups(void)
{
    char cap[1200], sparse[1300], model[1300], p[1400];
    snprintf(cap, sizeof cap, "%s", test_tmpdir("io_frame_lookup"));
    snprintf(sparse, sizeof sparse, "%s/sparse/0", cap);
    snprintf(model, sizeof model, "%s/model", cap);
    sp_error err = {0};
    sp_frame f;
    CHECK_OK(sp_mkdirs(sparse, &err), &err);
    CHECK_OK(sp_frame_of_capture(sparse, &f, &err), &err);
    CHECK(!strcmp(f.source, "colmap"));
    touch(cap, "ground_truth.json"); /* a synth capture from before frame.json */
    CHECK_OK(sp_frame_of_capture(sparse, &f, &err), &err);
    CHECK(!strcmp(f.source, "synth"));
    sp_frame a;
    sp_frame_init(&a, "align");
    make_similarity(a.world_from_model);
    snprintf(p, sizeof p, "%s/frame.json", cap);
    CHECK_OK(sp_frame_write(p, &a, &err), &err);
    CHECK_OK(sp_frame_of_capture(sparse, &f, &err), &err); /* the root's frame.json, from sparse/0 */
    CHECK(!strcmp(f.source, "align") && f.world_from_model[3] == 1);
    CHECK_OK(sp_frame_of_capture(cap, &f, &err), &err);
    CHECK(!strcmp(f.source, "align"));
    /* a model folder without frame.json takes its capture's; with one, its own */
    CHECK_OK(sp_mkdirs(model, &err), &err);
    CHECK_OK(sp_frame_of_model(model, sparse, &f, &err), &err);
    CHECK(!strcmp(f.source, "align"));
    sp_frame s;
    sp_frame_init(&s, "synth");
    snprintf(p, sizeof p, "%s/frame.json", model);
    CHECK_OK(sp_frame_write(p, &s, &err), &err);
    CHECK_OK(sp_frame_of_model(model, sparse, &f, &err), &err);
    CHECK(!strcmp(f.source, "synth"));
    CHECK_OK(sp_frame_of_model(cap, NULL, &f, &err), &err);
    CHECK(!strcmp(f.source, "align"));
}

/* Projection in double: pixel of world point p through camera (R, t, fx, fy, cx, cy). */
static void project(const sp_camera *c, const double p[3], double uv[2])
{
    double x[3];
    for (int r = 0; r < 3; r++) x[r] = c->R[r * 3] * p[0] + c->R[r * 3 + 1] * p[1] + c->R[r * 3 + 2] * p[2] + c->t[r];
    uv[0] = c->fx * x[0] / x[2] + c->cx;
    uv[1] = c->fy * x[1] / x[2] + c->cy;
}

static void test_apply(void)
{
    sp_frame f;
    sp_frame_init(&f, "align");
    make_similarity(f.world_from_model);
    sp_camera cam = {0};
    cam.width = 640, cam.height = 480, cam.fx = cam.fy = 500, cam.cx = 320, cam.cy = 240;
    sp_camera_look_at(&cam, sp_v3(3, 1, 1.2f), sp_v3(0, 0, 0.5f), sp_v3(0, 0, 1));
    sp_camera w = cam;
    sp_frame_apply_camera(&f, &w);
    test_rng r = {5};
    const double *M = f.world_from_model;
    for (int k = 0; k < 50; k++) {
        float pm[3] = {(float)test_range(&r, -1, 1), (float)test_range(&r, -1, 1), (float)test_range(&r, 0, 1)};
        float pw[3];
        sp_frame_apply_point(&f, pm, pw);
        double ref[3], pmd[3] = {pm[0], pm[1], pm[2]}, pwd[3] = {pw[0], pw[1], pw[2]}, a[2], b[2];
        for (int i = 0; i < 3; i++) ref[i] = M[i * 4] * pm[0] + M[i * 4 + 1] * pm[1] + M[i * 4 + 2] * pm[2] + M[i * 4 + 3];
        for (int i = 0; i < 3; i++) CHECK_NEAR(pw[i], ref[i], 1e-5);
        project(&cam, pmd, a);
        project(&w, pwd, b);
        CHECK_NEAR(a[0], b[0], 2e-3);
        CHECK_NEAR(a[1], b[1], 2e-3);
    }
    /* the world camera's centre is the model centre mapped, and R stays a rotation */
    sp_vec3 cm = sp_camera_center(&cam), cw = sp_camera_center(&w);
    float cmf[3] = {cm.x, cm.y, cm.z}, exp[3];
    sp_frame_apply_point(&f, cmf, exp);
    CHECK_NEAR(cw.x, exp[0], 1e-4);
    CHECK_NEAR(cw.y, exp[1], 1e-4);
    CHECK_NEAR(cw.z, exp[2], 1e-4);
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) {
            double d = 0;
            for (int k = 0; k < 3; k++) d += (double)w.R[a * 3 + k] * w.R[b * 3 + k];
            CHECK_NEAR(d, a == b, 1e-5);
        }
}

int main(void)
{
    RUN(test_round_trip_and_checks);
    RUN(test_lookups);
    RUN(test_apply);
    return TEST_EXIT();
}
