# SPDX-License-Identifier: MIT
# iskra — GNU make build.
#
#   make            libraries, the iskra tool, examples, tests, benchmarks
#   make test       install missing Debian packages, build, run every test
#   make test SANITIZE=1   the same under AddressSanitizer + UBSan (build-san/)
#   make test SANITIZE=thread  ThreadSanitizer (build-tsan/; CI runs the threaded tests)
#   make test SANITIZE=clang   the same built by clang, with float-cast-overflow
#                  and integer-divide-by-zero too (build-clang/)
#   make test NATIVE=1     built with -march=native (build-native/): same bits
#   make test REFERENCE=1  every fast path compiled out (build-ref/): same bits
#   make test M32=1        a 32-bit x86 build (build-m32/): same bits, and
#                  every size and count checked where size_t has 32 bits
#                  (the library and tool only, said, where i386 programs
#                  cannot run)
#   make fuzz-smoke   every kept fuzz crasher and corpus file, then a short
#                  fuzz run of each target (scene, png, texture, live)
#   make run        install missing packages, build the iskra tool, run the main demo
#   make bench      run the benchmarks (ratios measured in one run)
#   make install PREFIX=/usr/local DESTDIR=   headers, libraries, iskra.pc, iskra,
#                its manual pages (an rpath in iskra.pc for a non-system LIBDIR;
#                RPATH=no|yes)
#   make man        write man/iskra.1 and man/iskra-scene.5 again (after a change
#                to a command's help, the key table or man/*.in)
#
# Sources are discovered, not listed: every src/**/*.c goes into libiskra
# except src/io/sdl_*.c (libiskra-sdl); every examples/*.c, tests/test_*.c and
# bench/*.c is its own program.  Adding a file needs no Makefile edit.

# Every build uses all the cores (a -j on the command line still wins; the
# sub-makes share the top make's jobs): built one file at a time, CI spent
# most of its time compiling.
ifeq ($(MAKELEVEL),0)
MAKEFLAGS += -j$(shell nproc 2>/dev/null || echo 1)
endif

PREFIX  ?= /usr/local
DESTDIR ?=
# The version is written once, in include/iskra/version.h.
version_part = $(shell sed -n 's/^\#define ISKRA_VERSION_$(1) \([0-9][0-9]*\).*/\1/p' include/iskra/version.h)
VERSION := $(call version_part,MAJOR).$(call version_part,MINOR).$(call version_part,PATCH)
# Before 1.0 a minor version may change the ABI: the soname carries it.
SOVERSION := $(call version_part,MAJOR).$(call version_part,MINOR)

CC      ?= cc
ifeq ($(origin CC),default)
CC := gcc
endif

ifeq ($(SANITIZE),1)
BUILD   ?= build-san
SANFLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
OPT     ?= -O1 $(DEBUG_INFO)
else ifeq ($(SANITIZE),clang)
# clang's UBSan also checks float -> integer conversions that overflow
# (gcc's -fsanitize=undefined has no float-cast-overflow) and integer
# division by zero, named here so no default can drop them.
BUILD   ?= build-clang
override CC := clang
SANFLAGS := -fsanitize=address,undefined,float-cast-overflow,integer-divide-by-zero \
            -fno-sanitize-recover=all -fno-omit-frame-pointer
OPT     ?= -O1 $(DEBUG_INFO)
else ifeq ($(SANITIZE),thread)
# ThreadSanitizer for what runs on several threads (CI runs the threaded
# check with it: make threads-check SANITIZE=thread).
BUILD   ?= build-tsan
SANFLAGS := -fsanitize=thread -fno-omit-frame-pointer
OPT     ?= -O1 $(DEBUG_INFO)
else ifeq ($(REFERENCE),1)
# Every fast path compiled out (src/core/fast_paths.h): one thread, no
# bands, no rest, dots one at a time, no fused motion, the portable loops.
# The build to read first; the suite passes in it against the same
# reference images, which is what proves each fast path gives its bytes.
BUILD   ?= build-ref
SANFLAGS := -DISKRA_REFERENCE=1
OPT     ?= -O2 $(DEBUG_INFO)
else ifeq ($(M32),1)
# A 32-bit x86 program (i386): where size_t, long and pointers have 32
# bits, a limit, a shift or a product that assumed 64 shows up.  gcc's
# multilib (-m32) with Debian's i386 libraries, which `make deps M32=1`
# fetches into $(BUILD)/sysroot (tools/m32_sysroot.sh says why there and
# not installed): found through pkg-config's sysroot, -isystem and -L, and
# at run time through LD_LIBRARY_PATH, which make exports to the tests and
# `make run` (an rpath would not do: libpulse, which SDL needs, carries a
# RUNPATH of its own, and the loader then ignores the program's rpath for
# libpulse's libraries).  By hand: LD_LIBRARY_PATH=$$(make -s m32-path M32=1).
# Criterion's .pc names -dev packages the sysroot leaves out: its
# fallback, -lcriterion.
# SSE2 arithmetic (-mfpmath=sse), not the x87 unit's 80-bit registers, so
# every double is rounded as on x86-64: the same reference images and
# thesis trajectories, byte for byte.
BUILD   ?= build-m32
M32_ACTIVE := 1
M32_SYSROOT = $(BUILD)/sysroot
M32_ROOT = $(abspath $(M32_SYSROOT))/root
M32_LIBDIRS = $(M32_ROOT)/usr/lib/i386-linux-gnu $(M32_ROOT)/lib/i386-linux-gnu \
              $(M32_ROOT)/usr/lib/i386-linux-gnu/pulseaudio
SANFLAGS = -m32 -msse2 -mfpmath=sse -isystem $(M32_ROOT)/usr/include -isystem $(M32_ROOT)/usr/include/i386-linux-gnu \
           $(addprefix -L,$(M32_LIBDIRS)) $(foreach d,$(M32_LIBDIRS),-Wl,-rpath-link,$(d))
export LD_LIBRARY_PATH = $(subst $(eval) ,:,$(strip $(M32_LIBDIRS)))
# The i386 libraries, for a test that sets its own library path (build_tree_link.sh).
export ISKRA_M32_LIBS = $(LD_LIBRARY_PATH)
OPT     ?= -O3 $(DEBUG_INFO) $(GCC_SCHEDULE)
PKG_CONFIG = PKG_CONFIG_SYSROOT_DIR=$(M32_ROOT) \
             PKG_CONFIG_LIBDIR=$(M32_ROOT)/usr/lib/i386-linux-gnu/pkgconfig:$(M32_ROOT)/usr/share/pkgconfig pkg-config
else ifeq ($(NATIVE),1)
# Opt-in: every loop compiled for this CPU's vector units.  The bits stay
# those of the portable build (-ffp-contract=off: no FMA; no
# reassociation), which `make test NATIVE=1` checks against the same
# reference images.  Not portable to older CPUs: for local use.
BUILD   ?= build-native
SANFLAGS := -march=native
OPT     ?= -O3 $(DEBUG_INFO) $(GCC_SCHEDULE)
else
BUILD   ?= build
SANFLAGS :=
OPT     ?= -O3 $(DEBUG_INFO) $(GCC_SCHEDULE)
endif

# gcc's first scheduling pass, off by default on x86: it interleaves
# independent dependency chains, so a long chain per particle (a potential's
# sqrt and division, then the integrator) no longer fills the processor's
# queues before the next particle's work is in them.  Order of instructions
# only, so the same bits (-ffp-contract=off still holds); what it buys:
# docs/performance.md, "Compiler flags".  -fsched-pressure keeps it from
# spilling registers.  Not a clang flag.
GCC_IS := $(shell $(CC) --version 2>/dev/null | grep -i 'free software foundation')
GCC_SCHEDULE := $(if $(GCC_IS),-fschedule-insns -fsched-pressure)

# Debug information, without gcc's tracking of where each variable lives at
# each instruction (var-tracking-assignments): that pass took half the
# compile time of the batched-drawing kernels and a fifth of CI's builds
# (docs/performance.md, "Compiler flags").  -g never changes the code, so
# the bits are the same; a debugger shows fewer locals in optimized frames.
DEBUG_INFO := -g $(if $(GCC_IS),-fno-var-tracking-assignments)

# gcc's loop distribution finds the copies of the start state that the
# fused motion loops store as they read (src/sim/motion_fused.c) and hoists
# them out as memcpy calls before the loop: a pass of its own that waits on
# memory with no arithmetic to overlap (docs/performance.md, "Compiler
# flags").  Only those files: elsewhere the memcpy idiom is welcome.
GCC_NO_COPY_IDIOM := $(if $(GCC_IS),-fno-tree-loop-distribute-patterns)
# (After the configurations above: SANITIZE=clang sets CC, and OPT, a
# recursive variable, reads GCC_SCHEDULE when it is used.)

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
# _FILE_OFFSET_BITS=64: 64-bit file offsets and inode numbers on 32-bit
# systems too, where stat() otherwise fails (EOVERFLOW) for a file over
# 2 GiB or on a file system with 64-bit inode numbers; no change on 64-bit.
CSTD    := -std=c11 -D_POSIX_C_SOURCE=200809L -D_FILE_OFFSET_BITS=64
CFLAGS_BASE := $(CSTD) $(OPT) -Wall -Wextra -Wpedantic -ffp-contract=off -fno-math-errno \
               -fPIC $(WFLAGS) $(SANFLAGS) -Iinclude -Isrc
CFLAGS  ?=
ALL_CFLAGS = $(CFLAGS_BASE) $(CFLAGS)
LDFLAGS ?=
# ... and a flag that brings it in by another name (CFLAGS=..., OPT=...) stops the build.
# Fast math itself (and -Ofast, finite-math-only) the compiler announces by
# macros, and src/sim/kernels.h stops at them in any build; these leave no trace.
VALUE_CHANGING_FLAGS := -funsafe-math-optimizations -fassociative-math -freciprocal-math -ffp-contract=fast
ifneq ($(filter $(VALUE_CHANGING_FLAGS),$(ALL_CFLAGS) $(LDFLAGS)),)
$(error $(filter $(VALUE_CHANGING_FLAGS),$(ALL_CFLAGS) $(LDFLAGS)) changes floating-point results: the reference images and the thesis trajectories are compared bit for bit)
endif

# pkg-config reads the .pc files of the build's target (M32=1: i386).
PKG_CONFIG ?= pkg-config
PKG_PNG  = $(shell $(PKG_CONFIG) --cflags --libs libpng 2>/dev/null || echo -lpng)
PKG_GIF  = $(shell $(PKG_CONFIG) --cflags --libs libgif 2>/dev/null || echo -lgif)
PKG_SDL_CFLAGS = $(shell $(PKG_CONFIG) --cflags sdl2 2>/dev/null)
PKG_SDL_LIBS   = $(shell $(PKG_CONFIG) --libs sdl2 2>/dev/null || echo -lSDL2)
PKG_INIH = $(shell $(PKG_CONFIG) --cflags --libs inih 2>/dev/null || echo -linih)
PKG_CRIT = $(shell $(PKG_CONFIG) --cflags --libs criterion 2>/dev/null || echo -lcriterion)

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
# The names the run-time loader looks for (the sonames): links to the
# libraries above, so a program linked against $(BUILD)/lib starts with
# LD_LIBRARY_PATH=$(BUILD)/lib (or an rpath to it).
SONAME_LINKS := $(LIBSO).$(SOVERSION) $(SDLSO).$(SOVERSION)
TOOL     := $(BUILD)/bin/iskra
EXAMPLES := $(EX_SRC:examples/%.c=$(BUILD)/examples/%)
TESTS    := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)
BENCHES  := $(BENCH_SRC:bench/%.c=$(BUILD)/bench/%)

LIBS_CORE = $(PKG_PNG) $(PKG_GIF) $(PKG_INIH) -lm -pthread

# Quiet by default; `make V=1` shows full command lines.
ifeq ($(V),1)
Q :=
say = @true
else
Q := @
say = @printf '  %-6s %s\n' $(1) $(2)
endif
LIBS_SDL  = $(PKG_SDL_LIBS)

.PHONY: all lib examples tests benches test test-run run bench install uninstall clean deps help fuzz man
# Objects are intermediate files of the program rules; keep them (no
# deletion noise, no rebuilds).
.SECONDARY:
.DEFAULT_GOAL := all

CXX_CHECK := $(BUILD)/tests/cxx_link
# Threads never change a byte (a plain program: it runs under TSan too).
THREADS_CHECK := $(BUILD)/tests/threads_check
# The iskra tool with allocation failure injection (tests/alloc/alloc_fail.c).
ALLOC_TOOL := $(BUILD)/tests/iskra_allocfail

all: lib $(TOOL) examples tests benches $(CXX_CHECK) $(ALLOC_TOOL) $(THREADS_CHECK)

lib: $(LIBA) $(LIBSO) $(SDLA) $(SDLSO) $(SONAME_LINKS)
examples: $(EXAMPLES)
tests: $(TESTS)
benches: $(BENCHES)

# ---- objects -------------------------------------------------------------
# SDL's compiler flags only where SDL's headers are read (iskra/sdl.h itself
# needs none).
$(BUILD)/obj/src/io/sdl_%.o: src/io/sdl_%.c
	@mkdir -p $(dir $@)
	$(call say,CC,$<)
	$(Q)$(CC) $(ALL_CFLAGS) $(PKG_SDL_CFLAGS) -MMD -MP -c $< -o $@

$(BUILD)/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(call say,CC,$<)
	$(Q)$(CC) $(ALL_CFLAGS) -MMD -MP -c $< -o $@

# The one test that drives SDL itself.
$(BUILD)/obj/tests/test_sdl.o: ALL_CFLAGS += $(PKG_SDL_CFLAGS)

# The fused motion loops keep their start-state stores (GCC_NO_COPY_IDIOM),
# in every build of them (motion_fused.c, motion_fused_avx2.c, ...).
$(BUILD)/obj/src/sim/motion_fused%.o: ALL_CFLAGS += $(GCC_NO_COPY_IDIOM)

# ---- libraries -----------------------------------------------------------
$(LIBA): $(LIB_OBJ)
	@mkdir -p $(dir $@)
	$(call say,AR,$@)
	$(Q)rm -f $@ && ar rcs $@ $^

$(LIBSO): $(LIB_OBJ) src/exports.map
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) -shared $(SANFLAGS) -Wl,-soname,libiskra.so.$(SOVERSION) -Wl,--version-script,src/exports.map \
	    -o $@ $(LIB_OBJ) $(LDFLAGS) $(LIBS_CORE)

$(SDLA): $(SDL_OBJ)
	@mkdir -p $(dir $@)
	$(call say,AR,$@)
	$(Q)rm -f $@ && ar rcs $@ $^

$(SDLSO): $(SDL_OBJ) $(LIBSO) src/exports.map
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) -shared $(SANFLAGS) -Wl,-soname,libiskra-sdl.so.$(SOVERSION) -Wl,--version-script,src/exports.map \
	    -o $@ $(SDL_OBJ) $(LDFLAGS) -L$(BUILD)/lib -liskra $(LIBS_SDL) $(LIBS_CORE)

$(SONAME_LINKS): $(BUILD)/lib/%.$(SOVERSION): $(BUILD)/lib/%
	$(call say,LN,$@)
	$(Q)ln -sf $(notdir $<) $@

# ---- programs (statically linked against our own libraries) ----------------
$(TOOL): $(TOOL_OBJ) $(SDLA) $(LIBA)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_CFLAGS) -o $@ $(TOOL_OBJ) $(SDLA) $(LIBA) $(LDFLAGS) $(PKG_INIH) $(LIBS_SDL) $(LIBS_CORE)

$(THREADS_CHECK): $(BUILD)/obj/tests/checks/threads_check.o $(LIBA)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_CFLAGS) -o $@ $^ $(LDFLAGS) $(LIBS_CORE)

# CI: the threaded paths under ThreadSanitizer (make threads-check SANITIZE=thread).
.PHONY: threads-check
threads-check: deps
	@$(MAKE) --no-print-directory $(THREADS_CHECK)
	@TSAN_OPTIONS=halt_on_error=1 $(THREADS_CHECK) --quick

$(ALLOC_TOOL): $(TOOL_OBJ) $(BUILD)/obj/tests/alloc/alloc_fail.o $(SDLA) $(LIBA)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_CFLAGS) -o $@ $^ -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc,--wrap=aligned_alloc \
	    $(LDFLAGS) $(PKG_INIH) $(LIBS_SDL) $(LIBS_CORE)

$(BUILD)/examples/%: $(BUILD)/obj/examples/%.o $(SDLA) $(LIBA)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_CFLAGS) -o $@ $< $(SDLA) $(LIBA) $(LDFLAGS) $(LIBS_SDL) $(LIBS_CORE)

$(BUILD)/tests/%: $(BUILD)/obj/tests/%.o $(TEST_SUPPORT_OBJ) $(SDLA) $(LIBA)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_CFLAGS) -o $@ $< $(TEST_SUPPORT_OBJ) $(SDLA) $(LIBA) $(LDFLAGS) $(PKG_CRIT) $(PKG_INIH) $(LIBS_SDL) $(LIBS_CORE)

# Every public header as C++: compiled with the C++ compiler, linked, run by
# tests/run_all.sh.
CXX     ?= c++
ifeq ($(origin CXX),default)
CXX := g++
endif
$(CXX_CHECK): tests/cxx_link.cpp $(wildcard include/*.h include/iskra/*.h) $(SDLA) $(LIBA)
	@mkdir -p $(dir $@)
	$(call say,CXX,$<)
	$(Q)$(CXX) -std=c++11 $(OPT) -Wall -Wextra -Wpedantic $(WFLAGS) $(SANFLAGS) -Iinclude -o $@ $< $(SDLA) $(LIBA) \
	    $(LDFLAGS) $(LIBS_SDL) $(LIBS_CORE)

$(BUILD)/bench/%: $(BUILD)/obj/bench/%.o $(LIBA)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_CFLAGS) -o $@ $< $(LIBA) $(LDFLAGS) $(LIBS_CORE)

# The example list, generated so tests can run every example.
$(BUILD)/gen/examples.txt: FORCE
	@mkdir -p $(dir $@)
	@printf '%s\n' $(EX_SRC:examples/%.c=%) > $@.tmp
	@cmp -s $@.tmp $@ || mv $@.tmp $@; rm -f $@.tmp
# Phony, or .SECONDARY would let it count as a missing intermediate file
# that forces nothing (a new example would never reach examples.txt).
.PHONY: FORCE
FORCE:

# The test suite's compiler and flags for tests/header_examples.sh, which
# builds every public header's usage example as a user's program: the
# public include path only, warnings always errors, linked like the tests.
$(BUILD)/gen/header_examples.env: FORCE
	@mkdir -p $(dir $@)
	@printf "EX_CC='%s'\nEX_CFLAGS='%s'\nEX_LIBS='%s'\nEX_SDL_LIBS='%s'\n" "$(CC)" \
	    "$(filter-out -Isrc -Werror,$(ALL_CFLAGS)) -Werror" "$(LIBA) $(LDFLAGS) $(LIBS_CORE)" \
	    "$(SDLA) $(LIBA) $(LDFLAGS) $(LIBS_SDL) $(LIBS_CORE)" > $@.tmp
	@cmp -s $@.tmp $@ || mv $@.tmp $@; rm -f $@.tmp

# ---- built-in scenes --------------------------------------------------------
# scenes/*.ini are embedded into libiskra (isk_scene_builtin_*, `iskra list`),
# with the textures they use (scenes/textures/*.png): the generated header
# changes only when one does, and then the object, the libraries and the
# iskra tool are rebuilt.
SCENE_FILES := $(wildcard scenes/*.ini) $(wildcard scenes/textures/*.png)
$(BUILD)/gen/scenes_gen.h: tools/embed_scenes.sh $(SCENE_FILES) FORCE
	@mkdir -p $(dir $@)
	$(Q)sh tools/embed_scenes.sh $@ $(SCENE_FILES)
$(BUILD)/obj/src/scene/scene_builtin.o: $(BUILD)/gen/scenes_gen.h
$(BUILD)/obj/src/scene/scene_builtin.o: ALL_CFLAGS += -I$(BUILD)/gen

# ---- test / run / bench ----------------------------------------------------
# `make test` first makes sure the Debian packages are there, then builds and
# runs in a sub-make (so the package check finishes before pkg-config is read).
# M32=1 on a machine that cannot run i386 programs builds the library and
# the tool (warnings as errors) and says why it runs no test.
test: deps
	@if [ "$(M32_ACTIVE)" != 1 ] || sh tools/m32_can_run.sh $(CC) $(BUILD); then \
	    $(MAKE) --no-print-directory test-run; else $(MAKE) --no-print-directory lib $(TOOL); fi

test-run: all $(BUILD)/gen/examples.txt $(BUILD)/gen/header_examples.env
	@BUILD=$(BUILD) sh tests/run_all.sh

# The demo needs the iskra tool alone (and the libraries it links): not the
# tests, examples or benchmarks `all` builds.
run: deps
	@$(MAKE) --no-print-directory $(TOOL)
	@BUILD=$(BUILD) sh tools/run_demo.sh

bench: deps
	@$(MAKE) --no-print-directory benches $(TOOL)
	@set -e; for b in $(BENCHES); do echo "== $$b"; $$b; done
	@echo "== iskra bench accuracy"; $(TOOL) bench accuracy --out out/accuracy

# ---- manual pages ------------------------------------------------------------
# man/iskra.1 and man/iskra-scene.5 are written from man/*.in by the iskra
# tool itself (every command's --help, `iskra keys --man`), and committed;
# tests/test_man_pages.c fails when they differ from what this writes.
man: $(TOOL)
	$(Q)sh tools/gen_man.sh $(TOOL) man

# ---- peer benchmark (bench_peers) ------------------------------------------
# bench/bench_peers/ times iskra's primitives against cairo, pixman, AGG (a
# small C++ file), SDL2 and SDL2_gfx from Debian.  `make bench` installs them
# (not `make test`); when they cannot be had, it says so and skips the run.
# A sub-make builds it, so packages installed a moment before are seen.
PEER_PKGS := g++ libcairo2-dev libpixman-1-dev libagg-dev libsdl2-gfx-dev
PEER_CXX  ?= g++
PEER_MODS := cairo pixman-1 libagg SDL2_gfx sdl2
PEER_OK   := $(shell $(PKG_CONFIG) --exists $(PEER_MODS) 2>/dev/null && command -v $(PEER_CXX) >/dev/null 2>&1 && echo 1)
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
PEER_CFLAGS := $(patsubst -I%,-isystem %,$(shell $(PKG_CONFIG) --cflags $(PEER_MODS)))
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
	    $(shell $(PKG_CONFIG) --libs $(PEER_MODS)) $(LIBS_CORE)
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
# `make fuzz-png [FUZZ_TIME=600]`: the PNG reader likewise, seeded with
# tests/fuzz/png_corpus/; crashers go to tests/fuzz/png_regressions/.
# `make fuzz-texture`: PNG bytes made into textures and drawn (seeds: the
# PNG corpus, scenes/textures/ and tests/fuzz/texture_corpus/); crashers to
# tests/fuzz/texture_regressions/.
# `make fuzz-live`: a scene, live changes and steps, then saved and
# reloaded to the same bytes (seeds: tests/fuzz/live_corpus/); crashers to
# tests/fuzz/live_regressions/.  The scene target's seeds are scenes/*.ini
# and tests/fuzz/scene_corpus/*.ini (prewarm, sub-emitter chains, textures).
FUZZ_TIME ?= 600
FUZZ_CC   ?= clang
FUZZ_DEPS := clang libclang-rt-14-dev
FUZZ_BIN  := $(BUILD)/fuzz/fuzz_scene
FUZZ_FLAGS := $(CSTD) -g -O1 -ffp-contract=off -fno-math-errno -Iinclude -Isrc -I$(BUILD)/gen \
              -fno-sanitize-recover=undefined
FUZZ_SAN  := address,undefined
# The library compiled once for both targets, a file at a time on every
# core (one clang command per target compiling every file took most of
# CI's fuzz step: 266 s of which 32 s fuzzing), instrumented for the
# fuzzer but without its main.
FUZZ_OBJ := $(LIB_SRC:%.c=$(BUILD)/fuzz/obj/%.o)
FUZZ_LIBS = $(PKG_PNG) $(PKG_GIF) $(PKG_INIH) -lm

.PHONY: fuzz-deps fuzz-run fuzz-png fuzz-png-run fuzz-smoke fuzz-smoke-run
fuzz-deps:
	@sh tools/deps.sh $(FUZZ_DEPS)

fuzz: fuzz-deps
	@$(MAKE) --no-print-directory fuzz-run

$(BUILD)/fuzz/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(call say,FUZZCC,$<)
	$(Q)$(FUZZ_CC) $(FUZZ_FLAGS) -fsanitize=fuzzer-no-link,$(FUZZ_SAN) -MMD -MP -c $< -o $@
$(BUILD)/fuzz/obj/src/scene/scene_builtin.o: $(BUILD)/gen/scenes_gen.h

# Each target: its tests/fuzz/fuzz_NAME.c with libFuzzer's main.
$(BUILD)/fuzz/fuzz_%: tests/fuzz/fuzz_%.c $(FUZZ_OBJ)
	$(call say,FUZZLD,$@)
	$(Q)$(FUZZ_CC) $(FUZZ_FLAGS) -fsanitize=fuzzer,$(FUZZ_SAN) -o $@ $< $(FUZZ_OBJ) $(FUZZ_LIBS)

# $(call run_fuzzer,BINARY,CORPUS,CRASHER_DIR,MAX_LEN,SECONDS): fuzz, then
# print the summary lines and the number of executions.
run_fuzzer = set +e; $(1) -max_total_time=$(5) -max_len=$(4) -timeout=10 -rss_limit_mb=2048 \
	    -print_final_stats=1 -artifact_prefix=$(3)/ $(2) > $(1).log 2>&1; rc=$$?; \
	grep -E '^(Done|==[0-9]+==ERROR|SUMMARY)|Test unit written|^INFO: Seed' $(1).log; \
	echo "fuzz $(notdir $(1)): $$(sed -n 's/^stat::number_of_executed_units: *//p' $(1).log) executions," \
	     "exit status $$rc (full log: $(1).log)"; exit $$rc

FUZZ_SCENE_SEEDS := scenes/*.ini tests/fuzz/scene_corpus/*.ini
FUZZ_TEXTURE_SEEDS := tests/fuzz/png_corpus/* scenes/textures/*.png tests/fuzz/texture_corpus/*
FUZZ_LIVE_SEEDS := tests/fuzz/live_corpus/*

fuzz-run: $(FUZZ_BIN)
	@mkdir -p $(BUILD)/fuzz/corpus tests/fuzz/regressions
	@cp $(FUZZ_SCENE_SEEDS) $(BUILD)/fuzz/corpus/
	@echo "fuzz: running for $(FUZZ_TIME) s (crashers go to tests/fuzz/regressions/)"
	@$(call run_fuzzer,$(FUZZ_BIN),$(BUILD)/fuzz/corpus,tests/fuzz/regressions,8192,$(FUZZ_TIME))

FUZZ_PNG_BIN := $(BUILD)/fuzz/fuzz_png

fuzz-png: fuzz-deps
	@$(MAKE) --no-print-directory fuzz-png-run

fuzz-png-run: $(FUZZ_PNG_BIN)
	@mkdir -p $(BUILD)/fuzz/png-corpus tests/fuzz/png_regressions
	@cp tests/fuzz/png_corpus/* $(BUILD)/fuzz/png-corpus/
	@echo "fuzz: the PNG reader for $(FUZZ_TIME) s (crashers go to tests/fuzz/png_regressions/)"
	@$(call run_fuzzer,$(FUZZ_PNG_BIN),$(BUILD)/fuzz/png-corpus,tests/fuzz/png_regressions,65536,$(FUZZ_TIME))

FUZZ_TEXTURE_BIN := $(BUILD)/fuzz/fuzz_texture
FUZZ_LIVE_BIN := $(BUILD)/fuzz/fuzz_live
.PHONY: fuzz-texture fuzz-texture-run fuzz-live fuzz-live-run

fuzz-texture: fuzz-deps
	@$(MAKE) --no-print-directory fuzz-texture-run

fuzz-texture-run: $(FUZZ_TEXTURE_BIN)
	@mkdir -p $(BUILD)/fuzz/texture-corpus tests/fuzz/texture_regressions
	@cp $(FUZZ_TEXTURE_SEEDS) $(BUILD)/fuzz/texture-corpus/
	@echo "fuzz: textures for $(FUZZ_TIME) s (crashers go to tests/fuzz/texture_regressions/)"
	@$(call run_fuzzer,$(FUZZ_TEXTURE_BIN),$(BUILD)/fuzz/texture-corpus,tests/fuzz/texture_regressions,65536,$(FUZZ_TIME))

fuzz-live: fuzz-deps
	@$(MAKE) --no-print-directory fuzz-live-run

fuzz-live-run: $(FUZZ_LIVE_BIN)
	@mkdir -p $(BUILD)/fuzz/live-corpus tests/fuzz/live_regressions
	@cp $(FUZZ_LIVE_SEEDS) $(BUILD)/fuzz/live-corpus/
	@echo "fuzz: live changes, save and reload for $(FUZZ_TIME) s (crashers go to tests/fuzz/live_regressions/)"
	@$(call run_fuzzer,$(FUZZ_LIVE_BIN),$(BUILD)/fuzz/live-corpus,tests/fuzz/live_regressions,16384,$(FUZZ_TIME))

# CI's smoke test: every kept crasher and seed once (each must pass), then
# FUZZ_SMOKE_TIME seconds of fuzzing per target from the seeds; anything it
# finds lands in $(BUILD)/fuzz/smoke/ (copy it to the target's crasher
# folder to keep it).
FUZZ_SMOKE_TIME ?= 15
fuzz-smoke: fuzz-deps
	@$(MAKE) --no-print-directory fuzz-smoke-run

# $(call replay,BINARY,NAME,FILES): each file once; the log's tail on failure.
replay = $(1) -timeout=10 -rss_limit_mb=2048 $(3) > $(BUILD)/fuzz/smoke/replay-$(2).log 2>&1 || \
	{ tail -n 30 $(BUILD)/fuzz/smoke/replay-$(2).log; exit 1; }

fuzz-smoke-run: $(FUZZ_BIN) $(FUZZ_PNG_BIN) $(FUZZ_TEXTURE_BIN) $(FUZZ_LIVE_BIN)
	@rm -rf $(BUILD)/fuzz/smoke && mkdir -p $(BUILD)/fuzz/smoke/scene $(BUILD)/fuzz/smoke/png \
	    $(BUILD)/fuzz/smoke/texture $(BUILD)/fuzz/smoke/live
	@echo "fuzz-smoke: replaying kept crashers and seeds"
	@$(call replay,$(FUZZ_BIN),scene,tests/fuzz/regressions/* $(FUZZ_SCENE_SEEDS))
	@$(call replay,$(FUZZ_PNG_BIN),png,tests/fuzz/png_regressions/* tests/fuzz/png_corpus/*)
	@$(call replay,$(FUZZ_TEXTURE_BIN),texture,tests/fuzz/texture_regressions/* $(FUZZ_TEXTURE_SEEDS))
	@$(call replay,$(FUZZ_LIVE_BIN),live,tests/fuzz/live_regressions/* $(FUZZ_LIVE_SEEDS))
	@cp $(FUZZ_SCENE_SEEDS) $(BUILD)/fuzz/smoke/scene/ && cp tests/fuzz/png_corpus/* $(BUILD)/fuzz/smoke/png/ && \
	    cp $(FUZZ_TEXTURE_SEEDS) $(BUILD)/fuzz/smoke/texture/ && cp $(FUZZ_LIVE_SEEDS) $(BUILD)/fuzz/smoke/live/
	@$(call run_fuzzer,$(FUZZ_BIN),$(BUILD)/fuzz/smoke/scene,$(BUILD)/fuzz/smoke,8192,$(FUZZ_SMOKE_TIME))
	@$(call run_fuzzer,$(FUZZ_PNG_BIN),$(BUILD)/fuzz/smoke/png,$(BUILD)/fuzz/smoke,65536,$(FUZZ_SMOKE_TIME))
	@$(call run_fuzzer,$(FUZZ_TEXTURE_BIN),$(BUILD)/fuzz/smoke/texture,$(BUILD)/fuzz/smoke,65536,$(FUZZ_SMOKE_TIME))
	@$(call run_fuzzer,$(FUZZ_LIVE_BIN),$(BUILD)/fuzz/smoke/live,$(BUILD)/fuzz/smoke,16384,$(FUZZ_SMOKE_TIME))

# ---- dependencies (Debian) -------------------------------------------------
# M32=1: the multilib compiler (installed) and Debian's i386 libraries
# (fetched into the build's sysroot: tools/m32_sysroot.sh).
M32_DEB_PKGS := gcc-multilib g++-multilib
M32_RUNTIME  := libpng16-16 libgif7 libinih1 libcriterion3 libsdl2-2.0-0
M32_DEV      := libpng-dev zlib1g-dev libgif-dev libinih-dev libcriterion-dev libsdl2-dev
DEB_PKGS := build-essential pkg-config libpng-dev libgif-dev libsdl2-dev libcriterion-dev libinih-dev \
            $(if $(filter clang,$(SANITIZE)),$(FUZZ_DEPS)) $(if $(M32_ACTIVE),$(M32_DEB_PKGS))
deps:
	@sh tools/deps.sh $(DEB_PKGS)
ifeq ($(M32_ACTIVE),1)
	@sh tools/m32_sysroot.sh $(M32_SYSROOT) $(M32_RUNTIME) -- $(M32_DEV)
# The library path that runs build-m32's programs by hand (see M32=1 above).
.PHONY: m32-path
m32-path:
	@echo $(LD_LIBRARY_PATH)
endif

# ---- install ---------------------------------------------------------------
LIBDIR ?= $(PREFIX)/lib
INCDIR ?= $(PREFIX)/include
BINDIR ?= $(PREFIX)/bin
PCDIR  ?= $(LIBDIR)/pkgconfig
MANDIR ?= $(PREFIX)/share/man

# Programs built with `pkg-config --libs iskra` find libiskra.so at run time
# without LD_LIBRARY_PATH: for a LIBDIR outside the default system library
# directories the .pc files carry -Wl,-rpath,LIBDIR (RPATH=no leaves it out,
# RPATH=yes always puts it in).
RPATH ?= auto
MULTIARCH := $(shell $(CC) -print-multiarch 2>/dev/null)
SYSTEM_LIBDIRS := /lib /usr/lib /lib64 /usr/lib64 $(if $(MULTIARCH),/lib/$(MULTIARCH) /usr/lib/$(MULTIARCH))
PC_RPATH = $(if $(filter yes,$(RPATH)),-Wl$(,)-rpath$(,)$${libdir},$(if $(filter auto,$(RPATH)),$(if \
             $(filter $(patsubst %/,%,$(LIBDIR)),$(SYSTEM_LIBDIRS)),,-Wl$(,)-rpath$(,)$${libdir})))
, := ,
PC_SED = sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@LIBDIR@|$(LIBDIR)|g' -e 's|@INCDIR@|$(INCDIR)|g' \
             -e 's|@VERSION@|$(VERSION)|g' -e 's| @RPATH@|$(if $(PC_RPATH), $(PC_RPATH))|g'

install: lib $(TOOL)
	install -d $(DESTDIR)$(INCDIR)/iskra $(DESTDIR)$(LIBDIR) $(DESTDIR)$(BINDIR) $(DESTDIR)$(PCDIR)
	install -m 644 include/iskra.h $(DESTDIR)$(INCDIR)/iskra.h
	install -m 644 include/iskra/*.h $(DESTDIR)$(INCDIR)/iskra/
	install -m 644 $(LIBA) $(SDLA) $(DESTDIR)$(LIBDIR)/
	install -m 755 $(LIBSO) $(DESTDIR)$(LIBDIR)/libiskra.so.$(VERSION)
	ln -sf libiskra.so.$(VERSION) $(DESTDIR)$(LIBDIR)/libiskra.so.$(SOVERSION)
	ln -sf libiskra.so.$(SOVERSION) $(DESTDIR)$(LIBDIR)/libiskra.so
	install -m 755 $(SDLSO) $(DESTDIR)$(LIBDIR)/libiskra-sdl.so.$(VERSION)
	ln -sf libiskra-sdl.so.$(VERSION) $(DESTDIR)$(LIBDIR)/libiskra-sdl.so.$(SOVERSION)
	ln -sf libiskra-sdl.so.$(SOVERSION) $(DESTDIR)$(LIBDIR)/libiskra-sdl.so
	install -m 755 $(TOOL) $(DESTDIR)$(BINDIR)/iskra
	$(PC_SED) iskra.pc.in > $(DESTDIR)$(PCDIR)/iskra.pc
	$(PC_SED) iskra-sdl.pc.in > $(DESTDIR)$(PCDIR)/iskra-sdl.pc
	install -d $(DESTDIR)$(MANDIR)/man1 $(DESTDIR)$(MANDIR)/man5
	install -m 644 man/iskra.1 $(DESTDIR)$(MANDIR)/man1/iskra.1
	install -m 644 man/iskra-scene.5 $(DESTDIR)$(MANDIR)/man5/iskra-scene.5

uninstall:
	rm -f $(DESTDIR)$(INCDIR)/iskra.h
	rm -rf $(DESTDIR)$(INCDIR)/iskra
	rm -f $(DESTDIR)$(LIBDIR)/libiskra.a $(DESTDIR)$(LIBDIR)/libiskra-sdl.a
	rm -f $(DESTDIR)$(LIBDIR)/libiskra.so* $(DESTDIR)$(LIBDIR)/libiskra-sdl.so*
	rm -f $(DESTDIR)$(PCDIR)/iskra.pc $(DESTDIR)$(PCDIR)/iskra-sdl.pc
	rm -f $(DESTDIR)$(BINDIR)/iskra
	rm -f $(DESTDIR)$(MANDIR)/man1/iskra.1 $(DESTDIR)$(MANDIR)/man5/iskra-scene.5

clean:
	rm -rf build build-san build-clang build-tsan build-native build-ref build-m32 out

# The comment atop this file, up to its first blank line.
help:
	@sed -n '2,/^$$/p' Makefile
	@sed -n '4,/^#$$/p' Makefile

include mk/web.mk

-include $(shell find $(BUILD)/obj $(BUILD)/fuzz/obj -name '*.d' 2>/dev/null)
