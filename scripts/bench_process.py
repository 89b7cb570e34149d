"""How scripts/bench starts a run: retried where the binary was being
relinked, and with its peak private memory, the anonymous pages (heap,
stacks, anonymous maps) of every process of the run's executable below the
command, summed over them and sampled from /proc while the command runs.

Why beside /usr/bin/time's peak resident set: the resident set also counts
the pages a process maps from files, the libraries' code and their dynamic
symbol tables among them. Those pages come from the page cache, are shared
by every process that maps the same library (all ranks of a node) and can be
dropped and read again by the kernel; a process's anonymous pages are its
own. scripts/bench reports both, so that a reader can tell what a run needs
of its own from what it maps of the libraries it loads."""
import os
import re
import subprocess
import threading
import time

ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
           OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def children_by_parent():
    """{parent pid: [child pids]} of every process, from one pass over
    /proc."""
    found = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat") as f:
                    # The name in brackets may hold spaces: split after it.
                    parent = int(f.read().rsplit(")", 1)[1].split()[1])
                found.setdefault(parent, []).append(int(entry))
            except (OSError, IndexError, ValueError):
                pass  # gone meanwhile
    return found


def anonymous_kb(pid):
    """The process's anonymous resident memory in kB (RssAnon of
    /proc/PID/status, a counter the kernel keeps, cheap to read, unlike
    smaps, which walks the page tables), or 0 once it is gone."""
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith("RssAnon:"):
                    return int(line.split()[1])
    except (OSError, ValueError):
        pass
    return 0


def name_of(pid):
    try:
        with open(f"/proc/{pid}/comm") as f:
            return f.read().strip()
    except OSError:
        return ""


class PeakPrivateMemory:
    """Samples, every @p interval seconds from start() to stop(), the sum of
    the anonymous memory of the processes below @p root_pid whose name
    (/proc/PID/comm, at most 15 characters) is @p name's: the ranks of an
    MPI run, without mpirun, time or the shells around them. peak_mb() is
    the largest sum seen, in MB; a peak shorter than the interval can be
    missed, so the figure is a lower bound of the true peak."""

    def __init__(self, root_pid, name, interval=0.1):
        self.root, self.name = root_pid, os.path.basename(name)[:15]
        self.interval, self.peak_kb = interval, 0
        self.done = threading.Event()
        self.thread = threading.Thread(target=self.sample, daemon=True)

    def start(self):
        self.thread.start()
        return self

    def stop(self):
        self.done.set()
        self.thread.join()

    def processes(self):
        children = children_by_parent()
        tree, stack = [], [self.root]
        while stack:
            pid = stack.pop()
            tree.append(pid)
            stack += children.get(pid, [])
        return [p for p in tree if name_of(p) == self.name]

    def sample(self):
        # The tree is looked up again every tenth sample only (and while no
        # process of the name is found): listing /proc costs more than
        # reading the counters of the few processes found.
        found, count = [], 0
        while not self.done.is_set():
            if not found or count % 10 == 0:
                found = self.processes()
            count += 1
            self.peak_kb = max(self.peak_kb,
                               sum(anonymous_kb(p) for p in found))
            self.done.wait(self.interval)

    def peak_mb(self):
        return self.peak_kb / 1024 if self.peak_kb else ""


def binary_stamp(executable):
    """Modification times of the binary and its library: a change during a
    run means it was relinked under it."""
    files = [executable, os.path.join(os.path.dirname(executable),
                                      "libvpcontact_lib.so")]
    return tuple(os.stat(f).st_mtime if os.path.exists(f) else None
                 for f in files)


def run_retrying(command, executable=None, attempts=6, private=None):
    """Runs a command; (stdout, stderr, return code, wall seconds). A failure
    that looks like the binary being relinked (it changed or vanished, the
    loader could not start it) is retried after a minute: the program is
    rebuilt while benchmarks run. With a dict @p private, its "mb" becomes
    the peak private memory of the executable's processes below the command
    (PeakPrivateMemory)."""
    executable = executable or command[0]
    for attempt in range(attempts):
        before = binary_stamp(executable)
        start = time.perf_counter()
        try:
            p = subprocess.Popen(command, stdout=subprocess.PIPE,
                                 stderr=subprocess.PIPE, text=True, env=ENV)
            sampler = PeakPrivateMemory(
                p.pid, executable).start() if private is not None else None
            out, err = p.communicate()
            rc = p.returncode
            if sampler:
                sampler.stop()
                private["mb"] = sampler.peak_mb()
        except OSError as e:  # binary missing or busy
            out, err, rc = "", str(e), 127
        wall = time.perf_counter() - start
        relinked = (rc in (126, 127) or before != binary_stamp(executable)
                    or before[0] is None or re.search(
                        r"error while loading shared libraries|Text file busy|"
                        r"cannot open shared object|Exec format error", err))
        if rc == 0 or not relinked or attempt == attempts - 1:
            return out, err, rc, wall
        print("  the binary changed or could not start; retrying in 60 s",
              flush=True)
        time.sleep(60)
