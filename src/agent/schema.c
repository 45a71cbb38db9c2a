/* A JSON Schema validator for the subset our tool schemas use (type, properties, required,
 * additionalProperties: false, enum, minimum/maximum, minLength/maxLength, minItems/maxItems,
 * items). It checks what a model sends before any tool runs; the messages name the argument and
 * the rule so the model can correct itself. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "agent_internal.h"

static const char *json_type_name(const cJSON *v)
{
    if (cJSON_IsObject(v)) return "object";
    if (cJSON_IsArray(v)) return "array";
    if (cJSON_IsString(v)) return "string";
    if (cJSON_IsBool(v)) return "boolean";
    if (cJSON_IsNull(v)) return "null";
    if (cJSON_IsNumber(v)) return "number";
    return "invalid";
}

static int type_matches(const char *t, const cJSON *v)
{
    if (!strcmp(t, "object")) return cJSON_IsObject(v);
    if (!strcmp(t, "array")) return cJSON_IsArray(v);
    if (!strcmp(t, "string")) return cJSON_IsString(v);
    if (!strcmp(t, "boolean")) return cJSON_IsBool(v);
    if (!strcmp(t, "null")) return cJSON_IsNull(v);
    if (!strcmp(t, "number")) return cJSON_IsNumber(v) && isfinite(v->valuedouble);
    if (!strcmp(t, "integer"))
        return cJSON_IsNumber(v) && isfinite(v->valuedouble) &&
               v->valuedouble == floor(v->valuedouble) && fabs(v->valuedouble) < 9007199254740992.0;
    return 0;
}

/* "start[1]" or "goal" or "the arguments" for the top level. */
static const char *where(const char *path) { return path[0] ? path : "the arguments"; }

static int check_type(const cJSON *schema, const cJSON *v, const char *path, sp_error *err)
{
    const cJSON *t = cJSON_GetObjectItemCaseSensitive(schema, "type");
    if (!t) return SP_OK;
    char want[96] = "";
    if (cJSON_IsString(t)) {
        if (type_matches(t->valuestring, v)) return SP_OK;
        snprintf(want, sizeof want, "%s", t->valuestring);
    } else if (cJSON_IsArray(t)) {
        const cJSON *e;
        cJSON_ArrayForEach(e, t) {
            if (cJSON_IsString(e) && type_matches(e->valuestring, v)) return SP_OK;
            if (cJSON_IsString(e))
                snprintf(want + strlen(want), sizeof want - strlen(want), "%s%s",
                         want[0] ? " or " : "", e->valuestring);
        }
    } else {
        return SP_OK;
    }
    return sp_error_set(err, SP_E_ARG, "%s: expected %s %s, got %s", where(path),
                        (want[0] == 'a' || want[0] == 'i' || want[0] == 'o') ? "an" : "a", want,
                        json_type_name(v));
}

static int check_enum(const cJSON *schema, const cJSON *v, const char *path, sp_error *err)
{
    const cJSON *en = cJSON_GetObjectItemCaseSensitive(schema, "enum"), *e;
    if (!cJSON_IsArray(en)) return SP_OK;
    char list[256] = "";
    cJSON_ArrayForEach(e, en) {
        if (cJSON_Compare(e, v, 1)) return SP_OK;
        if (cJSON_IsString(e))
            snprintf(list + strlen(list), sizeof list - strlen(list), "%s'%s'", list[0] ? ", " : "",
                     e->valuestring);
    }
    return sp_error_set(err, SP_E_ARG, "%s: must be one of %s", where(path), list);
}

static int check_number(const cJSON *schema, const cJSON *v, const char *path, sp_error *err)
{
    if (!cJSON_IsNumber(v)) return SP_OK;
    const cJSON *mn = cJSON_GetObjectItemCaseSensitive(schema, "minimum");
    const cJSON *mx = cJSON_GetObjectItemCaseSensitive(schema, "maximum");
    if (cJSON_IsNumber(mn) && v->valuedouble < mn->valuedouble)
        return sp_error_set(err, SP_E_ARG, "%s: %g is below the minimum %g", where(path),
                            v->valuedouble, mn->valuedouble);
    if (cJSON_IsNumber(mx) && v->valuedouble > mx->valuedouble)
        return sp_error_set(err, SP_E_ARG, "%s: %g is above the maximum %g", where(path),
                            v->valuedouble, mx->valuedouble);
    return SP_OK;
}

static size_t utf8_chars(const char *s)
{
    size_t n = 0;
    for (; *s; s++) n += ((unsigned char)*s & 0xC0) != 0x80;
    return n;
}

static int check_string(const cJSON *schema, const cJSON *v, const char *path, sp_error *err)
{
    if (!cJSON_IsString(v)) return SP_OK;
    size_t n = utf8_chars(v->valuestring);
    const cJSON *mn = cJSON_GetObjectItemCaseSensitive(schema, "minLength");
    const cJSON *mx = cJSON_GetObjectItemCaseSensitive(schema, "maxLength");
    if (cJSON_IsNumber(mn) && (double)n < mn->valuedouble)
        return sp_error_set(err, SP_E_ARG, "%s: must not be empty%s", where(path),
                            mn->valuedouble > 1 ? " or that short" : "");
    if (cJSON_IsNumber(mx) && (double)n > mx->valuedouble)
        return sp_error_set(err, SP_E_ARG, "%s: %zu characters, at most %g allowed", where(path), n,
                            mx->valuedouble);
    return SP_OK;
}

static int check_array(const cJSON *schema, const cJSON *v, const char *path, sp_error *err)
{
    if (!cJSON_IsArray(v)) return SP_OK;
    int n = cJSON_GetArraySize(v);
    const cJSON *mn = cJSON_GetObjectItemCaseSensitive(schema, "minItems");
    const cJSON *mx = cJSON_GetObjectItemCaseSensitive(schema, "maxItems");
    if (cJSON_IsNumber(mn) && n < mn->valuedouble)
        return sp_error_set(err, SP_E_ARG, "%s: %d items, at least %g needed", where(path), n,
                            mn->valuedouble);
    if (cJSON_IsNumber(mx) && n > mx->valuedouble)
        return sp_error_set(err, SP_E_ARG, "%s: %d items, at most %g allowed", where(path), n,
                            mx->valuedouble);
    const cJSON *items = cJSON_GetObjectItemCaseSensitive(schema, "items");
    if (!cJSON_IsObject(items)) return SP_OK;
    int i = 0;
    const cJSON *e;
    cJSON_ArrayForEach(e, v) {
        char sub[160];
        snprintf(sub, sizeof sub, "%s[%d]", where(path), i++);
        int rc = agent_schema_check(items, e, sub, err);
        if (rc) return rc;
    }
    return SP_OK;
}

/* The names a tool takes, for "unexpected argument" messages. */
static void property_list(const cJSON *props, char *out, size_t cap)
{
    out[0] = 0;
    const cJSON *p;
    cJSON_ArrayForEach(p, props)
        snprintf(out + strlen(out), cap - strlen(out), "%s%s", out[0] ? ", " : "", p->string);
    if (!out[0]) snprintf(out, cap, "none");
}

static int check_object(const cJSON *schema, const cJSON *v, const char *path, sp_error *err)
{
    if (!cJSON_IsObject(v)) return SP_OK;
    const cJSON *props = cJSON_GetObjectItemCaseSensitive(schema, "properties");
    const cJSON *addl = cJSON_GetObjectItemCaseSensitive(schema, "additionalProperties");
    int closed = cJSON_IsFalse(addl);
    const cJSON *e;
    if (cJSON_GetArraySize(v) > 64) /* also bounds the duplicate check below */
        return sp_error_set(err, SP_E_ARG, "%s: %d members, at most 64 allowed", where(path),
                            cJSON_GetArraySize(v));
    cJSON_ArrayForEach(e, v) {
        char name[64];
        agent_clean_copy(name, sizeof name, e->string ? e->string : "");
        for (const cJSON *f = v->child; f != e; f = f->next)
            if (f->string && e->string && !strcmp(f->string, e->string))
                return sp_error_set(err, SP_E_ARG, "argument '%s' is given twice", name);
        const cJSON *ps = e->string ? cJSON_GetObjectItemCaseSensitive(props, e->string) : NULL;
        char sub[160];
        snprintf(sub, sizeof sub, "%s%s%s", path, path[0] ? "." : "", name);
        if (ps) {
            int rc = agent_schema_check(ps, e, sub, err);
            if (rc) return rc;
        } else if (closed) {
            char list[256];
            property_list(props, list, sizeof list);
            return sp_error_set(err, SP_E_ARG, "unexpected argument '%s' (this tool takes: %s)", sub,
                                list);
        }
    }
    const cJSON *req = cJSON_GetObjectItemCaseSensitive(schema, "required");
    cJSON_ArrayForEach(e, req) {
        if (cJSON_IsString(e) && !cJSON_GetObjectItemCaseSensitive(v, e->valuestring))
            return sp_error_set(err, SP_E_ARG, "missing required argument '%s%s%s'", path,
                                path[0] ? "." : "", e->valuestring);
    }
    return SP_OK;
}

int agent_schema_check(const cJSON *schema, const cJSON *value, const char *path, sp_error *err)
{
    int rc = check_type(schema, value, path, err);
    if (!rc) rc = check_enum(schema, value, path, err);
    if (!rc) rc = check_number(schema, value, path, err);
    if (!rc) rc = check_string(schema, value, path, err);
    if (!rc) rc = check_array(schema, value, path, err);
    if (!rc) rc = check_object(schema, value, path, err);
    return rc;
}

int sp_agent_validate_args(int tool, const char *bytes, size_t size, sp_error *err)
{
    sp_error local;
    if (!err) err = &local;
    const sp_agent_tool *t = sp_agent_tool_get(tool);
    if (!t) return sp_error_set(err, SP_E_ARG, "unknown tool id %d", tool);
    cJSON *schema = agent_tool_schema_json(tool, err);
    if (!schema) return err->code;
    char what[96];
    snprintf(what, sizeof what, "%s arguments", t->name);
    cJSON *v = agent_json_parse(bytes, size, what, err);
    int rc = v ? agent_schema_check(schema, v, "", err) : err->code;
    if (rc == SP_E_ARG) sp_error_prefix(err, "%s: ", t->name);
    cJSON_Delete(v);
    cJSON_Delete(schema);
    return rc;
}
