"""Images from Python through irid_io: round trips, an independent reader (PIL), metadata and
the refusals (OSError for files, ValueError for arrays)."""

import os
import socket
import stat

import numpy as np
import pytest

import irid


def test_exr_round_trip_is_exact(tmp_path):
    rng = np.random.default_rng(1)
    a = rng.uniform(-2, 5, (13, 17, 4)).astype(np.float32)
    irid.write_image(tmp_path / "a.exr", a, color_space="acescg", description="test")
    b, meta = irid.read_image(tmp_path / "a.exr")
    assert b.dtype == np.float32 and b.shape == (13, 17, 4)
    np.testing.assert_array_equal(b, a)
    assert meta["channels"] == ["R", "G", "B", "A"]
    assert meta["color_space"] == "acescg"
    assert meta["bits"] == 32 and not meta["integer"]
    for name in [str(tmp_path / "a.exr"), os.fsencode(tmp_path / "a.exr")]:   # str, bytes
        one, meta = irid.read_image(name)
        np.testing.assert_array_equal(one, a)


def test_png_matches_an_independent_reader(tmp_path):
    import PIL.Image as pil  # scripts/install-deps installs python3-pil
    rng = np.random.default_rng(2)
    a = rng.uniform(0, 1, (9, 11, 3))
    irid.write_image(tmp_path / "a.png", a, bits=8)
    with pil.open(tmp_path / "a.png") as im:
        assert im.mode == "RGB" and im.size == (11, 9)
        pixels = np.asarray(im)
    # 8-bit samples are round(v × 255) (docs/RELIABILITY.md, irid/io/image.h).
    np.testing.assert_array_equal(pixels, np.round(a.astype(np.float32) * 255).astype(np.uint8))
    back, meta = irid.read_image(tmp_path / "a.png")
    assert meta["integer"] and meta["bits"] == 8
    np.testing.assert_allclose(back, pixels / 255.0, atol=1e-7)


def test_sixteen_bit_tiff_and_grey(tmp_path):
    a = np.linspace(0, 1, 64, dtype=np.float32).reshape(8, 8)
    irid.write_image(tmp_path / "g.tif", a, bits=16)
    back, meta = irid.read_image(tmp_path / "g.tif")
    assert back.shape == (8, 8, 1) and meta["bits"] == 16
    np.testing.assert_allclose(back[..., 0], np.round(a * 65535) / 65535, atol=1e-7)


def test_refusals(tmp_path):
    with pytest.raises(OSError, match="no such file"):
        irid.read_image(tmp_path / "missing.exr")
    (tmp_path / "bad.png").write_bytes(b"not a png at all")
    with pytest.raises(OSError):
        irid.read_image(tmp_path / "bad.png")
    with pytest.raises(OSError):
        irid.read_image(tmp_path)                       # a folder
    a = np.zeros((4, 4, 3), dtype=np.float32)
    with pytest.raises(OSError, match="extension"):
        irid.write_image(tmp_path / "a.bmp", a)
    # What is neither a regular file nor a stream (a character device, a FIFO) is never
    # replaced: a folder, a socket.
    (tmp_path / "dir.exr").mkdir()
    with pytest.raises(OSError, match="directory"):
        irid.write_image(tmp_path / "dir.exr", a)
    assert (tmp_path / "dir.exr").is_dir()
    with socket.socket(socket.AF_UNIX) as s:
        s.bind(str(tmp_path / "sock.exr"))
        with pytest.raises(OSError, match="socket"):
            irid.write_image(tmp_path / "sock.exr", a)
        assert stat.S_ISSOCK(os.stat(tmp_path / "sock.exr").st_mode)
    for bad in [np.zeros((4,)), np.zeros((0, 4, 3)), "text"]:
        with pytest.raises(ValueError):
            irid.write_image(tmp_path / "x.exr", bad)
    with pytest.raises(ValueError, match="names"):
        irid.write_image(tmp_path / "x.exr", a, channels=["R", "G"])
    with pytest.raises(ValueError, match="8 and 16"):
        irid.write_image(tmp_path / "x.png", a, bits=12)
    with pytest.raises(ValueError, match="twice"):
        irid.write_image(tmp_path / "x.exr", a, channels=["R", "R", "B"])
    with pytest.raises(ValueError, match="NUL"):
        irid.write_image(str(tmp_path / "x.png") + "\0.exr", a)
    with pytest.raises(ValueError, match="NUL"):
        irid.read_image(str(tmp_path / "a.exr") + "\0junk")
    with pytest.raises(ValueError, match="NUL"):
        irid.write_image(tmp_path / "x.exr", a, description="x\0y")
    assert not (tmp_path / "x.png").exists() and not (tmp_path / "x.exr").exists()


def test_compression_is_written_and_unknown_names_refused(tmp_path):
    """OpenImageIO's iinfo (openimageio-tools, from scripts/install-deps) reads back what each
    file says it is compressed with; the pixels survive the lossless ones."""
    import shutil
    import subprocess

    iinfo = shutil.which("iinfo")
    assert iinfo, "iinfo (openimageio-tools) is missing: run scripts/install-deps"
    a = np.random.default_rng(2).uniform(0, 1, (16, 16, 3)).astype(np.float32)
    for name, compression, expect in [("a.exr", "piz", '"piz"'), ("b.exr", "dwaa:45", '"dwaa"'),
                                      ("c.tif", "lzw", '"lzw"'), ("d.exr", "", '"zip"')]:
        irid.write_image(tmp_path / name, a, compression=compression, bits=16)
        info = subprocess.run([iinfo, "-v", str(tmp_path / name)], capture_output=True, text=True,
                              check=True).stdout
        line = next(l for l in info.splitlines() if l.strip().startswith("compression:"))
        assert expect in line, (name, line)
    np.testing.assert_array_equal(irid.read_image(tmp_path / "a.exr")[0], a)
    for name, compression in [("e.exr", "bogus"), ("f.exr", "piz:3"), ("g.png", "zip"),
                              ("h.tif", "piz"), ("i.exr", "dwaa:x")]:
        with pytest.raises(KeyError, match="valid"):
            irid.write_image(tmp_path / name, a, compression=compression)
        assert not (tmp_path / name).exists()


# --- write_image writes what is asked, or refuses ---------------------------------------------

@pytest.mark.parametrize("name", ["display_p3", "Display P3", "nope", "s-RGB"])
def test_an_unknown_space_name_is_a_key_error(tmp_path, name):
    with pytest.raises(KeyError, match="unknown.*tag=False"):
        irid.write_image(tmp_path / "a.png", np.zeros((2, 2, 3)), color_space=name)
    assert not (tmp_path / "a.png").exists()
    # Without tagging it is a text attribute, whatever it says (read_image's "sRGB" round trips).
    irid.write_image(tmp_path / "a.png", np.zeros((2, 2, 3)), color_space=name, tag=False)
    _, meta = irid.read_image(tmp_path / "a.png")
    assert meta["color_space"] == name and meta["icc_profile"] is None


@pytest.mark.parametrize("name, canonical", [("Display-P3", "display-p3"), ("sRGB", "srgb")])
def test_a_space_name_in_another_case_tags_the_file_with_its_canonical_name(tmp_path, name, canonical):
    # Space names are found in any case (issue 37, item 9), and written as irid names them.
    irid.write_image(tmp_path / "a.png", np.zeros((2, 2, 3)), color_space=name)
    _, meta = irid.read_image(tmp_path / "a.png")
    assert meta["color_space"] == canonical and meta["icc_profile"] == irid.icc_profile(canonical)


def test_a_space_that_is_not_rgb_cannot_tag_a_file(tmp_path):
    with pytest.raises(ValueError, match="not an RGB space"):
        irid.write_image(tmp_path / "a.png", np.zeros((2, 2, 3)), color_space="lab")
    irid.write_image(tmp_path / "a.exr", np.zeros((2, 2, 3)), color_space="lab", tag=False)
    _, meta = irid.read_image(tmp_path / "a.exr")
    assert meta["color_space"] == "lab" and meta["chromaticities"] is None


def test_integer_arrays_are_code_values(tmp_path):
    codes = np.array([[[0, 128, 255]]], np.uint8)
    irid.write_image(tmp_path / "a.png", codes)
    back, _ = irid.read_image(tmp_path / "a.png")
    np.testing.assert_array_equal(np.round(back * 255), codes)       # 128 stays 128, not white
    for order in ("<u2", ">u2"):
        words = np.array([[[0, 32768, 65535]]], order)
        irid.write_image(tmp_path / "b.png", words, bits=16)
        back, _ = irid.read_image(tmp_path / "b.png")
        np.testing.assert_array_equal(np.round(back * 65535), words)
    for bad in (np.int64, np.int32, np.bool_):
        with pytest.raises(ValueError, match="uint8"):
            irid.write_image(tmp_path / "c.png", np.zeros((1, 1, 3), bad))
    with pytest.raises(ValueError, match="EXR holds linear"):
        irid.write_image(tmp_path / "c.exr", codes)


def test_tags_that_contradict_each_other_are_refused(tmp_path):
    p3 = irid.icc_profile("display-p3")
    with pytest.raises(ValueError, match="contradict"):
        irid.write_image(tmp_path / "a.png", np.zeros((2, 2, 3)), color_space="srgb",
                         icc_profile=p3)
    with pytest.raises(ValueError, match="contradict"):
        irid.write_image(tmp_path / "a.png", np.zeros((2, 2, 3)), color_space="display-p3-linear",
                         icc_profile=p3)     # the same primaries, another curve
    irid.write_image(tmp_path / "a.png", np.zeros((2, 2, 3)), color_space="display-p3",
                     icc_profile=p3)
    rec2020 = (0.708, 0.292, 0.170, 0.797, 0.131, 0.046, 0.3127, 0.3290)
    with pytest.raises(ValueError, match="contradict"):
        irid.write_image(tmp_path / "a.exr", np.zeros((2, 2, 3)), color_space="srgb-linear",
                         chromaticities=rec2020)
    irid.write_image(tmp_path / "a.exr", np.zeros((2, 2, 3)), color_space="rec2020-linear",
                     chromaticities=rec2020)
