#!/usr/bin/env python3
"""Reference values for Rng::jump() (tests/unit/problems/rng_test.cpp), computed independently.

xoshiro256** (Blackman and Vigna 2018) is linear over GF(2): one call to next() maps the 256-bit
state by a fixed matrix T. The reference jump() of xoshiro256starstar.c applies the polynomial
JUMP (four 64-bit words) in T to the state, which equals T^(2^128). This script computes the
jumped state two ways and checks they agree:
  1. the reference algorithm with the JUMP constants, written here from the published C code;
  2. T^(2^128) by 128 squarings of the 256x256 matrix T over GF(2), built from next() itself,
     which needs no constant at all.
Then it prints the first outputs after one and after two jumps from the state of Rng(seed)
(SplitMix64 seeding as in problems/core/rng.cpp). Run: python3 rng_jump_reference.py (a few seconds).
"""

M = (1 << 64) - 1
JUMP = (0x180EC6D33CFD0ABA, 0xD5A61266F0C9392C, 0xA9582618E03FC9AA, 0x39ABDC4529B1661C)


def rotl(x, k):
    return ((x << k) | (x >> (64 - k))) & M


def next_(s):
    """One step of xoshiro256**, in place; returns the output."""
    result = (rotl((s[1] * 5) & M, 7) * 9) & M
    t = (s[1] << 17) & M
    s[2] ^= s[0]
    s[3] ^= s[1]
    s[1] ^= s[2]
    s[0] ^= s[3]
    s[2] ^= t
    s[3] = rotl(s[3], 45)
    return result


def seed_state(seed):
    """Rng(seed): four outputs of SplitMix64 started at `seed`."""
    s, x = [], seed
    for _ in range(4):
        x = (x + 0x9E3779B97F4A7C15) & M
        z = x
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & M
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & M
        s.append(z ^ (z >> 31))
    return s


def jump_reference(s):
    acc = [0, 0, 0, 0]
    for word in JUMP:
        for b in range(64):
            if word >> b & 1:
                acc = [a ^ v for a, v in zip(acc, s)]
            next_(s)
    s[:] = acc


def pack(s):
    return s[0] | s[1] << 64 | s[2] << 128 | s[3] << 192


def unpack(v):
    return [(v >> (64 * i)) & M for i in range(4)]


def step_matrix():
    """Column c of T is the image of the c-th unit state; stored as 256 column bitsets."""
    cols = []
    for c in range(256):
        s = unpack(1 << c)
        next_(s)
        cols.append(pack(s))
    return cols


def apply(cols, v):
    out, c = 0, 0
    while v:
        if v & 1:
            out ^= cols[c]
        v >>= 1
        c += 1
    return out


def square(cols):
    return [apply(cols, col) for col in cols]


def jump_by_matrix_power(s):
    cols = step_matrix()
    for _ in range(128):
        cols = square(cols)
    s[:] = unpack(apply(cols, pack(s)))


if __name__ == "__main__":
    for seed in (42, 2024):
        a = seed_state(seed)
        b = list(a)
        jump_reference(a)
        jump_by_matrix_power(b)
        assert a == b, "the JUMP polynomial is not T^(2^128)"
        once = list(a)
        twice = list(a)
        jump_reference(twice)
        print(f"seed {seed}")
        print("  after one jump: ", ", ".join(f"0x{next_(once):016x}ULL" for _ in range(4)))
        print("  after two jumps:", ", ".join(f"0x{next_(twice):016x}ULL" for _ in range(4)))
    print("checked: reference jump == T^(2^128) for both seeds")
