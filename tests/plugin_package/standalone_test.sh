#!/usr/bin/env bash
# InstalledMhbenchStandsAlone: the installed prefix (the PluginPackageInstall fixture's), copied to
# another place as a whole, runs a study with its figures and `identify --flux-map` with its figure
# while the source and build trees are out of reach: hidden under empty tmpfs mounts in a private
# mount namespace (`unshare -rm`) where the system allows one, else only moved away from.
#   standalone_test.sh SOURCE_DIR BINARY_DIR PREFIX
set -euo pipefail
source_dir=$(realpath "$1")
binary_dir=$(realpath "$2")
prefix=$3
[ -x "$prefix/bin/mhbench" ] || { echo "no $prefix/bin/mhbench: the PluginPackageInstall fixture installs it" >&2; exit 1; }
work=$(mktemp -d /tmp/mhbench-standalone.XXXXXX)
trap 'rm -rf "$work"' EXIT
cp -a "$prefix" "$work/moved-prefix"
mhbench="$work/moved-prefix/bin/mhbench"

# The executable names no place of the trees it was built from where it could look for a file at run
# time: the scripts' folder of either. (Debug information and sanitizers' source locations do name
# the trees' C++ sources, which nothing opens.)
for place in "$source_dir/scripts" "$binary_dir/share"; do
    if grep -aqF "$place" "$mhbench"; then
        echo "the installed executable holds the path $place" >&2
        exit 1
    fi
done

# in_isolation COMMAND...: run it with both trees hidden when a mount namespace can be had. The build
# tree is hidden first: it may lie inside the source tree.
in_isolation() {
    if unshare -rm true 2> /dev/null; then
        unshare -rm bash -c 'mount -t tmpfs none "$1" && mount -t tmpfs none "$2" && shift 2 && exec "$@"' \
            _ "$binary_dir" "$source_dir" "$@"
    else
        echo "note: no private mount namespace here (unshare -rm); the trees are only not used" >&2
        "$@"
    fi
}

cd "$work"
in_isolation "$mhbench" run --study smoke --out "$work/study" -q
in_isolation "$mhbench" identify --flux-map shipped --starts 2 --out "$work/fluxmap" > "$work/identify.txt"
in_isolation "$mhbench" list studies > "$work/studies.txt"
grep -q '^ *paper' "$work/studies.txt" || { echo "the presets are not listed:" >&2; cat "$work/studies.txt" >&2; exit 1; }
[ -f "$work/moved-prefix/share/mhbench/studies/paper.ini" ] || { echo "the preset files are not installed" >&2; exit 1; }
[ -f "$work/moved-prefix/share/mhbench/data/fluxmap/LICENSE-motulator" ] ||
    { echo "the flux map's licence is not installed" >&2; exit 1; }

# Figures: required wherever Debian's Python can draw them (the report says why it skipped otherwise).
if /usr/bin/python3 -c 'import matplotlib' 2> /dev/null; then
    ls "$work"/study/report/figures/*.png > /dev/null 2>&1 ||
        { echo "the installed mhbench drew no figure of the study" >&2; exit 1; }
    [ -f "$work/fluxmap/flux-map.pdf" ] && [ -f "$work/fluxmap/flux-map.png" ] ||
        { echo "the installed mhbench drew no flux-map figure:" >&2; cat "$work/identify.txt" >&2; exit 1; }
    echo "figures drawn from the moved prefix with the trees hidden"
else
    echo "note: /usr/bin/python3 has no matplotlib; figures not checked"
fi
