# fflight: `make test` runs every test, `make demo` the main job. Both install the system
# packages they need first (apt-get as root, sudo otherwise).

CARGO ?= cargo
CC ?= cc
PACKAGES := libosmesa6-dev libglu1-mesa-dev pkg-config gcc make python3
CFLAGS_STRICT := -std=c99 -Wall -Wextra -Werror -pedantic
LIB := target/debug/libfflight.a
DEMO_DIR := target/demo

.PHONY: all deps build header test lint demo bench clean

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
