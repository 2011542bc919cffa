"""Fills the holes of a mesh that Open3D holds, and hands the result back to Open3D.

    PYTHONPATH=build/python python3 python/examples/fill_open3d.py scan.ply filled.ply

Open3D (Debian's python3-open3d, or pip's open3d) is needed to run this example only; holefill
itself takes and gives plain numpy arrays, which is all that passes between the two here.
"""

import sys

import numpy as np

import holefill


def fill_open3d_mesh(o3d_mesh, **options):
    """A filled copy of an open3d.geometry.TriangleMesh, with its vertex colours; the records of
    holefill.fill (one per hole). `options` are fill's (tau=..., weight=..., ...)."""
    import open3d as o3d  # pylint: disable=import-outside-toplevel

    colors = np.asarray(o3d_mesh.vertex_colors) if o3d_mesh.has_vertex_colors() else None
    mesh = holefill.Mesh(np.asarray(o3d_mesh.vertices), np.asarray(o3d_mesh.triangles),
                         vertex_colors=colors)
    records = holefill.fill(mesh, **options)
    filled = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(mesh.vertices),
                                       o3d.utility.Vector3iVector(mesh.faces.astype(np.int32)))
    if mesh.vertex_colors is not None:
        filled.vertex_colors = o3d.utility.Vector3dVector(mesh.vertex_colors)
    filled.compute_vertex_normals()
    return filled, records


def main():
    import open3d as o3d  # pylint: disable=import-outside-toplevel

    if len(sys.argv) != 3:
        sys.exit(__doc__)
    source = o3d.io.read_triangle_mesh(sys.argv[1])
    filled, records = fill_open3d_mesh(source)
    for record in records:
        outcome = "filled" if record["filled"] else "not filled: " + record["failure"]
        print(f"hole {record['hole']}: {record['boundary_edges']} edges, {outcome}, "
              f"{record['new_faces']} new faces")
    o3d.io.write_triangle_mesh(sys.argv[2], filled)


if __name__ == "__main__":
    main()
