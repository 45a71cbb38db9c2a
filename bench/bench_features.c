/* `semsplat features --source labels` on a synthetic capture of the size the issue names: 150
 * views of 640x480, 16-bit label images with 40 classes in overlapping rectangles, labels.json as
 * synth writes it; the label embeddings are the hash ones (512 wide), PCA to 32. Times the whole
 * sp_features_extract (both passes, the PCA, the maps written) on the CUDA device when one
 * answers (cuBLAS covariance), else on the CPU; the device's pool (--threads, default all cores)
 * writes the maps in parallel.
 *   bench_features [--views N] [--cpu] [--threads N] [--dir DIR] */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "semsplat/clip.h"
#include "semsplat/device.h"
#include "semsplat/io.h"

enum { W = 640, H = 480, CLASSES = 40 };

static unsigned long long rng = 88172645463325252ULL;
static unsigned rnd(unsigned n)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (unsigned)(rng % n);
}

static int make_capture(const char *dir, int views, sp_error *err)
{
    char p[1400];
    sp_colmap_model m;
    memset(&m, 0, sizeof m);
    sp_colmap_camera cam = {1, SP_COLMAP_PINHOLE, W, H, 4, {500, 500, W / 2.0, H / 2.0}};
    sp_colmap_image *im = calloc((size_t)views, sizeof *im);
    char (*names)[32] = calloc((size_t)views, sizeof *names);
    uint16_t *lab = malloc(sizeof(uint16_t) * W * H);
    int rc = im && names && lab ? 0 : sp_error_set(err, SP_E_NOMEM, "out of memory");
    for (int i = 0; i < views && !rc; i++) {
        snprintf(names[i], sizeof names[i], "%05d.png", i);
        im[i].id = (uint32_t)i + 1;
        im[i].qvec[0] = 1;
        im[i].tvec[0] = i;
        im[i].camera_id = 1;
        im[i].name = names[i];
    }
    m.n_cameras = 1;
    m.cameras = &cam;
    m.n_images = (size_t)views;
    m.images = im;
    snprintf(p, sizeof p, "%s/sparse/0", dir);
    if (!rc && !(rc = sp_mkdirs(p, err))) rc = sp_colmap_write_txt(p, &m, err);
    snprintf(p, sizeof p, "%s/labels", dir);
    if (!rc) rc = sp_mkdirs(p, err);
    for (int i = 0; i < views && !rc; i++) {
        for (int k = 0; k < W * H; k++) lab[k] = 0;
        for (int r = 0; r < 60; r++) { /* rectangles of random classes, later ones on top */
            int x0 = (int)rnd(W), y0 = (int)rnd(H), w = 20 + (int)rnd(200), h = 20 + (int)rnd(160), id = 1 + (int)rnd(CLASSES);
            for (int y = y0; y < y0 + h && y < H; y++)
                for (int x = x0; x < x0 + w && x < W; x++) lab[y * W + x] = (uint16_t)id;
        }
        sp_image img = {W, H, 1, 16, lab};
        snprintf(p, sizeof p, "%s/labels/%05d.png", dir, i);
        rc = sp_image_write_png(p, &img, err);
    }
    snprintf(p, sizeof p, "%s/labels.json", dir);
    FILE *f = rc ? NULL : fopen(p, "w");
    if (f) {
        fputs("{\"format\": \"semsplat-labels-1\", \"background\": 0, \"labels\": {", f);
        for (int k = 1; k <= CLASSES; k++)
            fprintf(f, "%s\"%d\": {\"name\": \"thing_%d\", \"class\": \"class %d\"}", k > 1 ? ", " : "", k, k, k);
        fputs("}}\n", f);
        fclose(f);
    } else if (!rc) {
        rc = sp_error_set(err, SP_E_IO, "%s: cannot write", p);
    }
    free(im);
    free(names);
    free(lab);
    return rc;
}

int main(int argc, char **argv)
{
    int views = 150, cpu = 0, threads = 0;
    char dir[1024];
    snprintf(dir, sizeof dir, "/tmp/bench_features_%d", (int)getpid());
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--views") && i + 1 < argc) views = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--cpu")) cpu = 1;
        else if (!strcmp(argv[i], "--threads") && i + 1 < argc) threads = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--dir") && i + 1 < argc) snprintf(dir, sizeof dir, "%s", argv[++i]);
        else {
            fprintf(stderr, "usage: bench_features [--views N] [--cpu] [--threads N] [--dir DIR]\n");
            return 2;
        }
    }
    if (views < 1) views = 1;
    sp_error err = {0};
    double t0 = sp_time_now();
    if (make_capture(dir, views, &err)) {
        fprintf(stderr, "bench_features: %s\n", err.msg);
        return 1;
    }
    double t_make = sp_time_now() - t0;
    sp_device *dev = NULL;
    sp_device_kind kind = !cpu && sp_cuda_available() ? SP_DEVICE_CUDA : SP_DEVICE_CPU;
    if (sp_device_create(&dev, kind, threads, &err)) {
        fprintf(stderr, "bench_features: %s\n", err.msg);
        return 1;
    }
    char out[1200];
    snprintf(out, sizeof out, "%s/features", dir);
    sp_features_opts o = sp_features_opts_default();
    o.colmap_dir = dir;
    o.out_dir = out;
    o.source = "labels";
    o.dim = 32;
    o.dev = dev;
    t0 = sp_time_now();
    int rc = sp_features_extract(&o, &err);
    double dt = sp_time_now() - t0;
    if (rc) fprintf(stderr, "bench_features: %s\n", err.msg);
    else
        printf("features_labels_s  %.2f  s  (%d views 640x480, %d classes, 512 -> 32, %s; capture written in %.1f s)\n", dt,
               views, CLASSES, sp_device_name(dev), t_make);
    sp_device_free(dev);
    return rc ? 1 : 0;
}
