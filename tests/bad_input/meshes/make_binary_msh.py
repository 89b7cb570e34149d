#!/usr/bin/env python3
# Writes two_triangles_binary.msh: the two triangles of two_triangles.msh in
# Gmsh's binary format 2.2 (what 'gmsh -bin' writes), for the test
# mesh_binary_gmsh, which must be refused with a message saying how to write
# ASCII. Run it in this folder.
import struct

nodes = [(1, 0., 0.), (2, 1., 0.), (3, 1., 1.), (4, 0., 1.)]
# (number, physical tag, elementary tag, nodes) of triangles (type 2).
triangles = [(1, 1, 1, (1, 2, 3)), (2, 1, 1, (1, 3, 4))]

with open("two_triangles_binary.msh", "wb") as out:
    out.write(b"$MeshFormat\n2.2 1 8\n")
    out.write(struct.pack("<i", 1))  # the "one" that tells the byte order
    out.write(b"\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
    for number, x, y in nodes:
        out.write(struct.pack("<iddd", number, x, y, 0.))
    out.write(b"\n$EndNodes\n$Elements\n%d\n" % len(triangles))
    out.write(struct.pack("<iii", 2, len(triangles), 2))
    for number, physical, elementary, vertices in triangles:
        out.write(struct.pack("<iii", number, physical, elementary))
        out.write(struct.pack("<iii", *vertices))
    out.write(b"\n$EndElements\n")
