#!/bin/sh
# tools/prefix_library.sh IN.a OUT.a: copies fflight's static library IN.a to OUT.a with every
# GL function it defines renamed glX -> ffl_glX (definitions and the library's own references
# alike; binutils objcopy), for programs that also link a real GL library
# (docs/coexistence.md). The ffl* functions keep their names. Declared by
# include/fflight_prefixed.h; tests/prefixed.rs checks that the two agree.
set -eu
in=$1
out=$2
map=$out.symbols
# Defined global text symbols: gl followed by an upper-case letter is a GL entry point (Rust's
# own symbols are mangled, _ZN... or _R...).
nm -g --defined-only "$in" 2>/dev/null |
    awk 'NF == 3 && $2 == "T" && $3 ~ /^gl[A-Z]/ { print $3, "ffl_" $3 }' | sort -u > "$map"
test -s "$map" || { echo "$in defines no GL function" >&2; exit 1; }
objcopy --redefine-syms="$map" "$in" "$out.tmp"
# No GL name may be left, defined or referenced.
left=$(nm -g "$out.tmp" 2>/dev/null | awk '$NF ~ /^gl[A-Z]/ { print $NF }' | sort -u)
if [ -n "$left" ]; then
    echo "$out still names:" $left >&2
    exit 1
fi
mv "$out.tmp" "$out"
echo "$out: $(wc -l < "$map") GL functions renamed ffl_glX"
