/* A planted out-of-bounds read and a signed overflow: the sanitizer build
 * of tests/check.d/20-unit.sh must reject this program (the step that
 * proves the sanitizer steps can fail). */
#include <limits.h>

int main(int argc, char **argv)
{
    int a[2] = {0, 0};
    int big = INT_MAX - 1 + argc; /* INT_MAX for argc = 1 */
    (void)argv;
    return a[argc + 1] + (big + argc);
}
