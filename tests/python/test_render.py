"""The renderer from Python: the same images as ``irid render``, scenes by name, file or dict."""

import json
import subprocess

import numpy as np
import pytest

import irid

from conftest import REPO

SMALL = dict(width=32, height=24, spp=1)


@pytest.fixture(scope="module")
def oil():
    return irid.render("oil-slick", **SMALL)


def test_images_and_stats(oil):
    linear, display = oil   # the pair the issue names
    assert linear.shape == display.shape == oil.xyz.shape == (24, 32, 3)
    assert linear.dtype == display.dtype == np.float32
    assert np.isfinite(linear).all() and np.isfinite(oil.xyz).all()
    assert display.min() >= 0.0 and display.max() <= 1.0
    s = oil.stats
    assert s["width"] == 32 and s["height"] == 24 and s["spp"] == 1
    assert s["camera_rays"] == 32 * 24 and s["rays"] >= s["camera_rays"]
    assert s["clip"] == "smits" and s["space"] == "srgb"


def rolloff(y, knee):
    """The default view's highlight roll-off (docs/RENDER.md): identity up to the knee,
    knee + (1 - knee) u / (1 + u) with u = (y - knee) / (1 - knee) above it."""
    u = np.maximum(y - knee, 0) / (1 - knee)
    return np.where(y > knee, knee + (1 - knee) * u / (1 + u), y)


def test_display_is_the_clipped_linear():
    # With render.view = "thesis": display = the sRGB encoding of the smits clip of the linear
    # image (the thesis' path, render.h).
    r = irid.render("oil-slick", set={"render.view": "thesis"}, **SMALL)
    assert r.stats["view"] == "thesis"
    expect = irid.convert(irid.clip(r.linear.astype(np.float64), "smits"), "srgb-linear", "srgb")
    np.testing.assert_allclose(r.display, expect, atol=2e-6)


def test_default_view_rolls_the_highlights_off(oil):
    # The default view scales each pixel by f(Y)/Y (Y from xyz) before the same clip.
    assert oil.stats["view"] == "rolloff"
    y = oil.xyz[..., 1].astype(np.float64)
    scale = np.where(y > 0.4, rolloff(y, 0.4) / np.maximum(y, 1e-30), 1.0)[..., None]
    expect = irid.convert(irid.clip(oil.linear.astype(np.float64) * scale, "smits"), "srgb-linear", "srgb")
    np.testing.assert_allclose(oil.display, expect, atol=2e-6)


def test_view_and_sky_from_set_and_the_command_line(irid_cli, tmp_path):
    # Over-exposed 20×, most of the image is above white: its display luminance is the curve's,
    # below white (smits keeps luminance), not clipped.
    knee = irid.render("oil-slick", set={"render.rolloff_knee": 0.2, "render.exposure": 18}, **SMALL)
    y = knee.xyz[..., 1].astype(np.float64)
    bright = y > 2
    assert bright.mean() > 0.5
    assert (knee.display[bright] < 254.5 / 255).any(axis=-1).all()
    shown = irid.convert(knee.display.astype(np.float64), "srgb", "srgb-linear")
    lum = shown @ np.array([0.2126, 0.7152, 0.0722])
    np.testing.assert_allclose(lum[bright], rolloff(y[bright], 0.2), atol=2e-4)
    gradient = irid.render("oil-slick", set={"light.sky": "gradient"}, **SMALL)
    hazy = irid.render("oil-slick", set={"light.turbidity": 8, "light.sky_scale": 0.1}, **SMALL)
    default = irid.render("oil-slick", **SMALL)
    assert not np.array_equal(gradient.linear, default.linear)
    assert not np.array_equal(hazy.linear, default.linear)
    png = tmp_path / "thesis.png"
    subprocess.run([irid_cli, "render", "oil-slick", "--width", "32", "--height", "24", "--spp", "1",
                    "--set", "render.view=thesis", "--set", "light.turbidity=8", "-q", "-o", str(png)],
                   check=True, capture_output=True)
    stored, _ = irid.read_image(png)
    same = irid.render("oil-slick", set={"render.view": "thesis", "light.turbidity": 8}, **SMALL)
    np.testing.assert_array_equal(np.round(stored * 255), np.round(same.display * 255))
    bad = subprocess.run([irid_cli, "render", "oil-slick", "--width", "8", "--height", "6", "--spp", "1",
                          "--set", "light.turbidity=12", "-q", "-o", str(tmp_path / "x.png")],
                         capture_output=True, text=True)
    assert bad.returncode == 2 and "'light.turbidity' is 12; allowed: [2, 10]" in bad.stderr


def test_same_as_the_command_line(oil, irid_cli, tmp_path):
    png = tmp_path / "oil.png"
    subprocess.run([irid_cli, "render", "oil-slick", "--width", "32", "--height", "24", "--spp", "1",
                    "-q", "-o", str(png)], check=True, capture_output=True)
    stored, meta = irid.read_image(png)
    assert meta["bits"] == 8
    np.testing.assert_array_equal(np.round(stored * 255), np.round(oil.display * 255))


def test_the_fourier_path_is_the_table_paths_colours_without_the_table():
    # render.path = "fourier": the exact film's colour per hit; against the table path (2 nm ×
    # 41 cos θ rows, within ΔE2000 0.36 of the exact colour) the images differ only by the
    # table's interpolation.
    a = irid.render("oil-slick", width=64, height=48, spp=1, set={"render.path": "fourier"})
    b = irid.render("oil-slick", width=64, height=48, spp=1)
    assert np.isfinite(a.xyz).all()
    lab = lambda x: irid.convert(x, "xyz", "lab")
    d = irid.delta_e(lab(a.xyz.reshape(-1, 3)), lab(b.xyz.reshape(-1, 3)))
    assert d.max() < 1.0 and d.mean() < 0.1
    with pytest.raises(ValueError, match="render.optics"):
        irid.render("oil-slick", width=8, height=8, set={"render.path": "fourier", "render.optics": "thesis"})


def test_threads_do_not_change_the_image(oil):
    one = irid.render("oil-slick", threads=1, **SMALL)
    np.testing.assert_array_equal(one.linear, oil.linear)


def test_scene_as_file_and_dict(oil, tmp_path):
    scene = json.loads((REPO / "scenes" / "oil-slick.json").read_text())
    from_dict = irid.render(scene, **SMALL)
    np.testing.assert_array_equal(from_dict.linear, oil.linear)
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(scene))
    np.testing.assert_array_equal(irid.render(path, **SMALL).linear, oil.linear)


def test_set_and_sizes():
    r = irid.render("soap-bubbles", width=40, spp=1, set={"render.path": "spectral", "soap.floor_checker": 0})
    assert r.linear.shape[1] == 40 and r.linear.shape[0] == 30   # 4:3 kept
    assert r.stats["width"] == 40
    seeded = irid.render("oil-slick", seed=7, **SMALL)
    assert irid.render("oil-slick", seed=7, **SMALL).linear.tobytes() == seeded.linear.tobytes()
    clipped = irid.render("oil-slick", clip="clamp", set={"render.view": "thesis"}, **SMALL)
    np.testing.assert_allclose(clipped.display, irid.convert(np.clip(clipped.linear.astype(np.float64), 0, 1),
                                                             "srgb-linear", "srgb"), atol=2e-6)


def test_morpho_renders():
    r = irid.render("morpho", width=24, height=18, spp=1)
    assert np.isfinite(r.linear).all()
    assert r.xyz[..., 2].max() > 0   # the wing's blue reaches the image


@pytest.mark.parametrize("kwargs, error", [
    (dict(scene="no-such-scene"), KeyError),
    (dict(scene="missing/scene.json"), OSError),
    (dict(scene=42), ValueError),
    (dict(scene="oil-slick", width=0), ValueError),
    (dict(scene="oil-slick", spp=5000), ValueError),
    (dict(scene="oil-slick", clip="nope"), KeyError),
    (dict(scene="oil-slick", set={"oil.k1": "many"}), ValueError),
    (dict(scene="oil-slick", set={"oil.no_such_key": 1}), ValueError),
    (dict(scene="oil-slick", set={"oil.k1": float("nan")}), ValueError),
    (dict(scene="oil-slick", set={"render.view": "filmic"}), ValueError),
    (dict(scene="oil-slick", set={"light.sky": "hosek"}), ValueError),
    (dict(scene="oil-slick", set={"light.sun_direction": [0, -1, 0]}), ValueError),
    (dict(scene={"scene": "oil-slick", "image": {"width": -3}}), ValueError),
    (dict(scene="oil-slick", threads=-1), ValueError),
])
def test_bad_input(kwargs, error):
    with pytest.raises(error):
        irid.render(**kwargs)


def test_messages_name_the_key():
    with pytest.raises(ValueError, match="oil.k1"):
        irid.render("oil-slick", set={"oil.k1": -5}, **SMALL)


def test_gallery_rejects_bad_options(tmp_path):
    with pytest.raises(ValueError):
        irid.gallery(tmp_path, width=10)
    (tmp_path / "file").write_text("x")
    with pytest.raises(OSError):
        irid.gallery(tmp_path / "file" / "sub", width=32, height=24, spp=1, figure_width=320)


def test_gallery_refuses_a_linked_page_that_is_not_in_the_folder(tmp_path):
    # Checked before anything is rendered, so these are quick.
    with pytest.raises(ValueError, match="missing.html"):
        irid.gallery(tmp_path, pages={"missing.html": "Missing"})
    with pytest.raises(ValueError, match="outside.html"):
        irid.gallery(tmp_path, pages={"../outside.html": "Outside"})
    with pytest.raises(ValueError, match="pages"):
        irid.gallery(tmp_path, pages=[("a.html", "A")])


def test_render_arguments_refused_as_the_library_says():
    with pytest.raises(ValueError, match="set: list"):
        irid.render("oil-slick", set=[("oil.k1", 2)], width=8, height=8)
    # The samples' range is the scene reader's, said once: [1, 1024].
    with pytest.raises(ValueError, match="1024"):
        irid.render("oil-slick", spp=2000, width=8, height=8)
    with pytest.raises(ValueError, match="spp"):
        irid.render("oil-slick", spp=1.5, width=8, height=8)
