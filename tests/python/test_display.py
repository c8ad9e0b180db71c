"""irid.display_transform: OpenColorIO's published ACES 2.0 outputs, arrays like irid.clip, errors."""

import csv
import os
import pathlib

import numpy as np
import pytest

import irid

DATA = pathlib.Path(__file__).resolve().parents[2] / "data" / "ocio-aces2"


def published():
    """OpenColorIO's output of ACES2065-1 (0.5, 0.4, 0.3) for each built-in display."""
    rows = []
    with open(DATA / "builtin_displays_20.csv", newline="") as f:
        for row in csv.reader(line for line in f if not line.startswith("#")):
            if row[0] == "display":
                continue
            rows.append((row[0], [float(v) for v in row[1:4]], [float(v) for v in row[4:7]]))
    return rows


def test_every_display_gives_opencolorios_published_output():
    rows = published()
    assert len(rows) == 31
    assert sorted(r[0].lower() for r in rows) == sorted(irid.display_names())
    for name, scene, xyz in rows:
        got = irid.display_transform(np.array(scene), display=name)
        assert np.allclose(got, xyz, rtol=0, atol=1e-4), name
        back = irid.display_transform(got, display=name, source="xyz", target="aces2065-1", inverse=True)
        assert np.allclose(back, scene, rtol=0, atol=1e-6), name


def test_matches_the_command_line_and_keeps_shapes_dtypes_and_out():
    rng = np.random.default_rng(3)
    scene = rng.uniform(-0.5, 16, size=(4, 5, 3))
    a = irid.display_transform(scene, display="hdr-1000nit-p3-d65", target="display-p3-linear")
    assert a.shape == (4, 5, 3) and a.dtype == np.float64
    # float32 between linear spaces goes through the float kernel: within 1e-5 of max(|value|, 1)
    # of the double result (docs/KERNELS.md).
    f = irid.display_transform(scene.astype(np.float32), display="hdr-1000nit-p3-d65",
                               target="display-p3-linear")
    assert f.dtype == np.float32
    ref = irid.display_transform(scene.astype(np.float32).astype(np.float64), display="hdr-1000nit-p3-d65",
                                 target="display-p3-linear")
    assert np.all(np.abs(f - ref) <= 1e-5 * np.maximum(np.abs(ref), 1.0))
    # An encoded target keeps the double path: the double result rounded.
    f = irid.display_transform(scene.astype(np.float32), display="hdr-1000nit-p3-d65", target="display-p3")
    ref = irid.display_transform(scene.astype(np.float32).astype(np.float64), display="hdr-1000nit-p3-d65",
                                 target="display-p3")
    assert np.array_equal(f, ref.astype(np.float32))
    # Any thread count gives the same bits, and out= may be the input.
    one = irid.display_transform(scene, display="hdr-1000nit-p3-d65", threads=1)
    buf = scene.copy()
    res = irid.display_transform(buf, display="hdr-1000nit-p3-d65", out=buf, threads=4)
    assert res is buf and np.array_equal(buf, one)
    assert np.all(np.isfinite(irid.display_transform([[np.nan, np.inf, -np.inf]], display="sdr-100nit-rec709")))


def test_names_and_values_are_checked():
    with pytest.raises(KeyError):
        irid.display_transform([0.1, 0.2, 0.3], display="hdr-9000nit")
    with pytest.raises(KeyError):
        irid.display_transform([0.1, 0.2, 0.3], view="aces1", display="sdr-100nit-rec709")
    with pytest.raises(KeyError):
        irid.display_transform([0.1, 0.2, 0.3], display="sdr-100nit-rec709", target="nonsense")
    with pytest.raises(ValueError):
        irid.display_transform([0.1, 0.2, 0.3], display="sdr-100nit-rec709", target="lab")
    with pytest.raises(ValueError):
        irid.display_transform([0.1, 0.2, 0.3])
    with pytest.raises(ValueError):
        irid.display_transform([0.1, 0.2], display="sdr-100nit-rec709")
    with pytest.raises(ValueError):
        irid.display_transform([0.1, 0.2, 0.3], display="sdr-100nit-rec709", threads=-1)


def test_space_names_are_taken_in_any_case():
    # As display names are (issue 37, item 9): the library's lookup, for every function that
    # names a space; the default target of clip is the source's space in any case too.
    rgb = np.array([[0.5, 0.4, 0.3], [1.2, 0.1, -0.05]])
    assert np.array_equal(irid.convert(rgb, "SRGB", "OkLab"), irid.convert(rgb, "srgb", "oklab"))
    assert np.array_equal(irid.display_transform(rgb, display="SDR-100nit-P3-D65", target="Display-P3"),
                          irid.display_transform(rgb, display="sdr-100nit-p3-d65", target="display-p3"))
    assert np.array_equal(irid.display_transform(rgb, display="hdr-1000nit-rec2020", source="ACEScg",
                                                 target="Rec2100-PQ"),
                          irid.display_transform(rgb, display="hdr-1000nit-rec2020", source="acescg",
                                                 target="rec2100-pq"))
    assert np.array_equal(irid.clip(rgb, "smits", source="SRGB"), irid.clip(rgb, "smits", source="srgb"))
    # The view's name too (found by review).
    assert np.array_equal(irid.display_transform(rgb, view="ACES2", display="sdr-100nit-rec709"),
                          irid.display_transform(rgb, view="aces2", display="sdr-100nit-rec709"))
    with pytest.raises(KeyError, match="known: aces2"):
        irid.display_transform(rgb, view="aces2x", display="sdr-100nit-rec709")
    with pytest.raises(KeyError, match="srgb, srgb-linear"):
        irid.convert(rgb, "SRGBX", "xyz")


def test_a_scene_value_exists_exactly_where_the_round_trip_holds():
    # The cube of a 1000 cd/m² Rec.2020 display: its ramps to the primaries, near white and
    # random points. has_scene_value at a tolerance is true exactly where the round trip (the
    # forward of the inverse) comes back within it, of the peak in the display's RGB.
    rng = np.random.default_rng(37)
    peak = 10.0
    ramps = np.concatenate([np.outer(2.0 ** np.linspace(-12, 0, 40), c) for c in np.eye(3)])
    near_white = peak * (1 - 1e-3 * rng.random((300, 3)))
    rgb = np.concatenate([ramps * peak, near_white, peak * rng.random((300, 3))])
    display = "hdr-1000nit-rec2020"
    scene = irid.display_transform(rgb, display=display, source="rec2020-linear", target="aces2065-1",
                                   inverse=True)
    back = irid.display_transform(scene, display=display, target="rec2020-linear")
    miss = np.abs(back - rgb).max(axis=-1) / peak
    for tolerance in (1e-10, 1e-5):
        exists = irid.display_has_scene_value(rgb, display=display, source="rec2020-linear",
                                              tolerance=tolerance)
        assert exists.shape == (len(rgb),) and exists.dtype == bool
        assert 0 < exists.sum() < len(rgb)
        assert np.array_equal(exists, miss <= tolerance)


def test_a_colour_the_display_shows_counts_as_shown_after_float_rounding():
    # The display's output of scene colours, rounded to float32 (as a file or a GPU holds it):
    # by default each counts as shown, though most lie a rounding step outside what the chain
    # gives; at a tolerance of 0 only those inside count.
    rng = np.random.default_rng(5)
    scene = rng.uniform(-0.5, 64.0, (2000, 3))
    shown = irid.display_transform(scene, display="sdr-100nit-rec709").astype(np.float32)
    assert irid.display_has_scene_value(shown, display="sdr-100nit-rec709").all()
    assert not irid.display_has_scene_value(shown, display="sdr-100nit-rec709", tolerance=0.0).all()


def test_scene_values_are_asked_of_display_colours():
    with pytest.raises(ValueError, match="expected"):
        irid.display_has_scene_value([1.0, 2.0], display="sdr-100nit-rec709")
    with pytest.raises(ValueError, match="threads"):
        irid.display_has_scene_value([1.0, 2.0, 3.0], display="sdr-100nit-rec709", threads=-1)
    with pytest.raises(KeyError):
        irid.display_has_scene_value([1.0, 2.0, 3.0], display="no-such-display")
    with pytest.raises(ValueError, match="display"):
        irid.display_has_scene_value([1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="tolerance"):
        irid.display_has_scene_value([1.0, 2.0, 3.0], display="sdr-100nit-rec709", tolerance=-1.0)
