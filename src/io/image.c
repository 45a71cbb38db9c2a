/* PNG and JPEG reading and writing (libpng, libjpeg), chosen by file content. Captures come in as
 * either; renders and feature previews go out as PNG. 16-bit PNGs (depth maps) keep 16 bits. */
#include "io_internal.h"

#include <errno.h>
#include <jpeglib.h>
#include <jerror.h>
#include <png.h>
#include <setjmp.h>
#include <stdlib.h>

/* Decoded images beyond this many pixels are refused before allocating (a corrupt header must not
 * ask for terabytes). 2^28 pixels = 16k x 16k. */
#define IMAGE_MAX_PIXELS ((size_t)1 << 28)

void sp_image_free(sp_image *img)
{
    if (!img) return;
    sp_free(img->data);
    memset(img, 0, sizeof *img);
}

/* ---- PNG -------------------------------------------------------------------------------------- */

typedef struct {
    jmp_buf jmp;
    char msg[256];
    int err_no; /* errno when libpng gave up (a failed fwrite's cause) */
} png_ctx;

static void png_on_error(png_structp png, png_const_charp msg)
{
    png_ctx *ctx = png_get_error_ptr(png);
    ctx->err_no = errno;
    snprintf(ctx->msg, sizeof ctx->msg, "%s", msg);
    longjmp(ctx->jmp, 1);
}

static void png_on_warning(png_structp png, png_const_charp msg) { (void)png, (void)msg; }

static int read_png(const char *path, FILE *f, sp_image *img, sp_error *err)
{
    png_ctx ctx = {.msg = ""};
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &ctx, png_on_error, png_on_warning);
    if (!png) return sp_error_set(err, SP_E_NOMEM, "%s: cannot create a PNG reader", path);
    png_infop info = png_create_info_struct(png);
    /* volatile: modified between setjmp and a possible longjmp. */
    unsigned char *volatile data = NULL;
    png_bytep *volatile rows = NULL;
    if (!info || setjmp(ctx.jmp)) {
        png_destroy_read_struct(&png, info ? &info : NULL, NULL);
        sp_free(data);
        free(rows);
        return sp_error_set(err, SP_E_FORMAT, "%s: bad PNG: %s", path, ctx.msg[0] ? ctx.msg : "cannot decode");
    }
    png_init_io(png, f);
    png_read_info(png, info);
    png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
    int depth = png_get_bit_depth(png, info), type = png_get_color_type(png, info);
    /* Normalise to grey / grey+alpha / RGB / RGBA at 8 or 16 bits, samples in host order. */
    if (type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (type == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
    if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
    if (depth == 16) png_set_swap(png);
    png_set_interlace_handling(png); /* Adam7 files are de-interlaced by png_read_image */
    png_read_update_info(png, info);
    int channels = png_get_channels(png, info);
    int out_depth = png_get_bit_depth(png, info);
    if ((size_t)w * h > IMAGE_MAX_PIXELS || w == 0 || h == 0) {
        png_destroy_read_struct(&png, &info, NULL);
        return sp_error_set(err, SP_E_FORMAT, "%s: PNG size %ux%u is out of range", path, (unsigned)w,
                            (unsigned)h);
    }
    size_t rowbytes = png_get_rowbytes(png, info);
    size_t bps = out_depth == 16 ? 2 : 1;
    if (rowbytes != (size_t)w * channels * bps) png_error(png, "unexpected row size after transforms");
    data = sp_alloc(rowbytes * h);
    rows = malloc(sizeof(png_bytep) * h);
    if (!data || !rows) png_error(png, "out of memory");
    for (png_uint_32 y = 0; y < h; y++) rows[y] = data + y * rowbytes;
    png_read_image(png, rows);
    png_read_end(png, NULL);
    png_destroy_read_struct(&png, &info, NULL);
    free(rows);
    img->width = (int)w;
    img->height = (int)h;
    img->channels = channels;
    img->bit_depth = out_depth;
    img->data = data;
    return SP_OK;
}

static int check_image(const char *path, const sp_image *img, sp_error *err)
{
    if (!img || !img->data || img->width <= 0 || img->height <= 0)
        return sp_error_set(err, SP_E_ARG, "%s: image is empty", path);
    if (img->channels < 1 || img->channels > 4)
        return sp_error_set(err, SP_E_ARG, "%s: %d channels (must be 1..4)", path, img->channels);
    if (img->bit_depth != 8 && img->bit_depth != 16)
        return sp_error_set(err, SP_E_ARG, "%s: bit depth %d (must be 8 or 16)", path, img->bit_depth);
    return SP_OK;
}

int sp_image_write_png(const char *path, const sp_image *img, sp_error *err)
{
    int rc = check_image(path, img, err);
    if (rc) return rc;
    char tmp[4200];
    FILE *f = io_tmp_open(path, tmp, sizeof tmp, err);
    if (!f) return err ? err->code : SP_E_IO;
    png_ctx ctx = {.msg = ""};
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &ctx, png_on_error, png_on_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!png || !info || setjmp(ctx.jmp)) {
        png_destroy_write_struct(&png, info ? &info : NULL);
        rc = sp_error_set(err, SP_E_IO, "%s: PNG write failed: %s%s%s", path, ctx.msg[0] ? ctx.msg : "no memory",
                          ctx.err_no ? ": " : "", ctx.err_no ? strerror(ctx.err_no) : "");
        io_tmp_commit(f, tmp, path, 0, NULL);
        return rc;
    }
    static const int types[5] = {0, PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                 PNG_COLOR_TYPE_RGB_ALPHA};
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)img->width, (png_uint_32)img->height, img->bit_depth,
                 types[img->channels], PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_set_compression_level(png, 6);
    png_write_info(png, info);
    if (img->bit_depth == 16) png_set_swap(png);
    size_t rowbytes = (size_t)img->width * img->channels * (img->bit_depth / 8);
    for (int y = 0; y < img->height; y++)
        png_write_row(png, (png_const_bytep)img->data + (size_t)y * rowbytes);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return io_tmp_commit(f, tmp, path, 1, err);
}

/* ---- JPEG ------------------------------------------------------------------------------------- */

typedef struct {
    struct jpeg_error_mgr mgr;
    jmp_buf jmp;
    int truncated;
    int err_no; /* errno when libjpeg gave up */
    char msg[JMSG_LENGTH_MAX];
} jpeg_ctx;

static void jpeg_on_error(j_common_ptr cinfo)
{
    jpeg_ctx *ctx = (jpeg_ctx *)cinfo->err;
    ctx->err_no = errno;
    cinfo->err->format_message(cinfo, ctx->msg);
    longjmp(ctx->jmp, 1);
}

static void jpeg_on_message(j_common_ptr cinfo) { (void)cinfo; }

/* libjpeg only warns at a premature end of data or corrupt entropy-coded data and invents the
 * missing pixels (grey); a truncated or corrupt capture image must fail instead. Other warnings
 * (extraneous bytes between markers, unknown JFIF revisions, ...) are benign and ignored. */
static void jpeg_on_emit(j_common_ptr cinfo, int level)
{
    jpeg_ctx *ctx = (jpeg_ctx *)cinfo->err;
    if (level >= 0 || ctx->truncated) return;
    int code = cinfo->err->msg_code;
    if (code == JWRN_JPEG_EOF || code == JWRN_HIT_MARKER || code == JWRN_HUFF_BAD_CODE || code == JWRN_ARITH_BAD_CODE ||
        code == JWRN_MUST_RESYNC || code == JWRN_BOGUS_PROGRESSION || code == JWRN_NOT_SEQUENTIAL) {
        ctx->truncated = code == JWRN_JPEG_EOF ? 1 : 2;
        cinfo->err->format_message(cinfo, ctx->msg);
    }
}

static int read_jpeg(const char *path, FILE *f, sp_image *img, sp_error *err)
{
    struct jpeg_decompress_struct cinfo;
    jpeg_ctx ctx;
    memset(&ctx, 0, sizeof ctx);
    cinfo.err = jpeg_std_error(&ctx.mgr);
    ctx.mgr.error_exit = jpeg_on_error;
    ctx.mgr.output_message = jpeg_on_message;
    ctx.mgr.emit_message = jpeg_on_emit;
    unsigned char *volatile data = NULL;
    if (setjmp(ctx.jmp)) {
        jpeg_destroy_decompress(&cinfo);
        sp_free(data);
        return sp_error_set(err, SP_E_FORMAT, "%s: bad JPEG: %s", path, ctx.msg);
    }
    jpeg_create_decompress(&cinfo);
    jpeg_stdio_src(&cinfo, f);
    jpeg_read_header(&cinfo, TRUE);
    if (cinfo.jpeg_color_space == JCS_CMYK || cinfo.jpeg_color_space == JCS_YCCK) {
        jpeg_destroy_decompress(&cinfo);
        return sp_error_set(err, SP_E_UNSUPPORTED, "%s: CMYK JPEG is not supported (convert to RGB)", path);
    }
    cinfo.out_color_space = cinfo.num_components == 1 ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_start_decompress(&cinfo);
    size_t w = cinfo.output_width, h = cinfo.output_height, c = (size_t)cinfo.output_components;
    if (w * h > IMAGE_MAX_PIXELS) {
        jpeg_destroy_decompress(&cinfo);
        return sp_error_set(err, SP_E_FORMAT, "%s: JPEG size %zux%zu is out of range", path, w, h);
    }
    data = sp_alloc(w * h * c);
    if (!data) {
        jpeg_destroy_decompress(&cinfo);
        return sp_error_set(err, SP_E_NOMEM, "%s: out of memory for a %zux%zu image", path, w, h);
    }
    /* Stop at the premature end: libjpeg would pad the rest with grey, which for a corrupt header
     * declaring 16k x 16k pixels is seconds of decoding nothing. */
    while (cinfo.output_scanline < cinfo.output_height && !ctx.truncated) {
        JSAMPROW row = data + (size_t)cinfo.output_scanline * w * c;
        jpeg_read_scanlines(&cinfo, &row, 1);
    }
    if (!ctx.truncated) jpeg_finish_decompress(&cinfo);
    jpeg_destroy_decompress(&cinfo);
    if (ctx.truncated) {
        sp_free(data);
        return sp_error_set(err, SP_E_FORMAT, "%s: JPEG data is %s (%s)", path,
                            ctx.truncated == 1 ? "truncated" : "corrupt", ctx.msg);
    }
    img->width = (int)w;
    img->height = (int)h;
    img->channels = (int)c;
    img->bit_depth = 8;
    img->data = data;
    return SP_OK;
}

int sp_image_write_jpeg(const char *path, const sp_image *img, int quality, sp_error *err)
{
    int rc = check_image(path, img, err);
    if (rc) return rc;
    if (quality < 1 || quality > 100)
        return sp_error_set(err, SP_E_ARG, "%s: JPEG quality %d is not in 1..100", path, quality);
    /* JPEG has no alpha and 8 bits only: alpha is dropped, 16-bit samples keep their high byte. */
    int in_c = img->channels, out_c = in_c >= 3 ? 3 : 1;
    unsigned char *row = malloc((size_t)img->width * 3);
    if (!row) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    char tmp[4200];
    FILE *f = io_tmp_open(path, tmp, sizeof tmp, err);
    if (!f) {
        free(row);
        return err ? err->code : SP_E_IO;
    }
    struct jpeg_compress_struct cinfo;
    jpeg_ctx ctx;
    memset(&ctx, 0, sizeof ctx);
    cinfo.err = jpeg_std_error(&ctx.mgr);
    ctx.mgr.error_exit = jpeg_on_error;
    ctx.mgr.output_message = jpeg_on_message;
    if (setjmp(ctx.jmp)) {
        jpeg_destroy_compress(&cinfo);
        free(row);
        rc = sp_error_set(err, SP_E_IO, "%s: JPEG write failed: %s%s%s", path, ctx.msg, ctx.err_no ? ": " : "",
                          ctx.err_no ? strerror(ctx.err_no) : "");
        io_tmp_commit(f, tmp, path, 0, NULL);
        return rc;
    }
    jpeg_create_compress(&cinfo);
    jpeg_stdio_dest(&cinfo, f);
    cinfo.image_width = (JDIMENSION)img->width;
    cinfo.image_height = (JDIMENSION)img->height;
    cinfo.input_components = out_c;
    cinfo.in_color_space = out_c == 3 ? JCS_RGB : JCS_GRAYSCALE;
    jpeg_set_defaults(&cinfo);
    jpeg_set_quality(&cinfo, quality, TRUE);
    jpeg_start_compress(&cinfo, TRUE);
    for (int y = 0; y < img->height; y++) {
        for (int x = 0; x < img->width; x++) {
            size_t base = ((size_t)y * img->width + x) * in_c;
            for (int k = 0; k < out_c; k++) {
                row[(size_t)x * out_c + k] = img->bit_depth == 16
                    ? (unsigned char)(((const uint16_t *)img->data)[base + k] >> 8)
                    : ((const unsigned char *)img->data)[base + k];
            }
        }
        JSAMPROW r = row;
        jpeg_write_scanlines(&cinfo, &r, 1);
    }
    jpeg_finish_compress(&cinfo);
    jpeg_destroy_compress(&cinfo);
    free(row);
    return io_tmp_commit(f, tmp, path, 1, err);
}

/* ---- dispatch and conversions ----------------------------------------------------------------- */

/* PNG or JPEG by the first bytes of f; path names it in messages. */
static int read_stream(FILE *f, const char *path, sp_image *img, sp_error *err)
{
    unsigned char magic[8] = {0};
    size_t got = fread(magic, 1, sizeof magic, f);
    rewind(f);
    int rc;
    if (got == 8 && png_sig_cmp(magic, 0, 8) == 0)
        rc = read_png(path, f, img, err);
    else if (got >= 3 && magic[0] == 0xFF && magic[1] == 0xD8 && magic[2] == 0xFF)
        rc = read_jpeg(path, f, img, err);
    else
        rc = sp_error_set(err, SP_E_FORMAT, "%s: neither a PNG nor a JPEG (first bytes %02x %02x %02x)",
                          path, magic[0], magic[1], magic[2]);
    if (rc) memset(img, 0, sizeof *img);
    return rc;
}

int sp_image_read(const char *path, sp_image *img, sp_error *err)
{
    memset(img, 0, sizeof *img);
    FILE *f = fopen(path, "rb");
    if (!f) return sp_error_set(err, SP_E_IO, "%s: cannot open: %s", path, strerror(errno));
    int rc = read_stream(f, path, img, err);
    fclose(f);
    return rc;
}

int sp_image_decode(const void *data, size_t size, const char *name, sp_image *img, sp_error *err)
{
    memset(img, 0, sizeof *img);
    FILE *f = io_memstream(data, size, name, "a PNG or JPEG", err);
    if (!f) return err ? err->code : SP_E_FORMAT;
    int rc = read_stream(f, name, img, err);
    fclose(f);
    return rc;
}

int sp_image_to_rgbf(const sp_image *img, float **rgb, sp_error *err)
{
    *rgb = NULL;
    int rc = check_image("image", img, err);
    if (rc) return rc;
    size_t n = (size_t)img->width * img->height, c = (size_t)img->channels;
    float *out = sp_alloc(n * 3 * sizeof(float));
    if (!out) return sp_error_set(err, SP_E_NOMEM, "image: out of memory converting %zu pixels", n);
    float scale = img->bit_depth == 16 ? 1.0f / 65535.0f : 1.0f / 255.0f;
    for (size_t i = 0; i < n; i++) {
        for (int k = 0; k < 3; k++) {
            /* Grey (1 or 2 channels) is replicated; a 4th channel (alpha) is dropped. */
            size_t src = i * c + (c >= 3 ? (size_t)k : 0);
            float v = img->bit_depth == 16 ? ((const uint16_t *)img->data)[src]
                                           : ((const unsigned char *)img->data)[src];
            out[i * 3 + k] = v * scale;
        }
    }
    *rgb = out;
    return SP_OK;
}

int sp_write_png_f32(const char *path, const float *data, int width, int height, int channels,
                     sp_error *err)
{
    if (!data || width <= 0 || height <= 0 || channels < 1 || channels > 4)
        return sp_error_set(err, SP_E_ARG, "%s: bad float image %dx%dx%d", path, width, height, channels);
    size_t n = (size_t)width * height * channels;
    unsigned char *px = malloc(n);
    if (!px) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    for (size_t i = 0; i < n; i++) {
        float v = data[i];
        v = v != v ? 0.0f : v < 0 ? 0.0f : v > 1 ? 1.0f : v; /* NaN shows as black */
        px[i] = (unsigned char)(v * 255.0f + 0.5f);
    }
    sp_image img = {width, height, channels, 8, px};
    int rc = sp_image_write_png(path, &img, err);
    free(px);
    return rc;
}
