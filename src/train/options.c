/* Ranges of the training options: a value outside is an error naming the option, before any
 * work (a step count of 2^31 would run for years, a NaN learning rate diverges at step 1, a
 * negative interval never fires). */
#include <limits.h>
#include <stddef.h>

#include "train/train_internal.h"

#define SP_TRAIN_MAX_STEPS 10000000 /* 330x the 30k of 3DGS; more is a typo, not a plan */

typedef struct {
    const char *name;
    size_t offset;
    long lo, hi;
} int_range;

typedef struct {
    const char *name;
    size_t offset;
    double lo, hi;
    int open_lo; /* lo itself is not allowed */
} float_range;

#define OFF(f) offsetof(sp_train_options, f)

static const int_range ints[] = {
    {"steps", OFF(steps), 1, SP_TRAIN_MAX_STEPS},
    {"sh_degree", OFF(sh_degree), 0, 3},
    {"sh_degree_interval", OFF(sh_degree_interval), 1, INT_MAX},
    {"refine_start", OFF(refine_start), 0, INT_MAX},
    {"refine_stop", OFF(refine_stop), 0, INT_MAX},
    {"refine_every", OFF(refine_every), 1, INT_MAX},
    {"reset_every", OFF(reset_every), 1, INT_MAX},
    {"eval_every", OFF(eval_every), 0, INT_MAX},
};

static const float_range floats[] = {
    {"ssim_lambda", OFF(ssim_lambda), 0, 1, 0},
    {"lr_means", OFF(lr_means), 0, 1e3, 0},
    {"lr_means_final_factor", OFF(lr_means_final_factor), 0, 1e3, 1},
    {"lr_scales", OFF(lr_scales), 0, 1e3, 0},
    {"lr_quats", OFF(lr_quats), 0, 1e3, 0},
    {"lr_opacities", OFF(lr_opacities), 0, 1e3, 0},
    {"lr_sh0", OFF(lr_sh0), 0, 1e3, 0},
    {"lr_shN", OFF(lr_shN), 0, 1e3, 0},
    {"lr_features", OFF(lr_features), 0, 1e3, 0},
    {"adam_beta1", OFF(adam_beta1), 0, 0.999999, 0},
    {"adam_beta2", OFF(adam_beta2), 0, 0.999999999, 0},
    {"adam_eps", OFF(adam_eps), 0, 1, 1},
    {"grow_grad2d", OFF(grow_grad2d), 0, 1e3, 0}, /* 0: auto (sp_train_grow_grad2d) */
    {"grow_scale3d", OFF(grow_scale3d), 0, 1e3, 1},
    {"prune_opacity", OFF(prune_opacity), 0, 1, 0},
    {"prune_scale3d", OFF(prune_scale3d), 0, 1e6, 1},
    {"scene_scale", OFF(scene_scale), 0, 1e9, 0},
    {"feature_lambda", OFF(feature_lambda), 0, 1e6, 0},
    {"depth_lambda", OFF(depth_lambda), 0, 1e6, 0},
};

int tr_check_option_ranges(const sp_train_options *o, sp_error *err)
{
    const char *base = (const char *)o;
    for (size_t i = 0; i < sizeof ints / sizeof ints[0]; i++) {
        int v = *(const int *)(base + ints[i].offset);
        if (v < ints[i].lo || v > ints[i].hi)
            return sp_error_set(err, SP_E_ARG, "train: %s %d is outside %ld..%ld", ints[i].name, v, ints[i].lo,
                                ints[i].hi);
    }
    for (size_t i = 0; i < sizeof floats / sizeof floats[0]; i++) {
        double v = *(const float *)(base + floats[i].offset);
        const float_range *r = &floats[i];
        if (!(v >= r->lo && v <= r->hi) || (r->open_lo && v == r->lo))
            return sp_error_set(err, SP_E_ARG, "train: %s %g is outside %s%g..%g]", r->name, v, r->open_lo ? "(" : "[",
                                r->lo, r->hi);
    }
    for (int k = 0; k < 3; k++)
        if (!(o->background[k] >= 0 && o->background[k] <= 1))
            return sp_error_set(err, SP_E_ARG, "train: background %g is outside [0, 1]", o->background[k]);
    /* 0: no periodic checkpoints (the final one is still written when checkpoint_dir is set) */
    if (o->checkpoint_every < 0 || o->checkpoint_every > 10000000)
        return sp_error_set(err, SP_E_ARG, "train: checkpoint_every %d outside 0 (none)..10000000", o->checkpoint_every);
    if (o->max_gaussians > (size_t)1 << 30)
        return sp_error_set(err, SP_E_ARG, "train: max_gaussians %zu is beyond 2^30", o->max_gaussians);
    return SP_OK;
}
