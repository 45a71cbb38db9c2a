/* The written analysis, made from the run's numbers only: what was measured (feature source, text
 * encoder, capture plan, poses) and what that means, then strengths, limits and the sources of
 * error the figures point at. Every sentence that states a figure computes it here. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "eval/eval_internal.h"

typedef struct out {
    char *p;
    size_t cap, n;
} out;

static void put(out *o, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void put(out *o, const char *fmt, ...)
{
    if (o->n + 1 >= o->cap) return;
    va_list ap;
    va_start(ap, fmt);
    int k = vsnprintf(o->p + o->n, o->cap - o->n, fmt, ap);
    va_end(ap);
    if (k > 0) o->n = o->n + (size_t)k < o->cap ? o->n + (size_t)k : o->cap - 1;
}

static void what_was_measured(out *o, const sp_eval_run *r)
{
    const sp_query_source *s = &r->loc.source;
    put(o, "**What this measures.** Feature source: `%s`; text encoder: `%s` for the localization "
           "queries, `%s` for the vocabulary comparison. ", s->features, s->encoder, r->vocab_encoder);
    if (s->ground_truth)
        put(o, "The features come from the world's own label images (a perfect 2D segmentation), so "
               "5.1 measures how well the splat puts labelled pixels back in 3D, not recognition. ");
    else if (!strcmp(s->features, "clip"))
        put(o, "The features are CLIP's, computed from the rendered pixels: recognition is measured, "
               "through the simulation gap (CLIP learned from photographs, these are renders). ");
    if (!strcmp(r->vocab_encoder, "lexical"))
        put(o, "The lexical encoder matches words against the class names the world file gives "
               "(WordNet synonyms, hypernyms, definitions): it finds only what the world names, and "
               "its open-vocabulary answers are matching against known names, not seeing. ");
    else if (!strcmp(r->vocab_encoder, "exact"))
        put(o, "The exact encoder answers a query only when it spells a class name. ");
    put(o, "Capture plan: `%s`", r->plan);
    if (!strcmp(r->plan, "walk+objects"))
        put(o, " (30%% of the views were aimed at the world's objects: the views lean on the ground truth)");
    else if (!strcmp(r->plan, "walk") || !strcmp(r->plan, "drive"))
        put(o, " (no view was aimed at a ground-truth object)");
    put(o, "; poses: %s.", r->poses);
    if (isfinite(r->train_psnr))
        put(o, " The splat has %ld Gaussians and renders held-out views at %.2f dB PSNR.", r->n_gaussians,
            r->train_psnr);
    put(o, "\n\n");
}

static int best_method(const sp_eval_run *r)
{
    const sp_eval_summary *a = &r->loc.summary[0], *b = &r->loc.summary[1];
    return b->matched > a->matched ? 1 : 0;
}

static void strengths_and_limits(out *o, const sp_eval_run *r)
{
    static const char *name[2] = {"3D-native", "multi-view"};
    int m = best_method(r);
    const sp_eval_summary *s = &r->loc.summary[m];
    put(o, "**Strengths.** With the %s method %d of %d objects were found and matched (recall %.2f); "
           "their mean error is %.2f m (median %.2f m), %d of %d classes were found.", name[m],
        s->matched, s->objects, s->recall, s->mean_error_m, s->median_error_m, s->classes_found, s->classes);
    int open_out = 0, open_found = 0, closed_found = 0, with_targets = 0;
    for (size_t k = 0; k < r->n_vocab; k++) {
        const sp_eval_vocab_row *q = &r->vocab[k];
        if (q->in_coco || !q->n_targets) continue;
        with_targets++;
        open_out += 1;
        open_found += q->open_found;
        closed_found += q->closed_found;
    }
    if (with_targets)
        put(o, " Of the %d queries outside COCO that this world can answer, the semantic splat found %d, the "
               "COCO-80 baseline %d.", open_out, open_found, closed_found);
    put(o, "\n\n**Limits.** Precision is %.2f (%d of %d returned instances lie on an object of their class); "
           "counting every miss at the largest error a match could have had, the mean error is %.2f m.",
        s->precision, s->true_instances, s->instances, s->mean_error_with_misses_m);
    int shown = 0;
    for (size_t i = 0; i < r->loc.n_objects && shown < 12; i++) {
        const sp_eval_object *ob = &r->loc.objects[i];
        if (ob->instance[0] >= 0 || ob->instance[1] >= 0) continue;
        put(o, "%s%s", shown ? ", " : " Missed by both methods: ", ob->name);
        shown++;
    }
    if (shown) put(o, ".");
    for (size_t k = 0, first = 1; k < r->n_vocab; k++) {
        const sp_eval_vocab_row *q = &r->vocab[k];
        if (!q->n_targets || q->open_found) continue;
        put(o, "%s\"%s\"", first ? " Vocabulary queries the splat did not answer right: " : ", ", q->spec.text);
        first = 0;
    }
    put(o, "\n\n");
}

static void sources_of_error(out *o, const sp_eval_run *r)
{
    put(o, "**Sources of error.** ");
    if (isfinite(r->train_psnr))
        put(o, "*Reconstruction*: %.1f dB held-out PSNR%s. ", r->train_psnr,
            r->train_psnr < 25 ? " is low: blurred or floating Gaussians spread labels beyond the objects"
                               : "; reconstruction is not the main limit");
    /* the largest errors among matched objects, with the object's size */
    const sp_eval_report *rep = &r->loc;
    int m = best_method(r), worst[3] = {-1, -1, -1};
    for (size_t i = 0; i < rep->n_objects; i++) {
        if (rep->objects[i].instance[m] < 0) continue;
        for (int w = 0; w < 3; w++)
            if (worst[w] < 0 || rep->objects[i].error_m[m] > rep->objects[worst[w]].error_m[m]) {
                for (int v = 2; v > w; v--) worst[v] = worst[v - 1];
                worst[w] = (int)i;
                break;
            }
    }
    for (int w = 0; w < 3 && worst[w] >= 0; w++) {
        const sp_eval_object *ob = &rep->objects[worst[w]];
        const sp_gt_object *g = NULL;
        for (size_t i = 0; i < r->gt.n && !g; i++)
            if (!strcmp(r->gt.objects[i].name, ob->name)) g = &r->gt.objects[i];
        float size = g ? fmaxf(g->aabb_max[0] - g->aabb_min[0], g->aabb_max[1] - g->aabb_min[1]) : NAN;
        put(o, "%s%s %.2f m (footprint %.1f m)", w ? ", " : "*Largest matched errors*: ", ob->name,
            ob->error_m[m], size);
    }
    if (worst[0] >= 0)
        put(o, ": the estimate is the middle of what the views saw of an object, the truth its box "
               "centre, so objects seen from one side or partly hidden err by up to half their size. ");
    put(o, "*Viewpoint selection*: the `%s` plan decides which sides of an object any view saw; ", r->plan);
    put(o, "objects off the walked or driven floor are seen from afar and small. ");
    if (isfinite(r->sfm_ate_rms_m))
        put(o, "*Poses*: COLMAP registered %d of %d images; after alignment its cameras are %.3f m (RMS) "
               "from the true ones, an error every position inherits. ", r->sfm_registered, r->sfm_images,
            r->sfm_ate_rms_m);
    else put(o, "*Poses*: exact (rendered), so no pose error enters these figures. ");
    put(o, "*Simulation gap*: the world is rendered, not photographed: textures are procedural and "
           "flat-coloured surfaces are common%s.\n\n",
        r->loc.source.ground_truth ? "; with label features this does not reach the labels, only the "
                                     "geometry" : ", which features computed from pixels feel directly");
    if (r->traj_measured && r->n_traj) {
        const sp_eval_trajectory *b = &r->traj[0];
        put(o, "**Trajectories.** %d to \"%s\"; the best is %.1f m long with %.2f m clearance at its "
               "narrowest, localizability %.2f, and its previews grade %d of 5 (%.0f%% of each view "
               "covered, sharpness %.2f).\n\n", r->n_traj, r->traj_target, b->length_m, b->clearance_min_m,
            b->localizability, b->visual_grade, 100.0 * b->coverage, b->sharpness);
    } else put(o, "**Trajectories.** Not measured: %s.\n\n", r->traj_note);
    if (r->nav_measured) {
        const sp_nav_success *n = &r->nav;
        put(o, "**Navigation commands.** Of %d commands, %d were read as go-to, %d located a valid goal, "
               "%d were driven to it and %d had useful views along the way (%s).\n", n->n, n->count[0],
            n->count[1], n->count[2], n->count[3], n->robot);
    } else put(o, "**Not measured here.** 5.3: %s.\n", r->nav_note);
}

void ev_analysis(sp_eval_run *r)
{
    out o = {r->analysis, sizeof r->analysis, 0};
    r->analysis[0] = 0;
    what_was_measured(&o, r);
    strengths_and_limits(&o, r);
    sources_of_error(&o, r);
}
