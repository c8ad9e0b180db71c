#!/usr/bin/env python3
"""irid inside Dask, when one machine's memory or one process is not enough.

1. A large array clipped chunk by chunk: ``dask.array.map_blocks`` of :func:`irid.clip`, on a
   ``distributed.LocalCluster`` of worker processes (irid is imported in each worker).
2. A directory of EXR frames clipped in parallel, one task per frame, each read and written
   by irid (irid_io) in the worker.

Both are checked against the same work done in this process. Run from the repository:

    PYTHONPATH=build/python python3 examples/dask_clip.py              # a demo on generated data
    PYTHONPATH=build/python python3 examples/dask_clip.py --frames IN --out OUT --method oklab-cusp

The functions are importable (tests/python/test_dask.py uses them).
"""

import argparse
import pathlib
import sys
import tempfile
import time

import numpy as np

import irid


def clip_array(array, method, **options):
    """``array`` (a dask array of shape (..., 3), its last axis in one chunk) clipped by
    ``irid.clip(block, method, **options)`` block by block; returns a dask array."""
    if array.chunks[-1] != (3,):
        array = array.rechunk({array.ndim - 1: 3})
    return array.map_blocks(irid.clip, method, dtype=array.dtype, **options)


def clip_frame(source_path, target_path, method, source="acescg", target="acescg", threads=1):
    """One EXR frame clipped as ``irid clip --method M --from SOURCE --to TARGET IN OUT`` does
    (irid.clip_image: the colour unpremultiplied by alpha, clipped, premultiplied again; other
    channels kept; aces-rgc with clip=True). Returns the target path."""
    pixels, meta = irid.read_image(source_path)
    clipped, names = irid.clip_image(pixels, meta["channels"], method, source=source,
                                     target=target, premultiplied=True, threads=threads)
    irid.write_image(target_path, clipped, channels=names, color_space=f"{target}-linear",
                     description=f"irid.clip_image method {method} from {source} to {target}")
    return str(target_path)


def clip_frames(client, source_dir, target_dir, method, **options):
    """Every *.exr of ``source_dir`` clipped into ``target_dir`` (same names), one Dask task
    per frame on ``client``; returns the written paths, sorted."""
    source_dir, target_dir = pathlib.Path(source_dir), pathlib.Path(target_dir)
    target_dir.mkdir(parents=True, exist_ok=True)
    frames = sorted(source_dir.glob("*.exr"))
    futures = [client.submit(clip_frame, str(f), str(target_dir / f.name), method, pure=False,
                             **options) for f in frames]
    return sorted(client.gather(futures))


def make_frames(folder, count, height=270, width=480, seed=1):
    """Synthetic ACEScg frames with out-of-gamut colours and an alpha channel."""
    rng = np.random.default_rng(seed)
    folder = pathlib.Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    for i in range(count):
        rgba = rng.uniform(-0.3, 1.4, (height, width, 4)).astype(np.float32)
        rgba[..., 3] = rng.uniform(0, 1, (height, width))
        irid.write_image(folder / f"frame.{i:04d}.exr", rgba, channels=["R", "G", "B", "A"],
                         color_space="acescg")


def main(argv=None):
    import dask.array as da
    from distributed import Client, LocalCluster

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--frames", help="a folder of EXR frames (default: 8 generated ones)")
    parser.add_argument("--out", help="where the clipped frames go (default: a temporary folder)")
    parser.add_argument("--method", default="aces-rgc", choices=irid.clip_methods())
    parser.add_argument("--workers", type=int, default=2)
    args = parser.parse_args(argv)

    with LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client, \
            tempfile.TemporaryDirectory() as scratch:
        # 1. An array of 16 Mcolours (201 MB of float32), 16 chunks.
        shape = (4096, 4096, 3)
        array = da.random.RandomState(2).uniform(-0.3, 1.4, size=shape, chunks=(1024, 1024, 3))
        array = array.astype(np.float32)
        start = time.perf_counter()
        clipped = clip_array(array, "oklab-cusp", source="srgb-linear")
        mean = clipped.mean(axis=(0, 1)).compute()
        print(f"array {shape}: clipped on {args.workers} workers in "
              f"{time.perf_counter() - start:.2f} s, mean RGB {mean}")
        block = array.blocks[1, 2].compute()
        assert np.array_equal(clipped.blocks[1, 2].compute(),
                              irid.clip(block, "oklab-cusp", source="srgb-linear"))

        # 2. A folder of frames.
        source = pathlib.Path(args.frames) if args.frames else pathlib.Path(scratch, "in")
        if not args.frames:
            make_frames(source, 8)
        target = pathlib.Path(args.out) if args.out else pathlib.Path(scratch, "out")
        start = time.perf_counter()
        written = clip_frames(client, source, target, args.method)
        print(f"{len(written)} frames clipped with {args.method} in "
              f"{time.perf_counter() - start:.2f} s into {target}")
        local = pathlib.Path(scratch, "local")
        local.mkdir()
        first = pathlib.Path(written[0])
        clip_frame(source / first.name, local / first.name, args.method)
        assert np.array_equal(irid.read_image(first)[0], irid.read_image(local / first.name)[0])
        print("the cluster's results equal this process' own")
    return 0


if __name__ == "__main__":
    sys.exit(main())
