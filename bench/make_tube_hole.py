# A wavy tube closed at the bottom by a fan, whose open top is one hole of N boundary edges (OBJ):
# RINGS rings of N vertices, ring k at z = 0.02 k + 0.05 sin(7t) k / (RINGS - 1). The threads
# benchmark's one large hole (bench/README.md, Threads): `make_tube_hole.py 1000 40 hole1000.obj`.
# usage: make_tube_hole.py N RINGS OUT.obj
import math, sys
n = int(sys.argv[1]); rings = int(sys.argv[2]); out = sys.argv[3]
lines = []
for k in range(rings):
    for i in range(n):
        t = 2 * math.pi * i / n
        r = 1.0
        z = k * 0.02 + 0.05 * math.sin(7 * t) * (k / max(1, rings - 1))
        lines.append("v %.9f %.9f %.9f" % (r * math.cos(t), r * math.sin(t), z))
lines.append("v 0 0 -0.5")
c = rings * n + 1
for k in range(rings - 1):
    for i in range(n):
        a = k * n + i + 1; b = k * n + (i + 1) % n + 1
        a2 = a + n; b2 = b + n
        lines.append("f %d %d %d" % (a, b, b2)); lines.append("f %d %d %d" % (a, b2, a2))
for i in range(n):
    a = i + 1; b = (i + 1) % n + 1
    lines.append("f %d %d %d" % (b, a, c))
open(out, "w").write("\n".join(lines) + "\n")
