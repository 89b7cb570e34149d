#!/usr/bin/env python3
"""Write bar_tets.msh (Gmsh 2.2 ASCII): the bar [0,4]x[0,1]x[0,1] [m] in
tetrahedra, each unit cube cut into the 6 tetrahedra around its diagonal
from (0,0,0) to (1,1,1) (Kuhn's subdivision, conforming between cubes),
positively oriented, with
its faces tagged as boundary ids (physical tags) 1 = x = 0, 2 = x = 4,
3 = y = 0, 4 = y = 1, 5 = z = 0, 6 = z = 1.
Usage: make_bar_tets.py [n] > bar_tets.msh   (n cubes along x, default 4)"""
import itertools
import sys

n = int(sys.argv[1]) if len(sys.argv) > 1 else 4
ids = {}
nodes = []
for k in range(2):
    for j in range(2):
        for i in range(n + 1):
            ids[(i, j, k)] = len(nodes) + 1
            nodes.append((i, j, k))

tets = []
for c in range(n):
    for perm in itertools.permutations(range(3)):
        corner = [c, 0, 0]
        path = [tuple(corner)]
        for axis in perm:
            corner[axis] += 1
            path.append(tuple(corner))
        # Positively oriented: a negative volume swaps two vertices.
        a, b, d, e = path
        u, v, w = ([q[i] - a[i] for i in range(3)] for q in (b, d, e))
        volume = (u[0] * (v[1] * w[2] - v[2] * w[1])
                  - u[1] * (v[0] * w[2] - v[2] * w[0])
                  + u[2] * (v[0] * w[1] - v[1] * w[0]))
        if volume < 0:
            path[2], path[3] = path[3], path[2]
        tets.append([ids[p] for p in path])


def tag(face):
    """The boundary tag of a face given by its three vertices, or None."""
    points = [nodes[v - 1] for v in face]
    for axis, (low, high) in enumerate([(0, n), (0, 1), (0, 1)]):
        for value, t in ((low, 2 * axis + 1), (high, 2 * axis + 2)):
            if all(p[axis] == value for p in points):
                return t
    return None


triangles = []
for t in tets:
    for face in itertools.combinations(t, 3):
        if tag(face):
            triangles.append((tag(face), face))

out = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$Nodes", str(len(nodes))]
out += [f"{k + 1} {x} {y} {z}" for k, (x, y, z) in enumerate(nodes)]
out += ["$EndNodes", "$Elements", str(len(triangles) + len(tets))]
e = 0
for t, face in triangles:
    e += 1
    out.append(f"{e} 2 2 {t} {t} " + " ".join(map(str, face)))
for t in tets:
    e += 1
    out.append(f"{e} 4 2 1 1 " + " ".join(map(str, t)))
out += ["$EndElements"]
print("\n".join(out))
