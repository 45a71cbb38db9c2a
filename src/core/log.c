/* Logging through a caller-owned sink, and terminal progress bars (step, rate, ETA). */
#include "semsplat/core.h"

#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

double sp_time_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void stderr_sink(void *user, sp_log_level level, const char *msg)
{
    static const char *names[] = {"debug", "info", "warning", "error"};
    if (level >= SP_LOG_WARN)
        fprintf(stderr, "semsplat: %s: %s\n", names[level], msg);
    else
        fprintf(stderr, "semsplat: %s\n", msg);
}

sp_log sp_log_stderr(sp_log_level min_level, int quiet)
{
    sp_log log = {stderr_sink, NULL, quiet ? SP_LOG_WARN : min_level, quiet ? -1 : 2};
    return log;
}

void sp_logf(const sp_log *log, sp_log_level level, const char *fmt, ...)
{
    if (!log || !log->fn || level < log->min_level) return;
    char buf[2048];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    log->fn(log->user, level, buf);
}

void sp_progress_begin(sp_progress *p, const sp_log *log, const char *label, long total,
                       const char *unit)
{
    memset(p, 0, sizeof *p);
    p->log = log;
    snprintf(p->label, sizeof p->label, "%s", label);
    p->unit = unit ? unit : "it";
    p->total = total;
    p->t_start = p->t_last_draw = sp_time_now();
    p->last_pct = -1;
    p->is_tty = log && log->progress_fd >= 0 && isatty(log->progress_fd);
}

static void fmt_time(char *out, size_t cap, double s)
{
    if (!(s >= 0) || s > 359999) {
        snprintf(out, cap, "--:--");
        return;
    }
    long t = (long)(s + 0.5);
    if (t >= 3600)
        snprintf(out, cap, "%ld:%02ld:%02ld", t / 3600, (t / 60) % 60, t % 60);
    else
        snprintf(out, cap, "%02ld:%02ld", t / 60, t % 60);
}

static void draw(sp_progress *p, const char *extra, int final)
{
    double now = sp_time_now(), el = now - p->t_start;
    double rate = el > 0 ? (double)p->step / el : 0;
    double eta = rate > 0 ? (double)(p->total - p->step) / rate : -1;
    char bar[21], tel[16], teta[16], line[512];
    int filled = p->total > 0 ? (int)(20 * p->step / p->total) : 0;
    for (int i = 0; i < 20; i++) bar[i] = i < filled ? '#' : '.';
    bar[20] = 0;
    fmt_time(tel, sizeof tel, el);
    fmt_time(teta, sizeof teta, final ? 0 : eta);
    int n = snprintf(line, sizeof line, "%s%-14s [%s] %ld/%ld  %.1f %s/s  %s %s  %s%s",
                     p->is_tty ? "\r" : "", p->label, bar, p->step, p->total, rate, p->unit,
                     final ? "took" : "ETA", final ? tel : teta, extra ? extra : "",
                     p->is_tty ? "\033[K" : "\n");
    if (final && p->is_tty && n > 0 && n < (int)sizeof line - 1) {
        line[n] = '\n';
        line[n + 1] = 0;
        n++;
    }
    if (n > 0) {
        ssize_t w = write(p->log->progress_fd, line, (size_t)(n < (int)sizeof line ? n : (int)sizeof line - 1));
        (void)w;
    }
}

void sp_progress_update(sp_progress *p, long step, const char *extra)
{
    p->step = step;
    if (!p->log || p->log->progress_fd < 0) return;
    double now = sp_time_now();
    if (p->is_tty) {
        if (now - p->t_last_draw < 0.1 && step < p->total) return;
    } else {
        /* Logs and pipes get a line every 10% or every 30 s. */
        int pct = p->total > 0 ? (int)(10 * step / p->total) : 0;
        if (pct == p->last_pct && now - p->t_last_draw < 30) return;
        p->last_pct = pct;
    }
    p->t_last_draw = now;
    draw(p, extra, 0);
}

void sp_progress_end(sp_progress *p, const char *extra)
{
    if (!p->log || p->log->progress_fd < 0) return;
    draw(p, extra, 1);
}
