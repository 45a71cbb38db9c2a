/* The LLM response decoders and the tool-argument decoder on the documented formats, the quirks,
 * error bodies, and on anything else: every prefix of valid bodies, byte flips, random bytes,
 * deep nesting. They must return a reply or SP_E_FORMAT/SP_E_NET with a message, never crash
 * (run under ASan/UBSan in the sanitizer build). Also the retry policy and Retry-After parsing. */
#include <cjson/cJSON.h>

#include "agent/agent_internal.h"
#include "test.h"

static const char oai_doc[] =
    "{\"id\":\"chatcmpl-abc\",\"object\":\"chat.completion\",\"created\":1,\"model\":\"gpt\","
    "\"choices\":[{\"index\":0,\"message\":{\"role\":\"assistant\",\"content\":null,\"tool_calls\":["
    "{\"id\":\"call_1\",\"type\":\"function\",\"function\":{\"name\":\"plan_path\","
    "\"arguments\":\"{\\\"start\\\":[0,0,0,0],\\\"goal\\\":[1,2]}\"}},"
    "{\"id\":\"call_2\",\"type\":\"function\",\"function\":{\"name\":\"get_robot_pose\",\"arguments\":\"{}\"}}]},"
    "\"logprobs\":null,\"finish_reason\":\"tool_calls\"}],"
    "\"usage\":{\"prompt_tokens\":82,\"completion_tokens\":17,\"total_tokens\":99}}";

static const char ant_doc[] =
    "{\"id\":\"msg_01\",\"type\":\"message\",\"role\":\"assistant\",\"model\":\"claude\","
    "\"content\":[{\"type\":\"thinking\",\"thinking\":\"plan it\",\"signature\":\"sig==\"},"
    "{\"type\":\"text\",\"text\":\"I'll plan a path.\"},"
    "{\"type\":\"tool_use\",\"id\":\"toolu_01A\",\"name\":\"plan_path\",\"input\":{\"start\":[0,0],\"goal\":[1,2]}}],"
    "\"stop_reason\":\"tool_use\",\"stop_sequence\":null,\"usage\":{\"input_tokens\":50,\"output_tokens\":30}}";

static void test_openai_documented(void)
{
    sp_agent_reply r;
    sp_error err = {0};
    CHECK_OK(sp_agent_decode_openai(oai_doc, strlen(oai_doc), &r, &err), &err);
    CHECK(r.stop == SP_AGENT_STOP_TOOL_USE && !strcmp(r.stop_raw, "tool_calls"));
    CHECK(r.n_calls == 2 && !r.text);
    CHECK(!strcmp(r.calls[0].id, "call_1") && !strcmp(r.calls[0].name, "plan_path") && !r.calls[0].synthesized);
    CHECK(r.calls[0].arguments && !strcmp(r.calls[0].arguments, "{\"start\":[0,0,0,0],\"goal\":[1,2]}"));
    CHECK(!strcmp(r.calls[1].arguments, "{}"));
    CHECK(r.input_tokens == 82 && r.output_tokens == 17);
    sp_agent_reply_free(&r);
    /* text answer, content as parts, the legacy function_call */
    const char *text = "{\"choices\":[{\"message\":{\"role\":\"assistant\",\"content\":\"Arrived.\"},\"finish_reason\":\"stop\"}]}";
    CHECK_OK(sp_agent_decode_openai(text, strlen(text), &r, &err), &err);
    CHECK(r.stop == SP_AGENT_STOP_END && r.n_calls == 0 && !strcmp(r.text, "Arrived."));
    sp_agent_reply_free(&r);
    const char *parts = "{\"choices\":[{\"message\":{\"content\":[{\"type\":\"text\",\"text\":\"a\"},{\"type\":\"text\",\"text\":\"b\"}]},\"finish_reason\":\"length\"}]}";
    CHECK_OK(sp_agent_decode_openai(parts, strlen(parts), &r, &err), &err);
    CHECK(r.stop == SP_AGENT_STOP_MAX_TOKENS && !strcmp(r.text, "a\nb"));
    sp_agent_reply_free(&r);
    const char *legacy = "{\"choices\":[{\"message\":{\"function_call\":{\"name\":\"get_robot_pose\",\"arguments\":\"{}\"}},\"finish_reason\":\"function_call\"}]}";
    CHECK_OK(sp_agent_decode_openai(legacy, strlen(legacy), &r, &err), &err);
    CHECK(r.n_calls == 1 && r.calls[0].synthesized && r.stop == SP_AGENT_STOP_TOOL_USE);
    sp_agent_reply_free(&r);
}

static void test_openai_quirks(void)
{
    sp_agent_reply r;
    sp_error err = {0};
    /* llama.cpp's documented sample, verbatim shape */
    const char *ll = "{\"choices\":[{\"finish_reason\":\"tool\",\"index\":0,\"message\":{\"content\":null,"
                     "\"tool_calls\":[{\"name\":\"python\",\"arguments\":\"{\\\"code\\\":\\\" \\\\nprint(\\\\\\\"Hello, World!\\\\\\\")\\\"}\"}],"
                     "\"role\":\"assistant\"}}],\"created\":1727287211,\"model\":\"gpt-3.5-turbo\",\"object\":\"chat.completion\","
                     "\"usage\":{\"completion_tokens\":16,\"prompt_tokens\":44,\"total_tokens\":60},\"id\":\"chatcmpl-Htbgh9feMmGM0LEH2hmQvwsCxq3c6Ni8\"}";
    CHECK_OK(sp_agent_decode_openai(ll, strlen(ll), &r, &err), &err);
    CHECK(r.n_calls == 1 && r.calls[0].synthesized && !strcmp(r.calls[0].id, "call_1"));
    CHECK(!strcmp(r.calls[0].name, "python") && strstr(r.calls[0].arguments, "Hello, World!"));
    CHECK(r.stop == SP_AGENT_STOP_TOOL_USE && !strcmp(r.stop_raw, "tool"));
    sp_agent_reply_free(&r);
    /* arguments as an object, finish_reason stop with calls, invalid argument JSON kept as an error */
    const char *mix = "{\"choices\":[{\"finish_reason\":\"stop\",\"message\":{\"tool_calls\":["
                      "{\"id\":\"a\",\"function\":{\"name\":\"get_robot_pose\",\"arguments\":{}}},"
                      "{\"id\":\"b\",\"function\":{\"name\":\"plan_path\",\"arguments\":\"{\\\"start\\\": [1,\"}},"
                      "{\"id\":\"c\",\"function\":{\"name\":\"plan_path\",\"arguments\":\"[1,2]\"}},"
                      "{\"id\":\"d\",\"function\":{\"arguments\":\"{}\"}}]}}]}";
    CHECK_OK(sp_agent_decode_openai(mix, strlen(mix), &r, &err), &err);
    CHECK(r.n_calls == 4 && r.stop == SP_AGENT_STOP_TOOL_USE && !strcmp(r.stop_raw, "stop"));
    CHECK(!strcmp(r.calls[0].arguments, "{}"));
    CHECK(!r.calls[1].arguments && strstr(r.calls[1].args_error, "ends early"));
    CHECK(!r.calls[2].arguments && strstr(r.calls[2].args_error, "object"));
    CHECK(strstr(r.calls[3].args_error, "without a function name"));
    sp_agent_reply_free(&r);
    /* an error object in a 200 body */
    const char *eb = "{\"error\":{\"message\":\"model 'x' not found\",\"type\":\"invalid_request_error\",\"code\":404}}";
    CHECK_FAILS(sp_agent_decode_openai(eb, strlen(eb), &r, &err), SP_E_NET, &err, "model 'x' not found");
}

static void test_anthropic_documented(void)
{
    sp_agent_reply r;
    sp_error err = {0};
    CHECK_OK(sp_agent_decode_anthropic(ant_doc, strlen(ant_doc), &r, &err), &err);
    CHECK(r.stop == SP_AGENT_STOP_TOOL_USE && r.n_calls == 1);
    CHECK(!strcmp(r.text, "I'll plan a path."));
    CHECK(!strcmp(r.calls[0].id, "toolu_01A") && !strcmp(r.calls[0].arguments, "{\"start\":[0,0],\"goal\":[1,2]}"));
    /* the echo keeps every block, the thinking one with its signature */
    cJSON *c = cJSON_Parse(r.content_json);
    CHECK(cJSON_GetArraySize(c) == 3 && strstr(r.content_json, "sig=="));
    cJSON_Delete(c);
    CHECK(r.input_tokens == 50 && r.output_tokens == 30);
    sp_agent_reply_free(&r);
    static const struct {
        const char *reason;
        int stop;
    } reasons[] = {{"end_turn", SP_AGENT_STOP_END},       {"stop_sequence", SP_AGENT_STOP_END},
                   {"max_tokens", SP_AGENT_STOP_MAX_TOKENS}, {"refusal", SP_AGENT_STOP_REFUSAL},
                   {"pause_turn", SP_AGENT_STOP_PAUSE},   {"something_new", SP_AGENT_STOP_OTHER}};
    for (size_t i = 0; i < sizeof reasons / sizeof reasons[0]; i++) {
        char b[256];
        snprintf(b, sizeof b, "{\"type\":\"message\",\"content\":[{\"type\":\"text\",\"text\":\"x\"}],\"stop_reason\":\"%s\"}", reasons[i].reason);
        CHECK_OK(sp_agent_decode_anthropic(b, strlen(b), &r, &err), &err);
        CHECK(r.stop == reasons[i].stop);
        sp_agent_reply_free(&r);
    }
    /* tool_use without an id and with a string input: normalized, and the echo patched */
    const char *q = "{\"content\":[{\"type\":\"tool_use\",\"name\":\"get_robot_pose\",\"input\":\"{}\"}],\"stop_reason\":\"tool_use\"}";
    CHECK_OK(sp_agent_decode_anthropic(q, strlen(q), &r, &err), &err);
    CHECK(r.calls[0].synthesized && strstr(r.content_json, r.calls[0].id) && strstr(r.content_json, "\"input\":{}"));
    sp_agent_reply_free(&r);
    const char *e = "{\"type\":\"error\",\"error\":{\"type\":\"overloaded_error\",\"message\":\"Overloaded\"}}";
    CHECK_FAILS(sp_agent_decode_anthropic(e, strlen(e), &r, &err), SP_E_NET, &err, "overloaded_error");
}

static void test_error_bodies(void)
{
    char t[64], c[64], m[256];
    const char *a = "{\"type\":\"error\",\"error\":{\"type\":\"rate_limit_error\",\"message\":\"slow\",\"details\":{\"error_code\":\"enforced_spend_limit_reached\"}},\"request_id\":\"r\"}";
    CHECK(sp_agent_decode_error_body(a, strlen(a), t, sizeof t, c, sizeof c, m, sizeof m) == 0);
    CHECK(!strcmp(t, "rate_limit_error") && !strcmp(c, "enforced_spend_limit_reached") && !strcmp(m, "slow"));
    const char *o = "{\"error\":\"model not loaded\"}";
    CHECK(sp_agent_decode_error_body(o, strlen(o), t, sizeof t, c, sizeof c, m, sizeof m) == 0 && !strcmp(m, "model not loaded"));
    CHECK(sp_agent_decode_error_body("busy", 4, t, sizeof t, c, sizeof c, m, sizeof m) == SP_E_FORMAT && !m[0]);
}

/* Decodes bytes with all three decoders; only the return code is checked. */
static void decode_all(const char *b, size_t n)
{
    sp_agent_reply r;
    sp_error err;
    int rc = sp_agent_decode_openai(b, n, &r, &err);
    if (rc == 0) sp_agent_reply_free(&r);
    else CHECK(err.msg[0] != 0);
    rc = sp_agent_decode_anthropic(b, n, &r, &err);
    if (rc == 0) sp_agent_reply_free(&r);
    else CHECK(err.msg[0] != 0);
    sp_agent_args a;
    for (int t = 0; t < SP_AGENT_N_TOOLS; t++)
        if (sp_agent_decode_tool_args(t, b, n, &a, &err)) CHECK(err.msg[0] != 0);
    char x[32], y[32], z[64];
    sp_agent_decode_error_body(b, n, x, sizeof x, y, sizeof y, z, sizeof z);
}

static void test_garbage(void)
{
    /* every prefix of the documented bodies (not NUL-terminated: copied into exact-size buffers) */
    const char *docs[] = {oai_doc, ant_doc};
    for (int d = 0; d < 2; d++) {
        size_t n = strlen(docs[d]);
        for (size_t k = 0; k < n; k++) {
            char *b = malloc(k ? k : 1);
            memcpy(b, docs[d], k);
            decode_all(b, k);
            free(b);
        }
    }
    test_rng rng = {99};
    for (int it = 0; it < 3000; it++) { /* byte flips */
        const char *src = docs[it & 1];
        size_t n = strlen(src);
        char *b = malloc(n);
        memcpy(b, src, n);
        int flips = 1 + (int)test_range(&rng, 0, 4);
        for (int f = 0; f < flips; f++) b[(size_t)test_range(&rng, 0, (double)n)] = (char)test_range(&rng, 0, 256);
        decode_all(b, n);
        free(b);
    }
    for (int it = 0; it < 500; it++) { /* random bytes */
        size_t n = (size_t)test_range(&rng, 0, 300);
        char *b = malloc(n ? n : 1);
        for (size_t i = 0; i < n; i++) b[i] = (char)test_range(&rng, 0, 256);
        decode_all(b, n);
        free(b);
    }
    /* deep nesting and huge values */
    size_t n = 200000;
    char *deep = malloc(n);
    for (size_t i = 0; i < n; i++) deep[i] = i < n / 2 ? '[' : ']';
    decode_all(deep, n);
    free(deep);
    const char *big = "{\"x\":1e999,\"y\":-1e999,\"yaw\":0}";
    sp_agent_args a;
    sp_error err;
    CHECK(sp_agent_decode_tool_args(SP_AGENT_TOOL_SEND_GOAL, big, strlen(big), &a, &err) == SP_E_ARG);
    CHECK(sp_agent_decode_tool_args(SP_AGENT_TOOL_SEND_GOAL, NULL, 0, &a, &err) == SP_E_FORMAT);
}

static void test_registry(void)
{
    for (int t = 0; t < SP_AGENT_N_TOOLS; t++) {
        const sp_agent_tool *tool = sp_agent_tool_get(t);
        size_t n = strlen(tool->name);
        CHECK(n >= 1 && n <= 64 && strspn(tool->name, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") == n);
        CHECK(sp_agent_tool_find(tool->name) == t);
        cJSON *s = cJSON_Parse(tool->schema);
        CHECK_MSG(s && !strcmp(cJSON_GetObjectItemCaseSensitive(s, "type")->valuestring, "object") &&
                      cJSON_IsFalse(cJSON_GetObjectItemCaseSensitive(s, "additionalProperties")),
                  "%s schema", tool->name);
        cJSON_Delete(s);
    }
    CHECK(sp_agent_tool_find("query_object_location") == SP_AGENT_TOOL_QUERY_OBJECT);
    CHECK(sp_agent_tool_find("nope") == -1 && !sp_agent_tool_get(SP_AGENT_N_TOOLS));
    sp_agent_args a;
    sp_error err;
    const char *ok = "{\"start\":[0.5,1,0,1.57],\"goal\":[2,3]}";
    CHECK_OK(sp_agent_decode_tool_args(SP_AGENT_TOOL_PLAN_PATH, ok, strlen(ok), &a, &err), &err);
    CHECK(a.start_n == 4 && a.goal_n == 2 && a.goal[1] == 3 && isnan(a.goal[2]) && a.tolerance_m == SP_AGENT_DEFAULT_TOLERANCE_M);
    const char *st = "{\"target\":\"fridge\"}";
    CHECK_OK(sp_agent_decode_tool_args(SP_AGENT_TOOL_SHOW_TRAJECTORIES, st, strlen(st), &a, &err), &err);
    CHECK(a.k == 3 && a.instance == 0 && !strcmp(a.text, "fridge"));
    /* tool descriptions in both wire shapes */
    cJSON *o = agent_tools_openai(), *an = agent_tools_anthropic();
    CHECK(cJSON_GetArraySize(o) == SP_AGENT_N_TOOLS && cJSON_GetArraySize(an) == SP_AGENT_N_TOOLS);
    CHECK(cJSON_GetObjectItemCaseSensitive(cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(o, 0), "function"), "parameters"));
    CHECK(cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(an, 0), "input_schema"));
    cJSON_Delete(o);
    cJSON_Delete(an);
}

static void test_retry_policy(void)
{
    sp_agent_llm_config cfg = sp_agent_config_default().llm;
    cfg.max_retries = 2;
    cfg.retry_base_s = 0.5;
    cfg.retry_max_s = 30;
    unsigned seed = 1;
    double d;
    char why[256];
    CHECK(agent_retry_decide(429, AGENT_NET_OK, "", 0, 3.0, 0, &cfg, &seed, &d, why, sizeof why) && d == 3.0);
    CHECK(agent_retry_decide(429, AGENT_NET_OK, "", 0, -1, 1, &cfg, &seed, &d, why, sizeof why) && d >= 0.5 && d <= 1.0);
    CHECK(agent_retry_decide(503, AGENT_NET_OK, "", 0, -1, 0, &cfg, &seed, &d, why, sizeof why) && d >= 0.25 && d <= 0.5);
    CHECK(agent_retry_decide(529, AGENT_NET_OK, "", 0, -1, 0, &cfg, &seed, &d, why, sizeof why));
    CHECK(agent_retry_decide(0, AGENT_NET_TIMEOUT, "", 0, -1, 0, &cfg, &seed, &d, why, sizeof why));
    CHECK(!agent_retry_decide(500, AGENT_NET_OK, "", 0, -1, 2, &cfg, &seed, &d, why, sizeof why) && strstr(why, "gave up"));
    static const long no[] = {400, 401, 403, 404, 408, 409, 413, 422};
    for (size_t i = 0; i < sizeof no / sizeof no[0]; i++)
        CHECK(!agent_retry_decide(no[i], AGENT_NET_OK, "", 0, 1, 0, &cfg, &seed, &d, why, sizeof why));
    const char *quota = "{\"error\":{\"type\":\"insufficient_quota\",\"code\":\"insufficient_quota\"}}";
    CHECK(!agent_retry_decide(429, AGENT_NET_OK, quota, strlen(quota), 1, 0, &cfg, &seed, &d, why, sizeof why));
    CHECK(!agent_retry_decide(429, AGENT_NET_OK, "", 0, 120, 0, &cfg, &seed, &d, why, sizeof why) && strstr(why, "more than"));
    /* jitter stays in [0.5, 1] x the backoff over many draws */
    for (int i = 0; i < 1000; i++) {
        agent_retry_decide(500, AGENT_NET_OK, "", 0, -1, 1, &cfg, &seed, &d, why, sizeof why);
        CHECK(d >= 0.5 && d <= 1.0);
    }
    CHECK(agent_parse_retry_after("7", 0) == 7 && agent_parse_retry_after(" 2.5\r\n", 0) == 2.5);
    CHECK(agent_parse_retry_after("soon", 0) == -1 && agent_parse_retry_after("-3", 0) == -1);
    /* 1445412480 = Wed, 21 Oct 2015 07:28:00 GMT */
    CHECK_NEAR(agent_parse_retry_after("Wed, 21 Oct 2015 07:28:00 GMT", 1445412480.0 - 42), 42, 1e-9);
    CHECK(agent_parse_retry_after("Wed, 21 Oct 2015 07:28:00 GMT", 1445412480.0 + 5) == 0);
}

int main(void)
{
    RUN(test_openai_documented);
    RUN(test_openai_quirks);
    RUN(test_anthropic_documented);
    RUN(test_error_bodies);
    RUN(test_garbage);
    RUN(test_registry);
    RUN(test_retry_policy);
    return TEST_EXIT();
}
