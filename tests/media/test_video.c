/* media: the H.264 MP4 writer. A short video of a title card and moving frames is checked with
 * ffprobe (codec, size, frame count, duration) and decoded back with ffmpeg (colours); the
 * temporary name never survives; bad options, empty videos and size mismatches are refused. */
#include <dirent.h>
#include <unistd.h>

#include "semsplat/io.h"
#include "semsplat/media.h"
#include "test.h"
#include "tools.h"

static int files_with(const char *dir, const char *needle)
{
    DIR *d = opendir(dir);
    int n = 0;
    struct dirent *e;
    while (d && (e = readdir(d))) n += strstr(e->d_name, needle) != NULL;
    if (d) closedir(d);
    return n;
}

/* A frame: a colour field (red, green, blue, grey quarters) and a white square moving right. */
static void pattern(uint8_t *rgb, int w, int h, int t)
{
    static const uint8_t q[4][3] = {{200, 30, 30}, {30, 180, 40}, {30, 60, 200}, {128, 128, 128}};
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            const uint8_t *c = q[(y >= h / 2) * 2 + (x >= w / 2)];
            uint8_t *p = rgb + ((size_t)y * w + x) * 3;
            int sq = x >= 40 + 8 * t && x < 120 + 8 * t && y >= 40 && y < 120;
            for (int k = 0; k < 3; k++) p[k] = sq ? 250 : c[k];
        }
}

static void test_video_h264(void)
{
    sp_error err = {0};
    const char *dir = test_tmpdir("media_video");
    char path[1200];
    snprintf(path, sizeof path, "%s/clip.mp4", dir);
    sp_video *v = NULL;
    sp_video_opts o = {.width = 1280, .height = 720, .fps = 25};
    int rc = sp_video_open(&v, path, &o, &err);
    if (rc == SP_E_UNSUPPORTED) TEST_SKIP("built without FFmpeg's libraries or an H.264 encoder");
    CHECK_MSG(rc == 0, "%s", err.msg);
    if (rc) return;
    CHECK(files_with(dir, ".tmp.") == 1 && !sp_file_exists(path));
    sp_canvas *c = NULL;
    if (sp_canvas_create(&c, 1280, 720, &err) == 0) {
        sp_media_title_card(c, "A test video", "one second of card, one of motion", NULL);
        CHECK_OK(sp_video_frame_canvas(v, c, 25, &err), &err);
        sp_canvas_free(c);
    } else {
        uint8_t *grey = malloc(1280 * 720 * 3);
        memset(grey, 40, 1280 * 720 * 3);
        CHECK_OK(sp_video_frame(v, grey, 25, &err), &err);
        free(grey);
    }
    uint8_t *rgb = malloc(1280 * 720 * 3);
    for (int t = 0; t < 25; t++) {
        pattern(rgb, 1280, 720, t);
        CHECK_OK(sp_video_frame(v, rgb, 1, &err), &err);
    }
    CHECK(sp_video_frames(v) == 50 && sp_video_fps(v) == 25);
    CHECK_OK(sp_video_close(v, &err), &err);
    CHECK(sp_file_exists(path));
    CHECK(files_with(dir, ".tmp.") == 0);
    if (!have_tool("ffprobe") || !have_tool("ffmpeg")) {
        free(rgb);
        TEST_SKIP("ffprobe/ffmpeg not installed (scripts/install-deps.sh): the file was not checked");
    }
    char cmd[2600], out[4096];
    snprintf(cmd, sizeof cmd,
             "ffprobe -v error -select_streams v:0 -count_frames -show_entries "
             "stream=codec_name,profile,width,height,pix_fmt,nb_read_frames,avg_frame_rate:format=duration,format_name "
             "-of default=nw=1 '%s'", path);
    CHECK(capture(cmd, out, sizeof out) == 0);
    CHECK_MSG(strstr(out, "codec_name=h264"), "%s", out);
    CHECK(strstr(out, "width=1280") && strstr(out, "height=720"));
    CHECK(strstr(out, "pix_fmt=yuv420p"));
    CHECK_MSG(strstr(out, "nb_read_frames=50"), "%s", out);
    CHECK(strstr(out, "avg_frame_rate=25/1"));
    CHECK(strstr(out, "format_name=mov,mp4"));
    const char *d = strstr(out, "duration=");
    CHECK(d != NULL);
    if (d) CHECK_NEAR(atof(d + 9), 2.0, 0.05);
    /* the last frame decodes to the colours that went in (BT.709 both ways) */
    char png[1300];
    snprintf(png, sizeof png, "%s/last.png", dir);
    snprintf(cmd, sizeof cmd,
             "ffmpeg -v error -y -i '%s' -vf \"select=eq(n\\,49),scale=in_color_matrix=bt709:in_range=tv:out_range=pc\" "
             "-frames:v 1 -pix_fmt rgb24 '%s'", path, png);
    CHECK(system(cmd) == 0);
    sp_image im = {0};
    CHECK_OK(sp_image_read(png, &im, &err), &err);
    if (im.data && im.width == 1280 && im.height == 720 && im.channels == 3) {
        pattern(rgb, 1280, 720, 24);
        double sum = 0;
        const uint8_t *a = im.data;
        for (long i = 0; i < 1280L * 720 * 3; i++) sum += abs((int)a[i] - (int)rgb[i]);
        double mae = sum / (1280.0 * 720 * 3);
        CHECK_MSG(mae < 3.0, "mean absolute difference %.2f of 255", mae);
        /* a flat quarter's centre, away from the edges the encoder blurs */
        const uint8_t *p = a + ((size_t)540 * 1280 + 960) * 3;
        CHECK_MSG(abs(p[0] - 128) < 6 && abs(p[1] - 128) < 6 && abs(p[2] - 128) < 6, "%d %d %d", p[0], p[1], p[2]);
        p = a + ((size_t)180 * 1280 + 900) * 3;
        CHECK_MSG(abs(p[0] - 30) < 8 && abs(p[1] - 180) < 8 && abs(p[2] - 40) < 8, "%d %d %d", p[0], p[1], p[2]);
    } else CHECK_MSG(0, "decoded frame %dx%d c%d", im.width, im.height, im.channels);
    sp_image_free(&im);
    free(rgb);
}

static void test_video_refusals(void)
{
    sp_error err = {0};
    const char *dir = test_tmpdir("media_video_bad");
    char path[1200];
    snprintf(path, sizeof path, "%s/bad.mp4", dir);
    sp_video *v = NULL;
    sp_video_opts odd = {.width = 641, .height = 480};
    int rc = sp_video_open(&v, path, &odd, &err);
    if (rc == SP_E_UNSUPPORTED) TEST_SKIP("built without FFmpeg's libraries");
    CHECK_FAILS(rc, SP_E_ARG, &err, "641x480");
    sp_video_opts fast = {.fps = 500};
    CHECK_FAILS(sp_video_open(&v, path, &fast, &err), SP_E_ARG, &err, "500");
    char nowhere[1300];
    snprintf(nowhere, sizeof nowhere, "%s/no/such/dir/x.mp4", dir);
    CHECK_FAILS(sp_video_open(&v, nowhere, NULL, &err), SP_E_IO, &err, "no/such/dir");
    CHECK(v == NULL);
    /* no frames: refused, nothing left behind */
    sp_video_opts small = {.width = 64, .height = 48, .fps = 10};
    CHECK_OK(sp_video_open(&v, path, &small, &err), &err);
    CHECK_FAILS(sp_video_close(v, &err), SP_E_ARG, &err, "at least one frame");
    CHECK(!sp_file_exists(path) && files_with(dir, ".tmp.") == 0);
    /* a canvas of the wrong size; repeat out of range; discard removes the file */
    CHECK_OK(sp_video_open(&v, path, &small, &err), &err);
    sp_canvas *c = NULL;
    if (sp_canvas_create(&c, 32, 32, &err) == 0) {
        CHECK_FAILS(sp_video_frame_canvas(v, c, 1, &err), SP_E_ARG, &err, "32x32");
        sp_canvas_free(c);
    }
    uint8_t px[64 * 48 * 3] = {0};
    CHECK_FAILS(sp_video_frame(v, px, 0, &err), SP_E_ARG, &err, "0 times");
    CHECK_OK(sp_video_frame(v, px, 3, &err), &err);
    sp_video_discard(v);
    CHECK(!sp_file_exists(path) && files_with(dir, ".tmp.") == 0);
}

int main(void)
{
    RUN(test_video_refusals);
    RUN(test_video_h264);
    return TEST_EXIT();
}
