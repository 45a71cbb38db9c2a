/* The eval queries file's own 5.3 commands: read into nav_success's form, every malformed entry an
 * error naming it, no "navigation" key meaning the built-in ten. */
#include <stdio.h>
#include <string.h>

#include "semsplat/eval.h"
#include "semsplat/nav.h"
#include "test.h"

static const char *write_json(const char *name, const char *text)
{
    static char p[1200];
    snprintf(p, sizeof p, "%s/%s.json", test_tmpdir("eval_nav_spec"), name);
    FILE *f = fopen(p, "w");
    CHECK(f != NULL);
    if (f) fputs(text, f), fclose(f);
    return p;
}

static void test_read(void)
{
    char **c = NULL;
    int n = -1;
    sp_error err = {0};
    const char *p = write_json("ok", "{\"vocabulary\": [], \"navigation\": [{\"text\": \"go to the desk\", "
                                     "\"targets\": [\"desk\", \"info desk\"]}, {\"text\": \"find a chair\", "
                                     "\"targets\": [\"chair\"]}]}");
    CHECK_MSG(sp_eval_read_nav_commands(p, &c, &n, &err) == 0, "%s", err.msg);
    CHECK(n == 2 && c && !strcmp(c[0], "go to the desk|desk,info desk") && !strcmp(c[1], "find a chair|chair"));
    sp_eval_free_nav_commands(c, n);
    p = write_json("none", "{\"vocabulary\": [{\"text\": \"desk\"}]}");
    CHECK(sp_eval_read_nav_commands(p, &c, &n, &err) == 0 && n == 0 && c == NULL);
}

static void test_bad(void)
{
    const char *bad[][2] = {
        {"notarray", "{\"navigation\": {\"text\": \"go\"}}"},
        {"notext", "{\"navigation\": [{\"targets\": [\"desk\"]}]}"},
        {"bar", "{\"navigation\": [{\"text\": \"go|to\", \"targets\": [\"desk\"]}]}"},
        {"notargets", "{\"navigation\": [{\"text\": \"go to the desk\"}]}"},
        {"comma", "{\"navigation\": [{\"text\": \"go to the desk\", \"targets\": [\"a,b\"]}]}"},
        {"number", "{\"navigation\": [{\"text\": \"go to the desk\", \"targets\": [3]}]}"},
        {"long", "{\"navigation\": [{\"text\": \"go\", \"targets\": [\"aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa\", "
                 "\"bbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbb\"]}]}"},
        {"trunc", "{\"navigation\": [{\"text\": \"go to"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        char **c = NULL;
        int n = -1;
        sp_error err = {0};
        int rc = sp_eval_read_nav_commands(write_json(bad[i][0], bad[i][1]), &c, &n, &err);
        CHECK_MSG(rc != 0 && c == NULL && n == 0 && err.msg[0], "%s: rc %d", bad[i][0], rc);
        CHECK_MSG(strstr(err.msg, ".json") != NULL, "%s: the error does not name the file: %s", bad[i][0], err.msg);
    }
    char many[4096] = "{\"navigation\": [";
    for (int i = 0; i < 17; i++)
        strcat(many, i ? ", {\"text\": \"go\", \"targets\": [\"a\"]}" : "{\"text\": \"go\", \"targets\": [\"a\"]}");
    strcat(many, "]}");
    char **c = NULL;
    int n = -1;
    sp_error err = {0};
    CHECK(sp_eval_read_nav_commands(write_json("many", many), &c, &n, &err) != 0 && strstr(err.msg, "16"));
}

/* The closed baseline's names: COCO's 80, as detectors name them, first to last. */
static void test_coco(void)
{
    int n = 0;
    const char *const *c = sp_nav_coco_classes(&n);
    CHECK(n == 80 && !strcmp(c[0], "person") && !strcmp(c[79], "toothbrush") && !strcmp(c[72], "refrigerator"));
}

int main(void)
{
    RUN(test_coco);
    RUN(test_read);
    RUN(test_bad);
    return TEST_EXIT();
}
