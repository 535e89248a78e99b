/* SPDX-License-Identifier: MIT */
/* tests/wasm/criterion/criterion.h — the part of Criterion the tests use,
 * for the wasm build (make test-web-unit), where Criterion itself cannot
 * run: it forks a process per test.
 *
 *     #include <criterion/criterion.h>      // this file, found first by -Itests/wasm
 *     Test(rng, same_seed_same_numbers, .timeout = 10) {
 *         cr_assert_eq(a, b, "after %d draws", n);
 *     }
 *
 * The tests compile unchanged.  Each Test() registers itself (a
 * constructor) with tests/wasm/runner.c, whose main() runs them in
 * Criterion's order (by suite, then name).  One test per run: a failed
 * cr_assert ends it by exit(1), which ends the module — wasm32 with this
 * toolchain has no setjmp/longjmp to unwind a test and go on — so the Node
 * driver (tools/wasm_test_run.mjs) starts a fresh instance for each test,
 * as Criterion forks a fresh process for each.  A failed cr_expect is
 * counted and the test goes on; it fails at its end.
 *
 * What it keeps of Criterion: the old-style assertions (cr_assert_eq and
 * the rest, each with an optional printf-style message), cr_skip_test,
 * cr_log_*, TestSuite and the test options .init, .fini, .disabled,
 * .description and .timeout (accepted; the driver has no timer), and
 * ParameterizedTest (criterion/parameterized.h).  A failure prints
 * "FAIL FILE:LINE: cr_assert_eq(a, b): message".
 *
 * The macros take the assertion's arguments as one variadic list and pick
 * them apart with the preprocessor (CRW_ARG*, CRW_REST*), so that
 * cr_assert(x) and cr_assert(x, "fmt", ...) both compile without the
 * empty-__VA_ARGS__ warning of -Wpedantic, and every argument is evaluated
 * once, the message only on failure. */
#ifndef ISKRA_TESTS_WASM_CRITERION_H
#define ISKRA_TESTS_WASM_CRITERION_H

/* What Criterion's criterion.h brings in, which tests rely on. */
#include <stdbool.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

/* ---- what a test is ------------------------------------------------------ */

/* The options a Test() or TestSuite() may set, by designated initializer. */
struct criterion_test_extra_data {
    const char *suite, *name; /* set by Test() itself */
    void (*test)(void);       /* a plain test's body ... */
    void (*param_test)(void *param);                     /* ... or a parameterized one's, */
    struct criterion_test_params (*params)(void); /* with its parameters */
    const char *file;
    int line;
    void (*init)(void); /* before the test (after the suite's .init) */
    void (*fini)(void); /* after it (before the suite's .fini) */
    bool disabled;      /* registered, reported as skipped, never run */
    const char *description;
    double timeout; /* accepted and ignored: a wasm module cannot be interrupted from within */
    int exit_code;  /* accepted; a test must end by returning (0) */
    int signal;     /* accepted; there are no signals in wasm */
};

/* What a ParameterizedTestParameters function returns (cr_make_param_array). */
struct criterion_test_params {
    size_t size;   /* of one parameter */
    void *params;  /* the first */
    size_t length; /* how many */
    void (*cleanup)(struct criterion_test_params *);
};

void crw_register_test(const struct criterion_test_extra_data *test);
void crw_register_suite(const struct criterion_test_extra_data *suite);

/* ---- the preprocessor's tools ---------------------------------------------- */

#define CRW_CAT(a, b) CRW_CAT_(a, b)
#define CRW_CAT_(a, b) a##b
/* The first, second, third argument of a list (a dummy makes "..." never empty). */
#define CRW_ARG1(...) CRW_ARG1_(__VA_ARGS__, ~)
#define CRW_ARG1_(a, ...) a
#define CRW_ARG2(...) CRW_ARG2_(__VA_ARGS__, ~, ~)
#define CRW_ARG2_(a, b, ...) b
#define CRW_ARG3(...) CRW_ARG3_(__VA_ARGS__, ~, ~, ~)
#define CRW_ARG3_(a, b, c, ...) c
/* CRW_MORE_n(list): 1 when the list has more than n arguments, else 0 (up to 48). */
#define CRW_PICK(a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, \
                 a23, a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35, a36, a37, a38, a39, a40, a41, a42,   \
                 a43, a44, a45, a46, a47, a48, n, ...)                                                                 \
    n
#define CRW_ONES_45 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1
#define CRW_MORE_1(...) CRW_PICK_(__VA_ARGS__, CRW_ONES_45, 1, 1, 0, ~)
#define CRW_MORE_2(...) CRW_PICK_(__VA_ARGS__, CRW_ONES_45, 1, 0, 0, ~)
#define CRW_MORE_3(...) CRW_PICK_(__VA_ARGS__, CRW_ONES_45, 0, 0, 0, ~)
#define CRW_PICK_(...) CRW_PICK(__VA_ARGS__)
/* CRW_REST_n(list): ", the arguments after the n-th", or nothing. */
#define CRW_REST_1(...) CRW_CAT(CRW_REST_1_, CRW_MORE_1(__VA_ARGS__))(__VA_ARGS__)
#define CRW_REST_1_0(...)
#define CRW_REST_1_1(a, ...) , __VA_ARGS__
#define CRW_REST_2(...) CRW_CAT(CRW_REST_2_, CRW_MORE_2(__VA_ARGS__))(__VA_ARGS__)
#define CRW_REST_2_0(...)
#define CRW_REST_2_1(a, b, ...) , __VA_ARGS__
#define CRW_REST_3(...) CRW_CAT(CRW_REST_3_, CRW_MORE_3(__VA_ARGS__))(__VA_ARGS__)
#define CRW_REST_3_0(...)
#define CRW_REST_3_1(a, b, c, ...) , __VA_ARGS__
/* CRW_MSG_n(list): the message after the n-th argument, formatted, or NULL. */
#define CRW_MSG_1(...) CRW_CAT(CRW_MSG_1_, CRW_MORE_1(__VA_ARGS__))(__VA_ARGS__)
#define CRW_MSG_1_0(...) NULL
#define CRW_MSG_1_1(a, ...) crw_format(__VA_ARGS__)
#define CRW_MSG_2(...) CRW_CAT(CRW_MSG_2_, CRW_MORE_2(__VA_ARGS__))(__VA_ARGS__)
#define CRW_MSG_2_0(...) NULL
#define CRW_MSG_2_1(a, b, ...) crw_format(__VA_ARGS__)
#define CRW_MSG_3(...) CRW_CAT(CRW_MSG_3_, CRW_MORE_3(__VA_ARGS__))(__VA_ARGS__)
#define CRW_MSG_3_0(...) NULL
#define CRW_MSG_3_1(a, b, c, ...) crw_format(__VA_ARGS__)

/* ---- tests and suites ---------------------------------------------------- */

#define CRW_ID(S, N, what) crw_##S##_##N##_##what

/* Test(suite, name [, .option = value ...]) { body } */
#define Test(...) CRW_TEST_(CRW_ARG1(__VA_ARGS__), CRW_ARG2(__VA_ARGS__), CRW_REST_2(__VA_ARGS__))
#define CRW_TEST_(S, N, ...) CRW_TEST__(S, N, __VA_ARGS__)
#define CRW_TEST__(S, N, ...)                                                                              \
    static void CRW_ID(S, N, body)(void);                                                                  \
    static const struct criterion_test_extra_data CRW_ID(S, N, data) = {                                   \
        .suite = #S, .name = #N, .test = CRW_ID(S, N, body), .file = __FILE__,                      \
        .line = __LINE__ __VA_ARGS__};                                                                            \
    __attribute__((constructor)) static void CRW_ID(S, N, register)(void)                                  \
    {                                                                                                             \
        crw_register_test(&CRW_ID(S, N, data));                                                            \
    }                                                                                                             \
    static void CRW_ID(S, N, body)(void)

/* TestSuite(suite [, .init = f, .fini = g ...]); */
#define TestSuite(...) CRW_SUITE_(CRW_ARG1(__VA_ARGS__), CRW_REST_1(__VA_ARGS__))
#define CRW_SUITE_(S, ...) CRW_SUITE__(S, __VA_ARGS__)
#define CRW_SUITE__(S, ...)                                                                                   \
    static const struct criterion_test_extra_data crw_suite_##S = {.suite = #S, .file = __FILE__,         \
                                                                       .line = __LINE__ __VA_ARGS__};             \
    __attribute__((constructor)) static void crw_suite_register_##S(void)                                     \
    {                                                                                                             \
        crw_register_suite(&crw_suite_##S);                                                                   \
    }                                                                                                             \
    struct crw_suite_##S##_needs_a_semicolon

/* ---- assertions ----------------------------------------------------------- */

/* Formats a failure message (a buffer that lives until the next call);
 * an empty message is no message. */
const char *crw_format(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
/* Reports a failed check: "FAIL file:line: what: message".  `args` is the
 * check's arguments as written (stringized), of which the first `shown` are
 * printed.  fatal: the test ends here (exit 1); else it goes on and fails at
 * its end. */
void crw_fail(int fatal, const char *file, int line, const char *check, const char *args, int shown,
              const char *message);
/* Ends the test as skipped, saying why (message may be NULL). */
_Noreturn void crw_skip(const char *file, int line, const char *message);

#define CRW_CHECK(fatal, check, shown, ok, ...)                                                                   \
    do {                                                                                                          \
        if (!(ok))                                                                                                \
            crw_fail(fatal, __FILE__, __LINE__, check, #__VA_ARGS__, shown, CRW_MSG_##shown(__VA_ARGS__));        \
    } while (0)

#define CRW_STR_OK(a, op, b) ((a) != NULL && (b) != NULL && strcmp((a), (b)) op 0)
#define CRW_FLOAT_EQ(a, b, eps) ((b) - (a) <= (eps) && (a) - (b) <= (eps))
#define CRW_FLOAT_NEQ(a, b, eps) ((b) - (a) > (eps) || (a) - (b) > (eps))

#define cr_assert(...) CRW_CHECK(1, "cr_assert", 1, CRW_ARG1(__VA_ARGS__), __VA_ARGS__)
#define cr_expect(...) CRW_CHECK(0, "cr_expect", 1, CRW_ARG1(__VA_ARGS__), __VA_ARGS__)
#define cr_assert_not(...) CRW_CHECK(1, "cr_assert_not", 1, !(CRW_ARG1(__VA_ARGS__)), __VA_ARGS__)
#define cr_expect_not(...) CRW_CHECK(0, "cr_expect_not", 1, !(CRW_ARG1(__VA_ARGS__)), __VA_ARGS__)
#define cr_assert_null(...) CRW_CHECK(1, "cr_assert_null", 1, (CRW_ARG1(__VA_ARGS__)) == NULL, __VA_ARGS__)
#define cr_expect_null(...) CRW_CHECK(0, "cr_expect_null", 1, (CRW_ARG1(__VA_ARGS__)) == NULL, __VA_ARGS__)
#define cr_assert_not_null(...) CRW_CHECK(1, "cr_assert_not_null", 1, (CRW_ARG1(__VA_ARGS__)) != NULL, __VA_ARGS__)
#define cr_expect_not_null(...) CRW_CHECK(0, "cr_expect_not_null", 1, (CRW_ARG1(__VA_ARGS__)) != NULL, __VA_ARGS__)

#define CRW_OP(fatal, check, op, ...)                                                                             \
    CRW_CHECK(fatal, check, 2, (CRW_ARG1(__VA_ARGS__))op(CRW_ARG2(__VA_ARGS__)), __VA_ARGS__)
#define cr_assert_eq(...) CRW_OP(1, "cr_assert_eq", ==, __VA_ARGS__)
#define cr_expect_eq(...) CRW_OP(0, "cr_expect_eq", ==, __VA_ARGS__)
#define cr_assert_neq(...) CRW_OP(1, "cr_assert_neq", !=, __VA_ARGS__)
#define cr_expect_neq(...) CRW_OP(0, "cr_expect_neq", !=, __VA_ARGS__)
#define cr_assert_lt(...) CRW_OP(1, "cr_assert_lt", <, __VA_ARGS__)
#define cr_expect_lt(...) CRW_OP(0, "cr_expect_lt", <, __VA_ARGS__)
#define cr_assert_leq(...) CRW_OP(1, "cr_assert_leq", <=, __VA_ARGS__)
#define cr_expect_leq(...) CRW_OP(0, "cr_expect_leq", <=, __VA_ARGS__)
#define cr_assert_gt(...) CRW_OP(1, "cr_assert_gt", >, __VA_ARGS__)
#define cr_expect_gt(...) CRW_OP(0, "cr_expect_gt", >, __VA_ARGS__)
#define cr_assert_geq(...) CRW_OP(1, "cr_assert_geq", >=, __VA_ARGS__)
#define cr_expect_geq(...) CRW_OP(0, "cr_expect_geq", >=, __VA_ARGS__)

/* Strings: a NULL string fails the check (wasm reads address 0 without a
 * fault, so strcmp(NULL, ...) would not crash as it does natively). */
#define CRW_STR(fatal, check, op, ...)                                                                            \
    CRW_CHECK(fatal, check, 2, CRW_STR_OK(CRW_ARG1(__VA_ARGS__), op, CRW_ARG2(__VA_ARGS__)), __VA_ARGS__)
#define cr_assert_str_eq(...) CRW_STR(1, "cr_assert_str_eq", ==, __VA_ARGS__)
#define cr_expect_str_eq(...) CRW_STR(0, "cr_expect_str_eq", ==, __VA_ARGS__)
#define cr_assert_str_neq(...) CRW_STR(1, "cr_assert_str_neq", !=, __VA_ARGS__)
#define cr_expect_str_neq(...) CRW_STR(0, "cr_expect_str_neq", !=, __VA_ARGS__)
#define cr_assert_str_empty(...) CRW_CHECK(1, "cr_assert_str_empty", 1, *(CRW_ARG1(__VA_ARGS__)) == '\0', __VA_ARGS__)
#define cr_assert_str_not_empty(...)                                                                              \
    CRW_CHECK(1, "cr_assert_str_not_empty", 1, *(CRW_ARG1(__VA_ARGS__)) != '\0', __VA_ARGS__)

/* Within an epsilon, as Criterion: b - a <= eps and a - b <= eps (NaN fails). */
#define cr_assert_float_eq(...)                                                                                   \
    CRW_CHECK(1, "cr_assert_float_eq", 3,                                                                         \
              CRW_FLOAT_EQ(CRW_ARG1(__VA_ARGS__), CRW_ARG2(__VA_ARGS__), CRW_ARG3(__VA_ARGS__)), __VA_ARGS__)
#define cr_expect_float_eq(...)                                                                                   \
    CRW_CHECK(0, "cr_expect_float_eq", 3,                                                                         \
              CRW_FLOAT_EQ(CRW_ARG1(__VA_ARGS__), CRW_ARG2(__VA_ARGS__), CRW_ARG3(__VA_ARGS__)), __VA_ARGS__)
#define cr_assert_float_neq(...)                                                                                  \
    CRW_CHECK(1, "cr_assert_float_neq", 3,                                                                        \
              CRW_FLOAT_NEQ(CRW_ARG1(__VA_ARGS__), CRW_ARG2(__VA_ARGS__), CRW_ARG3(__VA_ARGS__)), __VA_ARGS__)

/* The first `size` bytes of two arrays. */
#define cr_assert_arr_eq(...)                                                                                     \
    CRW_CHECK(1, "cr_assert_arr_eq", 3,                                                                           \
              memcmp(CRW_ARG1(__VA_ARGS__), CRW_ARG2(__VA_ARGS__), CRW_ARG3(__VA_ARGS__)) == 0, __VA_ARGS__)
#define cr_assert_arr_neq(...)                                                                                    \
    CRW_CHECK(1, "cr_assert_arr_neq", 3,                                                                          \
              memcmp(CRW_ARG1(__VA_ARGS__), CRW_ARG2(__VA_ARGS__), CRW_ARG3(__VA_ARGS__)) != 0, __VA_ARGS__)

/* cr_assert_fail([fmt, ...]) and cr_expect_fail: a failure where they stand.
 * The message, if any, is a string literal ("" joins it; clang does not
 * warn of the empty format when there is none). */
#define cr_assert_fail(...) crw_fail(1, __FILE__, __LINE__, "cr_assert_fail", "", 0, crw_format("" __VA_ARGS__))
#define cr_expect_fail(...) crw_fail(0, __FILE__, __LINE__, "cr_expect_fail", "", 0, crw_format("" __VA_ARGS__))

/* cr_skip_test([fmt, ...]): the test ends here, counted as skipped. */
#define cr_skip_test(...) crw_skip(__FILE__, __LINE__, crw_format("" __VA_ARGS__))
#define cr_skip(...) cr_skip_test(__VA_ARGS__)

/* ---- logging (criterion/logging.h includes this file) --------------------- */

void cr_log_info(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void cr_log_warn(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void cr_log_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

#endif
