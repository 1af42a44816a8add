#!/usr/bin/env python3
"""A problem that declares the true parameters it is given, for the "truth" field's tests
(tests/unit/problems/external_problem_test.cpp).

Parameters: truth = values separated by ':' ('inf' and 'nan' allowed, sent as the protocol's
strings), names = 1 (default) to name the two coordinates a and b, 0 not to. It describes
f(x) = sum of (x_i - 1)^2 on [-5, 5]^2 and evaluates it.
"""
import json
import math
import sys


def number(value):
    return value if math.isfinite(value) else str(value)


def send(message):
    sys.stdout.write(json.dumps(message) + "\n")
    sys.stdout.flush()


for line in sys.stdin:
    message = json.loads(line)
    if message["type"] == "describe":
        p = message["parameters"]
        description = {"type": "description", "version": "truth-1", "dimension": 2,
                       "lower": [-5.0, -5.0], "upper": [5.0, 5.0],
                       "truth": [number(float(v)) for v in p["truth"].split(":")]}
        if p.get("names", "1") == "1":
            description["names"] = ["a", "b"]
        send(description)
    elif message["type"] == "eval":
        send({"type": "values", "f": [sum((v - 1.0) ** 2 for v in x) for x in message["x"]]})
