/* One-to-one matching against an independent reference: exhaustive search over every injective
 * assignment (most matches first, then least summed centre distance) on random small cases, plus
 * the admissibility rule and the miss penalty on hand-checked boxes. */
#include <math.h>

#include "semsplat/eval.h"
#include "test.h"

static sp_gt_object box(float cx, float cy, float cz, float hx, float hy, float hz)
{
    sp_gt_object o;
    memset(&o, 0, sizeof o);
    float c[3] = {cx, cy, cz}, h[3] = {hx, hy, hz};
    for (int a = 0; a < 3; a++) {
        o.center[a] = c[a];
        o.aabb_min[a] = c[a] - h[a];
        o.aabb_max[a] = c[a] + h[a];
    }
    return o;
}

static void test_admissible_and_penalty(void)
{
    sp_gt_object o = box(1, 2, 0.5f, 0.4f, 0.3f, 0.5f);
    float in[3] = {1.3f, 2.2f, 0.9f}, near[3] = {1.85f, 2, 0.5f}, far[3] = {2.0f, 2, 0.5f};
    CHECK(sp_eval_admissible(&o, in, 0));
    CHECK(!sp_eval_admissible(&o, near, 0));
    CHECK(sp_eval_admissible(&o, near, 0.5f)); /* 0.45 m outside the box, radius 0.5 */
    CHECK(!sp_eval_admissible(&o, far, 0.5f));
    CHECK_NEAR(sp_eval_miss_penalty(&o, 0.5f), sqrt(0.9 * 0.9 + 0.8 * 0.8 + 1.0), 1e-6);
}

/* Exhaustive reference: best (matches, -error) over all injective maps object -> instance | none. */
typedef struct {
    const sp_gt_object *objs;
    const float *pos;
    int n_obj, n_inst;
    float radius;
    int best_m;
    double best_e;
    int used[8];
} ref_state;

static void ref_search(ref_state *s, int i, int m, double e)
{
    if (i == s->n_obj) {
        if (m > s->best_m || (m == s->best_m && e < s->best_e - 1e-9)) s->best_m = m, s->best_e = e;
        return;
    }
    ref_search(s, i + 1, m, e); /* object i unmatched */
    for (int k = 0; k < s->n_inst; k++) {
        if (s->used[k] || !sp_eval_admissible(&s->objs[i], s->pos + 3 * k, s->radius)) continue;
        const float *p = s->pos + 3 * k, *c = s->objs[i].center;
        double d = sqrt((double)(p[0] - c[0]) * (p[0] - c[0]) + (double)(p[1] - c[1]) * (p[1] - c[1]) +
                        (double)(p[2] - c[2]) * (p[2] - c[2]));
        s->used[k] = 1;
        ref_search(s, i + 1, m + 1, e + d);
        s->used[k] = 0;
    }
}

static void test_against_exhaustive(void)
{
    test_rng r = {77};
    sp_error err = {0};
    for (int trial = 0; trial < 400; trial++) {
        int n_obj = 1 + (int)(test_uniform(&r) * 6), n_inst = (int)(test_uniform(&r) * 7);
        sp_gt_object objs[6];
        float pos[3 * 7];
        /* crowded on purpose: objects overlap and instances sit between them */
        for (int i = 0; i < n_obj; i++)
            objs[i] = box((float)test_range(&r, 0, 2), (float)test_range(&r, 0, 2), 0.4f,
                          (float)test_range(&r, 0.1, 0.5), (float)test_range(&r, 0.1, 0.5), 0.4f);
        for (int k = 0; k < 3 * n_inst; k++) pos[k] = (float)test_range(&r, -0.3, 2.3);
        for (int k = 0; k < n_inst; k++) pos[3 * k + 2] = (float)test_range(&r, 0, 0.9);
        float radius = (float)test_range(&r, 0, 0.5);
        int inst_of[6];
        float e[6];
        int got = sp_eval_match(objs, n_obj, pos, n_inst, radius, inst_of, e, &err);
        ref_state s = {objs, pos, n_obj, n_inst, radius, -1, 0, {0}};
        ref_search(&s, 0, 0, 0);
        double sum = 0;
        int seen[7] = {0}, dup = 0;
        for (int i = 0; i < n_obj; i++) {
            if (inst_of[i] < 0) {
                CHECK(isnan(e[i]));
                continue;
            }
            dup |= seen[inst_of[i]]++;
            CHECK(sp_eval_admissible(&objs[i], pos + 3 * inst_of[i], radius));
            sum += e[i];
        }
        CHECK_MSG(!dup, "trial %d: an instance matched twice", trial);
        CHECK_MSG(got == s.best_m, "trial %d: %d matches, exhaustive %d", trial, got, s.best_m);
        CHECK_MSG(fabs(sum - s.best_e) < 1e-4, "trial %d: summed error %.6f, exhaustive %.6f", trial, sum, s.best_e);
    }
}

/* The case one-to-one exists for: two chairs, one instance between them, one far off. */
static void test_one_instance_one_object(void)
{
    sp_gt_object objs[2] = {box(0, 0, 0.4f, 0.25f, 0.25f, 0.4f), box(1, 0, 0.4f, 0.25f, 0.25f, 0.4f)};
    float pos[6] = {0.1f, 0, 0.4f, 5, 5, 0.4f};
    int inst_of[2];
    float e[2];
    sp_error err = {0};
    CHECK(sp_eval_match(objs, 2, pos, 2, 0.5f, inst_of, e, &err) == 1);
    CHECK(inst_of[0] == 0 && inst_of[1] == -1);
    CHECK_NEAR(e[0], 0.1, 1e-6);
    CHECK(sp_eval_match(objs, 2, pos, 0, 0.5f, inst_of, e, &err) == 0 && inst_of[0] == -1);
}

int main(void)
{
    RUN(test_admissible_and_penalty);
    RUN(test_against_exhaustive);
    RUN(test_one_instance_one_object);
    return TEST_EXIT();
}
