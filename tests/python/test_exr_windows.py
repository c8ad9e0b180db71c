"""OpenEXR's data and display windows survive irid (docs/RELIABILITY.md): read_image reports
them, write_image writes them, and ``irid clip`` and ``irid display`` keep them, as OpenEXR's own
``exrheader`` reads them back. A format without windows gets a note that they are dropped."""

import re
import shutil
import subprocess

import numpy as np
import pytest

import irid

EXRHEADER = shutil.which("exrheader")   # openexr (scripts/install-deps)


def exr_windows(path):
    """(data window, display window) as exrheader prints them."""
    assert EXRHEADER, "exrheader is missing (scripts/install-deps installs openexr)"
    out = subprocess.run([EXRHEADER, str(path)], capture_output=True, text=True, check=True).stdout
    boxes = {}
    for name in ("dataWindow", "displayWindow"):
        m = re.search(name + r" \(type box2i\): \((-?\d+) (-?\d+)\) - \((-?\d+) (-?\d+)\)", out)
        boxes[name] = tuple(int(v) for v in m.groups())
    return boxes["dataWindow"], boxes["displayWindow"]


CASES = [((100, 50, 107, 53), (0, 0, 1919, 1079)),      # a crop of an HD frame
         ((-16, -8, -9, -5), (0, 0, 63, 31)),           # overscan, left of and above the frame
         ((0, 0, 7, 3), (0, 0, 7, 3))]                  # no windows to speak of


@pytest.mark.parametrize("data,display", CASES)
def test_windows_survive_write_read_clip_and_display(irid_cli, tmp_path, data, display):
    px = np.random.default_rng(1).random((4, 8, 3)).astype(np.float32)
    src = tmp_path / "crop.exr"
    irid.write_image(src, px, color_space="acescg-linear", data_window=data, display_window=display)
    assert exr_windows(src) == (data, display)
    _, meta = irid.read_image(src)
    assert (meta["data_window"], meta["display_window"]) == (data, display)
    for command in (["clip", "--method", "clamp"],
                    ["display", "--view", "aces2", "--display", "sdr-100nit-rec709"]):
        out = tmp_path / f"{command[0]}.exr"
        r = subprocess.run([irid_cli, *command, str(src), str(out)], capture_output=True, text=True)
        assert r.returncode == 0 and "window" not in r.stderr, r.stderr
        assert exr_windows(out) == (data, display), command
        png = tmp_path / f"{command[0]}.png"
        r = subprocess.run([irid_cli, *command, str(src), str(png)], capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        assert ("not kept in PNG" in r.stderr) == (data != (0, 0, 7, 3)), r.stderr


def test_files_without_windows_report_their_own_box(tmp_path):
    irid.write_image(tmp_path / "a.png", np.zeros((3, 5, 3), np.float32))
    _, meta = irid.read_image(tmp_path / "a.png")
    assert meta["data_window"] == (0, 0, 4, 2) and meta["display_window"] == (0, 0, 4, 2)


@pytest.mark.parametrize("kw,reason", [
    ({"data_window": (0, 0, 8, 3)}, "is 9 x 4 pixels; the image is 8 x 4"),
    ({"display_window": (5, 0, 4, 3)}, "x min <= x max"),
    ({"data_window": (2**30, 0, 2**30 + 7, 3)}, "corners lie within"),
    ({"display_window": (0, 0, 7)}, "not 4 whole numbers"),
    ({"display_window": (0, 0, 7.5, 3)}, "not 4 whole numbers"),
])
def test_windows_openexr_cannot_hold_are_refused(tmp_path, kw, reason):
    with pytest.raises(ValueError, match=reason):
        irid.write_image(tmp_path / "x.exr", np.zeros((4, 8, 3), np.float32), **kw)
    assert not (tmp_path / "x.exr").exists()


def test_windows_go_to_exr_only(tmp_path):
    with pytest.raises(ValueError, match="only EXR files carry windows"):
        irid.write_image(tmp_path / "x.png", np.zeros((4, 8, 3), np.float32), data_window=(1, 1, 8, 4))
