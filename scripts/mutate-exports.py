#!/usr/bin/env python3
"""Damages real data exports at random and runs groovelab on each damaged copy.

Usage: scripts/mutate-exports.py BINARY FOLDER N SEED

FOLDER holds exports from Tracker, Logger Pro, Graphical Analysis, phyphox or a
spreadsheet (any files; a PROVENANCE.md is skipped). N times, one of them is damaged
1-4 ways (a cut, a repeated piece, a spliced hostile token, an early end, a changed
digit, two lines swapped) and given to `data` and `data --format json`, every third to
`fit`, every sixth to `render`. Counted: panics (exit 101 or "panicked"), exits other
than 0 and 2, more than one stderr line on exit 2, and NaN/inf printed on exit 0; the
damaged copies of the failures are kept in a temporary folder it names.
Real exports are not kept in the repository: bring your own (results in BENCHMARKS.md).
"""
import os, random, re, subprocess, sys, tempfile
BIN, ROOT, N, SEED = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
rng = random.Random(SEED)
files = [os.path.join(d, f) for d, _, fs in os.walk(ROOT) for f in fs if f != 'PROVENANCE.md']
SPLICE = [b'<', b'>', b'&', b'&amp;', b'&#0;', b'NaN', b'nan', b'inf', b'-inf', b'1e308', b'-1e308',
          b'1e-320', b'0', b'-', b'\r\n', b'\t', b',', b';', b'"', b'\x00', b'\xff\xfe', b'\n\n\n',
          b'9999999999', b'-0', b'e', b'.', b'</object>', b'<![CDATA[', b'\xe2\x80\xaf']
NONFINITE = re.compile(rb'(?<![A-Za-z_])(NaN|nan|inf|-inf|Infinity)(?![A-Za-z_])')
base = {f: open(f, 'rb').read() for f in files}
stats = dict(exit0=0, exit2=0, runs=0, panics=0, badexit=0, twolines=0, nonfinite=0, timeouts=0)
bad = []
tmp = tempfile.mkdtemp(prefix='groovelab-mutants-')
for k in range(N):
    f = rng.choice(files)
    b = bytearray(base[f])
    for _ in range(rng.randint(1, 4)):
        kind = rng.randrange(6)
        i = rng.randrange(len(b) + 1)
        j = min(len(b), i + rng.randint(1, 400))
        if kind == 0: del b[i:j]
        elif kind == 1: b[i:i] = b[i:j]
        elif kind == 2: b[i:i] = rng.choice(SPLICE)
        elif kind == 3: del b[i:]
        elif kind == 4:  # change a digit
            ds = [m.start() for m in re.finditer(rb'[0-9]', bytes(b[i:j]))]
            if ds: b[i + rng.choice(ds)] = ord(rng.choice('0123456789'))
        else:  # swap two lines
            lines = bytes(b).split(b'\n')
            if len(lines) > 2:
                a, c = rng.randrange(len(lines)), rng.randrange(len(lines))
                lines[a], lines[c] = lines[c], lines[a]
                b = bytearray(b'\n'.join(lines))
    ext = os.path.splitext(f)[1] or '.txt'
    p = os.path.join(tmp, 'm' + ext)
    open(p, 'wb').write(bytes(b))
    cmds = [['data', p], ['data', '--format', 'json', p]]
    if k % 3 == 0:
        cmds.append(['fit', '--preset', 'paper-b4.9', '--data', p])
    if k % 6 == 0:
        cmds.append(['render', '--preset', 'paper-b4.9', '--data', p, '--size', '80x24'])
    for c in cmds:
        stats['runs'] += 1
        try:
            r = subprocess.run([BIN] + c, capture_output=True, timeout=60,
                               env=dict(os.environ, GROOVELAB_PRESETS='/nonexistent', NO_COLOR='1'))
        except subprocess.TimeoutExpired:
            stats['timeouts'] += 1; bad.append(('timeout', f, c)); continue
        why = None
        stats['exit0' if r.returncode == 0 else 'exit2'] += r.returncode in (0, 2)
        if r.returncode == 101 or b'panicked' in r.stderr: stats['panics'] += 1; why = 'panic'
        elif r.returncode not in (0, 2): stats['badexit'] += 1; why = f'exit {r.returncode}'
        elif r.returncode == 2 and len(r.stderr.strip().split(b'\n')) > 1: stats['twolines'] += 1; why = 'two lines'
        elif r.returncode == 0 and NONFINITE.search(r.stdout.replace(b'empty or NaN', b'')): stats['nonfinite'] += 1; why = 'nonfinite'
        if why:
            keep = os.path.join(tmp, f'bad-{len(bad)}{ext}')
            open(keep, 'wb').write(bytes(b))
            bad.append((why, f, c[0], keep, r.stderr[-300:]))
print(stats)
for x in bad[:20]: print(x)
if bad: print(f'damaged copies of the failures: {tmp}')
