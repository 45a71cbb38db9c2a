/* When to retry an LLM request and how long to wait: 429 (honouring Retry-After), every 5xx,
 * Anthropic's 529 and transport failures (timeouts, refused connections, truncated bodies) are
 * retried with exponential backoff and jitter; no other 4xx is, and neither is a 429 that means
 * money ran out (OpenAI insufficient_quota, Anthropic enforced_spend_limit_reached). A server
 * asking for a longer wait than the configured limit is not waited for. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "agent_internal.h"

static double jitter(unsigned *seed)
{
    /* xorshift32: reproducible with a seed, no libc state */
    unsigned x = *seed ? *seed : 0x9E3779B9u;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *seed = x;
    return 0.5 + 0.5 * (x / 4294967296.0);
}

static int quota_exhausted(const char *body, size_t size)
{
    char type[64], code[64], msg[256];
    if (sp_agent_decode_error_body(body, size, type, sizeof type, code, sizeof code, msg, sizeof msg))
        return 0;
    return !strcmp(code, "insufficient_quota") || !strcmp(type, "insufficient_quota") ||
           !strcmp(code, "enforced_spend_limit_reached") || !strcmp(code, "billing_hard_limit_reached");
}

int agent_retry_decide(long status, int net, const char *body, size_t size, double retry_after_s,
                       int attempt, const sp_agent_llm_config *cfg, unsigned *seed,
                       double *delay_s, char *why, size_t why_cap)
{
    *delay_s = 0;
    int transient;
    if (net != AGENT_NET_OK) {
        transient = 1;
        snprintf(why, why_cap, "%s", net == AGENT_NET_TIMEOUT     ? "the request timed out"
                                     : net == AGENT_NET_CONNECT   ? "could not connect"
                                     : net == AGENT_NET_TRUNCATED ? "the response was truncated"
                                                                  : "the transfer failed");
    } else if (status == 429) {
        transient = !quota_exhausted(body, size);
        snprintf(why, why_cap, "HTTP 429 (%s)", transient ? "rate limited" : "quota or spend limit exhausted: not retried");
    } else if (status >= 500 && status <= 599) {
        transient = 1;
        snprintf(why, why_cap, "HTTP %ld (%s)", status, status == 529 ? "overloaded" : "server error");
    } else {
        snprintf(why, why_cap, "HTTP %ld (not retried)", status);
        return 0;
    }
    if (!transient) return 0;
    if (attempt >= cfg->max_retries) {
        size_t n = strlen(why);
        snprintf(why + n, why_cap - n, "; gave up after %d attempt%s", attempt + 1, attempt ? "s" : "");
        return 0;
    }
    double backoff = cfg->retry_base_s * pow(2.0, attempt) * jitter(seed);
    if (retry_after_s > cfg->retry_max_s) {
        size_t n = strlen(why);
        snprintf(why + n, why_cap - n, "; the server asks to wait %.0f s, more than the %.0f s limit",
                 retry_after_s, cfg->retry_max_s);
        return 0;
    }
    double d = retry_after_s >= 0 ? fmax(retry_after_s, backoff) : backoff;
    *delay_s = fmin(d, cfg->retry_max_s);
    return 1;
}

static int month_index(const char *m)
{
    static const char *const months[] = {"Jan", "Feb", "Mar", "Apr", "May", "Jun",
                                         "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"};
    for (int i = 0; i < 12; i++)
        if (!strncmp(m, months[i], 3)) return i;
    return -1;
}

double agent_parse_retry_after(const char *value, double now_epoch)
{
    if (!value) return -1;
    while (*value == ' ' || *value == '\t') value++;
    if (isdigit((unsigned char)*value)) {
        char *end;
        double v = strtod(value, &end);
        while (*end == ' ' || *end == '\r' || *end == '\n') end++;
        return *end == 0 && isfinite(v) && v >= 0 ? v : -1;
    }
    /* IMF-fixdate: "Wed, 21 Oct 2015 07:28:00 GMT" */
    char wd[4], mon[4];
    int day, year, hh, mm, ss;
    if (sscanf(value, "%3s %d %3s %d %d:%d:%d", wd, &day, mon, &year, &hh, &mm, &ss) != 7 &&
        sscanf(value, "%3s, %d %3s %d %d:%d:%d", wd, &day, mon, &year, &hh, &mm, &ss) != 7)
        return -1;
    int mi = month_index(mon);
    if (mi < 0 || day < 1 || day > 31 || year < 1970 || hh > 23 || mm > 59 || ss > 60) return -1;
    struct tm t = {0};
    t.tm_year = year - 1900, t.tm_mon = mi, t.tm_mday = day, t.tm_hour = hh, t.tm_min = mm, t.tm_sec = ss;
    double at = (double)timegm(&t);
    return at > now_epoch ? at - now_epoch : 0;
}
