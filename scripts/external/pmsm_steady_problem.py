#!/usr/bin/env python3
"""PMSM parameter identification from steady-state dq data (Li, Wang and Ji 2017, eqs. 2 and 11)
as an mhbench external problem, in Python (standard library only): the same function as the
built-in `pmsm:data=FILE` (model=steady), written out so that a drive engineer can start from it.

Parameters (`params=data=drive.csv;settle=0.01`): data = a CSV of t,ud,uq,id,iq,omega[,injected]
('#' comment lines allowed), settle = seconds left out after a switch of the injection state
(0.01), id_threshold = |id| (A) that marks the injected state without an 'injected' column (1),
w1..w4 = the residuals' weights (0.25 each). The search box is the paper's. A dataset whose
metadata lines give the motor's parameters (`# Rs=0.33`, `# Ld=...`, `# Lq=...`, `# psi=...`, as
`mhbench simulate` writes them) makes them the description's "truth", so that runs.csv reports the
errors of the estimates (Rs_err_pct, ...) as for the built-in.

theta = (Rs, Ld, Lq, psi);  r_d = ud - (Rs id - Lq omega iq),  r_q = uq - (Rs iq + Ld omega id + psi omega)
f = sum over the last n settled samples of each state of w1 r_d^2 + w2 r_q^2 (id = 0) and
w3 r_d^2 + w4 r_q^2 (injected), n = the smaller of the two counts.
"""
import csv
import json
import sys

VERSION = "pmsm-steady-py-1"
LOWER = [0.0, 0.0, 0.0, 0.0]
UPPER = [0.5, 0.01, 0.01, 0.1]


NAMES = ["Rs", "Ld", "Lq", "psi"]


def read_truth(path):
    """The motor's parameters from the dataset's '# key=value' lines, or None if one is missing."""
    metadata = {}
    with open(path) as f:
        for line in f:
            if line.startswith("#") and "=" in line:
                key, _, value = line[1:].partition("=")
                metadata[key.strip()] = value.strip()
            elif line.strip() and not line.startswith("#"):
                break
    try:
        return [float(metadata[name]) for name in NAMES]
    except (KeyError, ValueError):
        return None


def read_rows(path, id_threshold):
    with open(path, newline="") as f:
        lines = [line for line in f if line.strip() and not line.startswith("#")]
    table = list(csv.DictReader(lines))
    rows = []
    for r in table:
        row = {k: float(r[k]) for k in ("t", "ud", "uq", "id", "iq", "omega")}
        row["omega_iq"] = row["omega"] * row["iq"]
        row["omega_id"] = row["omega"] * row["id"]
        if "injected" in r and r["injected"] not in (None, ""):
            row["injected"] = float(r["injected"]) != 0.0
        else:
            row["injected"] = abs(row["id"]) > id_threshold
        rows.append(row)
    return rows


def settled(rows, settle):
    """The rows of each state that eq. 2 may use, as mhbench's pair_samples chooses them."""
    t = [r["t"] for r in rows]
    steps = sorted(t[k + 1] - t[k] for k in range(len(t) - 1) if t[k + 1] > t[k])
    ts = steps[len(steps) // 2] if steps else 0.0
    state_start = float("-inf")
    out = ([], [])
    for k, r in enumerate(rows):
        switched = k > 0 and r["injected"] != rows[k - 1]["injected"]
        if switched and steps and abs(t[k] - t[k - 1] - ts) <= 0.01 * ts:
            state_start = t[k]
        elif switched:
            state_start = float("-inf")
        if t[k] - state_start >= settle:
            out[1 if r["injected"] else 0].append(r)
    n = min(len(out[0]), len(out[1]))
    if n == 0:
        raise ValueError("no settled samples in one of the two states")
    return out[0][len(out[0]) - n:], out[1][len(out[1]) - n:]


def main():
    samples = None
    for line in sys.stdin:
        message = json.loads(line)
        if message["type"] == "describe":
            p = message["parameters"]
            rows = read_rows(p["data"], float(p.get("id_threshold", "1")))
            plain, injected = settled(rows, float(p.get("settle", "0.01")))
            w = [float(p.get("w%d" % i, "0.25")) for i in range(1, 5)]
            # (sample, weight of r_d, weight of r_q): the id = 0 samples, then the injected ones.
            samples = [(r, w[0], w[1]) for r in plain] + [(r, w[2], w[3]) for r in injected]
            description = {"type": "description", "version": VERSION, "dimension": 4,
                           "lower": LOWER, "upper": UPPER, "names": NAMES}
            truth = read_truth(p["data"])
            if truth is not None:
                description["truth"] = truth
            sys.stdout.write(json.dumps(description) + "\n")
        elif message["type"] == "eval":
            values = []
            for rs, ld, lq, psi in message["x"]:
                # The built-in's operations in its order (omega*iq and omega*id formed first), so
                # that each term is the same double; only the order of the sum differs.
                fd = 0.0
                fq = 0.0
                for r, wd, wq in samples:
                    d = r["ud"] - rs * r["id"] + lq * r["omega_iq"]
                    q = r["uq"] - rs * r["iq"] - ld * r["omega_id"] - psi * r["omega"]
                    fd += wd * (d * d)
                    fq += wq * (q * q)
                values.append(fd + fq)
            sys.stdout.write(json.dumps({"type": "values", "f": values}) + "\n")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
