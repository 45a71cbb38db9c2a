/* How `semsplat query` prints an answer as text: what produced it, where it is, the instances
 * with their class and relation cost, the region, and (--explain) what the encoder understood. */
#include <math.h>
#include <stdio.h>

#include "cli_query.h"

void cli_query_provenance(const sp_query_source *s, const sp_frame *f)
{
    const char *note = sp_query_source_note(s);
    printf("source: text encoder %s, features %s%s%s\n", s->encoder, s->features, note[0] ? "; " : "", note);
    printf("frame:  %s (%s; units %s, up %s)\n", sp_frame_name(f), f->source, f->units, f->up);
}

static void print_box(const char *what, const sp_query_region *r)
{
    printf("    %s '%s'  centre (%.3f, %.3f, %.3f)  extent (%.2f, %.2f, %.2f) .. (%.2f, %.2f, %.2f)  %d instance%s\n",
           what, r->name, (double)r->centre[0], (double)r->centre[1], (double)r->centre[2],
           (double)r->extent_min[0], (double)r->extent_min[1], (double)r->extent_min[2],
           (double)r->extent_max[0], (double)r->extent_max[1], (double)r->extent_max[2], r->n_instances,
           r->n_instances == 1 ? "" : "s");
}

void cli_query_print(const sp_query_result *res, const char *heatmap, int explain)
{
    if (res->valid)
        printf("%-24s found  (%.3f, %.3f, %.3f)  confidence %.3f  %d instance%s  %.1f ms\n", res->text,
               (double)res->position[0], (double)res->position[1], (double)res->position[2],
               (double)res->confidence, res->n_instances, res->n_instances == 1 ? "" : "s", res->ms_total);
    else
        printf("%-24s not found  confidence %.3f (threshold %.2f)  %.1f ms\n", res->text, (double)res->confidence,
               (double)res->threshold, res->ms_total);
    for (int k = 0; k < res->n_instances && res->valid; k++) {
        const sp_query_instance *I = &res->instances[k];
        printf("    instance %d  (%.3f, %.3f, %.3f)  score %.3g  confidence %.3f", k, (double)I->position[0],
               (double)I->position[1], (double)I->position[2], (double)I->score, (double)I->confidence);
        if (I->label[0]) printf("  %s", I->label);
        if (isfinite(I->relation_m)) printf("  %.2f m %s the anchor", (double)I->relation_m, res->relation);
        printf("\n");
    }
    if (res->region.valid) print_box("region", &res->region);
    if (res->anchor.valid) print_box("anchor", &res->anchor);
    if (heatmap) printf("    heatmap %s (view %s)\n", heatmap, res->view_name);
    if (explain && res->explanation) printf("%s", res->explanation);
    else if (explain) printf("    (the %s encoder gives no explanation)\n", res->source.encoder);
}
