"""Small triangle-mesh toolkit for the do-no-harm set: surfaces built from grids, welding by
exact position, cutting faces away, and OBJ/OFF/STL reading and OBJ writing (plain v and f
lines, optionally with every face on its own copies of its corners, as exporters that split
vertices write them). Pure Python, no dependencies."""

import math
import struct


class Mesh:
    def __init__(self, points=None, faces=None):
        self.points = list(points or [])
        self.faces = list(faces or [])

    def add(self, other):
        """Appends another mesh as a separate piece."""
        base = len(self.points)
        self.points += other.points
        self.faces += [tuple(base + i for i in f) for f in other.faces]
        return self

    def centroid(self, f):
        a, b, c = (self.points[i] for i in self.faces[f])
        return tuple((a[k] + b[k] + c[k]) / 3 for k in range(3))

    def remove_faces(self, doomed):
        """Drops faces whose index is in `doomed` (and vertices no face uses)."""
        self.faces = [f for i, f in enumerate(self.faces) if i not in doomed]
        return self.compact()

    def cut(self, predicate):
        """Drops the faces whose centroid satisfies predicate(x, y, z)."""
        return self.remove_faces({i for i in range(len(self.faces)) if predicate(*self.centroid(i))})

    def compact(self):
        used = sorted({v for f in self.faces for v in f})
        new = {v: i for i, v in enumerate(used)}
        self.points = [self.points[v] for v in used]
        self.faces = [tuple(new[v] for v in f) for f in self.faces]
        return self

    def weld(self):
        """Merges vertices at exactly the same position; drops faces that become degenerate."""
        ids, new = {}, []
        for p in self.points:
            new.append(ids.setdefault(tuple(p), len(ids)))
        self.points = [None] * len(ids)
        for p, i in ids.items():
            self.points[i] = p
        faces = [tuple(new[v] for v in f) for f in self.faces]
        seen = set()
        self.faces = []
        for f in faces:
            key = min(f[i:] + f[:i] for i in range(3))
            if len(set(f)) == 3 and key not in seen:
                seen.add(key)
                self.faces.append(f)
        return self

    def transformed(self, fn):
        return Mesh([fn(*p) for p in self.points], self.faces)

    def flipped(self):
        return Mesh(self.points, [(a, c, b) for a, b, c in self.faces])


def grid(nu, nv, at, wrap_u=False, wrap_v=False):
    """A surface from at(u, v) over a (nu+1) x (nv+1) lattice of integers u, v; each quad as two
    triangles, counter-clockwise in (u, v). Wrapped directions reuse the first row."""
    cols = nu if wrap_u else nu + 1
    rows = nv if wrap_v else nv + 1
    mesh = Mesh([at(u, v) for u in range(cols) for v in range(rows)])

    def idx(u, v):
        return (u % cols) * rows + (v % rows)

    for u in range(nu):
        for v in range(nv):
            a, b, c, d = idx(u, v), idx(u + 1, v), idx(u + 1, v + 1), idx(u, v + 1)
            mesh.faces += [(a, b, c), (a, c, d)]
    return mesh


def torus(big, small, nu, nv):
    def at(u, v):
        s, t = 2 * math.pi * u / nu, 2 * math.pi * v / nv
        r = big + small * math.cos(t)
        return (r * math.cos(s), r * math.sin(s), small * math.sin(t))

    return grid(nu, nv, at, True, True)


def box_lattice(n, project):
    """A closed surface from the six faces of the cube [-n, n]^3 (integer lattice, outward),
    each point mapped by project(x, y, z): the identity gives a box, normalising a sphere."""
    mesh = Mesh()
    for axis in range(3):
        for sign in (-1, 1):
            def at(u, v, axis=axis, sign=sign):
                p = [0, 0, 0]
                p[axis] = sign * n
                p[(axis + 1) % 3] = (u - n) * sign
                p[(axis + 2) % 3] = v - n
                return project(*p)

            mesh.add(grid(2 * n, 2 * n, at))
    return mesh.weld()


def sphere(n, radius=1.0, centre=(0, 0, 0)):
    def project(x, y, z):
        r = math.sqrt(x * x + y * y + z * z)
        return tuple(centre[k] + radius * (x, y, z)[k] / r for k in range(3))

    return box_lattice(n, project)


def box(n, low, high):
    def project(x, y, z):
        return tuple(low[k] + (high[k] - low[k]) * ((x, y, z)[k] + n) / (2 * n) for k in range(3))

    return box_lattice(n, project)


def rod(radius, z0, z1, segments=12, rings=8, centre=(0.0, 0.0)):
    """A closed cylinder along z, with fan caps."""
    def at(u, v):
        s = 2 * math.pi * u / segments
        return (centre[0] + radius * math.cos(s), centre[1] + radius * math.sin(s),
                z0 + (z1 - z0) * v / rings)

    mesh = grid(segments, rings, at, wrap_u=True)
    rows = rings + 1
    bottom, top = len(mesh.points), len(mesh.points) + 1
    mesh.points += [(centre[0], centre[1], z0), (centre[0], centre[1], z1)]
    for u in range(segments):
        a, b = u * rows, ((u + 1) % segments) * rows
        mesh.faces += [(bottom, b, a), (top, a + rings, b + rings)]
    return mesh


def read_mesh(path, weld=True):
    """OBJ (v, f), OFF or STL (ASCII or binary); welded by exact position, or as the file shares
    its vertices (faces using a vertex twice dropped)."""
    data = open(path, "rb").read()
    if path.lower().endswith(".stl"):
        mesh = read_stl(data)
    elif path.lower().endswith(".off"):
        words = data.decode().split("\n")
        lines = [l.split("#")[0].split() for l in words]
        lines = [l for l in lines if l]
        nv, nf = int(lines[1][0]), int(lines[1][1])
        points = [tuple(float(x) for x in l[:3]) for l in lines[2:2 + nv]]
        faces = []
        for l in lines[2 + nv:2 + nv + nf]:
            c = [int(x) for x in l[1:1 + int(l[0])]]
            faces += [(c[0], c[i], c[i + 1]) for i in range(1, len(c) - 1)]
        mesh = Mesh(points, faces)
    else:
        points, faces = [], []
        for line in data.decode(errors="replace").splitlines():
            w = line.split()
            if w and w[0] == "v":
                points.append(tuple(float(x) for x in w[1:4]))
            elif w and w[0] == "f":
                c = [int(x.split("/")[0]) for x in w[1:]]
                c = [i - 1 if i > 0 else len(points) + i for i in c]
                faces += [(c[0], c[i], c[i + 1]) for i in range(1, len(c) - 1)]
        mesh = Mesh(points, faces)
    if weld:
        return mesh.weld().compact()
    mesh.faces = [f for f in mesh.faces if len(set(f)) == 3]
    return mesh.compact()


def read_stl(data):
    points, faces = [], []
    if data[:5] == b"solid" and b"facet" in data[:1000]:
        for line in data.decode().splitlines():
            w = line.split()
            if w and w[0] == "vertex":
                points.append(tuple(float(x) for x in w[1:4]))
    else:
        count = struct.unpack("<I", data[80:84])[0]
        for t in range(count):
            values = struct.unpack("<12f", data[84 + 50 * t:84 + 50 * t + 48])
            points += [tuple(values[3 + 3 * k:6 + 3 * k]) for k in range(3)]
    faces = [(3 * t, 3 * t + 1, 3 * t + 2) for t in range(len(points) // 3)]
    return Mesh(points, faces)


def write_obj(path, mesh, split=False, comment=""):
    """Plain OBJ. split: every face on its own three vertices (an exporter's split vertices)."""
    with open(path, "w") as out:
        for line in comment.splitlines():
            out.write("# " + line + "\n")
        if split:
            for f in mesh.faces:
                for v in f:
                    out.write("v %r %r %r\n" % tuple(mesh.points[v]))
            for t in range(len(mesh.faces)):
                out.write("f %d %d %d\n" % (3 * t + 1, 3 * t + 2, 3 * t + 3))
        else:
            for p in mesh.points:
                out.write("v %r %r %r\n" % tuple(p))
            for f in mesh.faces:
                out.write("f %d %d %d\n" % tuple(v + 1 for v in f))
