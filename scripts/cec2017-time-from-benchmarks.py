#!/usr/bin/env python3
"""The cec2017 preset's CPU time added up from whole-run benchmarks (BENCHMARKS.md, issue 26).

For every algorithm a of the preset, function f (F2 excluded, as the preset) and dimension D:
    51 runs x 10000 D evaluations x (own_a(D) + cost_f(D) + the Objective's ~10 ns)
where own_a(D) is the algorithm's time per evaluation on the D-dimensional sphere minus the
sphere through the Objective (cec_baselines_overhead_bench: baseline/<a>/<D> - objective_only/<D>)
and cost_f(D) the function's own time per evaluation (functions_bench). An upper bound: the
preset's target (1e-8) ends runs early on the functions an algorithm solves.

    build/release/tests/bench/cec_baselines_overhead_bench --benchmark_min_time=0.5 > baselines.txt
    build/release/tests/bench/functions_bench --benchmark_filter=cec2017 --benchmark_min_time=0.1 > functions.txt
    scripts/cec2017-time-from-benchmarks.py baselines.txt functions.txt [THREADS]
"""
import re
import sys

RUNS = 51
OBJECTIVE_US = 0.01


def per_evaluation_us(value, unit):
    return float(value) * {"ns": 1e-3, "us": 1.0, "ms": 1e3}[unit]


def read_baselines(path):
    own, objective = {}, {}
    for line in open(path):
        m = re.match(r"(?:baseline/(\S+)|objective_only)/(\d+)\s.*per_eval=([\d.]+)(ns|us|ms)", line)
        if m:
            value = per_evaluation_us(m.group(3), m.group(4))
            if m.group(1):
                own[(m.group(1), int(m.group(2)))] = value
            else:
                objective[int(m.group(2))] = value
    return {key: max(value - objective[key[1]], 0.0) for key, value in own.items()}


def read_functions(path):
    cost = {}
    for line in open(path):
        m = re.match(r"cec2017:f=(\d+),dim=(\d+)\s+([\d.]+) (ns|us|ms)", line)
        if m:
            cost[(int(m.group(1)), int(m.group(2)))] = per_evaluation_us(m.group(3), m.group(4))
    return cost


def main():
    own = read_baselines(sys.argv[1])
    cost = read_functions(sys.argv[2])
    threads = int(sys.argv[3]) if len(sys.argv) > 3 else 2
    algorithms = sorted({a for a, _ in own})
    dimensions = sorted({d for _, d in own})
    by_algorithm = dict.fromkeys(algorithms, 0.0)
    by_dimension = dict.fromkeys(dimensions, 0.0)
    own_total = function_total = 0.0
    for (f, d), f_cost in sorted(cost.items()):
        if f == 2 or d not in by_dimension:
            continue
        evaluations = 10000 * d * RUNS
        for a in algorithms:
            seconds = evaluations * (own[(a, d)] + f_cost + OBJECTIVE_US) * 1e-6
            by_algorithm[a] += seconds
            by_dimension[d] += seconds
            own_total += evaluations * own[(a, d)] * 1e-6
            function_total += evaluations * f_cost * 1e-6
    total = sum(by_algorithm.values())
    print(f"CPU {total:.3g} s, {total / threads:.3g} s on {threads} threads "
          f"(algorithms' own {own_total:.3g} s, functions {function_total:.3g} s)")
    for a in sorted(algorithms, key=lambda a: -by_algorithm[a]):
        print(f"  {a:22s} {by_algorithm[a]:9.3g} s  {100 * by_algorithm[a] / total:3.0f}%")
    for d in dimensions:
        print(f"  D = {d:<3d} {by_dimension[d]:9.3g} s  {100 * by_dimension[d] / total:3.0f}%")


if __name__ == "__main__":
    main()
