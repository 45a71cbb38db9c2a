/* The neutral conversation every brain reads: user commands, assistant turns with their tool
 * calls, and tool results. Each LLM client serializes it into its own wire format. */
#include <stdlib.h>
#include <string.h>

#include "agent_internal.h"

static agent_msg *push(agent_convo *c)
{
    if (c->n == c->cap) {
        int nc = c->cap ? 2 * c->cap : 16;
        agent_msg *m = realloc(c->m, (size_t)nc * sizeof *m);
        if (!m) return NULL;
        c->m = m;
        c->cap = nc;
    }
    agent_msg *m = &c->m[c->n++];
    memset(m, 0, sizeof *m);
    return m;
}

int agent_convo_user(agent_convo *c, const char *text)
{
    agent_msg *m = push(c);
    if (!m) return SP_E_NOMEM;
    m->role = AGENT_MSG_USER;
    if (!(m->text = agent_strdup(text ? text : ""))) return c->n--, SP_E_NOMEM;
    return SP_OK;
}

int agent_convo_assistant(agent_convo *c, sp_agent_reply *r)
{
    agent_msg *m = push(c);
    if (!m) return SP_E_NOMEM;
    m->role = AGENT_MSG_ASSISTANT;
    m->text = r->text;
    m->calls = r->calls;
    m->n_calls = r->n_calls;
    m->content_json = r->content_json;
    r->text = NULL;
    r->calls = NULL;
    r->n_calls = 0;
    r->content_json = NULL;
    return SP_OK;
}

int agent_convo_tool(agent_convo *c, const char *call_id, const char *tool, const char *result,
                     int is_error)
{
    agent_msg *m = push(c);
    if (!m) return SP_E_NOMEM;
    m->role = AGENT_MSG_TOOL;
    if (!(m->text = agent_strdup(result ? result : "{}"))) return c->n--, SP_E_NOMEM;
    agent_clean_copy(m->call_id, sizeof m->call_id, call_id);
    agent_clean_copy(m->tool, sizeof m->tool, tool);
    m->is_error = is_error;
    return SP_OK;
}

static void msg_free(agent_msg *m)
{
    free(m->text);
    for (int i = 0; i < m->n_calls; i++) agent_call_free(&m->calls[i]);
    free(m->calls);
    free(m->content_json);
}

void agent_convo_trim(agent_convo *c, int max)
{
    /* Cut at a user message so no tool result loses the call it answers. */
    int cut = 0;
    while (c->n - cut > max) {
        int next = cut + 1;
        while (next < c->n && c->m[next].role != AGENT_MSG_USER) next++;
        if (next >= c->n) break;
        cut = next;
    }
    if (!cut) return;
    for (int i = 0; i < cut; i++) msg_free(&c->m[i]);
    memmove(c->m, c->m + cut, (size_t)(c->n - cut) * sizeof *c->m);
    c->n -= cut;
}

void agent_convo_free(agent_convo *c)
{
    for (int i = 0; i < c->n; i++) msg_free(&c->m[i]);
    free(c->m);
    memset(c, 0, sizeof *c);
}
