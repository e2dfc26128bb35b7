/* Test assertions: see se23_test.h. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>

#include <cmocka.h>

#include "se23_test.h"

int se23t_near(double actual, double expected, double abs_tol, double rel_tol)
{
    if (!isfinite(actual) || !isfinite(expected)) {
        return 0;
    }
    return fabs(actual - expected) <= abs_tol + rel_tol * fabs(expected);
}

void se23t_assert_near(double actual, double expected, double abs_tol,
                       double rel_tol, const char *what, const char *file,
                       int line)
{
    if (!se23t_near(actual, expected, abs_tol, rel_tol)) {
        print_error("%s:%d: %s = %.17g, expected %.17g (diff %.3g, "
                    "tol %.3g abs + %.3g rel)\n",
                    file, line, what, actual, expected, actual - expected,
                    abs_tol, rel_tol);
        _fail(file, line);
    }
}

void se23t_assert_array_near(const se23_real_t *actual,
                             const se23_real_t *expected, int n,
                             double abs_tol, double rel_tol, const char *what,
                             const char *file, int line)
{
    for (int i = 0; i < n; ++i) {
        if (!se23t_near((double)actual[i], (double)expected[i], abs_tol,
                        rel_tol)) {
            print_error("%s:%d: %s[%d] = %.17g, expected %.17g (diff %.3g, "
                        "tol %.3g abs + %.3g rel)\n",
                        file, line, what, i, (double)actual[i],
                        (double)expected[i],
                        (double)actual[i] - (double)expected[i], abs_tol,
                        rel_tol);
            _fail(file, line);
        }
    }
}
