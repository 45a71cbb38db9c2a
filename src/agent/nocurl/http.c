/* Stand-in for curl/http.c when libcurl is not found: the LLM clients fail with a message naming
 * the package; the built-in parser and everything offline still work. */
#include <stdlib.h>
#include <string.h>

#include "agent/agent_internal.h"

int agent_http_available(void) { return 0; }

int agent_http_post(const char *url, const char *const *headers, int n_headers, const char *body,
                    size_t body_len, double timeout_s, double connect_timeout_s,
                    agent_http_response *resp, sp_error *err)
{
    memset(resp, 0, sizeof *resp);
    return sp_error_set(err, SP_E_UNSUPPORTED,
                        "the LLM clients need libcurl, which this build lacks: install "
                        "libcurl4-openssl-dev (scripts/install-deps.sh) and rebuild, or use --llm builtin");
}

void agent_http_response_free(agent_http_response *r)
{
    if (!r) return;
    free(r->body);
    memset(r, 0, sizeof *r);
}
