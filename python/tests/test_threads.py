"""fill runs without the GIL: another Python thread runs while it works; a progress callback
sees the work advance and can cancel it; a mesh in use by a fill is refused to other threads."""

import os
import sys
import threading

import numpy as np
import pytest

import holefill
from conftest import cut_sphere


@pytest.fixture
def no_forced_switches():
    """Python switches threads only where one releases the GIL (sleep, a C++ call that lets
    it go), not every 5 ms: a fill that kept the GIL would keep every other thread out."""
    previous = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)
    yield
    sys.setswitchinterval(previous)


def big_hole():
    return holefill.Mesh(*cut_sphere(24, 400, 6))  # one hole of 400 boundary edges


def test_another_thread_runs_during_a_fill(no_forced_switches):
    mesh = big_hole()
    ticks = [0]
    seen = []  # the main thread's ticks as the fill starts, then at each progress report
    done = threading.Event()

    def work():
        seen.append(ticks[0])
        holefill.fill(mesh, progress=lambda fraction: seen.append(ticks[0]))
        done.set()

    worker = threading.Thread(target=work)
    worker.start()
    while not done.is_set():
        ticks[0] += 1
        os.sched_yield()  # lets the GIL go
    worker.join()
    # One hole: reported once triangulated (0.5), once added (1.0). Nothing lets the GIL go
    # between the start and the first report but the fill (the preparation, the triangulation).
    assert len(seen) == 3
    assert seen[1] > seen[0]
    assert len(holefill.holes(mesh)) == 0


def test_progress_reports_fractions_up_to_one(bunny_path):
    mesh = holefill.load(bunny_path)
    fractions = []
    records = holefill.fill(mesh, progress=fractions.append)
    assert len(records) == 3
    assert sorted(fractions) == pytest.approx([1 / 6, 2 / 6, 3 / 6, 4 / 6, 5 / 6, 1.0])


def test_false_cancels_and_leaves_the_mesh_as_it_was(bunny_path):
    mesh = holefill.load(bunny_path)
    before = (mesh.vertices, mesh.faces)
    assert holefill.fill(mesh, progress=lambda fraction: False) == []
    assert np.array_equal(mesh.vertices, before[0]) and np.array_equal(mesh.faces, before[1])


def test_a_cancel_while_adding_keeps_the_patches_added(bunny_path):
    mesh = holefill.load(bunny_path)
    records = holefill.fill(mesh, progress=lambda fraction: fraction < 0.6)
    assert [r["hole"] for r in records] == [0]
    assert len(holefill.holes(mesh)) == 2


def test_an_exception_in_the_callback_cancels_and_is_raised(bunny_path):
    mesh = holefill.load(bunny_path)
    before = mesh.faces

    def fail(fraction):
        raise KeyError("stop here")

    with pytest.raises(KeyError, match="stop here"):
        holefill.fill(mesh, progress=fail)
    assert np.array_equal(mesh.faces, before)


def test_a_mesh_in_use_is_refused_to_other_threads():
    mesh = big_hole()
    refusals = []

    def touch(fraction):
        # Called on the fill's thread while the fill holds the mesh.
        try:
            mesh.vertices
        except RuntimeError as e:
            refusals.append(str(e))

    holefill.fill(mesh, progress=touch)
    assert refusals and "in use by another thread" in refusals[0]


def test_load_takes_a_thread_count_and_reads_the_same_mesh_on_any(tmp_path):
    # More than 8 MB of OBJ: big enough that loading reads it in halves on two threads.
    path = tmp_path / "sphere.obj"
    holefill.Mesh(*cut_sphere(240, 480, 6)).save(path)
    assert os.path.getsize(path) > 8 << 20
    one = holefill.load(path, threads=1)
    for threads in (2, 3, 0):
        other = holefill.load(path, threads=threads)
        assert np.array_equal(other.vertices, one.vertices)
        assert np.array_equal(other.faces, one.faces)
    with pytest.raises(TypeError):
        holefill.load(path, threads=-1)
