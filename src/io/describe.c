/* What is in a file or folder, as text: a COLMAP model (folder or capture root), a splat PLY,
 * a PNG or JPEG image, a .npy array or a safetensors file, recognised by content. The CLI's
 * `info` prints it; the library only builds the text. */
#include "io_internal.h"

#include <math.h>
#include <stdlib.h>
#include <sys/stat.h>

#define LIST_MAX 20

static void print_bbox(sp_strbuf *b, const char *label, const double lo[3], const double hi[3])
{
    /* + 0.0 turns -0 into 0 for display. */
    sp_strbuf_printf(b, "%-14s [%.4g %.4g %.4g] .. [%.4g %.4g %.4g]  size %.4g x %.4g x %.4g\n", label, lo[0] + 0.0, lo[1] + 0.0,
           lo[2] + 0.0, hi[0] + 0.0, hi[1] + 0.0, hi[2] + 0.0, hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

static int info_colmap(sp_strbuf *b, const char *path, int all, sp_error *err)
{
    char dir[4096], p[4200];
    int rc = sp_colmap_find_model_dir(path, dir, sizeof dir, err);
    if (rc) return rc;
    sp_colmap_model m;
    if ((rc = sp_colmap_read(dir, &m, err))) return rc;
    sp_path_join(p, sizeof p, dir, "cameras.bin");
    sp_strbuf_printf(b, "COLMAP model   %s (%s)\n", dir, sp_file_exists(p) ? "binary" : "text");
    sp_strbuf_printf(b, "cameras        %zu\n", m.n_cameras);
    for (size_t i = 0; i < m.n_cameras && (all || i < LIST_MAX); i++) {
        const sp_colmap_camera *c = &m.cameras[i];
        sp_strbuf_printf(b, "  camera %-5u %-16s %llux%llu  params", c->id, sp_colmap_model_name(c->model),
               (unsigned long long)c->width, (unsigned long long)c->height);
        for (int k = 0; k < c->n_params; k++) sp_strbuf_printf(b, " %.6g", c->params[k]);
        sp_strbuf_printf(b, "\n");
    }
    if (!all && m.n_cameras > LIST_MAX) sp_strbuf_printf(b, "  ... %zu more (--all)\n", m.n_cameras - LIST_MAX);
    size_t obs = 0, tracks = 0;
    for (size_t i = 0; i < m.n_images; i++) obs += m.images[i].n_points2d;
    for (size_t i = 0; i < m.n_points; i++) tracks += m.points[i].track_len;
    sp_strbuf_printf(b, "images         %zu (mean %.1f observations each)\n", m.n_images, m.n_images ? (double)obs / m.n_images : 0.0);
    sp_strbuf_printf(b, "points3D       %zu (mean track length %.2f)\n", m.n_points, m.n_points ? (double)tracks / m.n_points : 0.0);
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
            print_bbox(b, "camera centres", lo, hi);
            sp_strbuf_printf(b, "scene extent   %.4g (1.1 x the largest camera distance from their mean, as 3DGS)\n", 1.1 * radius);
        }
        if (n_unsupported)
            sp_strbuf_printf(b, "note           %zu images use camera models semsplat cannot render (undistort them first)\n",
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
        print_bbox(b, "points bbox", lo, hi);
    }
    sp_colmap_free(&m);
    return 0;
}

static int cmp_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

static int info_ply(sp_strbuf *b, const char *path, sp_error *err)
{
    sp_splat s;
    int rc = sp_ply_read_splat(path, &s, err);
    if (rc) return rc;
    sp_strbuf_printf(b, "splat PLY      %s\n", path);
    sp_strbuf_printf(b, "Gaussians      %zu\n", s.n);
    sp_strbuf_printf(b, "SH degree      %d (%d coefficients per channel)\n", s.sh_degree, sp_sh_coeffs(s.sh_degree));
    sp_strbuf_printf(b, "feature dim    %d%s\n", s.feat_dim, s.feat_dim ? " (f_sem_*)" : "");
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
        print_bbox(b, "bounding box", lo, hi);
        sp_strbuf_printf(b, "opacity        min %.4f  mean %.4f  max %.4f  (%zu below 0.005)\n", op_min, op_sum / (double)s.n, op_max,
               faint);
        if (scales) {
            qsort(scales, s.n, sizeof(float), cmp_float);
            sp_strbuf_printf(b, "largest axis   median %.4g  p99 %.4g  max %.4g (metres, exp of log-scale)\n", scales[s.n / 2],
                   scales[(size_t)(0.99 * (double)(s.n - 1))], scales[s.n - 1]);
        }
        free(scales);
    }
    sp_splat_free(&s);
    return 0;
}

static int info_image(sp_strbuf *b, const char *path, sp_error *err)
{
    sp_image img;
    int rc = sp_image_read(path, &img, err);
    if (rc) return rc;
    static const char *kinds[5] = {"", "grey", "grey+alpha", "RGB", "RGBA"};
    sp_strbuf_printf(b, "image          %s\n", path);
    sp_strbuf_printf(b, "size           %dx%d, %d channels (%s), %d-bit\n", img.width, img.height, img.channels, kinds[img.channels],
           img.bit_depth);
    size_t n = (size_t)img.width * img.height;
    double max = img.bit_depth == 16 ? 65535.0 : 255.0;
    sp_strbuf_printf(b, "channel mean  ");
    for (int c = 0; c < img.channels; c++) {
        double sum = 0;
        for (size_t i = 0; i < n; i++)
            sum += img.bit_depth == 16 ? ((const uint16_t *)img.data)[i * img.channels + c]
                                       : ((const uint8_t *)img.data)[i * img.channels + c];
        sp_strbuf_printf(b, " %.4f", sum / (double)n / max);
    }
    sp_strbuf_printf(b, "  (of full scale)\n");
    sp_image_free(&img);
    return 0;
}

static void print_shape(sp_strbuf *b, int ndim, const size_t *shape)
{
    sp_strbuf_printf(b, "(");
    for (int k = 0; k < ndim; k++) sp_strbuf_printf(b, "%zu%s", shape[k], ndim == 1 ? "," : k + 1 < ndim ? ", " : "");
    sp_strbuf_printf(b, ")");
}

static int info_npy(sp_strbuf *b, const char *path, sp_error *err)
{
    sp_npy a;
    int rc = sp_npy_read(path, &a, err);
    if (rc) return rc;
    sp_strbuf_printf(b, "npy array      %s\n", path);
    sp_strbuf_printf(b, "dtype          %s\n", io_dtype_name(a.dtype));
    sp_strbuf_printf(b, "shape          ");
    print_shape(b, a.ndim, a.shape);
    size_t n = sp_npy_count(&a);
    sp_strbuf_printf(b, "  (%zu values, %zu bytes)\n", n, n * sp_dtype_size(a.dtype));
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
        if (n > bad) sp_strbuf_printf(b, "values         min %.6g  mean %.6g  max %.6g\n", lo, sum / (double)(n - bad), hi);
        if (bad) sp_strbuf_printf(b, "non-finite     %zu values\n", bad);
        free(f);
    }
    sp_npy_free(&a);
    return 0;
}

static int info_safetensors(sp_strbuf *b, const char *path, int all, sp_error *err)
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
    sp_strbuf_printf(b, "safetensors    %s\n", path);
    sp_strbuf_printf(b, "tensors        %zu (%zu values, %.3g MB)  by dtype:", st.n, params, (double)bytes / 1e6);
    for (int t = 0; t <= SP_DTYPE_BF16; t++)
        if (per_type[t]) sp_strbuf_printf(b, " %s %zu", io_dtype_name((sp_dtype)t), per_type[t]);
    sp_strbuf_printf(b, "\n");
    for (size_t i = 0; i < st.n && (all || i < LIST_MAX); i++) {
        sp_strbuf_printf(b, "  %-56s %-8s ", st.tensors[i].name, io_dtype_name(st.tensors[i].dtype));
        print_shape(b, st.tensors[i].ndim, st.tensors[i].shape);
        sp_strbuf_printf(b, "\n");
    }
    if (!all && st.n > LIST_MAX) sp_strbuf_printf(b, "  ... %zu more (--all)\n", st.n - LIST_MAX);
    sp_safetensors_close(&st);
    return 0;
}


/* cameras.bin, images.txt, ...: a file of a COLMAP model folder (any other .bin or .txt is
 * unknown: describing its folder instead would name the wrong thing). */
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

/* Kind by content: PLY header, PNG/JPEG signature, NUMPY magic, safetensors' 8-byte header
 * length before '{'; .bin/.txt files of a COLMAP model describe the folder around them. */
static int describe_file(sp_strbuf *b, const char *path, int all, sp_error *err)
{
    unsigned char magic[16] = {0};
    FILE *f = fopen(path, "rb");
    size_t got = f ? fread(magic, 1, sizeof magic, f) : 0;
    if (f) fclose(f);
    uint64_t hlen = 0;
    memcpy(&hlen, magic, 8);
    if (got >= 4 && !memcmp(magic, "ply", 3) && (magic[3] == '\n' || magic[3] == '\r'))
        return info_ply(b, path, err);
    if (got >= 8 && (!memcmp(magic, "\x89PNG", 4) || (magic[0] == 0xFF && magic[1] == 0xD8)))
        return info_image(b, path, err);
    if (got >= 6 && !memcmp(magic, "\x93NUMPY", 6)) return info_npy(b, path, err);
    if (got >= 9 && magic[8] == '{' && hlen > 1 && hlen < ((uint64_t)100 << 20))
        return info_safetensors(b, path, all, err);
    if (is_model_file(path)) {
        char dir[4096];
        snprintf(dir, sizeof dir, "%s", path);
        char *slash = strrchr(dir, '/');
        if (slash) *slash = 0;
        else snprintf(dir, sizeof dir, ".");
        return info_colmap(b, dir, all, err);
    }
    return sp_error_set(err, SP_E_UNSUPPORTED,
                        "%s: not a COLMAP model, splat PLY, PNG/JPEG, .npy or safetensors file", path);
}

int sp_io_describe(const char *path, int all, char **text, sp_error *err)
{
    *text = NULL;
    struct stat sb;
    if (stat(path, &sb) != 0) return sp_error_set(err, SP_E_IO, "%s: no such file or folder", path);
    sp_strbuf b = {0};
    int rc = S_ISDIR(sb.st_mode) ? info_colmap(&b, path, all, err) : describe_file(&b, path, all, err);
    if (rc) {
        sp_strbuf_free(&b);
        return rc;
    }
    *text = sp_strbuf_take(&b);
    return *text ? 0 : sp_error_set(err, SP_E_NOMEM, "%s: out of memory describing it", path);
}
