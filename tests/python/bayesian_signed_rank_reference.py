#!/usr/bin/python3
"""An independent Monte Carlo of the Bayesian signed-rank test (Benavoli et al., JMLR 18, 2017),
written the way baycomp's SignedRankTest computes it: numpy's own Dirichlet draws and the full
(n+1) x (n+1) matrix of Walsh sums, O(n^2) per sample, no sorting or prefix sums. It shares no code
and no random stream with results/analysis/bayesian_signed_rank.cpp, so the two agree only within
Monte Carlo error; tests/unit/results/bayesian_signed_rank_test.cpp holds what this prints.

Conventions as mhbench's: z = x - y, left = z < -rope (x better when lower is better), the rope's
bounds in the rope, prior strength 0.5 at z0 = 0, a tie of the largest thetas shared.

    /usr/bin/python3 tests/python/bayesian_signed_rank_reference.py            # the unit tests' cases
    /usr/bin/python3 tests/python/bayesian_signed_rank_reference.py ROPE Z...  # any differences
"""
import sys

import numpy as np

SAMPLES = 200_000
PRIOR = 0.5


def test(z, rope, samples=SAMPLES, seed=20170101):
    z = np.concatenate(([0.0], np.asarray(z, dtype=float)))
    sums = z[:, None] + z[None, :]
    below = (sums < -2 * rope).astype(float)
    above = (sums > 2 * rope).astype(float)
    alpha = np.ones(len(z))
    alpha[0] = PRIOR
    rng = np.random.default_rng(seed)
    wins = np.zeros(3)
    means = np.zeros(3)
    for start in range(0, samples, 5000):
        w = rng.dirichlet(alpha, min(5000, samples - start))  # rows of weights
        left = np.einsum("si,ij,sj->s", w, below, w)
        right = np.einsum("si,ij,sj->s", w, above, w)
        theta = np.stack((left, 1 - (left + right), right), axis=1)
        largest = theta.max(axis=1, keepdims=True)
        top = theta == largest
        wins += (top / top.sum(axis=1, keepdims=True)).sum(axis=0)
        means += theta.sum(axis=0)
    return wins / samples, means / samples


CASES = {
    # name: (rope, differences)
    "mixed": (0.1, [-0.3, -0.25, -0.1, 0.02, -0.4, 0.15, -0.2, -0.05, -0.35, 0.1]),
    "near_rope": (0.02, [0.01 * ((7 * i) % 13 - 6) for i in range(20)]),
    "skewed": (0.2, [0.5 * np.sin(1.3 * i) + 0.15 for i in range(30)]),
}


def main():
    if len(sys.argv) > 2:
        rope = float(sys.argv[1])
        cases = {"given": (rope, [float(v) for v in sys.argv[2:]])}
    else:
        cases = CASES
    for name, (rope, z) in cases.items():
        p, mean = test(z, rope)
        print(f"{name}: n={len(z)} rope={rope} P(left,rope,right)=({p[0]:.4f}, {p[1]:.4f}, {p[2]:.4f}) "
              f"mean theta=({mean[0]:.4f}, {mean[1]:.4f}, {mean[2]:.4f})")


if __name__ == "__main__":
    main()
