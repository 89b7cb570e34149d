#!/usr/bin/env bash
# Output and checkpoint folders used as a careless user would: two runs on
# one folder, a kill -9, a file of the user's in a checkpoint folder, a
# resume into another output folder, the last step of Checkpoint/Every
# steps, the screen output piped into head, eight runs at once. The scene
# is scene.prm (the paper scene on 8 x 8 cells) with the changes each case
# makes.
# Usage: run.sh VPCONTACT EXPECTED_OUTPUT CASE; prints what it checks and
# fails if that differs from EXPECTED_OUTPUT.
set -u
vpcontact=$1
expected=$2
case=$3
here=$(cd "$(dirname "$0")" && pwd)
work=$(pwd)/output_folder_$case
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
cp "$here/scene.prm" .

# variant NAME TEXT: NAME.prm, the scene with the lines of TEXT after it.
variant() {
  printf 'include scene.prm\n%s\n' "$2" > "$1.prm"
}

# The rows of statistics.csv without the column wall_time.
strip_wall_time() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "wall_time") w = i }
           { $w = ""; print }' OFS=, "$1"
}

# Whether the steps of FOLDER/statistics.csv are 0..N, each once.
steps_once() {
  local n
  n=$(awk -F, 'NR > 1 { print $1 }' "$1/statistics.csv" | sort -n | uniq \
    | awk -v n="$2" '$1 == NR - 1 { ++k } END { print (k == n + 1 && NR == n + 1) ? "yes" : "no" }')
  echo "$1/statistics.csv has the steps 0..$2 once each: $n"
}

# Wait (at most 30 s) until the file $1 exists.
wait_for() {
  for _ in $(seq 1 600); do
    [ -e "$1" ] && return 0
    sleep 0.05
  done
  echo "TIMEOUT waiting for $1"
  return 1
}

long_scene='subsection Geometry
  set Subdivisions = 16, 16
end
subsection Time
  set End time = 1
end'

case_lock() {
  # A run, and while it runs a second one on the same folder with another
  # mesh.
  variant long "$long_scene"
  variant other 'subsection Geometry
  set Subdivisions = 4, 4
end'
  "$vpcontact" long.prm > first.log 2>&1 &
  local first=$!
  for _ in $(seq 1 600); do
    grep -q "^$first@" out/.vpcontact-lock 2> /dev/null && break
    sleep 0.05
  done
  # Held (SIGSTOP) while the second run starts, so that it is surely
  # still running then, whatever the speed of the machine.
  kill -STOP "$first"
  "$vpcontact" other.prm > second.log 2>&1
  echo "second run: exit status $?"
  kill -0 "$first" 2> /dev/null \
    && echo "the first run was still running when the second stopped"
  kill -CONT "$first"
  grep -q "^Error: Output/Directory = out: this folder is in use by another run of vpcontact (the run $first@$(hostname), started 20" second.log \
    && echo "the message names the folder and the first run (pid@host, start)"
  grep -q '^step' second.log && echo "THE SECOND RUN COMPUTED"
  wait "$first"
  echo "first run: exit status $?"
  grep -q '^Run complete: 200 steps' first.log && echo "the first run completed"
  echo "cells in its statistics.csv: $(awk -F, 'NR > 1 { print $3 }' out/statistics.csv | sort -u | tr '\n' ' ')"
  echo "cells of its field at t = 0: $(grep -o 'NumberOfCells="[0-9]*"' out/solution_00000.0.vtu)"
  steps_once out 200

  # A run with checkpoints killed by SIGKILL, then resumed: the lock of
  # the killed run is gone with it.
  rm -rf out
  variant checkpointed "$long_scene
subsection Checkpoint
  set Every steps = 5
end"
  "$vpcontact" checkpointed.prm > killed.log 2>&1 &
  local killed=$!
  wait_for out/checkpoint/manifest.txt
  kill -KILL "$killed"
  # (Without the shell's notice "Killed", which names the process id.)
  wait "$killed" 2> /dev/null
  echo "killed run: exit status $?"
  "$vpcontact" --resume checkpointed.prm > resumed.log 2>&1
  echo "resumed run: exit status $?"
  grep -q '^Resuming from the checkpoint in out/checkpoint' resumed.log \
    && echo "it resumed from its checkpoint"
  steps_once out 200
}

case_foreign_file() {
  variant checkpointed 'subsection Checkpoint
  set Every steps = 5
end'
  "$vpcontact" checkpointed.prm > first.log 2>&1
  echo "first run: exit status $?"
  # A file of the user's in the newest checkpoint, then in the previous.
  for folder in checkpoint checkpoint.old; do
    echo "the user's notes" > "out/$folder/notes.txt"
    "$vpcontact" checkpointed.prm > refused.log 2>&1
    echo "--- notes.txt in out/$folder: exit status $?"
    grep -q "^Error: Output/Directory = out (its checkpoints go to out/checkpoint): out/$folder holds notes.txt, which vpcontact did not write" refused.log \
      && echo "the message names the entry, the folder and the file"
    grep -q '^step' refused.log && echo "THE REFUSED RUN COMPUTED"
    echo "out/$folder/notes.txt: $(cat "out/$folder/notes.txt")"
    rm "out/$folder/notes.txt"
  done

  # A file put into the checkpoint folder while the run goes on: the next
  # checkpoint stops the run, and the file stays.
  rm -rf out
  variant long "$long_scene
subsection Checkpoint
  set Every steps = 5
end"
  "$vpcontact" long.prm > during.log 2>&1 &
  local run=$!
  wait_for out/checkpoint/manifest.txt
  until echo "the user's notes" 2> /dev/null > out/checkpoint/notes.txt; do
    sleep 0.01
  done
  wait "$run"
  echo "--- notes.txt put in during the run: exit status $?"
  grep -q "holds notes.txt, which vpcontact did not write" during.log \
    && echo "the message names the file"
  echo "notes.txt in the checkpoint folders: $(cat out/checkpoint*/notes.txt)"

  # Without foreign files the rotation keeps exactly the files of the
  # manifest in checkpoint.old.
  rm -rf out
  "$vpcontact" checkpointed.prm > clean.log 2>&1
  echo "--- a clean run: exit status $?"
  listed=$(awk '!/^#/ { print $3 }' out/checkpoint.old/manifest.txt | sort | tr '\n' ' ')
  present=$(ls -A out/checkpoint.old | grep -v '^manifest.txt$' | sort | tr '\n' ' ')
  echo "checkpoint.old holds: $present"
  [ "$listed" = "$present" ] && echo "which is what its manifest lists"
}

case_resume_elsewhere() {
  local settings='subsection Output
  set Output every = 2
end
subsection Checkpoint
  set Every steps = 5
  set Folder      = ck
end'
  variant full "$settings
subsection Output
  set Directory = full
end"
  variant first "$settings
subsection Time
  set End time = 0.05
end
subsection Output
  set Directory = run1
end"
  variant second "$settings
subsection Output
  set Directory = run2
end"
  variant third "$settings
subsection Time
  set End time = 0.15
end
subsection Output
  set Directory = run3
end"
  "$vpcontact" full.prm > full.log 2>&1
  echo "uninterrupted run: exit status $?"
  "$vpcontact" first.prm > first.log 2>&1
  echo "run to step 10 in run1: exit status $?"
  "$vpcontact" --resume second.prm > second.log 2>&1
  echo "resumed to step 20 in run2: exit status $?"
  grep -q '^Field outputs: the 6 of the checkpointed run (12 files) brought from /.*/run1 into run2 (hard links)' second.log \
    && echo "the screen says what was brought from run1"
  check_pvd run2
  diff -q <(grep -v 'generated by' run2/solution.pvd) \
    <(grep -v 'generated by' full/solution.pvd) > /dev/null \
    && echo "run2/solution.pvd: the same as the uninterrupted run's"
  diff -q <(strip_wall_time run2/statistics.csv) \
    <(strip_wall_time full/statistics.csv) > /dev/null \
    && echo "run2/statistics.csv: the same as the uninterrupted run's"

  # The folder of the checkpointed run is gone: its outputs are left out.
  rm -rf run1 run2
  "$vpcontact" --resume third.prm > third.log 2>&1
  echo "resumed to step 30 in run3, run1 and run2 removed: exit status $?"
  grep -q '^Field outputs: solution_00000.pvtu and 10 more of the checkpointed run are missing or incomplete in /.*/run2; solution.pvd leaves them out.' third.log \
    && echo "the screen says which outputs are left out"
  check_pvd run3
}

# Every file that FOLDER/solution.pvd lists, with the pieces each .pvtu
# names, must be in FOLDER.
check_pvd() {
  local listed=0 missing=0 pvtu piece
  for pvtu in $(grep -o 'file="[^"]*"' "$1/solution.pvd" | cut -d'"' -f2); do
    listed=$((listed + 1))
    [ -f "$1/$pvtu" ] || missing=$((missing + 1))
    for piece in $(grep -o 'Source="[^"]*"' "$1/$pvtu" 2> /dev/null | cut -d'"' -f2); do
      [ -f "$1/$piece" ] || missing=$((missing + 1))
    done
  done
  echo "$1/solution.pvd lists $listed outputs; files missing in $1: $missing"
}

case_every_steps_last() {
  # 10 steps, a checkpoint every 3: at steps 3, 6, 9 and the last, 10.
  variant ten 'subsection Time
  set End time = 0.05
end
subsection Checkpoint
  set Every steps = 3
end'
  variant fifteen 'subsection Time
  set End time = 0.075
end
subsection Checkpoint
  set Every steps = 3
end'
  "$vpcontact" ten.prm > ten.log 2>&1
  echo "run of 10 steps: exit status $?"
  grep '^  checkpoint of step' ten.log
  "$vpcontact" --resume fifteen.prm > fifteen.log 2>&1
  echo "resumed with End time = 0.075: exit status $?"
  grep '^Resuming from' fifteen.log
  steps_once out 15
}

case_concurrent() {
  # Eight runs at once without mpirun, each into a folder of its own and
  # each with a checkpoint every step: the MPI library's files of one run
  # (a singleton's session directory) must not be another's.
  local k
  for k in 1 2 3 4 5 6 7 8; do
    variant "run$k" "subsection Output
  set Directory = out$k
end
subsection Checkpoint
  set Every steps = 1
end"
    "$vpcontact" "run$k.prm" > "run$k.log" 2>&1 &
    # Started one after another, so that runs end while others write.
    sleep 0.4
  done
  for k in 1 2 3 4 5 6 7 8; do
    wait -n
  done
  for k in 1 2 3 4 5 6 7 8; do
    grep -q '^Run complete: 20 steps' "run$k.log" \
      && echo "run $k: complete" \
      || echo "run $k: $(grep -m 1 -A 2 '^Error' "run$k.log" | tr '\n' ' ')"
    steps_once "out$k" 20
  done
}

case_pipe() {
  variant long "$long_scene"
  "$vpcontact" long.prm > full.log 2>&1
  echo "uninterrupted run: exit status $?"
  mv out full
  "$vpcontact" long.prm 2> stderr.log | head -3 > head.log
  echo "vpcontact long.prm | head -3: exit status ${PIPESTATUS[0]}"
  echo "lines through head: $(wc -l < head.log)"
  grep -q '^Stopped on SIGPIPE at the end of step [0-9]* of 200' stderr.log \
    && echo "the stop message is on the error output"
  [ -f out/checkpoint/manifest.txt ] && echo "a checkpoint is written"
  "$vpcontact" --resume long.prm > resumed.log 2>&1
  echo "resumed run: exit status $?"
  diff -q <(strip_wall_time out/statistics.csv) \
    <(strip_wall_time full/statistics.csv) > /dev/null \
    && echo "statistics.csv: the same as the uninterrupted run's"
}

"case_$case" > transcript 2>&1
cat transcript
diff -u "$expected" transcript && exit 0
echo "output_folder/$case: the transcript differs from $expected" >&2
exit 1
