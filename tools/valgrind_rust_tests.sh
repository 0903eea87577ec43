#!/bin/sh
# make test-valgrind-rust: the Rust test binaries that exercise the library, and the
# entry-point sweep's program, under valgrind memcheck, two at a time. Any memory error or
# definite leak fails (threads that exit without destroying their default context
# included: every Rust test runs on a thread of its own). Run after `cargo test`, which
# builds the binaries and writes the sweep's generated header.
#
# Skipped, and why:
#   c_programs  spawns gcc and the C programs; `make test-valgrind` runs those programs
#               under memcheck itself.
#   sweep       spawns gcc; its program is run under memcheck below, directly.
#   header      runs cbindgen over the sources, no library code.
#   symbols     runs nm over the built library, no library code.
#   fuzz_replay replays the fuzzer's inputs through its harness, which reserves a 2 TiB
#               address-space arena (MAP_NORESERVE) that memcheck cannot map; the same
#               entry points run under memcheck through the sweep and the other binaries.
#   osmesa_fuzz dlopens libOSMesa beside libfflight.so: memcheck reports Mesa's own leaks
#               (contexts it never frees) and the dynamic loader's reads of RPATH strings,
#               nothing of fflight's; fflight's side runs under memcheck in the other binaries.
#   batch_engine, robustness
#               14 s and 80 s of random states and sequences natively: 10 to 60 minutes
#               under memcheck. The sweep below covers the same entry points with hostile
#               arguments under memcheck; ASan and memcheck also run every C program.
#   mesh_draws  13 s of large indexed draws in a debug build: minutes under memcheck; the
#               mesh path it covers has no unsafe code, and its draws enter through the same
#               entry points as the C programs'.
# And tests of a binary that runs:
#   immediate_mode each_vertex_takes_the_attributes_current_at_its_glvertex
#               3 s natively, over 150 s under memcheck (with capture's layouts, the two
#               longest jobs): the order of attribute changes between vertices, through
#               the same calls and helper thread as the binary's other tests, which run.
#   immediate_mode primitives_reusing_blocks_take_the_attributes_current_at_each_glvertex
#               1.3 s in a debug build, over a minute under memcheck: the attributes that
#               blocks reused across primitives hold, through the same calls and helper
#               thread as the tests that run.
#   immediate_mode *_with_one_light_*
#               the thread-count tests again with one light (about 50 s under memcheck):
#               the same calls, helper thread and layouts as their three-light forms.
set -u
cd "$(dirname "$0")/.."
out=target/valgrind-rust
mkdir -p "$out"
skip=" c_programs sweep header symbols fuzz_replay osmesa_fuzz batch_engine robustness mesh_draws "
VALGRIND="valgrind -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite"

cargo test --no-run --message-format=json 2>/dev/null |
    python3 -c '
import json, sys
for line in sys.stdin:
    try:
        m = json.loads(line)
    except ValueError:
        continue
    if m.get("reason") == "compiler-artifact" and m.get("executable") and m["profile"]["test"]:
        print(m["target"]["name"], m["executable"])
' > "$out/binaries.txt"

: > "$out/run.txt"
while read -r name exe; do
    case "$skip" in *" $name "*) continue ;; esac
    case "$name" in
    immediate_mode) echo "$name $exe --skip each_vertex_takes_the_attributes_current_at_its_glvertex --skip primitives_reusing_blocks --skip _with_one_light_" ;;
    *) echo "$name $exe" ;;
    esac >> "$out/run.txt"
done < "$out/binaries.txt"

start=$(date +%s)
status=0
# One job per line: the test binaries, the longest first (capture's layouts take over 150 s
# under memcheck), then the sweep (one argument draw per function and situation, 5 s of
# random calls; calls may take minutes under memcheck).
{
    grep '^capture ' "$out/run.txt"
    grep -v '^capture ' "$out/run.txt"
    echo "sweep-program target/sweep/sweep"
} | xargs -P2 -L1 sh -c '
    name=$0 exe=$1 began=$(date +%s)
    shift
    if [ "$name" = sweep-program ]; then
        SWEEP_ROUNDS=1 SWEEP_SECONDS=5 SWEEP_CALL_SECONDS=600 timeout 1200 '"$VALGRIND"' "$exe" \
            > '"$out"'/$name.out 2> '"$out"'/$name.err
    else
        timeout 1200 '"$VALGRIND"' "$exe" -q "$@" > '"$out"'/$name.out 2> '"$out"'/$name.err
    fi
    rc=$?
    if [ $rc != 0 ]; then
        echo "valgrind-rust: $name failed ($rc)"; tail -n 60 '"$out"'/$name.err; tail -n 20 '"$out"'/$name.out
        exit 255
    fi
    echo "valgrind-rust: $name clean ($(( $(date +%s) - began )) s)"
' || status=1
echo "test-valgrind-rust: $(wc -l < "$out/run.txt") test binaries and the sweep under memcheck in $(( $(date +%s) - start )) s"
exit $status
