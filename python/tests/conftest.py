"""Shared helpers of the Python module's tests: the built command line, the assets, and meshes
made with numpy."""

import os
import subprocess

import numpy as np
import pytest

ASSETS = os.environ["HOLEFILL_ASSETS_DIR"]
CLI = os.environ["HOLEFILL_CLI"]


def run_cli(*args):
    """Runs the holefill command; returns (exit code, stdout, stderr)."""
    done = subprocess.run([CLI, *args], capture_output=True, text=True, check=False)
    return done.returncode, done.stdout, done.stderr


def cut_sphere(rows, cols, cut_rows):
    """A UV sphere of `rows` x `cols` quads (split into triangles, faces outward) without its
    first `cut_rows` rows of faces around the north pole: one hole of `cols` boundary edges."""
    theta = np.pi * np.arange(cut_rows, rows + 1) / rows
    phi = 2 * np.pi * np.arange(cols) / cols
    ring = np.stack(
        [np.outer(np.sin(theta), np.cos(phi)), np.outer(np.sin(theta), np.sin(phi)),
         np.outer(np.cos(theta), np.ones(cols))], axis=-1)
    vertices = ring[:-1].reshape(-1, 3)
    south = len(vertices)
    vertices = np.vstack([vertices, [[0.0, 0.0, -1.0]]])
    faces = []
    for i in range(rows - cut_rows - 1):
        for j in range(cols):
            a, b = i * cols + j, i * cols + (j + 1) % cols
            c, d = a + cols, b + cols
            faces += [[a, c, b], [b, c, d]]
    last = (rows - cut_rows - 1) * cols
    for j in range(cols):
        faces.append([last + j, south, last + (j + 1) % cols])
    return vertices, np.array(faces, dtype=np.int64)


@pytest.fixture
def bunny_path():
    return os.path.join(ASSETS, "bunny.obj")
