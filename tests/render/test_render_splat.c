/* sp_render_splat end to end on a small recognisable scene: a yellow smiley face (a disc of
 * Gaussians, two dark-blue eyes, a red mouth) seen from 3 m. Checks the colours where a person
 * would look, the depth and alpha outputs, upload caching, then writes the splat as PLY and a
 * COLMAP text model, renders again through the files (and through `semsplat render` when the
 * CLI is built) and writes smiley.png for a human to look at. */
#include "test.h"

#include <unistd.h>

#include "semsplat/io.h"
#include "semsplat/render.h"

#define S 128

static void set_gauss(sp_splat *s, size_t i, float x, float y, float z, float sigma, float r,
                      float g, float b, float opacity)
{
    s->means[3 * i] = x, s->means[3 * i + 1] = y, s->means[3 * i + 2] = z;
    for (int k = 0; k < 3; k++) s->log_scales[3 * i + k] = logf(sigma);
    s->log_scales[3 * i + 2] = logf(sigma * 0.2f); /* flat, facing the camera */
    s->quats[4 * i] = 1.f, s->quats[4 * i + 1] = s->quats[4 * i + 2] = s->quats[4 * i + 3] = 0.f;
    s->opacity_logits[i] = sp_logit(opacity);
    int K = sp_sh_coeffs(s->sh_degree);
    float rgb[3] = {r, g, b};
    for (int c = 0; c < 3; c++) s->sh[(i * K) * 3 + c] = (rgb[c] - 0.5f) / SP_SH_C0;
}

/* Camera frame = world frame shifted: the camera sits at (0, 0, -3) looking down +z, y down. */
static void smiley_camera(sp_camera *cam)
{
    memset(cam, 0, sizeof *cam);
    cam->width = cam->height = S;
    cam->fx = cam->fy = 1.2f * S;
    cam->cx = cam->cy = 0.5f * S;
    cam->R[0] = cam->R[4] = cam->R[8] = 1.f;
    cam->t[2] = 3.f;
}

static size_t make_smiley(sp_splat *s)
{
    size_t n = 0, cap = 400;
    sp_error err = {0};
    if (sp_splat_alloc(s, cap, 1, 0, &err)) return 0;
    /* face: a filled disc of radius 1 m at z = 0 */
    for (float rr = 0.f; rr <= 0.95f; rr += 0.12f) {
        int ring = rr == 0.f ? 1 : (int)(2 * 3.14159f * rr / 0.12f);
        for (int k = 0; k < ring; k++) {
            float a = 2 * 3.14159265f * k / ring;
            set_gauss(s, n++, rr * cosf(a), rr * sinf(a), 0.f, 0.09f, 1.0f, 0.85f, 0.1f, 0.95f);
        }
    }
    /* eyes (y down: negative y is up in the image), in front of the face */
    for (int e = -1; e <= 1; e += 2)
        for (int k = 0; k < 5; k++)
            set_gauss(s, n++, e * 0.35f, -0.3f + 0.05f * (k - 2), -0.05f, 0.07f, 0.05f, 0.1f, 0.45f, 0.99f);
    /* mouth: an arc below the centre */
    for (int k = 0; k <= 12; k++) {
        float a = 3.14159265f * (0.15f + 0.7f * k / 12.f);
        set_gauss(s, n++, 0.55f * cosf(a), 0.15f + 0.45f * sinf(a) - 0.1f, -0.05f, 0.05f, 0.85f, 0.05f,
                  0.05f, 0.99f);
    }
    s->n = n;
    return n;
}

static const float *px(const float *img, int x, int y) { return img + ((size_t)y * S + x) * 3; }

static void check_smiley(const float *rgb, const char *what)
{
    const float *face = px(rgb, 64 + 18, 64);   /* right cheek */
    const float *eye = px(rgb, 64 + (int)(0.35f * 1.2f * S / 3.05f), 64 - (int)(0.3f * 1.2f * S / 3.05f));
    const float *mouth = px(rgb, 64, 64 + (int)(0.5f * 1.2f * S / 3.05f));
    const float *corner = px(rgb, 3, 3);
    fprintf(stderr, "  %s: face %.2f %.2f %.2f  eye %.2f %.2f %.2f  mouth %.2f %.2f %.2f  corner %.2f %.2f %.2f\n",
            what, face[0], face[1], face[2], eye[0], eye[1], eye[2], mouth[0], mouth[1], mouth[2],
            corner[0], corner[1], corner[2]);
    CHECK(face[0] > 0.8f && face[1] > 0.65f && face[2] < 0.3f);     /* yellow */
    CHECK(eye[2] > eye[0] + 0.15f && eye[0] < 0.3f);                /* dark blue */
    CHECK(mouth[0] > 0.6f && mouth[1] < 0.35f && mouth[2] < 0.35f); /* red */
    CHECK(corner[0] < 0.02f && corner[1] < 0.02f && corner[2] < 0.02f); /* black background */
}

static void test_smiley(void)
{
    sp_splat s = {0};
    CHECK(make_smiley(&s) > 50);
    sp_camera cam;
    smiley_camera(&cam);
    sp_device *dev = NULL;
    sp_error err = {0};
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CPU, 2, &err), &err);
    sp_raster *r = NULL;
    CHECK_OK(sp_raster_create(&r, dev, &err), &err);
    float *rgb = calloc(S * S * 3, sizeof(float)), *depth = calloc(S * S, sizeof(float)),
          *alpha = calloc(S * S, sizeof(float)), *rgb2 = calloc(S * S * 3, sizeof(float));
    sp_render_request req = {.rgb = rgb, .depth = depth, .alpha = alpha};
    CHECK_OK(sp_render_splat(r, &s, &cam, &req, &err), &err);
    check_smiley(rgb, "in memory");
    CHECK(alpha[64 * S + 82] > 0.95f && alpha[3 * S + 3] < 1e-3f);
    CHECK_NEAR(depth[64 * S + 82], 3.0, 0.1);   /* the face plane is 3 m away */
    CHECK(depth[3 * S + 3] == 0.f);              /* nothing drawn: 0 */

    /* sp_render_splat uploads on every call: the same splat gives the same image, and a splat
     * edited in place (same pointer, same count) is seen at once. (It used to keep a cache keyed
     * on the pointer and count, which rendered the old splat here.) */
    sp_render_request req2 = {.rgb = rgb2};
    CHECK_OK(sp_render_splat(r, &s, &cam, &req2, &err), &err);
    CHECK(memcmp(rgb, rgb2, S * S * 3 * sizeof(float)) == 0);
    for (size_t i = 0; i < s.n; i++) s.sh[i * 3 + 2] += 1.0f; /* bluer */
    CHECK_OK(sp_render_splat(r, &s, &cam, &req2, &err), &err);
    CHECK(px(rgb2, 82, 64)[2] > px(rgb, 82, 64)[2] + 0.2f);
    for (size_t i = 0; i < s.n; i++) s.sh[i * 3 + 2] -= 1.0f;

    /* through the files: PLY + COLMAP text */
    const char *dir = test_tmpdir("render_smiley");
    char ply[1024], model[1024], out[1024], png[1200];
    snprintf(ply, sizeof ply, "%s/smiley.ply", dir);
    snprintf(model, sizeof model, "%s/sparse", dir);
    snprintf(out, sizeof out, "%s/out", dir);
    snprintf(png, sizeof png, "%s/smiley.png", dir);
    CHECK_OK(sp_write_png_f32(png, rgb, S, S, 3, &err), &err);
    fprintf(stderr, "  wrote %s\n", png);
    CHECK_OK(sp_ply_write_splat(ply, &s, &err), &err);
    sp_splat back = {0};
    CHECK_OK(sp_ply_read_splat(ply, &back, &err), &err);
    CHECK_OK(sp_render_splat(r, &back, &cam, &req2, &err), &err);
    double md = 0;
    for (size_t i = 0; i < S * S * 3; i++) md = fmax(md, fabs(rgb[i] - rgb2[i]));
    CHECK(md < 1e-5);

    sp_colmap_camera ccam = {1, SP_COLMAP_PINHOLE, S, S, 4, {cam.fx, cam.fy, cam.cx, cam.cy}};
    char name[] = "views/smiley.jpg";
    sp_colmap_image cimg = {1, {1, 0, 0, 0}, {0, 0, 3}, 1, name, 0, NULL, NULL};
    sp_colmap_model m = {1, 1, 0, &ccam, &cimg, NULL};
    CHECK_OK(sp_mkdirs(model, &err), &err);
    CHECK_OK(sp_colmap_write_txt(model, &m, &err), &err);
    sp_colmap_model mr = {0};
    CHECK_OK(sp_colmap_read(model, &mr, &err), &err);
    sp_camera cam2;
    CHECK_OK(sp_colmap_image_camera(&mr, 0, &cam2, &err), &err);
    CHECK_OK(sp_render_splat(r, &back, &cam2, &req2, &err), &err);
    check_smiley(rgb2, "via PLY + COLMAP");
    sp_colmap_free(&mr);

    /* the CLI, when this build has it */
    char cli[1200];
    snprintf(cli, sizeof cli, "%s/semsplat", SP_BUILD_DIR);
    if (access(cli, X_OK) == 0) {
        for (int ch = 0; ch < 3; ch++) {
            const char *chs[3] = {"rgb", "depth", "alpha"};
            char line[4096];
            snprintf(line, sizeof line, "'%s' render --splat '%s' --colmap '%s' --image %s --out '%s' "
                     "--channels %s --device cpu --quiet", cli, ply, model, name, out, chs[ch]);
            CHECK(system(line) == 0);
        }
        const char *files[3] = {"views_smiley.png", "views_smiley_depth.png", "views_smiley_alpha.png"};
        for (int k = 0; k < 3; k++) {
            char f[1400];
            snprintf(f, sizeof f, "%s/%s", out, files[k]);
            sp_image im = {0};
            CHECK_OK(sp_image_read(f, &im, &err), &err);
            CHECK(im.width == S && im.height == S);
            sp_image_free(&im);
        }
        char line[4096];
        snprintf(line, sizeof line, "'%s' render --splat '%s' --colmap '%s' --image nope.jpg --out '%s' "
                 "--quiet 2>/dev/null", cli, ply, model, out);
        CHECK(system(line) != 0); /* unknown image name */
    } else {
        fprintf(stderr, "  (no %s: CLI part skipped)\n", cli);
    }
    sp_splat_free(&back);
    free(rgb), free(depth), free(alpha), free(rgb2);
    sp_raster_free(r);
    sp_device_free(dev);
    sp_splat_free(&s);
}

static void test_bad_requests(void)
{
    sp_device *dev = NULL;
    sp_error err = {0};
    CHECK_OK(sp_device_create(&dev, SP_DEVICE_CPU, 1, &err), &err);
    sp_raster *r = NULL;
    CHECK_OK(sp_raster_create(&r, dev, &err), &err);
    sp_splat s = {0};
    CHECK_OK(sp_splat_alloc(&s, 4, 0, 0, &err), &err);
    sp_camera cam;
    smiley_camera(&cam);
    float feat[S * S];
    sp_render_request req = {.features = feat};
    CHECK_FAILS(sp_render_splat(r, &s, &cam, &req, &err), SP_E_ARG, &err, "features");
    cam.width = 0;
    req.features = NULL;
    CHECK_FAILS(sp_render_splat(r, &s, &cam, &req, &err), SP_E_ARG, &err, "0x128");
    sp_splat_free(&s);
    sp_raster_free(r);
    sp_device_free(dev);
}

int main(void)
{
    RUN(test_smiley);
    RUN(test_bad_requests);
    return TEST_EXIT();
}
