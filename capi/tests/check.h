/*
 * check.h: result reporting shared by the capi test programs (C99 and C++11).
 *
 * Every line goes to stdout, so stderr carries only the libraries' own warnings and a runner
 * can compare it with the expected Webots messages. A failed check is reported and counted; the
 * program goes on so that one run shows every failure, and check_finish() turns the count into
 * the exit status (0 only if every check passed). No libm function is used, so the programs
 * link without -lm.
 */

#ifndef CAPI_TEST_CHECK_H
#define CAPI_TEST_CHECK_H

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

static const char *check_program = "test";
static int check_count = 0;
static int check_failures = 0;

/* Names the program in every output line. */
static inline void check_begin(const char *program) {
  check_program = program;
  printf("%s: start\n", program);
}

/* |x|, without libm. */
static inline double check_abs(double x) {
  return x < 0.0 ? -x : x;
}

/* Records one check; `ok` false reports a failure with the printf-style description. */
static inline int check_true(int ok, const char *format, ...) {
  va_list args;
  check_count++;
  if (!ok)
    check_failures++;
  printf("%s: %s: ", check_program, ok ? "ok" : "FAIL");
  va_start(args, format);
  vprintf(format, args);
  va_end(args);
  printf("\n");
  return ok;
}

/* |actual - expected| <= tolerance (absolute). NaN always fails. */
static inline int check_close(const char *what, double actual, double expected, double tolerance) {
  return check_true(check_abs(actual - expected) <= tolerance, "%s = %.9g, expected %.9g +- %.3g", what, actual, expected,
                    tolerance);
}

/* |actual - expected| <= relative * |expected| (relative tolerance). NaN always fails. */
static inline int check_rel(const char *what, double actual, double expected, double relative) {
  const double tolerance = relative * check_abs(expected);
  return check_true(check_abs(actual - expected) <= tolerance, "%s = %.9g, expected %.9g +- %.3g %%", what, actual, expected,
                    100.0 * relative);
}

/* actual == expected for integers (and enumerations). */
static inline int check_int(const char *what, long actual, long expected) {
  return check_true(actual == expected, "%s = %ld, expected %ld", what, actual, expected);
}

/* A precondition the rest of the program depends on: report and exit(1) at once. */
static inline void check_fatal(const char *format, ...) {
  va_list args;
  printf("%s: FATAL: ", check_program);
  va_start(args, format);
  vprintf(format, args);
  va_end(args);
  printf("\n");
  fflush(stdout);
  exit(1);
}

/* Prints the summary; returns the exit status (0 if every check passed, else 1). */
static inline int check_finish(void) {
  if (check_failures == 0)
    printf("%s: PASS (%d checks)\n", check_program, check_count);
  else
    printf("%s: FAILED %d of %d checks\n", check_program, check_failures, check_count);
  fflush(stdout);
  return check_failures == 0 ? 0 : 1;
}

#endif /* CAPI_TEST_CHECK_H */
