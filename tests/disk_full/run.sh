#!/usr/bin/env bash
# Disk full during a run: the scene of scene.prm runs on a file system too
# small for all its output (a tmpfs in a private mount namespace). Checks:
# - the run stops with exit status 1 and a message (no crash, no abort);
# - every field output the .pvd record lists is complete, and no temporary
#   file is left;
# - once the disk has room again, the run resumes from its last complete
#   checkpoint and ends with the same statistics.csv (wall times aside) as
#   the uninterrupted run.
# Usage: run.sh VPCONTACT EXPECTED_OUTPUT; prints what it checks and fails if
# that differs from EXPECTED_OUTPUT.
set -u
vpcontact=$1
expected=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(pwd)/disk_full_work

if [ "${VPCONTACT_DISK_FULL_INSIDE:-}" != 1 ]; then
  # Re-run this script in a mount namespace of its own, where it may mount
  # a small tmpfs without touching the machine's mounts.
  rm -rf "$work" && mkdir -p "$work"
  if unshare -m true 2>/dev/null; then
    namespace=(unshare -m)
  elif unshare -rm true 2>/dev/null; then
    namespace=(unshare -rm)
  else
    echo "disk_full: this machine allows no private mount namespace" \
      "(unshare -m); the test cannot run here." >&2
    exit 1
  fi
  VPCONTACT_DISK_FULL_INSIDE=1 "${namespace[@]}" bash "$0" "$@" \
    > "$work/transcript" 2>&1
  cat "$work/transcript"
  diff -u "$expected" "$work/transcript" && exit 0
  echo "disk_full: the transcript differs from $expected" >&2
  exit 1
fi

# The uninterrupted run, on the ordinary disk.
mkdir -p "$work/full" && cp "$here/scene.prm" "$work/full/"
(cd "$work/full" && "$vpcontact" scene.prm > screen.log 2>&1)
echo "uninterrupted run: exit status $?"

# Check the output in ./out after a run that stopped because the disk was
# full: an error message, no unclean stop, every field output that the .pvd
# record lists complete (its record and each piece end with the closing
# tag), no temporary file left.
check_stopped_run() {
  echo "exit status $1"
  grep -q '^Error: ' screen.log && echo "it printed an error message"
  grep -qiE 'disk|space' screen.log && echo "the message speaks of the disk"
  grep -qiE 'terminate|abort|stacktrace|signal|segmentation' screen.log \
    && echo "UNCLEAN STOP:" && cat screen.log
  local listed=0 complete=0 ok pvtu piece
  for pvtu in $(grep -o 'solution_[0-9]*\.pvtu' out/solution.pvd); do
    listed=$((listed + 1))
    ok=1
    tail -c 20 "out/$pvtu" | grep -q '</VTKFile>' || ok=0
    for piece in $(grep -o 'solution_[0-9]*\.[0-9]*\.vtu' "out/$pvtu"); do
      tail -c 20 "out/$piece" | grep -q '</VTKFile>' || ok=0
    done
    complete=$((complete + ok))
  done
  [ "$listed" -gt 0 ] && echo "field outputs listed in solution.pvd:" \
    "$((listed - complete)) incomplete"
  echo "temporary files left: $(find out -name '*.tmp' | wc -l)"
}

# Fields only, no checkpoints, on a disk of 100 kB: a field output (a piece,
# its .pvtu record or the .pvd record) is the write that fails.
mkdir -p "$work/tiny"
mount -t tmpfs -o size=100k tmpfs "$work/tiny" || exit 1
sed 's/Every steps = 5/Every steps = 0/' "$here/scene.prm" \
  > "$work/tiny/scene.prm"
cd "$work/tiny" || exit 1
"$vpcontact" scene.prm > screen.log 2>&1
status=$?
echo "--- fields only, disk of 100 kB"
check_stopped_run $status
grep -qE 'solution(_[0-9]+\.|\.pvd)' screen.log && echo "the message names a field output file"

# Fields and checkpoints on a disk of 600 kB: the checkpoint of step 10
# does not fit with the margin the program asks for.
mkdir -p "$work/small"
mount -t tmpfs -o size=600k tmpfs "$work/small" || exit 1
cp "$here/scene.prm" "$work/small/"
cd "$work/small" || exit 1
"$vpcontact" scene.prm > screen.log 2>&1
status=$?
echo "--- fields and checkpoints, disk of 600 kB"
check_stopped_run $status
grep -q 'previous checkpoint, if any, is intact' screen.log \
  && echo "the message says the previous checkpoint is intact"

# Room again: the run resumes from its last complete checkpoint.
mount -o remount,size=20m "$work/small" || exit 1
"$vpcontact" --resume scene.prm > resume.log 2>&1
echo "resumed run: exit status $?"
strip_wall_time() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "wall_time") w = i }
           { $w = ""; print }' OFS=, "$1"
}
if diff <(strip_wall_time out/statistics.csv) \
  <(strip_wall_time "$work/full/out/statistics.csv") > /dev/null; then
  echo "statistics.csv of the resumed run: the same as uninterrupted"
else
  echo "statistics.csv of the resumed run: DIFFERENT"
fi
# Leaving the namespace unmounts both small disks.
