# The cases of scripts/probe_inputs for the faults of a many-rank, long-running run.
"""Ranks that read different inputs or own nothing of a physics object, concurrent runs
on one folder, checkpoint folders holding other files, resumes into another folder,
references that share too few times, memory limits, bodies that stop being held, entries
at extreme values and messages. Each case says what a demanding user expects; the harness
(scripts/probe_inputs) runs and classifies it."""
import os, signal, subprocess, time
from pathlib import Path

RANKS, CONC = "ranks", "concurrency"
LOCKED = "(another|other) run|in use|locked"


def cases(h):
    """The fault cases, built with the harness' helpers h (its module globals)."""
    case, scene, prior, msh = h.case, h.scene, h.prior, h.msh
    CKPT, RT, NUM, MESH, OUT, CF, CE, END = (h.CKPT, h.RT, h.NUM, h.MESH, h.OUT, h.CF,
                                              h.CE, h.END)
    PETSC = {"Solver/Linear algebra": "PETSc"}
    SLOW = {END: "100", "Geometry/Subdivisions": "64, 64"}   # runs until it is killed

    def folders(*specs):
        """setup: subfolders (name, overrides or None for no scene, extra files)."""
        def setup(d):
            for name, over, files in specs:
                Path(d, name).mkdir()
                if over is not None:   # the output folder where every rank sees it
                    over = dict({OUT: os.path.join(d, "A", "out")}, **over)
                    extra = over.pop("include", None)   # a last line 'include FILE'
                    Path(d, name, "scene.prm").write_bytes(
                        scene(over) + (b"include %s\n" % extra.encode() if extra else b""))
                for rel, text in files.items():
                    Path(d, name, rel).write_text(text)
        return setup

    def background(over, args=(), wait_for="out/statistics.csv"):
        """setup: a run of the base scene with over, left running while the case runs."""
        def setup(d):
            Path(d, "first.prm").write_bytes(scene(over))
            proc = subprocess.Popen([h.PRIOR[0], *args, "first.prm"], cwd=d,
                                    stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                    stderr=subprocess.DEVNULL, start_new_session=True)
            for _ in range(600):   # until the first run has written its first step
                if Path(d, wait_for).exists() or proc.poll() is not None:
                    break
                time.sleep(0.1)
            return proc
        return setup

    def killed(over):
        """setup: a run killed by SIGKILL after its first steps (no clean end)."""
        def setup(d):
            proc = background(over)(d)
            time.sleep(1)
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
        return setup

    def plant(*files):
        """then: plant a user's files after a prior run."""
        return lambda d: [(Path(d, f).parent.mkdir(parents=True, exist_ok=True),
                           Path(d, f).write_text(h.USER)) for f in files]

    def pvd_complete(folder):
        """check: every file the .pvd of folder lists exists."""
        def check(d, output):
            pvd = Path(d, folder, "solution.pvd")
            if not pvd.is_file():
                return "no %s/solution.pvd" % folder
            import re
            missing = [f for f in re.findall(r'file="([^"]+)"', pvd.read_text())
                       if not (pvd.parent / f).is_file()]
            return "solution.pvd lists missing files: " + ", ".join(missing[:3]) if missing \
                else None
        return check

    def violation_below(bound):
        """check: the end-of-run friction violation is below bound."""
        def check(d, output):
            import re
            found = re.findall(r"violation[^\n]*?([0-9.]+e[-+]?[0-9]+)", output)
            values = [float(v) for v in found]
            return ("friction violation %g reported" % max(values)
                    if values and max(values) > bound else None)
        return check

    # Three unit squares side by side, apart from each other: the left two clamped on
    # their left sides (tag 1), the right one held by nothing; the loads act on all.
    squares = [(x + dx, y) for x in (0, 2, 4) for dx, y in ((0, 0), (1, 0), (1, 1), (0, 1))]
    three = msh(squares, [(1, 2, 3, 4), (5, 6, 7, 8), (9, 10, 11, 12)],
                ((1, 1, 4), (1, 5, 8), (2, 2, 3), (2, 6, 7), (2, 10, 11)))
    unheld = dict(h.MESH_SET, **{"Boundary conditions/Contact boundary ids": "",
                                 "Damage/Model": "none"})
    return [
        # === ranks that read different inputs or own nothing of a physics object
        case("mpmd_prm_differs", RANKS, "mpirun A : B, B's scene has another Young's modulus: "
             "rank 0's scene is the run's (one reading), no hang", "ran", outdir="A/out",
             mpmd=[("A", 1), ("B", 1)], setup=folders(("A", {}, {}),
                                                      ("B", {h.E: "500"}, {}))),
        case("mpmd_relative_outdir", RANKS, "mpirun A : B with a relative Output/Directory "
             "that rank 1 (in B) does not see: refused naming rank 1, no hang",
             mpmd=[("A", 1), ("B", 1)], says="rank 1", allow=("A/out",),
             setup=folders(("A", {OUT: "out"}, {}), ("B", {OUT: "out"}, {}))),
        case("mpmd_prm_missing_rank0", RANKS, "mpirun A : B, no scene.prm in A (rank 0): one "
             "message naming the file, no hang", mpmd=[("A", 1), ("B", 1)],
             setup=folders(("A", None, {}), ("B", {}, {})), says="scene.prm"),
        case("mpmd_mesh_only_rank0", RANKS, "mpirun A : B (2 ranks), the mesh file only in A: "
             "rank 0 reads it for all", "ran", outdir="A/out", mpmd=[("A", 1), ("B", 2)],
             setup=folders(("A", h.MESH_SET, {"mesh.msh": h.GOOD}), ("B", h.MESH_SET, {}))),
        case("mpmd_include_only_rank0", RANKS, "mpirun A : B, the included file only in A",
             "ran", outdir="A/out", mpmd=[("A", 1), ("B", 1)],
             setup=folders(("A", {"include": "more.prm"},
                            {"more.prm": "subsection Time\n set End time = 0.05\nend\n"}),
                           ("B", {"include": "more.prm"}, {}))),
        case("np3_petsc_rank_without_cell", RANKS, "3 ranks, 2 x 1 cells (a rank owns no cell),"
             " PETSc, damage and friction g = 20", "ran", np=3,
             set=dict(PETSC, **{"Geometry/Subdivisions": "2, 1", h.FB: "20"})),
        case("np3_petsc_damage_on_one_rank", RANKS, "3 ranks, PETSc, a damage source that "
             "reaches zeta = 0 near the loaded corner only (one rank)", "ran", np=3,
             set=dict(PETSC, **{"Damage/Function constants": "lambda_w:0.5, lambda_E:1e5",
                                END: "0.2"})),
        case("np3_contact_top_one_rank", RANKS, "3 ranks, contact on the top side (id 3) only, "
             "g = 1, both loads", "ran", np=3,
             set={"Boundary conditions/Contact boundary ids": "3", h.FB: "1"}),
        case("np2_mumps_damage", RANKS, "2 ranks, PETSc MUMPS with damage", "ran", np=2,
             set=dict(PETSC, **{"Solver/Linear solver": "MUMPS"})),
        # === concurrent runs on one folder
        case("conc_same_checkpoint_folder", CONC, "while a run writes 'out', a second run to "
             "'out2' with Checkpoint/Folder = out/checkpoint: refused naming the other run",
             set={OUT: "out2", CF: "out/checkpoint", CE: "1"},
             setup=background(dict(SLOW, **{CE: "1"})), allow=("out",), says=LOCKED),
        case("conc_resume_while_running", CONC, "--resume on the folder of a run still going: "
             "refused naming the other run", args=("--resume",), set=dict(SLOW, **{CE: "1"}),
             setup=background(dict(SLOW, **{CE: "1"})), says=LOCKED),
        case("conc_after_kill9", CONC, "a run killed by SIGKILL, then a new run on its folder: "
             "the lock died with it", "ran", setup=killed(SLOW)),
        # === checkpoint folders and resumes
        case("ckpt_user_subfolder", CKPT, "a user's folder with a file inside out/checkpoint "
             "of an earlier run: refused, nothing removed", set={CE: "2"},
             setup=prior({CE: "2"}, plant("out/checkpoint/mine/thesis.tex")),
             says="mine|thesis"),
        case("ckpt_user_file_in_old", CKPT, "a user's file in out/checkpoint.old: refused or "
             "kept, never removed", set={CE: "1"},
             setup=prior({CE: "1"}, plant("out/checkpoint.old/thesis.tex")), says="thesis"),
        case("resume_other_outdir", CKPT, "--resume into Output/Directory = out2 (checkpoint "
             "of 'out'): every output solution.pvd lists exists", "ran", args=("--resume",),
             set={OUT: "out2", CF: "out/checkpoint", END: "0.2"},
             setup=prior({CE: "2"}), check=pvd_complete("out2")),
        case("reference_one_time", RT, "a reference whose snapshots share only t = 0.1 with "
             "the run: refused, not a table of round-off errors",
             set={"Reference solution/Compare with": "ref/reference"},
             setup=prior({OUT: "ref", "Reference solution/Write snapshots": "true",
                          "Reference solution/Snapshot interval": "0.1"}, name="ref.prm"),
             says="Reference solution"),
        # === memory
        case("memory_ulimit_box", NUM, "a 2048^2 box under an address space of 1 GiB: "
             "refused before building, naming the size entries",
             set={"Geometry/Subdivisions": "2048, 2048"}, memory=2**30, says="Subdivisions"),
        case("memory_adaptive_all_cells", NUM, "25 adaptive cycles refining every cell: "
             "refused as the same uniform cycles are",
             set={h.MR + "Strategy": "adaptive", h.MR + "Number of cycles": "25",
                  h.MR + "Refinement fraction": "1"}, says="Number of cycles"),
        case("memory_simplex_box_np2", NUM, "simplex box of 3000 x 3000 on 2 ranks (each rank "
             "holds the whole mesh): refused before building", np=2,
             set={"Geometry/Cell type": "simplex", "Geometry/Subdivisions": "3000, 3000"}, says="Subdivisions"),
        # === bodies that are not held, entries at extreme values
        case("unheld_third_square", MESH, "three separate squares, the right one held by "
             "nothing: refused naming that part", set=unheld, files={"mesh.msh": three}, says="held"),
        case("friction_bound_1e-200", RT, "Friction bound = 1e-200: the frictionless answer, "
             "a violation that stays small", "ran", set={h.FB: "1e-200"},
             check=violation_below(1e-6)),
        case("slip_tolerance_one_3d", NUM, "Slip direction tolerance = 1 (a radian) in 3D",
             set=dict(h.D3, **{h.FB: "20", "Contact/Slip direction tolerance": "1",
                               "Boundary conditions/Contact boundary ids": "4"}),
             says="Slip direction tolerance"),
        case("complementarity_1e30", NUM, "Contact/Complementarity factor = 1e30",
             set={"Contact/Complementarity factor": "1e30", h.FB: "20"},
             says="Complementarity factor"),
        case("petsc_options_bad_pc", NUM, "PETSC_OPTIONS='-vpcontact_pc_type nonsense' with "
             "PETSc: one message naming PETSC_OPTIONS", set=PETSC,
             env={"PETSC_OPTIONS": "-vpcontact_pc_type nonsense"}, says="PETSC_OPTIONS"),
        case("mesh_binary_msh", MESH, "a binary Gmsh 2.2 file: refused saying to write ASCII",
             set=h.MESH_SET, files={"mesh.msh": b"$MeshFormat\n2.2 1 8\n\x01\x00\x00\x00\n"
                                                b"$EndMeshFormat\n$Nodes\n" + bytes(64)},
             says="ASCII"),
        # === output that cannot be written any more
        case("stdout_closed", RT, "the program's standard output closed (>&-): it runs and "
             "says nothing, or stops with a checkpoint; never a crash", "ran",
             shell='"$VPCONTACT" scene.prm 2>&1 >&-; s=$?; [ $s = 0 ] && '
                   'echo "Run complete: 10 steps"; exit $s'),
    ]
