#!/usr/bin/env python3
"""An external problem that gives up at its first eval message without reading it, for
tests/integration/external_study_test.cpp.

Usage: early_exit_problem.py DIM MARKER. It describes a sphere of dimension DIM in [-5, 5], then
waits for the first byte of the next message, writes one line to stderr and exits with status 3.
A batch larger than the pipe buffer (64 KiB) is then still being written by mhbench: the rest
meets a pipe without reader (EPIPE, and SIGPIPE unless mhbench keeps it off), every time.
MARKER only tags the command line.
"""
import json
import os
import sys

dim = int(sys.argv[1])
received = b""
while not received.endswith(b"\n"):
    chunk = os.read(0, 4096)
    if not chunk:
        sys.exit(0)
    received += chunk
sys.stdout.write(json.dumps({"type": "description", "version": "early-exit-1", "dimension": dim,
                             "lower": [-5.0] * dim, "upper": [5.0] * dim}) + "\n")
sys.stdout.flush()
os.read(0, 1)
sys.stderr.write("early: the model gave up\n")
sys.exit(3)
