"""irid display IN OUT (issue 37): what its notes count (pixels too bright for the encoding,
pixels outside its gamut, non-finite input pixels), how +Inf is shown, the codes of 16-bit files,
and images of the two XYZ displays. Every expected count and code is computed here from
irid.display_transform (the double chain, checked against OpenColorIO's outputs elsewhere) and
the encodings' published definitions, never from the command's own output."""

import re
import shutil
import subprocess

import numpy as np
import pytest

import irid


def run(cli, *args, expect=0):
    r = subprocess.run([cli, "display", *map(str, args)], capture_output=True, text=True)
    assert r.returncode == expect, r.stderr
    return r


def scene(height=64, width=64, seed=11):
    """ACES2065-1 colours from deep shadow to 64: saturated ones, greys, some negative."""
    rng = np.random.default_rng(seed)
    img = rng.uniform(-0.05, 1.0, size=(height, width, 3)) * (2.0 ** rng.uniform(-6, 6, size=(height, width, 1)))
    img[0, :4] = [[0.18, 0.18, 0.18], [64.0, 64.0, 64.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]
    return img.astype(np.float32)


def note_count(stderr, pattern):
    """The number a note of stderr states (0 when no note says it)."""
    found = re.search(r"irid display: note: (\d+) pixels? " + pattern, stderr)
    return int(found.group(1)) if found else 0


# BT.709/sRGB relative luminance of linear RGB (ITU-R BT.709-6 Item 3.2), and BT.2020's
# (ITU-R BT.2020-2 Table 4): Y of the encoding's linear values, its white at 1.
LUMINANCE = {"srgb": [0.2126, 0.7152, 0.0722], "rec2100-pq": [0.2627, 0.6780, 0.0593]}


def expected_counts(linear, to, peak):
    """Pixels brighter than the encoding's white at its peak (luminance above it), and pixels
    of a luminance it holds with a channel below 0 or above the peak (out of its gamut); bounds
    within 1e-9 of the peak, as docs/DISPLAY.md defines them."""
    lin = linear.reshape(-1, 3)
    y = lin @ np.array(LUMINANCE[to])
    tol = 1e-9 * peak
    bright = y > peak + tol
    outside = ~bright & ((lin < -tol).any(axis=1) | (lin > peak + tol).any(axis=1))
    return int(bright.sum()), int(outside.sum())


@pytest.mark.parametrize("bits", [8, 16])
def test_a_p3_display_in_srgb_counts_pixels_out_of_gamut_not_too_bright(irid_cli, tmp_path, bits):
    img = scene()
    irid.write_image(tmp_path / "s.exr", img, color_space="aces2065-1-linear")
    r = run(irid_cli, "--display", "sdr-100nit-p3-d65", "--to", "srgb", "--bits", bits, tmp_path / "s.exr",
            tmp_path / "o.png")
    linear = irid.display_transform(img.astype(np.float64), display="sdr-100nit-p3-d65", target="srgb-linear")
    bright, outside = expected_counts(linear, "srgb", 1.0)
    # A 100 cd/m² display has nothing brighter than sRGB's white, but P3 colours sRGB lacks.
    assert bright == 0 and outside > 100
    assert "brighter" not in r.stderr
    assert note_count(r.stderr, r"are outside srgb's gamut") == outside, r.stderr
    assert "display-p3" in r.stderr  # what keeps them: the display's own encoding


def test_an_hdr_display_in_srgb_counts_both_and_says_what_keeps_them(irid_cli, tmp_path):
    img = scene(seed=12)
    irid.write_image(tmp_path / "s.exr", img, color_space="aces2065-1-linear")
    r = run(irid_cli, "--display", "hdr-1000nit-rec2020", "--to", "srgb", tmp_path / "s.exr", tmp_path / "o.png")
    linear = irid.display_transform(img.astype(np.float64), display="hdr-1000nit-rec2020", target="srgb-linear")
    bright, outside = expected_counts(linear, "srgb", 1.0)
    assert bright > 100 and outside > 10
    assert note_count(r.stderr, r"are brighter than srgb's white") == bright, r.stderr
    assert note_count(r.stderr, r"are outside srgb's gamut") == outside, r.stderr
    assert "rec2100-pq" in r.stderr
    # Its own encoding holds everything it shows: no note.
    r = run(irid_cli, "--display", "hdr-1000nit-rec2020", tmp_path / "s.exr", tmp_path / "pq.png")
    assert "note" not in r.stderr, r.stderr
    # An EXR clips nothing, whatever its encoding.
    r = run(irid_cli, "--display", "hdr-1000nit-rec2020", "--to", "srgb", tmp_path / "s.exr", tmp_path / "o.exr")
    assert "note" not in r.stderr, r.stderr


def test_infinite_and_nan_pixels_are_counted_and_plus_inf_is_a_blown_out_highlight(irid_cli, tmp_path):
    img = np.full((2, 4, 3), 0.18, np.float32)
    with np.errstate(over="ignore"):
        half_overflow = np.float32(np.float16(70000.0))  # half float overflows to +Inf
    img[0, 0] = [half_overflow] * 3
    img[0, 1] = [np.inf, 0.5, 0.2]
    img[0, 2] = [-np.inf, 0.18, 0.18]
    img[0, 3] = [np.nan, 0.18, 0.18]
    img[1, 0] = [np.nan, np.inf, 0.18]
    irid.write_image(tmp_path / "inf.exr", img, color_space="aces2065-1-linear")
    r = run(irid_cli, "--display", "sdr-100nit-rec709", tmp_path / "inf.exr", tmp_path / "o.png")
    got, _ = irid.read_image(tmp_path / "o.png")
    # +Inf is taken as 65504 (half float's largest value): white stays white, not black.
    assert np.array_equal(np.rint(got[0, 0] * 255), [255, 255, 255]), got[0, 0]
    want = irid.display_transform(np.array([65504.0, 0.5, 0.2]), display="sdr-100nit-rec709", target="srgb")
    assert np.array_equal(np.rint(got[0, 1] * 255), np.floor(np.clip(want, 0, 1) * 255 + 0.5))
    # -Inf and NaN are taken as 0, as before.
    zero = irid.display_transform(np.array([0.0, 0.18, 0.18]), display="sdr-100nit-rec709", target="srgb")
    for k in (2, 3):
        assert np.array_equal(np.rint(got[0, k] * 255), np.floor(np.clip(zero, 0, 1) * 255 + 0.5))
    assert note_count(r.stderr, r"have a non-finite channel") == 5, r.stderr
    assert "3 with +Inf" in r.stderr and "1 with -Inf" in r.stderr and "2 with NaN" in r.stderr, r.stderr
    assert "65504" in r.stderr
    # The CSV path and Python take +Inf the same way.
    direct = irid.display_transform(np.array([[np.inf, np.inf, np.inf]]), display="sdr-100nit-rec709",
                                    target="srgb")
    assert np.allclose(direct, 1.0, atol=1e-12)
    kernel = irid.display_transform(np.array([[np.inf, np.inf, np.inf]], np.float32), display="sdr-100nit-rec709",
                                    target="srgb-linear")
    assert np.allclose(kernel, 1.0, atol=1e-5)


def near_code_boundaries(display, to, levels, count):
    """ACES2065-1 colours (float32, as a file stores them) whose display values, encoded, lie
    within a hundredth of a code of a rounding boundary (k + 1/2) / levels in every channel."""
    rng = np.random.default_rng(37)
    codes = rng.integers(1, int(levels) - 1, size=(count, 3)) + 0.5 + rng.uniform(-0.01, 0.01, size=(count, 3))
    shown = irid.convert(codes / levels, to, to + "-linear")
    aces = irid.display_transform(shown, display=display, source=to + "-linear", target="aces2065-1", inverse=True)
    return aces.astype(np.float32)


@pytest.mark.parametrize("display, to", [("sdr-100nit-rec709", "srgb"), ("hdr-1000nit-p3-d65", "p3-d65-pq")])
def test_every_16_bit_code_is_the_double_chains_rounded(irid_cli, tmp_path, display, to):
    levels = 65535.0
    img = near_code_boundaries(display, to, levels, 64 * 64).reshape(64, 64, 3)
    irid.write_image(tmp_path / "s.exr", img, color_space="aces2065-1-linear")
    run(irid_cli, "--display", display, "--to", to, "--bits", 16, tmp_path / "s.exr", tmp_path / "o.png")
    got, meta = irid.read_image(tmp_path / "o.png")
    assert meta["bits"] == 16
    want = irid.display_transform(img.astype(np.float64), display=display, target=to)
    codes = np.floor(np.clip(want, 0, 1) * levels + 0.5)
    # Colours this near the boundaries: float32 rounding of the value would move many.
    near = np.abs(np.clip(want, 0, 1) * levels - np.floor(np.clip(want, 0, 1) * levels) - 0.5) < 0.01
    assert near.mean() > 0.2
    differ = np.rint(got * levels) != codes
    assert not differ.any(), (np.argwhere(differ)[:5], got[differ][:5] * levels, want[differ][:5] * levels)


def test_an_8_bit_file_has_the_double_chains_codes_near_boundaries_too(irid_cli, tmp_path):
    img = near_code_boundaries("sdr-100nit-rec709", "srgb", 255.0, 64 * 64).reshape(64, 64, 3)
    irid.write_image(tmp_path / "s.exr", img, color_space="aces2065-1-linear")
    run(irid_cli, "--display", "sdr-100nit-rec709", tmp_path / "s.exr", tmp_path / "o.png")
    got, _ = irid.read_image(tmp_path / "o.png")
    want = irid.display_transform(img.astype(np.float64), display="sdr-100nit-rec709", target="srgb")
    assert np.array_equal(np.rint(got * 255), np.floor(np.clip(want, 0, 1) * 255 + 0.5))


@pytest.mark.parametrize("display", ["sdr-100nit-p3-d60-in-xyz-e", "hdr-300nit-p3-d60-in-xyz-e"])
def test_an_xyz_display_writes_an_exr_of_cie_xyz(irid_cli, tmp_path, display):
    img = scene(8, 8, seed=13)
    irid.write_image(tmp_path / "s.exr", img, color_space="aces2065-1-linear")
    run(irid_cli, "--display", display, tmp_path / "s.exr", tmp_path / "xyz.exr")
    got, meta = irid.read_image(tmp_path / "xyz.exr")
    want = irid.display_transform(img, display=display, target="xyz")
    assert np.allclose(got, want, rtol=1e-5, atol=1e-5)
    # OpenEXR's chromaticities for CIE XYZ: red (1, 0), green (0, 1), blue (0, 0), white E.
    assert np.allclose(meta["chromaticities"], [1, 0, 0, 1, 0, 0, 1 / 3, 1 / 3])
    assert meta["color_space"] == "xyz"
    assert irid.image_space(meta)["space"] == "xyz"
    # OpenEXR's own reader (scripts/install-deps installs it) says the same.
    assert shutil.which("exrheader"), "exrheader (Debian's openexr) is missing"
    header = subprocess.run(["exrheader", str(tmp_path / "xyz.exr")], capture_output=True, text=True).stdout
    for line in [r"red\s+\(1 0\)", r"green\s+\(0 1\)", r"blue\s+\(0 0\)", r"white\s+\(0\.333333 0\.333333\)"]:
        assert re.search(line, header), header
    # irid reads it back as CIE XYZ: through the chain again from XYZ, as from the values.
    run(irid_cli, "--display", "sdr-100nit-rec709", tmp_path / "xyz.exr", tmp_path / "again.exr")
    again, _ = irid.read_image(tmp_path / "again.exr")
    direct = irid.display_transform(irid.convert(got.astype(np.float64), "xyz", "aces2065-1-linear"),
                                    display="sdr-100nit-rec709", target="srgb-linear")
    assert np.allclose(again, direct, rtol=1e-4, atol=1e-5)
    # --to xyz writes XYZ for any display; an integer file has no XYZ encoding and names EXR.
    run(irid_cli, "--display", "sdr-100nit-rec709", "--to", "xyz", tmp_path / "s.exr", tmp_path / "x709.exr")
    x709, _ = irid.read_image(tmp_path / "x709.exr")
    assert np.allclose(x709, irid.display_transform(img, display="sdr-100nit-rec709", target="xyz"),
                       rtol=1e-5, atol=1e-5)
    for out in ("xyz.png", "xyz.tif"):
        r = run(irid_cli, "--display", display, tmp_path / "s.exr", tmp_path / out, expect=2)
        assert "EXR" in r.stderr and "--to" in r.stderr, r.stderr
        assert not (tmp_path / out).exists()


def test_an_hlg_file_holds_bt2100_hlg_of_the_display_light(irid_cli, tmp_path):
    # rec2100-hlg (issue 37, item 7): BT.2020 primaries, D65, HLG with the reference OOTF of a
    # 1000 cd/m² display; 16 bits, tagged by name (no ICC.1 curve holds it).
    img = scene(16, 16, seed=14)
    irid.write_image(tmp_path / "s.exr", img, color_space="aces2065-1-linear")
    r = run(irid_cli, "--display", "hdr-1000nit-rec2020", "--to", "rec2100-hlg", tmp_path / "s.exr",
            tmp_path / "hlg.png")
    got, meta = irid.read_image(tmp_path / "hlg.png")
    assert meta["bits"] == 16 and meta["color_space"] == "rec2100-hlg" and meta["icc_profile"] is None
    want = irid.display_transform(img.astype(np.float64), display="hdr-1000nit-rec2020", target="rec2100-hlg")
    assert np.array_equal(np.rint(got * 65535), np.floor(np.clip(want, 0, 1) * 65535 + 0.5))
    # A 1000 cd/m² display fits HLG's 1000 cd/m² white, but not every saturated colour at that
    # luminance: what the note counts is outside HLG's scene light [0, 1].
    linear = irid.display_transform(img.astype(np.float64), display="hdr-1000nit-rec2020",
                                    target="rec2100-hlg-linear").reshape(-1, 3)
    y = irid.convert(linear, "rec2100-hlg-linear", "xyz")[:, 1]
    assert not (y > 10.0 * (1 + 1e-9)).any() and "brighter" not in r.stderr
    # The inverse OOTF (BT.2100-2 Table 5, γ 1.2): E = F_D / L_W · (Y_D / L_W)^(-1/6).
    rows = np.clip(y, 1e-300, None)[:, None]
    scene_light = linear * 100 / 1000 * (rows * 100 / 1000) ** (-0.2 / 1.2)
    outside = ((linear < -1e-9 * 10) | (scene_light > 1 + 1e-9)).any(axis=1)
    assert note_count(r.stderr, r"are outside rec2100-hlg's gamut") == int(outside.sum()), r.stderr
    # The space of convert and Python: the HDR reference white, 203 cd/m², is 75 % (ITU-R BT.2408).
    assert abs(irid.convert([2.03, 2.03, 2.03], "rec2100-hlg-linear", "rec2100-hlg")[0] - 0.75) < 0.001
    with pytest.raises(ValueError, match="HLG"):
        irid.icc_profile("rec2100-hlg")
