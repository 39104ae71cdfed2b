#!/usr/bin/env python3
"""looks-diff.py A.md B.md: the rows of two looks tables that differ, and both summaries.

The looks table (`LOOKS=48 cargo test --release --test it video::looks::looks_table --
--ignored --nocapture`) is written to target/tmp/video_looks/table.md; copy it aside
before a change, run the table again after it, and compare the two (a row differs when
its verdict, centre or mark RMS, scale or μ_k does). See docs/development.md, "Working
on the tracker".
"""
import sys
def rows(p):
    d, summ = {}, []
    for line in open(p):
        if line.startswith('| ') and not line.startswith('| seed'):
            c = [x.strip() for x in line.strip().strip('|').split('|')]
            if c[0].isdigit():
                d[int(c[0])] = c
        elif 'looks:' in line:
            summ.append(line.strip())
    return d, summ
a, sa = rows(sys.argv[1]); b, sb = rows(sys.argv[2])
for k in sorted(set(a) | set(b)):
    ra, rb = a.get(k), b.get(k)
    if ra is None or rb is None or ra[2:7] != rb[2:7]:
        fa = ' | '.join(ra[2:7]) if ra else '-'
        fb = ' | '.join(rb[2:7]) if rb else '-'
        print(f"{k:3}: {fa[:110]}\n  -> {fb[:110]}")
print('A:', *sa, sep='\n  '); print('B:', *sb, sep='\n  ')
