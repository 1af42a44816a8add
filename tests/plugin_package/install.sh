#!/usr/bin/env bash
# The CTest fixture PluginPackageInstall: `cmake --install` of this build into a scratch prefix,
# emptied first, shared by the tests that build plug-ins against the installed package.
#   install.sh CMAKE BINARY_DIR PREFIX
set -euo pipefail
rm -rf "$3"
"$1" --install "$2" --prefix "$3" > /dev/null
