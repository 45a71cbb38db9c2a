/* eval: ground truth read from the world file. A copy of the house with its refrigerator moved
 * 1.2 m gives a ground truth moved by the same amount and, for the same estimate, the error of
 * the move; the second small world reads with its classes. Fragments of one object are merged
 * into one instance, separate objects of a class are not. */
#include "eval/small_world.h"
#include "semsplat/eval.h"
#include "semsplat/io.h"
#include "test.h"

static const sp_gt_object *find(const sp_ground_truth *gt, const char *name)
{
    for (size_t i = 0; i < gt->n; i++)
        if (!strcmp(gt->objects[i].name, name)) return &gt->objects[i];
    return NULL;
}

/* A query result with instances at the given positions (boxes of half-size h around them). */
static void fake_result(sp_query_result *r, const float (*p)[3], int n, float h)
{
    memset(r, 0, sizeof *r);
    r->valid = n > 0;
    r->n_instances = n;
    r->instances = calloc((size_t)(n ? n : 1), sizeof *r->instances);
    for (int i = 0; i < n; i++) {
        sp_query_instance *q = &r->instances[i];
        for (int k = 0; k < 3; k++) {
            q->position[k] = p[i][k];
            q->extent_min[k] = p[i][k] - h;
            q->extent_max[k] = p[i][k] + h;
        }
        q->score = (float)(n - i);
        q->confidence = 0.9f;
        q->n_points = 10;
    }
    if (n) memcpy(r->position, p[0], sizeof r->position);
}

/* The error the report gives the refrigerator for one estimate, against a ground truth. */
static float fridge_error(const sp_ground_truth *gt, const float est[3])
{
    sp_eval_report rep;
    sp_error err = {0};
    if (sp_eval_report_init(&rep, gt, NULL, 0.5f, &err)) return -1;
    size_t q = 0;
    while (q < rep.n_queries && strcmp(rep.queries[q].text, "refrigerator")) q++;
    sp_query_result r;
    fake_result(&r, (const float(*)[3])est, 1, 0.2f);
    float e = -1;
    if (q < rep.n_queries && !sp_eval_report_add(&rep, gt, q, 0, &r, &err)) {
        for (size_t i = 0; i < rep.n_objects; i++)
            if (!strcmp(rep.objects[i].cls, "refrigerator")) e = rep.objects[i].error_m[0];
    }
    sp_query_result_free(&r);
    sp_eval_report_free(&rep);
    return e;
}

static void test_moved_refrigerator_in_the_house(void)
{
    sp_error err = {0};
    char src[1200], dst[1300], models[1200];
    snprintf(src, sizeof src, "%s/data/worlds/house.world", SP_SOURCE_DIR);
    snprintf(models, sizeof models, "%s/data/worlds/house_models", SP_SOURCE_DIR);
    snprintf(dst, sizeof dst, "%s/house_moved.world", test_tmpdir("eval_moved_fridge"));
    char *text = NULL;
    size_t n = 0;
    CHECK_OK(sp_read_file(src, &text, &n, &err), &err);
    if (!text) return;
    const char *from = "<name>refrigerator</name>\n    <pose>0.45 7.55 0 0 0 -1.5708</pose>";
    char *at = strstr(text, from);
    CHECK_MSG(at != NULL, "the house's refrigerator pose changed; update this test");
    if (!at) return free(text);
    /* a copy with the refrigerator 1.2 m further along +x */
    FILE *f = fopen(dst, "w");
    fwrite(text, 1, (size_t)(at - text), f);
    fputs("<name>refrigerator</name>\n    <pose>1.65 7.55 0 0 0 -1.5708</pose>", f);
    fputs(at + strlen(from), f);
    fclose(f);
    free(text);
    sp_ground_truth a, b;
    CHECK_OK(sp_ground_truth_from_world(src, models, 0, NULL, &a, &err), &err);
    CHECK_OK(sp_ground_truth_from_world(dst, models, 0, NULL, &b, &err), &err);
    if (err.code) return;
    CHECK(a.n == b.n && a.n >= 20);
    const sp_gt_object *fa = find(&a, "refrigerator"), *fb = find(&b, "refrigerator");
    CHECK(fa && fb);
    if (!fa || !fb) return;
    CHECK_NEAR(fb->center[0] - fa->center[0], 1.2, 1e-4);
    CHECK_NEAR(fb->center[1] - fa->center[1], 0, 1e-4);
    CHECK(!strcmp(fa->cls, "refrigerator"));
    /* nothing else moved */
    const sp_gt_object *ca = find(&a, "kitchen_counter_1"), *cb = find(&b, "kitchen_counter_1");
    CHECK(ca && cb && ca->center[0] == cb->center[0]);
    /* the same estimate: right on the original, 1.2 m off (and missed, beyond 0.5 m) on the copy */
    float est[3] = {fa->center[0] + 0.05f, fa->center[1], fa->center[2]};
    CHECK_NEAR(fridge_error(&a, est), 0.05, 1e-4);
    float moved[3] = {fb->center[0] - 1.15f, fb->center[1], fb->center[2]};
    CHECK(isnan(fridge_error(&b, moved))); /* outside the grown box: a miss */
    float near_b[3] = {fb->center[0] + 0.1f, fb->center[1] - 0.1f, fb->center[2]};
    CHECK_NEAR(fridge_error(&b, near_b), sqrt(0.02), 1e-4);
    sp_ground_truth_free(&a);
    sp_ground_truth_free(&b);
    CHECK_FAILS(sp_ground_truth_from_world("/no/such.world", NULL, 0, NULL, &a, &err), SP_E_IO, &err,
                "no/such.world");
}

static void test_small_world_truth(void)
{
    sp_error err = {0};
    char path[1300];
    snprintf(path, sizeof path, "%s/small.world", test_tmpdir("eval_small_truth"));
    CHECK(small_world_write(path, 2.0, 2.5) == 0);
    sp_ground_truth gt;
    CHECK_OK(sp_ground_truth_from_world(path, NULL, 0, NULL, &gt, &err), &err);
    CHECK(gt.n == 11);
    const sp_gt_object *fr = find(&gt, "refrigerator");
    CHECK(fr && fabsf(fr->center[0] - 2.0f) < 1e-4f && fabsf(fr->center[1] - 2.5f) < 1e-4f);
    CHECK(fr && fabsf(fr->aabb_max[2] - 1.8f) < 1e-4f);
    CHECK(find(&gt, "walls") == NULL && find(&gt, "floor") == NULL);
    sp_ground_truth_free(&gt);
}

static void test_merge_fragments(void)
{
    sp_error err = {0};
    /* a bed in two halves (touching), a chair 0.6 m from it, another chair 0.6 m further */
    const float p[4][3] = {{1.0f, 1.0f, 0.3f}, {1.75f, 1.0f, 0.3f}, {1.0f, 2.4f, 0.3f}, {1.0f, 3.5f, 0.3f}};
    sp_query_result r;
    fake_result(&r, p, 4, 0.35f);
    r.instances[0].score = 5;
    r.instances[1].score = 4;
    r.instances[2].score = 1;
    r.instances[3].score = 2;
    CHECK(sp_eval_merge_fragments(&r, 0.15f, &err) == 3);
    CHECK_NEAR(r.instances[0].position[0], 0.5f * (0.65f + 2.10f), 1e-5);
    CHECK_NEAR(r.instances[0].score, 9, 1e-6);
    CHECK(r.instances[0].n_points == 20);
    CHECK_NEAR(r.position[0], r.instances[0].position[0], 1e-6);
    CHECK_NEAR(r.instances[1].position[1], 3.5f, 1e-6); /* re-sorted by score */
    CHECK_NEAR(r.instances[2].position[1], 2.4f, 1e-6);
    sp_query_result_free(&r);
    /* off, and a single instance */
    fake_result(&r, p, 4, 0.35f);
    CHECK(sp_eval_merge_fragments(&r, -1, &err) == 4);
    sp_query_result_free(&r);
    fake_result(&r, p, 1, 0.35f);
    CHECK(sp_eval_merge_fragments(&r, 0.15f, &err) == 1);
    sp_query_result_free(&r);
}

int main(void)
{
    RUN(test_moved_refrigerator_in_the_house);
    RUN(test_small_world_truth);
    RUN(test_merge_fragments);
    return TEST_EXIT();
}
