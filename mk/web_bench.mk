# SPDX-License-Identifier: MIT
# make bench-web: the web build's speed beside the native build's (see mk/web.mk).
#
# The kernels (bench/web/web_kernels.c: the full frame of 10^6 coverage
# dots at 800x600 and its parts, and a control) are built three ways: a
# native program on the native library (build/bench/bench_web_native), and
# a wasm module of their own with and without -msimd128
# (build/web/bench.wasm, bench-nosimd.wasm, timed by web/bench.html).
# tools/web_bench.py runs the native program and the page in headless
# Chromium in turn and prints them side by side, with each side's hashes.

WEB_BENCH_ROUNDS ?= 3
WEB_BENCH_NATIVE := $(BUILD)/bench/bench_web_native
WEB_BENCH_FILES  := $(WEB_OUT)/bench.html $(WEB_OUT)/bench.js $(WEB_OUT)/bench.wasm $(WEB_OUT)/bench-nosimd.wasm

.PHONY: bench-web bench-web-build
# The native side needs the native build's packages (deps), the browser's
# side wasm's (web-deps) and Chromium with its driver.
bench-web: deps web-deps
	@sh tools/deps.sh $(WEB_TEST_PKGS)
	@$(MAKE) --no-print-directory bench-web-build
	@python3 tools/web_bench.py $(WEB_BENCH_NATIVE) $(WEB_OUT) --rounds $(WEB_BENCH_ROUNDS)
bench-web-build: $(WEB_BENCH_NATIVE) $(WEB_BENCH_FILES)

# Native: the kernels on the native library, like every benchmark.
$(WEB_BENCH_NATIVE): $(BUILD)/obj/bench/web/bench_web_native.o $(BUILD)/obj/bench/web/web_kernels.o $(LIBA)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_CFLAGS) -o $@ $^ $(LDFLAGS) $(LIBS_CORE)

# wasm: the library as an archive (a module then takes only what the
# kernels call), once with -msimd128 (the objects of iskra.wasm) and once
# without.
WEB_NOSIMD_CFLAGS = $(filter-out -msimd128,$(WEB_CFLAGS))
WEB_LIB_NOSIMD_OBJ := $(WEB_LIB_OBJ:$(WEB)/obj/%=$(WEB)/obj-nosimd/%)
WEB_BENCH_SRC := bench/web/web_kernels.c web/bench_web.c

$(WEB)/obj-nosimd/%.o: %.c $(WEB_STAMP)
	@mkdir -p $(dir $@)
	$(call say,NOSIMD,$<)
	$(Q)$(WEB_CC) $(WEB_NOSIMD_CFLAGS) -MMD -MP -c $< -o $@
$(WEB)/obj-nosimd/src/scene/scene_builtin.o: $(WEB)/gen/scenes_gen.h

$(WEB)/lib-nosimd/libiskra.a: $(WEB_LIB_NOSIMD_OBJ)
	@mkdir -p $(dir $@)
	$(call say,AR,$@)
	$(Q)rm -f $@ && $(WEB_AR) rcs $@ $^

# Reactors, as iskra.wasm: no main; the page calls the exports.
WEB_BENCH_LINK = $(WEB_CC) -mexec-model=reactor -o $@ $^ -lm -Wl,-z,stack-size=1048576 -Wl,--strip-all
$(WEB_OUT)/bench.wasm: $(WEB_BENCH_SRC:%.c=$(WEB)/obj/%.o) $(WEB_LIBA)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(WEB_BENCH_LINK)
$(WEB_OUT)/bench-nosimd.wasm: $(WEB_BENCH_SRC:%.c=$(WEB)/obj-nosimd/%.o) $(WEB)/lib-nosimd/libiskra.a
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(WEB_BENCH_LINK)
# (lld finds symbols in archives in any order.)
$(WEB_OUT)/bench.wasm $(WEB_OUT)/bench-nosimd.wasm: $(WEB_LIBS)

-include $(shell find $(WEB)/obj-nosimd -name '*.d' 2>/dev/null)
