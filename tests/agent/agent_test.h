/* Helpers of the agent's session tests: a tool's result in an answer's trace, a tool run by hand
 * (as an LLM would call it), the error code of a result. */
#ifndef SEMSPLAT_TEST_AGENT_TEST_H
#define SEMSPLAT_TEST_AGENT_TEST_H

#include <cjson/cJSON.h>
#include <stdio.h>
#include <string.h>

#include "agent/agent_internal.h"

/* The last result of `tool` in the answer's trace, parsed (caller deletes), or NULL. */
static inline cJSON *result_of(const sp_agent_answer *a, const char *tool)
{
    for (int i = a->n_trace - 1; i >= 0; i--)
        if (!strcmp(a->trace[i].tool, tool)) return cJSON_Parse(a->trace[i].result);
    return NULL;
}

static inline const cJSON *data_of(const cJSON *r) { return cJSON_GetObjectItemCaseSensitive(r, "data"); }

static inline char *run_tool(sp_agent_session *s, const char *name, const char *args, int *is_error)
{
    sp_agent_call c = {0};
    snprintf(c.id, sizeof c.id, "t1");
    snprintf(c.name, sizeof c.name, "%s", name);
    c.arguments = (char *)args;
    return agent_tool_run(s, &c, is_error);
}

static inline const char *error_code(const char *result, char *buf, size_t cap)
{
    cJSON *r = cJSON_Parse(result);
    const cJSON *c = cJSON_GetObjectItemCaseSensitive(cJSON_GetObjectItemCaseSensitive(r, "error"), "code");
    snprintf(buf, cap, "%s", cJSON_IsString(c) ? c->valuestring : "");
    cJSON_Delete(r);
    return buf;
}

#endif
