/* COLMAP models: binary files written byte by byte from COLMAP's documented layout
 * (src/colmap/scene/reconstruction_io.cc: cameras.bin, images.bin, points3D.bin) and text files as
 * COLMAP writes them; byte-exact binary round trip; text round trip; model lookup from a capture
 * root; conversion to sp_camera checked against an independent quaternion rotation; and one test
 * per way a file can be bad. */
#include "io_fixture.h"
#include "semsplat/io.h"
#include "test.h"

#define NONE UINT64_MAX /* COLMAP's invalid point3D_id */

/* cameras.bin: u64 count; per camera u32 id, i32 model, u64 width, u64 height, f64 params[]. */
static void build_cameras(fx_buf *f)
{
    fx_u64(f, 2);
    fx_u32(f, 1); fx_i32(f, 1); fx_u64(f, 640); fx_u64(f, 480); /* PINHOLE fx fy cx cy */
    fx_f64(f, 500); fx_f64(f, 510); fx_f64(f, 320); fx_f64(f, 240);
    fx_u32(f, 2); fx_i32(f, 4); fx_u64(f, 800); fx_u64(f, 600); /* OPENCV */
    double p[8] = {700, 705, 400, 300, -0.1, 0.01, 0.001, -0.002};
    for (int k = 0; k < 8; k++) fx_f64(f, p[k]);
}

/* images.bin: u64 count; per image u32 id, f64 qw qx qy qz, f64 tx ty tz, u32 camera_id, name,
 * NUL, u64 n_points2D, then (f64 x, f64 y, u64 point3D_id) each. */
#define IMG1_QW 12
#define IMG1_CAM 68
#define IMG1_NP 78
static void build_images(fx_buf *f)
{
    fx_u64(f, 2);
    fx_u32(f, 1);
    fx_f64(f, 1); fx_f64(f, 0); fx_f64(f, 0); fx_f64(f, 0);
    fx_f64(f, 0); fx_f64(f, 0); fx_f64(f, 2);
    fx_u32(f, 1);
    fx_strz(f, "a.png");
    fx_u64(f, 2);
    fx_f64(f, 10.5); fx_f64(f, 20.25); fx_u64(f, 0);
    fx_f64(f, 30); fx_f64(f, 40); fx_u64(f, NONE);
    fx_u32(f, 5); /* 90 degrees about z */
    fx_f64(f, sqrt(0.5)); fx_f64(f, 0); fx_f64(f, 0); fx_f64(f, sqrt(0.5));
    fx_f64(f, 1); fx_f64(f, 2); fx_f64(f, 3);
    fx_u32(f, 2);
    fx_strz(f, "sub dir/b.jpg");
    fx_u64(f, 0);
}

/* points3D.bin: u64 count; per point u64 id, f64 xyz, u8 rgb, f64 error, u64 track length, then
 * (u32 image_id, u32 point2D_idx) each. */
#define PT_X 16
#define PT_TL 51
static void build_points(fx_buf *f)
{
    fx_u64(f, 1);
    fx_u64(f, 0);
    fx_f64(f, 0.1); fx_f64(f, 0.2); fx_f64(f, 0.3);
    fx_u8(f, 255); fx_u8(f, 128); fx_u8(f, 0);
    fx_f64(f, 0.5);
    fx_u64(f, 2);
    fx_u32(f, 1); fx_u32(f, 0);
    fx_u32(f, 5); fx_u32(f, 3);
}

static const char *names[3] = {"cameras.bin", "images.bin", "points3D.bin"};

static void write_model(const char *dir)
{
    fx_buf f[3] = {{0}};
    build_cameras(&f[0]);
    build_images(&f[1]);
    build_points(&f[2]);
    char p[1024];
    for (int i = 0; i < 3; i++) {
        fx_write_buf(fx_path(p, sizeof p, dir, names[i]), &f[i]);
        fx_free(&f[i]);
    }
}

static void check_model(const sp_colmap_model *m)
{
    CHECK(m->n_cameras == 2 && m->n_images == 2 && m->n_points == 1);
    if (m->n_cameras != 2 || m->n_images != 2 || m->n_points != 1) return;
    CHECK(m->cameras[0].id == 1 && m->cameras[0].model == SP_COLMAP_PINHOLE && m->cameras[0].width == 640 &&
          m->cameras[0].n_params == 4 && m->cameras[0].params[1] == 510);
    CHECK(m->cameras[1].model == SP_COLMAP_OPENCV && m->cameras[1].n_params == 8 && m->cameras[1].params[7] == -0.002);
    const sp_colmap_image *a = &m->images[0], *b = &m->images[1];
    CHECK(a->id == 1 && a->camera_id == 1 && !strcmp(a->name, "a.png") && a->tvec[2] == 2 && a->n_points2d == 2);
    CHECK(a->n_points2d == 2 && a->xys[1] == 20.25 && a->point3d_ids[0] == 0 && a->point3d_ids[1] == -1);
    CHECK(b->id == 5 && !strcmp(b->name, "sub dir/b.jpg") && b->n_points2d == 0 && b->qvec[3] == sqrt(0.5));
    const sp_colmap_point *p = &m->points[0];
    CHECK(p->id == 0 && p->xyz[2] == 0.3 && p->rgb[1] == 128 && p->error == 0.5 && p->track_len == 2);
    CHECK(p->track_len == 2 && p->track[2] == 5 && p->track[3] == 3);
}

static int same_file(const char *a, const char *b)
{
    size_t na = 0, nb = 0;
    unsigned char *x = fx_slurp(a, &na), *y = fx_slurp(b, &nb);
    int same = x && y && na == nb && memcmp(x, y, na) == 0;
    free(x);
    free(y);
    return same;
}

static void test_bin_handmade_and_round_trip(void)
{
    const char *dir = test_tmpdir("io_colmap_bin");
    char in[1024], out[1024], a[1024], b[1024];
    fx_path(in, sizeof in, dir, "in");
    fx_path(out, sizeof out, dir, "out");
    sp_mkdirs(in, NULL);
    write_model(in);
    sp_error err = {0};
    sp_colmap_model m;
    CHECK_OK(sp_colmap_read_bin(in, &m, &err), &err);
    check_model(&m);
    CHECK_OK(sp_colmap_write_bin(out, &m, &err), &err);
    for (int i = 0; i < 3; i++)
        CHECK_MSG(same_file(fx_path(a, sizeof a, in, names[i]), fx_path(b, sizeof b, out, names[i])),
                  "%s differs after a round trip", names[i]);
    sp_colmap_free(&m);
    sp_colmap_free(&m); /* idempotent */
}

static const char *CAMERAS_TXT =
    "# Camera list with one line of data per camera:\n"
    "#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n"
    "# Number of cameras: 2\n"
    "1 PINHOLE 640 480 500 510 320 240\n"
    "2 OPENCV 800 600 700 705 400 300 -0.10000000000000001 0.01 0.001 -0.002\n";
static const char *IMAGES_TXT =
    "# Image list with two lines of data per image:\n"
    "#   IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n"
    "#   POINTS2D[] as (X, Y, POINT3D_ID)\n"
    "# Number of images: 2, mean observations per image: 1\n"
    "1 1 0 0 0 0 0 2 1 a.png\r\n"
    "10.5 20.25 0 30 40 -1\r\n"
    "5 0.70710678118654757 0 0 0.70710678118654757 1 2 3 2 sub dir/b.jpg\n"
    "\n";
static const char *POINTS_TXT =
    "# 3D point list with one line of data per point:\n"
    "#   POINT3D_ID, X, Y, Z, R, G, B, ERROR, TRACK[] as (IMAGE_ID, POINT2D_IDX)\n"
    "# Number of points: 1, mean track length: 2\n"
    "0 0.10000000000000001 0.20000000000000001 0.29999999999999999 255 128 0 0.5 1 0 5 3\n";

static void write_txt(const char *dir, const char *cams, const char *imgs, const char *pts)
{
    char p[1024];
    sp_mkdirs(dir, NULL);
    fx_write_text(fx_path(p, sizeof p, dir, "cameras.txt"), cams);
    fx_write_text(fx_path(p, sizeof p, dir, "images.txt"), imgs);
    fx_write_text(fx_path(p, sizeof p, dir, "points3D.txt"), pts);
}

static void test_txt(void)
{
    const char *dir = test_tmpdir("io_colmap_txt");
    char in[1024], out[1024], bin[1024], hand[1024], a[1024], b[1024];
    write_txt(fx_path(in, sizeof in, dir, "in"), CAMERAS_TXT, IMAGES_TXT, POINTS_TXT);
    sp_error err = {0};
    sp_colmap_model m, m2;
    CHECK_OK(sp_colmap_read_txt(in, &m, &err), &err);
    check_model(&m);
    CHECK_OK(sp_colmap_write_txt(fx_path(out, sizeof out, dir, "out"), &m, &err), &err);
    CHECK_OK(sp_colmap_read_txt(out, &m2, &err), &err);
    check_model(&m2);
    /* Text -> binary gives the same bytes as the hand-built binary files. */
    CHECK_OK(sp_colmap_write_bin(fx_path(bin, sizeof bin, dir, "bin"), &m2, &err), &err);
    sp_mkdirs(fx_path(hand, sizeof hand, dir, "hand"), NULL);
    write_model(hand);
    for (int i = 0; i < 3; i++)
        CHECK_MSG(same_file(fx_path(a, sizeof a, hand, names[i]), fx_path(b, sizeof b, bin, names[i])),
                  "%s from text differs from the hand-built one", names[i]);
    sp_colmap_free(&m);
    sp_colmap_free(&m2);
}

static void test_models_and_lookup(void)
{
    static const char *expect[] = {"SIMPLE_PINHOLE", "PINHOLE", "SIMPLE_RADIAL", "RADIAL", "OPENCV", "OPENCV_FISHEYE",
                                   "FULL_OPENCV", "FOV", "SIMPLE_RADIAL_FISHEYE", "RADIAL_FISHEYE", "THIN_PRISM_FISHEYE"};
    static const int np[] = {3, 4, 4, 5, 8, 8, 12, 5, 4, 5, 12};
    for (int i = 0; i <= SP_COLMAP_THIN_PRISM_FISHEYE; i++) {
        CHECK(sp_colmap_model_name(i) && !strcmp(sp_colmap_model_name(i), expect[i]));
        CHECK(sp_colmap_model_num_params(i) == np[i]);
        CHECK(sp_colmap_model_from_name(expect[i]) == i);
    }
    CHECK(sp_colmap_model_name(-1) == NULL && sp_colmap_model_name(99) == NULL);
    CHECK(sp_colmap_model_num_params(99) == -1 && sp_colmap_model_from_name("PINHOLEX") == -1);

    const char *root = test_tmpdir("io_colmap_find");
    char p[1024], out[1024];
    sp_error err = {0};
    CHECK_FAILS(sp_colmap_find_model_dir(root, out, sizeof out, &err), SP_E_NOTFOUND, &err, "no COLMAP model");
    sp_mkdirs(fx_path(p, sizeof p, root, "sparse"), NULL);
    write_txt(p, CAMERAS_TXT, IMAGES_TXT, POINTS_TXT);
    CHECK_OK(sp_colmap_find_model_dir(root, out, sizeof out, &err), &err);
    CHECK(strcmp(out, p) == 0);
    sp_mkdirs(fx_path(p, sizeof p, root, "sparse/0"), NULL);
    write_model(p);
    CHECK_OK(sp_colmap_find_model_dir(root, out, sizeof out, &err), &err);
    CHECK(strcmp(out, p) == 0); /* sparse/0 wins over sparse */
    CHECK_OK(sp_colmap_find_model_dir(p, out, sizeof out, &err), &err);
    CHECK(strcmp(out, p) == 0);
    sp_colmap_model m;
    CHECK_OK(sp_colmap_read(root, &m, &err), &err); /* the capture root works for reading too */
    check_model(&m);
    sp_colmap_free(&m);
}

/* v rotated by unit quaternion q: v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z). */
static void quat_rotate(const double q[4], const double v[3], double out[3])
{
    double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    double w = q[0] / n, u[3] = {q[1] / n, q[2] / n, q[3] / n};
    double c1[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    double c2[3] = {u[1] * c1[2] - u[2] * c1[1], u[2] * c1[0] - u[0] * c1[2], u[0] * c1[1] - u[1] * c1[0]};
    for (int k = 0; k < 3; k++) out[k] = v[k] + 2 * w * c1[k] + 2 * c2[k];
}

static void test_image_camera(void)
{
    sp_error err = {0};
    sp_colmap_camera cams[6] = {
        {1, SP_COLMAP_SIMPLE_PINHOLE, 100, 80, 3, {90, 50, 40}},
        {2, SP_COLMAP_PINHOLE, 100, 80, 4, {90, 95, 50, 40}},
        {3, SP_COLMAP_SIMPLE_RADIAL, 100, 80, 4, {90, 50, 40, 0.05}},
        {4, SP_COLMAP_RADIAL, 100, 80, 5, {90, 50, 40, 0.05, -0.01}},
        {5, SP_COLMAP_OPENCV, 100, 80, 8, {90, 95, 50, 40, 0.1, 0.2, 0.003, 0.004}},
        {6, SP_COLMAP_FULL_OPENCV, 100, 80, 12, {90, 95, 50, 40}},
    };
    sp_colmap_image imgs[7];
    memset(imgs, 0, sizeof imgs);
    char names_buf[7][16];
    test_rng rng = {3};
    for (int i = 0; i < 7; i++) {
        snprintf(names_buf[i], 16, "img%d.png", i);
        imgs[i].id = (uint32_t)i + 1;
        imgs[i].camera_id = i < 6 ? (uint32_t)i + 1 : 42;
        imgs[i].name = names_buf[i];
        for (int k = 0; k < 4; k++) imgs[i].qvec[k] = test_range(&rng, -1, 1) * 3; /* unnormalised */
        for (int k = 0; k < 3; k++) imgs[i].tvec[k] = test_range(&rng, -5, 5);
    }
    sp_colmap_model m = {6, 7, 0, cams, imgs, NULL};
    for (size_t i = 0; i < 5; i++) {
        sp_camera c;
        CHECK_OK(sp_colmap_image_camera(&m, i, &c, &err), &err);
        CHECK(c.width == 100 && c.height == 80);
        /* R applied to each axis equals rotating it with the quaternion. */
        for (int axis = 0; axis < 3; axis++) {
            double v[3] = {axis == 0, axis == 1, axis == 2}, r[3];
            quat_rotate(imgs[i].qvec, v, r);
            for (int row = 0; row < 3; row++) CHECK_NEAR(c.R[row * 3 + axis], r[row], 1e-6);
        }
        for (int k = 0; k < 3; k++) CHECK_NEAR(c.t[k], imgs[i].tvec[k], 1e-6);
    }
    sp_camera c;
    sp_colmap_image_camera(&m, 0, &c, &err);
    CHECK(c.fx == 90 && c.fy == 90 && c.cx == 50 && c.cy == 40 && c.distortion == SP_DIST_NONE);
    sp_colmap_image_camera(&m, 1, &c, &err);
    CHECK(c.fx == 90 && c.fy == 95 && c.distortion == SP_DIST_NONE);
    sp_colmap_image_camera(&m, 2, &c, &err);
    CHECK(c.distortion == SP_DIST_SIMPLE_RADIAL && c.dist[0] == 0.05f);
    sp_colmap_image_camera(&m, 3, &c, &err);
    CHECK(c.distortion == SP_DIST_RADIAL && c.dist[1] == -0.01f);
    sp_colmap_image_camera(&m, 4, &c, &err);
    CHECK(c.distortion == SP_DIST_OPENCV && c.dist[0] == 0.1f && c.dist[3] == 0.004f && c.fy == 95);
    CHECK_FAILS(sp_colmap_image_camera(&m, 5, &c, &err), SP_E_UNSUPPORTED, &err, "FULL_OPENCV");
    CHECK(strstr(err.msg, "img5.png") != NULL);
    CHECK_FAILS(sp_colmap_image_camera(&m, 6, &c, &err), SP_E_NOTFOUND, &err, "camera 42");
    CHECK_FAILS(sp_colmap_image_camera(&m, 7, &c, &err), SP_E_ARG, &err, "out of range");
    imgs[0].qvec[0] = imgs[0].qvec[1] = imgs[0].qvec[2] = imgs[0].qvec[3] = 0;
    CHECK_FAILS(sp_colmap_image_camera(&m, 0, &c, &err), SP_E_NUMERIC, &err, "quaternion");
}

/* ---- bad binary files: copies of the good model with one file patched or cut ------------------- */

static char bad_root[1024];

static const char *bad_case(const char *name, int file, size_t offset, const void *bytes, size_t n, long keep)
{
    static char dir[1024];
    char p[1024];
    fx_path(dir, sizeof dir, bad_root, name);
    sp_mkdirs(dir, NULL);
    write_model(dir);
    fx_path(p, sizeof p, dir, names[file]);
    size_t len = 0;
    unsigned char *b = fx_slurp(p, &len);
    if (bytes && offset + n > len) b = realloc(b, offset + n); /* appending past the end */
    if (bytes) memcpy(b + offset, bytes, n);
    if (keep >= 0) len = (size_t)keep;
    if (bytes && offset + n > len) len = offset + n;
    fx_write(p, b, len);
    free(b);
    return dir;
}

static void test_bad_bin(void)
{
    snprintf(bad_root, sizeof bad_root, "%s", test_tmpdir("io_colmap_bad"));
    sp_error err = {0};
    sp_colmap_model m;
    uint64_t huge = 1ull << 40;
    double nan = NAN, inf = INFINITY;
    uint32_t cam9 = 9;
    int32_t model42 = 42;
    uint64_t zero = 0;
    const unsigned char extra[4] = {1, 2, 3, 4};
    struct {
        const char *name;
        int file;
        size_t off;
        const void *bytes;
        size_t n;
        long keep;
        int code;
        const char *needle;
    } cases[] = {
        {"cam_trunc", 0, 0, NULL, 0, 120, SP_E_FORMAT, "truncated in camera 1 of 2"},
        {"cam_header", 0, 0, NULL, 0, 5, SP_E_FORMAT, "truncated header"},
        {"cam_count", 0, 0, &huge, 8, -1, SP_E_FORMAT, "header says 1099511627776 cameras"},
        {"cam_model", 0, 12, &model42, 4, -1, SP_E_FORMAT, "unknown model id 42"},
        {"cam_nan", 0, 32, &nan, 8, -1, SP_E_NUMERIC, "camera 1 (PINHOLE) has a non-finite parameter"},
        {"cam_width0", 0, 16, &zero, 8, -1, SP_E_FORMAT, "camera 1 has size 0x480"},
        {"cam_dup", 0, 64, "\x01\0\0\0", 4, -1, SP_E_FORMAT, "camera id 1 appears twice"},
        {"cam_extra", 0, 152, extra, 4, -1, SP_E_FORMAT, "4 unexpected bytes"},
        {"img_count", 1, 0, &huge, 8, -1, SP_E_FORMAT, "header says 1099511627776 images"},
        {"img_np", 1, IMG1_NP, &huge, 8, -1, SP_E_FORMAT, "('a.png') says 1099511627776 points2D but only 134 bytes follow"},
        {"img_qnan", 1, IMG1_QW, &nan, 8, -1, SP_E_NUMERIC, "image 1 ('a.png') has a non-finite pose"},
        {"img_tinf", 1, IMG1_QW + 48, &inf, 8, -1, SP_E_NUMERIC, "non-finite pose"},
        {"img_cam", 1, IMG1_CAM, &cam9, 4, -1, SP_E_FORMAT, "image 1 ('a.png') names camera 9"},
        {"img_name", 1, 0, NULL, 0, 200, SP_E_FORMAT, "truncated in image 1 of 2"},
        {"img_pts", 1, 0, NULL, 0, 120, SP_E_FORMAT, "header says 2 images but only 112 bytes follow"},
        {"pt_count", 2, 0, &huge, 8, -1, SP_E_FORMAT, "header says 1099511627776 points"},
        {"pt_track", 2, PT_TL, &huge, 8, -1, SP_E_FORMAT, "track length 1099511627776"},
        {"pt_nan", 2, PT_X, &nan, 8, -1, SP_E_NUMERIC, "point3D 0 (record 0) has a non-finite position"},
        {"pt_trunc", 2, 0, NULL, 0, 40, SP_E_FORMAT, "header says 1 points but only 32 bytes follow"},
        {"pt_trunc2", 2, 0, NULL, 0, 65, SP_E_FORMAT, "track length 2 but only 6 bytes follow"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const char *dir = bad_case(cases[i].name, cases[i].file, cases[i].off, cases[i].bytes, cases[i].n, cases[i].keep);
        memset(&m, 0x5A, sizeof m);
        CHECK_FAILS(sp_colmap_read_bin(dir, &m, &err), cases[i].code, &err, cases[i].needle);
        CHECK_MSG(strstr(err.msg, names[cases[i].file]) != NULL, "case %s: '%s' does not name %s", cases[i].name,
                  err.msg, names[cases[i].file]);
        CHECK(m.cameras == NULL && m.images == NULL && m.points == NULL && m.n_images == 0);
    }
    CHECK_FAILS(sp_colmap_read_bin("/nonexistent/model", &m, &err), SP_E_IO, &err, "cameras.bin");
    CHECK_FAILS(sp_colmap_read("/nonexistent/model", &m, &err), SP_E_NOTFOUND, &err, "/nonexistent/model");
}

static void test_bad_txt(void)
{
    const char *root = test_tmpdir("io_colmap_badtxt");
    sp_error err = {0};
    sp_colmap_model m;
    char dir[1024];
    struct {
        const char *name, *cams, *imgs, *pts;
        int code;
        const char *needle;
    } cases[] = {
        {"width", "# c\n1 PINHOLE 640 480 1 1 1 1\n2 PINHOLE abc 480 1 1 1 1\n", IMAGES_TXT, POINTS_TXT, SP_E_FORMAT,
         "cameras.txt:3: bad WIDTH 'abc'"},
        {"nparams", "1 PINHOLE 640 480 1 1 1\n", IMAGES_TXT, POINTS_TXT, SP_E_FORMAT,
         "cameras.txt:1: camera 1 model PINHOLE needs 4 params, found 3"},
        {"model", "1 PINHOLEX 640 480 1 1 1 1\n", IMAGES_TXT, POINTS_TXT, SP_E_FORMAT, "cameras.txt:1: unknown camera model 'PINHOLEX'"},
        {"param", "1 PINHOLE 640 480 1 1 1x 1\n", IMAGES_TXT, POINTS_TXT, SP_E_FORMAT, "cameras.txt:1: bad PARAMS '1x'"},
        {"negw", "1 PINHOLE -640 480 1 1 1 1\n", IMAGES_TXT, POINTS_TXT, SP_E_FORMAT, "bad WIDTH '-640'"},
        {"pnan", "1 PINHOLE 640 480 nan 1 1 1\n2 OPENCV 8 6 1 1 1 1 0 0 0 0\n", IMAGES_TXT, POINTS_TXT, SP_E_NUMERIC,
         "cameras.txt:1: camera 1 (PINHOLE) has a non-finite parameter"},
        {"imgshort", CAMERAS_TXT, "# x\n\n1 1 0 0 0 0 0 2\n\n", POINTS_TXT, SP_E_FORMAT,
         "images.txt:3: expected IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME"},
        {"imgtx", CAMERAS_TXT, "1 1 0 0 0 zero 0 2 1 a.png\n\n", POINTS_TXT, SP_E_FORMAT, "images.txt:1: bad TX 'zero'"},
        {"imginf", CAMERAS_TXT, "1 1 0 0 0 0 inf 2 1 a.png\n\n", POINTS_TXT, SP_E_NUMERIC, "images.txt:1: image 1 ('a.png') has a non-finite pose"},
        {"pts3", CAMERAS_TXT, "1 1 0 0 0 0 0 2 1 a.png\n1 2 3 4\n", POINTS_TXT, SP_E_FORMAT,
         "images.txt:2: POINTS2D line of image 1 has 4 fields"},
        {"ptid", CAMERAS_TXT, "1 1 0 0 0 0 0 2 1 a.png\n1 2 -7\n", POINTS_TXT, SP_E_FORMAT, "images.txt:2: bad POINT3D_ID '-7'"},
        {"unkcam", CAMERAS_TXT, "1 1 0 0 0 0 0 2 3 a.png\n\n", POINTS_TXT, SP_E_FORMAT, "image 1 ('a.png') names camera 3"},
        {"rgb", CAMERAS_TXT, IMAGES_TXT, "# p\n0 1 2 3 300 0 0 0.5\n", SP_E_FORMAT, "points3D.txt:2: bad R '300'"},
        {"track", CAMERAS_TXT, IMAGES_TXT, "0 1 2 3 1 0 0 0.5 1\n", SP_E_FORMAT, "points3D.txt:1: expected POINT3D_ID"},
        {"ptnan", CAMERAS_TXT, IMAGES_TXT, "0 1 nan 3 1 0 0 0.5\n", SP_E_NUMERIC, "points3D.txt:1: point3D 0"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        write_txt(fx_path(dir, sizeof dir, root, cases[i].name), cases[i].cams, cases[i].imgs, cases[i].pts);
        CHECK_FAILS(sp_colmap_read_txt(dir, &m, &err), cases[i].code, &err, cases[i].needle);
        CHECK(m.cameras == NULL && m.images == NULL && m.points == NULL);
    }
    /* A binary file named .txt. */
    fx_buf f = {0};
    build_cameras(&f);
    fx_write_buf(fx_path(dir, sizeof dir, root, "width/cameras.txt"), &f);
    fx_free(&f);
    fx_path(dir, sizeof dir, root, "width");
    CHECK_FAILS(sp_colmap_read_txt(dir, &m, &err), SP_E_FORMAT, &err, "NUL bytes");
}

int main(void)
{
    RUN(test_bin_handmade_and_round_trip);
    RUN(test_txt);
    RUN(test_models_and_lookup);
    RUN(test_image_camera);
    RUN(test_bad_bin);
    RUN(test_bad_txt);
    return TEST_EXIT();
}
