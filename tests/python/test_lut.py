"""3D LUTs read by the programs they are for: OpenColorIO 2.1 (PyOpenColorIO) evaluates every
format, ffmpeg's lut3d applies the .cube to a 16-bit image, and both are compared with the
LUT as irid evaluates it and with the clip method applied directly."""

import shutil
import subprocess

import numpy as np
import pytest

import irid


def ocio_apply(path, rgb):
    import PyOpenColorIO as ocio  # scripts/install-deps installs python3-pyopencolorio
    t = ocio.FileTransform(src=str(path))
    cpu = ocio.Config.CreateRaw().getProcessor(t).getDefaultCPUProcessor()
    out = np.ascontiguousarray(rgb, dtype=np.float32).copy()
    cpu.applyRGB(out)
    return out.astype(np.float64)


def delta_e2000(a_srgb, b_srgb):
    return irid.delta_e(irid.convert(a_srgb, "srgb", "lab"), irid.convert(b_srgb, "srgb", "lab"),
                        "ciede2000")


def colours(lo, hi, count, seed, log=False):
    rng = np.random.default_rng(seed)
    if log:
        # As scripts/lut-accuracy's scene-referred sample: 14 stops below the top, a tenth 0.
        x = hi * np.exp2(rng.uniform(-14.0, 0.0, (count, 3)))
        x[rng.random((count, 3)) < 0.1] = lo
    else:
        x = rng.uniform(lo, hi, (count, 3))
    # A few beyond the domain on each side: every client clamps them.
    beyond = np.array([[lo - 0.5, hi * 0.5, hi], [hi + 3.0, lo, hi * 0.25], [hi * 2, hi * 2, hi * 2]])
    return np.concatenate([x, beyond])


# (format, method, source, shaper, domain, log-distributed, mean and p99 ΔE2000 bounds against
# the method: docs/GAMUT.md's rows for 33³ (scripts/lut-accuracy) with a quarter's margin for
# the smaller sample; None where the table has no row and only OCIO's agreement is checked).
CASES = [
    ("cube", "oklab-cusp", "rec2020", "none", (0.0, 1.0), False, 0.076, 0.81),
    ("cube", "aces-rgc", "acescg-linear", "none", (0.0, 4.0), False, None, None),
    ("spi3d", "smits", "rec2020", "none", (0.0, 1.0), False, 0.075, 0.89),
    ("clf", "css", "acescg-linear", "none", (-0.25, 2.0), False, None, None),
    ("clf", "css", "rec2020", "none", (0.0, 1.0), False, 0.055, 0.49),
    ("clf", "oklab-cusp", "acescg-linear", "log2", (0.0, 16.0), True, 0.446, 10.14),
    ("clf", "aces-rgc", "acescg-linear", "log2", (0.0, 16.0), True, 0.079, 0.26),
]


@pytest.mark.parametrize("fmt,method,source,shaper,domain,log,mean_bound,p99_bound", CASES)
def test_opencolorio_evaluates_the_lut_as_irid_does(tmp_path, fmt, method, source, shaper, domain,
                                                    log, mean_bound, p99_bound):
    lut = irid.bake_lut(method, source, "srgb", size=33, shaper=shaper, domain=domain)
    path = tmp_path / f"look.{fmt}"
    lut.write(path)
    rgb = colours(domain[0], domain[1], 20000, seed=len(fmt) + len(method), log=log)
    got = ocio_apply(path, rgb)
    # OCIO's interpolation: trilinear for .cube and .spi3d, the .clf's own (tetrahedral). OCIO
    # computes in float32: the shaper's log2 and the interpolation weights round at ~1e-7.
    interpolation = "tetrahedral" if fmt == "clf" else "trilinear"
    np.testing.assert_allclose(got, lut.apply(rgb, interpolation), atol=2e-5, rtol=0)
    # Against the method itself, within what docs/GAMUT.md records for a 33³ LUT.
    if mean_bound is not None:
        d = delta_e2000(got, irid.clip(rgb, method, source, "srgb"))
        mean, p99 = d.mean(), np.percentile(d, 99)
        assert mean <= 1.25 * mean_bound and p99 <= 1.25 * p99_bound, (mean, p99)


def test_opencolorio_reads_the_same_lut_alike_in_every_format(tmp_path):
    lut = irid.bake_lut("smits-soft", "rec2020", "srgb", size=17)
    rgb = colours(0.0, 1.0, 3000, seed=5)
    results = {}
    for fmt in ("cube", "spi3d"):
        lut.write(tmp_path / f"l.{fmt}")
        results[fmt] = ocio_apply(tmp_path / f"l.{fmt}", rgb)
    np.testing.assert_allclose(results["cube"], results["spi3d"], atol=1e-6, rtol=0)
    lut.write(tmp_path / "l.clf")
    np.testing.assert_allclose(ocio_apply(tmp_path / "l.clf", rgb),
                               lut.apply(rgb, "tetrahedral"), atol=2e-5, rtol=0)


def test_ffmpeg_applies_the_cube_to_a_16_bit_image(tmp_path):
    ffmpeg = shutil.which("ffmpeg")
    assert ffmpeg, "ffmpeg is missing (scripts/install-deps installs it)"
    w, h = 64, 48
    rng = np.random.default_rng(11)
    image = rng.integers(0, 65536, (h, w, 3), dtype=np.uint16)
    image[0, :8] = [[0, 0, 0], [65535, 65535, 65535], [65535, 0, 0], [0, 65535, 0],
                    [0, 0, 65535], [65535, 65535, 0], [0, 65535, 65535], [65535, 0, 65535]]
    (tmp_path / "in.raw").write_bytes(image.astype("<u2").tobytes())
    lut = irid.bake_lut("oklab-cusp", "rec2020", "srgb", size=33)
    lut.write(tmp_path / "look.cube")
    subprocess.run([ffmpeg, "-v", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgb48le",
                    "-s", f"{w}x{h}", "-i", str(tmp_path / "in.raw"),
                    "-vf", f"lut3d=file={tmp_path / 'look.cube'}", "-f", "rawvideo",
                    "-pix_fmt", "rgb48le", str(tmp_path / "out.raw")], check=True)
    out = np.frombuffer((tmp_path / "out.raw").read_bytes(), dtype="<u2").reshape(h, w, 3)
    rgb = image.reshape(-1, 3) / 65535.0
    got = out.reshape(-1, 3) / 65535.0
    # ffmpeg's default is tetrahedral, in float, rounded to 16 bits.
    np.testing.assert_allclose(got, lut.apply(rgb, "tetrahedral"), atol=1.5 / 65535, rtol=0)
    d = delta_e2000(got, irid.clip(rgb, "oklab-cusp", "rec2020", "srgb"))
    # docs/GAMUT.md: 0.059 / 0.70 for oklab-cusp, 33³, tetrahedral; a quarter's margin.
    assert d.mean() <= 1.25 * 0.059 and np.percentile(d, 99) <= 1.25 * 0.70, (d.mean(), np.percentile(d, 99))


def test_the_command_line_writes_what_python_bakes(tmp_path, irid_cli):
    subprocess.run([irid_cli, "lut", "--method", "oklab-cusp", "--param", "alpha=0.1",
                    "--from", "acescg-linear", "--to", "srgb", "--size", "9", "--shaper", "log2",
                    "--domain", "0,16", "--stops", "12", "-o", str(tmp_path / "a.clf")], check=True)
    lut = irid.bake_lut("oklab-cusp", "acescg-linear", "srgb", size=9, shaper="log2",
                        domain=(0, 16), stops=12, alpha=0.1)
    assert (tmp_path / "a.clf").read_text() == lut.text("clf")


def test_lut_object_and_refusals(tmp_path):
    lut = irid.bake_lut("clamp", "srgb-linear", "srgb-linear", size=5, domain=(0, 2))
    assert lut.size == 5 and lut.shaper == "none" and lut.domain == (0.0, 2.0)
    assert lut.source == "srgb-linear" and lut.target == "srgb-linear"
    np.testing.assert_allclose(lut.nodes, [0, 0.5, 1, 1.5, 2])
    # table[r, g, b]: the identity clamped to the unit cube.
    t = lut.table
    assert t.shape == (5, 5, 5, 3) and not t.flags.writeable
    np.testing.assert_array_equal(t[3, 1, 4], [1.0, 0.5, 1.0])
    with pytest.raises(ValueError):
        t[0, 0, 0, 0] = 1
    with pytest.raises(ValueError, match="2 to 129|size"):
        irid.bake_lut("smits", size=1)
    with pytest.raises(KeyError):
        irid.bake_lut("smits", shaper="log10")
    with pytest.raises(KeyError):
        irid.bake_lut("nope")
    with pytest.raises(ValueError):
        irid.bake_lut("smits", domain=(1, 0))
    with pytest.raises(ValueError):
        irid.bake_lut("smits", domain="0,1")
    with pytest.raises(ValueError, match="spi3d"):
        lut.write(tmp_path / "x.spi3d")
    with pytest.raises(KeyError, match="cube"):
        lut.write(tmp_path / "x.3dl")
    (tmp_path / "d.cube").mkdir()
    with pytest.raises(OSError):
        lut.write(tmp_path / "d.cube")
    assert (tmp_path / "d.cube").is_dir()
    with pytest.raises(KeyError):
        lut.apply([[0, 0, 0]], "cubic")
    with pytest.raises(ValueError):
        lut.apply([[0, 0]])
    assert lut.apply(np.zeros((2, 4, 3))).shape == (2, 4, 3)


def test_write_ocio_config_from_python(tmp_path):
    path = irid.write_ocio_config(tmp_path / "c", "rec2020", "srgb", methods=["css"], size=9,
                                  range=(0, 1))
    assert path.endswith("config.ocio")
    assert (tmp_path / "c" / "luts" / "irid-css.clf").is_file()
    import PyOpenColorIO as ocio
    config = ocio.Config.CreateFromFile(path)
    config.validate()
    # An encoded source is decoded (BT.2020) before the matrix: white stays white, black black.
    p = config.getProcessor("rec2020", "srgb display", "unclipped",
                            ocio.TRANSFORM_DIR_FORWARD).getDefaultCPUProcessor()
    o = np.array([[1, 1, 1], [0, 0, 0], [0.5, 0.5, 0.5]], dtype=np.float32)
    p.applyRGB(o)
    want = irid.convert([[1, 1, 1], [0, 0, 0], [0.5, 0.5, 0.5]], "rec2020", "srgb")
    np.testing.assert_allclose(o, want, atol=1e-3)   # OCIO's BT.2020 break, not the standard's
    with pytest.raises(ValueError):
        irid.write_ocio_config(tmp_path / "d", "lab", "srgb")
    with pytest.raises(ValueError, match="source range"):
        irid.write_ocio_config(tmp_path / "d", methods=["css"], size=5, range=(2, 1))
    with pytest.raises(ValueError):
        irid.write_ocio_config(tmp_path / "d", methods=["css"], size=4)
    with pytest.raises(KeyError):
        irid.write_ocio_config(tmp_path / "d", methods=["nope"])
    with pytest.raises(ValueError):
        irid.write_ocio_config(tmp_path / "d", methods="smits")
    (tmp_path / "file").write_text("x")
    with pytest.raises(OSError):
        irid.write_ocio_config(tmp_path / "file", methods=["smits"], size=5)
