#!/usr/bin/env bash
# run.sh cells|pictures VPCONTACT SOURCE_DIR WORK_DIR: runs the paper scene on
# 8 x 8 cells for 5 steps with fields every step in WORK_DIR, then checks
# what a reader of its output sees (see CMakeLists.txt).
set -euo pipefail
what="$1" program="$2" source="$3" work="$4"
rm -rf "$work" && mkdir -p "$work" && cd "$work"
cat > scene.prm <<PRM
include $source/prm/paper_fig1.prm
subsection Geometry
  set Subdivisions = 8, 8
end
subsection Time
  set End time = 0.05
end
subsection Output
  set Directory    = run
  set Output every = 1
end
PRM
"$program" scene.prm > screen.log

if [ "$what" = cells ]; then
  exec /usr/bin/python3 - <<'PY'
import vtk
reader = vtk.vtkXMLPUnstructuredGridReader()
reader.SetFileName("run/solution_00005.pvtu")
reader.Update()
grid = reader.GetOutput()
cells, points = grid.GetCellData(), grid.GetPointData()
def names(data):
    return {data.GetArrayName(i) for i in range(data.GetNumberOfArrays())}
expected_cells = {"von_mises", "stress_xx", "stress_yy", "stress_xy", "subdomain"}
expected_points = {"displacement", "damage"}
ok = True
for name in sorted(expected_cells):
    array = cells.GetArray(name)
    good = array is not None and array.GetNumberOfTuples() == grid.GetNumberOfCells()
    print(f"{name}: cell data, one value per cell: {'yes' if good else 'NO'}")
    ok &= good
for name in sorted(expected_points):
    good = points.GetArray(name) is not None
    print(f"{name}: point data: {'yes' if good else 'NO'}")
    ok &= good
misplaced = expected_cells & names(points)
print(f"no cell field among the point data: {'yes' if not misplaced else 'NO ' + str(misplaced)}")
ok &= not misplaced
vm = cells.GetArray("von_mises").GetRange() if cells.GetArray("von_mises") else (0, 0)
print(f"von_mises range {vm[0]:.4g} .. {vm[1]:.4g}, positive: {'yes' if vm[1] > 0 else 'NO'}")
ok &= vm[1] > 0
# Each vertex once (9 x 9 of the 8 x 8 cells), and every cell's vertices in
# VTK's order: VTK's areas of the cells positive, and their sum the body's.
once = grid.GetNumberOfPoints() == 81
print(f"points: {grid.GetNumberOfPoints()} for {grid.GetNumberOfCells()} cells, each vertex once: {'yes' if once else 'NO'}")
sizes = vtk.vtkCellSizeFilter()
sizes.SetInputData(grid)
sizes.Update()
area = sizes.GetOutput().GetCellData().GetArray("Area")
areas = [area.GetValue(i) for i in range(area.GetNumberOfTuples())]
b = grid.GetBounds()
box = (b[1] - b[0]) * (b[3] - b[2])
oriented = min(areas) > 0 and abs(sum(areas) - box) < 1e-6 * box
print(f"cell areas positive and summing to the body's: {'yes' if oriented else 'NO'}")
ok &= once and oriented
raise SystemExit(0 if ok else 1)
PY
fi

status=0
"$source/scripts/pvfigures" run/solution.pvd --out pictures || status=$?
[ "$status" -eq 77 ] && exit 77
[ "$status" -eq 0 ] || { echo "scripts/pvfigures failed ($status)"; exit 1; }
for picture in von_mises damage mesh; do
  file="pictures/${picture}_t0.05.png"
  [ -s "$file" ] || { echo "missing: $file"; exit 1; }
  echo "$file written"
done
