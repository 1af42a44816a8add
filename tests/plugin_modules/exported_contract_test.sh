#!/usr/bin/env bash
# The symbols the executable exports to plug-ins are written at build time from the libraries'
# objects (cmake/MhbPluginSymbols.cmake); this test checks the result from three other sides, so
# that a plug-in never finds out about a missing one as dlopen's "undefined symbol":
#   - every global function that a source of the installed contract (cmake/mhbenchContractHeaders.cmake:
#     a header with a source file of the same name) defines in namespace mhb, under a name its
#     header mentions, is exported;
#   - the vtable, VTT, typeinfo and typeinfo name of every class the headers define are exported
#     wherever the libraries define them (an unoptimised plug-in references Problem's vtable);
#   - every mhbench symbol that the example plug-in built unoptimised (-O0) leaves undefined is
#     exported.
# Usage: exported_contract_test.sh SOURCE_DIR MHBENCH UNOPTIMISED_MODULE STATIC_LIBRARY...
set -euo pipefail
source_dir="$1"
mhbench="$2"
module="$3"
shift 3
headers=$(sed -n '/^set(MHBENCH_CONTRACT_HEADERS/,/)/p' "$source_dir/cmake/mhbenchContractHeaders.cmake" |
    grep -o '[a-z_/]*\.hpp')
[ -n "$headers" ] || { echo "no headers found in cmake/mhbenchContractHeaders.cmake" >&2; exit 1; }
exported=$(mktemp)
defined=$(mktemp)
trap 'rm -f "$exported" "$defined"' EXIT
nm -D --defined-only -C "$mhbench" | sed 's/^[0-9a-f]* [A-Za-z] //' | sort -u > "$exported"
# "library.a:member.o:address T name", every global symbol the libraries define.
nm -g --defined-only -C -A "$@" 2>/dev/null > "$defined" || true
checked=0
missing=0
# expect_exported SYMBOL WHY: counts it, and names it when the executable does not export it.
expect_exported() {
    checked=$((checked + 1))
    if ! grep -qxF -- "$1" "$exported"; then
        echo "not exported to plug-ins: $1 ($2; see cmake/MhbPluginSymbols.cmake)"
        missing=$((missing + 1))
    fi
}

# Functions: global text symbols only (weak ones are inline code the plug-in compiles itself).
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
        expect_exported "$symbol" "declared in $header"
    done < <(grep ":${stem}\.cpp\.o:[0-9a-f]* T mhb::" "$defined")
done
functions=$checked

# Typeinfos of function types ("typeinfo for mhb::Registry<mhb::Problem> const& ()"), which clang's
# -fsanitize=function emits beside each function of a sanitized build, are nobody's class: left out.
not_a_function_type() { grep -vE '^(typeinfo|typeinfo name) for .*\)$' || true; }

# Classes: those the headers define ("struct Name {", "class Name : Base {"), not only declare.
classes=$(for header in $headers; do
    sed -e 's|//.*||' -e 's/template *<[^>]*>//g' -e 's/enum \(class\|struct\)/enum/' "$source_dir/$header" |
        grep -oE '(class|struct) +[A-Za-z_][A-Za-z0-9_]*[^;{()]*\{' | awk '{print $2}'
done | sort -u)
[ -n "$classes" ] || { echo "no classes found in the headers" >&2; exit 1; }
for class in $classes; do
    while IFS= read -r symbol; do
        expect_exported "$symbol" "a class of the installed headers"
    done < <(sed 's/^[^ ]* [A-Za-z] //' "$defined" |
        grep -E "^(vtable|VTT|typeinfo|typeinfo name) for mhb::${class}(<.*)?$" | not_a_function_type | sort -u)
done
class_data=$((checked - functions))

# The unoptimised module: what it needs from mhbench, mhbench exports.
while IFS= read -r symbol; do
    expect_exported "$symbol" "left undefined by $(basename "$module")"
done < <(nm -u -C "$module" | sed 's/^ *U //' | grep -E '^(mhb::|(vtable|VTT|typeinfo|typeinfo name) for mhb::)' |
    not_a_function_type)

echo "$checked symbols checked ($functions functions, $class_data vtables and typeinfos of" \
     "$(echo "$classes" | wc -w) classes, the rest needed by $(basename "$module")), $missing not exported"
[ "$functions" -gt 20 ] || { echo "too few functions found: is the test looking at the right libraries?" >&2; exit 1; }
[ "$class_data" -ge 3 ] || { echo "too few vtables and typeinfos found: are the classes found?" >&2; exit 1; }
[ "$missing" -eq 0 ]
