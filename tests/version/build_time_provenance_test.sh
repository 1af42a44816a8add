#!/usr/bin/env bash
# Build-time provenance (cmake/MhbVersion.cmake): a tiny project built with mhbench's version
# machinery in a scratch git repository records the commit and the dirty flag of each build
# without reconfiguring: after an edit of a tracked file, after a commit, and rebuilds nothing
# when neither changed.
#   build_time_provenance_test.sh SOURCE_DIR
set -euo pipefail
source_dir=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

mkdir -p "$work/repo/cmake"
cp "$source_dir"/cmake/MhbVersion.cmake "$source_dir"/cmake/MhbWriteVersion.cmake \
   "$source_dir"/cmake/version.hpp.in "$work/repo/cmake/"
cd "$work/repo"
cat > CMakeLists.txt <<'CMAKE'
cmake_minimum_required(VERSION 3.25)
project(provenance VERSION 1.2.3 LANGUAGES CXX)
list(APPEND CMAKE_MODULE_PATH ${CMAKE_CURRENT_SOURCE_DIR}/cmake)
include(MhbVersion)
add_executable(show main.cpp)
target_include_directories(show PRIVATE ${CMAKE_CURRENT_BINARY_DIR}/generated)
add_dependencies(show mhb_version)
CMAKE
cat > main.cpp <<'CPP'
#include <cstdio>
#include "mhb_version.hpp"
int main() { std::printf("%s %s\n", mhb::build::git_commit, mhb::build::git_dirty); }
CPP
echo build > .gitignore
git init -q .
git -c user.name=t -c user.email=t@t add -A
git -c user.name=t -c user.email=t@t commit -qm first
first=$(git rev-parse --short=12 HEAD)

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
build() { cmake --build build >/dev/null && ./build/show; }
[ "$(build)" = "$first no" ] || fail "after configure and build: $(./build/show), expected $first no"

echo "// an edit" >> main.cpp
[ "$(build)" = "$first yes" ] || fail "after an edit of a tracked file: $(./build/show), expected $first yes"

git -c user.name=t -c user.email=t@t commit -qam second
second=$(git rev-parse --short=12 HEAD)
[ "$(build)" = "$second no" ] || fail "after a commit: $(./build/show), expected $second no"

# Nothing changed: the header is not rewritten, so nothing is recompiled.
before=$(stat -c %Y.%y build/generated/mhb_version.hpp build/show)
sleep 1.1
[ "$(build)" = "$second no" ] || fail "after an empty build: $(./build/show)"
after=$(stat -c %Y.%y build/generated/mhb_version.hpp build/show)
[ "$before" = "$after" ] || fail "an empty build rewrote the header or relinked: $before -> $after"
echo "build-time provenance: ok ($first no, $first yes, $second no, unchanged rebuild)"
