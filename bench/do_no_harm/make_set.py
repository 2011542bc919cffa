#!/usr/bin/env python3
"""Builds the do-no-harm evaluation set (issue 29) into OUTDIR as plain OBJ files named
kK_NAME.obj, K the kind: 1 holes touching at duplicated vertices, 2 open surfaces, 3 holes that
every boundary-only triangulation cuts, 4 ambiguous or nested islands. Generated meshes are made
here; real ones are read from Debian's assimp-testmodels (/usr/share/assimp/models) and the
repository's assets/, and written again as plain OBJ (v and f lines only). Deterministic.

usage: make_set.py OUTDIR [ASSIMP_MODELS] [ASSETS]"""

import math
import os
import sys

from meshes import Mesh, box, grid, read_mesh, rod, sphere, torus, write_obj

NU, NV = 48, 16  # the torus grid of the touching-hole cases


def quad_faces(u, v):
    """The two faces of quad (u, v) of torus(.., NU, NV)."""
    q = (u % NU) * NV + (v % NV)
    return {2 * q, 2 * q + 1}


def block(u0, v0, size):
    """Faces of the size x size quads from (u0, v0)."""
    return set().union(*(quad_faces(u0 + i, v0 + j) for i in range(size) for j in range(size)))


def pinched_torus(blocks):
    """A torus with square blocks of quads cut away; blocks placed corner to corner touch at one
    vertex only, which a file with split vertices then carries as two copies."""
    return torus(3.0, 1.0, NU, NV).remove_faces(set().union(*(block(*b) for b in blocks)))


def fan_cut(mesh, grow=2):
    """Two holes that touch at one vertex: the vertex farthest along (1, 2, 3) with a fan of at
    least six faces; two pairs of its fan's faces, opposite, each grown `grow` rings away from it
    without touching the other."""
    fans = {}
    for i, f in enumerate(mesh.faces):
        for v in f:
            fans.setdefault(v, []).append(i)
    apex = max((v for v in fans if len(fans[v]) >= 6),
               key=lambda v: sum(c * w for c, w in zip(mesh.points[v], (1, 2, 3))))
    order = [fans[apex][0]]  # the fan in order round the apex
    while len(order) < len(fans[apex]):
        f = mesh.faces[order[-1]]
        after = f[(f.index(apex) + 2) % 3]
        order.append(next(g for g in fans[apex] if mesh.faces[g][(mesh.faces[g].index(apex) + 1) % 3] == after))
    k = len(order)
    regions = [{order[0], order[1]}, {order[k // 2], order[k // 2 + 1]}]
    for _ in range(grow):
        for r, other in ((0, 1), (1, 0)):
            taken = {v for f in regions[other] for v in mesh.faces[f]}
            touched = {v for f in regions[r] for v in mesh.faces[f]}
            regions[r] |= {i for i, f in enumerate(mesh.faces)
                           if apex not in f and not taken & set(f) and len(touched & set(f)) >= 2}
    return mesh.remove_faces(regions[0] | regions[1])


def height_field(n, size, z):
    return grid(n, n, lambda u, v: (size * u / n, size * v / n, z(size * u / n, size * v / n)))


def sheet(n, profile, width):
    """An extruded sheet: profile(t) -> (x, z) for t in [0, 1], extruded along y."""
    return grid(n, n // 2, lambda u, v: (profile(u / n)[0], width * v / (n // 2), profile(u / n)[1]))


def polar_cut(mesh, direction, cos_max):
    """Removes faces whose centroid's direction from the origin is within acos(cos_max) of
    `direction`."""
    d = math.sqrt(sum(c * c for c in direction))

    def inside(x, y, z):
        r = math.sqrt(x * x + y * y + z * z)
        return (x * direction[0] + y * direction[1] + z * direction[2]) / (r * d) > cos_max

    return mesh.cut(inside)


def sphere_piece(n, radius, keep):
    """The faces of a sphere whose centroid satisfies keep(x, y, z) (a scan fragment)."""
    return sphere(n, radius).cut(lambda x, y, z: not keep(x, y, z))


def generated():
    """(name, mesh, split) for the generated meshes."""
    out = []
    # 1: holes touching at duplicated vertices (files with split vertices)
    out.append(("k1_torus_two_holes_touch", pinched_torus([(10, 2, 3), (13, 5, 3)]), True))
    out.append(("k1_torus_chain_of_three", pinched_torus([(4, 2, 3), (7, 5, 3), (10, 8, 3)]), True))
    out.append(("k1_torus_two_pinches", pinched_torus([(20, 4, 3), (23, 7, 3), (17, 7, 3)]), True))
    out.append(("k1_torus_ring_of_four", pinched_torus([(30, 2, 2), (32, 4, 2), (34, 2, 2), (32, 0, 2)]), True))
    # 2: open surfaces
    out.append(("k2_terrain", height_field(40, 4.0, lambda x, y: 0.3 * math.sin(1.3 * x) * math.cos(1.1 * y)
                                           + 0.15 * math.sin(3.1 * x + 1.0) + 0.1 * math.cos(2.3 * y)), False))
    out.append(("k2_horizon", height_field(40, 6.0, lambda x, y: 0.9 * math.sin(x) * math.exp(-(y - 3) ** 2 / 8)
                                           + 0.2 * y), False))
    out.append(("k2_saddle", height_field(30, 2.0, lambda x, y: 0.6 * (x - 1) ** 2 - 0.6 * (y - 1) ** 2), False))

    def mask(u, v):
        t, p = math.radians(-70 + 140 * u / 40), math.radians(-60 + 120 * v / 40)
        nose = 0.25 * math.exp(-((t / 0.25) ** 2 + ((p + 0.1) / 0.35) ** 2))
        r = 1.0 + nose
        return (0.8 * r * math.sin(t) * math.cos(p), 1.1 * r * math.sin(p), r * math.cos(t) * math.cos(p))

    face = grid(40, 40, mask).cut(lambda x, y, z: ((abs(x) - 0.3) / 0.13) ** 2 + ((y - 0.25) / 0.07) ** 2 < 1
                                  or (x / 0.25) ** 2 + ((y + 0.45) / 0.05) ** 2 < 1)
    out.append(("k2_face_mask", face, False))
    out.append(("k2_sheet_bent_L", sheet(40, lambda t: (min(t, 0.5) * 2, max(t - 0.5, 0) * 2), 1.0), False))
    out.append(("k2_sheet_Z", sheet(48, lambda t: (3 * t if t < 1 / 3 else (1 if t < 2 / 3 else 3 * t - 1),
                                                   0 if t < 1 / 3 else (3 * t - 1 if t < 2 / 3 else 1)), 1.0), False))
    out.append(("k2_dome", sphere(12).cut(lambda x, y, z: z < 0.2), False))
    # 3: holes that every boundary-only triangulation cuts
    plate = box(8, (-1, -1, -0.1), (1, 1, 0.1)).cut(lambda x, y, z: x * x + y * y < 0.09 and abs(z) > 0.09)
    out.append(("k3_rod_through_box", plate.add(rod(0.08, -0.6, 0.6)), False))
    ball = polar_cut(polar_cut(sphere(12), (0, 0, 1), 0.93), (0, 0, -1), 0.93)
    out.append(("k3_rod_through_sphere", ball.add(rod(0.1, -1.5, 1.5)), False))
    out.append(("k3_pin_in_hole", polar_cut(sphere(12), (0, 0, 1), 0.9).add(rod(0.05, 0.0, 1.4, rings=12)), False))
    out.append(("k3_part_next_to_hole", polar_cut(sphere(12), (0, 0, 1), 0.9).add(sphere(3, 0.06, (0, 0, 0.92))), False))
    wall = box(10, (0, 0, 0), (2, 1, 0.02)).cut(lambda x, y, z: (x - 2) ** 2 + (y - 0.5) ** 2 < 0.09)
    out.append(("k3_hole_round_thin_wall", wall, False))
    a = height_field(30, 2.0, lambda x, y: 0.1 * math.sin(2 * x)).cut(lambda x, y, z: (x - 1.5) ** 2 + (y - 1) ** 2 < 0.09)
    b = height_field(30, 2.0, lambda x, y: 0.1 * math.sin(2 * x + 2) + 0.04 * (x - 0.5)).transformed(
        lambda x, y, z: (x + 1.0, y, z))
    out.append(("k3_overlapping_scans", a.add(b), False))
    # 4: ambiguous or nested islands (fragments of the missing surface floating in the hole)
    cap = lambda c: lambda x, y, z: z / math.sqrt(x * x + y * y + z * z) > c
    holed = lambda: polar_cut(sphere(14), (0, 0, 1), 0.8)
    out.append(("k4_island_plain", holed().add(sphere_piece(14, 0.98, cap(0.93))), False))
    out.append(("k4_island_flipped", holed().add(sphere_piece(14, 0.98, cap(0.93)).flipped()), False))
    ring = sphere_piece(14, 0.98, lambda x, y, z: 0.9 < z / math.sqrt(x * x + y * y + z * z) < 0.96)
    out.append(("k4_island_with_island", holed().add(ring).add(sphere_piece(14, 0.96, cap(0.985))), False))
    two = polar_cut(sphere(14), (0.2, 0, 1), 0.85).add(polar_cut(sphere(14, 0.9), (-0.2, 0, 1), 0.85))
    out.append(("k4_island_in_two_holes", two.add(sphere_piece(14, 0.95, cap(0.97))), False))
    straddling = sphere_piece(14, 0.98, lambda x, y, z: abs(x / math.sqrt(x * x + y * y + z * z) - 0.5) < 0.12
                              and z > 0)
    out.append(("k4_island_across_the_rim", holed().add(straddling).add(sphere_piece(14, 0.97, cap(0.97))), False))
    ring_cut = {f for u in range(6) for v in range(6) if u in (0, 5) or v in (0, 5) for f in quad_faces(10 + u, 4 + v)}
    ring_cut -= quad_faces(10, 9)  # the ring of quads, open at one corner: it touches itself there
    out.append(("k4_island_touching_its_hole", torus(3.0, 1.0, NU, NV).remove_faces(ring_cut), True))
    return out


def real(assimp, assets):
    """(name, mesh, split, source) for the meshes read from files."""
    m = lambda *p: os.path.join(assimp, *p)
    out = [
        ("k1_bunny_two_holes_touch", fan_cut(read_mesh(os.path.join(assets, "bunny_closed.obj"))), True,
         "assets/bunny_closed.obj, two holes cut touching at one vertex"),
        ("k1_empty_mat_two_holes_touch", fan_cut(read_mesh(m("OBJ", "empty_mat.obj"))), True,
         "assimp OBJ/empty_mat.obj, two holes cut touching at one vertex"),
        ("k1_sphere_with_hole_stl", read_mesh(m("STL", "sphereWithHole.stl")), False,
         "assimp STL/sphereWithHole.stl welded by position as STL readers do"),
        ("k2_ragged_disk", read_mesh(os.path.join(assets, "ragged_disk.obj"), weld=False), False,
         "assets/ragged_disk.obj as is"),
        ("k3_wuson_off", read_mesh(m("OFF", "Wuson.off"), weld=False), False, "assimp OFF/Wuson.off as is"),
        ("k3_spider_stl", read_mesh(m("STL", "Spider_binary.stl")), False,
         "assimp STL/Spider_binary.stl welded by position"),
        ("k4_regr01", read_mesh(m("OBJ", "regr01.obj"), weld=False), False, "assimp OBJ/regr01.obj as is"),
        ("k4_spider_obj", read_mesh(m("OBJ", "spider.obj"), weld=False), False, "assimp OBJ/spider.obj as is"),
    ]
    return out


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    outdir = sys.argv[1]
    assimp = sys.argv[2] if len(sys.argv) > 2 else "/usr/share/assimp/models"
    assets = sys.argv[3] if len(sys.argv) > 3 else os.path.join(os.path.dirname(__file__), "..", "..", "assets")
    os.makedirs(outdir, exist_ok=True)
    for name, mesh, split in generated():
        write_obj(os.path.join(outdir, name + ".obj"), mesh, split, "generated by bench/do_no_harm/make_set.py")
    for name, mesh, split, source in real(assimp, assets):
        write_obj(os.path.join(outdir, name + ".obj"), mesh, split, "from " + source)


if __name__ == "__main__":
    main()
