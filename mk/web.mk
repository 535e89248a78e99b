# SPDX-License-Identifier: MIT
# iskra in the browser (docs/web.md).  Included by the Makefile.
#
#   make web          build/web/: index.html, iskra.js and iskra.wasm, a
#                     static site that works from any static server
#   make web-serve    serves it on http://127.0.0.1:$(WEB_PORT)/
#   make test-web     the library's tests in the wasm module (under Node),
#                     then the page in headless Chromium: every built-in
#                     scene's bytes against the native build, and the page
#                     driven by pointer and keys (tools/web_test.py)
#   make bench-web    the web build's speed beside the native build's
#
# The module is wasm32-wasi, built by Debian's clang, lld and wasi-libc;
# zlib, libpng and giflib come from Debian's source packages, built for it
# (tools/web_deps.sh), and libinih's one file from third_party/inih.  It is
# compiled with -msimd128 (the vector loops become wasm SIMD: the same
# bytes, tested) and runs on one thread (src/sim/pool_serial.c).

WEB       := build-web
WEB_OUT   := build/web
WEB_PORT  ?= 8000
WEB_CC    ?= clang --target=wasm32-wasi
WEB_AR    ?= llvm-ar
# Debian's wasi-libc: headers in /usr/include/wasm32-wasi, libraries in
# /usr/lib/wasm32-wasi.  -nostdlibinc keeps the host's /usr/include out.
WASI_INCLUDE ?= /usr/include/wasm32-wasi
WEB_OPT   ?= -O2
WEB_CFLAGS = -std=c11 -D_POSIX_C_SOURCE=200809L $(WEB_OPT) -msimd128 -ffp-contract=off -fno-math-errno \
             -Wall -Wextra -Wpedantic $(WFLAGS) -nostdlibinc -isystem $(WASI_INCLUDE) \
             -I$(WEB)/deps/include -Ithird_party/inih -Iinclude -Isrc -I$(WEB)/gen -Itools/iskra
WEB_DEPS_FLAGS = $(WEB_OPT) -msimd128 -ffp-contract=off -nostdlibinc -isystem $(WASI_INCLUDE)
WEB_PKGS := clang lld llvm wasi-libc libclang-rt-14-dev-wasm32 dpkg-dev

# The library, libinih, the simulator's files of the tool, the page's entry.
WEB_PLAY_SRC := $(wildcard tools/iskra/play_*.c) tools/iskra/scene_args.c tools/iskra/outpath.c tools/iskra/progress.c
WEB_SRC := $(LIB_SRC) third_party/inih/ini.c $(WEB_PLAY_SRC) web/iskra_web.c
WEB_OBJ := $(WEB_SRC:%.c=$(WEB)/obj/%.o)
WEB_LIBS := $(WEB)/deps/lib/libpng.a $(WEB)/deps/lib/libz.a $(WEB)/deps/lib/libgif.a
WEB_STAMP := $(WEB)/deps/.complete
WEB_FILES := $(WEB_OUT)/index.html $(WEB_OUT)/iskra.js $(WEB_OUT)/iskra.wasm

.PHONY: web web-deps web-build web-serve
web: web-deps
	@$(MAKE) --no-print-directory web-build
web-deps:
	@sh tools/deps.sh $(WEB_PKGS)
	@sh tools/web_deps.sh $(WEB)/deps "$(WEB_CC)" $(WEB_DEPS_FLAGS)
web-build: $(WEB_FILES)
	@echo "web: $(WEB_OUT)/ ($$(du -ck $(WEB_FILES) | tail -n 1 | cut -f1) KB): make web-serve, then open http://127.0.0.1:$(WEB_PORT)/"

$(WEB)/gen/scenes_gen.h: tools/embed_scenes.sh $(SCENE_FILES)
	@mkdir -p $(dir $@)
	$(Q)sh tools/embed_scenes.sh $@ $(SCENE_FILES)
$(WEB)/obj/src/scene/scene_builtin.o: $(WEB)/gen/scenes_gen.h

$(WEB)/obj/%.o: %.c $(WEB_STAMP)
	@mkdir -p $(dir $@)
	$(call say,WASM,$<)
	$(Q)$(WEB_CC) $(WEB_CFLAGS) -MMD -MP -c $< -o $@

# A reactor: no main; the page calls the functions web/iskra_web.c exports.
$(WEB_OUT)/iskra.wasm: $(WEB_OBJ) $(WEB_LIBS)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(WEB_CC) -mexec-model=reactor -o $@ $(WEB_OBJ) $(WEB_LIBS) -lm \
	    -Wl,-z,stack-size=1048576 -Wl,--strip-all
$(WEB_LIBS): $(WEB_STAMP)

# The library as an archive of the web build's objects, libinih's one file
# with it: a test module or the benchmark takes only what it calls.
WEB_LIBA := $(WEB)/lib/libiskra.a
WEB_LIB_OBJ := $(LIB_SRC:%.c=$(WEB)/obj/%.o) $(WEB)/obj/third_party/inih/ini.o
$(WEB_LIBA): $(WEB_LIB_OBJ)
	@mkdir -p $(dir $@)
	$(call say,AR,$@)
	$(Q)rm -f $@ && $(WEB_AR) rcs $@ $^
$(WEB_STAMP):
	@echo "web: run 'make web' (it builds the libraries for wasm first)" >&2; exit 1

$(WEB_OUT)/%: web/%
	@mkdir -p $(dir $@)
	$(Q)cp $< $@

# The page in headless Chromium against the native tool (tools/web_test.py).
WEB_TEST_PKGS := chromium chromium-driver python3
.PHONY: test-web test-web-page
test-web: web
	@sh tools/deps.sh $(WEB_TEST_PKGS)
	@$(MAKE) --no-print-directory test-web-unit
	@$(MAKE) --no-print-directory $(TOOL) test-web-page
test-web-page:
	@python3 tools/web_test.py $(TOOL) $(WEB_OUT)

web-serve: web
	@echo "web: serving $(WEB_OUT)/ on http://127.0.0.1:$(WEB_PORT)/ (Ctrl+C stops)"
	@cd $(WEB_OUT) && python3 -m http.server --bind 127.0.0.1 $(WEB_PORT)

# The library's tests in the wasm module (make test-web-unit), the
# benchmark (make bench-web).
include mk/web_tests.mk
include mk/web_bench.mk

-include $(shell find $(WEB)/obj -name '*.d' 2>/dev/null)
