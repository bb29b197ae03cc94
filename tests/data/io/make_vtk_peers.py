# Writes the .vtu/.vtk files of tests/data/io/peer_* with VTK 9.1 and meshio 5.0 (Debian 12's
# python3-vtk9 and python3-meshio): run once with /usr/bin/python3 from this folder; the files
# are committed, the tests (tests/io/vtk_formats.cpp) only read them.
#
# The grid: two tetrahedra glued along (0 1 2), labels 1 and 2, the boundary triangle (0 1 3)
# labelled 7, and (VTK files) a vertex cell, which readers ignore.
import meshio
import numpy as np
import vtk

points = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (0, 0, -1)]
tetrahedra = [(0, 1, 2, 3), (1, 0, 2, 4)]
triangle = (0, 1, 3)


def vtk_grid(label_name, label_type, float_points=False):
    grid = vtk.vtkUnstructuredGrid()
    p = vtk.vtkPoints()
    p.SetDataTypeToFloat() if float_points else p.SetDataTypeToDouble()
    for x in points:
        p.InsertNextPoint(*x)
    grid.SetPoints(p)
    for t in tetrahedra:
        grid.InsertNextCell(vtk.VTK_TETRA, 4, t)
    grid.InsertNextCell(vtk.VTK_TRIANGLE, 3, triangle)
    grid.InsertNextCell(vtk.VTK_VERTEX, 1, (4,))
    labels = label_type()
    labels.SetName(label_name)
    for value in (1, 2, 7, 0):
        labels.InsertNextValue(value)
    grid.GetCellData().AddArray(labels)
    other = vtk.vtkDoubleArray()
    other.SetName("quality")
    other.SetNumberOfComponents(2)
    for i in range(4):
        other.InsertNextTuple2(i, 0.5)
    grid.GetCellData().AddArray(other)
    moved = vtk.vtkFloatArray()
    moved.SetName("displacement")
    moved.SetNumberOfComponents(3)
    for i in range(len(points)):
        moved.InsertNextTuple3(0.1 * i, 0, 0)
    grid.GetPointData().AddArray(moved)
    return grid


def xml(name, grid, mode, encode=True, compress=True, header64=False, big_endian=False):
    w = vtk.vtkXMLUnstructuredGridWriter()
    w.SetFileName(name)
    w.SetInputData(grid)
    {"ascii": w.SetDataModeToAscii, "binary": w.SetDataModeToBinary,
     "appended": w.SetDataModeToAppended}[mode]()
    w.SetEncodeAppendedData(encode)
    if not compress:
        w.SetCompressorTypeToNone()
    w.SetHeaderTypeToUInt64() if header64 else w.SetHeaderTypeToUInt32()
    w.SetByteOrderToBigEndian() if big_endian else w.SetByteOrderToLittleEndian()
    w.Write()


def legacy(name, grid, binary, version=51):
    w = vtk.vtkUnstructuredGridWriter()
    w.SetFileVersion(version)  # 51: OFFSETS/CONNECTIVITY; 42: the classic cell list
    w.SetFileName(name)
    w.SetInputData(grid)
    w.SetFileTypeToBinary() if binary else w.SetFileTypeToASCII()
    w.Write()


xml("peer_vtk_ascii.vtu", vtk_grid("label", vtk.vtkIntArray), "ascii")
xml("peer_vtk_binary_zlib.vtu", vtk_grid("CellEntityIds", vtk.vtkIdTypeArray), "binary")
xml("peer_vtk_binary.vtu", vtk_grid("label", vtk.vtkShortArray), "binary", compress=False,
    header64=True)
xml("peer_vtk_default.vtu", vtk_grid("label", vtk.vtkIntArray), "appended")
xml("peer_vtk_base64_float.vtu", vtk_grid("label", vtk.vtkLongLongArray, True), "appended",
    compress=False)
xml("peer_vtk_raw.vtu", vtk_grid("label", vtk.vtkUnsignedCharArray), "appended", encode=False,
    compress=False, header64=True)
xml("peer_vtk_raw_zlib_big.vtu", vtk_grid("label", vtk.vtkFloatArray), "appended", encode=False,
    big_endian=True)
legacy("peer_vtk_ascii.vtk", vtk_grid("label", vtk.vtkIntArray), False)
legacy("peer_vtk_binary.vtk", vtk_grid("label", vtk.vtkIntArray), True)
legacy("peer_vtk42_ascii.vtk", vtk_grid("label", vtk.vtkIntArray), False, 42)
legacy("peer_vtk42_binary.vtk", vtk_grid("gmsh:physical", vtk.vtkDoubleArray), True, 42)

mesh = meshio.Mesh(np.array(points, dtype=float),
                   [("tetra", np.array(tetrahedra)), ("triangle", np.array([triangle]))],
                   cell_data={"medit:ref": [np.array([1, 2]), np.array([7])]})
mesh.write("peer_meshio_ascii.vtu", binary=False)
mesh.write("peer_meshio_zlib.vtu")
mesh.write("peer_meshio_binary.vtu", compression=None)
mesh.write("peer_meshio_ascii.vtk", binary=False)
mesh.write("peer_meshio_binary.vtk")
