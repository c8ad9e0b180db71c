"""The film colour as a shader chunk from Python: irid.write_film_shader's three files, and its
table against the transform computed here in numpy from the CIE tables (irid.cmfs,
irid.illuminant) and the sRGB matrix (irid.convert): V_c(τ) = Σ_i w_c,i e^(2πiτ(ν_i − ν_c)),
the channels' weights w_c the illuminant × matching functions in linear sRGB, each channel's
centre ν_c = Σ w_c ν / Σ w_c (docs/OPTICS.md, "In a renderer")."""

import json
import os
import re

import numpy as np
import pytest

import irid


def read_table(paths):
    with open(paths[2]) as f:
        meta = json.load(f)
    texels = np.fromfile(paths[1], dtype="<f4")
    return meta, texels.reshape(meta["height"], meta["width"], 4)


def test_writes_the_three_files(tmp_path):
    paths = irid.write_film_shader(tmp_path / "shader")
    assert [os.path.basename(p) for p in paths] == [
        "irid_iridescence.glsl", "irid_film_table.f32", "irid_film_table.json"]
    meta, table = read_table(paths)
    assert set(meta) == {"width", "height", "uniform", "illuminant", "space", "primaries", "white",
                         "filter"}
    assert (meta["uniform"], meta["illuminant"], meta["space"], meta["filter"]) == (
        "iridFilmTable", "D65", "srgb-linear", "nearest")
    assert (meta["primaries"], meta["white"]) == ([0.64, 0.33, 0.3, 0.6, 0.15, 0.06], [0.3127, 0.329])
    assert os.path.getsize(paths[1]) == meta["width"] * meta["height"] * 16
    chunk = open(paths[0]).read()
    assert "vec3 evalIridescence(float outsideIOR, float eta2, float cosTheta1, " \
           "float thinFilmThickness, vec3 baseF0)" in chunk
    assert chunk.count("uniform ") == 1 and "#version" not in chunk


def test_table_is_the_transform_of_the_weights(tmp_path):
    paths = irid.write_film_shader(tmp_path)
    meta, table = read_table(paths)
    chunk = open(paths[0]).read()
    centre = np.array([float(v) for v in re.search(
        r"const vec3 IRID_CENTRE = vec3\(([^,]+), ([^,]+), ([^)]+)\);", chunk).groups()])
    step = 1.0 / float(re.search(r"const float IRID_INV_STEP = ([^;]+);", chunk).group(1))
    wavelengths, cmf = irid.cmfs("cie1931")
    _, power = irid.illuminant("D65")
    xyz_weights = power[:, None] * cmf / np.sum(power * cmf[:, 1])
    # XYZ → linear sRGB applied to each wavelength's weights. The colorimeter adapts (Bradford)
    # from the white of its 1 nm sum to sRGB's D65 chromaticity, which differ in the fifth
    # decimal: hence the tolerances below, far tighter than any error of layout, step or sign.
    weights = irid.convert(xyz_weights, "xyz", "srgb-linear")
    nu = 1.0 / wavelengths
    np.testing.assert_allclose(centre, (weights * nu[:, None]).sum(0) / weights.sum(0), rtol=1e-4)
    for k in (0, 1, 2, 17, 100, meta["width"] - 1):
        tau = (k - 1) * step
        v = (weights * np.exp(2j * np.pi * tau * (nu[:, None] - centre[None, :]))).sum(0)
        np.testing.assert_allclose(table[0, k, :3], v.real, atol=2e-3)
        np.testing.assert_allclose(table[1, k, :3], v.imag, atol=2e-3)
        assert table[0, k, 3] == 0.0 and table[1, k, 3] == 0.0
    # Texel 1 is τ = 0: the white, (1, 1, 1).
    np.testing.assert_allclose(table[0, 1, :3], 1.0, atol=1e-4)


def test_other_colorimeters_and_refusals(tmp_path):
    paths = irid.write_film_shader(tmp_path, illuminant="d50", space="Display-P3")
    meta, _ = read_table(paths)
    # Recorded one way whatever the case; the space as the linear form the values are in.
    assert (meta["illuminant"], meta["space"]) == ("D50", "display-p3-linear")
    assert meta["primaries"] == [0.68, 0.32, 0.265, 0.69, 0.15, 0.06]
    with pytest.raises(ValueError, match="rec2020-linear"):
        irid.write_film_shader(tmp_path / "pq", space="rec2100-pq")
    assert not (tmp_path / "pq").exists()
    with pytest.raises(KeyError, match="wgsl"):
        irid.write_film_shader(tmp_path / "a", lang="hlsl")
    wgsl = irid.write_film_shader(tmp_path / "wgsl", lang="wgsl")
    assert os.path.basename(wgsl[0]) == "irid_iridescence.wgsl"
    assert "fn irid_eval(table: texture_2d<f32>," in open(wgsl[0]).read()
    with pytest.raises(KeyError, match="srgb"):
        irid.write_film_shader(tmp_path / "b", space="no-such-space")
    with pytest.raises((KeyError, ValueError)):
        irid.write_film_shader(tmp_path / "c", illuminant="D12")
    assert not (tmp_path / "a").exists() and not (tmp_path / "b").exists()
    (tmp_path / "file").write_text("x")
    with pytest.raises(OSError):
        irid.write_film_shader(tmp_path / "file" / "sub")
