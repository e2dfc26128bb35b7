/* Static-analysis fixture (tests/check.d/50-static.sh): a use of an
 * uninitialised variable that cppcheck and clang-tidy must both report. */
int fixture_uninit(int c);
int fixture_uninit(int c)
{
    int x;
    if (c > 0) {
        x = 1;
    }
    return x;
}
