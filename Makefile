# fflight: `make test` runs every test, `make demo` the main job. Both install the system
# packages they need first (apt-get as root, sudo otherwise).

CARGO ?= cargo
CC ?= cc
PACKAGES := libosmesa6-dev pkg-config gcc make python3
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

# Lit, fed-back vertices per second through immediate mode, fflight (release) vs OSMesa,
# measured in the same run: medians of 7 runs each.
bench: deps
	$(CARGO) build --release
	@mkdir -p target/bench
	$(CC) $(CFLAGS_STRICT) -O2 -D_POSIX_C_SOURCE=199309L examples/bench/lit_points.c target/release/libfflight.a -lm -lpthread -ldl -o target/bench/lit_points_fflight
	$(CC) $(CFLAGS_STRICT) -O2 -D_POSIX_C_SOURCE=199309L -DUSE_OSMESA examples/bench/lit_points.c -lOSMesa -lm -o target/bench/lit_points_osmesa
	@f=$$(target/bench/lit_points_fflight) && o=$$(target/bench/lit_points_osmesa) && \
	echo "immediate mode + feedback, 8 lights: fflight $$f vertices/s, OSMesa $$o vertices/s, ratio $$(python3 -c "print(f'{$$f/$$o:.2f}')")"

clean:
	$(CARGO) clean
