"""irid inside Dask (examples/dask_clip.py): map_blocks on a LocalCluster of two worker
processes, and a folder of EXR frames clipped in parallel; both equal to the same work done in
one process."""

import importlib.util
import subprocess

import numpy as np
import pytest

import irid

from conftest import REPO

import dask.array as dask_array  # noqa: E402  (scripts/install-deps installs python3-dask)
import distributed  # noqa: E402


def load_example():
    spec = importlib.util.spec_from_file_location("dask_clip", REPO / "examples" / "dask_clip.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as c:
        yield c


def test_map_blocks_on_two_worker_processes(client):
    example = load_example()
    rng = np.random.default_rng(1)
    data = rng.uniform(-0.5, 1.5, (512, 384, 3)).astype(np.float32)
    array = dask_array.from_array(data, chunks=(128, 128, 3))
    clipped = example.clip_array(array, "css-raytrace", source="display-p3-linear")
    result = client.compute(clipped).result()
    assert result.dtype == np.float32 and result.shape == data.shape
    np.testing.assert_array_equal(result, irid.clip(data, "css-raytrace", source="display-p3-linear"))
    # The work ran in the two worker processes, not here.
    workers = client.run(lambda: __import__("os").getpid())
    assert len(set(workers.values())) == 2


def test_folder_of_frames_in_parallel(client, tmp_path, irid_cli):
    example = load_example()
    example.make_frames(tmp_path / "in", 4, height=64, width=96)
    written = example.clip_frames(client, tmp_path / "in", tmp_path / "out", "aces-rgc")
    assert [p.rsplit("/", 1)[1] for p in written] == [f"frame.{i:04d}.exr" for i in range(4)]
    for path in written:
        name = path.rsplit("/", 1)[1]
        # The same frame through the command line, in this process' own program.
        subprocess.run([irid_cli, "clip", "--method", "aces-rgc", "--from", "acescg", "--to",
                        "acescg", str(tmp_path / "in" / name), str(tmp_path / name)], check=True)
        got, meta = irid.read_image(path)
        expected, cli_meta = irid.read_image(tmp_path / name)
        assert meta["channels"] == cli_meta["channels"] == ["R", "G", "B", "A"]
        np.testing.assert_array_equal(got, expected)
        original, _ = irid.read_image(tmp_path / "in" / name)
        np.testing.assert_array_equal(got[..., 3], original[..., 3])   # alpha untouched
        # Unpremultiplied, every colour is inside the cube (aces-rgc with clip=True).
        alpha = got[..., 3:]
        colour = np.where(alpha > 0, got[..., :3] / np.where(alpha > 0, alpha, 1), 0)
        assert colour.min() >= -1e-6 and colour.max() <= 1 + 1e-6
