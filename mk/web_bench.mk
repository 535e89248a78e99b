# SPDX-License-Identifier: MIT
# make bench-web: the web build's speed beside the native build's (see mk/web.mk).
