#!/usr/bin/env bash
# Ranks that do not see the same input: mpirun in MPMD mode with one working
# directory per rank (mpirun -np 1 -wdir A ... : -np 1 -wdir B ...), each
# holding its own copy of the scene (prm/l_shape_gmsh.prm, 4 steps) and of
# its mesh file, one of them broken or missing. Rank 0 alone reads the
# parameter file and the mesh file and hands them to the other ranks, so:
#  * a copy broken or missing in rank 0's folder stops both ranks with one
#    message and exit status 1;
#  * a copy broken, different or missing in rank 1's folder is never read:
#    the run completes, and its statistics.csv equals that of the run from
#    rank 0's folder alone (numdiff, absolute 1e-8, relative 1e-7);
#  * so is rank 1's command line: --resume given to rank 1 alone is ignored;
#  * a relative Output/Directory, which each rank takes from its own working
#    directory, is refused when a rank does not see the folder that rank 0
#    made (its pieces of the fields would be written elsewhere).
# Every run is under `timeout 300`: exit status 124 would be a hang.
# Usage: run.sh VPCONTACT EXPECTED_OUTPUT
set -u
vpcontact=$1
expected=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(pwd)/mpmd_work
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1

scene() { # folder output-folder [extra lines]
  mkdir -p "$1"
  cp "$here/../../prm/meshes/l_shape.msh" "$1/l_shape.msh"
  cat > "$1/scene.prm" << PRM
include $here/../../prm/l_shape_gmsh.prm
subsection Geometry
  set Mesh file = l_shape.msh
end
subsection Time
  set End time = 1
end
subsection Solver
  set Relative tolerance = 1e-12
end
subsection Output
  set Directory                   = $work/$2
  set Output every                = 0
  set Deterministic screen output = true
end
${3:-}
PRM
}

# The lines of a log that this program writes about an error or the end.
report() {
  grep -E '^(Error|Stopped|Run complete)' "$1" | sed "s|$work/||g"
}

mpmd() { # name [option of rank 1]
  timeout 300 mpirun -np 1 -wdir "$work/$1/A" "$vpcontact" scene.prm : \
    -np 1 -wdir "$work/$1/B" "$vpcontact" ${2:-} scene.prm > "$1.log" 2>&1
  echo "$1: exit status $?"
  report "$1.log"
}

# statistics.csv without its wall_time column, which differs between runs.
strip() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) skip[i] = ($i == "wall_time") }
           { line = ""; for (i = 1; i <= NF; ++i) if (!skip[i])
               line = line (line == "" ? "" : ",") $i; print line }' "$1"
}

same_statistics() { # name
  strip reference/statistics.csv > reference.csv
  strip "$1/statistics.csv" > "$1.csv"
  if numdiff -q -s ' \t\n,' -a 1e-8 -r 1e-7 reference.csv "$1.csv" \
       > /dev/null 2>&1; then
    echo "$1: statistics.csv equal to the run from rank 0's folder alone"
  else
    echo "$1: statistics.csv DIFFERENT from the run from rank 0's folder alone"
  fi
}

{
  scene reference/A reference
  (cd reference/A && timeout 300 mpirun -np 2 "$vpcontact" scene.prm \
     > ../../reference.log 2>&1)
  echo "reference (both ranks in one folder): exit status $?"

  name=prm_broken_on_rank_0
  scene $name/A $name "subsection Material
  set Youngs modulus = 1000
end"
  scene $name/B $name
  mpmd $name

  name=prm_missing_on_rank_0
  scene $name/A $name && rm $name/A/scene.prm
  scene $name/B $name
  mpmd $name

  name=mesh_missing_on_rank_0
  scene $name/A $name && rm $name/A/l_shape.msh
  scene $name/B $name
  mpmd $name

  name=prm_broken_on_rank_1
  scene $name/A $name
  scene $name/B $name "subsection Material
  set Youngs modulus = 1000
end"
  mpmd $name
  same_statistics $name

  name=prm_different_on_rank_1
  scene $name/A $name
  scene $name/B $name "subsection Geometry
  set Global refinements = 2
end"
  mpmd $name
  same_statistics $name

  name=files_missing_on_rank_1
  scene $name/A $name
  mkdir -p $name/B
  mpmd $name
  same_statistics $name

  name=resume_on_rank_1
  scene $name/A $name
  scene $name/B $name
  mpmd $name --resume
  same_statistics $name

  name=output_folder_not_shared
  scene $name/A $name "subsection Output
  set Directory    = results
  set Output every = 1
end"
  scene $name/B $name "subsection Output
  set Directory    = results
  set Output every = 1
end"
  mpmd $name
} > transcript 2>&1
cat transcript
diff -u "$expected" transcript
