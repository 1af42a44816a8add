#!/usr/bin/env python3
"""The sphere f(x) = sum of x_i^2 on [-5, 5]^dim as an mhbench external problem.

Standard library only. Run by mhbench as `external:cmd=python3 scripts/external/sphere_problem.py`
(problem side of the protocol: docs/extending.md, "External programs (any language)"). Parameters come in
the describe message (`params=dim=5`). json.dumps writes floats as their shortest round-trip text,
so every value reaches mhbench exactly.
"""
import json
import sys

VERSION = "sphere-1"


def send(message):
    sys.stdout.write(json.dumps(message) + "\n")
    sys.stdout.flush()


def main():
    for line in sys.stdin:
        message = json.loads(line)
        if message["type"] == "describe":
            dim = int(message["parameters"].get("dim", "10"))
            send({"type": "description", "version": VERSION, "dimension": dim,
                  "lower": [-5.0] * dim, "upper": [5.0] * dim,
                  "optimum": {"f": 0.0, "x": [0.0] * dim}})
        elif message["type"] == "eval":
            send({"type": "values", "f": [sum(v * v for v in x) for x in message["x"]]})


if __name__ == "__main__":
    main()
