#!/usr/bin/env python3
"""Speed of the Python module beside its baselines, in one run (docs/PERFORMANCE.md).

Debian 12 has no Python binding of Google Benchmark; each row is the best of several timed
repetitions (time.perf_counter), the baseline measured in the same process right beside it.

    PYTHONPATH=build/python python3 bench/python_bench.py [--quick]

1. irid.clip(a, "smits") on a 4096×4096×3 float32 array (201 MB, larger than four times a
   32 MiB L3) beside np.clip(a, 0, 1, out=b), a memory-bound floor: both read a and write b.
2. irid.convert srgb-linear → oklab beside the same conversion in plain numpy (Ottosson's
   matrices, np.cbrt), on 4 Mcolours of float64 and of float32.
3. The call overhead on one colour: irid.clip and irid.convert of a (3,) array.
"""

import argparse
import platform
import time
import timeit

import numpy as np

import irid

# Ottosson 2020, "A perceptual color space for image processing": linear sRGB → LMS (M1 for
# sRGB) and LMS' → Oklab (M2).
M1 = np.array([[0.4122214708, 0.5363325363, 0.0514459929],
               [0.2119034982, 0.6806995451, 0.1073969566],
               [0.0883024619, 0.2817188376, 0.6299787005]])
M2 = np.array([[0.2104542553, 0.7936177850, -0.0040720468],
               [1.9779984951, -2.4285922050, 0.4505937099],
               [0.0259040371, 0.7827717662, -0.8086757660]])


def numpy_oklab(rgb):
    return np.cbrt(rgb @ M1.T) @ M2.T


def best(f, repeat):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        f()
        times.append(time.perf_counter() - start)
    return min(times)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--quick", action="store_true", help="fewer repetitions")
    args = parser.parse_args()
    repeat = 3 if args.quick else 7
    print(f"irid {irid.__version__}, numpy {np.__version__}, Python {platform.python_version()}, "
          f"SIMD target {irid.simd_target()}")

    rng = np.random.default_rng(1)
    a = rng.uniform(-0.5, 1.5, (4096, 4096, 3)).astype(np.float32)
    b = np.empty_like(a)
    n = a.size // 3
    print(f"\n1. clip of {a.shape} float32 ({a.nbytes / 1e6:.0f} MB), read a, write b")
    rows = [("np.clip(a, 0, 1, out=b)", lambda: np.clip(a, 0, 1, out=b))]
    for threads in (1, 2):
        rows.append((f"irid.clip(a, 'smits', threads={threads}, out=b)",
                     lambda t=threads: irid.clip(a, "smits", threads=t, out=b)))
    base = None
    for name, f in rows:
        t = best(f, repeat)
        base = base or t
        print(f"  {name:48s} {t * 1e3:8.1f} ms  {n / t / 1e6:7.0f} M colours/s  "
              f"{t / base:5.2f}x np.clip")

    print("\n2. convert srgb-linear → oklab, 4 Mcolours (96 MB of float64: beyond the L3)")
    for dtype in (np.float64, np.float32):
        c = rng.uniform(0, 1, (1 << 22, 3)).astype(dtype)
        o = np.empty_like(c)
        t_copy = best(lambda: np.copyto(o, c), repeat)
        t_np = best(lambda: numpy_oklab(c), repeat)
        t_new = best(lambda: irid.convert(c, "srgb-linear", "oklab"), repeat)
        t_out = best(lambda: irid.convert(c, "srgb-linear", "oklab", out=o), repeat)
        diff = np.abs(numpy_oklab(c) - irid.convert(c, "srgb-linear", "oklab")).max()
        print(f"  {np.dtype(dtype).name}: np.copyto {t_copy * 1e3:6.1f} ms, numpy {t_np * 1e3:6.1f} ms, "
              f"irid {t_new * 1e3:6.1f} ms ({t_np / t_new:4.1f}x faster), irid out= "
              f"{t_out * 1e3:6.1f} ms ({t_np / t_out:4.1f}x faster); largest difference {diff:.1e}")
    print("  (a new result array costs its first touch of every page; numpy's three arrays too)")

    print("\n3. one colour")
    one = np.array([1.2, -0.1, 0.5])
    one32 = one.astype(np.float32)
    for name, stmt in [("irid.clip(float64 (3,), 'smits')", lambda: irid.clip(one, "smits")),
                       ("irid.clip(float32 (3,), 'smits')", lambda: irid.clip(one32, "smits")),
                       ("irid.clip(float64 (3,), 'oklab-cusp')",
                        lambda: irid.clip(one, "oklab-cusp")),
                       ("irid.convert(float64 (3,), srgb → oklab)",
                        lambda: irid.convert(one, "srgb", "oklab")),
                       ("np.clip(float64 (3,), 0, 1)", lambda: np.clip(one, 0, 1))]:
        number = 20000
        t = min(timeit.repeat(stmt, number=number, repeat=repeat)) / number
        print(f"  {name:44s} {t * 1e6:6.2f} µs per call")


if __name__ == "__main__":
    main()
