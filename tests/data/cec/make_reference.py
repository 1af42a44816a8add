#!/usr/bin/env python3
"""Writes cec2017_reference.csv and cec2022_reference.csv from the official CEC code.

Every (function, dimension) with official data, at these points (point_id):
  0 the shift optimum o (first D numbers of shift_data_F.txt; line 0 for compositions)
  1-3 uniform in [-100, 100]^D (Python's random, seed 20171022, in the order written)
  4 o + 1e-3 e_1 (the example of the cec README's quirk Q1)
  5 compositions only: o_1, the optimum of component 2 (line 1 of the shift file)
  6 the box corner (-100, 100, -100, ...)
Each point is evaluated by a fresh process (the official code keeps state between calls).
Usage: make_reference.py CASES REF17 REF22 DATA17 DATA22, where CASES lists suite:f:dim per line
and REF17/REF22 are reference_driver.cpp built against the official code (see its header).
"""
import random
import subprocess
import sys

cases_file, ref17, ref22, data17, data22 = sys.argv[1:6]
composition = {'cec2017': range(21, 31), 'cec2022': range(9, 13)}
rng = random.Random(20171022)
rows = {'cec2017': [], 'cec2022': []}
for case in open(cases_file).read().split():
    suite, f, d = case.split(':')
    f, d = int(f), int(d)
    exe, data = (ref17, data17) if suite == 'cec2017' else (ref22, data22)
    shift_lines = [l.split() for l in open(f'{data}/input_data/shift_data_{f}.txt') if l.split()]
    o = [float(t) for t in shift_lines[0][:d]]
    points = [(0, o)]
    for pid in (1, 2, 3):
        points.append((pid, [rng.uniform(-100, 100) for _ in range(d)]))
    points.append((4, [o[0] + 1e-3] + o[1:]))
    if f in composition[suite]:
        points.append((5, [float(t) for t in shift_lines[1][:d]]))
    points.append((6, [-100.0 if i % 2 == 0 else 100.0 for i in range(d)]))
    for pid, x in points:
        text = ' '.join('%.17g' % v for v in x)
        out = subprocess.run([exe, str(f), str(d)], input=text, capture_output=True, text=True,
                             cwd=data, check=True).stdout
        # At D = 2 the 2017 code warns that F17-F22 and F29-F30 are "not defined", then computes.
        rows[suite].append(f'{suite},{f},{d},{pid},{out.split()[-1]},{text}')
for suite, lines in rows.items():
    with open(f'{suite}_reference.csv', 'w') as fh:
        fh.write('suite,function,dim,point_id,f,x\n' + '\n'.join(lines) + '\n')
