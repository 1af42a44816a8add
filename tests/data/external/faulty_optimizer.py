#!/usr/bin/env python3
"""An external optimiser for tests/unit/algorithms/external_optimizer_test.cpp.

Usage: faulty_optimizer.py MODE BATCH MARKER [LOG]. It sends batches of BATCH points (i * 0.001 in
every coordinate) and, by MODE,
  ok       goes on until told to stop
  crash    exits with status 4 after its second batch
  hang     sleeps after its second batch
  done     says done after its second batch
  outside  sends its points 100 times beyond the upper bound (mhbench must clamp them)
It writes every reply it gets as one line "reply <values> <points> <evaluations> <largest x>" to
LOG (default stderr), for the counting test to read back.
"""
import json
import sys
import time

mode, batch = sys.argv[1], int(sys.argv[2])
log = open(sys.argv[4], "a") if len(sys.argv) > 4 else sys.stderr


def send(message):
    sys.stdout.write(json.dumps(message) + "\n")
    sys.stdout.flush()


def receive():
    line = sys.stdin.readline()
    if not line or json.loads(line)["type"] == "stop":
        sys.exit(0)
    return json.loads(line)


receive()
send({"type": "description", "version": "faulty-opt-1"})
start = receive()
dim = start["dimension"]
i = 0
batches = 0
while True:
    points = []
    for _ in range(batch):
        i += 1
        points.append([i * 0.001 * (100 if mode == "outside" else 1)] * dim)
    send({"type": "eval", "x": points})
    reply = receive()
    largest = max((v for x in reply["x"] for v in x), default=0.0)
    log.write("reply %d %d %d %r\n" % (len(reply["f"]), len(reply["x"]), reply["evaluations"], largest))
    log.flush()
    batches += 1
    if batches == 2 and mode == "crash":
        sys.exit(4)
    if batches == 2 and mode == "hang":
        time.sleep(1000)
    if batches == 2 and mode == "done":
        send({"type": "done"})
        sys.exit(0)
    send({"type": "iteration"})
