#!/usr/bin/env bash
# A plug-in built against a changed copy of the contract's headers (one virtual function added to
# Problem, which changes no size) is refused by `list`, `run` and `plugin-check`: one line starting
# "mhbench" that names the contract fingerprint, exit 1, no crash. The fingerprint is computed at
# the plug-in's build from the headers its compiler resolves (cmake/mhbenchContract.cmake), so a
# copy earlier in the include path is what counts, not the package the build found.
#   changed_contract_test.sh CMAKE GENERATOR CXX_COMPILER SOURCE_DIR PREFIX WORK
source "$(dirname "$0")/common.sh"

copy="$work/changed-include"
cp -r "$prefix/include/mhbench" "$copy"
# First in the vtable, so that every later virtual call of mhbench would land one entry off.
sed -i 's|^\(    virtual ~Problem() = default;\)$|\1\n    virtual void added_after_the_install() const {}|' \
    "$copy/problems/problem.hpp"
grep -q added_after_the_install "$copy/problems/problem.hpp" ||
    { echo "FAIL: the test could not edit problems/problem.hpp" >&2; exit 1; }

copy_example "$work/booth"
configure_example "$work/booth" "$work/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS="-I$copy"
build_example "$work/build"
plugin="$work/build/booth_plugin.so"

failed=0
# expect_refused WHAT ARGS...: exit 1 and one line on stderr, starting "mhbench" and naming the
# contract.
expect_refused() {
    local what=$1 code=0
    shift
    "$mhbench" "$@" > "$work/$what.out" 2> "$work/$what.err" || code=$?
    local err
    err=$(cat "$work/$what.err")
    if [ "$code" -ne 1 ] || [ "$(wc -l < "$work/$what.err")" -ne 1 ] || [[ "$err" != mhbench* ]] ||
        [[ "$err" != *"built with contract="*", this mhbench has contract="* ]]; then
        echo "FAIL: $what: exit $code, stderr:" >&2
        echo "$err" >&2
        failed=1
    fi
}
expect_refused list list --plugin "$plugin"
expect_refused run run --plugin "$plugin" --algorithms one-plus-one --problems booth --evaluations 200 \
    --no-report --quiet --out "$work/study"
expect_refused plugin-check plugin-check --plugin "$plugin" --algorithm one-plus-one --problem booth
[ "$failed" -eq 0 ] && echo "a plug-in built against a changed contract is refused by list, run and plugin-check"
exit "$failed"
