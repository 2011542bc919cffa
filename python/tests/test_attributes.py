"""A fill keeps what the mesh carries: original colours bit for bit, new vertices coloured from
the boundary, through a save and a load."""

import numpy as np

import holefill
from conftest import cut_sphere


def test_colours_are_kept_and_given_to_the_patch(tmp_path):
    vertices, faces = cut_sphere(16, 32, 3)
    n = len(vertices)
    rgb = np.clip((vertices + 1) * 127.5, 0, 255).astype(np.uint8)
    mesh = holefill.Mesh(vertices, faces, vertex_colors=rgb)
    records = holefill.fill(mesh)
    assert records[0]["filled"] and records[0]["new_vertices"] > 0
    colours = mesh.vertex_colors
    assert np.array_equal(colours[:n], rgb / 255.0)
    new = colours[n:]
    assert len(new) == records[0]["new_vertices"]
    boundary = rgb[:32] / 255.0  # the hole's loop is the first ring
    assert np.all(new >= boundary.min(axis=0) - 1e-9) and np.all(new <= boundary.max(axis=0) + 1e-9)
    mesh.save(tmp_path / "filled.ply")
    reloaded = holefill.load(tmp_path / "filled.ply")
    assert np.array_equal(reloaded.vertex_colors[:n], rgb / 255.0)
    # uint8 in the file: the patch's interpolated values are written rounded.
    assert np.abs(reloaded.vertex_colors[n:] - new).max() <= 0.5 / 255
    assert np.array_equal(reloaded.vertices, mesh.vertices)
    assert np.array_equal(reloaded.faces, mesh.faces)
