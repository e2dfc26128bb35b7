/* Gate fixture (tests/check.d/45-gates.sh): code every symbol gate must
 * reject when compiled for the M4F float build -- a double operation, a heap
 * call, stdio. Never linked into anything. */
#include <stdio.h>
#include <stdlib.h>

float fixture_double(float x);
float fixture_double(float x) { return (float)((double)x * 1.000000001); }

void *fixture_heap(int n);
void *fixture_heap(int n) { return malloc((size_t)n); }

void fixture_stdio(int n);
void fixture_stdio(int n) { printf("%d\n", n); }
