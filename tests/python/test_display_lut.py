"""The ACES 2.0 display transform baked by `irid lut --view aces2`, as OpenColorIO 2.1 (which has
no ACES 2.0 of its own) applies the .clf, against the transform itself (irid.display_transform):
docs/DISPLAY.md, "LUTs and OpenColorIO 2.1"."""

import subprocess

import numpy as np
import pytest

import irid
from test_lut import ocio_apply  # the .clf through PyOpenColorIO 2.1


def display_lab(signal, space, peak):
    """Display signals to CIELAB relative to the display's white at its peak (1.0 = 100 cd/m²)."""
    return irid.convert(irid.convert(signal, space, "xyz") / peak, "xyz", "lab")


def random_inputs(lut, count, seed):
    """Colours uniform in the code space of the LUT's domain (its nodes are even there), in the
    LUT's source: the log2 shaper's inverse x = min + e (2^(s span) - 1), e = (max - min)
    2^-stops, span = log2(1 + 2^stops) (irid/exchange/lut.h), or uniform over the range; then
    back through the LUT's matrix, when it has one."""
    lo, hi = lut.domain
    s = np.random.default_rng(seed).random((count, 3))
    if lut.shaper == "log2":
        e = (hi - lo) * 2.0 ** -lut.stops
        cube = lo + e * (np.exp2(s * np.log2(1.0 + 2.0 ** lut.stops)) - 1.0)
    else:
        cube = lo + s * (hi - lo)
    return cube if lut.matrix is None else cube @ np.linalg.inv(lut.matrix).T


def summary(de):
    """Mean, p95, p99 and max, the percentiles by nearest rank as irid/color/measure.h takes them."""
    de = np.sort(de)
    rank = lambda p: de[int(np.ceil(p * len(de))) - 1]
    return de.mean(), rank(0.95), rank(0.99), de[-1]


# (display, its encoding, peak / 100 cd/m², format, size, ΔE2000 mean, p95 and p99 bounds:
# docs/DISPLAY.md's table, which tests/exchange/display_lut_accuracy_test.cpp measures on 100 000
# colours through apply_lut, with its margin of about 10 %; here 20 000 other colours go through
# OpenColorIO). The .clf takes ACES2065-1 through its matrix to AP1 and its log2 shaper; the
# .cube ACEScct code values.
CASES = [
    ("sdr-100nit-rec709", "srgb", 1.0, "clf", 33, 0.090, 0.33, 0.79),
    ("sdr-100nit-rec709", "srgb", 1.0, "clf", 65, 0.026, 0.086, 0.27),
    ("sdr-100nit-rec709", "srgb", 1.0, "cube", 33, 0.18, 0.65, 1.29),
    ("sdr-100nit-rec709", "srgb", 1.0, "cube", 65, 0.052, 0.19, 0.48),
    ("hdr-1000nit-p3-d65", "p3-d65-pq", 10.0, "clf", 33, 0.113, 0.38, 0.97),
    ("hdr-1000nit-p3-d65", "p3-d65-pq", 10.0, "clf", 65, 0.031, 0.103, 0.31),
    ("hdr-1000nit-p3-d65", "p3-d65-pq", 10.0, "cube", 33, 0.24, 0.92, 1.87),
    ("hdr-1000nit-p3-d65", "p3-d65-pq", 10.0, "cube", 65, 0.070, 0.28, 0.65),
]


@pytest.mark.parametrize("display,space,peak,fmt,size,mean_bound,p95_bound,p99_bound", CASES)
def test_opencolorio_applies_the_baked_transform_within_its_measured_delta_e(
        tmp_path, irid_cli, display, space, peak, fmt, size, mean_bound, p95_bound, p99_bound):
    path = tmp_path / f"aces2.{fmt}"
    source = "acescct" if fmt == "cube" else "aces2065-1"
    r = subprocess.run([irid_cli, "lut", "--view", "aces2", "--display", display, "--from", source,
                        "--size", str(size), "-o", str(path)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    text = path.read_text()
    assert f"--display {display}" in text
    lut = irid.bake_display_lut(display, source=source, size=size, format=fmt)
    if fmt == "clf":
        limit = 1024.0 if peak == 1.0 else 4096.0  # ACES 2.0's forward limit, 8 (128 + 768 log10(peak/100) / 2)
        assert "log2 shaper over [0, %g], 16 stops in acescg-linear" % limit in text
        assert "<Matrix" in text
    else:
        assert "LUT_3D_INPUT_RANGE" not in text
    scene = random_inputs(lut, 20000, seed=size + len(fmt) + int(peak))
    through_ocio = ocio_apply(path, scene)
    # OpenColorIO reads the file as irid evaluates it: in float32, to ~1e-7 relative in the
    # matrix, the shaper's log2 and the weights.
    np.testing.assert_allclose(through_ocio, lut.apply(scene, "tetrahedral" if fmt == "clf" else "trilinear"), atol=3e-5, rtol=0)
    direct = irid.display_transform(scene, display=display, source=source, target=space)
    de = irid.delta_e(display_lab(direct, space, peak), display_lab(through_ocio, space, peak), "ciede2000")
    mean, p95, p99, worst = summary(de)
    print(f"OCIO 2.1 {display} .{fmt} {size}: {len(de)} colours, mean {mean:.3f} p95 {p95:.3f} p99 {p99:.3f} "
          f"max {worst:.2f}")
    assert mean <= mean_bound and p95 <= p95_bound and p99 <= p99_bound


def test_a_display_wider_than_the_display_space_is_refused(tmp_path):
    """Review of issue 37: --to srgb --aces2 sdr-100nit-p3-d65 baked codes from -0.51 to 1.09."""
    with pytest.raises(ValueError, match="gamut"):
        irid.write_ocio_config(tmp_path / "srgb", methods=["clamp"], size=5, aces2=["sdr-100nit-p3-d65"])
    assert not (tmp_path / "srgb").exists()
    # The pairing of OpenColorIO's ACES configs: P3-limited views on a Rec.2100-PQ display. Every
    # code OpenColorIO gives through the view lies in [0, 1], the saturated reds included.
    import PyOpenColorIO as ocio
    path = irid.write_ocio_config(tmp_path / "pq", display="rec2100-pq", methods=["clamp"], size=5,
                                  aces2=["hdr-1000nit-p3-d65"])
    config = ocio.Config.CreateFromFile(path)
    config.validate()
    rng = np.random.default_rng(5)
    scene = np.concatenate([rng.uniform(-0.5, 60.0, (20000, 3)),
                            np.outer(np.geomspace(0.01, 60.0, 200), [1.0, 0.0, 0.0])]).astype(np.float32)
    t = ocio.DisplayViewTransform(src="acescg-linear", display=config.getDefaultDisplay(),
                                  view="ACES 2.0 hdr-1000nit-p3-d65")
    config.getProcessor(t).getDefaultCPUProcessor().applyRGB(scene)
    assert scene.min() >= 0.0 and scene.max() <= 1.0


def test_the_ocio_config_offers_aces2_views_that_opencolorio_applies_as_the_transform(tmp_path, irid_cli):
    import shutil
    import PyOpenColorIO as ocio
    folder = tmp_path / "cfg"
    r = subprocess.run([irid_cli, "ocio-config", "--from", "acescg-linear", "--to", "srgb", "--methods",
                        "clamp", "-o", str(folder)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert "2 ACES 2.0 views" in r.stdout
    tool = shutil.which("ociocheck")
    assert tool, "ociocheck is missing (scripts/install-deps installs opencolorio-tools)"
    check = subprocess.run([tool, "--iconfig", str(folder / "config.ocio")], capture_output=True, text=True)
    assert check.returncode == 0 and "ERROR" not in check.stdout, check.stdout + check.stderr
    config = ocio.Config.CreateFromFile(str(folder / "config.ocio"))
    display = config.getDefaultDisplay()
    views = list(config.getViews(display))
    assert "ACES 2.0 sdr-100nit-rec709" in views and "ACES 2.0 sdr-100nit-rec709-d60-in-rec709-d65" in views
    # ACEScg scene colours (the reference) through the view, against the transform: the view's
    # LUT is the 33³ .clf over AP1, with no matrix (ACEScg is AP1), so the colours of its domain
    # measure as the .clf's row of the table does.
    lut = irid.bake_display_lut("sdr-100nit-rec709", source="acescg-linear")
    assert lut.matrix is None and lut.cube_space == "acescg-linear"
    scene = random_inputs(lut, 20000, seed=7)
    t = ocio.DisplayViewTransform(src="acescg-linear", display=display, view="ACES 2.0 sdr-100nit-rec709")
    out = np.array(scene, np.float32)
    config.getProcessor(t).getDefaultCPUProcessor().applyRGB(out)
    direct = irid.display_transform(scene, display="sdr-100nit-rec709", source="acescg-linear", target="srgb")
    de = irid.delta_e(display_lab(direct, "srgb", 1.0), display_lab(out.astype(np.float64), "srgb", 1.0),
                      "ciede2000")
    mean, p95, p99, worst = summary(de)
    print(f"OCIO config view sdr-100nit-rec709 33: {len(de)} colours, mean {mean:.3f} p95 {p95:.3f} "
          f"p99 {p99:.3f} max {worst:.2f}")
    assert mean <= 0.090 and p95 <= 0.33 and p99 <= 0.79  # the .clf 33³ row of docs/DISPLAY.md


def test_opencolorio_decodes_acescct_as_irid_does(tmp_path, irid_cli):
    """The config's acescct space (OCIO 2.1's LogCameraTransform) against irid's curve, over code
    values below 0 to above 1 (the toe carries negatives, unmirrored)."""
    import PyOpenColorIO as ocio
    folder = tmp_path / "cct"
    r = subprocess.run([irid_cli, "ocio-config", "--from", "acescct", "--to", "srgb", "--methods", "clamp",
                        "--size", "5", "--aces2", "none", "-o", str(folder)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    config = ocio.Config.CreateFromFile(str(folder / "config.ocio"))
    codes = np.linspace(-0.2, 1.1, 131)
    rgb = np.stack([codes, codes[::-1], np.full_like(codes, 0.4135884)], axis=1)
    out = np.array(rgb, np.float32)
    config.getProcessor("acescct", "acescct-linear").getDefaultCPUProcessor().applyRGB(out)
    expected = irid.convert(rgb, "acescct", "acescct-linear")
    np.testing.assert_allclose(out, expected, rtol=2e-6, atol=2e-7)
    assert abs(expected[0, 2] - 0.18) < 1e-6  # ACEScct's 0.4135884 is 0.18


def test_the_command_line_writes_what_python_bakes_for_a_display(tmp_path, irid_cli):
    for display, fmt, source in [("sdr-100nit-rec709", "clf", "aces2065-1"),
                                 ("hdr-1000nit-p3-d65", "cube", "acescct")]:
        out = tmp_path / f"{display}.{fmt}"
        subprocess.run([irid_cli, "lut", "--view", "aces2", "--display", display, "--from", source,
                        "--size", "9", "-o", str(out)], check=True)
        lut = irid.bake_display_lut(display, source=source, size=9, format=fmt)
        assert out.read_text() == lut.text(fmt), display
    # The LUT stands for the transform: at its nodes it is the transform (the .clf's nodes lie
    # on its log2 shaper's grid in AP1, here two greys and a colour on it, given as ACES2065-1).
    lut = irid.bake_display_lut("sdr-100nit-rec709", size=9)
    nodes = lut.nodes
    ap1 = np.array([[nodes[3]] * 3, [nodes[6]] * 3, [nodes[2], nodes[5], nodes[7]]])
    rgb = irid.convert(ap1, "acescg-linear", "aces2065-1-linear")
    want = irid.display_transform(rgb, display="sdr-100nit-rec709", target="srgb")
    np.testing.assert_allclose(lut.apply(rgb, "tetrahedral"), want, atol=1e-6)
    with pytest.raises(KeyError):
        irid.bake_display_lut("nope")
    with pytest.raises(KeyError):
        irid.bake_display_lut("sdr-100nit-rec709", format="3dl")
    with pytest.raises(ValueError, match="acescct"):
        irid.bake_display_lut("sdr-100nit-rec709", format="cube")
    with pytest.raises(ValueError):
        irid.bake_display_lut("sdr-100nit-rec709", size=1)


def test_write_ocio_config_chooses_its_aces2_views(tmp_path):
    def luts(folder):
        return sorted(p.name for p in (folder / "luts").iterdir() if p.name.startswith("aces2-"))

    irid.write_ocio_config(tmp_path / "none", methods=["clamp"], size=5, aces2=[])
    assert luts(tmp_path / "none") == []
    path = irid.write_ocio_config(tmp_path / "one", methods=["clamp"], size=5,
                                  aces2=["sdr-100nit-rec709"])
    assert luts(tmp_path / "one") == ["aces2-sdr-100nit-rec709.clf"]
    import PyOpenColorIO as ocio
    config = ocio.Config.CreateFromFile(path)
    config.validate()
    assert "ACES 2.0 sdr-100nit-rec709" in list(config.getViews("srgb display"))
    with pytest.raises(ValueError):
        irid.write_ocio_config(tmp_path / "bad", methods=["clamp"], size=5, aces2="sdr-100nit-rec709")
    with pytest.raises(KeyError):
        irid.write_ocio_config(tmp_path / "bad", methods=["clamp"], size=5, aces2=["nope"])
    with pytest.raises(ValueError, match="twice"):
        irid.write_ocio_config(tmp_path / "bad", methods=["clamp"], size=5,
                               aces2=["sdr-100nit-rec709", "sdr-100nit-rec709"])


@pytest.mark.parametrize("source", ["lab", "luv", "lchab", "lchuv", "oklab", "oklch", "xyy"])
def test_a_source_that_is_neither_light_nor_rgb_code_values_is_refused(tmp_path, irid_cli, source):
    """Issue 37: Lab through the log2 shaper and a [0, 1024] clamp gave a wrong LUT, silently."""
    with pytest.raises(ValueError, match="aces2065-1 or acescct"):
        irid.bake_display_lut("sdr-100nit-rec709", source=source, size=3)
    out = tmp_path / "x.clf"
    r = subprocess.run([irid_cli, "lut", "--view", "aces2", "--display", "sdr-100nit-rec709", "--from", source,
                        "--size", "3", "-o", str(out)], capture_output=True, text=True)
    assert r.returncode == 2 and f"--from {source}" in r.stderr and not out.exists(), r.stderr


def test_an_xyz_source_is_light_through_its_own_matrix_to_ap1():
    """XYZ (D65 white) goes to the same AP1 cube as ACES2065-1: the same colours give the same
    LUT output, within the .clf's float rounding."""
    xyz = irid.bake_display_lut("hdr-1000nit-p3-d65", source="xyz", size=17)
    aces = irid.bake_display_lut("hdr-1000nit-p3-d65", size=17)
    assert xyz.cube_space == aces.cube_space == "acescg-linear"
    np.testing.assert_allclose(xyz.table, aces.table, atol=2e-5)
    scene = random_inputs(aces, 2000, seed=3)
    np.testing.assert_allclose(xyz.apply(irid.convert(scene, "aces2065-1", "xyz"), "tetrahedral"),
                               aces.apply(scene, "tetrahedral"), atol=2e-5)


def test_an_hdr_display_is_refused_on_an_sdr_display_space(tmp_path):
    """Issue 37: --to srgb --aces2 hdr-1000nit-p3-d65 baked extended sRGB up to 2.64, silently."""
    with pytest.raises(ValueError, match="p3-d65-pq"):
        irid.write_ocio_config(tmp_path / "srgb", methods=["clamp"], size=5, aces2=["hdr-1000nit-p3-d65"])
    assert not (tmp_path / "srgb").exists()
    path = irid.write_ocio_config(tmp_path / "pq", display="p3-d65-pq", methods=["clamp"], size=5,
                                  aces2=["hdr-1000nit-p3-d65"])
    import PyOpenColorIO as ocio
    ocio.Config.CreateFromFile(path).validate()
