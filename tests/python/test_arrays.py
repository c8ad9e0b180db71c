"""The module's array contract: dtypes, shapes, broadcasting, copies, out=, errors, the GIL."""

import threading
import time

import numpy as np
import pytest

import irid


def test_dtype_and_shape_are_kept():
    for shape in [(3,), (7, 3), (2, 5, 3), (0, 3)]:
        a = np.full(shape, 0.25)
        for dtype in [np.float32, np.float64]:
            r = irid.clip(a.astype(dtype), "smits")
            assert r.shape == shape and r.dtype == dtype
            c = irid.convert(a.astype(dtype), "srgb-linear", "oklab")
            assert c.shape == shape and c.dtype == dtype
    # Other dtypes and lists are taken as float64.
    assert irid.clip(np.ones((4, 3), dtype=np.int32), "smits").dtype == np.float64
    assert irid.clip([[2, 0, 0]], "smits").dtype == np.float64


def test_broadcasting():
    a = np.random.default_rng(1).uniform(0, 100, (4, 5, 3))
    b = np.array([50.0, 0.0, 0.0])
    d = irid.delta_e(a, b, "cie76")
    assert d.shape == (4, 5)
    np.testing.assert_allclose(d, np.linalg.norm(a - b, axis=-1))
    with pytest.raises(ValueError, match="broadcast"):
        irid.delta_e(np.zeros((4, 3)), np.zeros((5, 3)))


def test_non_contiguous_inputs():
    big = np.random.default_rng(2).uniform(-0.5, 1.5, (1000, 6)).astype(np.float32)
    view = big[:, 1:4]
    assert not view.flags.c_contiguous
    np.testing.assert_array_equal(irid.clip(view, "oklab"), irid.clip(view.copy(), "oklab"))
    strided = big[::3, :3]
    np.testing.assert_array_equal(irid.convert(strided, "srgb-linear", "xyz"),
                                  irid.convert(np.ascontiguousarray(strided), "srgb-linear", "xyz"))


def test_out_writes_in_place():
    a = np.random.default_rng(3).uniform(-0.5, 1.5, (500, 3)).astype(np.float32)
    expected = irid.clip(a, "smits")
    r = irid.clip(a, "smits", out=a)
    assert r is a or np.shares_memory(r, a)
    np.testing.assert_array_equal(a, expected)
    out = np.empty((500, 3))
    r = irid.convert(a.astype(np.float64), "srgb-linear", "lab", out=out)
    assert np.shares_memory(r, out)
    np.testing.assert_array_equal(out, irid.convert(a.astype(np.float64), "srgb-linear", "lab"))


def test_out_is_checked():
    a = np.zeros((10, 3), dtype=np.float32)
    with pytest.raises(ValueError, match="dtype"):
        irid.clip(a, "smits", out=np.zeros((10, 3)))
    with pytest.raises(ValueError, match="shape"):
        irid.clip(a, "smits", out=np.zeros((9, 3), dtype=np.float32))
    ro = np.zeros((10, 3), dtype=np.float32)
    ro.flags.writeable = False
    with pytest.raises(ValueError, match="read-only"):
        irid.clip(a, "smits", out=ro)
    with pytest.raises(ValueError, match="contiguous"):
        irid.clip(a[::2], "smits", out=np.zeros((10, 3), dtype=np.float32)[::2])
    overlap = np.zeros(33, dtype=np.float32)
    with pytest.raises(ValueError, match="overlap"):
        irid.clip(overlap[:30].reshape(10, 3), "smits", out=overlap[3:33].reshape(10, 3))


def test_errors_raise_the_documented_exceptions():
    a = np.zeros((2, 3))
    for call in [lambda: irid.clip(a, "nope"),
                 lambda: irid.clip(a, "smits", source="nope"),
                 lambda: irid.clip(a, "aces-rgc", bogus=1.0),
                 lambda: irid.convert(a, "srgb", "lab", white="D99"),
                 lambda: irid.convert(a, "srgb", "lab", adaptation="nope"),
                 lambda: irid.delta_e(a, a, "nope"),
                 lambda: irid.cmfs("nope"),
                 lambda: irid.illuminant("F2")]:
        with pytest.raises(KeyError):
            call()
    with pytest.raises(KeyError, match="smits-soft"):    # lists the valid names
        irid.clip(a, "smits_soft")
    for call in [lambda: irid.clip(np.zeros((2, 4)), "smits"),
                 lambda: irid.clip("text", "smits"),
                 lambda: irid.clip(a, "smits", max=0.0),
                 lambda: irid.clip(a, "smits", max=float("nan")),
                 lambda: irid.clip(a, "smits", threads=-1),
                 lambda: irid.clip(a, "smits", inverse=True),
                 lambda: irid.clip(a, "smits", target="lab"),
                 lambda: irid.clip(a, "aces-rgc", power=0.5),
                 lambda: irid.clip(a, "aces-rgc", power="x"),
                 lambda: irid.convert([[0.3, 0.0, 1.0]], "xyy", "xyz"),
                 lambda: irid.convert(a, "srgb", "lab", white=(0.9, 0.9)),
                 lambda: irid.convert(a, "srgb", "lab", white=(0.3, 0.01)),   # below the purple line
                 lambda: irid.clip(a, "oklab", white=(0.5, 1e-300)),
                 lambda: irid.blackbody(-5.0),
                 lambda: irid.illuminant("D", cct=100.0)]:
        with pytest.raises(ValueError):
            call()


def test_non_finite_values_follow_the_library_rule():
    # NaN is taken as 0 and ±Inf as ±1e30 (clip.h), and every output is finite.
    a = np.array([[np.nan, 0.5, 0.5], [np.inf, 0.0, 0.0], [-np.inf, 1.0, 1.0]], dtype=np.float32)
    for method in irid.clip_methods():
        out = irid.clip(a, method, clip=True) if method == "aces-rgc" else irid.clip(a, method)
        assert np.all(np.isfinite(out)), method


def test_clip_releases_the_gil():
    # Thread A clips a large array; thread B, started once A is inside the call, clips a small
    # one. With the GIL released B runs during A's call and finishes first; were the GIL held,
    # B could not start before A returned.
    big = np.random.default_rng(4).uniform(-0.5, 1.5, (1 << 21, 3))
    small = big[:1000].copy()
    times = {}
    started = threading.Event()

    def a():
        started.set()
        irid.clip(big, "css", threads=1)
        times["a"] = time.perf_counter()

    def b():
        started.wait()
        time.sleep(0.01)  # A is in the library by now
        irid.clip(small, "css", threads=1)
        times["b"] = time.perf_counter()

    ta, tb = threading.Thread(target=a), threading.Thread(target=b)
    ta.start()
    tb.start()
    ta.join()
    tb.join()
    assert times["b"] < times["a"]


def test_dtypes_that_are_equal_but_not_identical():
    # An array back from pickle (multiprocessing, Dask) has an equal but distinct dtype object;
    # a big-endian float32 is float32 too.
    import pickle
    a = pickle.loads(pickle.dumps(np.full((4, 3), 0.5, dtype=np.float32)))
    assert irid.clip(a, "smits").dtype == np.float32
    r = irid.clip(a, "smits", out=a)
    assert np.shares_memory(r, a)
    assert irid.clip(np.zeros((2, 3), dtype=">f4"), "smits").dtype == np.float32
    b = pickle.loads(pickle.dumps(np.zeros((4, 3))))
    assert np.shares_memory(irid.convert(b, "xyz", "lab", out=b), b)


def test_refusals_of_non_numbers_and_bad_arguments():
    for bad in [np.array([[None, 2, 3]], dtype=object), np.array(["1", "2", "3"]),
                np.zeros((2, 3), dtype=complex), np.zeros((2, 3), dtype="datetime64[s]")]:
        with pytest.raises(ValueError, match="number"):
            irid.clip(bad, "smits")
        with pytest.raises(ValueError, match="number"):
            irid.convert(bad, "xyz", "lab")
    a = np.zeros((4, 3))
    with pytest.raises(ValueError):
        irid.clip(a, ["smits"])
    with pytest.raises(ValueError):
        irid.clip(a, "smits", threads=2**40)
    with pytest.raises(ValueError):
        irid.clip(a, "smits-soft", inverse="False")
    with pytest.raises(ValueError):
        irid.illuminant(None, cct=5000)
    with pytest.raises(KeyError, match="smits-soft"):     # the whole message, NUL escaped
        irid.clip(a, "smits\0junk")
    overlap = np.random.default_rng(0).uniform(0, 1, 33)
    with pytest.raises(ValueError, match="overlap"):
        irid.convert(overlap[:30].reshape(10, 3), "xyz", "srgb-linear",
                     out=overlap[3:33].reshape(10, 3))


def test_masked_arrays_are_refused_not_unmasked(tmp_path):
    """A numpy.ma array would lose its mask in any call: each entry point refuses it."""
    a = np.ma.masked_array(np.full((4, 3), 0.5), mask=[[0, 0, 0], [1, 0, 0], [0, 0, 0], [0, 0, 0]])
    calls = [lambda: irid.clip(a, "smits"), lambda: irid.convert(a, "srgb-linear", "oklab"),
             lambda: irid.delta_e(a, a), lambda: irid.write_image(tmp_path / "m.exr", a.reshape(2, 2, 3)),
             lambda: irid.clip_image(a.reshape(2, 2, 3), ["R", "G", "B"], "smits"),
             lambda: irid.Film.exact([("water", 100)]).reflectance(np.ma.masked_array([500.0], mask=[1]))]
    for call in calls:
        with pytest.raises(ValueError, match="masked"):
            call()
    # Its data, as the message says, is accepted.
    assert irid.clip(a.data, "smits").shape == (4, 3)


def test_every_public_name_is_documented_and_stubbed():
    """Every name in irid.__all__ has a docstring (its methods too) and a line in the .pyi."""
    import inspect
    import pathlib

    stub = (pathlib.Path(irid.__file__).parent / "__init__.pyi").read_text()
    for name in irid.__all__:
        obj = getattr(irid, name)
        assert (obj.__doc__ or "").strip(), name
        assert f"def {name}(" in stub or f"class {name}" in stub, name
        if inspect.isclass(obj):
            for attr, member in vars(obj).items():
                if attr.startswith("_") or not callable(getattr(obj, attr, None)):
                    continue
                assert (getattr(obj, attr).__doc__ or "").strip(), f"{name}.{attr}"
