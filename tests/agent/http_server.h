/* A scripted HTTP/1.1 server for the LLM protocol tests: a thread in the test process listening
 * on 127.0.0.1 (an ephemeral port), one request per connection, answering from a script (status,
 * extra headers, a fixed body or one computed from the request, a delay, a body cut short). It
 * records every request for the test to inspect. Every wait is bounded and ts_stop joins it. */
#ifndef SEMSPLAT_TEST_HTTP_SERVER_H
#define SEMSPLAT_TEST_HTTP_SERVER_H

#include <arpa/inet.h>
#include <errno.h>
#include <netinet/in.h>
#include <poll.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

typedef char *(*ts_body_fn)(const char *request_body, void *user); /* malloc'd body */

typedef struct ts_response {
    int status;
    const char *headers;   /* extra header lines, each ending in \r\n (may be NULL) */
    const char *body;      /* fixed body, or NULL with fn */
    ts_body_fn fn;
    int delay_ms;          /* wait before answering */
    int truncate_to;       /* > 0: announce the full length, send this many bytes, close */
} ts_response;

#define TS_MAX_REQ 48

typedef struct ts_request {
    char head[8192];       /* request line and headers */
    char *body;
} ts_request;

typedef struct test_server {
    int fd, port;
    pthread_t thread;
    const ts_response *script;
    int n_script, served;
    ts_request req[TS_MAX_REQ];
    int n_req;
    void *user;
    volatile int stop;
} test_server;

/* strcasestr is a GNU extension; this is the portable few lines. */
static inline const char *ts_strcasestr(const char *h, const char *n)
{
    size_t k = strlen(n);
    for (; *h; h++)
        if (!strncasecmp(h, n, k)) return h;
    return NULL;
}

static inline void ts_sleep_ms(int ms)
{
    struct timespec t = {ms / 1000, (long)(ms % 1000) * 1000000L};
    nanosleep(&t, NULL);
}

/* Reads until the headers and Content-Length bytes of body are in, or 5 s pass. */
static inline int ts_read_request(int c, ts_request *r)
{
    char *buf = malloc(1 << 20);
    size_t n = 0, need = 0, hlen = 0;
    int ok = 0;
    for (int waited = 0; waited < 5000 && n < (1u << 20) - 1;) {
        struct pollfd p = {c, POLLIN, 0};
        if (poll(&p, 1, 100) <= 0) {
            waited += 100;
            continue;
        }
        ssize_t k = recv(c, buf + n, (1u << 20) - 1 - n, 0);
        if (k <= 0) break;
        n += (size_t)k;
        buf[n] = 0;
        if (!hlen) {
            char *e = strstr(buf, "\r\n\r\n");
            if (!e) continue;
            hlen = (size_t)(e - buf) + 4;
            const char *cl = ts_strcasestr(buf, "\r\ncontent-length:");
            need = hlen + (cl && cl < e ? (size_t)atol(cl + 17) : 0);
        }
        if (n >= need) {
            ok = 1;
            break;
        }
    }
    if (ok) {
        snprintf(r->head, sizeof r->head, "%.*s", (int)hlen, buf);
        r->body = malloc(n - hlen + 1);
        memcpy(r->body, buf + hlen, n - hlen);
        r->body[n - hlen] = 0;
    }
    free(buf);
    return ok;
}

static inline void ts_send_all(int c, const char *p, size_t n)
{
    while (n > 0) {
        ssize_t k = send(c, p, n, MSG_NOSIGNAL);
        if (k <= 0) return;
        p += k, n -= (size_t)k;
    }
}

static inline void ts_handle(test_server *s, int c)
{
    ts_request *r = &s->req[s->n_req < TS_MAX_REQ ? s->n_req : TS_MAX_REQ - 1];
    if (!ts_read_request(c, r)) return;
    if (s->n_req < TS_MAX_REQ) s->n_req++;
    static const ts_response exhausted = {500, NULL, "{\"error\":{\"message\":\"test script exhausted\"}}",
                                          NULL, 0, 0};
    const ts_response *resp = s->served < s->n_script ? &s->script[s->served] : &exhausted;
    s->served++;
    for (int t = 0; t < resp->delay_ms && !s->stop; t += 20) ts_sleep_ms(20);
    if (s->stop) return;
    char *dyn = resp->fn ? resp->fn(r->body, s->user) : NULL;
    const char *body = dyn ? dyn : resp->body ? resp->body : "";
    size_t blen = strlen(body);
    char head[1024];
    int hn = snprintf(head, sizeof head,
                      "HTTP/1.1 %d X\r\nContent-Type: application/json\r\nContent-Length: %zu\r\n"
                      "Connection: close\r\n%s\r\n",
                      resp->status, blen, resp->headers ? resp->headers : "");
    ts_send_all(c, head, (size_t)hn);
    ts_send_all(c, body, resp->truncate_to > 0 && (size_t)resp->truncate_to < blen ? (size_t)resp->truncate_to : blen);
    free(dyn);
}

static inline void *ts_main(void *arg)
{
    test_server *s = arg;
    while (!s->stop) {
        struct pollfd p = {s->fd, POLLIN, 0};
        if (poll(&p, 1, 50) <= 0) continue;
        int c = accept(s->fd, NULL, NULL);
        if (c < 0) continue;
        ts_handle(s, c);
        shutdown(c, SHUT_RDWR);
        close(c);
    }
    return NULL;
}

static inline int ts_start(test_server *s, const ts_response *script, int n, void *user)
{
    memset(s, 0, sizeof *s);
    s->script = script, s->n_script = n, s->user = user;
    s->fd = socket(AF_INET, SOCK_STREAM, 0);
    if (s->fd < 0) return -1;
    int one = 1;
    setsockopt(s->fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    struct sockaddr_in a = {0};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = 0;
    socklen_t len = sizeof a;
    if (bind(s->fd, (struct sockaddr *)&a, sizeof a) || listen(s->fd, 8) ||
        getsockname(s->fd, (struct sockaddr *)&a, &len)) {
        close(s->fd);
        return -1;
    }
    s->port = ntohs(a.sin_port);
    return pthread_create(&s->thread, NULL, ts_main, s);
}

static inline void ts_stop(test_server *s)
{
    s->stop = 1;
    pthread_join(s->thread, NULL);
    close(s->fd);
    for (int i = 0; i < s->n_req; i++) free(s->req[i].body);
    s->n_req = 0;
}

/* A header's value in a recorded request ("" when absent). */
static inline const char *ts_header(const ts_request *r, const char *name, char *out, size_t cap)
{
    char key[128];
    snprintf(key, sizeof key, "\r\n%s:", name);
    const char *h = ts_strcasestr(r->head, key);
    out[0] = 0;
    if (!h) return out;
    h += strlen(key);
    while (*h == ' ') h++;
    size_t n = strcspn(h, "\r\n");
    snprintf(out, cap, "%.*s", (int)(n < cap ? n : cap - 1), h);
    return out;
}

#endif
