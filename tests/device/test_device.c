/* The device module: name parsing (exactly cpu|cuda|auto, a bad value named in the error). */
#include "test.h"

#include "semsplat/device.h"

static void test_kind_parse(void)
{
    sp_error err = {0};
    sp_device_kind k = SP_DEVICE_AUTO;
    CHECK_OK(sp_device_kind_parse("cpu", &k, &err), &err);
    CHECK(k == SP_DEVICE_CPU);
    CHECK_OK(sp_device_kind_parse("cuda", &k, &err), &err);
    CHECK(k == SP_DEVICE_CUDA);
    CHECK_OK(sp_device_kind_parse("auto", &k, &err), &err);
    CHECK(k == SP_DEVICE_AUTO);
    static const char *bad[] = {"gpu", "CPU", "", "cuda ", "cpu0", "Auto"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        k = SP_DEVICE_CUDA;
        char quoted[32];
        snprintf(quoted, sizeof quoted, "'%s'", bad[i]);
        CHECK_FAILS(sp_device_kind_parse(bad[i], &k, &err), SP_E_ARG, &err, quoted);
        CHECK(strstr(err.msg, "cpu, cuda, auto") != NULL);
        CHECK(k == SP_DEVICE_CUDA); /* unchanged on error */
    }
    CHECK_FAILS(sp_device_kind_parse(NULL, &k, &err), SP_E_ARG, &err, "no name");
    CHECK(!strcmp(sp_device_kind_name(SP_DEVICE_CUDA), "cuda"));
    CHECK(!strcmp(sp_device_kind_name(SP_DEVICE_CPU), "cpu"));
}

int main(void)
{
    RUN(test_kind_parse);
    return TEST_EXIT();
}
