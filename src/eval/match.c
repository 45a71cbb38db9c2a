/* One-to-one matching of returned instances to ground-truth objects: admissible pairs (the
 * instance inside the object's box grown by a radius), then the assignment with the most matches
 * and the least summed centre distance, by the Hungarian algorithm (Kuhn-Munkres with
 * potentials, O(N^3) on the square padded cost matrix; N is a class's object or instance count). */
#include <math.h>
#include <stdlib.h>

#include "semsplat/eval.h"

int sp_eval_admissible(const sp_gt_object *o, const float p[3], float radius)
{
    for (int a = 0; a < 3; a++)
        if (!(p[a] >= o->aabb_min[a] - radius && p[a] <= o->aabb_max[a] + radius)) return 0;
    return 1;
}

float sp_eval_miss_penalty(const sp_gt_object *o, float radius)
{
    double s = 0;
    for (int a = 0; a < 3; a++) {
        double h = 0.5 * ((double)o->aabb_max[a] - o->aabb_min[a]) + radius;
        s += h * h;
    }
    return (float)sqrt(s);
}

static double dist3(const float *a, const float *b)
{
    double dx = (double)a[0] - b[0], dy = (double)a[1] - b[1], dz = (double)a[2] - b[2];
    return sqrt(dx * dx + dy * dy + dz * dz);
}

/* Minimum-cost perfect assignment of an N x N matrix c (row-major): row_to[i] = column. */
static int hungarian(const double *c, int N, int *row_to, sp_error *err)
{
    double *u = calloc((size_t)N + 1, sizeof *u), *v = calloc((size_t)N + 1, sizeof *v);
    double *minv = malloc(sizeof(double) * ((size_t)N + 1));
    int *p = calloc((size_t)N + 1, sizeof *p), *way = calloc((size_t)N + 1, sizeof *way);
    char *used = malloc((size_t)N + 1);
    if (!u || !v || !minv || !p || !way || !used) {
        free(u), free(v), free(minv), free(p), free(way), free(used);
        return sp_error_set(err, SP_E_NOMEM, "matching: out of memory for %d x %d", N, N);
    }
    /* 1-based: p[j] is the row assigned to column j, column 0 a sentinel */
    for (int i = 1; i <= N; i++) {
        p[0] = i;
        int j0 = 0;
        for (int j = 0; j <= N; j++) minv[j] = INFINITY, used[j] = 0;
        do {
            used[j0] = 1;
            int i0 = p[j0], j1 = 0;
            double delta = INFINITY;
            for (int j = 1; j <= N; j++) {
                if (used[j]) continue;
                double cur = c[(size_t)(i0 - 1) * N + (j - 1)] - u[i0] - v[j];
                if (cur < minv[j]) minv[j] = cur, way[j] = j0;
                if (minv[j] < delta) delta = minv[j], j1 = j;
            }
            for (int j = 0; j <= N; j++) {
                if (used[j]) u[p[j]] += delta, v[j] -= delta;
                else minv[j] -= delta;
            }
            j0 = j1;
        } while (p[j0] != 0);
        do {
            int j1 = way[j0];
            p[j0] = p[j1];
            j0 = j1;
        } while (j0);
    }
    for (int j = 1; j <= N; j++) row_to[p[j] - 1] = j - 1;
    free(u), free(v), free(minv), free(p), free(way), free(used);
    return 0;
}

int sp_eval_match(const sp_gt_object *objs, int n_obj, const float *positions, int n_inst,
                  float radius, int *instance_of, float *error, sp_error *err)
{
    for (int i = 0; i < n_obj; i++) {
        instance_of[i] = -1;
        if (error) error[i] = NAN;
    }
    if (n_obj <= 0 || n_inst <= 0) return 0;
    int N = n_obj > n_inst ? n_obj : n_inst;
    double *c = malloc(sizeof(double) * (size_t)N * N);
    int *row_to = malloc(sizeof(int) * (size_t)N);
    if (!c || !row_to) {
        free(c), free(row_to);
        return sp_error_set(err, SP_E_NOMEM, "matching: out of memory for %d x %d", N, N);
    }
    /* A non-match costs more than all admissible errors together, so the assignment first
     * maximizes the number of matches, then minimizes their summed error. */
    double total = 0;
    for (int i = 0; i < n_obj; i++)
        for (int k = 0; k < n_inst; k++)
            if (sp_eval_admissible(&objs[i], positions + 3 * k, radius))
                total += dist3(positions + 3 * k, objs[i].center);
    double big = 2.0 * total + 1.0;
    for (int i = 0; i < N; i++)
        for (int k = 0; k < N; k++) {
            int real = i < n_obj && k < n_inst;
            c[(size_t)i * N + k] = real && sp_eval_admissible(&objs[i], positions + 3 * k, radius)
                                       ? dist3(positions + 3 * k, objs[i].center) : big;
        }
    int rc = hungarian(c, N, row_to, err), matched = 0;
    for (int i = 0; i < n_obj && !rc; i++) {
        int k = row_to[i];
        if (k >= n_inst || !sp_eval_admissible(&objs[i], positions + 3 * k, radius)) continue;
        instance_of[i] = k;
        if (error) error[i] = (float)dist3(positions + 3 * k, objs[i].center);
        matched++;
    }
    free(c), free(row_to);
    return rc ? rc : matched;
}
