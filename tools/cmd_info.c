/* semsplat info FILE: says what is in a COLMAP model (folder or capture root), a splat PLY, a PNG
 * or JPEG image, a .npy array or a safetensors file. The kind is taken from the content. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"
#include "semsplat/io.h"

static void help(void)
{
    printf("usage: semsplat info [--all] PATH\n\n"
           "  PATH   a COLMAP model folder or capture root (sparse/0 or sparse inside), a splat\n"
           "         .ply, a PNG/JPEG image, a .npy array or a .safetensors file\n"
           "  --all  list every camera / tensor (default: the first 20)\n");
}

#define LIST_MAX 20

static void print_bbox(const char *label, const double lo[3], const double hi[3])
{
    /* + 0.0 turns -0 into 0 for display. */
    printf("%-14s [%.4g %.4g %.4g] .. [%.4g %.4g %.4g]  size %.4g x %.4g x %.4g\n", label, lo[0] + 0.0, lo[1] + 0.0,
           lo[2] + 0.0, hi[0] + 0.0, hi[1] + 0.0, hi[2] + 0.0, hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

static int info_colmap(const char *path, int all, sp_error *err)
{
    char dir[4096], p[4200];
    int rc = sp_colmap_find_model_dir(path, dir, sizeof dir, err);
    if (rc) return rc;
    sp_colmap_model m;
    if ((rc = sp_colmap_read(dir, &m, err))) return rc;
    sp_path_join(p, sizeof p, dir, "cameras.bin");
    printf("COLMAP model   %s (%s)\n", dir, sp_file_exists(p) ? "binary" : "text");
    printf("cameras        %zu\n", m.n_cameras);
    for (size_t i = 0; i < m.n_cameras && (all || i < LIST_MAX); i++) {
        const sp_colmap_camera *c = &m.cameras[i];
        printf("  camera %-5u %-16s %llux%llu  params", c->id, sp_colmap_model_name(c->model),
               (unsigned long long)c->width, (unsigned long long)c->height);
        for (int k = 0; k < c->n_params; k++) printf(" %.6g", c->params[k]);
        printf("\n");
    }
    if (!all && m.n_cameras > LIST_MAX) printf("  ... %zu more (--all)\n", m.n_cameras - LIST_MAX);
    size_t obs = 0, tracks = 0;
    for (size_t i = 0; i < m.n_images; i++) obs += m.images[i].n_points2d;
    for (size_t i = 0; i < m.n_points; i++) tracks += m.points[i].track_len;
    printf("images         %zu (mean %.1f observations each)\n", m.n_images, m.n_images ? (double)obs / m.n_images : 0.0);
    printf("points3D       %zu (mean track length %.2f)\n", m.n_points, m.n_points ? (double)tracks / m.n_points : 0.0);
    /* Scene extent as 3DGS measures it: camera centres' spread about their mean. */
    if (m.n_images) {
        double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY}, mean[3] = {0, 0, 0};
        double *centres = malloc(sizeof(double) * 3 * m.n_images);
        size_t n_ok = 0, n_unsupported = 0;
        for (size_t i = 0; centres && i < m.n_images; i++) {
            const sp_colmap_image *im = &m.images[i];
            double q[4] = {im->qvec[0], im->qvec[1], im->qvec[2], im->qvec[3]};
            double qn = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            for (int k = 0; k < 4; k++) q[k] /= qn;
            double w = q[0], x = q[1], y = q[2], z = q[3];
            double R[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
                           2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                           2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
            double *c = centres + 3 * n_ok; /* C = -R^T t */
            for (int r = 0; r < 3; r++)
                c[r] = -(R[0 * 3 + r] * im->tvec[0] + R[1 * 3 + r] * im->tvec[1] + R[2 * 3 + r] * im->tvec[2]);
            for (int k = 0; k < 3; k++) {
                lo[k] = fmin(lo[k], c[k]);
                hi[k] = fmax(hi[k], c[k]);
                mean[k] += c[k];
            }
            sp_camera cam;
            sp_error e2;
            if (sp_colmap_image_camera(&m, i, &cam, &e2) == SP_E_UNSUPPORTED) n_unsupported++;
            n_ok++;
        }
        if (n_ok) {
            double radius = 0;
            for (int k = 0; k < 3; k++) mean[k] /= (double)n_ok;
            for (size_t i = 0; i < n_ok; i++) {
                double d = 0;
                for (int k = 0; k < 3; k++) d += (centres[3 * i + k] - mean[k]) * (centres[3 * i + k] - mean[k]);
                radius = fmax(radius, sqrt(d));
            }
            print_bbox("camera centres", lo, hi);
            printf("scene extent   %.4g (1.1 x the largest camera distance from their mean, as 3DGS)\n", 1.1 * radius);
        }
        if (n_unsupported)
            printf("note           %zu images use camera models semsplat cannot render (undistort them first)\n",
                   n_unsupported);
        free(centres);
    }
    if (m.n_points) {
        double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (size_t i = 0; i < m.n_points; i++)
            for (int k = 0; k < 3; k++) {
                lo[k] = fmin(lo[k], m.points[i].xyz[k]);
                hi[k] = fmax(hi[k], m.points[i].xyz[k]);
            }
        print_bbox("points bbox", lo, hi);
    }
    sp_colmap_free(&m);
    return 0;
}

static int cmp_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

static int info_ply(const char *path, sp_error *err)
{
    sp_splat s;
    int rc = sp_ply_read_splat(path, &s, err);
    if (rc) return rc;
    printf("splat PLY      %s\n", path);
    printf("Gaussians      %zu\n", s.n);
    printf("SH degree      %d (%d coefficients per channel)\n", s.sh_degree, sp_sh_coeffs(s.sh_degree));
    printf("feature dim    %d%s\n", s.feat_dim, s.feat_dim ? " (f_sem_*)" : "");
    if (s.n) {
        double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        double op_sum = 0, op_min = 1, op_max = 0;
        size_t faint = 0;
        float *scales = malloc(sizeof(float) * s.n);
        for (size_t i = 0; i < s.n; i++) {
            for (int k = 0; k < 3; k++) {
                lo[k] = fmin(lo[k], s.means[3 * i + k]);
                hi[k] = fmax(hi[k], s.means[3 * i + k]);
            }
            double o = 1.0 / (1.0 + exp(-(double)s.opacity_logits[i]));
            op_sum += o;
            op_min = fmin(op_min, o);
            op_max = fmax(op_max, o);
            faint += o < 0.005; /* 3DGS prunes below this */
            const float *ls = s.log_scales + 3 * i;
            if (scales) scales[i] = expf(fmaxf(ls[0], fmaxf(ls[1], ls[2])));
        }
        print_bbox("bounding box", lo, hi);
        printf("opacity        min %.4f  mean %.4f  max %.4f  (%zu below 0.005)\n", op_min, op_sum / (double)s.n, op_max,
               faint);
        if (scales) {
            qsort(scales, s.n, sizeof(float), cmp_float);
            printf("largest axis   median %.4g  p99 %.4g  max %.4g (metres, exp of log-scale)\n", scales[s.n / 2],
                   scales[(size_t)(0.99 * (double)(s.n - 1))], scales[s.n - 1]);
        }
        free(scales);
    }
    sp_splat_free(&s);
    return 0;
}

static int info_image(const char *path, sp_error *err)
{
    sp_image img;
    int rc = sp_image_read(path, &img, err);
    if (rc) return rc;
    static const char *kinds[5] = {"", "grey", "grey+alpha", "RGB", "RGBA"};
    printf("image          %s\n", path);
    printf("size           %dx%d, %d channels (%s), %d-bit\n", img.width, img.height, img.channels, kinds[img.channels],
           img.bit_depth);
    size_t n = (size_t)img.width * img.height;
    double max = img.bit_depth == 16 ? 65535.0 : 255.0;
    printf("channel mean  ");
    for (int c = 0; c < img.channels; c++) {
        double sum = 0;
        for (size_t i = 0; i < n; i++)
            sum += img.bit_depth == 16 ? ((const uint16_t *)img.data)[i * img.channels + c]
                                       : ((const uint8_t *)img.data)[i * img.channels + c];
        printf(" %.4f", sum / (double)n / max);
    }
    printf("  (of full scale)\n");
    sp_image_free(&img);
    return 0;
}

static const char *dtype_name(sp_dtype t)
{
    static const char *names[] = {"float32", "float16", "uint8", "int32", "uint16", "float64", "int64", "bfloat16"};
    return (int)t >= 0 && t <= SP_DTYPE_BF16 ? names[t] : "?";
}

static void print_shape(int ndim, const size_t *shape)
{
    printf("(");
    for (int k = 0; k < ndim; k++) printf("%zu%s", shape[k], ndim == 1 ? "," : k + 1 < ndim ? ", " : "");
    printf(")");
}

static int info_npy(const char *path, sp_error *err)
{
    sp_npy a;
    int rc = sp_npy_read(path, &a, err);
    if (rc) return rc;
    printf("npy array      %s\n", path);
    printf("dtype          %s\n", dtype_name(a.dtype));
    printf("shape          ");
    print_shape(a.ndim, a.shape);
    size_t n = sp_npy_count(&a);
    printf("  (%zu values, %zu bytes)\n", n, n * sp_dtype_size(a.dtype));
    float *f = NULL;
    if (n && sp_npy_to_f32(&a, &f, err) == 0) {
        double lo = INFINITY, hi = -INFINITY, sum = 0;
        size_t bad = 0;
        for (size_t i = 0; i < n; i++) {
            if (!isfinite(f[i])) {
                bad++;
                continue;
            }
            lo = fmin(lo, f[i]);
            hi = fmax(hi, f[i]);
            sum += f[i];
        }
        if (n > bad) printf("values         min %.6g  mean %.6g  max %.6g\n", lo, sum / (double)(n - bad), hi);
        if (bad) printf("non-finite     %zu values\n", bad);
        free(f);
    }
    sp_npy_free(&a);
    return 0;
}

static int info_safetensors(const char *path, int all, sp_error *err)
{
    sp_safetensors st;
    int rc = sp_safetensors_open(path, &st, err);
    if (rc) return rc;
    size_t bytes = 0, params = 0, per_type[8] = {0};
    for (size_t i = 0; i < st.n; i++) {
        bytes += st.tensors[i].nbytes;
        params += st.tensors[i].nbytes / sp_dtype_size(st.tensors[i].dtype);
        if ((int)st.tensors[i].dtype >= 0 && st.tensors[i].dtype <= SP_DTYPE_BF16) per_type[st.tensors[i].dtype]++;
    }
    printf("safetensors    %s\n", path);
    printf("tensors        %zu (%zu values, %.3g MB)  by dtype:", st.n, params, (double)bytes / 1e6);
    for (int t = 0; t <= SP_DTYPE_BF16; t++)
        if (per_type[t]) printf(" %s %zu", dtype_name((sp_dtype)t), per_type[t]);
    printf("\n");
    for (size_t i = 0; i < st.n && (all || i < LIST_MAX); i++) {
        printf("  %-56s %-8s ", st.tensors[i].name, dtype_name(st.tensors[i].dtype));
        print_shape(st.tensors[i].ndim, st.tensors[i].shape);
        printf("\n");
    }
    if (!all && st.n > LIST_MAX) printf("  ... %zu more (--all)\n", st.n - LIST_MAX);
    sp_safetensors_close(&st);
    return 0;
}

/* cameras.bin, images.txt, ...: a file of a COLMAP model folder. */
static int is_model_file(const char *path)
{
    static const char *const names[] = {"cameras.bin", "images.bin", "points3D.bin",
                                        "cameras.txt", "images.txt", "points3D.txt"};
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (!strcmp(base, names[i])) return 1;
    return 0;
}

int cmd_info(int argc, char **argv)
{
    const char *path = NULL;
    int all = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            help();
            return 0;
        } else if (!strcmp(argv[i], "--all")) {
            all = 1;
        } else if (!strcmp(argv[i], "--quiet")) {
            /* nothing to silence: info prints only its answer */
        } else if (argv[i][0] == '-' && argv[i][1]) {
            return cli_usage_error("info", "unknown flag '%s'", argv[i]);
        } else if (path) {
            return cli_usage_error("info", "one PATH at a time (got '%s' and '%s')", path, argv[i]);
        } else {
            path = argv[i];
        }
    }
    if (!path) return cli_usage_error("info", "PATH is required");
    sp_error err = {0};
    struct stat sb;
    if (stat(path, &sb) != 0) {
        sp_error_set(&err, SP_E_IO, "%s: no such file or folder", path);
        return cli_fail("info", &err);
    }
    int rc;
    if (S_ISDIR(sb.st_mode)) {
        rc = info_colmap(path, all, &err);
    } else {
        unsigned char magic[16] = {0};
        FILE *f = fopen(path, "rb");
        size_t got = f ? fread(magic, 1, sizeof magic, f) : 0;
        if (f) fclose(f);
        uint64_t hlen = 0;
        memcpy(&hlen, magic, 8);
        if (got >= 4 && !memcmp(magic, "ply", 3) && (magic[3] == '\n' || magic[3] == '\r'))
            rc = info_ply(path, &err);
        else if (got >= 8 && (!memcmp(magic, "\x89PNG", 4) || (magic[0] == 0xFF && magic[1] == 0xD8)))
            rc = info_image(path, &err);
        else if (got >= 6 && !memcmp(magic, "\x93NUMPY", 6))
            rc = info_npy(path, &err);
        else if (got >= 9 && magic[8] == '{' && hlen > 1 && hlen < ((uint64_t)100 << 20))
            rc = info_safetensors(path, all, &err);
        else if (is_model_file(path)) {
            /* cameras.bin / images.txt etc.: describe the model folder around it. */
            char dir[4096];
            snprintf(dir, sizeof dir, "%s", path);
            char *slash = strrchr(dir, '/');
            if (slash) *slash = 0;
            else snprintf(dir, sizeof dir, ".");
            rc = info_colmap(dir, all, &err);
        } else {
            rc = sp_error_set(&err, SP_E_UNSUPPORTED,
                              "%s: not a COLMAP model, splat PLY, PNG/JPEG, .npy or safetensors file", path);
        }
    }
    return rc ? cli_fail("info", &err) : 0;
}
