/* Tests of src/base/status.c. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "se23/types.h"

static void test_status_str_names_every_status(void **state)
{
    (void)state;
    assert_string_equal(se23_status_str(SE23_OK), "SE23_OK");
    assert_string_equal(se23_status_str(SE23_ERR_DT), "SE23_ERR_DT");
    assert_string_equal(se23_status_str(SE23_ERR_NOT_PSD), "SE23_ERR_NOT_PSD");
    for (int s = SE23_OK; s <= SE23_ERR_DIM; ++s) {
        const char *name = se23_status_str((se23_status_t)s);
        assert_non_null(name);
        assert_int_equal(strncmp(name, "SE23_", 5), 0);
        assert_string_not_equal(name, "SE23_ERR_UNKNOWN");
    }
    assert_string_equal(se23_status_str((se23_status_t)99), "SE23_ERR_UNKNOWN");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_status_str_names_every_status),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
