/* What leaves the query engine: results as JSON (with the source and frame that say what the
 * numbers mean), the caveat for label features, and the ABI facts bindings check. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sem_internal.h"
#include "semsplat/semantic.h"

const char *sp_query_source_note(const sp_query_source *s)
{
    if (s && !strcmp(s->encoder, SP_ENCODER_LEXICAL))
        return s->ground_truth
                   ? "features from ground-truth label images and text matched to the scene's class names "
                     "with WordNet (lexical encoder): this measures localization given a perfect 2D "
                     "segmentation and matching against known class names, not recognition or language "
                     "understanding of things the world file does not name"
                   : "text matched to the scene's class names with WordNet (lexical encoder): it finds only "
                     "what the scene's labels name";
    if (!s || !s->ground_truth) return "";
    if (!strcmp(s->encoder, "exact"))
        return "features from ground-truth label images and text matched to exact class names: "
               "this measures localization given a perfect 2D segmentation, not language "
               "understanding";
    return "features from ground-truth label images: this measures localization given a perfect "
           "2D segmentation, not language understanding";
}

static cJSON *vec3(const float *v)
{
    cJSON *a = cJSON_CreateArray();
    for (int k = 0; k < 3; k++) cJSON_AddItemToArray(a, cJSON_CreateNumber(v[k]));
    return a;
}

static void add_source_and_frame(cJSON *o, const sp_query_result *res)
{
    cJSON *s = cJSON_AddObjectToObject(o, "source");
    cJSON_AddStringToObject(s, "encoder", res->source.encoder);
    cJSON_AddStringToObject(s, "features", res->source.features);
    cJSON_AddBoolToObject(s, "ground_truth", res->source.ground_truth);
    const char *note = sp_query_source_note(&res->source);
    if (note[0]) cJSON_AddStringToObject(s, "note", note);
    else cJSON_AddNullToObject(s, "note");
    cJSON *f = cJSON_AddObjectToObject(o, "frame");
    cJSON_AddStringToObject(f, "name", res->frame.name);
    cJSON_AddStringToObject(f, "source", res->frame.source);
    cJSON_AddStringToObject(f, "units", res->frame.units);
    cJSON_AddStringToObject(f, "up", res->frame.up);
}

cJSON *sem_match_json(const sp_query_match *m, float threshold)
{
    cJSON *it = cJSON_CreateObject();
    cJSON_AddStringToObject(it, "class", m->label);
    cJSON_AddStringToObject(it, "role", m->role);
    cJSON_AddNumberToObject(it, "score", m->score);
    cJSON_AddBoolToObject(it, "match", m->score >= threshold);
    cJSON_AddStringToObject(it, "kind", m->kind);
    cJSON_AddStringToObject(it, "query_sense", m->query_sense);
    cJSON_AddStringToObject(it, "class_sense", m->class_sense);
    cJSON_AddStringToObject(it, "path", m->path);
    cJSON_AddStringToObject(it, "gloss_words", m->gloss_words);
    cJSON_AddStringToObject(it, "definition", m->definition);
    return it;
}

static cJSON *str_or_null(const char *s) { return s && s[0] ? cJSON_CreateString(s) : cJSON_CreateNull(); }

static cJSON *region_json(const sp_query_region *r)
{
    if (!r->valid) return cJSON_CreateNull();
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "name", r->name);
    cJSON_AddItemToObject(o, "extent_min", vec3(r->extent_min));
    cJSON_AddItemToObject(o, "extent_max", vec3(r->extent_max));
    cJSON_AddItemToObject(o, "centre", vec3(r->centre));
    cJSON_AddNumberToObject(o, "instances", r->n_instances);
    return o;
}

/* What the encoder understood: matches, relation, region, anchor, ignored words, explanation. */
static void add_understanding(cJSON *o, const sp_query_result *res)
{
    cJSON *arr = cJSON_AddArrayToObject(o, "matches");
    for (int i = 0; i < res->n_matches; i++) cJSON_AddItemToArray(arr, sem_match_json(&res->matches[i], res->threshold));
    cJSON_AddItemToObject(o, "relation", str_or_null(res->relation));
    cJSON_AddItemToObject(o, "region", region_json(&res->region));
    cJSON_AddItemToObject(o, "anchor", region_json(&res->anchor));
    cJSON *ig = cJSON_AddArrayToObject(o, "ignored");
    for (int i = 0; i < res->n_ignored; i++) cJSON_AddItemToArray(ig, cJSON_CreateString(res->ignored[i]));
    cJSON_AddItemToObject(o, "explanation", str_or_null(res->explanation));
}

char *sp_query_result_json(const sp_query_result *res, const char *heatmap_path)
{
    cJSON *o = cJSON_CreateObject();
    if (!o) return NULL;
    cJSON_AddStringToObject(o, "text", res->text);
    cJSON_AddStringToObject(o, "encoder", res->source.encoder);
    cJSON_AddStringToObject(o, "method", res->method == SP_QUERY_MULTIVIEW ? "multiview" : "3d");
    cJSON_AddBoolToObject(o, "found", res->valid);
    if (res->valid) cJSON_AddItemToObject(o, "position", vec3(res->position));
    else cJSON_AddNullToObject(o, "position");
    cJSON_AddNumberToObject(o, "confidence", res->confidence);
    cJSON_AddNumberToObject(o, "threshold", res->threshold);
    cJSON_AddNumberToObject(o, "relevancy_max", res->relevancy_max);
    if (res->view_index >= 0) {
        cJSON *v = cJSON_AddObjectToObject(o, "view");
        cJSON_AddNumberToObject(v, "index", res->view_index);
        cJSON_AddStringToObject(v, "name", res->view_name);
    } else {
        cJSON_AddNullToObject(o, "view");
    }
    cJSON *arr = cJSON_AddArrayToObject(o, "instances");
    for (int i = 0; i < res->n_instances; i++) {
        const sp_query_instance *I = &res->instances[i];
        cJSON *it = cJSON_CreateObject();
        cJSON_AddItemToObject(it, "position", vec3(I->position));
        cJSON_AddItemToObject(it, "extent_min", vec3(I->extent_min));
        cJSON_AddItemToObject(it, "extent_max", vec3(I->extent_max));
        cJSON_AddNumberToObject(it, "score", I->score);
        cJSON_AddNumberToObject(it, "confidence", I->confidence);
        cJSON_AddNumberToObject(it, "points", I->n_points);
        cJSON_AddItemToObject(it, "class", str_or_null(I->label));
        if (isfinite(I->relation_m)) cJSON_AddNumberToObject(it, "relation_m", I->relation_m);
        else cJSON_AddNullToObject(it, "relation_m");
        cJSON_AddItemToArray(arr, it);
    }
    if (heatmap_path) cJSON_AddStringToObject(o, "heatmap", heatmap_path);
    else cJSON_AddNullToObject(o, "heatmap");
    add_source_and_frame(o, res);
    cJSON *t = cJSON_AddObjectToObject(o, "timings_ms");
    cJSON_AddNumberToObject(t, "embed", res->ms_embed);
    cJSON_AddNumberToObject(t, "relevancy", res->ms_relevancy);
    cJSON_AddNumberToObject(t, "localize", res->ms_localize);
    cJSON_AddNumberToObject(t, "heatmap", res->ms_heatmap);
    cJSON_AddNumberToObject(t, "total", res->ms_total);
    add_understanding(o, res);
    char *s = cJSON_Print(o);
    cJSON_Delete(o);
    return s;
}

int sp_semantic_abi_version(void) { return SP_SEMANTIC_ABI_VERSION; }

size_t sp_semantic_abi_sizeof(const char *name)
{
    static const struct {
        const char *name;
        size_t size;
    } sizes[] = {
        {"sp_query_opts", sizeof(sp_query_opts)},     {"sp_query_result", sizeof(sp_query_result)},
        {"sp_query_instance", sizeof(sp_query_instance)}, {"sp_query_source", sizeof(sp_query_source)},
        {"sp_query_frame", sizeof(sp_query_frame)},   {"sp_error", sizeof(sp_error)},
        {"sp_query_match", sizeof(sp_query_match)},   {"sp_query_region", sizeof(sp_query_region)},
        {"sp_encoder_opts", sizeof(sp_encoder_opts)},
        {"sp_camera", sizeof(sp_camera)},             {"sp_image", sizeof(sp_image)},
        {"sp_splat", sizeof(sp_splat)},
    };
    for (size_t i = 0; name && i < sizeof sizes / sizeof sizes[0]; i++)
        if (!strcmp(sizes[i].name, name)) return sizes[i].size;
    return 0;
}
