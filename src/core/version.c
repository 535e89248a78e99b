/* SPDX-License-Identifier: MIT */
/* The library's version at run time (iskra/version.h). */
#include "iskra/version.h"

const char *isk_version(void) { return ISKRA_VERSION_STRING; }
