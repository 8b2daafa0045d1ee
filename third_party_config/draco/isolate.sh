#!/usr/bin/env bash
# Links OBJECTS with the members of ARCHIVE they need into one relocatable object OUT in which only the
# SYMBOLS stay global (third_party_config/Draco.cmake says why).
# Usage: isolate.sh LD OBJCOPY NM OUT ARCHIVE OBJECT... -- SYMBOL...
set -euo pipefail
ld=$1 objcopy=$2 nm=$3 out=$4 archive=$5
shift 5
objects=()
while [ "$1" != "--" ]; do objects+=("$1"); shift; done
shift
keep=()
for symbol in "$@"; do keep+=("--keep-global-symbol=$symbol"); done
# Section groups (inline functions any object may carry) become plain sections: a group's copy here could
# be the one the final link discards, while our now local symbols still point into it.
"$ld" -r --force-group-allocation -o "$out.partial" "${objects[@]}" "$archive"
# GNU unique symbols (function-local statics of inline code) cannot be made local: they are renamed after
# OUT, so that no other object's copy meets them.
prefix="$(basename "$out" .o)_"
"$nm" --defined-only "$out.partial" | awk -v prefix="$prefix" '$2 == "u" { print $3 " " prefix $3 }' > "$out.unique"
"$objcopy" "${keep[@]}" --redefine-syms="$out.unique" "$out.partial" "$out"
rm -f "$out.partial" "$out.unique"
