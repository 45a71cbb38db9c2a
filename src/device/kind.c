/* Device names as users type them ("cpu", "cuda", "auto"): the one parser every command and
 * binding uses, so an unknown name is an error naming it, never a silent fallback. */
#include <string.h>

#include "semsplat/device.h"

static const char *const kind_names[] = {"cpu", "cuda", "auto"};

int sp_device_kind_parse(const char *s, sp_device_kind *out, sp_error *err)
{
    if (!s) return sp_error_set(err, SP_E_ARG, "device: no name given (expected cpu, cuda or auto)");
    for (int k = 0; k < 3; k++)
        if (!strcmp(s, kind_names[k])) {
            *out = (sp_device_kind)k;
            return 0;
        }
    return sp_error_set(err, SP_E_ARG, "device '%s' is not one of cpu, cuda, auto", s);
}

const char *sp_device_kind_name(sp_device_kind kind)
{
    return (unsigned)kind < 3 ? kind_names[kind] : "unknown";
}
