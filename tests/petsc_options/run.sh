#!/usr/bin/env bash
# PETSC_OPTIONS that PETSc cannot use: for each value, the scene of
# scene.prm runs with it. Checks:
# - the run stops with exit status 1 and one message that names
#   PETSC_OPTIONS (no PETSc traceback, no abort);
# - a valid option still reaches the solver and the run completes.
# Usage: run.sh VPCONTACT EXPECTED_OUTPUT; prints what it checks and fails if
# that differs from EXPECTED_OUTPUT.
set -u
vpcontact=$1
expected=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(pwd)/petsc_options_work
rm -rf "$work" && mkdir -p "$work" && cp "$here/scene.prm" "$work/"
cd "$work" || exit 1

check() {
  echo "--- PETSC_OPTIONS='$1'"
  PETSC_OPTIONS="$1" "$vpcontact" scene.prm > screen.log 2>&1
  echo "exit status $?"
  echo "lines of PETSc traceback: $(grep -c 'PETSC ERROR' screen.log)"
  grep -qiE 'abort|stacktrace|signal' screen.log && echo "UNCLEAN STOP"
  grep '^Error: ' screen.log | grep -q 'PETSC_OPTIONS' \
    && echo "the message names PETSC_OPTIONS"
  grep -q '^Run complete' screen.log && echo "run complete"
  # What PETSc objected to, in the message's own words.
  grep -oE "Unable to find requested PC type nonsense|abc has no integer value|options file '/nonexistent/petsc.opts'" screen.log
}

{
  check "-vpcontact_pc_type nonsense"
  check "-vpcontact_ksp_max_it abc"
  check "-options_file /nonexistent/petsc.opts"
  check "-vpcontact_ksp_type cg -vpcontact_pc_type jacobi"
} > transcript 2>&1
cat transcript
diff -u "$expected" transcript && exit 0
echo "petsc_options: the transcript differs from $expected" >&2
exit 1
