/* Shared by fuzz_png.c and fuzz_jpeg.c: an image decoded by our wrapper (sp_image_decode) must
 * convert to float RGB, and small ones must survive a PNG write and re-read exactly. */
#ifndef SP_FUZZ_IMAGE_H
#define SP_FUZZ_IMAGE_H

#include "fuzz_util.h"
#include "semsplat/io.h"

static inline int fz_image_one(const uint8_t *data, size_t size, const char *name)
{
    sp_image img, back;
    sp_error err = {0};
    int rc = sp_image_decode(data, size, name, &img, &err);
    if (rc) {
        fz_check_error(rc, &err, "sp_image_decode");
        FZ_ASSERT(!img.data, "a failed decode left pixels behind");
        return 0;
    }
    FZ_ASSERT(img.width > 0 && img.height > 0 && img.channels >= 1 && img.channels <= 4 &&
                  (img.bit_depth == 8 || img.bit_depth == 16),
              "decoded %dx%dx%d at %d bits", img.width, img.height, img.channels, img.bit_depth);
    float *rgb = NULL;
    if ((size_t)img.width * img.height <= 4096 * 4096) { /* a huge valid image is slow, not a fault */
        rc = sp_image_to_rgbf(&img, &rgb, &err);
        FZ_ASSERT(rc == 0, "sp_image_to_rgbf: %s", err.msg);
        sp_free(rgb);
    }
    if ((size_t)img.width * img.height <= 256 * 256) {
        char path[1024];
        fz_path("rt.png", path);
        rc = sp_image_write_png(path, &img, &err);
        FZ_ASSERT(rc == 0, "a decoded image does not write as PNG: %s", err.msg);
        rc = sp_image_read(path, &back, &err);
        FZ_ASSERT(rc == 0, "our PNG does not read back: %s", err.msg);
        size_t bytes = (size_t)img.width * img.height * img.channels * (img.bit_depth / 8);
        FZ_ASSERT(back.width == img.width && back.height == img.height && back.channels == img.channels &&
                      back.bit_depth == img.bit_depth && !memcmp(back.data, img.data, bytes),
                  "PNG round trip changed the image");
        sp_image_free(&back);
    }
    sp_image_free(&img);
    return 0;
}

#endif
