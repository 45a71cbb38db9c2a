/* An answer: the text, the whole tool-call trace and the images, as a struct and as the JSON the
 * session writes to the output folder. */
#include <cjson/cJSON.h>
#include <stdlib.h>
#include <string.h>

#include "agent_internal.h"

int agent_answer_add_image(sp_agent_answer *a, const char *path)
{
    if (!a || !path || !path[0]) return SP_OK;
    for (int i = 0; i < a->n_images; i++)
        if (!strcmp(a->images[i], path)) return SP_OK;
    char **im = realloc(a->images, (size_t)(a->n_images + 1) * sizeof *im);
    if (!im) return SP_E_NOMEM;
    a->images = im;
    if (!(im[a->n_images] = agent_strdup(path))) return SP_E_NOMEM;
    a->n_images++;
    return SP_OK;
}

void sp_agent_answer_free(sp_agent_answer *a)
{
    if (!a) return;
    free(a->command);
    free(a->text);
    for (int i = 0; i < a->n_trace; i++) {
        free(a->trace[i].tool);
        free(a->trace[i].call_id);
        free(a->trace[i].arguments);
        free(a->trace[i].result);
    }
    free(a->trace);
    for (int i = 0; i < a->n_images; i++) free(a->images[i]);
    free(a->images);
    memset(a, 0, sizeof *a);
}

/* Embeds JSON text as JSON when it parses, else as a string (a model's broken arguments). */
static cJSON *json_or_string(const char *s)
{
    cJSON *j = s ? cJSON_Parse(s) : NULL;
    return j ? j : cJSON_CreateString(s ? s : "");
}

char *sp_agent_answer_json(const sp_agent_answer *a)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "command", a->command ? a->command : "");
    cJSON_AddStringToObject(o, "answer", a->text ? a->text : "");
    cJSON_AddBoolToObject(o, "asked_back", a->asked_back);
    cJSON_AddStringToObject(o, "builtin_reading", sp_agent_intent_name(a->intent));
    cJSON_AddNumberToObject(o, "brain_turns", a->steps);
    cJSON *llm = cJSON_AddObjectToObject(o, "llm");
    cJSON_AddNumberToObject(llm, "requests", a->llm_requests);
    cJSON_AddNumberToObject(llm, "retries", a->llm_retries);
    cJSON *tr = cJSON_AddArrayToObject(o, "trace");
    for (int i = 0; i < a->n_trace; i++) {
        cJSON *t = cJSON_CreateObject();
        cJSON_AddStringToObject(t, "tool", a->trace[i].tool ? a->trace[i].tool : "");
        cJSON_AddStringToObject(t, "call_id", a->trace[i].call_id ? a->trace[i].call_id : "");
        cJSON_AddItemToObject(t, "arguments", json_or_string(a->trace[i].arguments));
        cJSON_AddItemToObject(t, "result", json_or_string(a->trace[i].result));
        cJSON_AddBoolToObject(t, "is_error", a->trace[i].is_error);
        cJSON_AddNumberToObject(t, "ms", agent_round4(a->trace[i].ms));
        cJSON_AddItemToArray(tr, t);
    }
    cJSON *im = cJSON_AddArrayToObject(o, "images");
    for (int i = 0; i < a->n_images; i++) cJSON_AddItemToArray(im, cJSON_CreateString(a->images[i]));
    char *s = cJSON_Print(o);
    cJSON_Delete(o);
    return s;
}
