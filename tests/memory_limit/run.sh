#!/usr/bin/env bash
# The memory check under a process limit: a simplex box whose cells need
# more than `ulimit -v` allows (though less than the machine has) is refused
# before the mesh is built, with a message naming the entries and the
# limit, instead of running into std::bad_alloc. (On a machine with less
# than the 5.6 GB the mesh needs, the message names its memory instead.)
# Usage: run.sh VPCONTACT EXPECTED_OUTPUT; prints what it checks and fails if
# that differs from EXPECTED_OUTPUT.
set -u
vpcontact=$1
expected=$2
work=$(pwd)/memory_limit_work
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
cat > scene.prm <<'PRM'
subsection Geometry
  set Cell type    = simplex
  set Subdivisions = 2000, 1000
end
subsection Output
  set Directory = out
end
PRM
(ulimit -v 4000000 && "$vpcontact" scene.prm) > screen.log 2>&1
status=$?
{
  echo "under ulimit -v 4000000: exit status $status"
  grep '^Error: ' screen.log
  grep -qiE 'bad_alloc|terminate|abort|segmentation' screen.log \
    && echo "UNCLEAN STOP"
  [ -e out/statistics.csv ] && echo "the run started computing"
} > transcript
cat transcript
diff -u "$expected" transcript && exit 0
echo "memory_limit: the transcript differs from $expected" >&2
exit 1
