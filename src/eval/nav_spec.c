/* Users' own 5.3 commands: {"navigation": [{"text": "...", "targets": ["class", ...]}]} in the
 * eval queries file, so that a world other than the house is driven with commands that name its
 * own objects (the built-in ten name the house's). */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/eval.h"
#include "semsplat/io.h"

void sp_eval_free_nav_commands(char **cmds, int n)
{
    for (int i = 0; cmds && i < n; i++) free(cmds[i]);
    free(cmds);
}

/* One entry as "text|class,class" (nav_success's internal form); names with ',' or '|' refused. */
static int read_command(const cJSON *e, const char *path, int idx, char **out, sp_error *err)
{
    const cJSON *t = cJSON_GetObjectItemCaseSensitive(e, "text"), *tg = cJSON_GetObjectItemCaseSensitive(e, "targets");
    if (!cJSON_IsString(t) || !t->valuestring[0] || strlen(t->valuestring) > 200 || strchr(t->valuestring, '|'))
        return sp_error_set(err, SP_E_FORMAT, "%s: navigation entry %d: \"text\" must be a command of 1 to 200 "
                            "characters without '|'", path, idx);
    int nt = cJSON_IsArray(tg) ? cJSON_GetArraySize(tg) : -1;
    if (nt < 1 || nt > 8)
        return sp_error_set(err, SP_E_FORMAT, "%s: navigation entry %d: \"targets\" must be an array of 1 to 8 "
                            "class names", path, idx);
    char buf[800];
    int len = snprintf(buf, sizeof buf, "%s|", t->valuestring);
    const cJSON *c;
    int k = 0;
    cJSON_ArrayForEach(c, tg)
    {
        if (!cJSON_IsString(c) || !c->valuestring[0] || strlen(c->valuestring) >= 64 || strpbrk(c->valuestring, ",|"))
            return sp_error_set(err, SP_E_FORMAT, "%s: navigation entry %d: target %d must be a class name of 1 to "
                                "63 characters without ',' or '|'", path, idx, k);
        len += snprintf(buf + len, sizeof buf - (size_t)len, "%s%s", k++ ? "," : "", c->valuestring);
    }
    if (len - (int)strlen(t->valuestring) - 1 >= 64) /* sp_nav_success_row.expect holds 63 characters */
        return sp_error_set(err, SP_E_FORMAT, "%s: navigation entry %d: the class names are longer than 63 characters together",
                            path, idx);
    if (!(*out = strdup(buf))) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    return 0;
}

int sp_eval_read_nav_commands(const char *path, char ***cmds, int *n, sp_error *err)
{
    *cmds = NULL;
    *n = 0;
    cJSON *root = NULL;
    int rc = sp_json_read_file(path, &root, err);
    if (rc) return rc;
    const cJSON *arr = cJSON_GetObjectItemCaseSensitive(root, "navigation");
    int count = arr ? (cJSON_IsArray(arr) ? cJSON_GetArraySize(arr) : -1) : 0;
    if (count < 0 || count > 16)
        rc = sp_error_set(err, SP_E_FORMAT, "%s: \"navigation\" must be an array of at most 16 commands", path);
    char **c = rc || !count ? NULL : calloc((size_t)count, sizeof *c);
    if (!rc && count && !c) rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    int i = 0;
    const cJSON *e;
    if (!rc && count) cJSON_ArrayForEach(e, arr)
    {
        if ((rc = read_command(e, path, i, &c[i], err))) break;
        i++;
    }
    cJSON_Delete(root);
    if (rc) {
        sp_eval_free_nav_commands(c, i);
        return rc;
    }
    *cmds = c;
    *n = count;
    return 0;
}
