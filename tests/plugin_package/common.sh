# Shared by the installed-package tests (sourced): the example plug-in configured and built out of
# the tree, as the README says, against the package of tests/plugin_package/install.sh.
#   PLUGIN_PACKAGE_ARGS: CMAKE GENERATOR CXX_COMPILER SOURCE_DIR PREFIX WORK
set -euo pipefail
cmake_command=$1
generator=$2
cxx_compiler=$3
source_dir=$4
prefix=$5
work=$6
mhbench="$prefix/bin/mhbench"
[ -x "$mhbench" ] || { echo "no $mhbench: the PluginPackageInstall fixture installs it" >&2; exit 1; }
rm -rf "$work"
mkdir -p "$work"

# copy_example DIR: the example's three files, as a user's own project would hold them.
copy_example() {
    mkdir -p "$1"
    cp "$source_dir"/tests/plugin_example/{CMakeLists.txt,booth_plugin.cpp,booth_components.hpp} "$1/"
}

# configure_example SOURCE BUILD [CMAKE ARGUMENTS...]: the README's configure line, with this
# build's generator and compiler (a plug-in must use mhbench's compiler).
configure_example() {
    local source=$1 build=$2
    shift 2
    "$cmake_command" -S "$source" -B "$build" -G "$generator" -DCMAKE_CXX_COMPILER="$cxx_compiler" \
        -DCMAKE_PREFIX_PATH="$prefix" "$@" > "$build.configure.log" 2>&1 ||
        { cat "$build.configure.log" >&2; return 1; }
}

# build_example BUILD: the README's build line; the log is shown only when it fails.
build_example() {
    "$cmake_command" --build "$1" > "$1.build.log" 2>&1 || { cat "$1.build.log" >&2; return 1; }
}
