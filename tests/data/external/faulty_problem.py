#!/usr/bin/env python3
"""A sphere problem that misbehaves on purpose, for tests/unit/problems/external_problem_test.cpp.

Usage: faulty_problem.py MODE N MARKER. On its Nth eval message (counted per process) it
  crash    writes to stderr and exits with status 3
  hang     starts a grandchild in its process group, then sleeps (a timeout must end both)
  garbage  writes a line that is not JSON
  nan      returns NaN for the first point
  count    returns one value too few
  ok       behaves
and with MODE=startup it exits before describing itself. MARKER only tags the command line, so a
test can look for its processes. Counts its eval messages in $MHB_TEST_COUNT_FILE if set.
"""
import json
import os
import subprocess
import sys
import time

mode, nth = sys.argv[1], int(sys.argv[2])


def send(message):
    sys.stdout.write(json.dumps(message) + "\n")
    sys.stdout.flush()


if mode == "startup":
    sys.stderr.write("faulty: cannot load the model\n")
    sys.exit(2)

evals = 0
for line in sys.stdin:
    message = json.loads(line)
    if message["type"] == "describe":
        send({"type": "description", "version": "faulty-1", "dimension": 2,
              "lower": [-5.0, -5.0], "upper": [5.0, 5.0]})
        continue
    evals += 1
    f = [sum(v * v for v in x) for x in message["x"]]
    if evals == nth:
        if mode == "crash":
            sys.stderr.write("faulty: segmentation fault in the model\n")
            sys.stderr.flush()
            sys.exit(3)
        if mode == "hang":
            subprocess.Popen([sys.executable, "-c", "import time; time.sleep(1000)", sys.argv[3]])
            time.sleep(1000)
        if mode == "garbage":
            sys.stdout.write("Warning: model converged slowly\n")
            sys.stdout.flush()
            continue
        if mode == "nan":
            f[0] = float("nan")
        if mode == "count":
            f = f[:-1]
    send({"type": "values", "f": f})
