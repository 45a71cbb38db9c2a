/* Private to src/clip: the `labels` feature source (features_labels.c), used by features.c. */
#ifndef SP_CLIP_FEATURES_INTERNAL_H
#define SP_CLIP_FEATURES_INTERNAL_H

#include "semsplat/clip.h"

/* label id -> class name, from labels.json ({"labels": {"1": {"class": ..}}} as synth writes it,
 * or {"labels": [{"id": 1, "class": ..}]}). */
typedef struct label_table {
    int n;                /* ids 0..n-1 */
    char (*cls)[128];
    int n_classes;
    char (*class_names)[128];
    int *class_of;        /* id -> class index */
} label_table;

int label_table_read(const char *path, label_table *t, sp_error *err);
void label_table_free(label_table *t);

/* The label image at path as class weights per map cell: w [mh][mw][n_classes], each cell of
 * factor x factor pixels (clipped at the border) holding the share of its pixels in each class
 * (rows sum to 1). A cell's feature is then w times the class embeddings, and its PCA code w
 * times the classes' codes: both one small product instead of a sum over every pixel. */
int label_weights(const char *path, const label_table *t, int factor, float **w, int *mw, int *mh, sp_error *err);

#endif
