/* Decoders of LLM response bodies into one reply shape: OpenAI-compatible chat completions
 * (OpenAI, llama.cpp's server, Ollama's /v1, vLLM) and Anthropic Messages, plus their error
 * bodies. Input is untrusted bytes with a size; anything unexpected is a clean SP_E_FORMAT
 * naming the field, and a tool call whose arguments do not decode is kept with args_error set
 * (the session answers it with an error so the model can retry), never a crash. */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "agent_internal.h"

#define MAX_CALLS 32

void agent_call_free(sp_agent_call *c)
{
    if (!c) return;
    free(c->arguments);
    c->arguments = NULL;
}

void sp_agent_reply_free(sp_agent_reply *r)
{
    if (!r) return;
    for (int i = 0; i < r->n_calls; i++) agent_call_free(&r->calls[i]);
    free(r->calls);
    free(r->text);
    free(r->content_json);
    memset(r, 0, sizeof *r);
}

static int append_text(sp_agent_reply *r, const char *s)
{
    if (!s || !s[0]) return SP_OK;
    size_t a = r->text ? strlen(r->text) : 0, b = strlen(s);
    char *t = realloc(r->text, a + b + 2);
    if (!t) return SP_E_NOMEM;
    if (a) t[a++] = '\n';
    memcpy(t + a, s, b + 1);
    r->text = t;
    return SP_OK;
}

/* Normalizes arguments given as a JSON string (the OpenAI spec), an object (Anthropic, Ollama
 * native, some vLLM parsers) or nothing (a call without parameters) into compact JSON. */
static void set_arguments(sp_agent_call *c, const cJSON *args)
{
    if (!args || cJSON_IsNull(args)) {
        c->arguments = agent_strdup("{}");
    } else if (cJSON_IsString(args)) {
        const char *s = args->valuestring;
        size_t n = strlen(s), i = 0;
        while (i < n && (s[i] == ' ' || s[i] == '\n' || s[i] == '\t' || s[i] == '\r')) i++;
        if (i == n) {
            c->arguments = agent_strdup("{}");
            return;
        }
        sp_error e;
        cJSON *p = agent_json_parse(s, n, "arguments", &e);
        if (!p) {
            agent_clean_copy(c->args_error, sizeof c->args_error, e.msg);
            return;
        }
        if (!cJSON_IsObject(p))
            snprintf(c->args_error, sizeof c->args_error,
                     "arguments: expected a JSON object, got another JSON value");
        else
            c->arguments = cJSON_PrintUnformatted(p);
        cJSON_Delete(p);
    } else if (cJSON_IsObject(args)) {
        c->arguments = cJSON_PrintUnformatted(args);
    } else {
        snprintf(c->args_error, sizeof c->args_error,
                 "arguments: expected a JSON object or a string holding one");
    }
    if (!c->arguments && !c->args_error[0])
        snprintf(c->args_error, sizeof c->args_error, "arguments: out of memory");
}

static sp_agent_call *add_call(sp_agent_reply *r, sp_error *err)
{
    if (r->n_calls >= MAX_CALLS) {
        sp_error_set(err, SP_E_FORMAT, "more than %d tool calls in one turn", MAX_CALLS);
        return NULL;
    }
    if (!r->calls) {
        r->calls = calloc(MAX_CALLS, sizeof *r->calls);
        if (!r->calls) {
            sp_error_set(err, SP_E_NOMEM, "out of memory");
            return NULL;
        }
    }
    return &r->calls[r->n_calls++];
}

static void set_id_name(sp_agent_call *c, const cJSON *id, const cJSON *name, int index,
                        const char *prefix)
{
    if (cJSON_IsString(id) && id->valuestring[0]) {
        agent_clean_copy(c->id, sizeof c->id, id->valuestring);
    } else {
        snprintf(c->id, sizeof c->id, "%s%d", prefix, index + 1);
        c->synthesized = 1;
    }
    if (cJSON_IsString(name)) agent_clean_copy(c->name, sizeof c->name, name->valuestring);
    if (!c->name[0] && !c->args_error[0])
        snprintf(c->args_error, sizeof c->args_error, "tool call without a function name");
}

static int stop_from_openai(const char *s)
{
    if (!strcmp(s, "stop") || !s[0]) return SP_AGENT_STOP_END;
    if (!strcmp(s, "tool_calls") || !strcmp(s, "tool") || !strcmp(s, "function_call"))
        return SP_AGENT_STOP_TOOL_USE;
    if (!strcmp(s, "length")) return SP_AGENT_STOP_MAX_TOKENS;
    if (!strcmp(s, "content_filter")) return SP_AGENT_STOP_REFUSAL;
    return SP_AGENT_STOP_OTHER;
}

static int stop_from_anthropic(const char *s)
{
    if (!strcmp(s, "end_turn") || !strcmp(s, "stop_sequence")) return SP_AGENT_STOP_END;
    if (!strcmp(s, "tool_use")) return SP_AGENT_STOP_TOOL_USE;
    if (!strcmp(s, "max_tokens") || !strcmp(s, "model_context_window_exceeded"))
        return SP_AGENT_STOP_MAX_TOKENS;
    if (!strcmp(s, "refusal")) return SP_AGENT_STOP_REFUSAL;
    if (!strcmp(s, "pause_turn")) return SP_AGENT_STOP_PAUSE;
    return SP_AGENT_STOP_OTHER;
}

static long get_long(const cJSON *o, const char *k)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, k);
    return cJSON_IsNumber(v) && v->valuedouble >= 0 && v->valuedouble < 1e15 ? (long)v->valuedouble : 0;
}

/* An error object in a 200 body, or the body is not a reply at all. */
static int error_body(const char *bytes, size_t size, sp_error *err)
{
    char type[64], code[64], msg[400];
    if (sp_agent_decode_error_body(bytes, size, type, sizeof type, code, sizeof code, msg,
                                   sizeof msg) == 0)
        return sp_error_set(err, SP_E_NET, "the server answered with an error: %s%s%s%s%s%s",
                            type[0] ? type : "error", code[0] ? " (" : "", code, code[0] ? ")" : "",
                            msg[0] ? ": " : "", msg);
    return 0;
}

static int openai_message_text(sp_agent_reply *r, const cJSON *content)
{
    if (cJSON_IsString(content)) return append_text(r, content->valuestring);
    const cJSON *part, *parts = cJSON_IsArray(content) ? content : NULL;
    cJSON_ArrayForEach(part, parts) {
        const cJSON *t = cJSON_GetObjectItemCaseSensitive(part, "text");
        if (cJSON_IsString(t) && append_text(r, t->valuestring)) return SP_E_NOMEM;
    }
    return SP_OK;
}

static int openai_calls(sp_agent_reply *r, const cJSON *msg, sp_error *err)
{
    const cJSON *calls = cJSON_GetObjectItemCaseSensitive(msg, "tool_calls"), *tc;
    if (calls && !cJSON_IsArray(calls) && !cJSON_IsNull(calls))
        return sp_error_set(err, SP_E_FORMAT, "choices[0].message.tool_calls: expected an array");
    int i = 0;
    const cJSON *list = cJSON_IsArray(calls) ? calls : NULL;
    cJSON_ArrayForEach(tc, list) {
        if (!cJSON_IsObject(tc))
            return sp_error_set(err, SP_E_FORMAT, "choices[0].message.tool_calls[%d]: expected an object", i);
        sp_agent_call *c = add_call(r, err);
        if (!c) return err->code;
        /* Standard: {id, type, function: {name, arguments}}; llama.cpp's documented sample:
         * {name, arguments} without id or wrapper. */
        const cJSON *fn = cJSON_GetObjectItemCaseSensitive(tc, "function");
        const cJSON *src = cJSON_IsObject(fn) ? fn : tc;
        set_arguments(c, cJSON_GetObjectItemCaseSensitive(src, "arguments"));
        set_id_name(c, cJSON_GetObjectItemCaseSensitive(tc, "id"),
                    cJSON_GetObjectItemCaseSensitive(src, "name"), i, "call_");
        i++;
    }
    /* The deprecated single function_call. */
    const cJSON *fc = cJSON_GetObjectItemCaseSensitive(msg, "function_call");
    if (cJSON_IsObject(fc) && r->n_calls == 0) {
        sp_agent_call *c = add_call(r, err);
        if (!c) return err->code;
        set_arguments(c, cJSON_GetObjectItemCaseSensitive(fc, "arguments"));
        set_id_name(c, NULL, cJSON_GetObjectItemCaseSensitive(fc, "name"), 0, "call_");
    }
    return SP_OK;
}

int sp_agent_decode_openai(const char *bytes, size_t size, sp_agent_reply *out, sp_error *err)
{
    sp_error local;
    if (!err) err = &local;
    memset(out, 0, sizeof *out);
    cJSON *j = agent_json_parse(bytes, size, "chat completion", err);
    if (!j) return err->code;
    int rc = SP_OK;
    const cJSON *choices = cJSON_GetObjectItemCaseSensitive(j, "choices");
    if (!cJSON_IsObject(j)) {
        rc = sp_error_set(err, SP_E_FORMAT, "chat completion: expected a JSON object");
    } else if (!cJSON_IsArray(choices)) {
        rc = error_body(bytes, size, err);
        if (!rc) rc = sp_error_set(err, SP_E_FORMAT, "chat completion: no 'choices' array");
    } else if (cJSON_GetArraySize(choices) == 0) {
        rc = sp_error_set(err, SP_E_FORMAT, "chat completion: 'choices' is empty");
    } else {
        const cJSON *ch = cJSON_GetArrayItem(choices, 0);
        const cJSON *msg = cJSON_GetObjectItemCaseSensitive(ch, "message");
        const cJSON *fr = cJSON_GetObjectItemCaseSensitive(ch, "finish_reason");
        if (!cJSON_IsObject(msg)) {
            rc = sp_error_set(err, SP_E_FORMAT, "choices[0].message: missing or not an object");
        } else {
            agent_clean_copy(out->stop_raw, sizeof out->stop_raw, cJSON_IsString(fr) ? fr->valuestring : "");
            out->stop = stop_from_openai(out->stop_raw);
            rc = openai_message_text(out, cJSON_GetObjectItemCaseSensitive(msg, "content"));
            if (rc) sp_error_set(err, rc, "out of memory");
            else rc = openai_calls(out, msg, err);
            if (!rc && out->n_calls > 0) out->stop = SP_AGENT_STOP_TOOL_USE;
        }
        const cJSON *u = cJSON_GetObjectItemCaseSensitive(j, "usage");
        out->input_tokens = get_long(u, "prompt_tokens");
        out->output_tokens = get_long(u, "completion_tokens");
    }
    cJSON_Delete(j);
    if (rc) sp_agent_reply_free(out);
    return rc;
}

/* A tool_use block: id, name, input (an object; a string holding one is tolerated). The block is
 * rewritten in place so the echo carries the id we use and an object input. */
static int anthropic_tool_use(sp_agent_reply *r, cJSON *block, int index, sp_error *err)
{
    sp_agent_call *c = add_call(r, err);
    if (!c) return err->code;
    set_arguments(c, cJSON_GetObjectItemCaseSensitive(block, "input"));
    set_id_name(c, cJSON_GetObjectItemCaseSensitive(block, "id"),
                cJSON_GetObjectItemCaseSensitive(block, "name"), index, "toolu_semsplat_");
    if (c->synthesized) {
        cJSON_DeleteItemFromObjectCaseSensitive(block, "id");
        cJSON_AddStringToObject(block, "id", c->id);
    }
    const cJSON *in = cJSON_GetObjectItemCaseSensitive(block, "input");
    if (!cJSON_IsObject(in)) {
        cJSON *obj = c->arguments ? cJSON_Parse(c->arguments) : NULL;
        cJSON_DeleteItemFromObjectCaseSensitive(block, "input");
        cJSON_AddItemToObject(block, "input", obj ? obj : cJSON_CreateObject());
    }
    return SP_OK;
}

int sp_agent_decode_anthropic(const char *bytes, size_t size, sp_agent_reply *out, sp_error *err)
{
    sp_error local;
    if (!err) err = &local;
    memset(out, 0, sizeof *out);
    cJSON *j = agent_json_parse(bytes, size, "message", err);
    if (!j) return err->code;
    int rc = SP_OK;
    cJSON *content = cJSON_GetObjectItemCaseSensitive(j, "content");
    const cJSON *type = cJSON_GetObjectItemCaseSensitive(j, "type");
    if (!cJSON_IsObject(j)) {
        rc = sp_error_set(err, SP_E_FORMAT, "message: expected a JSON object");
    } else if (cJSON_IsString(type) && !strcmp(type->valuestring, "error")) {
        rc = error_body(bytes, size, err);
        if (!rc) rc = sp_error_set(err, SP_E_NET, "the server answered with an error");
    } else if (!cJSON_IsArray(content)) {
        rc = sp_error_set(err, SP_E_FORMAT, "message: no 'content' array");
    } else {
        const cJSON *sr = cJSON_GetObjectItemCaseSensitive(j, "stop_reason");
        agent_clean_copy(out->stop_raw, sizeof out->stop_raw, cJSON_IsString(sr) ? sr->valuestring : "");
        out->stop = stop_from_anthropic(out->stop_raw);
        int i = 0, n_tool = 0;
        cJSON *b;
        cJSON_ArrayForEach(b, content) {
            const cJSON *bt = cJSON_GetObjectItemCaseSensitive(b, "type");
            if (!cJSON_IsObject(b) || !cJSON_IsString(bt)) {
                rc = sp_error_set(err, SP_E_FORMAT, "content[%d]: expected a block with a 'type'", i);
                break;
            }
            if (!strcmp(bt->valuestring, "text")) {
                const cJSON *t = cJSON_GetObjectItemCaseSensitive(b, "text");
                if (cJSON_IsString(t) && append_text(out, t->valuestring)) {
                    rc = sp_error_set(err, SP_E_NOMEM, "out of memory");
                    break;
                }
            } else if (!strcmp(bt->valuestring, "tool_use")) {
                rc = anthropic_tool_use(out, b, n_tool++, err);
                if (rc) break;
            }
            i++;
        }
        if (!rc && out->n_calls > 0) out->stop = SP_AGENT_STOP_TOOL_USE;
        if (!rc && !(out->content_json = cJSON_PrintUnformatted(content)))
            rc = sp_error_set(err, SP_E_NOMEM, "out of memory");
        const cJSON *u = cJSON_GetObjectItemCaseSensitive(j, "usage");
        out->input_tokens = get_long(u, "input_tokens");
        out->output_tokens = get_long(u, "output_tokens");
    }
    cJSON_Delete(j);
    if (rc) sp_agent_reply_free(out);
    return rc;
}

static void copy_field(const cJSON *o, const char *k, char *out, size_t cap)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, k);
    if (cJSON_IsString(v)) agent_clean_copy(out, cap, v->valuestring);
    else if (cJSON_IsNumber(v)) snprintf(out, cap, "%.0f", v->valuedouble);
}

int sp_agent_decode_error_body(const char *bytes, size_t size, char *type, size_t type_cap,
                               char *code, size_t code_cap, char *message, size_t message_cap)
{
    if (type_cap) type[0] = 0;
    if (code_cap) code[0] = 0;
    if (message_cap) message[0] = 0;
    cJSON *j = agent_json_parse(bytes, size, "error body", NULL);
    const cJSON *e = cJSON_GetObjectItemCaseSensitive(j, "error");
    int rc = SP_OK;
    if (cJSON_IsString(e)) { /* Ollama, some proxies: {"error": "text"} */
        agent_clean_copy(message, message_cap, e->valuestring);
    } else if (cJSON_IsObject(e)) {
        copy_field(e, "type", type, type_cap);
        copy_field(e, "code", code, code_cap);
        copy_field(e, "message", message, message_cap);
        /* Anthropic's spend limit: error.details.error_code. */
        const cJSON *d = cJSON_GetObjectItemCaseSensitive(e, "details");
        if (code_cap && !code[0]) copy_field(d, "error_code", code, code_cap);
    } else {
        rc = SP_E_FORMAT;
    }
    cJSON_Delete(j);
    return rc;
}
