"""holefill.Fill: the stages one at a time give fill's result, and undo takes each back exactly."""

import numpy as np
import pytest

import holefill


def arrays(mesh):
    return mesh.vertices, mesh.faces


def assert_same(a, b):
    assert np.array_equal(a[0], b[0]) and np.array_equal(a[1], b[1])


def test_the_three_stages_give_what_fill_gives(bunny_path):
    staged = holefill.load(bunny_path)
    whole = holefill.load(bunny_path)
    expected = holefill.fill(whole, [1])
    stages = holefill.Fill(staged, 1)
    assert stages.stage == "open"
    assert stages.triangulate()["stage"] == "triangulated"
    assert stages.refine()["stage"] == "refined"
    record = stages.smooth()
    assert stages.stage == "smoothed"
    assert_same(arrays(staged), arrays(whole))
    assert record["new_faces"] == expected[0]["new_faces"] == len(stages.patch_faces)
    assert record["new_vertices"] == len(stages.new_vertices)


def test_undo_takes_each_stage_back_exactly(bunny_path):
    mesh = holefill.load(bunny_path)
    original = arrays(mesh)
    stages = holefill.Fill(mesh, 0, tau=1.0)
    stages.triangulate()
    triangulated = arrays(mesh)
    stages.refine()
    assert mesh.n_faces > triangulated[1].shape[0]
    stages.undo()
    assert stages.stage == "triangulated"
    assert_same(arrays(mesh), triangulated)
    stages.undo()
    assert stages.stage == "open"
    assert_same(arrays(mesh), original)
    with pytest.raises(holefill.Error, match="no stage to undo"):
        stages.undo()


def test_a_later_stage_runs_the_ones_before_and_a_stage_runs_once(bunny_path):
    mesh = holefill.load(bunny_path)
    stages = holefill.Fill(mesh, 2)
    assert stages.refine()["stage"] == "refined"
    with pytest.raises(holefill.Error, match="is refined already"):
        stages.triangulate()


def test_a_mesh_changed_under_a_fill_is_refused(bunny_path):
    mesh = holefill.load(bunny_path)
    stages = holefill.Fill(mesh, 0)
    holefill.fill(mesh, [1])
    with pytest.raises(holefill.Error, match="the mesh changed since this Fill"):
        stages.triangulate()


def test_a_hole_the_mesh_lacks_is_refused(bunny_path):
    with pytest.raises(holefill.Error, match="has no hole 3 \\(it has 3\\)"):
        holefill.Fill(holefill.load(bunny_path), 3)
