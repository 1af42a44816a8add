#!/usr/bin/env bash
# Fuzzing: builds the libFuzzer targets of tests/fuzz/ with Debian's clang (the `fuzz` preset:
# ASan + UBSan) and runs each for SECONDS (default 60) on a scratch copy of its seed corpus
# (tests/fuzz/corpus/<target>/ is never modified), as many at a time as there are cores.
# Exits non-zero on any crash, leak, sanitizer report, timeout or out-of-memory, printing the
# reproducer's path and the command that replays it.
#
#   scripts/fuzz.sh [SECONDS]        MHB_FUZZ_KEEP=1 keeps the scratch directory of a clean run
set -euo pipefail
seconds="${1:-60}"
if ! [[ "$seconds" =~ ^[1-9][0-9]*$ ]]; then
    echo "usage: scripts/fuzz.sh [SECONDS]  (a whole number of seconds per target, default 60)" >&2
    exit 2
fi
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
started=$SECONDS

bash scripts/setup-debian.sh fuzz
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j"$(nproc)"
built=$SECONDS

# target and its -max_len: room for a real file of each kind, small enough to mutate quickly.
targets=(dataset_csv:4096 spec:1024 study_file:4096 points:2048 study_dir:8192)
scratch="$(mktemp -d "${TMPDIR:-/tmp}/mhb-fuzz.XXXXXX")"
export UBSAN_OPTIONS=print_stacktrace=1

run_target() {
    local name="$1" max_len="$2" dir="$scratch/$1"
    mkdir -p "$dir/tmp"
    cp -r "tests/fuzz/corpus/$name" "$dir/corpus"
    # Each target's own temporary files (fuzz_study_dir's directories) stay inside $dir/tmp.
    local rc=0
    TMPDIR="$dir/tmp" "build/fuzz/tests/fuzz/fuzz_$name" "$dir/corpus" -max_total_time="$seconds" \
        -max_len="$max_len" -timeout=30 -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="$dir/" >"$dir/log" 2>&1 || rc=$?
    echo "$rc" >"$dir/rc"
}

for entry in "${targets[@]}"; do
    while [ "$(jobs -rp | wc -l)" -ge "$(nproc)" ]; do
        wait -n || true
    done
    run_target "${entry%%:*}" "${entry##*:}" &
done
wait

failed=0
for entry in "${targets[@]}"; do
    name="${entry%%:*}"
    log="$scratch/$name/log"
    if [ "$(cat "$scratch/$name/rc" 2>/dev/null)" = 0 ]; then
        runs="$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)"
        echo "fuzz_$name: ${runs:-?} executions in ${seconds} s, no finding"
    else
        failed=1
        echo "fuzz_$name: FAILED (log: $log)" >&2
        grep -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error|.*uncaught exception|.*Test unit written)' \
            "$log" | head -n 20 >&2 || tail -n 30 "$log" >&2
        for artifact in "$scratch/$name"/crash-* "$scratch/$name"/leak-* "$scratch/$name"/timeout-* \
            "$scratch/$name"/oom-*; do
            [ -e "$artifact" ] || continue
            echo "  reproducer: $artifact" >&2
            echo "  replay:     build/fuzz/tests/fuzz/fuzz_$name $artifact" >&2
        done
    fi
done

echo "fuzz: build $((built - started)) s, runs $((SECONDS - built)) s (${#targets[@]} targets x ${seconds} s, $(nproc) at a time)"
if [ "$failed" -ne 0 ]; then
    echo "fuzz: findings above; scratch directory kept: $scratch" >&2
    exit 1
fi
if [ -z "${MHB_FUZZ_KEEP:-}" ]; then
    rm -rf "$scratch"
else
    echo "fuzz: scratch directory kept: $scratch"
fi
