# fflight: `make test` runs every test, `make demo` the main job. Both install the system
# packages they need first (apt-get as root, sudo otherwise).

CARGO ?= cargo
CC ?= cc
PACKAGES := libosmesa6-dev libglu1-mesa-dev pkg-config gcc g++ cmake binutils valgrind make python3
CFLAGS_STRICT := -std=c99 -Wall -Wextra -Werror -pedantic
LIB := target/debug/libfflight.a
DEMO_DIR := target/demo

.PHONY: all deps build header test lint demo bench clean install uninstall test-install test-sanitize test-valgrind fuzz fuzz-osmesa

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

# Regenerates include/fflight.h from the sources (tests/header.rs fails when it is stale).
header:
	FFLIGHT_BLESS=1 $(CARGO) build

lint:
	$(CARGO) fmt --check
	$(CARGO) clippy --all-targets -- -D warnings

test: build
	$(CARGO) test
	$(MAKE) lint
	$(MAKE) --no-print-directory test-install
	$(MAKE) --no-print-directory test-sanitize
	$(MAKE) --no-print-directory test-valgrind

demo: build
	@mkdir -p $(DEMO_DIR)
	$(CC) $(CFLAGS_STRICT) -D_DEFAULT_SOURCE examples/demo/scene.c $(LIB) -lm -lpthread -ldl -o $(DEMO_DIR)/scene_fflight
	$(CC) $(CFLAGS_STRICT) -D_DEFAULT_SOURCE -DUSE_OSMESA examples/demo/scene.c -lOSMesa -lm -o $(DEMO_DIR)/scene_osmesa
	$(DEMO_DIR)/scene_fflight > $(DEMO_DIR)/fflight.txt
	$(DEMO_DIR)/scene_osmesa > $(DEMO_DIR)/osmesa.txt
	python3 examples/demo/compare.py $(DEMO_DIR)/fflight.txt $(DEMO_DIR)/osmesa.txt

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
	lib/cmake/fflight/fflightConfig.cmake lib/cmake/fflight/fflightConfigVersion.cmake
SUBSTITUTE = sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@VERSION@|$(VERSION)|g' -e 's|@MAJOR@|$(MAJOR)|g'

install:
	$(CARGO) build $(if $(filter release,$(PROFILE)),--release,)
	install -d $(INSTALL_ROOT)/lib/pkgconfig $(INSTALL_ROOT)/lib/cmake/fflight $(INSTALL_ROOT)/include
	install -m 755 target/$(PROFILE)/libfflight.so $(INSTALL_ROOT)/lib/libfflight.so.$(VERSION)
	ln -sf libfflight.so.$(VERSION) $(INSTALL_ROOT)/lib/libfflight.so.$(MAJOR)
	ln -sf libfflight.so.$(MAJOR) $(INSTALL_ROOT)/lib/libfflight.so
	install -m 644 target/$(PROFILE)/libfflight.a $(INSTALL_ROOT)/lib/libfflight.a
	install -m 644 include/fflight.h $(INSTALL_ROOT)/include/fflight.h
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

# ---- the C test programs under AddressSanitizer and UndefinedBehaviorSanitizer ----
# Each c_tests program, built against libfflight.a with the sanitizers on the C side (the
# Rust library itself is not instrumented: its sanitizers need a nightly compiler) and run:
# any sanitizer report fails. Their outputs are checked by `cargo test` (tests/c_programs.rs).
SANITIZE_DIR := target/sanitize
SANITIZE_FLAGS := -std=c99 -g -O1 -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
SANITIZE_PROGRAMS := $(patsubst c_tests/%.c,$(SANITIZE_DIR)/%.ok,$(wildcard c_tests/*.c))
test-sanitize: build
	@mkdir -p $(SANITIZE_DIR)
	@$(MAKE) --no-print-directory -j2 $(SANITIZE_PROGRAMS)
	@echo "test-sanitize: $(words $(SANITIZE_PROGRAMS)) programs under ASan and UBSan, no report"

# One program: built, run, its sanitizer reports (stderr) grepped; a clean run leaves .ok.
$(SANITIZE_DIR)/%.ok: c_tests/%.c c_tests/ffl_test.h $(LIB)
	@libs=$$(sed -n 's/.*ffl-libs:\(.*\)/\1/p' $< | head -1); \
	if [ -n "$$libs" ]; then libs="$$libs -rdynamic"; fi; \
	$(CC) $(SANITIZE_FLAGS) -Iinclude -Ic_tests $< $$libs $(LIB) -lm -lpthread -ldl -o $(@:.ok=)
	@ASAN_OPTIONS=detect_leaks=1 $(@:.ok=) > $(@:.ok=.txt) 2> $(@:.ok=.err) || true
	@if grep -q 'ERROR: AddressSanitizer\|ERROR: LeakSanitizer\|runtime error' $(@:.ok=.err); then \
		echo "sanitizer report: $*"; cat $(@:.ok=.err); exit 1; fi
	@touch $@

# ---- valgrind memcheck over the C test programs ----
# Every fflight build of c_tests (made by `cargo test`: run that first) under memcheck, two at
# a time: any memory error or definite leak (threads that exit without destroying their
# default context included: thread_exit_context.c) fails. Exit statuses of the programs
# themselves are checked by `cargo test`.
test-valgrind:
	@ls target/c_tests/*.fflight > /dev/null
	@ls target/c_tests/*.fflight | xargs -P2 -I{} sh -c \
		'valgrind -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite {} \
		> /dev/null 2> {}.valgrind; if [ $$? = 99 ]; then echo "valgrind: {}"; cat {}.valgrind; exit 255; fi'
	@echo "test-valgrind: $$(ls target/c_tests/*.fflight | wc -l) programs under memcheck, no error, no definite leak"

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
