/* SPDX-License-Identifier: MIT */
/* iskra/version.h — which iskra this is, at compile time and at run time.
 *
 * Example:
 *
 *     #if ISKRA_VERSION_MAJOR == 0 && ISKRA_VERSION_MINOR < 3
 *     #error "needs iskra 0.3 (the emitter in parts: e->born.rate)"
 *     #endif
 *     printf("built with %s, running %s\n", ISKRA_VERSION_STRING, isk_version());
 *
 * The one place the version is written: the Makefile reads it from here for
 * the shared libraries' names and iskra.pc, and `iskra --version` prints it.
 * Before 1.0 a minor version may change the ABI, so the shared library's
 * soname carries MAJOR.MINOR (libiskra.so.0.3).
 */
#ifndef ISKRA_VERSION_H
#define ISKRA_VERSION_H

#ifdef __cplusplus
extern "C" {
#endif

#define ISKRA_VERSION_MAJOR 0
#define ISKRA_VERSION_MINOR 3
#define ISKRA_VERSION_PATCH 0

#define ISKRA_VERSION_STR_(x) #x
#define ISKRA_VERSION_STR(x) ISKRA_VERSION_STR_(x)
#define ISKRA_VERSION_STRING                                                                                   \
    ISKRA_VERSION_STR(ISKRA_VERSION_MAJOR) "." ISKRA_VERSION_STR(ISKRA_VERSION_MINOR) "." ISKRA_VERSION_STR(   \
        ISKRA_VERSION_PATCH)

/* The version of the library the program runs with ("0.3.0"). */
const char *isk_version(void);

#ifdef __cplusplus
}
#endif

#endif
