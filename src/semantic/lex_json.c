/* The lexical text encoder's results as JSON and as a human-readable explanation (--explain). */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <string.h>

#include "lexical.h"
#include "sem_internal.h"

static cJSON *phrase_json(const sp_lex_phrase *ph, const sp_lex_vocab *v, float min_score, const char *role)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "text", ph->text);
    cJSON_AddStringToObject(o, "head", ph->head);
    if (ph->is_region) cJSON_AddStringToObject(o, "region", ph->region);
    else cJSON_AddNullToObject(o, "region");
    cJSON *arr = cJSON_AddArrayToObject(o, "matches");
    for (int i = 0; i < ph->n_matches; i++) {
        const sp_lex_class_match *m = &ph->matches[i];
        if (m->score < min_score) continue;
        sp_query_match q;
        sem_lex_match_copy(&q, m, v, role);
        cJSON *it = sem_match_json(&q, SP_LEX_THRESHOLD);
        cJSON_AddNumberToObject(it, "class_index", m->class_index);
        cJSON_AddItemToArray(arr, it);
    }
    return o;
}

char *sp_lex_result_json(const sp_lex_result *res, const sp_lex_vocab *v, float min_score)
{
    cJSON *o = cJSON_CreateObject();
    if (!o) return NULL;
    cJSON_AddStringToObject(o, "text", res->text);
    cJSON_AddStringToObject(o, "encoder", "lexical");
    cJSON_AddBoolToObject(o, "found", res->found);
    cJSON_AddNumberToObject(o, "confidence", res->confidence);
    cJSON_AddNumberToObject(o, "threshold", SP_LEX_THRESHOLD);
    cJSON_AddItemToObject(o, "target", phrase_json(&res->target, v, min_score, "target"));
    if (res->relation[0]) {
        cJSON_AddStringToObject(o, "relation", res->relation);
        cJSON_AddItemToObject(o, "anchor", phrase_json(&res->anchor, v, min_score, "anchor"));
    } else {
        cJSON_AddNullToObject(o, "relation");
        cJSON_AddNullToObject(o, "anchor");
    }
    cJSON *ig = cJSON_AddArrayToObject(o, "ignored");
    for (int i = 0; i < res->n_ignored; i++) cJSON_AddItemToArray(ig, cJSON_CreateString(res->ignored[i]));
    char *s = cJSON_Print(o);
    cJSON_Delete(o);
    return s;
}

static size_t put(char *out, size_t cap, size_t o, const char *fmt, const char *a, const char *b)
{
    if (o + 1 >= cap) return o;
    int k = snprintf(out + o, cap - o, fmt, a, b);
    return k > 0 ? (o + (size_t)k < cap ? o + (size_t)k : cap - 1) : o;
}

static size_t explain_phrase(const sp_lex_phrase *ph, const sp_lex_vocab *v, const char *role,
                             char *out, size_t cap, size_t o)
{
    char line[1024];
    if (ph->is_region)
        snprintf(line, sizeof line, "%s '%s': the region '%s', the extent of its objects:\n", role,
                 ph->text, ph->region);
    else {
        /* the best class found through the activity table (lex_uses.c) was not matched by definitions */
        int activity = ph->n_matches && !strncmp(ph->matches[0].path, "activity ", 9);
        snprintf(line, sizeof line, "%s '%s'%s%s%s:\n", role, ph->text, ph->head[0] ? " (head noun '" : "",
                 ph->head, ph->head[0]  ? "')"
                           : activity ? " (no head noun: matched by the activity table and definitions)"
                                      : " (no head noun: matched by definitions)");
    }
    o = put(out, cap, o, "%s%s", line, "");
    int shown = 0;
    for (int i = 0; i < ph->n_matches && shown < 6; i++) {
        const sp_lex_class_match *m = &ph->matches[i];
        if (m->score <= 0) break;
        if (m->score < SP_LEX_THRESHOLD && shown >= 1) break;
        shown++;
        snprintf(line, sizeof line, "  %-18s %.2f %-8s %s", sp_lex_vocab_class(v, m->class_index),
                 (double)m->score, m->score >= SP_LEX_THRESHOLD ? "match" : "below", sp_lex_kind_name(m->kind));
        o = put(out, cap, o, "%s%s", line, "");
        if (m->query_sense[0] && m->class_sense[0] && strcmp(m->query_sense, m->class_sense)) {
            snprintf(line, sizeof line, "  ('%s' ~ '%s')", m->query_sense, m->class_sense);
            o = put(out, cap, o, "%s%s", line, "");
        }
        o = put(out, cap, o, "%s%s", "\n", "");
        if (m->path[0]) o = put(out, cap, o, "      path: %s\n%s", m->path, "");
        if (m->gloss_words[0]) o = put(out, cap, o, "      definitions: %s\n%s", m->gloss_words, "");
        if (m->definition[0]) o = put(out, cap, o, "      WordNet: %s\n%s", m->definition, "");
    }
    if (!shown) o = put(out, cap, o, "  no class of this scene is related%s%s\n", "", "");
    return o;
}

void sp_lex_explain(const sp_lex_result *res, const sp_lex_vocab *v, char *out, size_t cap)
{
    if (!cap) return;
    out[0] = 0;
    char line[512];
    snprintf(line, sizeof line, "lexical encoder (WordNet 3.0, threshold %.2f): '%s' %s, confidence %.2f\n",
             (double)SP_LEX_THRESHOLD, res->text, res->found ? "matches" : "matches no class", (double)res->confidence);
    size_t o = put(out, cap, 0, "%s%s", line, "");
    o = explain_phrase(&res->target, v, res->relation[0] ? "target" : "query", out, cap, o);
    if (res->relation[0]) {
        o = put(out, cap, o, "relation: %s\n%s", res->relation, "");
        o = explain_phrase(&res->anchor, v, "anchor", out, cap, o);
    }
    for (int i = 0; i < res->n_ignored; i++)
        o = put(out, cap, o, "ignored: '%s' (an attribute these class names cannot show)\n%s", res->ignored[i], "");
    put(out, cap, o, "%s%s", "(matching against the scene's known class names, not recognition)\n", "");
}
