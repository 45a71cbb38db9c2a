/* The class names a label-feature scene knows (semantic.json "classes", or the capture's
 * labels.json), vocabularies made from them, and the lexical encoder as a text embedding. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lexical.h"
#include "sem_internal.h"
#include "semsplat/clip.h"
#include "semsplat/io.h"

/* Appends name to list unless it is "background", empty or already there. */
static int add_class(char (*list)[128], int *n, const char *name, const char *where, sp_error *err)
{
    if (!name[0] || !strcmp(name, "background")) return 0;
    for (int k = 0; k < *n; k++)
        if (!strcmp(list[k], name)) return 0;
    if (*n == SP_LEX_MAX_CLASSES)
        return sp_error_set(err, SP_E_UNSUPPORTED, "%s: more than %d classes", where, SP_LEX_MAX_CLASSES);
    snprintf(list[(*n)++], 128, "%s", name);
    return 0;
}

/* The classes of a capture's labels.json (synth's format: {"labels": {"1": {"class": ...}}}). */
static int classes_of_labels(const char *labels_json, char (**out)[128], int *n, sp_error *err)
{
    *out = NULL, *n = 0;
    cJSON *js = NULL;
    int rc = sp_json_read_file(labels_json, &js, err);
    if (rc) return rc;
    const cJSON *labs = cJSON_GetObjectItemCaseSensitive(js, "labels"), *it;
    char (*list)[128] = calloc(SP_LEX_MAX_CLASSES, sizeof *list);
    if (!list) rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", labels_json);
    else if (!labs) rc = sp_error_set(err, SP_E_FORMAT, "%s: missing \"labels\"", labels_json);
    cJSON_ArrayForEach(it, labs) {
        if (rc) break;
        const cJSON *c = cJSON_GetObjectItemCaseSensitive(it, "class");
        if (!cJSON_IsString(c) || !c->valuestring[0])
            rc = sp_error_set(err, SP_E_FORMAT, "%s: label '%s' has no \"class\"", labels_json,
                              it->string ? it->string : "?");
        else rc = add_class(list, n, c->valuestring, labels_json, err);
    }
    cJSON_Delete(js);
    if (rc) free(list), *n = 0;
    else *out = list;
    return rc;
}

static int vocab_of(sp_lex_vocab **out, const sp_lexicon *lx, char (*list)[128], int n,
                    const char *regions_path, sp_error *err)
{
    const char *names[SP_LEX_MAX_CLASSES];
    for (int i = 0; i < n; i++) names[i] = list[i];
    return sp_lex_vocab_create(out, lx, names, n, regions_path, err);
}

int sp_lex_vocab_from_labels(sp_lex_vocab **out, const sp_lexicon *lx, const char *labels_json,
                             const char *regions_path, sp_error *err)
{
    *out = NULL;
    char (*list)[128] = NULL;
    int n = 0, rc = classes_of_labels(labels_json, &list, &n, err);
    if (!rc) rc = vocab_of(out, lx, list, n, regions_path, err);
    free(list);
    return rc;
}

/* labels.json of the capture a model folder was lifted from: beside its COLMAP folder or up to
 * two levels above it (capture/sparse/0). */
static int find_labels(const char *colmap, char *out, size_t cap)
{
    char dir[2048];
    snprintf(dir, sizeof dir, "%s", colmap);
    for (int up = 0; up < 3; up++) {
        snprintf(out, cap, "%s/labels.json", dir);
        if (sp_file_exists(out)) return 0;
        char *s = strrchr(dir, '/');
        if (!s || s == dir) break;
        *s = 0;
    }
    return -1;
}

int sem_model_classes(const char *model_dir, const cJSON *js, char (**names)[128], int *n, sp_error *err)
{
    *names = NULL, *n = 0;
    const cJSON *classes = cJSON_GetObjectItemCaseSensitive(js, "classes"), *it;
    if (cJSON_IsArray(classes)) {
        char where[2100];
        snprintf(where, sizeof where, "%s: \"classes\"", model_dir);
        char (*list)[128] = calloc(SP_LEX_MAX_CLASSES, sizeof *list);
        if (!list) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", where);
        int rc = 0;
        cJSON_ArrayForEach(it, classes) {
            if (!cJSON_IsString(it)) rc = sp_error_set(err, SP_E_FORMAT, "%s: a class name is not a string", where);
            else rc = add_class(list, n, it->valuestring, where, err);
            if (rc) break;
        }
        if (rc) free(list), *n = 0;
        else *names = list;
        return rc;
    }
    const cJSON *colmap = cJSON_GetObjectItemCaseSensitive(js, "colmap");
    char dir[2048], labels[2100];
    if (!cJSON_IsString(colmap) || !colmap->valuestring[0]) return 0;
    if (colmap->valuestring[0] == '/') snprintf(dir, sizeof dir, "%s", colmap->valuestring);
    else sp_path_join(dir, sizeof dir, model_dir, colmap->valuestring);
    if (find_labels(dir, labels, sizeof labels)) return 0;
    return classes_of_labels(labels, names, n, err);
}

int sp_lex_vocab_for_model(sp_lex_vocab **out, const sp_lexicon *lx, const char *model_dir,
                           const char *regions_path, sp_error *err)
{
    *out = NULL;
    char path[2048];
    sp_path_join(path, sizeof path, model_dir, "semantic.json");
    cJSON *js = NULL;
    int rc = sp_json_read_file(path, &js, err);
    if (rc) return rc;
    const cJSON *src = cJSON_GetObjectItem(js, "source"), *le = cJSON_GetObjectItem(js, "label_embedding");
    char (*list)[128] = NULL;
    int n = 0;
    if (!cJSON_IsString(src) || strcmp(src->valuestring, "labels") || !cJSON_IsString(le) ||
        strcmp(le->valuestring, "hash"))
        rc = sp_error_set(err, SP_E_UNSUPPORTED,
                          "%s: lexical answers need a label-feature model (source \"labels\", label_embedding "
                          "\"hash\"); this one has source \"%s\": query it with its CLIP text tower",
                          path, cJSON_IsString(src) ? src->valuestring : "?");
    else if (!(rc = sem_model_classes(model_dir, js, &list, &n, err)) && n == 0)
        rc = sp_error_set(err, SP_E_NOTFOUND, "%s: no \"classes\", and no labels.json beside the capture it "
                          "names (\"colmap\")", path);
    cJSON_Delete(js);
    if (!rc) rc = vocab_of(out, lx, list, n, regions_path, err);
    free(list);
    return rc;
}

int sp_lex_embed(const sp_lex_vocab *v, const char *text, int dim, float *out, float *confidence,
                 sp_error *err)
{
    if (!v || !text || !out || dim < 1) return sp_error_set(err, SP_E_ARG, "lexical embed: bad argument");
    sp_lex_result *res = malloc(sizeof *res);
    float *one = malloc(sizeof(float) * (size_t)dim);
    if (!res || !one) {
        free(res), free(one);
        return sp_error_set(err, SP_E_NOMEM, "lexical embed: out of memory");
    }
    int rc = sp_lex_match(v, text, res, err);
    memset(out, 0, sizeof(float) * (size_t)dim);
    double n2 = 0;
    int named = res->target.n_matches > 0 && res->target.matches[0].kind == SP_LEX_EXACT;
    for (int i = 0; !rc && i < res->target.n_matches; i++) {
        const sp_lex_class_match *m = &res->target.matches[i];
        if (m->score < SP_LEX_THRESHOLD) break;
        if (named && m->kind != SP_LEX_EXACT) continue; /* a class's own name means that class */
        sp_label_embedding(sp_lex_vocab_class(v, m->class_index), dim, one);
        for (int j = 0; j < dim; j++) out[j] += m->score * one[j];
    }
    for (int j = 0; j < dim; j++) n2 += (double)out[j] * out[j];
    if (n2 > 0)
        for (int j = 0; j < dim; j++) out[j] = (float)(out[j] / sqrt(n2));
    if (confidence) *confidence = rc ? 0 : res->confidence;
    free(res);
    free(one);
    return rc;
}
