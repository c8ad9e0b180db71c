"""irid inside Dask (examples/dask_clip.py): map_blocks on a LocalCluster of two worker
processes, and a folder of EXR frames clipped in parallel; both equal to the same work done in
one process."""

import importlib.util

import numpy as np
import pytest

import irid

from conftest import REPO

dask_array = pytest.importorskip("dask.array")
distributed = pytest.importorskip("distributed")


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


def test_folder_of_frames_in_parallel(client, tmp_path):
    example = load_example()
    example.make_frames(tmp_path / "in", 4, height=64, width=96)
    written = example.clip_frames(client, tmp_path / "in", tmp_path / "out", "aces-rgc")
    assert [p.rsplit("/", 1)[1] for p in written] == [f"frame.{i:04d}.exr" for i in range(4)]
    for path in written:
        name = path.rsplit("/", 1)[1]
        example.clip_frame(tmp_path / "in" / name, tmp_path / name, "aces-rgc")
        got, meta = irid.read_image(path)
        expected, _ = irid.read_image(tmp_path / name)
        assert meta["channels"] == ["R", "G", "B", "A"]
        np.testing.assert_array_equal(got, expected)
        original, _ = irid.read_image(tmp_path / "in" / name)
        np.testing.assert_array_equal(got[..., 3], original[..., 3])   # alpha untouched
        assert not np.array_equal(got[..., :3], original[..., :3])
