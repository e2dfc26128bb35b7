/* Gate fixture: recursion, which the stack gate must reject. */
int fixture_recursion(int n);
int fixture_recursion(int n) { return n <= 0 ? 0 : 1 + fixture_recursion(n - 2) + fixture_recursion(n - 1); }
