#!/usr/bin/env python3
"""An external optimiser that exits as soon as its budget is spent, without waiting for "stop",
for tests/integration/external_study_test.cpp.

Usage: early_exit_optimizer.py MODE BATCH MARKER. It sends batches of BATCH points (in the box,
each coordinate i * 1e-3 of the way from lower to upper) until its budget of evaluations is
spent, then exits with status 0 by MODE:
  answer   after reading all of its last answer (mhbench's "stop" races with its exit)
  partial  after reading only the start of its last answer, which carries the values it needs;
           the rest (the repaired points, larger than the pipe buffer for BATCH * D large
           enough) then meets a pipe without reader, every time
MARKER only tags the command line.
"""
import json
import os
import sys

mode, batch = sys.argv[1], int(sys.argv[2])
pending = b""


def send(message):
    sys.stdout.write(json.dumps(message) + "\n")
    sys.stdout.flush()


def receive(whole=True):
    """The next line (whole) or, with whole=False, the bytes read until its values have come."""
    global pending
    while b"\n" not in pending and (whole or b'"x"' not in pending):
        chunk = os.read(0, 4096)
        if not chunk:
            sys.exit(0)
        pending += chunk
    if not whole:
        return None
    line, _, pending = pending.partition(b"\n")
    return json.loads(line)


receive()
send({"type": "description", "version": "early-exit-opt-1"})
start = receive()
lower, upper = start["lower"], start["upper"]
remaining = start["budget"]["evaluations"]
i = 0
while True:
    points = []
    for _ in range(min(batch, remaining)):
        i += 1
        points.append([lo + (i * 1e-3 % 1.0) * (up - lo) for lo, up in zip(lower, upper)])
    send({"type": "eval", "x": points})
    remaining -= len(points)
    if remaining == 0:
        receive(whole=(mode == "answer"))
        sys.exit(0)
    reply = receive()
    if reply["type"] == "stop":
        sys.exit(0)
    send({"type": "iteration"})
