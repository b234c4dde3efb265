"""Let glibc serve large arrays from the heap (a process-wide setting for the CLI).

glibc gives every allocation above its mmap threshold (128 kB, rising to at most 32 MB
as blocks are freed) a memory map of its own and unmaps it on free, so in a long
vectorised computation each new array faults all its pages in again. With the threshold
at 1 GiB, freed blocks stay in the heap and the next arrays reuse them. Setting the mmap
threshold switches glibc's automatic tuning off, which also leaves the trim threshold at
128 kB: every free at the top of the heap would then hand the memory back to the system and
the next call fault it in again, so the trim threshold is raised to the same 1 GiB.
Measured on the shaper's core pipeline at 1,000,000 crank positions (2-core machine):
2.0 s → 0.8 s, the same peak memory (benchmarks/bench_shaper.py); repeated 100,000-point
calls with neither, the mmap threshold alone and both: benchmarks/bench_allocator.py. `mechdesign run` and `batch` set it at start;
a program importing mechdesign as a library may call :func:`prefer_heap` itself.
"""
from __future__ import annotations

import ctypes
import sys

M_TRIM_THRESHOLD = -1   # glibc's mallopt parameter numbers
M_MMAP_THRESHOLD = -3
HEAP_UP_TO = 1 << 30    # [bytes]


def prefer_heap(trim: bool = True) -> bool:
    """Raise glibc's mmap threshold (and, with ``trim``, its trim threshold) to 1 GiB;
    True when it took effect (glibc on Linux), False elsewhere (macOS, Windows, musl),
    where nothing changes. ``trim=False`` is for the benchmark's comparison only."""
    if not sys.platform.startswith("linux"):
        return False
    try:
        mallopt = ctypes.CDLL(None).mallopt
    except (OSError, AttributeError):
        return False
    mallopt.argtypes = (ctypes.c_int, ctypes.c_int)
    mallopt.restype = ctypes.c_int
    ok = mallopt(M_MMAP_THRESHOLD, HEAP_UP_TO) == 1
    if ok and trim:
        ok = mallopt(M_TRIM_THRESHOLD, HEAP_UP_TO) == 1
    return ok
