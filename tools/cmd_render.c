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
    const char *channels = "rgb";
    cli_common cf = cli_common_default();
    int all = 0, bad = 0, took;
    long downscale = 1;
    float bg[3] = {0.f, 0.f, 0.f};
    for (int i = 1; i < argc; i++) {
        const char *v;
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            usage(stdout);
            return 0;
        } else if ((took = cli_common_flag(cmd, argc, argv, &i, CLI_ALL, &cf))) {
            if (took == 2) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--splat", &bad))) splat_path = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--colmap", &bad))) colmap_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--image", &bad))) image_name = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--out", &bad))) out_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--channels", &bad))) channels = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--downscale", &bad))) {
            if (cli_parse_int(cmd, "--downscale", v, &downscale)) return 2;
            if (downscale < 1 || downscale > 64)
                return cli_usage_error(cmd, "--downscale %ld: must be 1..64", downscale);
        } else if ((v = cli_flag_value(argc, argv, &i, "--background", &bad))) {
            char tail;
            if (sscanf(v, "%f,%f,%f%c", &bg[0], &bg[1], &bg[2], &tail) != 3 || !(bg[0] >= 0 && bg[0] <= 1) ||
                !(bg[1] >= 0 && bg[1] <= 1) || !(bg[2] >= 0 && bg[2] <= 1))
                return cli_usage_error(cmd, "--background '%s': expected R,G,B in [0,1]", v);
        } else if (!strcmp(argv[i], "--all")) all = 1;
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

    sp_log log = cli_log(&cf, SP_LOG_INFO);
    sp_error err = {0};
    sp_splat splat = {0};
    sp_colmap_model model = {0};
    sp_device *dev = NULL;
    sp_raster *r = NULL;
    sp_scene *scene = NULL;
    float *buf = NULL, *aux = NULL, *rgb8 = NULL;
    int rc = 1;
    if (sp_ply_read_splat(splat_path, &splat, &err) || sp_colmap_read(colmap_dir, &model, &err) ||
        sp_mkdirs(out_dir, &err) || sp_device_create(&dev, cf.device, (int)cf.threads, &err) ||
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
            wrc = sp_depth_colormap(buf, aux, npix, rgb8, &err);
            if (!wrc) wrc = sp_write_png_f32(path, rgb8, cam.width, cam.height, 3, &err);
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
