#!/usr/bin/env bash
# Packs the official CEC 2017 and CEC 2022 input data into problems/cec/data/, once per suite:
#   cec2017.tar, cec2022.tar  the original files byte for byte (CRLF kept), each compressed alone
#                             (xz -9e), as input_data/<name>.xz, in a reproducible uncompressed tar
#                             (sorted, owner 0, mtime 0): a program decompresses only the files it
#                             uses (3% larger than one solid tar.xz)
#   SHA256SUMS                the SHA-256 of every original file, copied as published
# The executable embeds the archives (problems/cec/cec_archives.cpp); a test checks every member
# against SHA256SUMS. Run it only when the data change:
#   bash scripts/pack-cec-data.sh [CEC_DIR]     (default ../shared/cec beside the repository)
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source_dir="${1:-$repo/../shared/cec}"
out="$repo/problems/cec/data"

if [ ! -f "$source_dir/SHA256SUMS" ]; then
    echo "pack-cec-data: no SHA256SUMS in $source_dir (give the folder holding 2017/ and 2022/)" >&2
    exit 2
fi
(cd "$source_dir" && sha256sum --quiet -c SHA256SUMS) || {
    echo "pack-cec-data: the files in $source_dir do not match their SHA256SUMS" >&2
    exit 1
}

mkdir -p "$out"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for year in 2017 2022; do
    mkdir -p "$work/$year/input_data"
    cp "$source_dir/$year/input_data/"* "$work/$year/input_data/"
    # xz's output depends only on its input and settings: the packing is reproducible.
    find "$work/$year/input_data" -type f -print0 | xargs -0 -P "$(nproc)" -n 16 xz -9e --threads=1
    touch -d @0 "$work/$year/input_data" "$work/$year/input_data/"*
    tar --sort=name --owner=0 --group=0 --numeric-owner --mtime=@0 --format=gnu \
        -C "$work/$year" -cf "$out/cec$year.tar.tmp" input_data
    mv "$out/cec$year.tar.tmp" "$out/cec$year.tar"
    rm -f "$out/cec$year.tar.xz"
done
install -m 644 "$source_dir/SHA256SUMS" "$out/SHA256SUMS"
ls -l "$out"
