"""holefill.Mesh from numpy arrays and back: exact round trips, conversions, refusals."""

import numpy as np
import pytest

import holefill
from conftest import cut_sphere


def test_a_loaded_mesh_goes_through_its_arrays_unchanged(bunny_path):
    loaded = holefill.load(bunny_path)
    rebuilt = holefill.Mesh(loaded.vertices, loaded.faces)
    assert rebuilt.vertices.dtype == np.float64 and rebuilt.faces.dtype == np.int64
    assert np.array_equal(rebuilt.vertices, loaded.vertices)
    assert np.array_equal(rebuilt.faces, loaded.faces)
    assert (rebuilt.n_vertices, rebuilt.n_faces) == (1646, 3130)


def test_arrays_are_copies(bunny_path):
    mesh = holefill.load(bunny_path)
    vertices = mesh.vertices
    vertices[0] = 99.0
    assert mesh.vertices[0, 0] != 99.0


def test_other_dtypes_are_converted():
    vertices, faces = cut_sphere(8, 12, 2)
    mesh = holefill.Mesh(vertices.astype(np.float32), faces.astype(np.uint32))
    assert np.array_equal(mesh.vertices, vertices.astype(np.float32).astype(np.float64))
    assert np.array_equal(mesh.faces, faces)
    as_lists = holefill.Mesh(vertices.tolist(), faces.tolist())
    assert np.array_equal(as_lists.vertices, vertices)


@pytest.mark.parametrize(
    "vertices, faces, message",
    [
        (np.zeros((3, 2)), [[0, 1, 2]], "vertices must be an array of n x 3, got shape (3 x 2)"),
        (np.zeros((3, 3), dtype=complex), [[0, 1, 2]], "vertices must be real numbers"),
        (np.eye(3), np.array([[0.0, 1.0, 2.0]]), "faces must be integer vertex indices"),
        (np.eye(3), [[0, 1, 3]], "face 0 uses vertex 3, not one of the 3 vertices"),
        (np.eye(3), [[0, -1, 2]], "face 0 uses vertex -1"),
        ([[0, 0, 0], [1, 0, np.nan], [0, 1, 0]], [[0, 1, 2]], "vertex 1 has a non-finite"),
        (np.eye(3), np.zeros((0, 3), dtype=int), "contains no faces"),
    ],
)
def test_bad_arrays_are_refused_naming_the_fault(vertices, faces, message):
    with pytest.raises(holefill.Error, match=None) as refused:
        holefill.Mesh(vertices, faces)
    assert message in str(refused.value)
    assert str(refused.value).startswith("Mesh(vertices, faces): ")
    assert isinstance(refused.value, ValueError)


def test_colours_normals_and_attributes_come_back():
    vertices, faces = cut_sphere(8, 12, 2)
    n = len(vertices)
    rng = np.random.default_rng(1)
    bytes_rgb = rng.integers(0, 256, size=(n, 3), dtype=np.uint8)
    normals = vertices / np.linalg.norm(vertices, axis=1)[:, None]
    quality = rng.random(n)
    labels = np.arange(len(faces), dtype=np.int32)
    mesh = holefill.Mesh(vertices, faces, vertex_colors=bytes_rgb, vertex_normals=normals,
                         vertex_attributes={"quality": quality}, face_attributes={"label": labels})
    assert np.array_equal(mesh.vertex_colors, bytes_rgb / 255.0)
    assert np.array_equal(mesh.vertex_normals, normals)
    assert np.array_equal(mesh.vertex_attributes["quality"], quality)
    assert np.array_equal(mesh.vertex_attributes["red"], bytes_rgb[:, 0])
    assert np.array_equal(mesh.face_attributes["label"], labels)
    floats = rng.random((n, 3))
    assert np.array_equal(holefill.Mesh(vertices, faces, vertex_colors=floats).vertex_colors, floats)
    plain = holefill.Mesh(vertices, faces)
    assert plain.vertex_colors is None and plain.vertex_normals is None
    assert plain.vertex_attributes == {} and plain.face_attributes == {}


def test_bad_attributes_are_refused():
    vertices, faces = cut_sphere(8, 12, 2)
    with pytest.raises(holefill.Error, match="vertex_colors must be an array of"):
        holefill.Mesh(vertices, faces, vertex_colors=np.zeros((3, 3)))
    with pytest.raises(holefill.Error, match="vertex_colors must be uint8"):
        holefill.Mesh(vertices, faces, vertex_colors=np.zeros((len(vertices), 3), dtype=np.int64))
    with pytest.raises(holefill.Error, match=r"vertex_attributes\['q'\] must be of a type"):
        holefill.Mesh(vertices, faces, vertex_attributes={"q": np.zeros(len(vertices), dtype=bool)})


def test_repairs_of_the_arrays_are_warned():
    vertices, faces = cut_sphere(8, 12, 2)
    flipped = faces.copy()
    flipped[5] = flipped[5][::-1]
    with pytest.warns(holefill.HolefillWarning, match="flipped"):
        mesh = holefill.Mesh(vertices, flipped)
    assert rotated_to_lowest(mesh.faces) == rotated_to_lowest(faces)


def rotated_to_lowest(faces):
    """Each triangle's corners rotated to start at its lowest index (the same orientation)."""
    return sorted(tuple(np.roll(f, -int(np.argmin(f)))) for f in np.asarray(faces).tolist())
