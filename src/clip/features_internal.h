/* Private to src/clip: the `labels` feature source (features_labels.c), used by features.c. */
#ifndef SP_CLIP_FEATURES_INTERNAL_H
#define SP_CLIP_FEATURES_INTERNAL_H

#include "clip_internal.h"
#include "semsplat/clip.h"

/* labels.json is read by clip_label_table_read (labels_json.c, clip_internal.h: the fuzzed
 * reader). */

/* The label image at path as class weights per map cell: w [mh][mw][n_classes], each cell of
 * factor x factor pixels (clipped at the border) holding the share of its pixels in each class
 * (rows sum to 1). A cell's feature is then w times the class embeddings, and its PCA code w
 * times the classes' codes: both one small product instead of a sum over every pixel. */
int label_weights(const char *path, const clip_label_table *t, int factor, float **w, int *mw, int *mh, sp_error *err);

#endif
