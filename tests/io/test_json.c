/* JSON helpers: parse, pretty-print round trip, and errors that name file, line and column. */
#include <cjson/cJSON.h>

#include "io_fixture.h"
#include "semsplat/io.h"
#include "test.h"

static void test_json(void)
{
    const char *dir = test_tmpdir("io_json");
    char p[1024], q[1024];
    sp_error err = {0};
    cJSON *j = NULL;
    fx_write_text(fx_path(p, sizeof p, dir, "ok.json"), "{\n  \"a\": [1, 2.5, \"x\"],\n  \"b\": {\"c\": true}\n}\n");
    CHECK_OK(sp_json_read_file(p, &j, &err), &err);
    CHECK(j && cJSON_GetArraySize(cJSON_GetObjectItem(j, "a")) == 3);
    CHECK_OK(sp_json_write_file(fx_path(q, sizeof q, dir, "out.json"), j, &err), &err);
    cJSON *k = NULL;
    CHECK_OK(sp_json_read_file(q, &k, &err), &err);
    CHECK(k && cJSON_Compare(j, k, 1));
    cJSON_Delete(j);
    cJSON_Delete(k);
    /* The stray '}' on line 3 column 12. */
    fx_write_text(fx_path(p, sizeof p, dir, "bad.json"), "{\n  \"a\": 1,\n  \"b\": [2, }\n}\n");
    CHECK_FAILS(sp_json_read_file(p, &j, &err), SP_E_FORMAT, &err, "bad.json:3:");
    CHECK(j == NULL);
    fx_write_text(fx_path(p, sizeof p, dir, "trail.json"), "{\"a\": 1} extra");
    CHECK_FAILS(sp_json_read_file(p, &j, &err), SP_E_FORMAT, &err, "trail.json:1:");
    CHECK_FAILS(sp_json_read_file(fx_path(p, sizeof p, dir, "none.json"), &j, &err), SP_E_IO, &err, "none.json");
}

int main(void)
{
    RUN(test_json);
    return TEST_EXIT();
}
