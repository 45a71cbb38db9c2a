/* Error status and messages (sp_error), shared by every module. */
#include "semsplat/core.h"

#include <stdio.h>
#include <string.h>

int sp_error_set(sp_error *err, int code, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err->msg, sizeof err->msg, fmt, ap);
        va_end(ap);
        err->code = code;
    }
    return code;
}

int sp_error_prefix(sp_error *err, const char *fmt, ...)
{
    if (!err) return SP_E_ARG;
    char prefix[512], old[sizeof err->msg];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(prefix, sizeof prefix, fmt, ap);
    va_end(ap);
    memcpy(old, err->msg, sizeof old);
    snprintf(err->msg, sizeof err->msg, "%s%s", prefix, old);
    return err->code;
}

void sp_error_clear(sp_error *err)
{
    if (err) {
        err->code = 0;
        err->msg[0] = 0;
    }
}

const char *sp_strerror(int code)
{
    switch (code) {
    case SP_OK: return "ok";
    case SP_E_IO: return "I/O error";
    case SP_E_FORMAT: return "malformed input";
    case SP_E_NOMEM: return "out of memory";
    case SP_E_ARG: return "invalid argument";
    case SP_E_UNSUPPORTED: return "unsupported";
    case SP_E_NODEVICE: return "no GPU";
    case SP_E_NUMERIC: return "numerical error";
    case SP_E_NOTFOUND: return "not found";
    case SP_E_NET: return "network error";
    case SP_E_DEVICE: return "GPU error";
    default: return "unknown error";
    }
}
