#!/usr/bin/python3
"""Plot of make bench-aa: edge RMS error (log) against seconds per frame
(log), one line per filter and output format.  Plain SVG by hand."""
import math, sys

rows = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith('#')]
series = {}
for r in rows:
    series.setdefault((r[1], r[2]), []).append((int(r[0]), float(r[3]), max(float(r[4]), 1e-6)))
W, H, L, R, T, B = 720, 460, 80, 180, 40, 60
xs = [p[1] for s in series.values() for p in s]
ys = [p[2] for s in series.values() for p in s]
x0, x1 = math.floor(math.log10(min(xs))), math.ceil(math.log10(max(xs)))
y0, y1 = math.floor(math.log10(min(ys))), math.ceil(math.log10(max(ys)))
X = lambda v: L + (math.log10(v) - x0) / (x1 - x0) * (W - L - R)
Y = lambda v: T + (y1 - math.log10(v)) / (y1 - y0) * (H - T - B)
o = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="12">' % (W, H),
     '<rect width="100%" height="100%" fill="white"/>',
     '<text x="%d" y="20" font-size="14">glsplay anti-aliasing: edge error vs time per frame (make bench-aa)</text>' % L]
for e in range(x0, x1 + 1):
    o.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="#ddd"/>' % (X(10**e), T, X(10**e), H - B))
    o.append('<text x="%.1f" y="%d" text-anchor="middle">1e%d</text>' % (X(10**e), H - B + 16, e))
for e in range(y0, y1 + 1):
    o.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#ddd"/>' % (L, Y(10**e), W - R, Y(10**e)))
    o.append('<text x="%d" y="%.1f" text-anchor="end">1e%d</text>' % (L - 6, Y(10**e) + 4, e))
yb = 1 / 256
if 10**y0 < yb < 10**y1:
    o.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#999" stroke-dasharray="4 3"/>' % (L, Y(yb), W - R, Y(yb)))
    o.append('<text x="%d" y="%.1f" fill="#666">1/256 px</text>' % (W - R - 60, Y(yb) - 4))
o.append('<text x="%d" y="%d" text-anchor="middle">seconds per frame</text>' % ((L + W - R) // 2, H - 20))
o.append('<text x="18" y="%d" transform="rotate(-90 18 %d)" text-anchor="middle">edge RMS error, px</text>' % ((T + H - B) // 2, (T + H - B) // 2))
colours = {'box': '#1f77b4', 'gauss': '#d62728'}
dash = {'png8': '', 'png16': '6 3', 'pfm': '2 2'}
for i, ((f, out), pts) in enumerate(sorted(series.items())):
    pts.sort()
    path = ' '.join('%s%.1f,%.1f' % ('M' if j == 0 else 'L', X(p[1]), Y(p[2])) for j, p in enumerate(pts))
    o.append('<path d="%s" fill="none" stroke="%s" stroke-width="1.5" stroke-dasharray="%s"/>' % (path, colours[f], dash[out]))
    for p in pts:
        o.append('<circle cx="%.1f" cy="%.1f" r="2.5" fill="%s"/>' % (X(p[1]), Y(p[2]), colours[f]))
        if out == 'png16':
            o.append('<text x="%.1f" y="%.1f" font-size="9" fill="%s">%d</text>' % (X(p[1]) + 4, Y(p[2]) - 4, colours[f], p[0]))
    ly = T + 20 + 18 * i
    o.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="%s" stroke-width="1.5" stroke-dasharray="%s"/>' % (W - R + 15, ly, W - R + 45, ly, colours[f], dash[out]))
    o.append('<text x="%d" y="%d">%s %s</text>' % (W - R + 50, ly + 4, f, out))
o.append('<text x="%d" y="%d" font-size="10" fill="#666">labels: N (NxN samples)</text>' % (W - R + 15, T + 20 + 18 * len(series)))
o.append('</svg>')
open(sys.argv[2], 'w').write('\n'.join(o) + '\n')
