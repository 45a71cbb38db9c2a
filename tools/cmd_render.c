/* semsplat render: renders a splat PLY from the cameras of a COLMAP model to PNGs.
 *   semsplat render --splat S.ply --colmap DIR (--image NAME | --all) --out DIR
 *                   [--channels rgb|depth|alpha] [--device cpu|cuda|auto] [--threads N]
 *                   [--background R,G,B] [--downscale F] [--quiet]
 * rgb: the SH colours; depth: expected depth colour-mapped (turbo) between the 2nd and 98th
 * percentile of covered pixels, black where nothing was drawn; alpha: accumulated opacity in grey.
 * Files are <out>/<image name with '/' -> '_' and extension -> .png> (depth/alpha add _depth /
 * _alpha before .png). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "semsplat/io.h"
#include "semsplat/render.h"

static void usage(FILE *f)
{
    fprintf(f,
            "usage: semsplat render --splat S.ply --colmap DIR (--image NAME | --all) --out DIR\n"
            "                       [--channels rgb|depth|alpha] [--device cpu|cuda|auto]\n"
            "                       [--threads N] [--background R,G,B] [--downscale F] [--quiet]\n"
            "Renders the splat from the cameras of a COLMAP model (pinhole; distortion ignored)\n"
            "and writes one PNG per image into DIR.\n");
}

/* Turbo colour map (Google, 2019), polynomial fit, t in [0, 1]. */
static void turbo(float t, float rgb[3])
{
    t = t < 0.f ? 0.f : (t > 1.f ? 1.f : t);
    float t2 = t * t, t3 = t2 * t, t4 = t3 * t, t5 = t4 * t;
    rgb[0] = 0.13572138f + 4.61539260f * t - 42.66032258f * t2 + 132.13108234f * t3 -
             152.94239396f * t4 + 59.28637943f * t5;
    rgb[1] = 0.09140261f + 2.19418839f * t + 4.84296658f * t2 - 14.18503333f * t3 +
             4.27729857f * t4 + 2.82956604f * t5;
    rgb[2] = 0.10667330f + 12.64194608f * t - 60.58204836f * t2 + 110.36276771f * t3 -
             89.90310912f * t4 + 27.34824973f * t5;
    for (int c = 0; c < 3; c++) rgb[c] = rgb[c] < 0.f ? 0.f : (rgb[c] > 1.f ? 1.f : rgb[c]);
}

static int cmp_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* depth [n] -> rgb [n][3]: turbo between the 2nd and 98th percentile of covered pixels, near in
 * red and far in blue; black where alpha < 0.5 (nothing solid drawn). */
static void depth_to_rgb(const float *depth, const float *alpha, size_t n, float *rgb)
{
    float *vals = malloc((n ? n : 1) * sizeof(float));
    size_t m = 0;
    for (size_t i = 0; i < n; i++)
        if (alpha[i] >= 0.5f && depth[i] > 0.f) vals[m++] = depth[i];
    float lo = 0.f, hi = 1.f;
    if (m > 0) {
        qsort(vals, m, sizeof(float), cmp_float);
        lo = vals[(size_t)(0.02 * (m - 1))];
        hi = vals[(size_t)(0.98 * (m - 1))];
        if (!(hi > lo)) hi = lo + 1e-3f;
    }
    for (size_t i = 0; i < n; i++) {
        if (alpha[i] < 0.5f || !(depth[i] > 0.f)) {
            rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = 0.f;
            continue;
        }
        turbo(1.f - (depth[i] - lo) / (hi - lo), rgb + 3 * i); /* near = red, far = blue */
    }
    free(vals);
}

static void output_path(char *out, size_t cap, const char *dir, const char *image_name,
                        const char *suffix)
{
    char stem[1024];
    snprintf(stem, sizeof stem, "%s", image_name);
    for (char *p = stem; *p; p++)
        if (*p == '/' || *p == '\\') *p = '_';
    char *dot = strrchr(stem, '.');
    if (dot && dot != stem) *dot = 0;
    char file[1100];
    snprintf(file, sizeof file, "%s%s.png", stem, suffix);
    sp_path_join(out, cap, dir, file);
}

int cmd_render(int argc, char **argv)
{
    const char *cmd = "render";
    const char *splat_path = NULL, *colmap_dir = NULL, *image_name = NULL, *out_dir = NULL;
    const char *channels = "rgb", *device = "auto";
    int all = 0, quiet = 0, bad = 0;
    long threads = 0, downscale = 1;
    float bg[3] = {0.f, 0.f, 0.f};
    for (int i = 1; i < argc; i++) {
        const char *v;
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            usage(stdout);
            return 0;
        } else if ((v = cli_flag_value(argc, argv, &i, "--splat", &bad))) splat_path = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--colmap", &bad))) colmap_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--image", &bad))) image_name = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--out", &bad))) out_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--channels", &bad))) channels = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--device", &bad))) device = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--threads", &bad))) {
            if (cli_parse_int(cmd, "--threads", v, &threads)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--downscale", &bad))) {
            if (cli_parse_int(cmd, "--downscale", v, &downscale)) return 2;
            if (downscale < 1 || downscale > 64)
                return cli_usage_error(cmd, "--downscale %ld: must be 1..64", downscale);
        } else if ((v = cli_flag_value(argc, argv, &i, "--background", &bad))) {
            char tail;
            if (sscanf(v, "%f,%f,%f%c", &bg[0], &bg[1], &bg[2], &tail) != 3 || !(bg[0] >= 0 && bg[0] <= 1) ||
                !(bg[1] >= 0 && bg[1] <= 1) || !(bg[2] >= 0 && bg[2] <= 1))
                return cli_usage_error(cmd, "--background '%s': expected R,G,B in [0,1]", v);
        } else if (!strcmp(argv[i], "--all")) all = 1;
        else if (!strcmp(argv[i], "--quiet") || !strcmp(argv[i], "-q")) quiet = 1;
        else if (!bad)
            return cli_usage_error(cmd, "unknown argument '%s'", argv[i]);
        if (bad) return 2;
    }
    if (!splat_path) return cli_usage_error(cmd, "--splat is required");
    if (!colmap_dir) return cli_usage_error(cmd, "--colmap is required");
    if (!out_dir) return cli_usage_error(cmd, "--out is required");
    if (!all == !image_name) return cli_usage_error(cmd, "give exactly one of --image NAME and --all");
    int mode = !strcmp(channels, "rgb") ? 0 : !strcmp(channels, "depth") ? 1 : !strcmp(channels, "alpha") ? 2 : -1;
    if (mode < 0) return cli_usage_error(cmd, "--channels '%s': expected rgb, depth or alpha", channels);
    sp_device_kind kind = !strcmp(device, "cpu") ? SP_DEVICE_CPU
                          : !strcmp(device, "cuda") ? SP_DEVICE_CUDA
                          : !strcmp(device, "auto") ? SP_DEVICE_AUTO : (sp_device_kind)-1;
    if ((int)kind < 0) return cli_usage_error(cmd, "--device '%s': expected cpu, cuda or auto", device);

    sp_log log = sp_log_stderr(SP_LOG_INFO, quiet);
    sp_error err = {0};
    sp_splat splat = {0};
    sp_colmap_model model = {0};
    sp_device *dev = NULL;
    sp_raster *r = NULL;
    sp_scene *scene = NULL;
    float *buf = NULL, *aux = NULL, *rgb8 = NULL;
    int rc = 1;
    if (sp_ply_read_splat(splat_path, &splat, &err) || sp_colmap_read(colmap_dir, &model, &err) ||
        sp_mkdirs(out_dir, &err) || sp_device_create(&dev, kind, (int)threads, &err) ||
        sp_raster_create(&r, dev, &err) ||
        sp_scene_create(&scene, dev, &splat, mode == 0 ? SP_SCENE_RGB : 0, &err)) {
        cli_fail(cmd, &err);
        goto done;
    }
    sp_logf(&log, SP_LOG_INFO, "%zu Gaussians (SH degree %d), %zu images, rendering on %s", splat.n,
            splat.sh_degree, model.n_images, sp_device_name(dev));

    size_t first = 0, count = model.n_images;
    if (image_name) {
        size_t k = 0;
        while (k < model.n_images && strcmp(model.images[k].name, image_name)) k++;
        if (k == model.n_images) {
            sp_error_set(&err, SP_E_NOTFOUND, "%s: no image named '%s' in the COLMAP model (%zu images%s%s)",
                         colmap_dir, image_name, model.n_images, model.n_images ? ", first is " : "",
                         model.n_images ? model.images[0].name : "");
            cli_fail(cmd, &err);
            goto done;
        }
        first = k;
        count = 1;
    }
    sp_progress prog;
    sp_log bar_log = log;
    if (count == 1) bar_log.progress_fd = -1; /* one image: the "wrote" line says enough */
    sp_progress_begin(&prog, &bar_log, "render", (long)count, "img");
    for (size_t k = first; k < first + count; k++) {
        sp_camera cam;
        if (sp_colmap_image_camera(&model, k, &cam, &err)) {
            cli_fail(cmd, &err);
            goto done;
        }
        if (downscale > 1) sp_camera_downscale(&cam, (int)downscale);
        size_t npix = (size_t)cam.width * cam.height;
        free(buf), free(aux), free(rgb8);
        buf = malloc(npix * 3 * sizeof(float));
        aux = malloc(npix * sizeof(float));
        rgb8 = malloc(npix * 3 * sizeof(float));
        if (!buf || !aux || !rgb8) {
            sp_error_set(&err, SP_E_NOMEM, "out of memory for a %dx%d image", cam.width, cam.height);
            cli_fail(cmd, &err);
            goto done;
        }
        sp_render_request req = {0};
        req.background = bg;
        const char *suffix = "";
        if (mode == 0) req.rgb = buf;
        if (mode == 1) req.depth = buf, req.alpha = aux, suffix = "_depth";
        if (mode == 2) req.alpha = buf, suffix = "_alpha";
        if (sp_render_views(r, scene, &cam, 1, &req, &err)) {
            sp_error_prefix(&err, "image '%s': ", model.images[k].name);
            cli_fail(cmd, &err);
            goto done;
        }
        char path[2048];
        output_path(path, sizeof path, out_dir, model.images[k].name, suffix);
        int wrc;
        if (mode == 1) {
            depth_to_rgb(buf, aux, npix, rgb8);
            wrc = sp_write_png_f32(path, rgb8, cam.width, cam.height, 3, &err);
        } else {
            wrc = sp_write_png_f32(path, buf, cam.width, cam.height, mode == 0 ? 3 : 1, &err);
        }
        if (wrc) {
            cli_fail(cmd, &err);
            goto done;
        }
        sp_progress_update(&prog, (long)(k - first + 1), NULL);
        if (count == 1) sp_logf(&log, SP_LOG_INFO, "wrote %s", path);
    }
    sp_progress_end(&prog, NULL);
    rc = 0;
done:
    free(buf), free(aux), free(rgb8);
    sp_scene_free(scene);
    sp_raster_free(r);
    sp_device_free(dev);
    sp_colmap_free(&model);
    sp_splat_free(&splat);
    return rc;
}
