/* The `labels` feature source: the label images that `semsplat synth` writes, read as per-cell
 * class weights (labels.json: labels_json.c). */
#include <stdint.h>
#include <stdlib.h>

#include "features_internal.h"
#include "semsplat/io.h"

int label_weights(const char *path, const clip_label_table *t, int factor, float **w, int *mw, int *mh, sp_error *err)
{
    *w = NULL;
    sp_image img;
    int rc = sp_image_read(path, &img, err);
    if (rc) return rc;
    int W = img.width, H = img.height, nc = t->n_classes;
    *mw = (W + factor - 1) / factor;
    *mh = (H + factor - 1) / factor;
    size_t cells = (size_t)*mw * *mh;
    if ((double)cells * nc > (double)(1 << 28)) {
        sp_image_free(&img);
        return sp_error_set(err, SP_E_NOMEM, "%s: %zu cells x %d classes is too large a weight map", path, cells, nc);
    }
    float *m = calloc(cells * nc, sizeof *m);
    if (!m) {
        sp_image_free(&img);
        return sp_error_set(err, SP_E_NOMEM, "out of memory");
    }
    for (int y = 0; y < H && !rc; y++) {
        float *row = m + (size_t)(y / factor) * *mw * nc;
        for (int x = 0; x < W; x++) {
            size_t at = ((size_t)y * W + x) * img.channels;
            int id = img.bit_depth == 16 ? ((uint16_t *)img.data)[at] : ((uint8_t *)img.data)[at];
            if (id >= t->n) {
                rc = sp_error_set(err, SP_E_FORMAT, "%s: pixel (%d, %d) has label %d, labels.json knows ids up to %d",
                                  path, x, y, id, t->n - 1);
                break;
            }
            row[(size_t)(x / factor) * nc + t->class_of[id]] += 1.f;
        }
    }
    sp_image_free(&img);
    if (rc) {
        free(m);
        return rc;
    }
    for (size_t c = 0; c < cells; c++) {
        float *r = m + c * nc, n = 0;
        for (int k = 0; k < nc; k++) n += r[k];
        for (int k = 0; k < nc; k++) r[k] /= n;
    }
    *w = m;
    return 0;
}
