"""Errors reach Python as holefill.Error (a ValueError) with the command line's messages."""

import os

import pytest

import holefill
from conftest import run_cli


def cli_message(stderr):
    """The command's error line without its 'holefill: ' in front."""
    return stderr.splitlines()[0].removeprefix("holefill: ")


def test_a_missing_file_is_the_commands_message(tmp_path):
    missing = str(tmp_path / "missing.ply")
    code, _, err = run_cli("info", missing)
    assert code == 3
    with pytest.raises(holefill.Error) as refused:
        holefill.load(missing)
    assert str(refused.value) == cli_message(err)


def test_a_broken_file_is_the_commands_message(tmp_path):
    broken = tmp_path / "broken.off"
    broken.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    code, _, err = run_cli("info", str(broken))
    assert code == 3
    with pytest.raises(holefill.Error) as refused:
        holefill.load(broken)
    assert str(refused.value) == cli_message(err)


def test_options_out_of_range_are_the_commands_messages_under_python_names(bunny_path):
    mesh = holefill.load(bunny_path)
    code, _, err = run_cli("fill", bunny_path, "-o", "/nonexistent/x.ply", "--tau", "-1")
    assert code == 2
    with pytest.raises(holefill.Error) as refused:
        holefill.fill(mesh, tau=-1)
    assert str(refused.value) == cli_message(err).replace("--tau", "tau")
    for options, message in [
        ({"weight": "best"}, "weight: best not in {maxmin,liepa,area}"),
        ({"smooth_step": 2}, "smooth_step: must be in (0, 1], got 2"),
        ({"fold_limit": float("inf")}, "fold_limit: must be in (0, 180], got inf"),
        ({"holes": [7]}, "holes: " + bunny_path + " has no hole 7 (it has 3)"),
        ({"bridge": [(0, 9)]}, "bridge: " + bunny_path + " has no hole 9 (it has 3)"),
        ({"taux": 1}, "fill has no option 'taux'"),
    ]:
        with pytest.raises(holefill.Error) as refused:
            holefill.fill(mesh, **options)
        assert message in str(refused.value)
    assert len(holefill.holes(mesh)) == 3  # nothing was filled


def test_an_unwritable_output_is_an_error(tmp_path, bunny_path):
    mesh = holefill.load(bunny_path)
    with pytest.raises(holefill.Error, match="cannot write '.xyz' files"):
        mesh.save(tmp_path / "out.xyz")
    with pytest.raises(holefill.Error, match="missing"):
        mesh.save(tmp_path / "missing" / "out.ply")
    assert not os.path.exists(tmp_path / "out.xyz")


def test_a_format_that_cannot_hold_an_attribute_warns(tmp_path):
    colored = os.path.join(os.environ["HOLEFILL_ASSETS_DIR"], "..", "tests", "data",
                           "colored_tetra.off")
    mesh = holefill.load(colored)
    with pytest.warns(holefill.HolefillWarning, match="not written"):
        mesh.save(tmp_path / "out.stl")


def test_the_preparations_advice_names_the_python_option():
    # A closed tetrahedron and a lone triangle beside it: the warning about the triangle names
    # fill's option as Python spells it, not the command's flag.
    vertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [5, 0, 0], [6, 0, 0], [5, 1, 0]]
    faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2], [4, 5, 6]]
    mesh = holefill.Mesh(vertices, faces)
    with pytest.warns(holefill.HolefillWarning) as warnings:
        holefill.fill(mesh)
    texts = [str(w.message) for w in warnings]
    assert any("1 lone triangle beside the surface, of at most 1 face; "
               "remove_small_components=1 removes them" in text for text in texts), texts
    assert not any("--" in text for text in texts), texts
    holefill.fill(mesh, remove_small_components=1)
    assert mesh.n_faces == 4
