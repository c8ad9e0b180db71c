"""The colour core from Python, against published values and closed forms."""

import csv
import math

import numpy as np
import pytest

import irid

from conftest import DATA


def read_csv(name):
    with open(DATA / name, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], np.array([[float(v) for v in r] for r in rows[1:]])


# Ottosson 2020, "A perceptual color space for image processing": Oklab of XYZ (D65), to the
# three decimals published.
OTTOSSON = [
    ((0.950, 1.000, 1.089), (1.000, 0.000, 0.000)),
    ((1.000, 0.000, 0.000), (0.450, 1.236, -0.019)),
    ((0.000, 1.000, 0.000), (0.922, -0.671, 0.263)),
    ((0.000, 0.000, 1.000), (0.153, -1.415, -0.449)),
]


def test_oklab_matches_ottosson_table():
    xyz = np.array([x for x, _ in OTTOSSON])
    lab = irid.convert(xyz, "xyz", "oklab")
    np.testing.assert_allclose(lab, [l for _, l in OTTOSSON], atol=1.5e-3)


def test_srgb_white_and_transfer_function():
    # IEC 61966-2-1: the sRGB white is D65, XYZ (0.9505, 1, 1.0890).
    np.testing.assert_allclose(irid.convert([1.0, 1.0, 1.0], "srgb", "xyz"),
                               [0.9505, 1.0, 1.0890], atol=2e-4)
    # The encoding: 1.055 v^(1/2.4) - 0.055 above 0.0031308, 12.92 v below.
    v = np.array([0.5, 0.002, 0.2])
    expected = np.where(v > 0.0031308, 1.055 * v ** (1 / 2.4) - 0.055, 12.92 * v)
    np.testing.assert_allclose(irid.convert(v, "srgb-linear", "srgb"), expected, rtol=1e-12)


def test_srgb_red_in_oklab():
    # Ottosson 2020 and CSS Color Module Level 4 give sRGB red as oklab(0.627955 0.224863
    # 0.125846), from Ottosson's own linear-sRGB → LMS matrix. irid composes Oklab's XYZ → LMS
    # M1 with the sRGB matrix derived from its primaries and white, which differ from that one
    # by about 6e-5 in a and b.
    np.testing.assert_allclose(irid.convert([1.0, 0.0, 0.0], "srgb", "oklab"),
                               [0.627955, 0.224863, 0.125846], atol=1e-4)


def test_lab_of_the_white_and_round_trips():
    lab = irid.convert([0.95047, 1.0, 1.08883], "xyz", "lab")
    np.testing.assert_allclose(lab, [100.0, 0.0, 0.0], atol=0.05)
    rng = np.random.default_rng(1)
    rgb = rng.uniform(0.0, 1.0, (1000, 3))
    for space in ["xyz", "xyy", "luv", "lab", "lchuv", "lchab", "oklab", "oklch", "display-p3",
                  "rec2020-linear", "acescg", "aces2065-1"]:
        there = irid.convert(rgb, "srgb-linear", space)
        back = irid.convert(there, space, "srgb-linear")
        np.testing.assert_allclose(back, rgb, atol=1e-9, err_msg=space)


def test_convert_equals_the_command_line(irid_cli):
    import subprocess
    rng = np.random.default_rng(2)
    rgb = rng.uniform(-0.2, 1.2, (50, 3))
    text = "R,G,B\n" + "\n".join(",".join(repr(float(v)) for v in row) for row in rgb) + "\n"
    out = subprocess.run([irid_cli, "convert", "--from", "srgb", "--to", "lab", "--white", "D50"],
                         input=text, capture_output=True, text=True, check=True).stdout
    cli = np.array([[float(v) for v in line.split(",")] for line in out.splitlines()[1:]])
    np.testing.assert_array_equal(irid.convert(rgb, "srgb", "lab", white="D50"), cli)


def test_ciede2000_sharma_pairs():
    _, t = read_csv("sharma2005_ciede2000_pairs.csv")
    d = irid.delta_e(t[:, 0:3], t[:, 3:6], metric="ciede2000")
    assert d.shape == (34,)
    np.testing.assert_allclose(d, t[:, 6], atol=5e-5)


def test_other_metrics_closed_forms():
    a = np.array([50.0, 10.0, -20.0])
    b = np.array([[60.0, 0.0, 0.0], [50.0, 10.0, -20.0]])
    np.testing.assert_allclose(irid.delta_e(a, b, "cie76"),
                               [math.sqrt(100 + 100 + 400), 0.0])
    np.testing.assert_allclose(irid.delta_e(a, b, "cieuv"), [math.sqrt(600), 0.0])
    np.testing.assert_allclose(irid.delta_e([0.5, 0.1, 0.0], [0.5, 0.0, 0.0], "oklab"), 0.1)


def test_cmfs_are_the_cie_tables():
    for observer, name in [("cie1931", "cie1931_2deg_xyz_cmf.csv"),
                           ("cie1964", "cie1964_10deg_xyz_cmf.csv")]:
        w, v = irid.cmfs(observer)
        _, t = read_csv(name)
        assert w.shape == (471,) and v.shape == (471, 3)
        np.testing.assert_array_equal(w, np.arange(360, 831))
        rows = np.isin(t[:, 0], w)
        np.testing.assert_allclose(v, t[rows, 1:], rtol=1e-12)
    w, v = irid.cmfs("cie1931")
    assert v[w == 555, 1] == pytest.approx(1.0)       # ȳ(555 nm) = 1 (CIE 015:2018)


def test_illuminants():
    w, d65 = irid.illuminant("D65")
    assert d65[w == 560] == pytest.approx(100.0)
    _, table = read_csv("cie_illuminant_D65.csv")
    np.testing.assert_allclose(d65[np.isin(w, table[:, 0])], table[np.isin(table[:, 0], w), 1],
                               rtol=1e-9)
    # Illuminant A: CIE 015:2018 eq. 4.1, Planck at 2848 K with c2 = 1.435e-2 m K (2856 K
    # with c2 = 1.4388e-2).
    w, a = irid.illuminant("A")
    c2 = 1.435e7  # nm K
    planck = 100 * (560 / w) ** 5 * (np.exp(c2 / (2848 * 560)) - 1) / (np.exp(c2 / (2848 * w)) - 1)
    np.testing.assert_allclose(a, planck, rtol=2e-4)


def test_daylight_chromaticity_is_cie_daylight_locus():
    # CIE 015:2018 eq. 4.7 and 4.8 (4000-7000 K): x_D and y_D of the daylight locus.
    t = 5000.0
    x = -4.6070e9 / t**3 + 2.9678e6 / t**2 + 0.09911e3 / t + 0.244063
    y = -3.000 * x * x + 2.870 * x - 0.275
    w, s = irid.illuminant("D", cct=t)
    _, cmf = irid.cmfs("cie1931")
    X, Y, Z = (s[:, None] * cmf).sum(axis=0)
    assert X / (X + Y + Z) == pytest.approx(x, abs=2e-4)
    assert Y / (X + Y + Z) == pytest.approx(y, abs=2e-4)


def test_blackbody_is_planck():
    w, b = irid.blackbody(3000.0)
    c2 = 1.4388e-2 * 1e9  # nm K, the library's constant (CODATA 2018 rounds it so)
    shape = w ** -5 / (np.exp(c2 / (w * 3000.0)) - 1)
    np.testing.assert_allclose(b / b[w == 560], shape / shape[w == 560], rtol=1e-9)


def test_spectrum_to_xyz():
    w = np.arange(360.0, 831.0, 5.0)
    # The perfect reflecting diffuser under D65 is D65's white (ASTM E308 / CIE 015:2018:
    # 95.047, 100, 108.883 for the 2° observer; 94.811, 100, 107.304 for 10°).
    np.testing.assert_allclose(irid.spectrum_to_xyz(w, np.ones_like(w)),
                               [0.95047, 1.0, 1.08883], atol=3e-4)
    np.testing.assert_allclose(irid.spectrum_to_xyz(w, np.ones_like(w), observer="cie1964"),
                               [0.94811, 1.0, 1.07304], atol=3e-4)
    # Many spectra at once, any leading shape; a linear spectrum is sampled exactly by linear
    # interpolation, so 10 nm and 1 nm samples give the same XYZ.
    fine = np.arange(360.0, 831.0, 1.0)
    coarse = np.arange(360.0, 831.0, 10.0)
    slopes = np.linspace(0.0, 1.0, 6).reshape(2, 3, 1)
    xyz_fine = irid.spectrum_to_xyz(fine, slopes * (fine - 360) / 470)
    xyz_coarse = irid.spectrum_to_xyz(coarse, slopes * (coarse - 360) / 470)
    assert xyz_fine.shape == (2, 3, 3)
    np.testing.assert_allclose(xyz_coarse, xyz_fine, rtol=1e-12, atol=1e-15)
    with pytest.raises(ValueError, match="greater than"):
        irid.spectrum_to_xyz([400, 390, 500], [1, 1, 1])


def test_primaries_transform_thesis_figure_2():
    w, rgb, m = irid.primaries_transform(645, 526, 444)
    _, cmf = irid.cmfs("cie1931")
    # Light at a primary's own wavelength is matched by that primary alone.
    for k, nm in enumerate([645, 526, 444]):
        row = rgb[w == nm][0]
        assert row[k] > 0
        np.testing.assert_allclose(np.delete(row, k), 0.0, atol=1e-12)
    # The equal-energy stimulus is matched by equal amounts, each sum that of ȳ (CIE 1931 RGB's
    # normalisation).
    np.testing.assert_allclose(rgb.sum(axis=0), cmf[:, 1].sum(), rtol=1e-12)


def test_primaries_transform_reproduces_cie_1931_rgb():
    # With the CIE 1931 primaries (700, 546.1, 435.8 nm) the transform gives the CIE 1931 RGB
    # colour-matching functions, up to their overall scale. Published values (CIE 1931 standard
    # observer in RGB, Wyszecki & Stiles, Color Science, 2nd ed., Table I(3.3.3)):
    published = {450: (-0.01213, 0.00678, 0.31670), 500: (-0.07173, 0.08536, 0.04776),
                 600: (0.34357, 0.06246, -0.00060)}
    w, rgb, _ = irid.primaries_transform(700, 546.1, 435.8)
    ours = np.array([rgb[w == nm][0] for nm in published])
    cie = np.array(list(published.values()))
    big = np.abs(cie) > 0.005
    scale = (ours[big] / cie[big]).mean()
    np.testing.assert_allclose(ours[big] / scale, cie[big], rtol=6e-3)


def test_delta_e_takes_triples_not_scalars():
    lab = np.array([50.0, 10.0, -10.0])
    for bad in (5.0, np.float64(5.0), [1.0, 2.0]):
        with pytest.raises(ValueError, match="triples"):
            irid.delta_e(bad, lab)
        with pytest.raises(ValueError, match="triples"):
            irid.delta_e(lab, bad)
    assert irid.delta_e(lab, lab) == 0.0


def test_a_mistyped_keyword_is_an_unknown_name_whatever_its_value():
    # Not "parameter shapr: 'log2' is not a number": the name is what is wrong.
    with pytest.raises(KeyError, match="'shapr' is neither an argument nor a parameter"):
        irid.bake_lut("smits", "srgb-linear", "srgb", size=5, shapr="log2")
    with pytest.raises(KeyError, match="'strenght'.*smits-soft"):
        irid.clip([[2.0, 0.5, 0.1]], "smits-soft", strenght=0.5)
