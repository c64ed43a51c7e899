/* STREAM's triad a = b + s c over arrays far larger than the caches, timed per pass: the memory bandwidth one
   process gets. bench/bandwidth.py runs one copy alone and two side by side (docs/performance.md, issue 27).
   Usage: stream [megabytes per array, default 200] [passes, default 20]; prints the best pass's GB/s. */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double Now(void)
{
  struct timespec t;

  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

int main(int argc, char **argv)
{
  const size_t mb     = argc > 1 ? (size_t)atol(argv[1]) : 200;
  const int    passes = argc > 2 ? atoi(argv[2]) : 20;
  const size_t n      = mb * 1024 * 1024 / sizeof(double);
  double      *a = malloc(n * sizeof(double)), *b = malloc(n * sizeof(double)), *c = malloc(n * sizeof(double));
  double       best = 1e30, sum = 0.0;

  if (!a || !b || !c || n == 0 || passes < 1) {
    fprintf(stderr, "stream: cannot allocate 3 arrays of %zu MB (or passes %d < 1)\n", mb, passes);
    return 1;
  }
  for (size_t i = 0; i < n; ++i) {
    a[i] = 0.0;
    b[i] = 1.0;
    c[i] = 2.0;
  }
  for (int p = 0; p < passes; ++p) {
    const double t0 = Now();

    for (size_t i = 0; i < n; ++i) a[i] = b[i] + 0.5 * c[i];
    const double t = Now() - t0;
    if (t < best) best = t;
    sum += a[p % n];
  }
  printf("%.3f GB/s (best of %d passes, 3 x %zu MB; check %g)\n", 3.0 * n * sizeof(double) / best / 1e9, passes, mb, sum);
  free(a);
  free(b);
  free(c);
  return 0;
}
