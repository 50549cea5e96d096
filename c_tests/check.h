/* A minimal test harness for the C tests: CHECK records a failure and goes on; the summary line
 * and the exit code tell CTest the result. Compiles as C11 and as C++17. */
#ifndef HALFWING_C_TESTS_CHECK_H
#define HALFWING_C_TESTS_CHECK_H

#include <stdio.h>
#include <string.h>

#include "halfwing.h"

static int check_passed = 0;
static int check_failed = 0;

#define CHECK(cond)                                                        \
  do {                                                                     \
    if (cond) {                                                            \
      check_passed++;                                                      \
    } else {                                                               \
      check_failed++;                                                      \
      fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); \
    }                                                                      \
  } while (0)

/* The call returns `status` and the last error message contains `needle`. */
#define CHECK_STATUS(call, status, needle)                                 \
  do {                                                                     \
    hw_status got_ = (call);                                               \
    CHECK(got_ == (status));                                               \
    CHECK(last_error_contains(needle));                                    \
  } while (0)

static inline int last_error_contains(const char *needle) {
  char message[1024];
  size_t needed = 0;
  if (hw_last_error_message(message, sizeof message, &needed) != HW_OK) return 0;
  if (strstr(message, needle) == NULL) {
    fprintf(stderr, "  last error \"%s\" lacks \"%s\"\n", message, needle);
    return 0;
  }
  return 1;
}

static inline int check_summary(const char *name) {
  printf("%s: %d passed, %d failed\n", name, check_passed, check_failed);
  return check_failed == 0 ? 0 : 1;
}

#endif
