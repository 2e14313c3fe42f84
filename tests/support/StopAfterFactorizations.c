// A batch scheduler's SIGTERM in the middle of a Newton step, for the tests of a stop that
// takes effect within one iteration. Preloaded into vesica-simulate (LD_PRELOAD), it counts
// CHOLMOD's numeric factorisations — one per Newton iteration on a positive-definite
// tangent — and raises SIGTERM at the K-th, K being $VESICA_TEST_STOP_AFTER_FACTORIZATIONS;
// the signal then travels the product's own path (handler, flag, checkpoint).
// The signatures are CHOLMOD's, with its structures left opaque.
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <signal.h>
#include <stddef.h>
#include <stdlib.h>

typedef int (*factorize_p_fn)(void* A, double beta[2], int* fset, size_t fsize, void* L,
                              void* common);

int cholmod_factorize_p(void* A, double beta[2], int* fset, size_t fsize, void* L,
                        void* common) {
  static factorize_p_fn real;
  static long calls;
  if (!real) real = (factorize_p_fn)dlsym(RTLD_NEXT, "cholmod_factorize_p");
  const char* k = getenv("VESICA_TEST_STOP_AFTER_FACTORIZATIONS");
  if (k && ++calls == atol(k)) raise(SIGTERM);
  return real ? real(A, beta, fset, fsize, L, common) : 0;
}
