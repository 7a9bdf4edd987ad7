"""Grading a student's notebook where it cannot reach the instructor's files: bubblewrap (``bwrap``).

``toolkit grade`` runs code the instructor has never read. :func:`command` wraps the process that
runs a submission's notebook (:mod:`~toolkit.teaching.submission`) in a bubblewrap sandbox that sees
only the system's programs and libraries, the Python installation, the toolkit package (read-only,
without the repository around it: no masters, no solutions, no test suite; the grader lays copies
without the assignment's answers over the modules that hold them), the submission (read-only;
never its tests, which run outside) and a private ``/tmp``; it has no network (its own network
namespace, loopback only), its own process and IPC namespaces, and runs as an unprivileged user
of its own (a distinct uid per running sandbox) under limits on processes, open files, file
sizes and CPU time. Everything in it dies with it. bubblewrap comes from Debian's
``bubblewrap`` package (``make sandbox``). Where it cannot run, :func:`unavailable` says why.
"""

from __future__ import annotations

import functools
import itertools
import os
import shutil
import subprocess
import sys
import threading
from pathlib import Path

import toolkit

PROCESSES = 256  # processes a sandbox's user may run: a fork bomb stops here
OPEN_FILES = 1024
FILE_BYTES = 2**30  # the largest file it may write
MEMORY_BYTES = 8 * 2**30  # its address space: a submission that hoards memory fails, not the machine grading it
TMP_BYTES = 2 * 2**30  # its private /tmp (memory-backed)
PRIVATE_TMP = ("--size", str(TMP_BYTES), "--perms", "1777", "--tmpfs", "/tmp")  # bubblewrap: an empty /tmp of its own
FIRST_UID, UIDS = 61_000, 1_000  # each running sandbox gets its own uid (process limits are per uid)
LIBRARY = "/grading/lib"  # where the toolkit package appears inside
_uids = itertools.count()
_lock = threading.Lock()


def _system_paths() -> list[str]:
    """The system's programs and libraries (read-only), as they exist here."""
    system = (
        "/usr",
        "/bin",
        "/sbin",
        "/lib",
        "/lib32",
        "/lib64",
        "/etc/alternatives",
        "/etc/hosts",
        "/etc/nsswitch.conf",
    )
    return [p for p in system if os.path.exists(p)]  # /etc/hosts: the kernel's loopback "localhost"


def _directories(paths: list[str]) -> list[str]:
    """``--dir`` arguments that create every ancestor of ``paths`` traversable (bwrap would make them 0700)."""
    ancestors = sorted({str(parent) for p in paths for parent in Path(p).parents if str(parent) != "/"}, key=len)
    return [arg for a in ancestors for arg in ("--perms", "0755", "--dir", a)]


def command(inner: list[str], read_only: dict[str, str], writable: dict[str, str], cpu_s: float) -> list[str]:
    """``inner`` (a command line, paths as the sandbox sees them) wrapped in bubblewrap: ``read_only`` and
    ``writable`` map host paths to where they appear inside; ``cpu_s`` caps its CPU seconds."""
    with _lock:
        uid = FIRST_UID + next(_uids) % UIDS
    binds = {p: p for p in _system_paths() if not os.path.islink(p)}
    binds |= {
        sys.base_prefix: sys.base_prefix,
        sys.prefix: sys.prefix,
        str(Path(toolkit.__file__).parent): f"{LIBRARY}/toolkit",
    }
    binds |= read_only
    links = [arg for p in _system_paths() if os.path.islink(p) for arg in ("--symlink", os.readlink(p), p)]
    mounts = [arg for host, inside in binds.items() for arg in ("--ro-bind", host, inside)]
    mounts += [arg for host, inside in writable.items() for arg in ("--bind", host, inside)]
    env = {
        "PATH": f"{sys.prefix}/bin:/usr/bin:/bin",
        "HOME": "/tmp",
        "PYTHONPATH": LIBRARY,
        "LANG": "C.UTF-8",
        "MPLBACKEND": "Agg",
        "OMP_NUM_THREADS": "1",  # one core a submission: several are graded at once
        "MKL_NUM_THREADS": "1",
    }
    return [
        "bwrap",
        "--unshare-pid",
        "--unshare-net",
        "--unshare-ipc",
        "--unshare-uts",
        "--die-with-parent",
        "--new-session",
        "--clearenv",
        *[arg for key, value in env.items() for arg in ("--setenv", key, value)],
        *PRIVATE_TMP,  # first: the binds below may lie under /tmp (a clone's venv) and must stay visible
        *_directories([*binds.values(), *writable.values()]),
        *links,
        *mounts,
        "--proc",
        "/proc",
        "--dev",
        "/dev",
        "--chdir",
        "/tmp",
        "--",
        *_unprivileged(uid, cpu_s),
        *inner,
    ]


def _unprivileged(uid: int, cpu_s: float) -> list[str]:
    """The command line prefix that drops to ``uid`` (no capabilities) under the sandbox's limits."""
    user = ["setpriv", f"--reuid={uid}", f"--regid={uid}", "--clear-groups", "--inh-caps=-all", "--bounding-set=-all"]
    limits = [f"--nproc={PROCESSES}", f"--nofile={OPEN_FILES}", f"--fsize={FILE_BYTES}", f"--as={MEMORY_BYTES}"]
    limits.append(f"--cpu={max(1, int(cpu_s))}")
    return [*user, "--", "prlimit", *limits, "--"]


@functools.cache
def unavailable() -> str | None:
    """Why submissions cannot be isolated here (None: they can): bubblewrap missing, or not allowed to run."""
    for program in ("bwrap", "setpriv", "prlimit"):
        if shutil.which(program) is None:
            package = "bubblewrap" if program == "bwrap" else "util-linux"
            return f"{program} is not installed (Debian package {package}; `make sandbox` installs it)"
    trial = subprocess.run(
        command([sys.executable, "-c", "import toolkit"], {}, {}, cpu_s=60), capture_output=True, text=True
    )
    if trial.returncode != 0:
        return f"bubblewrap cannot run here: {(trial.stderr.strip().splitlines() or ['no message'])[-1]}"
    return None


class CannotIsolate(OSError):
    """Submissions cannot be isolated on this machine (:func:`unavailable` says why): grading refuses to run them."""


def require() -> None:
    """Raise :class:`CannotIsolate` where submissions cannot be isolated (a one-line error at the command line)."""
    if why := unavailable():
        raise CannotIsolate(f"cannot isolate the submissions: {why}; grade without isolation only if you trust them")
