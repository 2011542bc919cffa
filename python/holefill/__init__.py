"""holefill: fill holes in triangle meshes (Wei, Wu & Pang 2010).

    m = holefill.load("scan.ply")        # or holefill.Mesh(vertices, faces) from numpy arrays
    holefill.holes(m)                    # the holes, as `holefill info --json` lists them
    records = holefill.fill(m, tau=1.0)  # fills in place; one record per hole
    m.save("scan-filled.ply")

fill() takes the options of the `holefill fill` command under Python names (FILL_OPTIONS lists
them with their defaults); Fill(m, hole) runs the stages one at a time. Errors are
holefill.Error (a ValueError) with the command's messages, or MemoryError; what a load, save or
preparation repaired or left out comes as a HolefillWarning.
"""

from ._holefill import (
    FILL_OPTIONS,
    Error,
    Fill,
    HolefillWarning,
    Mesh,
    __version__,
    fill,
    holes,
    info,
    load,
)

__all__ = [
    "FILL_OPTIONS",
    "Error",
    "Fill",
    "HolefillWarning",
    "Mesh",
    "fill",
    "holes",
    "info",
    "load",
]
