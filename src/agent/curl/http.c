/* HTTP POST for the LLM clients through libcurl: bounded time (connect and total timeouts),
 * bounded body size, no redirects, http/https only, never a proxy for loopback hosts, no
 * signals. Transport failures are classified for the retry policy, not returned as errors.
 * Compiled only when libcurl is found (nocurl/http.c otherwise). */
#include <curl/curl.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <time.h>

#include "agent/agent_internal.h"

static pthread_once_t curl_once = PTHREAD_ONCE_INIT;
static void curl_init_once(void) { curl_global_init(CURL_GLOBAL_DEFAULT); }

int agent_http_available(void) { return 1; }

typedef struct sink {
    agent_http_response *r;
    size_t cap;
    int overflow;
} sink;

static size_t on_body(char *data, size_t size, size_t n, void *user)
{
    sink *s = user;
    size_t len = size * n;
    if (s->r->size + len > AGENT_HTTP_MAX_BODY) {
        s->overflow = 1;
        return 0; /* aborts the transfer */
    }
    if (s->r->size + len + 1 > s->cap) {
        size_t nc = s->cap ? s->cap : 4096;
        while (nc < s->r->size + len + 1) nc *= 2;
        char *nb = realloc(s->r->body, nc);
        if (!nb) return 0;
        s->r->body = nb;
        s->cap = nc;
    }
    memcpy(s->r->body + s->r->size, data, len);
    s->r->size += len;
    s->r->body[s->r->size] = 0;
    return len;
}

/* Retry-After (seconds or an HTTP date) and OpenAI's retry-after-ms. */
static size_t on_header(char *data, size_t size, size_t n, void *user)
{
    agent_http_response *r = user;
    size_t len = size * n;
    char line[256];
    if (len >= sizeof line) return len;
    memcpy(line, data, len);
    line[len] = 0;
    if (!strncasecmp(line, "HTTP/", 5)) r->retry_after_s = -1; /* a new response (after 100) */
    char *colon = strchr(line, ':');
    if (!colon) return len;
    *colon = 0;
    double v;
    if (!strcasecmp(line, "retry-after-ms")) {
        v = agent_parse_retry_after(colon + 1, 0);
        if (v >= 0) r->retry_after_s = v / 1000.0;
    } else if (!strcasecmp(line, "retry-after") && r->retry_after_s < 0) {
        v = agent_parse_retry_after(colon + 1, (double)time(NULL));
        if (v >= 0) r->retry_after_s = v;
    }
    return len;
}

static int classify(CURLcode c)
{
    switch (c) {
    case CURLE_OK: return AGENT_NET_OK;
    case CURLE_OPERATION_TIMEDOUT: return AGENT_NET_TIMEOUT;
    case CURLE_COULDNT_CONNECT:
    case CURLE_COULDNT_RESOLVE_HOST:
    case CURLE_COULDNT_RESOLVE_PROXY: return AGENT_NET_CONNECT;
    case CURLE_PARTIAL_FILE:
    case CURLE_RECV_ERROR:
    case CURLE_GOT_NOTHING: return AGENT_NET_TRUNCATED;
    default: return AGENT_NET_OTHER;
    }
}

int agent_http_post(const char *url, const char *const *headers, int n_headers, const char *body,
                    size_t body_len, double timeout_s, double connect_timeout_s,
                    agent_http_response *resp, sp_error *err)
{
    memset(resp, 0, sizeof *resp);
    resp->retry_after_s = -1;
    if (strncmp(url, "http://", 7) && strncmp(url, "https://", 8))
        return sp_error_set(err, SP_E_ARG, "%s: only http:// and https:// URLs are supported", url);
    pthread_once(&curl_once, curl_init_once);
    CURL *h = curl_easy_init();
    if (!h) return sp_error_set(err, SP_E_NOMEM, "libcurl: cannot create a handle");
    struct curl_slist *hl = NULL;
    for (int i = 0; i < n_headers; i++) hl = curl_slist_append(hl, headers[i]);
    hl = curl_slist_append(hl, "Expect:"); /* no 100-continue round trip */
    sink s = {resp, 0, 0};
    curl_easy_setopt(h, CURLOPT_URL, url);
    curl_easy_setopt(h, CURLOPT_POST, 1L);
    curl_easy_setopt(h, CURLOPT_POSTFIELDS, body);
    curl_easy_setopt(h, CURLOPT_POSTFIELDSIZE_LARGE, (curl_off_t)body_len);
    curl_easy_setopt(h, CURLOPT_HTTPHEADER, hl);
    curl_easy_setopt(h, CURLOPT_WRITEFUNCTION, on_body);
    curl_easy_setopt(h, CURLOPT_WRITEDATA, &s);
    curl_easy_setopt(h, CURLOPT_HEADERFUNCTION, on_header);
    curl_easy_setopt(h, CURLOPT_HEADERDATA, resp);
    curl_easy_setopt(h, CURLOPT_TIMEOUT_MS, (long)(timeout_s * 1000));
    curl_easy_setopt(h, CURLOPT_CONNECTTIMEOUT_MS, (long)(connect_timeout_s * 1000));
    curl_easy_setopt(h, CURLOPT_NOSIGNAL, 1L);
    curl_easy_setopt(h, CURLOPT_FOLLOWLOCATION, 0L);
#if LIBCURL_VERSION_NUM >= 0x075500 /* 7.85 */
    curl_easy_setopt(h, CURLOPT_PROTOCOLS_STR, "http,https");
#else
    curl_easy_setopt(h, CURLOPT_PROTOCOLS, (long)(CURLPROTO_HTTP | CURLPROTO_HTTPS));
#endif
    curl_easy_setopt(h, CURLOPT_NOPROXY, "localhost,127.0.0.1,::1");
    curl_easy_setopt(h, CURLOPT_USERAGENT, "semsplat-agent");
    CURLcode c = curl_easy_perform(h);
    curl_easy_getinfo(h, CURLINFO_RESPONSE_CODE, &resp->status);
    resp->net = s.overflow ? AGENT_NET_OTHER : classify(c);
    if (c != CURLE_OK)
        snprintf(resp->net_msg, sizeof resp->net_msg, "%s",
                 s.overflow ? "the response is larger than 16 MiB" : curl_easy_strerror(c));
    curl_slist_free_all(hl);
    curl_easy_cleanup(h);
    if (!resp->body && !(resp->body = calloc(1, 1))) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    return SP_OK;
}

void agent_http_response_free(agent_http_response *r)
{
    if (!r) return;
    free(r->body);
    memset(r, 0, sizeof *r);
}
