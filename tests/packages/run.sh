#!/usr/bin/env bash
# A 2D scene (24 x 24 cells, 20 steps; prm/SCENE.prm, default paper_fig1,
# or paper_fig1_p1 on triangles with its monitor points, or paper_fig1_slip
# whose sets change within the steps) with
# each package and method, on 1 and 2 ranks: its statistics.csv must equal
# that of the serial Trilinos run with CG and AMG to the solver tolerance. The columns compared are every
# column but wall_time, linear_iterations and active_set_iterations (which
# differ by method: CG solves loosely while Tresca's sets change), with
# numdiff's absolute tolerance 1e-8 and relative 1e-7, far above the solver
# tolerance of 1e-12 and far below any figure of the model.
# Usage: run.sh VPCONTACT EXPECTED_OUTPUT [SCENE]
set -u
vpcontact=$1
expected=$2
scene=${3:-paper_fig1}
work=$(pwd)/${scene}_work
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
here=$(cd "$(dirname "$0")" && pwd)

run() { # name ranks package method
  cat > "$1.prm" << PRM
include $here/../../prm/$scene.prm
subsection Geometry
  set Subdivisions = 24, 24
end
subsection Time
  set End time  = 0.2
end
subsection Solver
  set Linear algebra     = $3
  set Linear solver      = $4
  set Relative tolerance = 1e-12
end
subsection Output
  set Directory    = $1
  set Output every = 0
end
PRM
  if [ "$2" = 1 ]; then "$vpcontact" "$1.prm" > "$1.log" 2>&1
  else mpirun -np "$2" "$vpcontact" "$1.prm" > "$1.log" 2>&1; fi
  echo "$1: exit status $?"
}
strip() { # the columns but wall_time and the iteration counts
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i)
                       skip[i] = ($i == "wall_time" || $i == "linear_iterations" \
                                  || $i == "active_set_iterations") }
           { line = ""; for (i = 1; i <= NF; ++i) if (!skip[i])
               line = line (line == "" ? "" : ",") $i; print line }' "$1"
}
{
  run trilinos_amg 1 Trilinos "CG with AMG"
  strip trilinos_amg/statistics.csv > reference.csv
  echo "reference: $(($(wc -l < reference.csv) - 1)) rows (steps 0 to 20)"
  for case in "trilinos_amg_2 2 Trilinos CG with AMG" \
              "trilinos_mumps_2 2 Trilinos MUMPS" \
              "petsc_amg 1 PETSc CG with AMG" "petsc_amg_2 2 PETSc CG with AMG" \
              "petsc_mumps 1 PETSc MUMPS" "petsc_mumps_2 2 PETSc MUMPS" \
              "cholesky 1 Trilinos Cholesky"; do
    set -- $case
    name=$1 ranks=$2 package=$3; shift 3
    run "$name" "$ranks" "$package" "$*"
    strip "$name/statistics.csv" > "$name.csv"
    if numdiff -q -s ' \t\n,' -a 1e-8 -r 1e-7 reference.csv "$name.csv" > /dev/null; then
      echo "$name: statistics.csv equal to the reference"
    else
      echo "$name: statistics.csv DIFFERENT from the reference"
    fi
  done
} > transcript 2>&1
cat transcript
diff -u "$expected" transcript
