#!/usr/bin/env python3
"""A sphere problem whose model fails while $MHB_TEST_TRANSIENT_FAULT is set, for the retry of
failed runs (tests/integration/failed_runs_test.cpp): a transient fault, such as a licence server
or a simulator that was down, that the same command, run again once it is gone, must get past.

Usage: transient_problem.py N MARKER. While the variable is set, its Nth eval message (counted per
process) writes to stderr and exits with status 3; otherwise it is a 2-D sphere. MARKER only tags
the command line.
"""
import json
import os
import sys

nth = int(sys.argv[1])
faulty = bool(os.environ.get("MHB_TEST_TRANSIENT_FAULT"))


def send(message):
    sys.stdout.write(json.dumps(message) + "\n")
    sys.stdout.flush()


evals = 0
for line in sys.stdin:
    message = json.loads(line)
    if message["type"] == "describe":
        send({"type": "description", "version": "transient-1", "dimension": 2,
              "lower": [-5.0, -5.0], "upper": [5.0, 5.0]})
        continue
    evals += 1
    if faulty and evals == nth:
        sys.stderr.write("transient: the model's licence server is down\n")
        sys.stderr.flush()
        sys.exit(3)
    send({"type": "values", "f": [sum(v * v for v in x) for x in message["x"]]})
