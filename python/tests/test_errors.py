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
