#!/usr/bin/env bash
# The whole-process comparison with pagmo2 (BENCHMARKS.md, "Whole process against pagmo2"): the
# paper's PSO study on the PMSM problem, 20 seeds x 7550 evaluations, on one core, as
#   A: mhbench run --algorithms pso --problems pmsm:speed=2500,load=2 --runs 20 --iterations 150
#      --threads 1 --no-report -q   (a new study directory each time: store, CSVs, fsync)
#   B: pagmo_pso_pmsm               (tests/bench/pagmo: pagmo2's pso on the same Problem)
# started in turn, A B A B ..., ROUNDS times each (default 11) after one warm-up of each; prints
# the median and best CPU (user + system) and wall seconds of each and the median of the paired
# ratios A/B. Installs libpagmo-dev (setup-debian.sh pagmo) and builds the `pagmo` preset.
#   scripts/pagmo-compare.sh [ROUNDS]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash scripts/setup-debian.sh pagmo
cmake --preset pagmo >/dev/null
cmake --build --preset pagmo -j"$(nproc)" >/dev/null
rounds="${1:-11}"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
python3 - "$rounds" "$scratch" build/pagmo/runner/mhbench build/pagmo/tests/bench/pagmo/pagmo_pso_pmsm <<'PY'
import os, shutil, statistics, subprocess, sys, time

rounds, scratch, mhbench, pagmo = int(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4]
study = os.path.join(scratch, "study")
commands = {
    "A mhbench": [mhbench, "run", "-q", "--no-report", "--algorithms", "pso", "--problems",
                  "pmsm:speed=2500,load=2", "--runs", "20", "--iterations", "150", "--threads", "1",
                  "--out", study],
    "B pagmo2": [pagmo],
}
cpu = min(os.sched_getaffinity(0))
os.sched_setaffinity(0, {cpu})  # inherited by the children: one core


def timed(argv):
    shutil.rmtree(study, ignore_errors=True)  # outside the timed span
    started = time.perf_counter()
    child = subprocess.Popen(argv, stdout=subprocess.DEVNULL)
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.perf_counter() - started
    if status != 0:
        sys.exit(f"pagmo-compare: {argv[0]} exited with status {status}")
    return usage.ru_utime + usage.ru_stime, wall


samples = {name: [] for name in commands}
for name, argv in commands.items():
    timed(argv)  # warm-up: page cache, dynamic loader
for _ in range(rounds):
    for name, argv in commands.items():
        samples[name].append(timed(argv))
print(f"pinned to cpu {cpu}, {rounds} rounds")
for name, values in samples.items():
    cpus, walls = [v[0] for v in values], [v[1] for v in values]
    print(f"{name:10s} cpu median {statistics.median(cpus):.4f} s best {min(cpus):.4f} s; "
          f"wall median {statistics.median(walls):.4f} s best {min(walls):.4f} s")
a, b = samples["A mhbench"], samples["B pagmo2"]
print(f"A/B cpu: median of pairs {statistics.median(x[0] / y[0] for x, y in zip(a, b)):.3f}; "
      f"A/B wall: median of pairs {statistics.median(x[1] / y[1] for x, y in zip(a, b)):.3f}, "
      f"best of each {min(x[1] for x in a) / min(y[1] for y in b):.3f}")
PY
