/* media: the view-quality proxy. A synth render of a small room reads near the sharp anchor, the
 * same render blurred reads blurrier step by step and near the blurry anchor at 2 px; coverage
 * follows alpha; an empty or flat view grades 1; bad input is refused. */
#include "eval/small_world.h"
#include "semsplat/media.h"
#include "semsplat/synth.h"
#include "test.h"

static void gblur(float *im, int w, int h, float s)
{
    int r = (int)ceilf(3 * s);
    float k[64], sum = 0;
    for (int i = -r; i <= r; i++) sum += k[i + r] = expf(-(float)(i * i) / (2 * s * s));
    for (int i = 0; i <= 2 * r; i++) k[i] /= sum;
    float *t = malloc((size_t)w * h * 3 * sizeof *t);
    for (int pass = 0; pass < 2; pass++) {
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++)
                for (int c = 0; c < 3; c++) {
                    float a = 0;
                    for (int i = -r; i <= r; i++) {
                        int xx = pass ? x : x + i, yy = pass ? y + i : y;
                        xx = xx < 0 ? 0 : xx >= w ? w - 1 : xx;
                        yy = yy < 0 ? 0 : yy >= h ? h - 1 : yy;
                        a += k[i + r] * im[((size_t)yy * w + xx) * 3 + c];
                    }
                    t[((size_t)y * w + x) * 3 + c] = a;
                }
        memcpy(im, t, (size_t)w * h * 3 * sizeof *t);
    }
    free(t);
}

static void test_blur_scale_on_a_render(void)
{
    sp_error err = {0};
    char path[1300];
    snprintf(path, sizeof path, "%s/small_flat.world", test_tmpdir("media_quality"));
    CHECK(small_world_write(path, SMALL_WORLD_FRIDGE_X, SMALL_WORLD_FRIDGE_Y) == 0);
    sp_world w;
    sp_synth_load_opts lo = {.no_env = 1};
    CHECK_OK(sp_synth_load_world(path, &lo, &w, &err), &err);
    if (err.code) return;
    const int W = 320, H = 240;
    sp_camera cam = {.width = W, .height = H, .fx = 228, .fy = 228, .cx = W / 2.0f, .cy = H / 2.0f};
    sp_camera_look_at(&cam, sp_v3(3.2f, 1.0f, 1.0f), sp_v3(0.5f, 3.2f, 0.7f), sp_v3(0, 0, 1));
    sp_synth_frame f = {0};
    CHECK_OK(sp_synth_render(&w, &cam, NULL, NULL, &f, &err), &err);
    if (err.code) return;
    sp_view_quality q[4];
    const float sig[4] = {0, 1, 2, 3};
    float *im = malloc((size_t)W * H * 3 * sizeof *im);
    for (int s = 0; s < 4; s++) {
        memcpy(im, f.rgb, (size_t)W * H * 3 * sizeof *im);
        if (sig[s] > 0) gblur(im, W, H, sig[s]);
        CHECK_OK(sp_media_view_quality(im, NULL, W, H, &q[s], &err), &err);
        fprintf(stderr, "blur at +%g px: %.3f (grade %d)\n", sig[s], q[s].blur, q[s].grade);
        if (s) CHECK(q[s].blur > q[s - 1].blur + 0.05);
    }
    /* flat-coloured boxes read blurrier than the house (0.41 against 0.31 at 320x240): the
     * metric depends on content, which is why it only grades views and decides nothing alone */
    CHECK_NEAR(q[0].blur, SP_BLUR_SHARP, 0.12);
    CHECK_NEAR(q[2].blur, SP_BLUR_BLURRY, 0.1);
    CHECK(q[0].grade >= 4 && q[3].grade == 1);
    CHECK_NEAR(q[0].coverage, 1, 1e-9);
    /* half the view covered: the score follows */
    float *alpha = malloc((size_t)W * H * sizeof *alpha);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) alpha[y * W + x] = x < W / 2 ? 1.0f : 0.0f;
    sp_view_quality half;
    CHECK_OK(sp_media_view_quality(f.rgb, alpha, W, H, &half, &err), &err);
    CHECK_NEAR(half.coverage, 0.5, 1e-9);
    CHECK_NEAR(half.score, 1 + 4 * 0.5 * half.sharpness, 1e-9);
    /* nothing covered, or a flat grey picture: useless */
    for (size_t i = 0; i < (size_t)W * H; i++) alpha[i] = 0;
    CHECK_OK(sp_media_view_quality(f.rgb, alpha, W, H, &half, &err), &err);
    CHECK(half.grade == 1 && half.coverage == 0);
    for (size_t i = 0; i < (size_t)W * H * 3; i++) im[i] = 0.5f;
    CHECK_OK(sp_media_view_quality(im, NULL, W, H, &half, &err), &err);
    CHECK(half.blur == 1 && half.grade == 1);
    im[77] = NAN;
    CHECK_FAILS(sp_media_view_quality(im, NULL, W, H, &half, &err), SP_E_NUMERIC, &err, "pixel 25");
    CHECK_FAILS(sp_media_view_quality(im, NULL, 8, 8, &half, &err), SP_E_ARG, &err, "8x8");
    free(alpha);
    free(im);
    sp_synth_frame_free(&f);
    sp_world_free(&w);
}

int main(void)
{
    RUN(test_blur_scale_on_a_render);
    return TEST_EXIT();
}
