/* SPDX-License-Identifier: MIT */
/* tests/wasm/criterion/logging.h — cr_log_info, cr_log_warn, cr_log_error
 * for the wasm tests: declared with the rest in criterion.h (this shim's),
 * as Criterion's own logging.h is included beside its criterion.h. */
#ifndef ISKRA_TESTS_WASM_CRITERION_LOGGING_H
#define ISKRA_TESTS_WASM_CRITERION_LOGGING_H

#include <criterion/criterion.h>

#endif
