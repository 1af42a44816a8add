#!/usr/bin/env bash
# runner/plugin_symbols.list is kept by hand: this test fails when a function of the installed
# contract (cmake/MhbInstall.cmake's headers) is defined in mhbench but not exported to plug-ins,
# which a plug-in calling it would only find out as dlopen's "undefined symbol". For each installed
# header with a source file of the same name, every global function that source defines in
# namespace mhb, and whose class or function name the header mentions, must be in the
# executable's dynamic symbol table.
# Usage: exported_contract_test.sh SOURCE_DIR MHBENCH STATIC_LIBRARY...
set -euo pipefail
source_dir="$1"
mhbench="$2"
shift 2
headers=$(sed -n '/^set(MHB_PUBLIC_HEADERS/,/)/p' "$source_dir/cmake/MhbInstall.cmake" | grep -o '[a-z_/]*\.hpp')
[ -n "$headers" ] || { echo "no headers found in cmake/MhbInstall.cmake" >&2; exit 1; }
exported=$(mktemp)
defined=$(mktemp)
trap 'rm -f "$exported" "$defined"' EXIT
nm -D --defined-only -C "$mhbench" | sed 's/^[0-9a-f]* [A-Za-z] //' | sort -u > "$exported"
# "library.a:member.o:address T name", global text symbols only (weak ones are inline code the
# plug-in compiles itself).
nm -g --defined-only -C -A "$@" 2>/dev/null | grep ' T mhb::' > "$defined" || true
checked=0
missing=0
for header in $headers; do
    stem=$(basename "$header" .hpp)
    [ -f "$source_dir/${header%.hpp}.cpp" ] || continue
    while IFS= read -r line; do
        symbol=${line#* T }
        name=${symbol#mhb::}
        name=${name%%(*}
        name=${name%%::*}
        name=${name%%<*}
        grep -qw -- "$name" "$source_dir/$header" || continue
        checked=$((checked + 1))
        if ! grep -qxF -- "$symbol" "$exported"; then
            echo "not exported to plug-ins: $symbol (declared in $header; add it to runner/plugin_symbols.list)"
            missing=$((missing + 1))
        fi
    done < <(grep ":${stem}\.cpp\.o:" "$defined")
done
echo "$checked functions of the installed headers checked, $missing not exported"
[ "$checked" -gt 20 ] || { echo "too few functions found: is the test looking at the right libraries?" >&2; exit 1; }
[ "$missing" -eq 0 ]
