"""The ACES 2.0 display transform baked by `irid lut --view aces2`, as OpenColorIO 2.1 (which has
no ACES 2.0 of its own) applies the .clf, against the transform itself (irid.display_transform):
docs/DISPLAY.md, "LUTs and OpenColorIO 2.1"."""

import subprocess

import numpy as np
import pytest

import irid
from test_lut import ocio_apply  # the .clf through PyOpenColorIO 2.1


def scene_colours(limit):
    """Greys and 12 hues at three saturations, every half stop from 2^-12 to the forward limit
    (tests/exchange/display_lut_test.cpp's set)."""
    out = []
    stop = -12.0
    while 2.0 ** stop <= limit:
        e = 2.0 ** stop
        out.append([e, e, e])
        for h in range(12):
            angle = 2.0 * np.pi * h / 12.0
            for s in (0.3, 0.6, 0.9):
                out.append([e * (1.0 - s + s * 0.5 * (1.0 + np.cos(angle - 2.0 * np.pi * k / 3.0)))
                            for k in range(3)])
        stop += 0.5
    return np.array(out)


def display_lab(signal, space, peak):
    """Display signals to CIELAB relative to the display's white at its peak (1.0 = 100 cd/m²)."""
    return irid.convert(irid.convert(signal, space, "xyz") / peak, "xyz", "lab")


# (display, its encoding, peak / 100 cd/m², format, size, ΔE2000 mean, p95 and max bounds:
# docs/DISPLAY.md's OCIO rows with a margin of about 10 %). The .clf takes ACES2065-1 up to the
# forward limit through its log2 shaper; the .cube ACEScct code values, up to 222.86.
CASES = [
    ("sdr-100nit-rec709", "srgb", 1.0, "clf", 33, 0.24, 1.0, 2.6),
    ("sdr-100nit-rec709", "srgb", 1.0, "clf", 65, 0.065, 0.29, 0.81),
    ("sdr-100nit-rec709", "srgb", 1.0, "cube", 33, 0.21, 0.82, 1.95),
    ("sdr-100nit-rec709", "srgb", 1.0, "cube", 65, 0.065, 0.28, 1.15),
    ("hdr-1000nit-p3-d65", "p3-d65-pq", 10.0, "clf", 33, 0.19, 0.78, 3.0),
    ("hdr-1000nit-p3-d65", "p3-d65-pq", 10.0, "clf", 65, 0.052, 0.26, 1.05),
    ("hdr-1000nit-p3-d65", "p3-d65-pq", 10.0, "cube", 33, 0.145, 0.57, 4.0),
    ("hdr-1000nit-p3-d65", "p3-d65-pq", 10.0, "cube", 65, 0.047, 0.2, 0.83),
]


@pytest.mark.parametrize("display,space,peak,fmt,size,mean_bound,p95_bound,max_bound", CASES)
def test_opencolorio_applies_the_baked_transform_within_its_measured_delta_e(
        tmp_path, irid_cli, display, space, peak, fmt, size, mean_bound, p95_bound, max_bound):
    path = tmp_path / f"aces2.{fmt}"
    source = "acescct" if fmt == "cube" else "aces2065-1"
    r = subprocess.run([irid_cli, "lut", "--view", "aces2", "--display", display, "--from", source,
                        "--size", str(size), "-o", str(path)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    text = path.read_text()
    assert f"--display {display}" in text
    if fmt == "clf":
        limit = 1024.0 if peak == 1.0 else 4096.0  # ACES 2.0's forward limit, 8 (128 + 768 log10(peak/100) / 2)
        assert "log2 shaper over [0, %g]" % limit in text
    else:
        limit = 2.0 ** 7.8  # ACEScct's code value 1
        assert "LUT_3D_INPUT_RANGE" not in text
    scene = scene_colours(limit)
    direct = irid.display_transform(scene, display=display, target=space)
    through_ocio = ocio_apply(path, irid.convert(scene, "aces2065-1", source))
    de = np.sort(irid.delta_e(display_lab(direct, space, peak), display_lab(through_ocio, space, peak),
                              "ciede2000"))
    mean, p95, worst = de.mean(), de[int(np.ceil(0.95 * len(de))) - 1], de[-1]
    print(f"OCIO 2.1 {display} .{fmt} {size}: {len(de)} colours, mean {mean:.3f} p95 {p95:.3f} max {worst:.3f}")
    assert mean <= mean_bound and p95 <= p95_bound and worst <= max_bound


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
    # ACEScg scene colours (the reference) through the view, against the transform.
    scene = irid.convert(scene_colours(1024.0), "aces2065-1-linear", "acescg-linear")
    scene = np.clip(scene, 0.0, None)  # the LUT's domain starts at 0
    t = ocio.DisplayViewTransform(src="acescg-linear", display=display, view="ACES 2.0 sdr-100nit-rec709")
    out = np.array(scene, np.float32)
    config.getProcessor(t).getDefaultCPUProcessor().applyRGB(out)
    direct = irid.display_transform(scene, display="sdr-100nit-rec709", source="acescg-linear", target="srgb")
    de = np.sort(irid.delta_e(display_lab(direct, "srgb", 1.0), display_lab(out.astype(np.float64), "srgb", 1.0),
                              "ciede2000"))
    mean, p95 = de.mean(), de[int(np.ceil(0.95 * len(de))) - 1]
    print(f"OCIO config view sdr-100nit-rec709 33: {len(de)} colours, mean {mean:.3f} p95 {p95:.3f} max {de[-1]:.3f}")
    assert mean <= 0.135 and p95 <= 0.53 and de[-1] <= 1.8  # measured 0.120, 0.479, 1.607


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
    # The LUT stands for the transform: at its nodes it is the transform (the .clf's nodes on
    # its log2 shaper's grid, here two greys and a colour on it).
    lut = irid.bake_display_lut("sdr-100nit-rec709", size=9)
    nodes = lut.nodes
    rgb = np.array([[nodes[3]] * 3, [nodes[6]] * 3, [nodes[2], nodes[5], nodes[7]]])
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
