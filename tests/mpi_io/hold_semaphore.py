# Makes or removes the POSIX named semaphore that Open MPI's OMPIO would use
# for files named NAME (/dev/shm/sem.OMPIO_NAME), held at 0 as a process
# that died holding it leaves it.
# Usage: hold_semaphore.py make|remove NAME. "make" refuses a semaphore that
# exists already (another program's), with exit status 2. "remove" first
# releases it once: a program of the machine that opened a file NAME
# through OMPIO meanwhile waits in it, and would wait for ever on a
# semaphore removed while held; released, each waiter passes it on.
import ctypes
import os
import sys

action, name = sys.argv[1], ("/OMPIO_" + sys.argv[2]).encode()
libc = ctypes.CDLL("libc.so.6", use_errno=True)
libc.sem_open.restype = ctypes.c_void_p
if action == "make":
    if libc.sem_open(name, os.O_CREAT | os.O_EXCL, 0o644, 0) in (None, 0):
        error = ctypes.get_errno()
        print(f"hold_semaphore.py: cannot make {name.decode()}: "
              f"{os.strerror(error)}. If no program of this machine is "
              f"writing a file named {sys.argv[2]} through MPI-IO, the "
              f"semaphore is a stale one: remove /dev/shm/sem.OMPIO_"
              f"{sys.argv[2]} and run the test again.", file=sys.stderr)
        sys.exit(2 if error == 17 else 1)
else:
    held = libc.sem_open(name, 0)
    if held not in (None, 0):
        libc.sem_post(ctypes.c_void_p(held))
        libc.sem_close(ctypes.c_void_p(held))
if action != "make" and libc.sem_unlink(name) != 0:
    print(f"hold_semaphore.py: cannot remove {name.decode()}: "
          f"{os.strerror(ctypes.get_errno())}", file=sys.stderr)
    sys.exit(1)
