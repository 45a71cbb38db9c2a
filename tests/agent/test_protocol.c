/* Both LLM clients against a scripted HTTP server on 127.0.0.1 that replays responses in the
 * APIs' documented formats: multi-step and parallel tool calls, the local servers' quirks
 * (llama.cpp's calls without ids or `function` wrapper, arguments as an object, finish_reason
 * "tool" / "stop"), 429 with Retry-After, 500, 529, 4xx that must not be retried, a timeout, a
 * truncated body, a refused connection, schema-violating arguments, a model that never stops.
 * The agent completes or fails with a clear message; every wait is bounded; a proxy in the
 * environment is bypassed for loopback, so no request leaves it. */
/* The scripts leave trailing fields of ts_response zero. */
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

#include <cjson/cJSON.h>

#include "fake_world.h"
#include "http_server.h"
#include "test.h"

#define OAI 1
#define ANT 2

/* ---- replies in the two wire formats ---- */

/* calls: "name", "args json" pairs; ids "call_<i>" unless no_ids. */
static char *oai_reply(const char *content, int n, const char *const *calls, const char *finish)
{
    cJSON *r = cJSON_CreateObject(), *choices = cJSON_AddArrayToObject(r, "choices"), *ch = cJSON_CreateObject();
    cJSON_AddStringToObject(r, "id", "chatcmpl-test");
    cJSON_AddStringToObject(r, "object", "chat.completion");
    cJSON_AddStringToObject(r, "model", "test-model");
    cJSON *m = cJSON_AddObjectToObject(ch, "message");
    cJSON_AddStringToObject(m, "role", "assistant");
    if (content) cJSON_AddStringToObject(m, "content", content);
    else cJSON_AddNullToObject(m, "content");
    if (n) {
        cJSON *tc = cJSON_AddArrayToObject(m, "tool_calls");
        for (int i = 0; i < n; i++) {
            cJSON *c = cJSON_CreateObject(), *f = cJSON_CreateObject();
            char id[32];
            snprintf(id, sizeof id, "call_%c%d", 'a' + i, i + 1);
            cJSON_AddStringToObject(c, "id", id);
            cJSON_AddStringToObject(c, "type", "function");
            cJSON_AddStringToObject(f, "name", calls[2 * i]);
            cJSON_AddStringToObject(f, "arguments", calls[2 * i + 1]);
            cJSON_AddItemToObject(c, "function", f);
            cJSON_AddItemToArray(tc, c);
        }
    }
    cJSON_AddStringToObject(ch, "finish_reason", finish);
    cJSON_AddNumberToObject(ch, "index", 0);
    cJSON_AddItemToArray(choices, ch);
    cJSON *u = cJSON_AddObjectToObject(r, "usage");
    cJSON_AddNumberToObject(u, "prompt_tokens", 100);
    cJSON_AddNumberToObject(u, "completion_tokens", 20);
    char *s = cJSON_PrintUnformatted(r);
    cJSON_Delete(r);
    return s;
}

static char *ant_reply(const char *text, int n, const char *const *calls, const char *stop)
{
    cJSON *r = cJSON_CreateObject(), *content;
    cJSON_AddStringToObject(r, "id", "msg_test");
    cJSON_AddStringToObject(r, "type", "message");
    cJSON_AddStringToObject(r, "role", "assistant");
    cJSON_AddStringToObject(r, "model", "test-model");
    content = cJSON_AddArrayToObject(r, "content");
    if (text) {
        cJSON *b = cJSON_CreateObject();
        cJSON_AddStringToObject(b, "type", "text");
        cJSON_AddStringToObject(b, "text", text);
        cJSON_AddItemToArray(content, b);
    }
    for (int i = 0; i < n; i++) {
        cJSON *b = cJSON_CreateObject();
        char id[32];
        snprintf(id, sizeof id, "toolu_%02d", i + 1);
        cJSON_AddStringToObject(b, "type", "tool_use");
        cJSON_AddStringToObject(b, "id", id);
        cJSON_AddStringToObject(b, "name", calls[2 * i]);
        cJSON *in = cJSON_Parse(calls[2 * i + 1]);
        cJSON_AddItemToObject(b, "input", in ? in : cJSON_CreateString(calls[2 * i + 1]));
        cJSON_AddItemToArray(content, b);
    }
    cJSON_AddStringToObject(r, "stop_reason", stop);
    cJSON_AddNullToObject(r, "stop_sequence");
    cJSON *u = cJSON_AddObjectToObject(r, "usage");
    cJSON_AddNumberToObject(u, "input_tokens", 100);
    cJSON_AddNumberToObject(u, "output_tokens", 20);
    char *s = cJSON_PrintUnformatted(r);
    cJSON_Delete(r);
    return s;
}

static char *reply(int dialect, const char *text, int n, const char *const *calls)
{
    if (dialect == OAI) return oai_reply(n ? NULL : text, n, calls, n ? "tool_calls" : "stop");
    return ant_reply(text, n, calls, n ? "tool_use" : "end_turn");
}

/* The data of the last result of `tool` in a request body (either wire format), or NULL. */
static cJSON *tool_data(const char *req, const char *tool)
{
    cJSON *j = cJSON_Parse(req), *found = NULL;
    const cJSON *m;
    cJSON_ArrayForEach(m, cJSON_GetObjectItemCaseSensitive(j, "messages")) {
        const cJSON *c = cJSON_GetObjectItemCaseSensitive(m, "content"), *b;
        const cJSON *blocks = cJSON_IsArray(c) ? c : NULL;
        const char *texts[16];
        int n = 0;
        if (cJSON_IsString(c)) texts[n++] = c->valuestring;
        cJSON_ArrayForEach(b, blocks) {
            const cJSON *t = cJSON_GetObjectItemCaseSensitive(b, "content");
            if (cJSON_IsString(t) && n < 16) texts[n++] = t->valuestring;
        }
        for (int i = 0; i < n; i++) {
            cJSON *r = cJSON_Parse(texts[i]);
            const cJSON *name = cJSON_GetObjectItemCaseSensitive(r, "tool");
            if (cJSON_IsString(name) && !strcmp(name->valuestring, tool)) {
                cJSON_Delete(found);
                found = cJSON_DetachItemFromObjectCaseSensitive(r, "data");
            }
            cJSON_Delete(r);
        }
    }
    cJSON_Delete(j);
    return found;
}

static int g_dialect;

/* plan_path from the pose and the object position the tools returned earlier. */
static char *respond_plan(const char *req, void *u)
{
    cJSON *pose = tool_data(req, "get_robot_pose"), *q = tool_data(req, "query_object_location");
    if (!pose || !q) {
        cJSON_Delete(pose);
        cJSON_Delete(q);
        return reply(g_dialect, "the request lacked the tool results", 0, NULL);
    }
    const cJSON *p = cJSON_GetObjectItemCaseSensitive(q, "position");
    char args[256];
    snprintf(args, sizeof args, "{\"start\":[%g,%g,%g,%g],\"goal\":[%g,%g,%g]}",
             cJSON_GetObjectItemCaseSensitive(pose, "x")->valuedouble, cJSON_GetObjectItemCaseSensitive(pose, "y")->valuedouble,
             cJSON_GetObjectItemCaseSensitive(pose, "z")->valuedouble, cJSON_GetObjectItemCaseSensitive(pose, "yaw")->valuedouble,
             cJSON_GetArrayItem(p, 0)->valuedouble, cJSON_GetArrayItem(p, 1)->valuedouble, cJSON_GetArrayItem(p, 2)->valuedouble);
    cJSON_Delete(pose);
    cJSON_Delete(q);
    const char *calls[] = {"plan_path", args};
    return reply(g_dialect, NULL, 1, calls);
}

static char *respond_goal(const char *req, void *u)
{
    cJSON *pl = tool_data(req, "plan_path");
    if (!pl) return reply(g_dialect, "no plan in the request", 0, NULL);
    const cJSON *e = cJSON_GetObjectItemCaseSensitive(pl, "end");
    char args[256];
    snprintf(args, sizeof args, "{\"x\":%.4f,\"y\":%.4f,\"yaw\":%.4f,\"plan_id\":\"%s\"}",
             cJSON_GetArrayItem(e, 0)->valuedouble, cJSON_GetArrayItem(e, 1)->valuedouble,
             cJSON_GetArrayItem(e, 3)->valuedouble, cJSON_GetObjectItemCaseSensitive(pl, "plan_id")->valuestring);
    cJSON_Delete(pl);
    const char *calls[] = {"send_nav2_goal", args};
    return reply(g_dialect, NULL, 1, calls);
}

static char *respond_query(const char *req, void *u)
{
    const char *calls[] = {"query_object_location", "{\"object_name\":\"refrigerator\"}"};
    return reply(g_dialect, "I'll find it.", 1, calls);
}
static char *respond_pose(const char *req, void *u)
{
    const char *calls[] = {"get_robot_pose", "{}"};
    return reply(g_dialect, NULL, 1, calls);
}
static char *respond_done(const char *req, void *u)
{
    cJSON *g = tool_data(req, "send_nav2_goal");
    const cJSON *st = cJSON_GetObjectItemCaseSensitive(g, "status");
    char text[128];
    snprintf(text, sizeof text, "Done: the goal %s.", cJSON_IsString(st) ? st->valuestring : "was not sent");
    cJSON_Delete(g);
    return reply(g_dialect, text, 0, NULL);
}
static char *respond_text(const char *req, void *u) { return reply(g_dialect, "All done.", 0, NULL); }

/* ---- the session under test ---- */

typedef struct run {
    test_server srv;
    sp_agent_session *s;
    sp_agent_answer a;
    sp_error err;
    int rc;
    double seconds;
} run;

static void start(run *r, int dialect, const ts_response *script, int n, int max_retries, double timeout_s,
                  int base_in_env)
{
    memset(r, 0, sizeof *r);
    g_dialect = dialect;
    CHECK(ts_start(&r->srv, script, n, NULL) == 0);
    char url[128];
    snprintf(url, sizeof url, dialect == OAI ? "http://127.0.0.1:%d/v1" : "http://127.0.0.1:%d", r->srv.port);
    sp_agent_config cfg = sp_agent_config_default();
    cfg.brain = dialect == OAI ? SP_AGENT_BRAIN_OPENAI : SP_AGENT_BRAIN_ANTHROPIC;
    if (base_in_env) setenv(dialect == OAI ? "OPENAI_BASE_URL" : "ANTHROPIC_BASE_URL", url, 1);
    else cfg.llm.base_url = url;
    cfg.llm.model = "test-model";
    cfg.llm.max_retries = max_retries;
    cfg.llm.retry_base_s = 0.01;
    cfg.llm.retry_max_s = 5;
    cfg.llm.timeout_s = timeout_s;
    cfg.llm.connect_timeout_s = 1;
    cfg.llm.max_steps = 6;
    cfg.out_dir = test_tmpdir(dialect == OAI ? "protocol_openai" : "protocol_anthropic");
    sp_agent_offline_opts o = sp_agent_offline_opts_default();
    o.start.x = 3.0, o.start.y = 1.8;
    sp_agent_robot robot;
    CHECK_OK(sp_agent_robot_offline(&robot, &o, &r->err), &r->err);
    CHECK_OK(agent_session_open_world(&r->s, &cfg, fw_world(NULL), robot, &r->err), &r->err);
}

static void ask(run *r, const char *text)
{
    double t0 = sp_time_now();
    sp_agent_answer_free(&r->a);
    sp_error_clear(&r->err);
    r->rc = r->s ? sp_agent_session_ask(r->s, text, &r->a, &r->err) : -1;
    r->seconds = sp_time_now() - t0;
}

static void finish(run *r)
{
    sp_agent_answer_free(&r->a);
    sp_agent_session_close(r->s);
    ts_stop(&r->srv);
    unsetenv("OPENAI_BASE_URL");
    unsetenv("ANTHROPIC_BASE_URL");
    unsetenv("OPENAI_API_KEY");
    unsetenv("ANTHROPIC_API_KEY");
}

static const char *trace_tool(const run *r, int i) { return i < r->a.n_trace ? r->a.trace[i].tool : ""; }

static cJSON *req_json(const run *r, int i) { return i < r->srv.n_req ? cJSON_Parse(r->srv.req[i].body) : NULL; }

/* ---- multi-step, both APIs ---- */

static const ts_response go_script[] = {
    {200, NULL, NULL, respond_query}, {200, NULL, NULL, respond_pose}, {200, NULL, NULL, respond_plan},
    {200, NULL, NULL, respond_goal},  {200, NULL, NULL, respond_done},
};

static void check_go(run *r)
{
    CHECK_MSG(r->rc == 0, "%s", r->err.msg);
    CHECK(r->a.n_trace == 4);
    CHECK(!strcmp(trace_tool(r, 3), "send_nav2_goal"));
    CHECK_MSG(r->a.text && strstr(r->a.text, "Done: the goal succeeded"), "%s", r->a.text ? r->a.text : "");
    CHECK(r->srv.n_req == 5);
    for (int i = 0; i < r->a.n_trace; i++) CHECK_MSG(!r->a.trace[i].is_error, "%s", r->a.trace[i].result);
}

static void test_openai_multistep(void)
{
    run r;
    setenv("OPENAI_API_KEY", "sk-test-SECRET-123", 1);
    start(&r, OAI, go_script, 5, 0, 5, 1);
    ask(&r, "go to the refrigerator");
    check_go(&r);
    char h[256];
    CHECK(!strcmp(ts_header(&r.srv.req[0], "Authorization", h, sizeof h), "Bearer sk-test-SECRET-123"));
    CHECK(!strncmp(r.srv.req[0].head, "POST /v1/chat/completions ", 26));
    cJSON *b0 = req_json(&r, 0), *b1 = req_json(&r, 1);
    CHECK(!strcmp(cJSON_GetObjectItemCaseSensitive(b0, "model")->valuestring, "test-model"));
    CHECK(!strcmp(cJSON_GetObjectItemCaseSensitive(b0, "tool_choice")->valuestring, "auto"));
    CHECK(cJSON_GetArraySize(cJSON_GetObjectItemCaseSensitive(b0, "tools")) == SP_AGENT_N_TOOLS);
    CHECK(!cJSON_GetObjectItemCaseSensitive(b0, "temperature") && !cJSON_GetObjectItemCaseSensitive(b0, "top_p"));
    const cJSON *m = cJSON_GetObjectItemCaseSensitive(b1, "messages");
    CHECK(cJSON_GetArraySize(m) == 4); /* system, user, assistant with tool_calls, tool */
    const cJSON *as = cJSON_GetArrayItem(m, 2), *tm = cJSON_GetArrayItem(m, 3);
    const cJSON *tc = cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(as, "tool_calls"), 0);
    CHECK(cJSON_IsString(cJSON_GetObjectItemCaseSensitive(cJSON_GetObjectItemCaseSensitive(tc, "function"), "arguments")));
    CHECK(!strcmp(cJSON_GetObjectItemCaseSensitive(tm, "role")->valuestring, "tool"));
    CHECK(!strcmp(cJSON_GetObjectItemCaseSensitive(tm, "tool_call_id")->valuestring, "call_a1"));
    /* the key is in the header only: not in the answer written to disk */
    char *file = NULL;
    size_t size;
    sp_error e;
    CHECK(sp_read_file(r.a.json_path, &file, &size, &e) == 0 && !strstr(file, "SECRET"));
    free(file);
    cJSON_Delete(b0);
    cJSON_Delete(b1);
    finish(&r);
}

static void test_anthropic_multistep(void)
{
    run r;
    setenv("ANTHROPIC_API_KEY", "sk-ant-SECRET-456", 1);
    start(&r, ANT, go_script, 5, 0, 5, 1);
    ask(&r, "go to the refrigerator");
    check_go(&r);
    char h[256];
    CHECK(!strncmp(r.srv.req[0].head, "POST /v1/messages ", 18));
    CHECK(!strcmp(ts_header(&r.srv.req[0], "x-api-key", h, sizeof h), "sk-ant-SECRET-456"));
    CHECK(!strcmp(ts_header(&r.srv.req[0], "anthropic-version", h, sizeof h), "2023-06-01"));
    CHECK(!ts_header(&r.srv.req[0], "Authorization", h, sizeof h)[0]);
    cJSON *b0 = req_json(&r, 0), *b1 = req_json(&r, 1);
    CHECK(cJSON_GetObjectItemCaseSensitive(b0, "max_tokens")->valueint == 1024);
    CHECK(cJSON_IsString(cJSON_GetObjectItemCaseSensitive(b0, "system")));
    CHECK(!cJSON_GetObjectItemCaseSensitive(b0, "temperature") && !cJSON_GetObjectItemCaseSensitive(b0, "top_p") &&
          !cJSON_GetObjectItemCaseSensitive(b0, "top_k"));
    const cJSON *t0 = cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(b0, "tools"), 0);
    CHECK(cJSON_IsObject(cJSON_GetObjectItemCaseSensitive(t0, "input_schema")));
    const cJSON *m = cJSON_GetObjectItemCaseSensitive(b1, "messages");
    CHECK(cJSON_GetArraySize(m) == 3); /* user, assistant (text + tool_use echoed), user (tool_result) */
    const cJSON *as = cJSON_GetArrayItem(m, 1), *res = cJSON_GetArrayItem(m, 2);
    CHECK(cJSON_GetArraySize(cJSON_GetObjectItemCaseSensitive(as, "content")) == 2);
    const cJSON *tr = cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(res, "content"), 0);
    CHECK(!strcmp(cJSON_GetObjectItemCaseSensitive(tr, "type")->valuestring, "tool_result"));
    CHECK(!strcmp(cJSON_GetObjectItemCaseSensitive(tr, "tool_use_id")->valuestring, "toolu_01"));
    cJSON_Delete(b0);
    cJSON_Delete(b1);
    finish(&r);
}

/* ---- parallel calls ---- */

static char *respond_parallel(const char *req, void *u)
{
    const char *calls[] = {"query_object_location", "{\"object_name\":\"couch\"}", "get_robot_pose", "{}",
                           "describe_surroundings", "{\"object_name\":\"dining table\"}"};
    return reply(g_dialect, "Looking.", 3, calls);
}

static const ts_response parallel_script[] = {{200, NULL, NULL, respond_parallel}, {200, NULL, NULL, respond_text}};

static void test_parallel(int dialect)
{
    run r;
    start(&r, dialect, parallel_script, 2, 0, 5, 0);
    ask(&r, "where is the couch and what is near the dining table?");
    CHECK_MSG(r.rc == 0, "%s", r.err.msg);
    CHECK(r.a.n_trace == 3 && !strcmp(trace_tool(&r, 2), "describe_surroundings"));
    cJSON *b1 = req_json(&r, 1);
    const cJSON *m = cJSON_GetObjectItemCaseSensitive(b1, "messages");
    if (dialect == OAI) {
        CHECK(cJSON_GetArraySize(m) == 6); /* system, user, assistant, 3 x tool */
        for (int i = 0; i < 3; i++) {
            char id[16];
            snprintf(id, sizeof id, "call_%c%d", 'a' + i, i + 1);
            CHECK(!strcmp(cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(m, 3 + i), "tool_call_id")->valuestring, id));
        }
    } else {
        CHECK(cJSON_GetArraySize(m) == 3); /* every tool_result in one user turn */
        const cJSON *c = cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(m, 2), "content");
        CHECK(cJSON_GetArraySize(c) == 3);
        for (int i = 0; i < 3; i++) {
            char id[16];
            snprintf(id, sizeof id, "toolu_%02d", i + 1);
            CHECK(!strcmp(cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(c, i), "tool_use_id")->valuestring, id));
        }
    }
    cJSON_Delete(b1);
    finish(&r);
}
static void test_openai_parallel(void) { test_parallel(OAI); }
static void test_anthropic_parallel(void) { test_parallel(ANT); }

/* ---- local servers' quirks (OpenAI-compatible) ---- */

/* llama.cpp's documented non-stream sample: calls without id/type/function wrapper,
 * finish_reason "tool". Here with arguments as an object (Ollama native, some vLLM parsers). */
static const char quirk_flat[] =
    "{\"choices\":[{\"finish_reason\":\"tool\",\"index\":0,\"message\":{\"content\":null,\"tool_calls\":"
    "[{\"name\":\"query_object_location\",\"arguments\":{\"object_name\":\"couch\"}},"
    "{\"name\":\"get_robot_pose\",\"arguments\":\"\"}],\"role\":\"assistant\"}}],"
    "\"created\":1727287211,\"model\":\"gpt-3.5-turbo\",\"object\":\"chat.completion\",\"id\":\"chatcmpl-x\"}";
/* finish_reason "stop" although there are tool calls; id present but empty. */
static const char quirk_stop[] =
    "{\"choices\":[{\"finish_reason\":\"stop\",\"index\":0,\"message\":{\"role\":\"assistant\",\"content\":\"\","
    "\"tool_calls\":[{\"id\":\"\",\"type\":\"function\",\"function\":{\"name\":\"get_robot_pose\",\"arguments\":\"{}\"}}]}}]}";

static const ts_response quirk_script[] = {
    {200, NULL, quirk_flat}, {200, NULL, quirk_stop}, {200, NULL, NULL, respond_text}};

static void test_openai_quirks(void)
{
    run r;
    start(&r, OAI, quirk_script, 3, 0, 5, 0);
    ask(&r, "where is the couch?");
    CHECK_MSG(r.rc == 0, "%s", r.err.msg);
    CHECK(r.a.n_trace == 3);
    for (int i = 0; i < r.a.n_trace; i++) CHECK_MSG(!r.a.trace[i].is_error, "%s", r.a.trace[i].result);
    /* synthesized ids: unique, and echoed the same in the assistant message and the tool message */
    cJSON *b1 = req_json(&r, 1), *b2 = req_json(&r, 2);
    const cJSON *m1 = cJSON_GetObjectItemCaseSensitive(b1, "messages");
    const cJSON *calls = cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(m1, 2), "tool_calls");
    const char *id0 = cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(calls, 0), "id")->valuestring;
    const char *id1 = cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(calls, 1), "id")->valuestring;
    CHECK(id0[0] && strcmp(id0, id1) != 0);
    CHECK(!strcmp(cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(m1, 3), "tool_call_id")->valuestring, id0));
    CHECK(!strcmp(cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(m1, 4), "tool_call_id")->valuestring, id1));
    const cJSON *m2 = cJSON_GetObjectItemCaseSensitive(b2, "messages");
    const char *id2 = cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(m2, 5), "tool_calls"), 0), "id")->valuestring;
    CHECK(strcmp(id2, id0) && strcmp(id2, id1));
    /* the arguments object went back as a JSON string */
    CHECK(cJSON_IsString(cJSON_GetObjectItemCaseSensitive(cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(calls, 0), "function"), "arguments")));
    cJSON_Delete(b1);
    cJSON_Delete(b2);
    finish(&r);
}

/* ---- retries and failures ---- */

static const char rate_body[] = "{\"error\":{\"message\":\"Rate limit reached\",\"type\":\"requests\",\"code\":\"rate_limit_exceeded\"}}";
static const char quota_body[] = "{\"error\":{\"message\":\"You exceeded your current quota\",\"type\":\"insufficient_quota\",\"code\":\"insufficient_quota\"}}";
static const char overloaded_body[] = "{\"type\":\"error\",\"error\":{\"type\":\"overloaded_error\",\"message\":\"Overloaded\"},\"request_id\":\"req_1\"}";
static const char invalid_body[] = "{\"type\":\"error\",\"error\":{\"type\":\"invalid_request_error\",\"message\":\"messages: field required\"}}";
static const char spend_body[] = "{\"type\":\"error\",\"error\":{\"type\":\"rate_limit_error\",\"message\":\"spend limit\",\"details\":{\"error_code\":\"enforced_spend_limit_reached\"}}}";
static const char auth_body[] = "{\"error\":{\"message\":\"Incorrect API key provided: sk-test-SECRET-123.\",\"type\":\"invalid_request_error\",\"code\":\"invalid_api_key\"}}";

static void test_retry_after(void)
{
    static const ts_response script[] = {{429, "Retry-After: 1\r\n", rate_body}, {200, NULL, NULL, respond_text}};
    run r;
    start(&r, OAI, script, 2, 2, 5, 0);
    ask(&r, "hello");
    CHECK_MSG(r.rc == 0, "%s", r.err.msg);
    CHECK(r.a.llm_requests == 2 && r.a.llm_retries == 1);
    CHECK_MSG(r.seconds >= 0.95 && r.seconds < 4, "%.2f s", r.seconds); /* Retry-After honoured */
    finish(&r);
}

static void test_server_errors_retried(void)
{
    static const ts_response oai[] = {{500, NULL, "{\"error\":{\"message\":\"boom\"}}"}, {503, NULL, "busy"},
                                      {200, NULL, NULL, respond_text}};
    static const ts_response ant[] = {{529, NULL, overloaded_body}, {200, NULL, NULL, respond_text}};
    run r;
    start(&r, OAI, oai, 3, 2, 5, 0);
    ask(&r, "hello");
    CHECK_MSG(r.rc == 0 && r.a.llm_retries == 2, "%s (%d retries)", r.err.msg, r.a.llm_retries);
    finish(&r);
    start(&r, ANT, ant, 2, 2, 5, 0);
    ask(&r, "hello");
    CHECK_MSG(r.rc == 0 && r.a.llm_retries == 1, "%s", r.err.msg);
    finish(&r);
    /* retries run out: a clear message */
    static const ts_response always500[] = {{500, NULL, "{}"}, {500, NULL, "{}"}, {500, NULL, "{}"}};
    start(&r, OAI, always500, 3, 2, 5, 0);
    ask(&r, "hello");
    CHECK(r.rc == SP_E_NET && strstr(r.err.msg, "HTTP 500") && strstr(r.err.msg, "gave up after 3 attempts"));
    CHECK(r.srv.n_req == 3);
    fprintf(stderr, "  %s\n", r.err.msg);
    finish(&r);
}

static void test_client_errors_not_retried(void)
{
    static const ts_response q[] = {{429, "Retry-After: 1\r\n", quota_body}};
    static const ts_response a400[] = {{400, NULL, invalid_body}};
    static const ts_response spend[] = {{429, NULL, spend_body}};
    static const ts_response auth[] = {{401, NULL, auth_body}};
    run r;
    start(&r, OAI, q, 1, 3, 5, 0);
    ask(&r, "hello");
    CHECK(r.rc == SP_E_NET && r.srv.n_req == 1 && strstr(r.err.msg, "quota"));
    fprintf(stderr, "  %s\n", r.err.msg);
    finish(&r);
    start(&r, ANT, a400, 1, 3, 5, 0);
    ask(&r, "hello");
    CHECK(r.rc == SP_E_NET && r.srv.n_req == 1 && strstr(r.err.msg, "HTTP 400") && strstr(r.err.msg, "field required"));
    fprintf(stderr, "  %s\n", r.err.msg);
    finish(&r);
    start(&r, ANT, spend, 1, 3, 5, 0);
    ask(&r, "hello");
    CHECK(r.rc == SP_E_NET && r.srv.n_req == 1);
    finish(&r);
    setenv("OPENAI_API_KEY", "sk-test-SECRET-123", 1);
    start(&r, OAI, auth, 1, 3, 5, 0);
    ask(&r, "hello");
    CHECK(r.rc == SP_E_NET && r.srv.n_req == 1 && strstr(r.err.msg, "HTTP 401") && !strstr(r.err.msg, "SECRET"));
    CHECK(r.a.text && !strstr(r.a.text, "SECRET"));
    fprintf(stderr, "  %s\n", r.err.msg);
    finish(&r);
}

static void test_timeout(void)
{
    static const ts_response hang[] = {{200, NULL, "{}", NULL, 3000}, {200, NULL, "{}", NULL, 3000}};
    run r;
    start(&r, OAI, hang, 2, 1, 0.4, 0);
    ask(&r, "hello");
    CHECK(r.rc == SP_E_NET && strstr(r.err.msg, "timed out"));
    CHECK_MSG(r.seconds < 2.5, "%.2f s", r.seconds);
    fprintf(stderr, "  %s (%.2f s)\n", r.err.msg, r.seconds);
    finish(&r);
}

static void test_truncated(void)
{
    char *full = oai_reply("a long enough answer to cut in the middle", 0, NULL, "stop");
    ts_response cut[] = {{200, NULL, full, NULL, 0, 40}, {200, NULL, full, NULL, 0, 40}};
    run r;
    start(&r, OAI, cut, 2, 1, 5, 0);
    ask(&r, "hello");
    CHECK(r.rc == SP_E_NET && strstr(r.err.msg, "truncated") && r.srv.n_req == 2);
    fprintf(stderr, "  %s\n", r.err.msg);
    finish(&r);
    /* complete HTTP, but the JSON stops early */
    full[60] = 0;
    ts_response bad[] = {{200, NULL, full}};
    start(&r, ANT, bad, 1, 1, 5, 0);
    ask(&r, "hello");
    CHECK(r.rc == SP_E_FORMAT && strstr(r.err.msg, "JSON ends early"));
    fprintf(stderr, "  %s\n", r.err.msg);
    finish(&r);
    free(full);
}

static void test_refused(void)
{
    /* a port nobody listens on: bind one, close it */
    test_server t;
    ts_start(&t, NULL, 0, NULL);
    int port = t.port;
    ts_stop(&t);
    sp_agent_config cfg = sp_agent_config_default();
    char url[64];
    snprintf(url, sizeof url, "http://127.0.0.1:%d/v1", port);
    cfg.brain = SP_AGENT_BRAIN_OPENAI;
    cfg.llm.base_url = url;
    cfg.llm.model = "m";
    cfg.llm.max_retries = 2;
    cfg.llm.retry_base_s = 0.01;
    sp_agent_robot robot;
    sp_error err = {0};
    sp_agent_robot_offline(&robot, NULL, &err);
    sp_agent_session *s = NULL;
    CHECK_OK(agent_session_open_world(&s, &cfg, fw_world(NULL), robot, &err), &err);
    sp_agent_answer a;
    double t0 = sp_time_now();
    CHECK(sp_agent_session_ask(s, "hello", &a, &err) == SP_E_NET && strstr(err.msg, "could not connect"));
    CHECK(sp_time_now() - t0 < 3);
    CHECK(a.llm_requests == 3);
    fprintf(stderr, "  %s\n", err.msg);
    sp_agent_answer_free(&a);
    sp_agent_session_close(s);
}

/* ---- what the model sends is checked in C ---- */

static char *respond_bad_args(const char *req, void *u)
{
    const char *calls[] = {"send_nav2_goal", "{\"x\":\"far away\",\"y\":1}", "query_object_location",
                           "{\"object_name\": \"fri"};
    return reply(g_dialect, NULL, g_dialect == OAI ? 2 : 1, calls);
}
static char *respond_after_bad(const char *req, void *u)
{
    /* the errors came back to the model, structured */
    return reply(g_dialect, strstr(req, "INVALID_ARGUMENTS") ? "fixed" : "no error seen", 0, NULL);
}
static char *respond_raw_goal(const char *req, void *u)
{
    const char *calls[] = {"send_nav2_goal", "{\"x\":3.5,\"y\":7.5,\"yaw\":0}"};
    return reply(g_dialect, NULL, 1, calls);
}
static char *respond_after_raw(const char *req, void *u)
{
    return reply(g_dialect, strstr(req, "PLAN_REQUIRED") ? "refused as it should be" : "moved?!", 0, NULL);
}

static void test_invalid_from_model(int dialect)
{
    static const ts_response bad[] = {{200, NULL, NULL, respond_bad_args}, {200, NULL, NULL, respond_after_bad}};
    static const ts_response raw[] = {{200, NULL, NULL, respond_raw_goal}, {200, NULL, NULL, respond_after_raw}};
    run r;
    start(&r, dialect, bad, 2, 0, 5, 0);
    ask(&r, "go far away");
    CHECK_MSG(r.rc == 0 && !strcmp(r.a.text, "fixed"), "%s %s", r.err.msg, r.a.text ? r.a.text : "");
    CHECK(r.a.n_trace >= 1 && r.a.trace[0].is_error && strstr(r.a.trace[0].result, "x: expected a number"));
    if (dialect == OAI) CHECK(r.a.n_trace == 2 && r.a.trace[1].is_error && strstr(r.a.trace[1].result, "could not be read"));
    if (dialect == ANT) { /* is_error travels in the tool_result block */
        cJSON *b1 = req_json(&r, 1);
        const cJSON *m = cJSON_GetObjectItemCaseSensitive(b1, "messages");
        const cJSON *blk = cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(m, 2), "content"), 0);
        CHECK(cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(blk, "is_error")));
        cJSON_Delete(b1);
    }
    finish(&r);
    start(&r, dialect, raw, 2, 0, 5, 0);
    ask(&r, "drive into the wall at 3.5, 7.5");
    CHECK_MSG(r.rc == 0 && !strcmp(r.a.text, "refused as it should be"), "%s", r.a.text ? r.a.text : r.err.msg);
    sp_agent_pose p;
    r.s->robot.ops->get_pose(r.s->robot.ctx, &p, &r.err);
    CHECK(p.x == 3.0 && p.y == 1.8); /* never moved */
    finish(&r);
}
static void test_openai_invalid(void) { test_invalid_from_model(OAI); }
static void test_anthropic_invalid(void) { test_invalid_from_model(ANT); }

/* A model that skips the question: "go to the chair" straight to a plan. */
static char *respond_query_chair(const char *req, void *u)
{
    const char *calls[] = {"query_object_location", "{\"object_name\":\"chair\"}", "get_robot_pose", "{}"};
    return reply(g_dialect, NULL, 2, calls);
}
/* What the last tool message of an OpenAI request said. */
static char *respond_after_plan(const char *req, void *u)
{
    cJSON *j = cJSON_Parse(req);
    const cJSON *m = cJSON_GetObjectItemCaseSensitive(j, "messages");
    const cJSON *last = cJSON_GetArrayItem(m, cJSON_GetArraySize(m) - 1);
    const cJSON *c = cJSON_GetObjectItemCaseSensitive(last, "content");
    const char *t = cJSON_IsString(c) ? c->valuestring : "";
    char *r = reply(g_dialect, strstr(t, "AMBIGUOUS") ? "asked" : strstr(t, "\"ok\":true") ? "planned" : "?", 0, NULL);
    cJSON_Delete(j);
    return r;
}
static char *respond_pick_2(const char *req, void *u)
{
    const char *calls[] = {"describe_surroundings", "{\"object_name\":\"chair\",\"instance\":2}"};
    return reply(g_dialect, NULL, 1, calls);
}

static void test_model_must_ask(void)
{
    static const ts_response script[] = {
        {200, NULL, NULL, respond_query_chair}, {200, NULL, NULL, respond_plan}, {200, NULL, NULL, respond_after_plan},
        {200, NULL, NULL, respond_query_chair}, {200, NULL, NULL, respond_plan}, {200, NULL, NULL, respond_after_plan},
        {200, NULL, NULL, respond_pick_2},      {200, NULL, NULL, respond_after_plan}};
    run r;
    start(&r, OAI, script, 8, 0, 5, 0);
    ask(&r, "go to the chair");
    CHECK_MSG(r.rc == 0 && !strcmp(r.a.text, "asked"), "%s", r.a.text ? r.a.text : r.err.msg);
    ask(&r, "go to the nearest chair"); /* said which: the plan goes ahead */
    CHECK_MSG(r.rc == 0 && !strcmp(r.a.text, "planned"), "%s", r.a.text ? r.a.text : r.err.msg);
    ask(&r, "what is near the chair?"); /* the model picks instance 2 itself */
    CHECK_MSG(r.rc == 0 && !strcmp(r.a.text, "asked"), "%s", r.a.text ? r.a.text : r.err.msg);
    finish(&r);
}

static void test_loop_bound(void)
{
    static const ts_response again[] = {
        {200, NULL, NULL, respond_pose}, {200, NULL, NULL, respond_pose}, {200, NULL, NULL, respond_pose},
        {200, NULL, NULL, respond_pose}, {200, NULL, NULL, respond_pose}, {200, NULL, NULL, respond_pose},
        {200, NULL, NULL, respond_pose}, {200, NULL, NULL, respond_pose}};
    run r;
    start(&r, ANT, again, 8, 0, 5, 0);
    ask(&r, "where am I, forever");
    CHECK(r.rc == SP_E_FORMAT && strstr(r.err.msg, "within 6 turns"));
    CHECK(r.srv.n_req == 6);
    fprintf(stderr, "  %s\n", r.err.msg);
    finish(&r);
}

static void test_malformed_bodies(void)
{
    static const ts_response oai[] = {{200, NULL, "{\"choices\":[]}"}};
    static const ts_response ant[] = {{200, NULL, "{\"type\":\"message\",\"content\":\"text\"}"}};
    static const ts_response html[] = {{200, NULL, "<html>proxy error</html>"}};
    run r;
    start(&r, OAI, oai, 1, 0, 5, 0);
    ask(&r, "hello");
    CHECK(r.rc == SP_E_FORMAT && strstr(r.err.msg, "'choices' is empty"));
    finish(&r);
    start(&r, ANT, ant, 1, 0, 5, 0);
    ask(&r, "hello");
    CHECK(r.rc == SP_E_FORMAT && strstr(r.err.msg, "content"));
    finish(&r);
    start(&r, OAI, html, 1, 0, 5, 0);
    ask(&r, "hello");
    CHECK(r.rc == SP_E_FORMAT && strstr(r.err.msg, "invalid JSON at byte 0"));
    fprintf(stderr, "  %s\n", r.err.msg);
    finish(&r);
}

/* A proxy set in the environment must not see loopback requests (they would leave the host). */
static void test_proxy_bypassed(void)
{
    setenv("http_proxy", "http://10.255.255.1:9", 1);
    setenv("HTTPS_PROXY", "http://10.255.255.1:9", 1);
    setenv("ALL_PROXY", "http://10.255.255.1:9", 1);
    static const ts_response script[] = {{200, NULL, NULL, respond_text}};
    run r;
    start(&r, OAI, script, 1, 0, 3, 0);
    ask(&r, "hello");
    CHECK_MSG(r.rc == 0 && r.srv.n_req == 1, "%s", r.err.msg);
    finish(&r);
    unsetenv("http_proxy");
    unsetenv("HTTPS_PROXY");
    unsetenv("ALL_PROXY");
}

static void test_presets_and_config(void)
{
    sp_agent_config cfg = sp_agent_config_default();
    cfg.brain = SP_AGENT_BRAIN_OPENAI;
    cfg.llm.preset = "nonsense";
    sp_agent_robot robot;
    sp_error err = {0};
    sp_agent_session *s = NULL;
    sp_agent_robot_offline(&robot, NULL, &err);
    CHECK_FAILS(agent_session_open_world(&s, &cfg, fw_world(NULL), robot, &err), SP_E_ARG, &err, "unknown LLM preset");
    cfg.llm.preset = NULL; /* hosted OpenAI needs a model name */
    sp_agent_robot_offline(&robot, NULL, &err);
    CHECK_FAILS(agent_session_open_world(&s, &cfg, fw_world(NULL), robot, &err), SP_E_ARG, &err, "--llm-model");
    cfg.llm.preset = "llama.cpp"; /* key-less local server, model defaults to "local" */
    sp_agent_robot_offline(&robot, NULL, &err);
    CHECK_OK(agent_session_open_world(&s, &cfg, fw_world(NULL), robot, &err), &err);
    sp_agent_session_close(s);
    cfg.llm.base_url = "ftp://example";
    sp_agent_robot_offline(&robot, NULL, &err);
    CHECK_FAILS(agent_session_open_world(&s, &cfg, fw_world(NULL), robot, &err), SP_E_ARG, &err, "http://");
}

int main(void)
{
    if (!agent_http_available()) TEST_SKIP("built without libcurl");
    unsetenv("OPENAI_BASE_URL");
    unsetenv("ANTHROPIC_BASE_URL");
    unsetenv("OPENAI_API_KEY");
    unsetenv("ANTHROPIC_API_KEY");
    RUN(test_openai_multistep);
    RUN(test_anthropic_multistep);
    RUN(test_openai_parallel);
    RUN(test_anthropic_parallel);
    RUN(test_openai_quirks);
    RUN(test_retry_after);
    RUN(test_server_errors_retried);
    RUN(test_client_errors_not_retried);
    RUN(test_timeout);
    RUN(test_truncated);
    RUN(test_refused);
    RUN(test_openai_invalid);
    RUN(test_anthropic_invalid);
    RUN(test_model_must_ask);
    RUN(test_loop_bound);
    RUN(test_malformed_bodies);
    RUN(test_proxy_bypassed);
    RUN(test_presets_and_config);
    return TEST_EXIT();
}
