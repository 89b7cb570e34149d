#!/usr/bin/env bash
# Checkpoints beside a semaphore that a killed process left held. Open MPI's
# OMPIO guards a file's shared pointer with the named semaphore
# /dev/shm/sem.OMPIO_<file name>, one for every file of that name on the
# machine; a process that dies holding it leaves it held, and OMPIO then
# waits for ever in MPI_File_open (mpi_io_choice.cc). This test holds the
# semaphore of a checkpoint's "mesh" file and checks:
# - a run with checkpoints finishes (1 rank), and a resume from its
#   checkpoint on 2 ranks reads it and writes its own: the program opens
#   files with ROMIO;
# - with the user's choice OMPI_MCA_io=ompio the same run stops at its first
#   checkpoint until it is killed: the user's choice stands, and the held
#   semaphore does block OMPIO, so that this test would see the fault.
# The semaphore is made only where none exists (another program's is left
# alone, and the test fails saying so); the test removes the one it made.
# Usage: run.sh VPCONTACT EXPECTED_OUTPUT; prints what it checks and fails
# if that differs from EXPECTED_OUTPUT.
set -u
vpcontact=$1
expected=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(pwd)/mpi_io_work
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# The resume on 2 ranks also on a machine of one core, as in tests/mpmd.
export OMPI_MCA_rmaps_base_oversubscribe=1
hold="/usr/bin/python3 $here/hold_semaphore.py"

# The paper scene on 8 x 8 cells (that of tests/output_folder), 20 steps,
# a checkpoint every 5.
cp "$here/../output_folder/scene.prm" .
printf 'include scene.prm\nsubsection Checkpoint\n  set Every steps = 5\nend\n' \
  > checkpointed.prm
printf 'include checkpointed.prm\nsubsection Time\n  set End time = 0.15\nend\n' \
  > longer.prm
printf 'include checkpointed.prm\nsubsection Output\n  set Directory = ompio\nend\n' \
  > ompio.prm

$hold make mesh || exit 1
trap '$hold remove mesh' EXIT
{
  timeout --foreground -s KILL 120 "$vpcontact" checkpointed.prm \
    > first.log 2>&1
  echo "run with checkpoints, 1 rank: exit status $?"
  grep -q '^  checkpoint of step 20 written' first.log \
    && echo "it wrote the checkpoint of step 20"

  timeout -s KILL 120 mpirun -np 2 "$vpcontact" --resume longer.prm \
    > resumed.log 2>&1
  echo "resumed on 2 ranks to step 30: exit status $?"
  grep -q '^Resuming from the checkpoint in out/checkpoint' resumed.log \
    && echo "it resumed from the checkpoint of step 20"
  grep -q '^  checkpoint of step 30 written' resumed.log \
    && echo "it wrote the checkpoint of step 30"

  # 15 s: the run reaches its first checkpoint in about 1 s.
  # (--foreground: timeout kills the run alone, not itself, so that the
  # shell prints no notice "Killed" with a process id.)
  OMPI_MCA_io=ompio timeout --foreground -s KILL 15 "$vpcontact" \
    ompio.prm > ompio.log 2>&1
  echo "with OMPI_MCA_io=ompio: exit status $? (137: killed)"
  grep -q '^step 5 ' ompio.log && echo "it computed step 5"
  grep -q 'checkpoint of step' ompio.log \
    || echo "it wrote no checkpoint"
} > transcript 2>&1
cat transcript
diff -u "$expected" transcript && exit 0
echo "mpi_io: the transcript differs from $expected" >&2
exit 1
