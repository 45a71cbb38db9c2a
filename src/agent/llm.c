/* The LLM brains: an OpenAI-compatible chat-completions client (OpenAI, llama.cpp's server,
 * Ollama's /v1, vLLM) and an Anthropic Messages client, behind the brain interface. Endpoint and
 * model come from the config, else the SDKs' environment variables, else a preset; the key only
 * from the environment, sent in one header and redacted from every message. Requests are retried
 * by retry.c's rules and every wait is bounded. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "agent_internal.h"

typedef struct llm {
    int dialect;
    char url[1024];
    char model[160];
    char key[512];          /* never printed */
    char auth[600];         /* the header carrying it */
    char version[64];       /* anthropic-version header */
    sp_agent_llm_config cfg;
    agent_llm_wire wire;
    const sp_log *log;
    unsigned seed;
    int turn;
} llm;

typedef struct preset {
    const char *name, *base_url, *model, *dummy_key;
    int parallel; /* -1 = leave the field out */
} preset;

/* llama.cpp's server has parallel calls off unless asked; Ollama wants some key ("required but
 * ignored"); vLLM and llama.cpp accept none. */
static const preset presets[] = {
    {"openai", "https://api.openai.com/v1", NULL, NULL, -1},
    {"llama.cpp", "http://127.0.0.1:8080/v1", "local", NULL, 1},
    {"llamacpp", "http://127.0.0.1:8080/v1", "local", NULL, 1},
    {"ollama", "http://127.0.0.1:11434/v1", NULL, "ollama", -1},
    {"vllm", "http://127.0.0.1:8000/v1", NULL, NULL, -1},
};

static const preset *find_preset(const char *name)
{
    for (size_t i = 0; i < sizeof presets / sizeof presets[0]; i++)
        if (name && !strcmp(name, presets[i].name)) return &presets[i];
    return NULL;
}

/* Base URL + the endpoint path, unless the base already ends with it. */
static int endpoint(char *out, size_t cap, const char *base, int dialect)
{
    size_t n = strlen(base);
    while (n > 0 && base[n - 1] == '/') n--;
    const char *path = dialect == SP_AGENT_BRAIN_OPENAI ? "/chat/completions" : "/v1/messages";
    size_t pl = strlen(path);
    if (n >= pl && !strncmp(base + n - pl, path, pl)) path = "";
    else if (dialect == SP_AGENT_BRAIN_ANTHROPIC && n >= 3 && !strncmp(base + n - 3, "/v1", 3))
        path = "/messages";
    int w = snprintf(out, cap, "%.*s%s", (int)n, base, path);
    return w > 0 && (size_t)w < cap ? 0 : -1;
}

/* Removes the key from a server's message (some echo a prefix of it back). */
static void redact(const llm *l, char *msg)
{
    size_t k = strlen(l->key);
    if (k < 4) return;
    for (char *p = strstr(msg, l->key); p; p = strstr(p, l->key)) {
        memcpy(p, "[key]", 5);
        memmove(p + 5, p + k, strlen(p + k) + 1);
    }
}

static void sleep_s(double t)
{
    struct timespec ts = {(time_t)t, (long)((t - floor(t)) * 1e9)};
    while (nanosleep(&ts, &ts) != 0) {
    }
}

/* One POST with retries; on success *resp holds a 200 body. */
static int post(llm *l, const char *body, agent_http_response *resp, agent_stats *st, sp_error *err)
{
    const char *hdr[4];
    int nh = 0;
    hdr[nh++] = "Content-Type: application/json";
    if (l->auth[0]) hdr[nh++] = l->auth;
    if (l->version[0]) hdr[nh++] = l->version;
    for (int attempt = 0;; attempt++) {
        st->requests++;
        int rc = agent_http_post(l->url, hdr, nh, body, strlen(body), l->cfg.timeout_s,
                                 l->cfg.connect_timeout_s, resp, err);
        if (rc) return rc;
        if (resp->net == AGENT_NET_OK && resp->status == 200) return SP_OK;
        double delay;
        char why[300];
        int again = agent_retry_decide(resp->status, resp->net, resp->body, resp->size,
                                       resp->retry_after_s, attempt, &l->cfg, &l->seed, &delay,
                                       why, sizeof why);
        if (!again) {
            char type[64], code[64], msg[400] = "";
            if (resp->net == AGENT_NET_OK)
                sp_agent_decode_error_body(resp->body, resp->size, type, sizeof type, code, sizeof code,
                                           msg, sizeof msg);
            else
                snprintf(msg, sizeof msg, "%s", resp->net_msg);
            redact(l, msg);
            rc = sp_error_set(err, SP_E_NET, "%s: %s%s%s", l->url, why, msg[0] ? ": " : "", msg);
            agent_http_response_free(resp);
            return rc;
        }
        sp_logf(l->log, SP_LOG_WARN, "LLM %s: %s; retrying in %.2f s (attempt %d of %d)", l->url, why,
                delay, attempt + 2, l->cfg.max_retries + 1);
        agent_http_response_free(resp);
        st->retries++;
        sleep_s(delay);
    }
}

static int llm_next(void *ctx, const agent_convo *c, sp_agent_reply *out, agent_stats *st,
                    sp_error *err)
{
    llm *l = ctx;
    memset(out, 0, sizeof *out);
    char *body = l->dialect == SP_AGENT_BRAIN_OPENAI ? agent_openai_request(&l->wire, c, err)
                                                      : agent_anthropic_request(&l->wire, c, err);
    if (!body) return err->code;
    agent_http_response resp;
    int rc = post(l, body, &resp, st, err);
    free(body);
    if (rc) return rc;
    rc = l->dialect == SP_AGENT_BRAIN_OPENAI ? sp_agent_decode_openai(resp.body, resp.size, out, err)
                                              : sp_agent_decode_anthropic(resp.body, resp.size, out, err);
    if (rc) {
        redact(l, err->msg);
        sp_error_prefix(err, "%s: the reply could not be used: ", l->url);
    }
    agent_http_response_free(&resp);
    l->turn++;
    /* Ids we made up must not repeat across turns (OpenAI pairs results by id). */
    for (int i = 0; !rc && i < out->n_calls; i++)
        if (out->calls[i].synthesized && l->dialect == SP_AGENT_BRAIN_OPENAI)
            snprintf(out->calls[i].id, sizeof out->calls[i].id, "call_%d_%d", l->turn, i + 1);
    return rc;
}

static void llm_close(void *ctx)
{
    llm *l = ctx;
    if (!l) return;
    memset(l->key, 0, sizeof l->key);
    memset(l->auth, 0, sizeof l->auth);
    free(l);
}

static int setup(llm *l, int dialect, const sp_agent_llm_config *cfg, sp_error *err)
{
    const preset *p = dialect == SP_AGENT_BRAIN_OPENAI ? find_preset(cfg->preset ? cfg->preset : "openai") : NULL;
    if (dialect == SP_AGENT_BRAIN_OPENAI && !p)
        return sp_error_set(err, SP_E_ARG, "unknown LLM preset '%s' (openai, llama.cpp, ollama, vllm)", cfg->preset);
    const char *env_url = getenv(dialect == SP_AGENT_BRAIN_OPENAI ? "OPENAI_BASE_URL" : "ANTHROPIC_BASE_URL");
    const char *env_key = getenv(dialect == SP_AGENT_BRAIN_OPENAI ? "OPENAI_API_KEY" : "ANTHROPIC_API_KEY");
    /* A preset names a local server: the hosted default in the environment does not override it. */
    int local = p && strcmp(p->name, "openai") != 0;
    const char *base = cfg->base_url && cfg->base_url[0] ? cfg->base_url
                       : env_url && env_url[0] && !local ? env_url
                       : p                               ? p->base_url
                                                         : "https://api.anthropic.com";
    if (strncmp(base, "http://", 7) && strncmp(base, "https://", 8))
        return sp_error_set(err, SP_E_ARG, "LLM base URL '%.200s' must start with http:// or https://", base);
    if (endpoint(l->url, sizeof l->url, base, dialect))
        return sp_error_set(err, SP_E_ARG, "LLM base URL is too long");
    const char *model = cfg->model && cfg->model[0] ? cfg->model : p ? p->model : NULL;
    if (!model)
        return sp_error_set(err, SP_E_ARG, "%s needs a model name (--llm-model NAME)", l->url);
    snprintf(l->model, sizeof l->model, "%s", model);
    const char *key = env_key && env_key[0] ? env_key : p ? p->dummy_key : NULL;
    if (key && strlen(key) >= sizeof l->key)
        return sp_error_set(err, SP_E_ARG, "the API key in the environment is too long");
    if (key && strpbrk(key, "\r\n"))
        return sp_error_set(err, SP_E_ARG, "the API key in the environment contains a line break");
    snprintf(l->key, sizeof l->key, "%s", key ? key : "");
    if (l->key[0])
        snprintf(l->auth, sizeof l->auth, dialect == SP_AGENT_BRAIN_OPENAI ? "Authorization: Bearer %s" : "x-api-key: %s",
                 l->key);
    if (dialect == SP_AGENT_BRAIN_ANTHROPIC)
        snprintf(l->version, sizeof l->version, "anthropic-version: %s",
                 cfg->anthropic_version && cfg->anthropic_version[0] ? cfg->anthropic_version : "2023-06-01");
    l->wire.model = l->model;
    l->wire.max_tokens = cfg->max_tokens > 0 ? cfg->max_tokens : 1024;
    l->wire.parallel_tool_calls = p ? p->parallel : -1;
    return SP_OK;
}

int agent_brain_llm(agent_brain *out, int dialect, const sp_agent_llm_config *cfg,
                    const sp_log *log, sp_error *err)
{
    memset(out, 0, sizeof *out);
    if (dialect != SP_AGENT_BRAIN_OPENAI && dialect != SP_AGENT_BRAIN_ANTHROPIC)
        return sp_error_set(err, SP_E_ARG, "unknown LLM dialect %d", dialect);
    if (!agent_http_available())
        return agent_http_post("", NULL, 0, "", 0, 0, 0, &(agent_http_response){0}, err);
    llm *l = calloc(1, sizeof *l);
    if (!l) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    l->dialect = dialect;
    l->cfg = *cfg;
    if (!(l->cfg.timeout_s > 0)) l->cfg.timeout_s = 60;
    if (!(l->cfg.connect_timeout_s > 0)) l->cfg.connect_timeout_s = 10;
    if (l->cfg.max_retries < 0) l->cfg.max_retries = 0;
    if (l->cfg.max_retries > 10) l->cfg.max_retries = 10;
    if (!(l->cfg.retry_base_s >= 0)) l->cfg.retry_base_s = 0.5;
    if (!(l->cfg.retry_max_s > 0)) l->cfg.retry_max_s = 30;
    l->seed = cfg->seed ? cfg->seed : 0x5eed;
    l->log = log;
    int rc = setup(l, dialect, &l->cfg, err);
    if (rc) {
        llm_close(l);
        return rc;
    }
    out->name = dialect == SP_AGENT_BRAIN_OPENAI ? "openai" : "anthropic";
    out->next = llm_next;
    out->close = llm_close;
    out->ctx = l;
    return SP_OK;
}
