"""Builds earlier commits of vpcontact for `scripts/bench --against COMMIT`:
each in a temporary git worktree under the benchmark's work folder, configured
as a Release build and compiled (only its `vpcontact` target, through ccache
where it is installed), so that its runs and phases join HEAD's in the same
benchmark run; the worktrees are removed again when the benchmark ends.

The module knows nothing of the runs themselves: bench.py plans and times
them alike for every binary and skips what a binary does not offer."""
import hashlib
import os
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join("prm", "paper_fig1.prm")


class Program:
    """One vpcontact binary of the benchmark: the commit it was built from
    (its label in the report and the CSV), the executable, the paper scene
    file of its tree (a binary reads the scene as its own commit writes it:
    an earlier one refuses entries it does not know), the entries it offers
    (`--print-parameters`, filled in by bench.py) and the environment
    entries its runs get (bench.py --huge-pages)."""

    def __init__(self, commit, executable, root):
        self.commit = commit
        self.executable = executable
        self.scene = os.path.join(root, SCENE)
        with open(self.scene, "rb") as f:
            self.scene_hash = hashlib.sha1(f.read()).hexdigest()[:7]
        self.has = {}
        # NAME=VALUE entries set for this binary's runs alone (bench.py
        # --huge-pages); none for a commit's own build.
        self.environment = ()


def git(*args, check=True):
    """Runs git in this repository; its stdout, stripped."""
    p = subprocess.run(["git", "-C", ROOT] + list(args), capture_output=True,
                       text=True)
    if check and p.returncode:
        raise RuntimeError(f"git {' '.join(args)}: {p.stderr.strip()}")
    return p.stdout.strip() if p.returncode == 0 else None


def resolve(commit):
    """The full hash of a commit given by the user, or exit naming it."""
    full = git("rev-parse", "--verify", "--quiet", commit + "^{commit}",
               check=False)
    if not full:
        sys.exit(f"error: --against {commit}: not a commit of this "
                 f"repository ({ROOT}); give a hash, tag or branch that "
                 "`git log` shows")
    return full


class Worktrees:
    """The temporary worktrees of one benchmark run, used as a `with` block:
    `add` checks a commit out and builds it; leaving the block removes every
    worktree it added, also after a failure or an interrupt."""

    def __init__(self, workdir):
        self.folder = os.path.join(os.path.abspath(workdir), "against")
        self.added = []

    def __enter__(self):
        return self

    def __exit__(self, *exception):
        for path in self.added:
            git("worktree", "remove", "--force", path, check=False)
        if os.path.isdir(self.folder) and not os.listdir(self.folder):
            os.rmdir(self.folder)
        return False

    def add(self, commit, log_folder):
        """Checks `commit` out in the folder against/<hash> of the work
        folder, builds its vpcontact and returns its Program. The folder's
        name stays the same from run to run, so that ccache finds the
        objects of an earlier benchmark of the same commit."""
        full = resolve(commit)
        short = git("rev-parse", "--short", full)
        path = os.path.join(self.folder, full)
        self.take_over(path)
        os.makedirs(self.folder, exist_ok=True)
        print(f"building vpcontact at {short} in {path}", flush=True)
        # --force: git may still list the folder of a killed run whose
        # files are gone (take_over leaves nothing in its place).
        git("worktree", "add", "--force", "--detach", path, full)
        self.added.append(path)
        log = os.path.join(log_folder, f"build_{short}.log")
        build(path, log, f"--against {commit}")
        return Program(short, os.path.join(path, "build", "vpcontact"), path)

    def take_over(self, path):
        """An earlier benchmark that was killed may have left its worktree
        of this commit behind: this script's own, known to git, so it goes.
        Anything else in its place is the user's and stops the run."""
        if not os.path.exists(path):
            return
        listed = git("worktree", "list", "--porcelain").splitlines()
        if "worktree " + path not in listed:
            sys.exit(f"error: {path} exists and is not a worktree that "
                     "scripts/bench made; move it away or give another "
                     "--workdir")
        git("worktree", "remove", "--force", path)


def build(path, log, option):
    """Configures the worktree's Release build and compiles its vpcontact
    target; the output goes to `log`. A failure ends the benchmark before
    anything is timed, naming the log."""
    launcher = (["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"]
                if shutil.which("ccache") else [])
    steps = [["cmake", "-S", path, "-B", os.path.join(path, "build"),
              "-DCMAKE_BUILD_TYPE=Release"] + launcher,
             ["cmake", "--build", os.path.join(path, "build"), "--parallel",
              str(os.cpu_count() or 1), "--target", "vpcontact"]]
    with open(log, "w") as f:
        for command in steps:
            f.write(" ".join(command) + "\n")
            f.flush()
            if subprocess.run(command, stdout=f, stderr=subprocess.STDOUT,
                              cwd=path).returncode:
                sys.exit(f"error: {option}: building vpcontact failed "
                         f"(`{' '.join(command)}`); see {log}")
