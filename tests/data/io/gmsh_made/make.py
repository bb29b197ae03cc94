# The Gmsh-made files of tests/data/io/gmsh_made/: a unit box meshed coarsely by Gmsh 4.8 (Debian's
# python3-gmsh), volume in physical group 7 "bone", two of its faces in group 3 "sides", saved
# in 2.2 and 4.1, ASCII and binary.
import gmsh, sys
out = sys.argv[1]
gmsh.initialize(); gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.add("box")
gmsh.model.occ.addBox(0, 0, 0, 1, 1, 1); gmsh.model.occ.synchronize()
gmsh.model.addPhysicalGroup(3, [1], 7); gmsh.model.setPhysicalName(3, 7, "bone")
gmsh.model.addPhysicalGroup(2, [1, 2], 3); gmsh.model.setPhysicalName(2, 3, "sides")
gmsh.option.setNumber("Mesh.MeshSizeMin", 1.0); gmsh.option.setNumber("Mesh.MeshSizeMax", 1.0)
gmsh.model.mesh.generate(3)
for version in (2.2, 4.1):
    for binary in (0, 1):
        gmsh.option.setNumber("Mesh.MshFileVersion", version); gmsh.option.setNumber("Mesh.Binary", binary)
        gmsh.write(f"{out}/box{str(version).replace('.', '')}_{'binary' if binary else 'ascii'}.msh")
gmsh.finalize()
