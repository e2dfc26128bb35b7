/* Gate fixture: a variable-length array, which the stack gate must reject
 * (its frame is "dynamic" in the -fcallgraph-info graph). */
int fixture_vla(int n);
int fixture_vla(int n)
{
    volatile int a[n];
    a[0] = n;
    return a[0];
}
