# fflight: `make test` runs every test, `make demo` the main job. Both install the system
# packages they need first (apt-get as root, sudo otherwise).

CARGO ?= cargo
CC ?= cc
PACKAGES := libosmesa6-dev libglu1-mesa-dev pkg-config gcc g++ cmake binutils valgrind make python3 \
	xvfb libx11-dev libxext-dev libxrandr-dev libxinerama-dev libxcursor-dev libxi-dev \
	libgl-dev libgl1-mesa-dri
CFLAGS_STRICT := -std=c99 -Wall -Wextra -Werror -pedantic
LIB := target/debug/libfflight.a
DEMO_DIR := target/demo

.PHONY: all deps build test-build header test lint demo bench clean install uninstall test-install test-sanitize test-valgrind \
	test-window prefixed test-cinstall test-sweep-sanitize test-valgrind-rust fuzz fuzz-osmesa

all: build

deps:
	@missing=""; for p in $(PACKAGES); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
		echo "installing:$$missing"; \
		if [ "$$(id -u)" = 0 ]; then SUDO=""; else SUDO=sudo; fi; \
		$$SUDO apt-get update -qq && $$SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing; \
	fi

build: deps
	$(CARGO) build

# The debug library as `cargo test` builds it, with the tests: a plain `cargo build` resolves
# the dependencies' features without the dev-dependencies, and every switch between the two
# compiles the library again (25-40 s, three times in a make test).
DEBUG_BUILD := $(CARGO) build --lib --tests
test-build: deps
	$(DEBUG_BUILD)

# Regenerates include/fflight.h, include/fflight_prefixed.h and src/capi/generated.rs from the
# sources (tests/header.rs fails when one is stale).
header:
	FFLIGHT_BLESS=1 $(CARGO) build

lint:
	$(CARGO) fmt --check
	$(CARGO) clippy --all-targets -- -D warnings

test: test-build
	$(CARGO) test
	$(MAKE) --no-print-directory test-window
	$(MAKE) lint
	$(MAKE) --no-print-directory test-install
	$(MAKE) --no-print-directory test-sanitize
	$(MAKE) --no-print-directory test-sweep-sanitize
	$(MAKE) --no-print-directory test-valgrind
	$(MAKE) --no-print-directory test-valgrind-rust
	@echo "make test: target/ holds $$(du -sh target | cut -f1)"

# The demo scene (examples/demo/scene.c: a lit sphere on a lit floor, three lights) through
# fflight and through OSMesa, fed back and compared: a short summary, the raw rows in
# target/demo/{fflight,osmesa}.txt (VERBOSE=1 prints them side by side), and both renderings
# with a map of their differences in target/demo/fflight-vs-osmesa.png.
DEMO_PACKAGES := python3-pil
demo:
	@$(MAKE) --no-print-directory deps PACKAGES="$(PACKAGES) $(DEMO_PACKAGES)"
	$(CARGO) build
	@mkdir -p $(DEMO_DIR)
	$(CC) $(CFLAGS_STRICT) -D_DEFAULT_SOURCE examples/demo/scene.c $(LIB) -lm -lpthread -ldl -o $(DEMO_DIR)/scene_fflight
	$(CC) $(CFLAGS_STRICT) -D_DEFAULT_SOURCE -DUSE_OSMESA examples/demo/scene.c -lOSMesa -lm -o $(DEMO_DIR)/scene_osmesa
	$(DEMO_DIR)/scene_fflight > $(DEMO_DIR)/fflight.txt
	$(DEMO_DIR)/scene_osmesa > $(DEMO_DIR)/osmesa.txt
	@$(BENCH_PYTHON) examples/demo/compare.py $(DEMO_DIR)/fflight.txt $(DEMO_DIR)/osmesa.txt \
		--picture $(DEMO_DIR)/fflight-vs-osmesa.png $(if $(VERBOSE),--verbose,)

# fflight (release) vs OSMesa on the same scenes in the same run: one table of ns per vertex,
# speed ratios and targets (also target/bench/results.md), and a plot against the number of
# lights (target/bench/lights.png, copied to docs/bench-lights.png). A missed target is
# reported, not an error; a crash or a wrong feedback count is. BENCH_FLAGS=--vertices=N
# runs smaller scenes quickly.
BENCH_PACKAGES := python3-matplotlib
# Debian's interpreter, the one python3-matplotlib installs for (python3 on PATH may be a
# pyenv or virtualenv one).
BENCH_PYTHON := /usr/bin/python3
BENCH_DIR := target/bench
BENCH_CFLAGS := $(CFLAGS_STRICT) -O2 -Iinclude

bench:
	@$(MAKE) --no-print-directory deps PACKAGES="$(PACKAGES) $(BENCH_PACKAGES)"
	$(CARGO) build --release
	@mkdir -p $(BENCH_DIR)
	$(CC) $(BENCH_CFLAGS) examples/bench/bench.c target/release/libfflight.a -lm -lpthread -ldl -o $(BENCH_DIR)/bench_fflight
	$(CC) $(BENCH_CFLAGS) -DUSE_OSMESA examples/bench/bench.c -lOSMesa -lm -o $(BENCH_DIR)/bench_osmesa
	$(BENCH_PYTHON) examples/bench/run.py $(BENCH_DIR) $(BENCH_FLAGS)

clean:
	$(CARGO) clean

# Every GL entry point renamed ffl_glX in a static library of its own, for programs that also
# link a real GL library (docs/coexistence.md): target/prefixed/libfflight_prefixed.a, declared
# by include/fflight_prefixed.h (tests/prefixed.rs checks both and links one with OSMesa).
PREFIXED_LIB := target/prefixed/libfflight_prefixed.a
prefixed:
	$(if $(filter release,$(PROFILE)),$(CARGO) build --release,$(DEBUG_BUILD))
	@mkdir -p target/prefixed
	tools/prefix_library.sh target/$(PROFILE)/libfflight.a $(PREFIXED_LIB)

# ---- installation: make install PREFIX=/usr/local DESTDIR= (PROFILE=release) ----
# The shared library as libfflight.so.VERSION with the SONAME libfflight.so.MAJOR (set by
# build.rs) and its two links, the static library, the header, a pkg-config file and a CMake
# package (fflight::fflight). `make uninstall` removes exactly these files.
PREFIX ?= /usr/local
DESTDIR ?=
PROFILE ?= release
VERSION := $(shell sed -n 's/^version = "\(.*\)"/\1/p' Cargo.toml | head -1)
MAJOR := $(firstword $(subst ., ,$(VERSION)))
INSTALL_ROOT = $(DESTDIR)$(PREFIX)
INSTALLED = lib/libfflight.so.$(VERSION) lib/libfflight.so.$(MAJOR) lib/libfflight.so \
	lib/libfflight.a include/fflight.h lib/pkgconfig/fflight.pc \
	lib/libfflight_prefixed.a include/fflight_prefixed.h \
	lib/cmake/fflight/fflightConfig.cmake lib/cmake/fflight/fflightConfigVersion.cmake
SUBSTITUTE = sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@VERSION@|$(VERSION)|g' -e 's|@MAJOR@|$(MAJOR)|g'

install: prefixed
	install -d $(INSTALL_ROOT)/lib/pkgconfig $(INSTALL_ROOT)/lib/cmake/fflight $(INSTALL_ROOT)/include
	install -m 755 target/$(PROFILE)/libfflight.so $(INSTALL_ROOT)/lib/libfflight.so.$(VERSION)
	ln -sf libfflight.so.$(VERSION) $(INSTALL_ROOT)/lib/libfflight.so.$(MAJOR)
	ln -sf libfflight.so.$(MAJOR) $(INSTALL_ROOT)/lib/libfflight.so
	install -m 644 target/$(PROFILE)/libfflight.a $(INSTALL_ROOT)/lib/libfflight.a
	install -m 644 include/fflight.h $(INSTALL_ROOT)/include/fflight.h
	install -m 644 $(PREFIXED_LIB) $(INSTALL_ROOT)/lib/libfflight_prefixed.a
	install -m 644 include/fflight_prefixed.h $(INSTALL_ROOT)/include/fflight_prefixed.h
	$(SUBSTITUTE) build/install/fflight.pc.in > $(INSTALL_ROOT)/lib/pkgconfig/fflight.pc
	$(SUBSTITUTE) build/install/fflightConfig.cmake.in > $(INSTALL_ROOT)/lib/cmake/fflight/fflightConfig.cmake
	$(SUBSTITUTE) build/install/fflightConfigVersion.cmake.in > $(INSTALL_ROOT)/lib/cmake/fflight/fflightConfigVersion.cmake

uninstall:
	rm -f $(addprefix $(INSTALL_ROOT)/,$(INSTALLED))
	-rmdir $(INSTALL_ROOT)/lib/cmake/fflight 2>/dev/null

# Installs the debug build into a temporary prefix, builds a C program with pkg-config
# (shared and static) and a C++ program with CMake against it, runs them, checks the SONAME,
# uninstalls and checks that nothing of fflight is left.
INSTALL_TEST := $(CURDIR)/target/install-test
test-install:
	rm -rf $(INSTALL_TEST)
	$(MAKE) --no-print-directory install PROFILE=debug PREFIX=$(INSTALL_TEST)/prefix
	readelf -d $(INSTALL_TEST)/prefix/lib/libfflight.so | grep -q 'SONAME.*libfflight.so.$(MAJOR)'
	mkdir -p $(INSTALL_TEST)/build
	PKG_CONFIG_PATH=$(INSTALL_TEST)/prefix/lib/pkgconfig; export PKG_CONFIG_PATH; \
	$(CC) -std=c99 -Wall -Werror tests/install/hello.c $$(pkg-config --cflags --libs fflight) -lm \
		-o $(INSTALL_TEST)/build/hello_shared && \
	$(CC) -std=c99 -Wall -Werror tests/install/hello.c $$(pkg-config --cflags fflight) \
		$(INSTALL_TEST)/prefix/lib/libfflight.a $$(pkg-config --libs-only-other --static fflight) -lm -lpthread -ldl \
		-o $(INSTALL_TEST)/build/hello_static
	LD_LIBRARY_PATH=$(INSTALL_TEST)/prefix/lib $(INSTALL_TEST)/build/hello_shared
	$(INSTALL_TEST)/build/hello_static
	cmake -S tests/install -B $(INSTALL_TEST)/cmake -DCMAKE_PREFIX_PATH=$(INSTALL_TEST)/prefix > /dev/null
	cmake --build $(INSTALL_TEST)/cmake > /dev/null
	$(INSTALL_TEST)/cmake/hello_cmake
	$(MAKE) --no-print-directory uninstall PREFIX=$(INSTALL_TEST)/prefix
	test -z "$$(find $(INSTALL_TEST)/prefix -type f -o -type l)"

# cargo-c's install (`cargo cinstall`, Cargo.toml's [package.metadata.capi]) into a temporary
# root: the SONAME, the header, and tests/install/hello.c built against its pkg-config file,
# shared and static. Not run by `make test`: cargo-c itself takes about 45 minutes to build on
# 2 cores (`cargo install cargo-c --locked`; 0.10.24 is the last release for rustc 1.95).
CINSTALL_TEST := $(CURDIR)/target/cinstall-test
CINSTALL_PREFIX := $(CINSTALL_TEST)/root/usr/local
CINSTALL_PC = PKG_CONFIG_PATH=$(CINSTALL_PREFIX)/lib/pkgconfig pkg-config --define-variable=prefix=$(CINSTALL_PREFIX)
test-cinstall:
	@command -v cargo-cinstall > /dev/null || { echo "cargo-c is not installed: cargo install cargo-c --locked"; exit 1; }
	rm -rf $(CINSTALL_TEST)
	$(CARGO) cinstall --release --prefix=/usr/local --libdir=/usr/local/lib --destdir=$(CINSTALL_TEST)/root
	readelf -d $(CINSTALL_PREFIX)/lib/libfflight.so.$(VERSION) | grep -q 'SONAME.*libfflight.so.$(MAJOR)'
	cmp include/fflight.h $(CINSTALL_PREFIX)/include/fflight.h
	$(CC) -std=c99 -Wall -Werror tests/install/hello.c $$($(CINSTALL_PC) --cflags --libs fflight) -lm \
		-o $(CINSTALL_TEST)/hello_shared
	$(CC) -std=c99 -Wall -Werror tests/install/hello.c $$($(CINSTALL_PC) --cflags fflight) \
		$(CINSTALL_PREFIX)/lib/libfflight.a $$($(CINSTALL_PC) --libs-only-other --static fflight) -lm -lpthread -ldl \
		-o $(CINSTALL_TEST)/hello_static
	LD_LIBRARY_PATH=$(CINSTALL_PREFIX)/lib $(CINSTALL_TEST)/hello_shared
	$(CINSTALL_TEST)/hello_static

# ---- the C test programs under AddressSanitizer and UndefinedBehaviorSanitizer ----
# Each c_tests program, built against the debug libfflight.so with the sanitizers on the C
# side (the Rust library itself is not instrumented: its sanitizers need a nightly compiler)
# and run: any sanitizer report fails. Their outputs are checked by `cargo test`
# (tests/c_programs.rs). -O0 and the shared library: ASan and UBSan check every access as
# written, and a program builds in about 0.5 s, where -O1 -g and a static copy of the debug
# library took up to 9.
SANITIZE_DIR := target/sanitize
SANITIZE_FLAGS := -std=c99 -g -O0 -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
SANITIZE_PROGRAMS := $(patsubst c_tests/%.c,$(SANITIZE_DIR)/%.ok,$(wildcard c_tests/*.c))
# Under its SONAME, which the programs name and find by their run path.
SANITIZE_SO := $(SANITIZE_DIR)/lib/libfflight.so.0
test-sanitize: test-build
	@$(MAKE) --no-print-directory -j2 $(SANITIZE_PROGRAMS)
	@echo "test-sanitize: $(words $(SANITIZE_PROGRAMS)) programs under ASan and UBSan, no report"

$(SANITIZE_SO): target/debug/libfflight.so
	@mkdir -p $(@D) && cp $< $@

# One program: built, run, its sanitizer reports (stderr) grepped; a clean run leaves .ok, a
# report keeps the program. Client libraries (ffl-libs: libGLU) come before libfflight.so,
# which the loader searches before their own dependencies (libGL).
$(SANITIZE_DIR)/%.ok: c_tests/%.c c_tests/ffl_test.h $(SANITIZE_SO)
	@libs=$$(sed -n 's/.*ffl-libs:\(.*\)/\1/p' $< | head -1); \
	$(CC) $(SANITIZE_FLAGS) -Iinclude -Ic_tests $< $$libs $(SANITIZE_SO) \
		-Wl,-rpath,$(CURDIR)/$(SANITIZE_DIR)/lib -lm -lpthread -ldl -o $(@:.ok=)
	@ASAN_OPTIONS=detect_leaks=1 $(@:.ok=) > $(@:.ok=.txt) 2> $(@:.ok=.err) || true
	@if grep -q 'ERROR: AddressSanitizer\|ERROR: LeakSanitizer\|runtime error' $(@:.ok=.err); then \
		echo "sanitizer report: $*"; cat $(@:.ok=.err); exit 1; fi
	@touch $@ && rm -f $(@:.ok=)

# ---- valgrind memcheck over the C test programs ----
# Every fflight build of c_tests (made by `cargo test`: run that first) under memcheck, two at
# a time: any memory error or definite leak (threads that exit without destroying their
# default context included: thread_exit_context.c) fails. Exit statuses of the programs
# themselves are checked by `cargo test`. The longest first (thread_stress takes over 2
# minutes under memcheck, random_lighting and random_meshes about 30 s; the others 2-6 s),
# so that none is left running alone at the end. The library is loaded without its
# debugging information, which memcheck spends half a second reading for each program (2.2
# -> 1.7 s for a short one): a report names functions but not lines (for those, run the
# program under valgrind as it is, with target/c_tests/lib's library).
LONG_UNDER_MEMCHECK := thread_stress random_lighting random_meshes
VALGRIND_C_LIB := target/valgrind-c/lib
test-valgrind:
	@ls target/c_tests/*.fflight > /dev/null
	@mkdir -p $(VALGRIND_C_LIB) && strip --strip-debug -o $(VALGRIND_C_LIB)/libfflight.so.0 target/c_tests/lib/libfflight.so.0
	@{ for p in $(LONG_UNDER_MEMCHECK); do echo target/c_tests/$$p.fflight; done; \
		ls target/c_tests/*.fflight | grep -v $(foreach p,$(LONG_UNDER_MEMCHECK),-e /$(p).fflight); } | \
		LD_LIBRARY_PATH=$(CURDIR)/$(VALGRIND_C_LIB) xargs -P2 -I{} sh -c \
		'valgrind -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite {} \
		> /dev/null 2> {}.valgrind; if [ $$? = 99 ]; then echo "valgrind: {}"; cat {}.valgrind; exit 255; fi'
	@echo "test-valgrind: $$(ls target/c_tests/*.fflight | wc -l) programs under memcheck, no error, no definite leak"

# ---- legacy lighting in a real OpenGL 3.3 core window (examples/modern_window) ----
# fflight's capture of a legacy lighting routine drawn in a GLFW core profile context, compared
# pixel by pixel with Mesa's own fixed-function lighting in a compatibility context; writes
# target/window/fflight-vs-gl.png (docs/fflight-vs-gl.png is a copy). Under a private Xvfb
# when there is no $DISPLAY (tools/with-display.sh); LIBGL_ALWAYS_SOFTWARE=1 keeps both
# contexts on llvmpipe. About 2 s after `cargo test`, which compiles the examples (and GLFW
# from source, with cmake). It depends on deps, not build: a plain `cargo build` compiles the
# library without the dev-dependencies, and switching between the two rebuilds it.
WINDOW_DIR := target/window
test-window: deps
	@mkdir -p $(WINDOW_DIR)
	$(CARGO) build --example modern_window
	LIBGL_ALWAYS_SOFTWARE=1 tools/with-display.sh \
		timeout 120 target/debug/examples/modern_window $(WINDOW_DIR)/fflight-vs-gl.png
# ---- the entry-point sweep under ASan and UBSan (tests/sweep.rs, run by `cargo test`, writes
# its generated header target/sweep/sweep_functions.h and runs the plain build) ----
SWEEP_DIR := target/sweep
test-sweep-sanitize: test-build
	@ls $(SWEEP_DIR)/sweep_functions.h > /dev/null
	@$(CC) $(SANITIZE_FLAGS) -D_DEFAULT_SOURCE -Iinclude -I$(SWEEP_DIR) tests/sweep/sweep.c $(LIB) \
		-lm -lpthread -ldl -o $(SWEEP_DIR)/sweep_asan
	@SWEEP_SECONDS=10 ASAN_OPTIONS=detect_leaks=1 $(SWEEP_DIR)/sweep_asan > $(SWEEP_DIR)/sweep_asan.txt \
		2> $(SWEEP_DIR)/sweep_asan.err || { cat $(SWEEP_DIR)/sweep_asan.txt $(SWEEP_DIR)/sweep_asan.err; exit 1; }
	@if grep -q 'ERROR: AddressSanitizer\|ERROR: LeakSanitizer\|runtime error\|panicked at' $(SWEEP_DIR)/sweep_asan.err; then \
		cat $(SWEEP_DIR)/sweep_asan.err; exit 1; fi
	@echo "test-sweep-sanitize: $$(grep '^calls:' $(SWEEP_DIR)/sweep_asan.txt | cut -d';' -f1) under ASan and UBSan, no report"

# ---- the Rust test binaries and the sweep under valgrind memcheck (see the script for which
# binaries and why) ----
test-valgrind-rust:
	@tools/valgrind_rust_tests.sh

# ---- fuzzing (not run by make test; cargo test replays the seeds and findings) ----
# make fuzz: the coverage-guided target of the C ABI (fuzz/, cargo fuzz with libFuzzer, built on
# stable with --sanitizer none) for FUZZ_TIME seconds; prints executions, coverage and
# findings (fuzz/artifacts/capi_calls/). cargo-fuzz is installed into target/tools.
FUZZ_TIME ?= 600
FUZZ_TOOLS := $(CURDIR)/target/tools
FUZZ_BIN = fuzz/target/$$(rustc -vV | sed -n 's/host: //p')/release/capi_calls
fuzz: deps
	@test -x $(FUZZ_TOOLS)/bin/cargo-fuzz || $(CARGO) install --locked --root $(FUZZ_TOOLS) cargo-fuzz
	cd fuzz && PATH="$(FUZZ_TOOLS)/bin:$$PATH" $(CARGO) fuzz build --sanitizer none -O capi_calls
	@mkdir -p fuzz/corpus/capi_calls fuzz/artifacts/capi_calls target/fuzz
	@$(FUZZ_BIN) -dict=fuzz/gl_enums.dict -max_total_time=$(FUZZ_TIME) -max_len=256 -print_final_stats=1 \
		-artifact_prefix=fuzz/artifacts/capi_calls/ fuzz/corpus/capi_calls fuzz/seeds/capi_calls \
		> target/fuzz/capi_calls.log 2>&1; status=$$?; \
	grep -E 'INITED|DONE|stat::' target/fuzz/capi_calls.log | tail -7; \
	echo "findings: $$(ls fuzz/artifacts/capi_calls | wc -l) in fuzz/artifacts/capi_calls/ (log: target/fuzz/capi_calls.log)"; \
	exit $$status

# make fuzz-osmesa SEQUENCES=N: N random command sequences run on fflight and OSMesa in one
# process (tests/osmesa_fuzz.rs, release build), outputs compared with the C harness's rules;
# DRAW_USE_LLVM=0: Mesa interprets its fixed-function vertex programs instead of compiling
# each variant with LLVM (20 times faster; cargo test runs the default).
SEQUENCES ?= 100000
fuzz-osmesa: deps
	DRAW_USE_LLVM=0 FFL_OSMESA_SEQUENCES=$(SEQUENCES) $(CARGO) test --release --test osmesa_fuzz -- --nocapture fflight_agrees
