# Made the peer files vtk_sphere_*.{stl,ply} and meshio_sphere_*.{stl,ply} beside this script, once,
# with Debian 12's python3-vtk9 (9.1) and python3-meshio (5.0): /usr/bin/python3 stl_ply_peers.py .
# (tests/io/stl_ply.cpp reads them). One sphere of 14 points and 24 triangles, VTK's PLY files with
# a colour per face, meshio's from the same points and triangles.
import vtk, meshio, numpy as np, sys
out = sys.argv[1]
sphere = vtk.vtkSphereSource()
sphere.SetThetaResolution(6); sphere.SetPhiResolution(4); sphere.SetRadius(1.5)
sphere.Update()
poly = sphere.GetOutput()
print("sphere", poly.GetNumberOfPoints(), poly.GetNumberOfCells())
for mode, tag in ((True, "binary"), (False, "ascii")):
    w = vtk.vtkSTLWriter(); w.SetInputData(poly); w.SetFileName(f"{out}/vtk_sphere_{tag}.stl")
    w.SetFileTypeToBinary() if mode else w.SetFileTypeToASCII(); w.Write()
for tag, setup in (("binary", lambda w: (w.SetFileTypeToBinary(), w.SetDataByteOrderToLittleEndian())),
                   ("big_endian", lambda w: (w.SetFileTypeToBinary(), w.SetDataByteOrderToBigEndian())),
                   ("ascii", lambda w: w.SetFileTypeToASCII())):
    w = vtk.vtkPLYWriter(); w.SetInputData(poly); w.SetFileName(f"{out}/vtk_sphere_{tag}.ply")
    setup(w)
    w.SetColorModeToUniformCellColor(); w.SetColor(200, 30, 30)
    w.Write()
points = np.array([poly.GetPoint(i) for i in range(poly.GetNumberOfPoints())])
cells = np.array([[poly.GetCell(i).GetPointId(j) for j in range(3)] for i in range(poly.GetNumberOfCells())])
mesh = meshio.Mesh(points, [("triangle", cells)])
for binary, tag in ((True, "binary"), (False, "ascii")):
    meshio.write(f"{out}/meshio_sphere_{tag}.stl", mesh, binary=binary)
    meshio.write(f"{out}/meshio_sphere_{tag}.ply", mesh, binary=binary)
