"""irid display IN OUT: an image through the ACES 2.0 display chain to a display encoding, checked
pixel by pixel against irid.display_transform (itself checked against OpenColorIO's outputs)."""

import subprocess

import numpy as np
import pytest

import irid


def scene_image(height=24, width=40, seed=5):
    """ACES2065-1 colours from deep shadow to 64 (HDR highlights), some negative."""
    rng = np.random.default_rng(seed)
    img = rng.uniform(-0.05, 1.0, size=(height, width, 3)) * (2.0 ** rng.uniform(-8, 6, size=(height, width, 1)))
    img[0, 0] = [0.18, 0.18, 0.18]
    img[0, 1] = [64.0, 64.0, 64.0]
    return img.astype(np.float32)


def run(cli, *args, expect=0):
    r = subprocess.run([cli, "display", *map(str, args)], capture_output=True, text=True)
    assert r.returncode == expect, r.stderr
    return r


def test_an_sdr_png_holds_the_srgb_code_values_of_the_transform(irid_cli, tmp_path):
    scene = scene_image()
    src, out = tmp_path / "scene.exr", tmp_path / "out.png"
    irid.write_image(src, scene, color_space="aces2065-1-linear")
    run(irid_cli, "--view", "aces2", "--display", "sdr-100nit-rec709", src, out)
    got, meta = irid.read_image(out)
    want = irid.display_transform(scene, display="sdr-100nit-rec709", target="srgb")
    assert meta["bits"] == 8 and meta["color_space"] == "srgb"
    assert meta["icc_profile"] == irid.icc_profile("srgb") or irid.image_space(meta)["space"] == "srgb"
    assert np.max(np.abs(got - np.clip(want, 0, 1))) <= 0.5 / 255 + 1e-6
    # 0.18 grey is about 10 cd/m² (the published mid grey), the brightest at most the white.
    assert abs(irid.convert(got[0, 0], "srgb", "srgb-linear")[1] - 0.1) < 0.01
    assert np.all(got <= 1.0)


@pytest.mark.parametrize("display, to, bits", [("sdr-100nit-rec709", "srgb", 8),
                                              ("sdr-100nit-rec709", "rec1886", 8),
                                              ("hdr-108nit-p3-d65", "p3-d65", 8),
                                              ("sdr-100nit-p3-d65", "rec1886", 16),
                                              ("hdr-1000nit-p3-d65", "p3-d65-pq", 16),
                                              ("hdr-4000nit-rec2020", "rec2100-pq", 16)])
def test_an_encoded_file_holds_the_double_chains_codes(irid_cli, tmp_path, display, to, bits):
    # The float kernel writes the 8-bit files, and hands each colour whose error bound could
    # change a code to the double chain; the double chain writes the 16-bit ones. (On this
    # sample, and on 512 x 512 of it, the kernel's actual errors changed no 8-bit code even
    # without that recomputation: it guarantees the worst case.) Every code is the double
    # chain's, except where its value lies
    # within 0.01 of a code of a rounding boundary (where float32, which both are stored as
    # before the writer rounds, decides). Shadows down to 2^-14, saturated colours whose small
    # channels sit on the steep foot of the curves, and highlights.
    rng = np.random.default_rng(21)
    scene = (rng.uniform(-0.1, 1.0, size=(128, 128, 3)) *
             2.0 ** rng.uniform(-14, 6, size=(128, 128, 1))).astype(np.float32)
    src, out = tmp_path / "scene.exr", tmp_path / "out.png"
    irid.write_image(src, scene, color_space="aces2065-1-linear")
    run(irid_cli, "--view", "aces2", "--display", display, "--to", to, "--bits", bits, src, out)
    got, meta = irid.read_image(out)
    assert meta["bits"] == bits
    levels = 2.0 ** bits - 1
    want = np.clip(irid.display_transform(scene.astype(np.float64), display=display, target=to), 0, 1) * levels
    boundary = np.abs(want - np.floor(want) - 0.5) < 0.01
    differ = (np.rint(got * levels) != np.floor(want + 0.5)) & ~boundary
    assert not differ.any(), (np.argwhere(differ)[:5], got[differ][:5] * levels, want[differ][:5])


def test_an_hdr_png_is_16_bit_pq_and_an_exr_is_linear_with_its_chromaticities(irid_cli, tmp_path):
    scene = scene_image(seed=6)
    src = tmp_path / "scene.exr"
    irid.write_image(src, scene, color_space="aces2065-1-linear")
    run(irid_cli, "--view", "aces2", "--display", "hdr-1000nit-p3-d65", src, tmp_path / "pq.png")
    got, meta = irid.read_image(tmp_path / "pq.png")
    want = irid.display_transform(scene, display="hdr-1000nit-p3-d65", target="p3-d65-pq")
    assert meta["bits"] == 16 and meta["color_space"] == "p3-d65-pq" and meta["icc_profile"] is None
    assert np.max(np.abs(got - want)) <= 0.5 / 65535 + 1e-6
    # 1000 cd/m² is PQ's 0.7518; nothing above it.
    assert np.max(got) <= 0.7519
    run(irid_cli, "--view", "aces2", "--display", "hdr-1000nit-p3-d65", src, tmp_path / "lin.exr")
    lin, meta = irid.read_image(tmp_path / "lin.exr")
    want = irid.display_transform(scene, display="hdr-1000nit-p3-d65", target="p3-d65-pq-linear")
    # Linear float to linear float runs the float kernel, within 1e-5 of max(|value|, 1).
    assert np.allclose(lin, want, rtol=1e-5, atol=1e-5)
    assert np.allclose(meta["chromaticities"], [0.68, 0.32, 0.265, 0.69, 0.15, 0.06, 0.3127, 0.329])
    assert np.max(lin) <= 10.0 + 1e-6


def test_the_scene_space_is_the_files_or_from_and_aces_when_it_says_nothing(irid_cli, tmp_path):
    scene = scene_image(seed=7)
    want = irid.display_transform(scene, display="sdr-100nit-p3-d65", target="display-p3-linear")
    # A file of linear sRGB (its chromaticities say so) is converted to ACES2065-1 first.
    srgb = irid.convert(scene, "aces2065-1-linear", "srgb-linear").astype(np.float32)
    irid.write_image(tmp_path / "srgb.exr", srgb, color_space="srgb-linear")
    run(irid_cli, "--display", "sdr-100nit-p3-d65", tmp_path / "srgb.exr", tmp_path / "a.exr")
    a, _ = irid.read_image(tmp_path / "a.exr")
    assert np.allclose(a, want, rtol=1e-4, atol=1e-5)
    # A file that says nothing is ACES2065-1; --from overrides what a file says.
    irid.write_image(tmp_path / "bare.exr", scene, tag=False)
    run(irid_cli, "--display", "sdr-100nit-p3-d65", tmp_path / "bare.exr", tmp_path / "b.exr")
    b, _ = irid.read_image(tmp_path / "b.exr")
    assert np.allclose(b, want, rtol=1e-5, atol=1e-5)
    r = run(irid_cli, "--display", "sdr-100nit-p3-d65", "--from", "aces2065-1-linear", tmp_path / "srgb.exr",
            tmp_path / "c.exr")
    assert "--from" in r.stderr
    c, _ = irid.read_image(tmp_path / "c.exr")
    over = irid.display_transform(srgb, display="sdr-100nit-p3-d65", target="display-p3-linear")
    assert np.allclose(c, over, rtol=1e-5, atol=1e-5)


def test_alpha_passes_and_exr_colour_stays_premultiplied(irid_cli, tmp_path):
    scene = scene_image(4, 4, seed=8)
    alpha = np.full((4, 4, 1), 0.5, np.float32)
    alpha[0, 0] = 0.0
    rgba = np.concatenate([scene * alpha, alpha], axis=-1)
    rgba[0, 0, :3] = scene[0, 0]  # light added without covering
    irid.write_image(tmp_path / "a.exr", rgba, color_space="aces2065-1-linear")
    run(irid_cli, "--display", "sdr-100nit-rec709", tmp_path / "a.exr", tmp_path / "o.exr")
    got, meta = irid.read_image(tmp_path / "o.exr")
    assert meta["channels"] == ["R", "G", "B", "A"]
    want = irid.display_transform(scene, display="sdr-100nit-rec709", target="srgb-linear")
    assert np.allclose(got[..., 3], alpha[..., 0])
    assert np.allclose(got[1:, :, :3], want[1:] * 0.5, rtol=1e-5, atol=1e-5)
    assert np.allclose(got[0, 0, :3], want[0, 0], rtol=1e-5, atol=1e-5)
    run(irid_cli, "--display", "sdr-100nit-rec709", tmp_path / "a.exr", tmp_path / "o.png")
    png, _ = irid.read_image(tmp_path / "o.png")
    enc = irid.display_transform(scene, display="sdr-100nit-rec709", target="srgb")
    assert np.max(np.abs(png[1:, :, :3] - enc[1:])) <= 0.5 / 255 + 1e-6  # PNG: unassociated


def test_custom_displays_other_encodings_and_refusals(irid_cli, tmp_path):
    scene = scene_image(6, 6, seed=9)
    irid.write_image(tmp_path / "s.exr", scene, color_space="aces2065-1-linear")
    custom = "custom:peak=600,limiting=display-p3,encoding=rec2020"
    run(irid_cli, "--display", custom, tmp_path / "s.exr", tmp_path / "c.tif")
    got, meta = irid.read_image(tmp_path / "c.tif")
    assert meta["bits"] == 16
    want = irid.display_transform(scene, display=custom, target="rec2100-pq")
    assert np.max(np.abs(got - want)) <= 0.5 / 65535 + 1e-6
    # An HDR display written in sRGB clips what is brighter than 100 cd/m², and says so.
    r = run(irid_cli, "--display", "hdr-1000nit-rec2020", "--to", "srgb", tmp_path / "s.exr", tmp_path / "b.png")
    assert "clipped" in r.stderr
    r = run(irid_cli, "--display", "sdr-100nit-rec709", "--to", "rec1886", "--bits", "16", tmp_path / "s.exr",
            tmp_path / "g.png")
    got, meta = irid.read_image(tmp_path / "g.png")
    want = irid.display_transform(scene, display="sdr-100nit-rec709", target="rec1886")
    assert meta["bits"] == 16 and meta["color_space"] == "rec1886"
    assert np.max(np.abs(got - want)) <= 0.5 / 65535 + 1e-6
    for args, message in [
        (["--display", "sdr-100nit-p3-d60-in-xyz-e"], "--to"),
        (["--display", "sdr-100nit-rec709", "--to", "lab"], "not an RGB space"),
        (["--display", "sdr-100nit-rec709", "--inverse"], "--inverse"),
        (["--display", "sdr-100nit-rec709", "--bits", "12"], "8 and 16"),
        (["--display", "custom:peak=50,limiting=srgb"], "100 to 10000"),
        (["--display", "sdr-100nit-rec709", "--from", "nonsense"], "nonsense"),
    ]:
        r = run(irid_cli, *args, tmp_path / "s.exr", tmp_path / "x.png", expect=2)
        assert message in r.stderr, (args, r.stderr)
        assert not (tmp_path / "x.png").exists()
    r = run(irid_cli, "--display", "sdr-100nit-rec709", tmp_path / "missing.exr", tmp_path / "x.png", expect=1)
    assert "missing.exr" in r.stderr and not (tmp_path / "x.png").exists()
    # PQ and HLG in a JPEG: 8 lossy bits and no tag for the curve (readers take the codes for
    # sRGB); an SDR display's JPEG is written, with its profile.
    for args, message in [(["--display", "hdr-1000nit-p3-d65"], "p3-d65-pq in a JPEG"),
                          (["--display", "hdr-1000nit-rec2020", "--to", "rec2100-hlg"], "HLG's steps")]:
        r = run(irid_cli, *args, tmp_path / "s.exr", tmp_path / "x.jpg", expect=2)
        assert message in r.stderr and "PNG or TIFF" in r.stderr, (args, r.stderr)
        assert not (tmp_path / "x.jpg").exists()
    run(irid_cli, "--display", "sdr-100nit-p3-d65", tmp_path / "s.exr", tmp_path / "p3.jpg")
    got, meta = irid.read_image(tmp_path / "p3.jpg")
    assert irid.read_icc_profile(meta["icc_profile"])["description"] == "display-p3 (irid)"
    with pytest.raises(ValueError, match="rec2100-pq in a JPEG"):
        irid.write_image(tmp_path / "w.jpg", np.full((2, 2, 3), 0.5), color_space="rec2100-pq")
    assert not (tmp_path / "w.jpg").exists()
