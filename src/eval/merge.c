/* Fragments of one object merged into one instance before scoring: the clustering of a query's
 * Gaussians (or pixels) can split a bed, a sofa or a counter into parts, and scoring the biggest
 * part would report a part's centre as the object's. Parts touch; separate objects of one class
 * (chairs round a table) stand apart. */
#include <stdlib.h>
#include <string.h>

#include "semsplat/eval.h"

static int find(int *parent, int i)
{
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

static int touching(const sp_query_instance *a, const sp_query_instance *b, float gap)
{
    for (int k = 0; k < 3; k++)
        if (a->extent_min[k] > b->extent_max[k] + gap || b->extent_min[k] > a->extent_max[k] + gap)
            return 0;
    return 1;
}

static int by_score(const void *x, const void *y)
{
    const sp_query_instance *a = x, *b = y;
    return (a->score < b->score) - (a->score > b->score);
}

int sp_eval_merge_fragments(sp_query_result *res, float gap_m, sp_error *err)
{
    int n = res->n_instances;
    if (n < 2 || gap_m < 0) return n;
    int *parent = malloc(sizeof *parent * (size_t)n);
    sp_query_instance *out = malloc(sizeof *out * (size_t)n);
    if (!parent || !out) {
        free(parent);
        free(out);
        return sp_error_set(err, SP_E_NOMEM, "eval: out of memory merging %d instances", n);
    }
    for (int i = 0; i < n; i++) parent[i] = i;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            if (touching(&res->instances[i], &res->instances[j], gap_m)) parent[find(parent, i)] = find(parent, j);
    int m = 0;
    for (int i = 0; i < n; i++) {
        if (find(parent, i) != i) continue;
        sp_query_instance u = {0};
        int first = 1;
        for (int j = 0; j < n; j++) {
            if (find(parent, j) != i) continue;
            const sp_query_instance *p = &res->instances[j];
            for (int k = 0; k < 3; k++) {
                u.extent_min[k] = first ? p->extent_min[k] : fminf(u.extent_min[k], p->extent_min[k]);
                u.extent_max[k] = first ? p->extent_max[k] : fmaxf(u.extent_max[k], p->extent_max[k]);
            }
            u.score += p->score;
            u.n_points += p->n_points;
            u.confidence = first ? p->confidence : fmaxf(u.confidence, p->confidence);
            first = 0;
        }
        for (int k = 0; k < 3; k++) u.position[k] = 0.5f * (u.extent_min[k] + u.extent_max[k]);
        out[m++] = u;
    }
    qsort(out, (size_t)m, sizeof *out, by_score);
    memcpy(res->instances, out, sizeof *out * (size_t)m);
    res->n_instances = m;
    if (res->valid && m > 0) memcpy(res->position, out[0].position, sizeof res->position);
    free(parent);
    free(out);
    return m;
}
