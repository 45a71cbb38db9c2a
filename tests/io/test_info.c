/* `semsplat info`: runs the built CLI on one file of each kind (written here) and checks that the
 * summary names what is in it, and that bad input gives a non-zero exit and a message. */
#include <sys/wait.h>

#include "io_fixture.h"
#include "semsplat/io.h"
#include "test.h"

static char out[16384];

/* Runs `semsplat info ARGS`, capturing stdout+stderr into out; returns the exit status. */
static int run_info(const char *args)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "'%s/semsplat' info %s 2>&1", SP_BUILD_DIR, args);
    FILE *p = popen(cmd, "r");
    if (!p) return -1;
    size_t n = fread(out, 1, sizeof out - 1, p);
    out[n] = 0;
    int st = pclose(p);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

#define HAS(s) CHECK_MSG(strstr(out, (s)) != NULL, "output lacks '%s':\n%s", (s), out)

static void test_info(void)
{
    char bin[1200];
    snprintf(bin, sizeof bin, "%s/semsplat", SP_BUILD_DIR);
    if (!sp_file_exists(bin)) TEST_SKIP("semsplat binary not built");
    const char *dir = test_tmpdir("io_info");
    char p[1024], args[1200];
    sp_error err = {0};

    /* A COLMAP capture root with sparse/0 holding one SIMPLE_RADIAL camera and two images. */
    sp_colmap_camera cam = {3, SP_COLMAP_SIMPLE_RADIAL, 64, 48, 4, {50, 32, 24, 0.01}};
    sp_colmap_image im[2] = {{1, {1, 0, 0, 0}, {0, 0, 0}, 3, "a.png", 0, NULL, NULL},
                             {2, {1, 0, 0, 0}, {-2, 0, 0}, 3, "b.png", 0, NULL, NULL}};
    sp_colmap_point pt = {7, {1, 2, 3}, {1, 2, 3}, 0.1, 0, NULL};
    sp_colmap_model m = {1, 2, 1, &cam, im, &pt};
    CHECK_OK(sp_colmap_write_bin(fx_path(p, sizeof p, dir, "capture/sparse/0"), &m, &err), &err);
    snprintf(args, sizeof args, "'%s/capture'", dir);
    CHECK(run_info(args) == 0);
    HAS("(binary)");
    HAS("cameras        1");
    HAS("camera 3     SIMPLE_RADIAL    64x48  params 50 32 24 0.01");
    HAS("images         2");
    HAS("points3D       1");
    HAS("camera centres [0 0 0] .. [2 0 0]");
    HAS("scene extent   1.1 ");

    sp_splat s;
    sp_splat_alloc(&s, 4, 1, 8, &err);
    for (int i = 0; i < 4; i++) s.means[3 * i] = (float)i;
    CHECK_OK(sp_ply_write_splat(fx_path(p, sizeof p, dir, "s.ply"), &s, &err), &err);
    sp_splat_free(&s);
    snprintf(args, sizeof args, "'%s'", p);
    CHECK(run_info(args) == 0);
    HAS("Gaussians      4");
    HAS("SH degree      1");
    HAS("feature dim    8");
    HAS("bounding box   [0 0 0] .. [3 0 0]");
    HAS("opacity        min 0.5000  mean 0.5000  max 0.5000");

    unsigned char px[12] = {0, 255, 0, 255, 0, 255, 0, 255, 0, 255, 0, 255};
    sp_image img = {2, 2, 3, 8, px};
    CHECK_OK(sp_image_write_png(fx_path(p, sizeof p, dir, "i.png"), &img, &err), &err);
    snprintf(args, sizeof args, "'%s'", p);
    CHECK(run_info(args) == 0);
    HAS("2x2, 3 channels (RGB), 8-bit");

    float v[6] = {-1, 0, 1, 2, 3, 4};
    size_t shape[2] = {3, 2};
    CHECK_OK(sp_npy_write(fx_path(p, sizeof p, dir, "a.npy"), SP_DTYPE_F32, 2, shape, v, &err), &err);
    snprintf(args, sizeof args, "'%s'", p);
    CHECK(run_info(args) == 0);
    HAS("dtype          float32");
    HAS("shape          (3, 2)");
    HAS("min -1  mean 1.5  max 4");

    uint16_t halves[12] = {0};
    sp_tensor_info t = {"text.proj", SP_DTYPE_F16, 2, {4, 3}, halves, sizeof halves};
    CHECK_OK(sp_safetensors_write(fx_path(p, sizeof p, dir, "m.safetensors"), &t, 1, &err), &err);
    snprintf(args, sizeof args, "'%s'", p);
    CHECK(run_info(args) == 0);
    HAS("tensors        1 (12 values");
    HAS("text.proj");
    HAS("float16  (4, 3)");

    fx_write_text(fx_path(p, sizeof p, dir, "x.dat"), "nothing we know");
    snprintf(args, sizeof args, "'%s'", p);
    CHECK(run_info(args) == 1);
    HAS("x.dat: not a COLMAP model");
    snprintf(args, sizeof args, "'%s/nowhere'", dir);
    CHECK(run_info(args) == 1);
    HAS("nowhere");
    CHECK(run_info("--help") == 0);
    HAS("usage: semsplat info");
    CHECK(run_info("--bogus") == 2);
}

int main(void)
{
    RUN(test_info);
    return TEST_EXIT();
}
