/* SPDX-License-Identifier: MIT */
/* tests/wasm/criterion/parameterized.h — Criterion's parameterized tests
 * for the wasm tests (see criterion.h, this shim's):
 *
 *     ParameterizedTestParameters(suite, name) {
 *         static int shares[] = {0, 1, 2};
 *         return cr_make_param_array(int, shares, 3);
 *     }
 *     ParameterizedTest(int *share, suite, name, .timeout = 60) { ... *share ... }
 *
 * Each parameter is a test of its own, "suite::name/INDEX" in the runner's
 * list, given a pointer to its element of the array, as in Criterion. */
#ifndef ISKRA_TESTS_WASM_CRITERION_PARAMETERIZED_H
#define ISKRA_TESTS_WASM_CRITERION_PARAMETERIZED_H

#include <criterion/criterion.h>

#define ParameterizedTestParameters(S, N) static struct criterion_test_params CRW_ID(S, N, params)(void)

/* cr_make_param_array(Type, array, length [, cleanup]) */
#define cr_make_param_array(...)                                                                                  \
    ((struct criterion_test_params){.size = sizeof(CRW_ARG1(__VA_ARGS__)), .params = (CRW_ARG2(__VA_ARGS__)),    \
                                    .length = (CRW_ARG3(__VA_ARGS__)) CRW_REST_3(__VA_ARGS__)})

/* ParameterizedTest(Type *param, suite, name [, .option = value ...]) { body }:
 * the body takes the parameter as declared; a thunk of one signature for
 * all hands it the element's address. */
#define ParameterizedTest(...)                                                                                    \
    CRW_PTEST_(CRW_ARG1(__VA_ARGS__), CRW_ARG2(__VA_ARGS__), CRW_ARG3(__VA_ARGS__), CRW_REST_3(__VA_ARGS__))
#define CRW_PTEST_(P, S, N, ...) CRW_PTEST__(P, S, N, __VA_ARGS__)
#define CRW_PTEST__(P, S, N, ...)                                                                      \
    static struct criterion_test_params CRW_ID(S, N, params)(void);                                        \
    static void CRW_ID(S, N, body)(P);                                                                 \
    static void CRW_ID(S, N, thunk)(void *element)                                                         \
    {                                                                                                             \
        CRW_ID(S, N, body)(element);                                                                       \
    }                                                                                                             \
    static const struct criterion_test_extra_data CRW_ID(S, N, data) = {                                   \
        .suite = #S, .name = #N, .param_test = CRW_ID(S, N, thunk),                                 \
        .params = CRW_ID(S, N, params), .file = __FILE__, .line = __LINE__ __VA_ARGS__};                   \
    __attribute__((constructor)) static void CRW_ID(S, N, register)(void)                                  \
    {                                                                                                             \
        crw_register_test(&CRW_ID(S, N, data));                                                            \
    }                                                                                                             \
    static void CRW_ID(S, N, body)(P)

#endif
