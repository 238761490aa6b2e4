#!/usr/bin/python3
"""Reads a VTU file with meshio and prints what it found, for tests/mesh/mesh_io_vtu_test.cc.

    /usr/bin/python3 tests/mesh/read_vtu_with_meshio.py FILE.vtu

Prints one block per array: a line `KIND NAME DTYPE ROWS COLUMNS` (KIND points, cells,
point_data or cell_data; NAME the cell type for cells), then one line per row. Floats are
printed with repr(), the shortest text that reads back as the same double, so the test can
compare bit for bit with what it wrote. Exits 1 (with the reason on stderr) when meshio
cannot read the file.
"""
import sys

import meshio
import numpy as np


def dump(kind, name, array):
    array = np.asarray(array)
    rows = array.reshape(array.shape[0], -1) if array.ndim > 0 else array.reshape(1, 1)
    print(kind, name, array.dtype.name, rows.shape[0], rows.shape[1])
    for row in rows:
        print(" ".join(repr(float(v)) if rows.dtype.kind == "f" else str(int(v)) for v in row))


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: read_vtu_with_meshio.py FILE.vtu")
    try:
        mesh = meshio.read(sys.argv[1])
    except Exception as error:  # meshio raises several types; all mean "not readable"
        sys.exit(f"meshio could not read {sys.argv[1]}: {error}")
    dump("points", "-", mesh.points)
    for block in mesh.cells:
        dump("cells", block.type, block.data)
    for name, values in mesh.point_data.items():
        dump("point_data", name, values)
    for name, blocks in mesh.cell_data.items():
        for values in blocks:
            dump("cell_data", name, values)


if __name__ == "__main__":
    main()
