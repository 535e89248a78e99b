/* SPDX-License-Identifier: MIT */
/* tests/wasm/runner.c — main() of every wasm test module (make test-web-unit):
 * the tests that tests/wasm/criterion/criterion.h registered, run in
 * Criterion's order (by suite, then by name).
 *
 *     test_rng.wasm --list        every test's id, one a line: suite::name
 *                                 (a parameterized test: suite::name/INDEX)
 *     test_rng.wasm --run ID      that test alone; exit status 0 passed,
 *                                 1 failed, 77 skipped
 *     test_rng.wasm               every test in turn, in this one instance;
 *                                 a failed cr_assert or a skip ends the run
 *
 * Each test prints one line: "ok ID", "skip ID: why", or for each failed
 * check "FAIL ID: FILE:LINE: check(args): message".  tools/wasm_test_run.mjs
 * lists a module's tests, then runs each with --run in a fresh instance,
 * as Criterion runs each in a fresh process: a failed cr_assert calls
 * exit(1) (wasm32 here has no longjmp to unwind a test and go on). */
#include <criterion/criterion.h>

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { EXIT_PASSED = 0, EXIT_FAILED = 1, EXIT_SKIPPED = 77, EXIT_USAGE = 2 };

/* The registry: filled by the constructors before main, read-only after. */
struct registry {
    const struct criterion_test_extra_data **tests, **suites;
    size_t n_tests, n_suites, cap_tests, cap_suites;
};
static struct registry registry;

/* The test under way (its id for the report lines) and its failed checks. */
static struct {
    char id[256];
    int failures;
} current;

static void append(const struct criterion_test_extra_data ***list, size_t *n, size_t *cap,
                   const struct criterion_test_extra_data *item)
{
    if (*n == *cap) {
        size_t grown = *cap ? 2 * *cap : 64;
        const struct criterion_test_extra_data **bigger = realloc((void *)*list, grown * sizeof **list);
        if (!bigger) {
            fputs("wasm runner: out of memory registering tests\n", stderr);
            exit(EXIT_FAILED);
        }
        *list = bigger;
        *cap = grown;
    }
    (*list)[(*n)++] = item;
}

void crw_register_test(const struct criterion_test_extra_data *test)
{
    append(&registry.tests, &registry.n_tests, &registry.cap_tests, test);
}

void crw_register_suite(const struct criterion_test_extra_data *suite)
{
    append(&registry.suites, &registry.n_suites, &registry.cap_suites, suite);
}

static int by_suite_then_name(const void *pa, const void *pb)
{
    const struct criterion_test_extra_data *a = *(const struct criterion_test_extra_data *const *)pa;
    const struct criterion_test_extra_data *b = *(const struct criterion_test_extra_data *const *)pb;
    int c = strcmp(a->suite, b->suite);
    return c ? c : strcmp(a->name, b->name);
}

static const struct criterion_test_extra_data *suite_of(const struct criterion_test_extra_data *test)
{
    for (size_t i = 0; i < registry.n_suites; i++)
        if (strcmp(registry.suites[i]->suite, test->suite) == 0)
            return registry.suites[i];
    return NULL;
}

/* How many tests one registration stands for: its parameters, or one. */
static size_t instances(const struct criterion_test_extra_data *test, struct criterion_test_params *params)
{
    if (!test->param_test)
        return 1;
    *params = test->params();
    return params->length;
}

/* ---- reports --------------------------------------------------------------- */

static char message[4096];

const char *crw_format(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(message, sizeof message, fmt, ap);
    va_end(ap);
    return message[0] ? message : NULL;
}

/* The first `shown` arguments of a stringized argument list: up to the
 * shown-th comma outside brackets, strings and character constants. */
static int shown_length(const char *args, int shown)
{
    int depth = 0, commas = 0;
    char quote = 0;
    for (int i = 0; args[i]; i++) {
        char c = args[i];
        if (quote) {
            if (c == '\\' && args[i + 1])
                i++;
            else if (c == quote)
                quote = 0;
        } else if (c == '"' || c == '\'') {
            quote = c;
        } else if (c == '(' || c == '[' || c == '{') {
            depth++;
        } else if (c == ')' || c == ']' || c == '}') {
            depth--;
        } else if (c == ',' && depth == 0 && ++commas == shown) {
            return i;
        }
    }
    return (int)strlen(args);
}

void crw_fail(int fatal, const char *file, int line, const char *check, const char *args, int shown,
              const char *why)
{
    printf("FAIL %s: %s:%d: %s(%.*s)%s%s\n", current.id, file, line, check, shown_length(args, shown), args,
           why ? ": " : "", why ? why : "");
    fflush(stdout);
    current.failures++;
    if (fatal)
        exit(EXIT_FAILED);
}

_Noreturn void crw_skip(const char *file, int line, const char *why)
{
    printf("skip %s: %s (%s:%d)\n", current.id, why ? why : "skipped", file, line);
    fflush(stdout);
    exit(EXIT_SKIPPED);
}

static void log_line(const char *level, const char *fmt, va_list ap)
{
    fflush(stdout);
    fprintf(stderr, "[%s] ", level);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
}

void cr_log_info(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    log_line("INFO", fmt, ap);
    va_end(ap);
}

void cr_log_warn(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    log_line("WARN", fmt, ap);
    va_end(ap);
}

void cr_log_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    log_line("ERR", fmt, ap);
    va_end(ap);
}

/* ---- running ----------------------------------------------------------------- */

static void set_id(const struct criterion_test_extra_data *test, size_t index)
{
    if (test->param_test)
        snprintf(current.id, sizeof current.id, "%s::%s/%zu", test->suite, test->name, index);
    else
        snprintf(current.id, sizeof current.id, "%s::%s", test->suite, test->name);
}

/* Runs one test (parameter `index` of a parameterized one) to its end:
 * the suite's .init, the test's, the body, the test's .fini, the suite's.
 * Returns its exit status; a failed cr_assert or a skip never returns. */
static int run_one(const struct criterion_test_extra_data *test, size_t index)
{
    const struct criterion_test_extra_data *suite = suite_of(test);
    set_id(test, index);
    current.failures = 0;
    if (test->disabled || (suite && suite->disabled)) {
        printf("skip %s: disabled\n", current.id);
        return EXIT_SKIPPED;
    }
    if (suite && suite->init)
        suite->init();
    if (test->init)
        test->init();
    if (test->param_test) {
        struct criterion_test_params params = test->params();
        test->param_test((char *)params.params + index * params.size);
        if (params.cleanup)
            params.cleanup(&params);
    } else {
        test->test();
    }
    if (test->fini)
        test->fini();
    if (suite && suite->fini)
        suite->fini();
    if (current.failures)
        return EXIT_FAILED;
    printf("ok %s\n", current.id);
    fflush(stdout);
    return EXIT_PASSED;
}

int main(int argc, char **argv)
{
    qsort((void *)registry.tests, registry.n_tests, sizeof *registry.tests, by_suite_then_name);
    int list = argc == 2 && strcmp(argv[1], "--list") == 0;
    const char *only = argc == 3 && strcmp(argv[1], "--run") == 0 ? argv[2] : NULL;
    if (argc > 1 && !list && !only) {
        fprintf(stderr, "usage: %s [--list | --run SUITE::NAME[/INDEX]]\n", argv[0]);
        return EXIT_USAGE;
    }
    int failed = 0;
    for (size_t t = 0; t < registry.n_tests; t++) {
        const struct criterion_test_extra_data *test = registry.tests[t];
        struct criterion_test_params params = {0};
        size_t n = instances(test, &params);
        for (size_t i = 0; i < n; i++) {
            set_id(test, i);
            if (list)
                puts(current.id);
            else if (only && strcmp(only, current.id) == 0)
                return run_one(test, i);
            else if (!only)
                failed |= run_one(test, i) == EXIT_FAILED;
        }
    }
    if (only) {
        fprintf(stderr, "%s: no test %s (--list lists them)\n", argv[0], only);
        return EXIT_USAGE;
    }
    return failed ? EXIT_FAILED : EXIT_PASSED;
}
