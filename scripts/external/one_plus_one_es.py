#!/usr/bin/env python3
"""A (1+lambda)-ES with the 1/5th success rule (Rechenberg 1973; Beyer and Schwefel 2002) as an
mhbench external optimiser: an ask/tell loop over the protocol (docs/extending.md, "External programs (any
language)"). Standard library only.

Parameters (`params=sigma=0.3;lambda=1`): sigma = initial step as a fraction of the box width
(default 0.3), lambda = offspring per generation, sent in one message (default 1).
Every random number comes from random.Random(seed), the seed mhbench draws from the run's stream:
the same run gives the same numbers. Evaluations per iteration: lambda (1 for the initial point).
"""
import json
import math
import random
import sys

VERSION = "es-1"


def send(message):
    sys.stdout.write(json.dumps(message) + "\n")
    sys.stdout.flush()


def receive():
    line = sys.stdin.readline()
    if not line:  # mhbench has gone
        sys.exit(0)
    message = json.loads(line)
    if message["type"] == "stop":  # the budget is spent
        sys.exit(0)
    return message


def ask_tell(points):
    """Sends points, returns (values, repaired points): fewer than sent when the budget ended."""
    send({"type": "eval", "x": points})
    reply = receive()
    return [float(f) for f in reply["f"]], reply["x"]


def main():
    describe = receive()
    parameters = describe["parameters"]
    send({"type": "description", "version": VERSION})
    start = receive()
    lower, upper = start["lower"], start["upper"]
    rng = random.Random(start["seed"])
    sigma = float(parameters.get("sigma", "0.3"))
    offspring = int(parameters.get("lambda", "1"))
    width = [u - l for l, u in zip(lower, upper)]

    values, points = ask_tell([[rng.uniform(l, u) for l, u in zip(lower, upper)]])
    best_f, best_x = values[0], points[0]
    send({"type": "initialised"})
    while True:
        children = [[x + sigma * w * rng.gauss(0.0, 1.0) for x, w in zip(best_x, width)]
                    for _ in range(offspring)]
        values, points = ask_tell(children)
        successes = 0
        for f, x in zip(values, points):
            if f <= best_f:
                best_f, best_x = f, x
                successes += 1
        # 1/5th rule per generation: widen on success, narrow otherwise.
        sigma *= math.exp((successes / offspring - 0.2) / 0.8) if offspring > 1 else (1.5 if successes else 1.5 ** -0.25)
        sigma = min(max(sigma, 1e-12), 1.0)
        send({"type": "iteration"})


if __name__ == "__main__":
    main()
