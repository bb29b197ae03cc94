#!/usr/bin/python3
"""What simplexkit writes, read by the tools its users open files with, and what those tools
write, read by simplexkit: meshio 5, VTK 9 (XML and legacy readers and writers, STL and PLY) and
Gmsh 4.8 (its Python API), all Debian packages (tools/setup installs them). docs/formats.md has
the table of what is checked.

    /usr/bin/python3 tests/interop/interop.py SXK [unittest arguments]   e.g. -k Meshio

SXK is the sxk binary. ctest runs it with the label `interop` (tests/interop/CMakeLists.txt).
Each check compares counts, connectivity, labels, names and arrays, not only that a file opens.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np

import gmsh
import meshio
import vtk
from vtk.util.numpy_support import vtk_to_numpy

SXK = None
WORK = None

# Every format and encoding sxk writes: (file name, sxk convert options).
OUR_OUTPUTS = [
    ("ours.vtu", ["--encoding", "standard"]),  # appended, zlib
    ("ours_raw.vtu", ["--encoding", "binary"]),  # appended raw
    ("ours_ascii.vtu", ["--encoding", "ascii"]),
    ("ours.vtk", ["--encoding", "ascii"]),
    ("ours_binary.vtk", ["--encoding", "binary"]),
    ("ours41.msh", ["--gmsh-version", "41"]),
    ("ours41_binary.msh", ["--gmsh-version", "41", "--encoding", "binary"]),
    ("ours22.msh", ["--gmsh-version", "22"]),
    ("ours22_binary.msh", ["--gmsh-version", "22", "--encoding", "binary"]),
    ("ours.stl", ["--encoding", "binary"]),  # surfaces: a tetrahedral mesh's boundary
    ("ours_ascii.stl", ["--encoding", "ascii"]),
    ("ours.ply", ["--encoding", "binary"]),
    ("ours_ascii.ply", ["--encoding", "ascii"]),
]
SURFACES = ("ours.stl", "ours_ascii.stl", "ours.ply", "ours_ascii.ply")


def sxk(*args, check=True):
    run = subprocess.run([SXK, *map(str, args)], capture_output=True, text=True)
    if check and run.returncode != 0:
        raise AssertionError(f"sxk {' '.join(map(str, args))} exited {run.returncode}: {run.stderr}")
    return run


def path(name):
    return os.path.join(WORK, name)


def info(mesh_file):
    return json.loads(sxk("info", mesh_file, "--json").stdout)


# ---- the reference mesh ---------------------------------------------------------------------
# A Kuhn cube of 3 x 3 x 3 cells (162 tetrahedra) made by sxk, with element labels 0 (x < 1.5)
# and 4 (x > 1.5), and the boundary triangles in x = 0 labelled 9999, in y = 0 labelled 7: label
# 0 is the kernel's "no label", the case Gmsh and meshio misread before.

def reference():
    if os.path.exists(path("reference.mesh")):
        return meshio.read(path("reference.mesh"))
    sxk("generate", path("cube.mesh"), "--cells", "3")
    cube = meshio.read(path("cube.mesh"))
    points = cube.points
    tets = cube.get_cells_type("tetra")
    labels = np.where(points[tets].mean(axis=1)[:, 0] > 1.5, 4, 0).astype(np.int32)
    faces, face_labels = [], []
    for tet in tets:
        for skip in range(4):
            face = [v for j, v in enumerate(tet) if j != skip]
            p = points[face]
            if np.all(p[:, 0] == 0):
                faces.append(face)
                face_labels.append(9999)
            elif np.all(p[:, 1] == 0):
                faces.append(face)
                face_labels.append(7)
    mesh = meshio.Mesh(points, [("triangle", np.array(faces)), ("tetra", tets)],
                       cell_data={"medit:ref": [np.array(face_labels, dtype=np.int32), labels]})
    meshio.write(path("reference.mesh"), mesh)
    return meshio.read(path("reference.mesh"))


def sorted_cells(cells, labels):
    """(cell as sorted vertex tuple, label) pairs, sorted: equal lists mean equal meshes."""
    return sorted((tuple(sorted(int(v) for v in c)), int(l)) for c, l in zip(cells, labels))


def cells_by_type(mesh, kind, data_name):
    cells, labels = [], []
    for block, data in zip(mesh.cells, mesh.cell_data[data_name]):
        if block.type == kind:
            cells.extend(block.data)
            labels.extend(data)
    return cells, labels


def point_map(points, reference_points):
    """The reference vertex of each point (files may renumber)."""
    index = {tuple(p): i for i, p in enumerate(reference_points)}
    return np.array([index[tuple(p)] for p in points])


class Expectations(unittest.TestCase):
    """Helpers comparing a mesh meshio read with the reference."""

    def assertSameMesh(self, mesh, labels_of, exact=True):
        ref = reference()
        self.assertEqual(len(mesh.points), len(ref.points))
        if exact:
            to_ref = point_map(mesh.points[:, :3], ref.points)
        else:
            to_ref = np.arange(len(ref.points))
            np.testing.assert_allclose(mesh.points[:, :3], ref.points, rtol=1e-6)
        for kind in ("tetra", "triangle"):
            cells, labels = cells_by_type(mesh, kind, next(iter(mesh.cell_data)))
            cells = [to_ref[c] for c in cells]
            labels = labels_of(mesh, kind)
            ref_cells, ref_labels = cells_by_type(ref, kind, "medit:ref")
            self.assertEqual(sorted_cells(cells, labels), sorted_cells(ref_cells, ref_labels), kind)


def labels_from(name):
    def of(mesh, kind):
        return [l for block, data in zip(mesh.cells, mesh.cell_data[name]) if block.type == kind for l in data]
    return of


def gmsh_labels(mesh, kind):
    """meshio's gmsh:physical, with groups named `label N` turned into N (docs/formats.md)."""
    names = {int(tag): name for name, (tag, dim) in mesh.field_data.items()}
    out = []
    for block, data in zip(mesh.cells, mesh.cell_data["gmsh:physical"]):
        if block.type != kind:
            continue
        for tag in data:
            name = names.get(int(tag), "")
            out.append(int(name[6:]) if name.startswith("label ") else int(tag))
    return out


def write_ours(suffix=""):
    """sxk writes the reference in every format and encoding whose name ends in `suffix`."""
    reference()
    for name, options in OUR_OUTPUTS:
        if name.endswith(suffix) and not os.path.exists(path(name)):
            sxk("convert", path("reference.mesh"), path(name), *options)


# ---- ours, read by meshio ----------------------------------------------------------------------

class MeshioReadsOurs(Expectations):
    def test_vtu_and_vtk_in_every_encoding(self):
        write_ours(".vtu")
        write_ours(".vtk")
        for name in ("ours.vtu", "ours_raw.vtu", "ours_ascii.vtu", "ours.vtk", "ours_binary.vtk"):
            with self.subTest(name):
                mesh = meshio.read(path(name))
                self.assertSameMesh(mesh, labels_from("label"))
                self.assertIn("piece", mesh.cell_data)

    def test_gmsh_in_every_version_and_encoding(self):
        write_ours(".msh")
        for name in ("ours41.msh", "ours41_binary.msh", "ours22.msh", "ours22_binary.msh"):
            with self.subTest(name):
                mesh = meshio.read(path(name))
                self.assertSameMesh(mesh, gmsh_labels)
                # label 0 is no physical tag to Gmsh: the smallest free tag, named for the label
                self.assertEqual(mesh.field_data["label 0"].tolist(), [1, 3])

    def test_stl_and_ply_surfaces_in_both_encodings(self):
        write_ours(".stl")
        write_ours(".ply")
        boundary = info(path("reference.mesh"))["boundary_faces"]
        for name in SURFACES:
            with self.subTest(name):
                mesh = meshio.read(path(name))
                self.assertEqual(sum(len(b.data) for b in mesh.cells if b.type == "triangle"), boundary)
                # meshio reads STL per triangle corner; welded, the points are sxk's vertices
                points = np.unique(mesh.points, axis=0)
                self.assertEqual(len(points), info(path(name))["vertices"])


# ---- ours, read by VTK ------------------------------------------------------------------------

class VtkErrors:
    """Collects the errors and warnings a VTK reader reports (it goes on after many of them)."""

    def __init__(self, reader):
        self.messages = []
        for event in ("ErrorEvent", "WarningEvent"):
            reader.AddObserver(event, lambda caller, name: self.messages.append(name))


def vtk_read(reader, name):
    errors = VtkErrors(reader)
    reader.SetFileName(path(name))
    reader.Update()
    if errors.messages:
        raise AssertionError(f"{type(reader).__name__} on {name}: {errors.messages}")
    return reader.GetOutput()


class VtkReadsOurs(unittest.TestCase):
    def setUp(self):
        for suffix in (".vtu", ".vtk", ".stl", ".ply"):
            write_ours(suffix)

    def check(self, grid):
        ref = reference()
        tets = len(ref.get_cells_type("tetra"))
        triangles = len(ref.get_cells_type("triangle"))
        self.assertEqual(grid.GetNumberOfPoints(), len(ref.points))
        self.assertEqual(grid.GetNumberOfCells(), tets + triangles)
        types = vtk_to_numpy(grid.GetCellTypesArray())
        self.assertEqual(int(np.sum(types == vtk.VTK_TETRA)), tets)
        self.assertEqual(int(np.sum(types == vtk.VTK_TRIANGLE)), triangles)
        labels = vtk_to_numpy(grid.GetCellData().GetArray("label"))
        self.assertEqual(sorted(set(labels[types == vtk.VTK_TETRA].tolist())), [0, 4])
        self.assertEqual(sorted(set(labels[types == vtk.VTK_TRIANGLE].tolist())), [7, 9999])
        # ParaView colours by the active scalars: they must show something (labels differ here)
        scalars = grid.GetCellData().GetScalars()
        self.assertIsNotNone(scalars)
        self.assertGreater(np.ptp(vtk_to_numpy(scalars)), 0)

    def test_xml_reader_every_encoding(self):
        for name in ("ours.vtu", "ours_raw.vtu", "ours_ascii.vtu"):
            with self.subTest(name):
                self.check(vtk_read(vtk.vtkXMLUnstructuredGridReader(), name))

    def test_legacy_reader_both_encodings(self):
        for name in ("ours.vtk", "ours_binary.vtk"):
            with self.subTest(name):
                self.check(vtk_read(vtk.vtkUnstructuredGridReader(), name))

    def test_stl_and_ply_readers_both_encodings(self):
        boundary = info(path("reference.mesh"))["boundary_faces"]
        for name in SURFACES:
            with self.subTest(name):
                reader = vtk.vtkSTLReader() if name.endswith(".stl") else vtk.vtkPLYReader()
                surface = vtk_read(reader, name)
                self.assertEqual(surface.GetNumberOfPolys(), boundary)
                self.assertEqual(surface.GetNumberOfPoints(), info(path(name))["vertices"])

    def test_a_cut_shows_its_faces_and_two_pieces(self):
        # the snap cutter through the whole 8-cell cube: cut faces labelled 9999, two pieces
        sxk("generate", path("cube8.mesh"), "--cells", "8")
        with open(path("through.path"), "w") as f:
            f.write("# time hx hy hz tx ty tz\n")
            for i, y in enumerate(range(-1, 11, 2)):
                f.write(f"{i / 10} 3.3 {y} 10 3.3 {y} -1\n")
        sxk("cut", "snap", path("cube8.mesh"), path("through.path"), path("cut.vtu"))
        grid = vtk_read(vtk.vtkXMLUnstructuredGridReader(), "cut.vtu")
        types = vtk_to_numpy(grid.GetCellTypesArray())
        labels = vtk_to_numpy(grid.GetCellData().GetArray("label"))
        self.assertGreater(int(np.sum((types == vtk.VTK_TRIANGLE) & (labels == 9999))), 0)
        pieces = vtk_to_numpy(grid.GetCellData().GetArray("piece"))
        self.assertEqual(len(set(pieces.tolist())), 2)
        self.assertEqual(grid.GetCellData().GetScalars().GetName(), "piece")
        # ParaView's Connectivity filter finds the same two pieces
        connectivity = vtk.vtkConnectivityFilter()
        connectivity.SetInputData(grid)
        connectivity.SetExtractionModeToAllRegions()
        connectivity.Update()
        self.assertEqual(connectivity.GetNumberOfExtractedRegions(), 2)

    def test_displacement_is_written_when_the_body_deforms(self):
        sxk("generate", path("cube2.mesh"), "--cells", "2")
        sxk("deform", path("cube2.mesh"), path("deformed.vtu"), "--fix", "z<0.001", "--force", "z>1.99:0,0.1,0")
        grid = vtk_read(vtk.vtkXMLUnstructuredGridReader(), "deformed.vtu")
        displacement = vtk_to_numpy(grid.GetPointData().GetArray("displacement"))
        self.assertEqual(displacement.shape, (grid.GetNumberOfPoints(), 3))
        self.assertGreater(np.abs(displacement[:, 1]).max(), 0)
        self.assertEqual(np.abs(displacement[vtk_to_numpy(grid.GetPoints().GetData())[:, 2] < 1e-9]).max(), 0)


# ---- ours, read by Gmsh -----------------------------------------------------------------------

class GmshReadsOurs(unittest.TestCase):
    def setUp(self):
        write_ours(".msh")
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)

    def tearDown(self):
        gmsh.finalize()

    def test_every_element_survives_gmsh_saving_it_again(self):
        ref = reference()
        tets = len(ref.get_cells_type("tetra"))
        for name in ("ours41.msh", "ours41_binary.msh", "ours22.msh", "ours22_binary.msh"):
            for version in (2.2, 4.1):
                with self.subTest(name=name, version=version):
                    gmsh.clear()
                    gmsh.open(path(name))
                    groups = {(d, t): gmsh.model.getPhysicalName(d, t) for d, t in gmsh.model.getPhysicalGroups()}
                    self.assertEqual(sorted(groups.values()), sorted(["label 0", "", "", ""]))
                    again = path(f"again_{version}_{name}")
                    gmsh.option.setNumber("Mesh.MshFileVersion", version)
                    gmsh.write(again)
                    counts = info(again)
                    self.assertEqual(counts["elements"], tets)
                    self.assertEqual(counts["element_labels"], [0, 4])
                    self.assertEqual(counts["face_labels"], [7, 9999])
                    self.assertEqual(json.loads(sxk("components", again, "--json").stdout)["components"], 1)
                    self.assertEqual(counts["vertices"], len(ref.points))


# ---- theirs, read by sxk ---------------------------------------------------------------------

class SxkReadsMeshio(Expectations):
    """meshio writes the reference in each format and encoding; sxk reads it and writes Medit,
    which meshio compares with the reference."""

    def round_trip(self, name, **options):
        ref = reference()
        cell_data = {"label": ref.cell_data["medit:ref"], "gmsh:physical": ref.cell_data["medit:ref"],
                     "gmsh:geometrical": ref.cell_data["medit:ref"]}
        if name.endswith(".msh"):
            # meshio's 4.1 writer needs each node's entity when there are several cell types
            dim_tags = np.tile([3, 1], (len(ref.points), 1))
            mesh = meshio.Mesh(ref.points, ref.cells, point_data={"gmsh:dim_tags": dim_tags},
                               cell_data={k: cell_data[k] for k in ("gmsh:physical", "gmsh:geometrical")})
        else:
            mesh = meshio.Mesh(ref.points, ref.cells, cell_data={"label": cell_data["label"]})
        meshio.write(path(name), mesh, **options)
        sxk("convert", path(name), path(name + ".mesh"))
        return meshio.read(path(name + ".mesh"))

    def test_vtu_every_encoding(self):
        for options in ({"binary": False}, {"binary": True, "compression": None},
                        {"binary": True, "compression": "zlib"}):
            with self.subTest(**options):
                self.assertSameMesh(self.round_trip("meshio.vtu", **options), labels_from("medit:ref"))

    def test_legacy_vtk_both_encodings(self):
        for binary in (False, True):
            with self.subTest(binary=binary):
                self.assertSameMesh(self.round_trip("meshio.vtk", binary=binary), labels_from("medit:ref"))

    def test_gmsh_every_version_and_encoding(self):
        for binary in (False, True):
            with self.subTest(fmt="gmsh22", binary=binary):
                self.assertSameMesh(self.round_trip("meshio_gmsh22.msh", file_format="gmsh22", binary=binary),
                                    labels_from("medit:ref"))

    def test_gmsh41_of_tetrahedra(self):
        # meshio 5's 4.1 writer gives each entity the physical tag of its cells when they share one
        ref = reference()
        tets = ref.get_cells_type("tetra")
        for binary in (False, True):
            with self.subTest(binary=binary):
                mesh = meshio.Mesh(ref.points, [("tetra", tets)], point_data={"gmsh:dim_tags": np.tile([3, 1], (len(ref.points), 1))},
                                   cell_data={"gmsh:physical": [np.full(len(tets), 4)],
                                              "gmsh:geometrical": [np.ones(len(tets), dtype=int)]})
                meshio.write(path("meshio41.msh"), mesh, file_format="gmsh", binary=binary)
                counts = info(path("meshio41.msh"))
                self.assertEqual(counts["elements"], len(tets))
                self.assertEqual(counts["vertices"], len(ref.points))
                self.assertEqual(counts["element_labels"], [4])

    def test_gmsh41_with_entities_it_does_not_list_is_refused_as_gmsh_refuses_it(self):
        # with triangles and tetrahedra, meshio 5 puts elements on entities its $Entities does
        # not list; Gmsh 4.8 says "Unknown entity 7 of dimension 2", sxk the same
        ref = reference()
        mesh = meshio.Mesh(ref.points, ref.cells, point_data={"gmsh:dim_tags": np.tile([3, 1], (len(ref.points), 1))},
                           cell_data={"gmsh:physical": ref.cell_data["medit:ref"],
                                      "gmsh:geometrical": ref.cell_data["medit:ref"]})
        meshio.write(path("meshio41_mixed.msh"), mesh, file_format="gmsh", binary=False)
        run = sxk("info", path("meshio41_mixed.msh"), check=False)
        self.assertEqual(run.returncode, 2)
        self.assertIn("unknown entity (dimension 2, tag 7)", run.stderr)
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)
        try:
            with self.assertRaisesRegex(Exception, "Unknown entity 7 of dimension 2"):
                gmsh.open(path("meshio41_mixed.msh"))
        finally:
            gmsh.finalize()


class SxkReadsVtk(Expectations):
    """VTK's own writers: XML in every data mode, compressor and header size; legacy ASCII and
    binary; STL and PLY of the surface."""

    def grid(self, kinds=("triangle", "tetra")):
        ref = reference()
        grid = vtk.vtkUnstructuredGrid()
        points = vtk.vtkPoints()
        points.SetDataTypeToDouble()
        for p in ref.points:
            points.InsertNextPoint(*p)
        grid.SetPoints(points)
        labels = vtk.vtkIntArray()
        labels.SetName("label")
        for kind, vtk_type in (("triangle", vtk.VTK_TRIANGLE), ("tetra", vtk.VTK_TETRA)):
            if kind not in kinds:
                continue
            cells, values = cells_by_type(ref, kind, "medit:ref")
            for cell, value in zip(cells, values):
                ids = vtk.vtkIdList()
                for v in cell:
                    ids.InsertNextId(int(v))
                grid.InsertNextCell(vtk_type, ids)
                labels.InsertNextValue(int(value))
        grid.GetCellData().AddArray(labels)
        return grid

    def read_back(self, name):
        sxk("convert", path(name), path(name + ".mesh"))
        return meshio.read(path(name + ".mesh"))

    def test_xml_writer_every_mode(self):
        grid = self.grid()
        for mode in ("Ascii", "Binary", "Appended"):
            for compressor in ("None", "ZLib"):
                for header in (32, 64):
                    for encode in (0, 1):
                        if mode != "Appended" and encode:
                            continue
                        with self.subTest(mode=mode, compressor=compressor, header=header, encode=encode):
                            writer = vtk.vtkXMLUnstructuredGridWriter()
                            writer.SetInputData(grid)
                            name = f"vtk_{mode}_{compressor}_{header}_{encode}.vtu"
                            writer.SetFileName(path(name))
                            getattr(writer, f"SetDataModeTo{mode}")()
                            getattr(writer, f"SetCompressorTypeTo{compressor}")()
                            writer.SetHeaderTypeToUInt32() if header == 32 else writer.SetHeaderTypeToUInt64()
                            writer.SetEncodeAppendedData(encode)
                            writer.SetIdTypeToInt32() if header == 32 else writer.SetIdTypeToInt64()
                            self.assertEqual(writer.Write(), 1)
                            self.assertSameMesh(self.read_back(name), labels_from("medit:ref"))

    def test_legacy_writer_both_encodings(self):
        grid = self.grid()
        for binary in (False, True):
            with self.subTest(binary=binary):
                writer = vtk.vtkUnstructuredGridWriter()
                writer.SetInputData(grid)
                name = f"vtk_legacy_{binary}.vtk"
                writer.SetFileName(path(name))
                writer.SetFileTypeToBinary() if binary else writer.SetFileTypeToASCII()
                self.assertEqual(writer.Write(), 1)
                self.assertSameMesh(self.read_back(name), labels_from("medit:ref"))

    def surface(self):
        geometry = vtk.vtkGeometryFilter()
        geometry.SetInputData(self.grid(kinds=("tetra",)))  # the boundary of the tetrahedra
        geometry.Update()
        triangles = vtk.vtkTriangleFilter()
        triangles.SetInputConnection(geometry.GetOutputPort())
        triangles.Update()
        return triangles.GetOutput()

    def test_stl_and_ply_writers_both_encodings(self):
        surface = self.surface()
        for writer_type, ext in ((vtk.vtkSTLWriter, "stl"), (vtk.vtkPLYWriter, "ply")):
            for binary in (False, True):
                with self.subTest(ext=ext, binary=binary):
                    writer = writer_type()
                    writer.SetInputData(surface)
                    name = f"vtk_surface_{binary}.{ext}"
                    writer.SetFileName(path(name))
                    writer.SetFileTypeToBinary() if binary else writer.SetFileTypeToASCII()
                    self.assertEqual(writer.Write(), 1)
                    counts = info(path(name))
                    self.assertEqual(counts["elements"], surface.GetNumberOfCells())
                    self.assertEqual(counts["element_kind"], "triangle")
                    self.assertEqual(counts["components"], 1)


class SxkReadsGmsh(unittest.TestCase):
    """Meshes Gmsh makes itself, with physical groups and names from its Python API."""

    def setUp(self):
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)

    def tearDown(self):
        gmsh.finalize()

    def test_physical_groups_and_names_in_every_version_and_encoding(self):
        gmsh.model.add("two")
        gmsh.model.occ.addBox(0, 0, 0, 1, 1, 1)
        gmsh.model.occ.addBox(1, 0, 0, 1, 1, 1)
        gmsh.model.occ.fragment([(3, 1)], [(3, 2)])
        gmsh.model.occ.synchronize()
        gmsh.model.addPhysicalGroup(3, [1], 11)
        gmsh.model.setPhysicalName(3, 11, "bone")
        gmsh.model.addPhysicalGroup(3, [2], 12)
        gmsh.model.setPhysicalName(3, 12, "muscle")
        boundary = [tag for dim, tag in gmsh.model.getBoundary([(3, 1), (3, 2)], oriented=False)]
        gmsh.model.addPhysicalGroup(2, boundary, 21)
        gmsh.model.setPhysicalName(2, 21, "skin")
        gmsh.option.setNumber("Mesh.MeshSizeMax", 0.4)
        gmsh.model.mesh.generate(3)
        tets = len(gmsh.model.mesh.getElementsByType(4)[0])
        triangles = sum(len(gmsh.model.mesh.getElements(2, t)[1][0]) for t in boundary)
        for version in (2.2, 4.1):
            for binary in (0, 1):
                with self.subTest(version=version, binary=binary):
                    gmsh.option.setNumber("Mesh.MshFileVersion", version)
                    gmsh.option.setNumber("Mesh.Binary", binary)
                    name = path(f"gmsh_{version}_{binary}.msh")
                    gmsh.write(name)
                    counts = info(name)
                    self.assertEqual(counts["elements"], tets)
                    self.assertEqual(counts["element_labels"], [11, 12])
                    self.assertEqual(counts["face_labels"], [21])
                    # the names go through sxk and back into Gmsh
                    sxk("convert", name, path("named.msh"))
                    mesh = meshio.read(path("named.msh"))
                    self.assertEqual({k: v.tolist() for k, v in mesh.field_data.items()},
                                     {"skin": [21, 2], "bone": [11, 3], "muscle": [12, 3]})
                    self.assertEqual(sum(len(b.data) for b in mesh.cells if b.type == "triangle"), triangles)


def main():
    global SXK, WORK
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    SXK = os.path.abspath(sys.argv.pop(1))
    WORK = tempfile.mkdtemp(prefix="sxk-interop-")
    try:
        unittest.main(verbosity=2)
    finally:
        shutil.rmtree(WORK, ignore_errors=True)


if __name__ == "__main__":
    main()
