#!/usr/bin/env python3
"""Write l_shape.msh (Gmsh 2.2 ASCII): the L-shaped plate
[0,2]x[0,1] + [0,1]x[1,2] [m] in quadrilaterals of size 1/n (or triangles: each quadrilateral cut along
its diagonal from the lower left to the upper right corner), with the
boundary ids (physical tags) used by prm/l_shape_gmsh.prm:
1 = bottom (y = 0), 2 = left (x = 0), 3 = right end (x = 2), 4 = the rest.
With "shuffled", the nodes and cells are numbered in a random order (fixed
seed), as a mesh generator's numbering can be: a program whose setup relies
on cells coming in the order of their degrees of freedom shows it here
(scripts/bench_setup).
Usage: make_l_shape.py [n] [triangles] [shuffled] > l_shape.msh   (default n = 4)
       make_l_shape.py 4 triangles > l_shape_triangles.msh"""
import random
import sys

n = int(sys.argv[1]) if len(sys.argv) > 1 else 4
triangles = "triangles" in sys.argv[2:]
shuffled = "shuffled" in sys.argv[2:]
inside = lambda i, j: not (i > n and j > n)  # grid point (i/n, j/n)
ids = {}
nodes = []
for j in range(2 * n + 1):
    for i in range(2 * n + 1):
        if inside(i, j):
            ids[(i, j)] = len(nodes) + 1
            nodes.append((i / n, j / n))

quads = []
for j in range(2 * n):
    for i in range(2 * n):
        if i >= n and j >= n:
            continue
        quads.append([ids[(i, j)], ids[(i + 1, j)], ids[(i + 1, j + 1)], ids[(i, j + 1)]])

lines = []
for i in range(2 * n):
    lines.append((1, ids[(i, 0)], ids[(i + 1, 0)]))                 # bottom
for j in range(2 * n):
    lines.append((2, ids[(0, j)], ids[(0, j + 1)]))                 # left
for j in range(n):
    lines.append((3, ids[(2 * n, j)], ids[(2 * n, j + 1)]))         # right end
for i in range(n, 2 * n):
    lines.append((4, ids[(i, n)], ids[(i + 1, n)]))                 # top of arm
for j in range(n, 2 * n):
    lines.append((4, ids[(n, j)], ids[(n, j + 1)]))                 # inner side
for i in range(n):
    lines.append((4, ids[(i, 2 * n)], ids[(i + 1, 2 * n)]))         # top

cells = quads
if triangles:  # Gmsh type 2 (triangle) instead of 3 (quadrilateral)
    cells = [t for a, b, c, d in quads for t in ([a, b, c], [a, c, d])]
# Node k gets the number number[k]; the cells and lines come in a random
# order too. Each cell keeps its vertices' order (its orientation).
number = list(range(1, len(nodes) + 1))
if shuffled:
    shuffle = random.Random(51)
    shuffle.shuffle(number)
    shuffle.shuffle(cells)
    shuffle.shuffle(lines)
    cells = [[number[v - 1] for v in c] for c in cells]
    lines = [(tag, number[a - 1], number[b - 1]) for tag, a, b in lines]
order = sorted(range(len(nodes)), key=lambda k: number[k])
out = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$Nodes", str(len(nodes))]
out += [f"{number[k]} {nodes[k][0]:.17g} {nodes[k][1]:.17g} 0" for k in order]
out += ["$EndNodes", "$Elements", str(len(lines) + len(cells))]
e = 0
for tag, a, b in lines:
    e += 1
    out.append(f"{e} 1 2 {tag} {tag} {a} {b}")
for q in cells:
    e += 1
    out.append(f"{e} {2 if triangles else 3} 2 1 1 " + " ".join(map(str, q)))
out += ["$EndElements"]
print("\n".join(out))
