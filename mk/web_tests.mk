# SPDX-License-Identifier: MIT
# The library's unit tests in the wasm build (docs/web.md).  Included by
# mk/web.mk.
#
#   make test-web-unit   every tests/test_*.c not in tests/wasm/skip.txt,
#                        built for wasm32-wasi and run under Node's WASI
#                        from the repository root, a fresh instance per
#                        test (tools/wasm_test_run.mjs)
#
# The tests compile unchanged: tests/wasm/criterion/ stands in for
# Criterion's headers and tests/wasm/runner.c for its runner.  wasm32 is a
# 32-bit target, so this is where the library's sizes, limits and counts
# are tested with 32-bit size_t and pointers besides the i386 build.  A test
# file that cannot run here (it runs the iskra tool, reads a PNG file,
# needs threads or SDL) is in tests/wasm/skip.txt with the reason.

WEB_TEST_PKGS += nodejs
WEB_TEST_NODE ?= node
WEB_TEST_SKIP_FILE := tests/wasm/skip.txt
WEB_TEST_SKIP := $(shell sed -n 's/^\(test_[A-Za-z0-9_]*\)[[:space:]].*/\1/p' $(WEB_TEST_SKIP_FILE))
WEB_TEST_NAMES := $(filter-out $(WEB_TEST_SKIP),$(TEST_SRC:tests/%.c=%))
WEB_TEST_MODULES := $(WEB_TEST_NAMES:%=$(WEB)/tests/%.wasm)

# The tests' own helpers (refimg.c, key_case.c, ...), also an archive: a
# helper that needs what wasm lacks stays out of the modules that do not
# call it.  One that does not compile for wasm is left out of it.
WEB_TEST_SUPPORT_SRC := $(filter-out tests/tool_cli.c,$(TEST_SUPPORT_SRC))
WEB_TEST_SUPPORT := $(WEB)/tests/libsupport.a
WEB_TEST_RUNNER := $(WEB)/tests/obj/tests/wasm/runner.o

# Criterion's headers are this directory's; the tests' own headers are
# found beside them (tests/), as in the native build.
WEB_TEST_CFLAGS = -Itests/wasm $(WEB_CFLAGS)
# A native test has an 8 MiB stack; the stack first in memory, so that
# running off its end traps instead of writing over the data.  printf of a
# long double (%Lg) needs wasi-libc's library for it (without, it aborts).
WEB_TEST_LDFLAGS = -Wl,-z,stack-size=8388608 -Wl,--stack-first
WEB_TEST_LDLIBS = -lc-printscan-long-double -lm

.PHONY: test-web-unit web-test-deps web-test-unit-run
test-web-unit: web-deps web-test-deps
	@$(MAKE) --no-print-directory web-test-unit-run
web-test-deps:
	@sh tools/deps.sh $(WEB_TEST_PKGS)
web-test-unit-run: $(WEB_TEST_MODULES)
	@nice $(WEB_TEST_NODE) tools/wasm_test_run.mjs --skip $(WEB_TEST_SKIP_FILE) $(WEB_TEST_MODULES)

$(WEB)/tests/obj/%.o: %.c $(WEB_STAMP)
	@mkdir -p $(dir $@)
	$(call say,WASM,$<)
	$(Q)$(WEB_CC) $(WEB_TEST_CFLAGS) -MMD -MP -c $< -o $@

$(WEB_TEST_SUPPORT): $(WEB_TEST_SUPPORT_SRC:%.c=$(WEB)/tests/obj/%.o)
	@mkdir -p $(dir $@)
	$(call say,AR,$@)
	$(Q)rm -f $@ && $(WEB_AR) rcs $@ $^

$(WEB)/tests/%.wasm: $(WEB)/tests/obj/tests/%.o $(WEB_TEST_RUNNER) $(WEB_TEST_SUPPORT) $(WEB_LIBA) $(WEB_LIBS)
	$(call say,LD,$@)
	$(Q)$(WEB_CC) $(WEB_TEST_LDFLAGS) -o $@ $< $(WEB_TEST_RUNNER) $(WEB_TEST_SUPPORT) $(WEB_LIBA) $(WEB_LIBS) $(WEB_TEST_LDLIBS)

-include $(shell find $(WEB)/tests/obj -name '*.d' 2>/dev/null)
