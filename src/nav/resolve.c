/* Phrases to footprints: the query engine's instances (their robust extents as footprints), and
 * regions of a home ("kitchen") through the objects kept there when the engine does not find the
 * region word itself (label-feature scenes know objects, not rooms). */
#include <ctype.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "nav_scene.h"

/* "The Refrigerator " -> "refrigerator". */
static void normalize(const char *in, char *out, size_t cap)
{
    while (isspace((unsigned char)*in)) in++;
    static const char *const articles[] = {"the ", "a ", "an "};
    for (int k = 0; k < 3; k++)
        if (!strncasecmp(in, articles[k], strlen(articles[k]))) in += strlen(articles[k]);
    size_t j = 0;
    for (; *in && j + 1 < cap; in++) out[j++] = (char)tolower((unsigned char)*in);
    while (j > 0 && isspace((unsigned char)out[j - 1])) j--;
    out[j] = 0;
}

/* One engine query with the engine's defaults but no heatmap (per-call options: the engine may
 * be shared with the caller). */
static int query(sp_nav *nav, const char *text, sp_query_result *res, sp_error *err)
{
    sp_query_opts qo = *sp_query_engine_defaults(nav->engine);
    qo.heatmap = 0;
    return sp_query_engine_query(nav->engine, text, &qo, res, err);
}

static void add_instances(sp_nav_target *t, const char *label, const sp_query_result *res, float min_conf)
{
    for (int k = 0; k < res->n_instances && t->n < SP_NAV_MAX_BOXES; k++) {
        const sp_query_instance *q = &res->instances[k];
        if (q->confidence < min_conf || !isfinite(q->position[0])) continue;
        sp_nav_instance *in = &t->inst[t->n++];
        snprintf(in->label, sizeof in->label, "%s", label);
        memcpy(in->position, q->position, sizeof in->position);
        for (int a = 0; a < 2; a++) in->box.min[a] = q->extent_min[a], in->box.max[a] = q->extent_max[a];
        in->z_min = q->extent_min[2], in->z_max = q->extent_max[2];
        in->confidence = q->confidence;
        in->score = q->score;
    }
}

int sp_nav_resolve(sp_nav *nav, const char *phrase, sp_nav_target *t, sp_error *err)
{
    memset(t, 0, sizeof *t);
    if (!phrase) return sp_error_set(err, SP_E_ARG, "nav: no target phrase");
    normalize(phrase, t->text, sizeof t->text);
    if (!t->text[0]) return sp_error_set(err, SP_E_ARG, "nav: the target phrase '%s' is empty", phrase);
    if (!nav->engine)
        return sp_error_set(err, SP_E_UNSUPPORTED, "nav: this model has no semantic field, so '%s' "
                            "cannot be looked up (run semsplat lift or distill; point and pose goals "
                            "work)", t->text);
    sp_query_result res;
    int rc = query(nav, t->text, &res, err);
    if (rc) return rc;
    t->confidence = res.confidence;
    if (res.valid) add_instances(t, t->text, &res, nav->opts.min_confidence);
    sp_query_result_free(&res);
    snprintf(t->source, sizeof t->source, "query");
    if (t->n > 0) {
        t->found = 1;
        return SP_OK;
    }
    int r = nav_region_index(t->text);
    if (r < 0) return SP_OK;
    const char *const *objs;
    int n = nav_region_objects(r, &objs), used = 0;
    size_t len = (size_t)snprintf(t->source, sizeof t->source, "region: %s = ", nav_region_name(r));
    for (int k = 0; k < n; k++) {
        if ((rc = query(nav, objs[k], &res, err))) return rc;
        int before = t->n;
        if (res.valid) add_instances(t, objs[k], &res, nav->opts.min_confidence);
        if (t->n > before) {
            t->confidence = fmaxf(t->confidence, res.confidence);
            if (len < sizeof t->source)
                len += (size_t)snprintf(t->source + len, sizeof t->source - len, "%s%s", used++ ? ", " : "", objs[k]);
        }
        sp_query_result_free(&res);
    }
    if (t->n > 0) {
        t->found = 1;
        snprintf(t->text, sizeof t->text, "%s", nav_region_name(r)); /* the region the phrase names */
        if (len < sizeof t->source) snprintf(t->source + len, sizeof t->source - len, " found");
    } else {
        snprintf(t->source, sizeof t->source, "region: %s (none of its objects found)", nav_region_name(r));
    }
    return SP_OK;
}
