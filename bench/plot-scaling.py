#!/usr/bin/env python3
"""Draw the cost per robot-step of the simulator against the number of
robots (log scale) from bench/scaling.tsv (written by bench/scaling.sh) as
an SVG, with no library beyond Python's own:

    python3 bench/plot-scaling.py bench/scaling.tsv bench/scaling.svg

One line per number of cores: microseconds of wall-clock time per
robot-step (1e6 / robot-steps per second), the benchmark world only; the
grey band is "within 2x" of the 10-robot figure on one core (the flatness
the issue asks for). The legend gives the range of the one-way latency
between the two processors (the file's latency_ns, when it has it) over
the two-core rows. A two-core point drawn hollow used no more than 1.2
cores' worth of CPU time (CPU time over wall-clock time): other work held
the second core while it ran (or, below 16 robots, the step is not split)."""
import csv
import math
import sys

src, dst = sys.argv[1], sys.argv[2]
rows = [r for r in csv.DictReader(open(src), delimiter='\t') if r['what'] == 'bench']
series = {}
for r in rows:
    rate = float(r['robot_steps_per_s'])
    used = float(r['cpu_us_per_robot_step']) * rate / 1e6   # cores' worth of CPU time
    series.setdefault(int(r['cores']), []).append(
        (int(r['robots']), 1e6 / rate, int(r['cores']) > 1 and used < 1.2))
for s in series.values():
    s.sort()

W, H, L, R, T, B = 640, 400, 70, 20, 40, 60
xs = [n for s in series.values() for n, _, _ in s]
ys = [u for s in series.values() for _, u, _ in s]
base = {n: u for n, u, _ in series.get(1, [])}.get(10)
x0, x1 = math.log10(min(xs)), math.log10(max(xs))
y1 = max(ys + ([2 * base] if base else [])) * 1.15


def px(n):
    return L + (math.log10(n) - x0) / (x1 - x0) * (W - L - R)


def py(u):
    return H - B - u / y1 * (H - T - B)


out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" '
       'font-family="sans-serif" font-size="12">' % (W, H),
       '<rect width="100%" height="100%" fill="white"/>',
       '<text x="%d" y="22" font-size="14">afrp simulator: wall-clock time per '
       'robot-step (dt = 0.01, 10 m^2 per robot)</text>' % L]
if base:
    out.append('<rect x="%d" y="%.1f" width="%d" height="%.1f" fill="#eee"/>'
               % (L, py(2 * base), W - L - R, py(0) - py(2 * base)))
    out.append('<text x="%d" y="%.1f" fill="#777" text-anchor="end">within 2x of the '
               '10-robot figure (1 core)</text>' % (W - R - 6, py(2 * base) + 14))
out.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="black"/>' % (L, H - B, W - R, H - B))
out.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="black"/>' % (L, T, L, H - B))
for n in sorted(set(xs)):
    out.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="black"/>'
               % (px(n), H - B, px(n), H - B + 5))
    out.append('<text x="%.1f" y="%d" text-anchor="middle">%d</text>' % (px(n), H - B + 18, n))
out.append('<text x="%d" y="%d" text-anchor="middle">robots (log scale)</text>'
           % ((L + W - R) // 2, H - 18))
step = 0.5 if y1 <= 4 else 1.0
v = 0.0
while v <= y1:
    out.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="black"/>' % (L - 5, py(v), L, py(v)))
    out.append('<text x="%d" y="%.1f" text-anchor="end">%.1f</text>' % (L - 8, py(v) + 4, v))
    v += step
out.append('<text x="18" y="%d" transform="rotate(-90 18 %d)" text-anchor="middle">'
           'microseconds per robot-step</text>' % ((T + H - B) // 2, (T + H - B) // 2))
colours = {1: '#1f5fbf', 2: '#d0602a'}
for k, (cores, s) in enumerate(sorted(series.items())):
    c = colours.get(cores, 'black')
    out.append('<polyline fill="none" stroke="%s" stroke-width="2" points="%s"/>'
               % (c, ' '.join('%.1f,%.1f' % (px(n), py(u)) for n, u, _ in s)))
    for n, u, alone in s:
        out.append('<circle cx="%.1f" cy="%.1f" r="%d" fill="%s" stroke="%s" stroke-width="2"/>'
                   % (px(n), py(u), 4 if alone else 3, 'white' if alone else c, c))
        out.append('<text x="%.1f" y="%.1f" fill="%s" text-anchor="middle">%.2f</text>'
                   % (px(n), py(u) - 8, c, u))
    lats = sorted(int(r['latency_ns']) for r in rows
                  if int(r['cores']) == cores and (r.get('latency_ns') or '-').isdigit())
    out.append('<text x="%d" y="%d" fill="%s">%s</text>'
               % (W - R - 190, T + 16 + 16 * k, c,
                  '%d core%s' % (cores, '' if cores == 1 else 's')
                  + (' (%d-%d ns apart)' % (lats[0], lats[-1]) if cores > 1 and lats else '')))
if any(alone for s in series.values() for _, _, alone in s):
    out.append('<text x="%d" y="%d" fill="#777">hollow: two cores asked for, one used</text>'
               % (L + 6, T + 16))
out.append('</svg>')
open(dst, 'w').write('\n'.join(out) + '\n')
