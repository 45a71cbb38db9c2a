/* LLM server bodies and tool arguments (the agent's decoders, any bytes): the first byte picks
 * the decoder (byte % 4: 0 OpenAI chat-completions body, 1 Anthropic Messages body, 2 an HTTP
 * error body of either, 3 a tool's arguments, the tool = second byte % SP_AGENT_N_TOOLS); the rest
 * is the body. Never a crash, a clear error, and a reply that decodes is consistent (calls named,
 * arguments JSON or an error saying why). */
#include "fuzz_util.h"
#include "semsplat/agent.h"

static void check_reply(const sp_agent_reply *r)
{
    FZ_ASSERT(r->n_calls >= 0 && (r->n_calls == 0 || r->calls), "%d calls", r->n_calls);
    for (int i = 0; i < r->n_calls; i++) {
        const sp_agent_call *c = &r->calls[i];
        FZ_ASSERT(strlen(c->name) < sizeof c->name && strlen(c->id) < sizeof c->id, "call %d fields", i);
        FZ_ASSERT(c->arguments || c->args_error[0], "call %d has neither arguments nor an error", i);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2) return 0;
    const char *body = (const char *)data + 2;
    size_t n = size - 2;
    sp_error err = {0};
    int rc;
    switch (data[0] % 4) {
    case 0:
    case 1: {
        sp_agent_reply r;
        rc = data[0] % 4 ? sp_agent_decode_anthropic(body, n, &r, &err) : sp_agent_decode_openai(body, n, &r, &err);
        if (rc) fz_check_error(rc, &err, "decode reply");
        else check_reply(&r);
        sp_agent_reply_free(&r);
        break;
    }
    case 2: {
        char type[64], code[64], msg[256];
        rc = sp_agent_decode_error_body(body, n, type, sizeof type, code, sizeof code, msg, sizeof msg);
        FZ_ASSERT(rc == 0 || rc == SP_E_FORMAT, "error body: rc %d", rc);
        FZ_ASSERT(strlen(type) < sizeof type && strlen(code) < sizeof code && strlen(msg) < sizeof msg, "strings");
        break;
    }
    default: {
        sp_agent_args a;
        int tool = data[1] % SP_AGENT_N_TOOLS;
        rc = sp_agent_decode_tool_args(tool, body, n, &a, &err);
        if (rc) fz_check_error(rc, &err, "sp_agent_decode_tool_args");
        else FZ_ASSERT(a.tool == tool && strlen(a.text) <= SP_AGENT_MAX_PHRASE, "decoded args inconsistent");
        break;
    }
    }
    return 0;
}
