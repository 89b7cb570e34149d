"""Which kernels OpenBLAS runs on this machine, and a hint where it chose
generic ones on a CPU that has better: an OpenBLAS older than the CPU does
not know its model and falls back to its Prescott (SSE3) kernels, whose
dense products (most of the work of the factorizations of Cholesky and
MUMPS) are several times slower than its AVX2 or AVX-512 ones. OPENBLAS_CORETYPE chooses the kernels
when the library loads.

    openblas_core.py          prints the kernels' name and the hint, if any
"""
import ctypes


def core():
    """The name of OpenBLAS's kernels as a process started now with this
    environment gets them ('' without OpenBLAS)."""
    try:
        library = ctypes.CDLL("libopenblas.so.0")
        library.openblas_get_corename.restype = ctypes.c_char_p
        return library.openblas_get_corename().decode()
    except (OSError, AttributeError):
        return ""


def better_core():
    """The OPENBLAS_CORETYPE for the vector instructions the CPU has
    (SkylakeX for AVX-512, Haswell for AVX2), '' without either."""
    try:
        flags = next(line.split(":", 1)[1].split()
                     for line in open("/proc/cpuinfo")
                     if line.startswith("flags"))
    except (OSError, StopIteration):
        return ""
    if "avx512f" in flags:
        return "SkylakeX"
    return "Haswell" if "avx2" in flags else ""


def hint(name=None):
    """What to set where OpenBLAS runs its Prescott kernels on a CPU with
    AVX2 or AVX-512, '' otherwise."""
    name = core() if name is None else name
    better = better_core()
    if name.lower() != "prescott" or not better:
        return ""
    return (f"OpenBLAS does not know this CPU and runs its generic Prescott "
            f"kernels, although the CPU has the vector instructions of its "
            f"{better} kernels: set OPENBLAS_CORETYPE={better} in the "
            f"environment of the runs (the dense products of the "
            f"factorizations of Cholesky and MUMPS run several times faster "
            f"so, the factorizations and substitutions faster).")


if __name__ == "__main__":
    print(core() or "no OpenBLAS")
    if hint():
        print(hint())
