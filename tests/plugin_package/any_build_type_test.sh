#!/usr/bin/env bash
# The example plug-in built exactly as the README says, with no build type, and in Debug, Release
# and RelWithDebInfo, loads into the installed mhbench: `list`, a short `run` and `plugin-check`
# each exit 0. (An unoptimised module references the vtables of the contract's classes, which
# mhbench must export, not only its functions: cmake/MhbPluginSymbols.cmake.)
#   any_build_type_test.sh CMAKE GENERATOR CXX_COMPILER SOURCE_DIR PREFIX WORK
source "$(dirname "$0")/common.sh"

copy_example "$work/booth"
build_types=(none Debug Release RelWithDebInfo)
# Two builds at a time (one source file each: -j2 inside one build would leave a core idle).
build_one() {
    local type=$1 args=()
    [ "$type" = none ] || args=(-DCMAKE_BUILD_TYPE="$type")
    configure_example "$work/booth" "$work/build-$type" "${args[@]}" && build_example "$work/build-$type"
}
pids=()
for type in "${build_types[@]}"; do
    build_one "$type" &
    pids+=($!)
    if [ ${#pids[@]} -eq 2 ]; then
        wait "${pids[0]}" || { echo "FAIL: the example did not build (${pids[0]})" >&2; exit 1; }
        pids=("${pids[1]}")
    fi
done
for pid in "${pids[@]}"; do
    wait "$pid" || { echo "FAIL: the example did not build" >&2; exit 1; }
done

failed=0
# expect_ok TYPE WHAT COMMAND...: the command exits 0, or its output is shown.
expect_ok() {
    local type=$1 what=$2
    shift 2
    local out
    if ! out=$("$@" 2>&1); then
        echo "FAIL: build type $type: $what exited non-zero:" >&2
        echo "$out" >&2
        failed=1
    fi
}
for type in "${build_types[@]}"; do
    plugin="$work/build-$type/booth_plugin.so"
    expect_ok "$type" list "$mhbench" list --plugin "$plugin"
    expect_ok "$type" run "$mhbench" run --plugin "$plugin" --algorithms one-plus-one:step=0.5 \
        --problems booth --evaluations 200 --runs 2 --no-report --quiet --out "$work/study-$type"
    expect_ok "$type" plugin-check "$mhbench" plugin-check --plugin "$plugin" --algorithm one-plus-one \
        --problem booth
done
[ "$failed" -eq 0 ] && echo "the example loads in every build type: ${build_types[*]}"
exit "$failed"
