/* SPDX-License-Identifier: MIT */
/* tests/sanitized.h — is this test built under AddressSanitizer?
 *
 *     #include "sanitized.h"
 *     #if TEST_SANITIZED
 *     enum { FRAMES = 1000 };   // instrumented builds: the same check, shorter
 *     #else
 *     enum { FRAMES = 10000 };
 *     #endif
 *
 * gcc says so with __SANITIZE_ADDRESS__, clang (before 16) only through
 * __has_feature(address_sanitizer): testing the first alone ran the clang
 * build's long tests at their full length. */
#ifndef ISKRA_TESTS_SANITIZED_H
#define ISKRA_TESTS_SANITIZED_H

#if defined(__SANITIZE_ADDRESS__)
#define TEST_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TEST_SANITIZED 1
#endif
#endif
#ifndef TEST_SANITIZED
#define TEST_SANITIZED 0
#endif

#endif
