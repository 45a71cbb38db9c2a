/* The evaluation's second small world (tests/eval/small_world.h) loads through synth with the
 * classes people ask for, and moving its refrigerator in the text moves the ground truth by the
 * same offset (what the evaluation tests rely on). */
#include "eval/small_world.h"
#include "semsplat/synth.h"
#include "test.h"

static int load(const char *dir, double fx, double fy, sp_world *w, sp_error *err)
{
    char path[1300];
    snprintf(path, sizeof path, "%s/small_flat.world", dir);
    if (small_world_write(path, fx, fy)) return -1;
    sp_synth_load_opts o = {.no_env = 1};
    return sp_synth_load_world(path, &o, w, err);
}

static const sp_synth_object *find(const sp_world *w, const char *cls)
{
    for (size_t i = 0; i < w->n_objects; i++)
        if (!strcmp(w->objects[i].class_name, cls)) return &w->objects[i];
    return NULL;
}

static void test_classes_and_moved_fridge(void)
{
    sp_world a, b;
    sp_error err = {0};
    CHECK_OK(load(test_tmpdir("small_world_a"), SMALL_WORLD_FRIDGE_X, SMALL_WORLD_FRIDGE_Y, &a, &err), &err);
    CHECK_OK(load(test_tmpdir("small_world_b"), 3.4, 0.5, &b, &err), &err);
    if (err.code) return;
    const char *want[] = {"refrigerator", "kitchen counter", "dining table", "chair", "sofa",
                          "tv stand", "television", "bookshelf", "floor lamp", "potted plant"};
    for (size_t i = 0; i < sizeof want / sizeof *want; i++) CHECK_MSG(find(&a, want[i]), "no %s", want[i]);
    size_t objects = 0, chairs = 0;
    for (size_t i = 0; i < a.n_objects; i++) {
        objects += !a.objects[i].is_structure;
        chairs += !strcmp(a.objects[i].class_name, "chair");
    }
    CHECK(objects == 11 && chairs == 2);
    CHECK(find(&a, "wall") == NULL || find(&a, "wall")->is_structure);
    const sp_synth_object *fa = find(&a, "refrigerator"), *fb = find(&b, "refrigerator");
    if (fa && fb) {
        CHECK_NEAR(0.5 * (fa->aabb_min[0] + fa->aabb_max[0]), SMALL_WORLD_FRIDGE_X, 1e-4);
        CHECK_NEAR(0.5 * (fa->aabb_min[1] + fa->aabb_max[1]), SMALL_WORLD_FRIDGE_Y, 1e-4);
        CHECK_NEAR(fb->aabb_min[0] - fa->aabb_min[0], 3.4 - SMALL_WORLD_FRIDGE_X, 1e-4);
        CHECK_NEAR(fb->aabb_max[1] - fa->aabb_max[1], 0.5 - SMALL_WORLD_FRIDGE_Y, 1e-4);
        CHECK_NEAR(fa->aabb_max[2], 1.8, 1e-4);
    }
    sp_world_free(&a);
    sp_world_free(&b);
}

int main(void)
{
    RUN(test_classes_and_moved_fridge);
    return TEST_EXIT();
}
