# iskra — GNU make build.
#
#   make            libraries, the iskra tool, examples, tests, benchmarks
#   make test       install missing Debian packages, build, run every test
#   make test SANITIZE=1   the same under AddressSanitizer + UBSan (build-san/)
#   make run        install missing packages, then run the main demo
#   make bench      run the benchmarks (ratios measured in one run)
#   make install PREFIX=/usr/local DESTDIR=   headers, libraries, iskra.pc, iskra
#
# Sources are discovered, not listed: every src/**/*.c goes into libiskra
# except src/io/sdl_*.c (libiskra-sdl); every examples/*.c, tests/test_*.c and
# bench/*.c is its own program.  Adding a file needs no Makefile edit.

PREFIX  ?= /usr/local
DESTDIR ?=
VERSION := 0.1.0

CC      ?= cc
ifeq ($(origin CC),default)
CC := gcc
endif

ifeq ($(SANITIZE),1)
BUILD   ?= build-san
SANFLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
OPT     ?= -O1 -g
else
BUILD   ?= build
SANFLAGS :=
OPT     ?= -O3 -g
endif

# Warnings are errors in CI (CI=true is set by the CI runner) or on request.
ifneq ($(CI),)
WERROR ?= 1
endif
ifeq ($(WERROR),1)
WFLAGS := -Werror
endif

# -ffp-contract=off: no fused multiply-add, so the same source gives the same
# bits everywhere (the thesis trajectories are reproduced bit for bit).
# Never fast-math (it reassociates and breaks bit-exactness).
CSTD    := -std=c11 -D_POSIX_C_SOURCE=200809L
CFLAGS_BASE := $(CSTD) $(OPT) -Wall -Wextra -Wpedantic -ffp-contract=off -fno-math-errno \
               -fPIC $(WFLAGS) $(SANFLAGS) -Iinclude -Isrc
CFLAGS  ?=
ALL_CFLAGS = $(CFLAGS_BASE) $(CFLAGS)
LDFLAGS ?=

PKG_PNG  = $(shell pkg-config --cflags --libs libpng 2>/dev/null || echo -lpng)
PKG_SDL_CFLAGS = $(shell pkg-config --cflags sdl2 2>/dev/null)
PKG_SDL_LIBS   = $(shell pkg-config --libs sdl2 2>/dev/null || echo -lSDL2)
PKG_INIH = $(shell pkg-config --cflags --libs inih 2>/dev/null || echo -linih)
PKG_CRIT = $(shell pkg-config --cflags --libs criterion 2>/dev/null || echo -lcriterion)

LIB_SRC  := $(filter-out src/io/sdl_%.c,$(wildcard src/*/*.c))
SDL_SRC  := $(wildcard src/io/sdl_*.c)
TOOL_SRC := $(wildcard tools/iskra/*.c)
EX_SRC   := $(wildcard examples/*.c)
TEST_SRC := $(wildcard tests/test_*.c)
TEST_SUPPORT_SRC := $(filter-out $(TEST_SRC),$(wildcard tests/*.c))
BENCH_SRC := $(wildcard bench/*.c)

LIB_OBJ  := $(LIB_SRC:%.c=$(BUILD)/obj/%.o)
SDL_OBJ  := $(SDL_SRC:%.c=$(BUILD)/obj/%.o)
TOOL_OBJ := $(TOOL_SRC:%.c=$(BUILD)/obj/%.o)
TEST_SUPPORT_OBJ := $(TEST_SUPPORT_SRC:%.c=$(BUILD)/obj/%.o)

LIBA     := $(BUILD)/lib/libiskra.a
LIBSO    := $(BUILD)/lib/libiskra.so
SDLA     := $(BUILD)/lib/libiskra-sdl.a
SDLSO    := $(BUILD)/lib/libiskra-sdl.so
TOOL     := $(BUILD)/bin/iskra
EXAMPLES := $(EX_SRC:examples/%.c=$(BUILD)/examples/%)
TESTS    := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)
BENCHES  := $(BENCH_SRC:bench/%.c=$(BUILD)/bench/%)

LIBS_CORE = $(PKG_PNG) $(PKG_INIH) -lm

# Quiet by default; `make V=1` shows full command lines.
ifeq ($(V),1)
Q :=
say = @true
else
Q := @
say = @printf '  %-6s %s\n' $(1) $(2)
endif
LIBS_SDL  = $(PKG_SDL_LIBS)

.PHONY: all lib examples tests benches test test-run run bench install uninstall clean deps help fuzz
# Objects are intermediate files of the program rules; keep them (no
# deletion noise, no rebuilds).
.SECONDARY:
.DEFAULT_GOAL := all

all: lib $(TOOL) examples tests benches

lib: $(LIBA) $(LIBSO) $(SDLA) $(SDLSO)
examples: $(EXAMPLES)
tests: $(TESTS)
benches: $(BENCHES)

# ---- objects -------------------------------------------------------------
$(BUILD)/obj/src/io/sdl_%.o: src/io/sdl_%.c
	@mkdir -p $(dir $@)
	$(call say,CC,$<)
	$(Q)$(CC) $(ALL_CFLAGS) $(PKG_SDL_CFLAGS) -MMD -MP -c $< -o $@

$(BUILD)/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(call say,CC,$<)
	$(Q)$(CC) $(ALL_CFLAGS) $(PKG_SDL_CFLAGS) -MMD -MP -c $< -o $@

# ---- libraries -----------------------------------------------------------
$(LIBA): $(LIB_OBJ)
	@mkdir -p $(dir $@)
	$(call say,AR,$@)
	$(Q)rm -f $@ && ar rcs $@ $^

$(LIBSO): $(LIB_OBJ)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) -shared $(SANFLAGS) -Wl,-soname,libiskra.so.0 -o $@ $^ $(LDFLAGS) $(LIBS_CORE)

$(SDLA): $(SDL_OBJ)
	@mkdir -p $(dir $@)
	$(call say,AR,$@)
	$(Q)rm -f $@ && ar rcs $@ $^

$(SDLSO): $(SDL_OBJ) $(LIBSO)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) -shared $(SANFLAGS) -Wl,-soname,libiskra-sdl.so.0 -o $@ $(SDL_OBJ) $(LDFLAGS) -L$(BUILD)/lib -liskra $(LIBS_SDL) $(LIBS_CORE)

# ---- programs (statically linked against our own libraries) ----------------
$(TOOL): $(TOOL_OBJ) $(SDLA) $(LIBA)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_CFLAGS) -o $@ $(TOOL_OBJ) $(SDLA) $(LIBA) $(LDFLAGS) $(PKG_INIH) $(LIBS_SDL) $(LIBS_CORE)

$(BUILD)/examples/%: $(BUILD)/obj/examples/%.o $(SDLA) $(LIBA)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_CFLAGS) -o $@ $< $(SDLA) $(LIBA) $(LDFLAGS) $(LIBS_SDL) $(LIBS_CORE)

$(BUILD)/tests/%: $(BUILD)/obj/tests/%.o $(TEST_SUPPORT_OBJ) $(SDLA) $(LIBA)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_CFLAGS) -o $@ $< $(TEST_SUPPORT_OBJ) $(SDLA) $(LIBA) $(LDFLAGS) $(PKG_CRIT) $(PKG_INIH) $(LIBS_SDL) $(LIBS_CORE)

$(BUILD)/bench/%: $(BUILD)/obj/bench/%.o $(LIBA)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_CFLAGS) -o $@ $< $(LIBA) $(LDFLAGS) $(LIBS_CORE)

# The example list, generated so tests can run every example.
$(BUILD)/gen/examples.txt: FORCE
	@mkdir -p $(dir $@)
	@printf '%s\n' $(EX_SRC:examples/%.c=%) > $@.tmp
	@cmp -s $@.tmp $@ || mv $@.tmp $@; rm -f $@.tmp
FORCE:

# ---- built-in scenes --------------------------------------------------------
# scenes/*.ini are embedded into libiskra (isk_scene_builtin_*, `iskra list`):
# the generated header changes only when a scene does, and then the object,
# the libraries and the iskra tool are rebuilt.
SCENE_FILES := $(wildcard scenes/*.ini)
$(BUILD)/gen/scenes_gen.h: tools/embed_scenes.sh $(SCENE_FILES) FORCE
	@mkdir -p $(dir $@)
	$(Q)sh tools/embed_scenes.sh $@ $(SCENE_FILES)
$(BUILD)/obj/src/scene/scene_builtin.o: $(BUILD)/gen/scenes_gen.h
$(BUILD)/obj/src/scene/scene_builtin.o: ALL_CFLAGS += -I$(BUILD)/gen

# ---- test / run / bench ----------------------------------------------------
# `make test` first makes sure the Debian packages are there, then builds and
# runs in a sub-make (so the package check finishes before pkg-config is read).
test: deps
	@$(MAKE) --no-print-directory test-run

test-run: all $(BUILD)/gen/examples.txt
	@BUILD=$(BUILD) sh tests/run_all.sh

run: deps
	@$(MAKE) --no-print-directory all
	@BUILD=$(BUILD) sh tools/run_demo.sh

bench: deps
	@$(MAKE) --no-print-directory benches $(TOOL)
	@set -e; for b in $(BENCHES); do echo "== $$b"; $$b; done
	@echo "== iskra bench accuracy"; $(TOOL) bench accuracy --out out/accuracy

# ---- peer benchmark (bench_peers) ------------------------------------------
# bench/bench_peers/ times iskra's primitives against cairo, pixman, AGG (a
# small C++ file), SDL2 and SDL2_gfx from Debian.  `make bench` installs them
# (not `make test`); when they cannot be had, it says so and skips the run.
# A sub-make builds it, so packages installed a moment before are seen.
PEER_PKGS := g++ libcairo2-dev libpixman-1-dev libagg-dev libsdl2-gfx-dev
PEER_CXX  ?= g++
PEER_MODS := cairo pixman-1 libagg SDL2_gfx sdl2
PEER_OK   := $(shell pkg-config --exists $(PEER_MODS) 2>/dev/null && command -v $(PEER_CXX) >/dev/null 2>&1 && echo 1)
PEER_BIN  := $(BUILD)/bench/bench_peers
PEER_OBJ  := $(BUILD)/obj/bench/bench_peers/bench_peers.o $(BUILD)/obj/bench/bench_peers/peer_agg.o
.PHONY: bench-peers peer-deps peer-run
bench: bench-peers
peer-deps: deps
	@sh tools/deps.sh $(PEER_PKGS) || echo "bench_peers: could not install $(PEER_PKGS)"
bench-peers: peer-deps
	@$(MAKE) --no-print-directory peer-run
ifeq ($(PEER_OK),1)
# the peers' headers are system headers: their warnings are not ours
PEER_CFLAGS := $(patsubst -I%,-isystem %,$(shell pkg-config --cflags $(PEER_MODS)))
$(BUILD)/obj/bench/bench_peers/bench_peers.o: bench/bench_peers/bench_peers.c
	@mkdir -p $(dir $@)
	$(call say,CC,$<)
	$(Q)$(CC) $(ALL_CFLAGS) $(PEER_CFLAGS) -MMD -MP -c $< -o $@
$(BUILD)/obj/bench/bench_peers/peer_agg.o: bench/bench_peers/peer_agg.cpp bench/bench_peers/peer_agg.h
	@mkdir -p $(dir $@)
	$(call say,CXX,$<)
	$(Q)$(PEER_CXX) -std=c++11 $(OPT) -Wall -Wextra $(WFLAGS) $(SANFLAGS) $(PEER_CFLAGS) -c $< -o $@
$(PEER_BIN): $(PEER_OBJ) $(LIBA)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(PEER_CXX) $(OPT) $(SANFLAGS) -o $@ $(PEER_OBJ) $(LIBA) $(LDFLAGS) \
	    $(shell pkg-config --libs $(PEER_MODS)) $(LIBS_CORE)
peer-run: $(PEER_BIN)
	@echo "== $(PEER_BIN)"; $(PEER_BIN)
else
peer-run:
	@echo "== bench_peers: skipped (needs the Debian packages $(PEER_PKGS))"
endif

# ---- fuzzing (clang + libFuzzer) -------------------------------------------
# `make fuzz [FUZZ_TIME=600]`: the scene parser and runtime under libFuzzer
# with ASan+UBSan, seeded with scenes/*.ini (the corpus grows in
# $(BUILD)/fuzz/corpus); crashers are written to tests/fuzz/regressions/.
FUZZ_TIME ?= 600
FUZZ_CC   ?= clang
FUZZ_DEPS := clang libclang-rt-14-dev
FUZZ_BIN  := $(BUILD)/fuzz/fuzz_scene
FUZZ_CFLAGS := $(CSTD) -g -O1 -ffp-contract=off -fno-math-errno -Iinclude -Isrc -I$(BUILD)/gen \
               -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined

.PHONY: fuzz-deps fuzz-run
fuzz-deps:
	@sh tools/deps.sh $(FUZZ_DEPS)

fuzz: fuzz-deps
	@$(MAKE) --no-print-directory fuzz-run

$(FUZZ_BIN): tests/fuzz/fuzz_scene.c $(LIB_SRC) $(BUILD)/gen/scenes_gen.h
	@mkdir -p $(dir $@)
	$(call say,FUZZCC,$@)
	$(Q)$(FUZZ_CC) $(FUZZ_CFLAGS) -o $@ tests/fuzz/fuzz_scene.c $(LIB_SRC) $(PKG_PNG) $(PKG_INIH) -lm

fuzz-run: $(FUZZ_BIN)
	@mkdir -p $(BUILD)/fuzz/corpus tests/fuzz/regressions
	@cp scenes/*.ini $(BUILD)/fuzz/corpus/
	@echo "fuzz: running for $(FUZZ_TIME) s (crashers go to tests/fuzz/regressions/)"
	@set +e; $(FUZZ_BIN) -max_total_time=$(FUZZ_TIME) -max_len=8192 -timeout=10 -rss_limit_mb=2048 \
	    -print_final_stats=1 -artifact_prefix=tests/fuzz/regressions/ $(BUILD)/fuzz/corpus \
	    > $(BUILD)/fuzz/log 2>&1; rc=$$?; \
	grep -E '^(Done|==[0-9]+==ERROR|SUMMARY)|Test unit written|^INFO: Seed' $(BUILD)/fuzz/log; \
	echo "fuzz: $$(sed -n 's/^stat::number_of_executed_units: *//p' $(BUILD)/fuzz/log) executions," \
	     "exit status $$rc (full log: $(BUILD)/fuzz/log)"; exit $$rc

# ---- dependencies (Debian) -------------------------------------------------
DEB_PKGS := build-essential pkg-config libpng-dev libsdl2-dev libcriterion-dev libinih-dev
deps:
	@sh tools/deps.sh $(DEB_PKGS)

# ---- install ---------------------------------------------------------------
LIBDIR ?= $(PREFIX)/lib
INCDIR ?= $(PREFIX)/include
BINDIR ?= $(PREFIX)/bin
PCDIR  ?= $(LIBDIR)/pkgconfig

install: lib $(TOOL)
	install -d $(DESTDIR)$(INCDIR)/iskra $(DESTDIR)$(LIBDIR) $(DESTDIR)$(BINDIR) $(DESTDIR)$(PCDIR)
	install -m 644 include/iskra.h $(DESTDIR)$(INCDIR)/iskra.h
	install -m 644 include/iskra/*.h $(DESTDIR)$(INCDIR)/iskra/
	install -m 644 $(LIBA) $(SDLA) $(DESTDIR)$(LIBDIR)/
	install -m 755 $(LIBSO) $(DESTDIR)$(LIBDIR)/libiskra.so.$(VERSION)
	ln -sf libiskra.so.$(VERSION) $(DESTDIR)$(LIBDIR)/libiskra.so.0
	ln -sf libiskra.so.0 $(DESTDIR)$(LIBDIR)/libiskra.so
	install -m 755 $(SDLSO) $(DESTDIR)$(LIBDIR)/libiskra-sdl.so.$(VERSION)
	ln -sf libiskra-sdl.so.$(VERSION) $(DESTDIR)$(LIBDIR)/libiskra-sdl.so.0
	ln -sf libiskra-sdl.so.0 $(DESTDIR)$(LIBDIR)/libiskra-sdl.so
	install -m 755 $(TOOL) $(DESTDIR)$(BINDIR)/iskra
	sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@LIBDIR@|$(LIBDIR)|g' -e 's|@INCDIR@|$(INCDIR)|g' \
	    -e 's|@VERSION@|$(VERSION)|g' iskra.pc.in > $(DESTDIR)$(PCDIR)/iskra.pc
	sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@LIBDIR@|$(LIBDIR)|g' -e 's|@INCDIR@|$(INCDIR)|g' \
	    -e 's|@VERSION@|$(VERSION)|g' iskra-sdl.pc.in > $(DESTDIR)$(PCDIR)/iskra-sdl.pc

uninstall:
	rm -f $(DESTDIR)$(INCDIR)/iskra.h
	rm -rf $(DESTDIR)$(INCDIR)/iskra
	rm -f $(DESTDIR)$(LIBDIR)/libiskra.a $(DESTDIR)$(LIBDIR)/libiskra-sdl.a
	rm -f $(DESTDIR)$(LIBDIR)/libiskra.so* $(DESTDIR)$(LIBDIR)/libiskra-sdl.so*
	rm -f $(DESTDIR)$(PCDIR)/iskra.pc $(DESTDIR)$(PCDIR)/iskra-sdl.pc
	rm -f $(DESTDIR)$(BINDIR)/iskra

clean:
	rm -rf build build-san out

help:
	@sed -n '1,12p' Makefile

-include $(shell find $(BUILD)/obj -name '*.d' 2>/dev/null)
