"""Optics from Python: materials, the film models, the thesis' closed forms and colour tables.

References: the Airy sum and Fresnel's equations written here in numpy (Born & Wolf §1.5,
§7.6.1), the quarter-wave closed form, the thesis' equations as printed (Smits 1990, eq. 21,
25, 26, 29), and CIE colorimetry through irid.spectrum_to_xyz (a separate code path)."""

import csv
import io
import pickle
import subprocess

import numpy as np
import pytest

import irid

LAMBDA = np.arange(380.0, 781.0, 5.0)


def airy(n0, n1, n2, d, lam, theta0=0.0, pol="s"):
    """Reflectance of ambient n0 | film n1 (d nm) | substrate n2, real indices, by Fresnel and
    the Airy sum, for s or p light (Born & Wolf §1.5.2, §7.6.1)."""
    s = n0 * np.sin(theta0)
    c0, c1, c2 = (np.sqrt(1 - (s / n) ** 2 + 0j) for n in (n0, n1, n2))
    if pol == "s":
        r01 = (n0 * c0 - n1 * c1) / (n0 * c0 + n1 * c1)
        r12 = (n1 * c1 - n2 * c2) / (n1 * c1 + n2 * c2)
    else:
        r01 = (n1 * c0 - n0 * c1) / (n1 * c0 + n0 * c1)
        r12 = (n2 * c1 - n1 * c2) / (n2 * c1 + n1 * c2)
    z = np.exp(2j * 2 * np.pi * n1 * d * c1 / lam)
    r = (r01 + r12 * z) / (1 + r01 * r12 * z)
    return np.abs(r) ** 2


# --- Materials ---------------------------------------------------------------------------------

def test_material_forms():
    assert "water" in irid.materials() and "silver" in irid.materials()
    assert irid.Material("1.5").index([500.0])[0] == 1.5
    n = irid.Material("1.5+0.02i").index(np.array([[400.0, 600.0]]))
    assert n.shape == (1, 2) and n.dtype == np.complex128 and np.all(n == 1.5 + 0.02j)
    assert not irid.Material("1.5+0.02i").is_lossless
    # Cauchy: n = A + B/λ² (λ in µm).
    c = irid.Material.cauchy("glass", 1.5, 0.004)
    assert c.index([500.0])[0].real == pytest.approx(1.5 + 0.004 / 0.25, abs=1e-15)
    # Sellmeier, Malitson's fused silica (J. Opt. Soc. Am. 55, 1205, 1965): n(587.6 nm) = 1.4585.
    silica = irid.Material.sellmeier("silica", [(0.6961663, 0.0684043 ** 2), (0.4079426, 0.1162414 ** 2),
                                                (0.8974794, 9.896161 ** 2)])
    assert silica.index([587.6])[0].real == pytest.approx(1.4585, abs=1e-4)
    assert silica.name == "silica"


def test_material_csv(tmp_path):
    p = tmp_path / "m.csv"
    p.write_text("wavelength_nm,n,k\n400,1.4,0\n600,1.6,0.1\n")
    m = irid.Material.read_csv(str(p))
    assert m.name == "m"
    assert m.index([500.0])[0] == pytest.approx(1.5 + 0.05j)
    with pytest.raises(OSError):
        irid.Material.read_csv(str(tmp_path / "missing.csv"))
    # A first line of numbers with other separators is data, and an error at line 1 (not a
    # header over an empty table); a header names the three columns (issue 37, item 1).
    for text in ["400;1.4;0\n", "400 1.4 0\n600 1.6 0.1\n", "n;k\n400,1.4,0\n"]:
        p.write_text(text)
        with pytest.raises(ValueError, match=r"m\.csv:1: field 1 .* is not a number; line 1 holds 3 numbers"):
            irid.Material.read_csv(str(p))


def test_material_errors():
    with pytest.raises(ValueError):
        irid.Material("unobtainium")   # the class itself: the library's ValueError
    with pytest.raises(ValueError):
        irid.Material.constant("x", -1.0)
    with pytest.raises(ValueError):
        irid.Material("water").index([0.0])
    with pytest.raises(KeyError, match="unobtainium"):
        irid.Film.exact([("unobtainium", 100)])
    with pytest.raises(ValueError):
        irid.Film.exact([("1.5+x", 100)])


# --- The exact model against Fresnel and Airy ----------------------------------------------------

def test_exact_single_film_is_airy():
    # Ambient and substrate of index 1 (the material "air", the default, has air's dispersion).
    f = irid.Film.exact([(1.33, 350.0)], ambient=1.0, substrate=1.0)
    R, T = f.reflectance(LAMBDA)
    assert R.shape == LAMBDA.shape
    np.testing.assert_allclose(R, airy(1.0, 1.33, 1.0, 350.0, LAMBDA), rtol=0, atol=1e-12)
    np.testing.assert_allclose(R + T, 1.0, atol=1e-12)   # lossless: nothing absorbed


@pytest.mark.parametrize("pol", ["s", "p"])
def test_exact_oblique_polarized(pol):
    R, _ = irid.film_reflectance([(1.45, 420.0)], LAMBDA, angle=50.0, polarization=pol,
                                 ambient=1.0, substrate=1.33)
    np.testing.assert_allclose(R, airy(1.0, 1.45, 1.33, 420.0, LAMBDA, np.radians(50.0), pol),
                               atol=1e-12)


def test_quarter_wave_coating():
    # MgF2 (1.38) a quarter wave thick at 550 nm on glass (1.52): R = ((n0 n2 − n1²)/(n0 n2 + n1²))².
    f = irid.Film.exact([(1.38, 550.0 / (4 * 1.38))], ambient=1.0, substrate=1.52)
    R, _ = f.reflectance([550.0])
    assert R[0] == pytest.approx(((1.52 - 1.38 ** 2) / (1.52 + 1.38 ** 2)) ** 2, abs=1e-12)


def test_two_layers_and_thickness_replacement():
    # The second layer of thickness 0 changes nothing; thickness= replaces the first layer's.
    one = irid.Film.exact([(1.33, 200.0)])
    two = irid.Film.exact([(1.33, 100.0), (2.0, 0.0)])
    np.testing.assert_allclose(two.reflectance(LAMBDA, thickness=200.0)[0], one.reflectance(LAMBDA)[0],
                               atol=1e-12)


def test_wavelengths_any_shape_and_layout():
    f = irid.Film.exact([("water", 300.0)])
    w = np.linspace(400, 700, 12).reshape(3, 4)
    R, _ = f.reflectance(w.T)   # not C-contiguous
    assert R.shape == (4, 3)
    np.testing.assert_allclose(R, f.reflectance(np.ascontiguousarray(w.T))[0])


# --- The thesis' closed forms ---------------------------------------------------------------------

def test_eq21_and_eq22():
    lam, t, n = 500.0, np.array([0.0, 80.0, 120.0]), 1.33
    np.testing.assert_allclose(irid.thesis_film_reflectance(lam, t, n, True, 0.5),
                               0.25 * np.sin(2 * np.pi * t * n / lam) ** 2, atol=1e-15)
    np.testing.assert_allclose(irid.thesis_film_reflectance(lam, t, n, False, 1.0),
                               np.cos(2 * np.pi * t * n / lam) ** 2, atol=1e-15)
    assert irid.thesis_film_reflectance(lam, 0.0, n, True, 1.0) == 0.0   # exactly black
    assert bool(irid.thesis_phase_change(1.0, 1.33, 1.0))
    assert not bool(irid.thesis_phase_change(1.0, 1.4, 1.5))


def test_eq23_24_snell_and_effective_thickness():
    theta = irid.thesis_film_angle(30.0, 1.33)
    assert theta == pytest.approx(np.degrees(np.arcsin(0.5 / 1.33)))
    assert irid.thesis_effective_thickness(100.0, 1.33, 0.0) == pytest.approx(133.0)
    assert irid.thesis_film_angle(80.0, 0.9, 1.0) == pytest.approx(90.0)   # beyond critical


def test_eq25_26_and_peak():
    l = 12
    k = irid.thesis_unit_peak_k(l)
    assert k == pytest.approx(2 / (l + 1) ** 2)
    # At t = λ/2 every beam is in phase: ½K(l+1)² = 1.
    assert irid.thesis_multilayer_reflectance(500.0, 250.0, l, k) == pytest.approx(1.0, abs=1e-12)
    t = np.array([60.0, 90.0])
    x = 2 * np.pi * t / 450.0
    np.testing.assert_allclose(irid.thesis_multilayer_reflectance(450.0, t, l, 1.0),
                               0.5 * (np.sin((l + 1) * x) / np.sin(x)) ** 2, rtol=1e-12)
    assert irid.thesis_multilayer_effective_thickness(100.0, 1.56, 40.0) == pytest.approx(
        100 * np.sqrt(1.56 ** 2 - np.sin(np.radians(40)) ** 2))


def test_eq29_morpho():
    a = np.array([0.0, 30.0, 60.0])
    expect = 150 * np.cos(np.radians(a)) + 50 * np.sqrt(1.56 ** 2 - np.sin(np.radians(a)) ** 2)
    np.testing.assert_allclose(irid.morpho_effective_thickness(a), expect, rtol=1e-14)
    wing = irid.Film.morpho()
    np.testing.assert_allclose(wing.effective_thickness(a), expect, rtol=1e-14)
    R, T = wing.reflectance(LAMBDA, angle=30.0)
    np.testing.assert_allclose(R, irid.morpho_reflectance(LAMBDA, 30.0), rtol=1e-12)
    assert np.all(T == 0) and R.max() <= 1.0 + 1e-12


def test_thesis_film_matches_closed_form_with_snell():
    # A film of constant index: eq. 21 with t' = t n cos θ_film and the matched K.
    f = irid.Film.thesis(1.33, 300.0, ambient=1.0, substrate=1.0)
    k = irid.thesis_matched_k(1.33, ambient=1.0, substrate=1.0)
    assert k == pytest.approx(2 * 0.33 / 2.33)   # |r01| + |r12| for 1 | 1.33 | 1
    theta_film = np.arcsin(np.sin(np.radians(40.0)) / 1.33)
    t_eff = 300.0 * 1.33 * np.cos(theta_film)
    R, _ = f.reflectance(LAMBDA, angle=40.0)
    np.testing.assert_allclose(R, k ** 2 * np.sin(2 * np.pi * t_eff / LAMBDA) ** 2, atol=1e-13)
    # k=1 is the thesis as written; phase_change=False forces eq. 22.
    R22, _ = irid.Film.thesis(1.33, 300.0, k=1.0, phase_change=False).reflectance([500.0])
    assert R22[0] == pytest.approx(np.cos(2 * np.pi * 300 * 1.33 / 500) ** 2)


def test_thesis_multilayer_film():
    f = irid.Film.thesis_multilayer(1.56, 100.0, 12)
    R, _ = f.reflectance(LAMBDA, angle=20.0)
    t = irid.thesis_multilayer_effective_thickness(100.0, 1.56, 20.0)
    np.testing.assert_allclose(R, irid.thesis_multilayer_reflectance(LAMBDA, t, 12, 2 / 169), rtol=1e-12)


# --- Colours ----------------------------------------------------------------------------------------

def test_film_color_is_the_spectrum_colour():
    f = irid.Film.exact([("water", 350.0)])
    w = np.arange(360.0, 831.0)
    R, _ = f.reflectance(w, angle=25.0)
    xyz = irid.spectrum_to_xyz(w, R)
    c = f.color(angle=25.0)
    np.testing.assert_allclose(c.xyz, xyz, atol=1e-12)
    # sRGB linear of that XYZ: the colorimeter adapts (Bradford) from the white of the D65 table
    # (x, y = 0.31272, 0.32903) to sRGB's rounded one (0.3127, 0.3290), convert() does not; the
    # two whites differ by 3e-5 in xy, the colours by less than 3e-5.
    np.testing.assert_allclose(c.rgb, irid.convert(xyz, "xyz", "srgb-linear"), atol=3e-5)


def test_film_color_broadcasts_thickness_and_angle():
    f = irid.Film.exact([("water", 0.0)])
    t = np.array([0.0, 200.0, 400.0])[:, None]
    a = np.array([0.0, 45.0])
    c = irid.film_color(f, thickness=t, angle=a)
    assert c.xyz.shape == (3, 2, 3) and c.rgb.shape == (3, 2, 3)
    np.testing.assert_allclose(c.xyz[0], 0.0, atol=1e-15)   # no film, air on air: black
    for i in range(3):
        for j in range(2):
            np.testing.assert_allclose(c.xyz[i, j], f.color(float(t[i, 0]), float(a[j])).xyz, atol=1e-14)
    # A white reflector would be (1, 1, 1) in RGB: a film never exceeds what it reflects.
    assert np.all(c.xyz[..., 1] <= 1.0)


def test_fourier_integration_matches_the_sum_and_the_closed_forms():
    # A constant-index film on glass: the series against the 1 nm sum within ΔE2000 0.2 over
    # thickness × angle, the bare interface at zero thickness (Fresnel, written here) and the
    # incoherent sum of the faces for a 1 mm film.
    f = irid.Film.exact([(1.33, 0.0)], ambient=1.0, substrate=1.5)
    t = np.linspace(0.0, 2000.0, 41)[:, None]
    a = np.array([0.0, 30.0, 60.0, 85.0])
    exact = f.color(t, a)
    fast = f.color(t, a, integration="fourier")
    lab = lambda x: irid.convert(x, "xyz", "lab")
    assert irid.delta_e(lab(exact.xyz), lab(fast.xyz)).max() < 0.2
    bare = f.color(0.0, [0.0, 45.0], integration="fourier")
    r = [0.5 * (airy(1.0, 1.5, 1.5, 0.0, 500.0, np.radians(x), "s") + airy(1.0, 1.5, 1.5, 0.0, 500.0, np.radians(x), "p"))
         for x in (0.0, 45.0)]
    np.testing.assert_allclose(bare.xyz[:, 1], np.ravel(r), atol=2e-6)
    r01, r12 = (0.33 / 2.33) ** 2, (0.17 / 2.83) ** 2
    thick = f.color(1e6, 0.0, integration="fourier")
    np.testing.assert_allclose(thick.xyz[1], r01 + (1 - r01) ** 2 * r12 / (1 - r01 * r12), atol=1e-9)
    # The same through film_color, and what it does not cover is refused.
    np.testing.assert_allclose(irid.film_color([(1.33, 300.0)], angle=20.0, integration="fourier").xyz,
                               irid.film_color([(1.33, 300.0)], angle=20.0).xyz, atol=2e-4)
    with pytest.raises(ValueError, match="one layer"):
        irid.Film.exact([(1.33, 100.0), (2.0, 50.0)]).color(integration="fourier")
    with pytest.raises(ValueError, match="exact film"):
        irid.Film.thesis("water", 300.0).color(integration="fourier")
    with pytest.raises(KeyError, match="sum, fourier"):
        f.color(100.0, integration="fft")


def test_every_model_colours():
    for f in (irid.Film.exact([(1.33, 300.0)], polarization="s"), irid.Film.thesis("water", 300.0),
              irid.Film.thesis_multilayer("chitin", 100.0, 12), irid.Film.morpho(blend=True)):
        c = f.color(angle=[0.0, 30.0]) if f.model == "morpho" else f.color([100.0, 300.0], [0.0, 30.0])
        assert c.xyz.shape == (2, 3) and np.isfinite(c.xyz).all() and np.all(c.xyz >= -1e-12)


def test_cli_agrees(irid_cli):
    out = subprocess.run([irid_cli, "film", "--layer", "water:350", "--angle", "30",
                          "--wavelengths", "400:700:50"], capture_output=True, text=True, check=True)
    rows = list(csv.DictReader(io.StringIO(out.stdout)))
    w = np.array([float(r["wavelength_nm"]) for r in rows])
    R, T = irid.Film.exact([("water", 350.0)]).reflectance(w, angle=30.0)
    np.testing.assert_allclose(R, [float(r["R"]) for r in rows], rtol=1e-12)
    np.testing.assert_allclose(T, [float(r["T"]) for r in rows], rtol=1e-12)


# --- Tables -------------------------------------------------------------------------------------------

def test_color_table_lookup():
    f = irid.Film.exact([("water", 0.0)])
    table = f.color_table(1000.0, step=2.0)
    assert table.step == 2.0 and table.thickness[0] == 0.0 and table.thickness[-1] == 1000.0
    xyz, rgb = table.at([300.0, 301.0, 2000.0])
    np.testing.assert_allclose(xyz[0], f.color(300.0).xyz, atol=1e-14)   # a node
    np.testing.assert_allclose(xyz[1], 0.5 * (f.color(300.0).xyz + f.color(302.0).xyz), atol=1e-14)
    np.testing.assert_allclose(xyz[2], f.color(1000.0).xyz, atol=1e-14)   # clamped
    two = f.color_table_2d(500.0, step=5.0, max_angle=60.0, cos_steps=10)
    xyz2, _ = two.at([250.0], [1.0])
    np.testing.assert_allclose(xyz2[0], f.color(250.0).xyz, atol=1e-14)


def test_thesis_table_scales_by_k_squared():
    table = irid.thesis_film_table(True, 1000.0, 1.0)
    w = np.arange(360.0, 831.0)
    direct = irid.spectrum_to_xyz(w, irid.thesis_film_reflectance(w, 250.0, 1.0, True, 1.0))
    np.testing.assert_allclose(table.at([250.0], 1.0)[0], direct, atol=1e-12)
    np.testing.assert_allclose(table.at([250.0], 0.5)[0], 0.25 * direct, atol=1e-12)


# --- Bad input ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("call, error", [
    (lambda: irid.Film.exact([("water", -1.0)]), ValueError),
    (lambda: irid.Film.exact([("water", float("nan"))]), ValueError),
    (lambda: irid.Film.exact([]), ValueError),
    (lambda: irid.Film.exact([("water", 100)], ambient="1.5+0.1i"), ValueError),
    (lambda: irid.Film.exact([("water", 100)], polarization="circular"), KeyError),
    (lambda: irid.Film.exact([("water", 100)]).reflectance([500.0], angle=90.0), ValueError),
    (lambda: irid.Film.exact([("water", 100)]).reflectance([-5.0]), ValueError),
    (lambda: irid.Film.exact([("water", 100)]).color(angle=float("nan")), ValueError),
    (lambda: irid.Film.exact([("water", 100)]).color(illuminant="D0"), KeyError),
    (lambda: irid.Film.exact([("water", 100)]).color(rgb="cmyk"), KeyError),
    (lambda: irid.Film.thesis("silver", 100.0), ValueError),   # absorbs: no closed form
    (lambda: irid.Film.thesis("water", 100.0, k=0.0), ValueError),
    (lambda: irid.Film.thesis_multilayer(0.8, 100.0, 12), ValueError),
    (lambda: irid.Film.thesis_multilayer(1.5, 100.0, -1), ValueError),
    (lambda: irid.Film.morpho(n=0.5), ValueError),
    (lambda: irid.Film.morpho(periods=0), ValueError),          # 1..1000000, from the library
    (lambda: irid.Film.morpho(periods=10**30), ValueError),     # past any C integer, still a ValueError
    (lambda: irid.Film.thesis_multilayer(1.5, 100.0, 10**12), ValueError),
    (lambda: irid.Film.morpho(d1=2e6), ValueError),             # the CLI's range, now the library's
    (lambda: irid.Film.morpho(blend=True, blend_vary="d3"), KeyError),
    (lambda: irid.Film.morpho().color(thickness=100.0), ValueError),
    (lambda: irid.Film.exact([("water", 0)]).color_table(100.0, step=0.0), ValueError),
    (lambda: irid.Film.exact([("water", 0)]).color_table(1e6, step=1e-4), ValueError),
    (lambda: irid.thesis_film_reflectance(500.0, -1.0), ValueError),
    (lambda: irid.thesis_multilayer_reflectance(500.0, 100.0, -3), ValueError),
    (lambda: irid.morpho_effective_thickness(95.0), ValueError),
    (lambda: irid.Film.exact([("water", 100)]).color(np.zeros(3000), np.zeros((3000, 1000))),
     ValueError),   # 3 million colours: over the work limit, refused before any work
])
def test_bad_input_raises(call, error):
    with pytest.raises(error):
        call()


def test_film_pickles_for_workers():
    f = irid.Film.thesis("water", 300.0, k=0.5)
    g = pickle.loads(pickle.dumps(f))
    np.testing.assert_array_equal(g.reflectance(LAMBDA)[0], f.reflectance(LAMBDA)[0])


def test_masked_arrays_refused():
    m = np.ma.masked_array([100.0, 200.0], mask=[0, 1])
    for call in (lambda: irid.Film.exact([("water", 0)]).color(m),
                 lambda: irid.thesis_film_reflectance(500.0, m),
                 lambda: irid.morpho_effective_thickness(np.ma.masked_array([0.0], mask=[1]))):
        with pytest.raises(ValueError, match="masked"):
            call()


# --- The renderers' thin-film models -------------------------------------------------------------

def test_renderer_film_models_are_named():
    assert irid.renderer_film_models() == ["gltf", "belcour", "cycles"]
    with pytest.raises(KeyError):
        irid.renderer_film_color("thesis", 1.33, 300.0)


def test_renderer_film_without_a_film_is_the_bare_base():
    # A film of the ambient's index on glass: Cycles gives the exact Fresnel ((1.5-1)/(1.5+1))² in
    # every channel at normal incidence, the colour of a grey with Y = 0.04 under D65.
    c = irid.renderer_film_color("cycles", 1.0, [0.0, 300.0, 1000.0], ambient=1.0, substrate=1.5)
    assert c.rgb.shape == (3, 3)
    np.testing.assert_allclose(c.rgb, 0.04, atol=1e-12)
    np.testing.assert_allclose(c.xyz[:, 1], 0.04, atol=1e-12)


def test_renderer_film_broadcasts_and_refuses_absorbing_films():
    c = irid.renderer_film_color("gltf", 1.33, [[100.0], [300.0]], angle=[0.0, 30.0, 60.0], substrate="gold")
    assert c.xyz.shape == (2, 3, 3) and np.isfinite(c.xyz).all() and (c.rgb >= 0).all()
    with pytest.raises(ValueError):
        irid.renderer_film_color("cycles", "1.5+0.1i", 100.0)
    with pytest.raises(ValueError):
        irid.renderer_film_color("cycles", 1.33, 100.0, angle=95.0)


def test_renderer_film_agrees_with_the_cli(irid_cli):
    out = subprocess.run([irid_cli, "film", "--model", "belcour", "--layer", "1.33:350", "--substrate", "water",
                          "--angle", "30"], capture_output=True, text=True, check=True)
    row = next(csv.DictReader(io.StringIO(out.stdout)))
    c = irid.renderer_film_color("belcour", 1.33, 350.0, angle=30.0, substrate="water")
    np.testing.assert_allclose(c.rgb, [float(row[k]) for k in ("R_linear", "G_linear", "B_linear")], rtol=1e-12)
    np.testing.assert_allclose(c.xyz, [float(row[k]) for k in ("X", "Y", "Z")], rtol=1e-12)


@pytest.mark.parametrize("integration", ["sum", "fourier"])
def test_film_colours_are_finite_up_to_grazing_incidence(integration):
    # The cases: a film of zero thickness at 89.9999999°, an index of 1e6 at 89.9°.
    angles = np.array([0.0, 45.0, 89.0, 89.9, 89.99999, 89.9999999])
    for layer, substrate in [("1.33", "air"), ("1e6", "air"), ("2.4", "1.5"), ("1.0001", "1e6")]:
        for t in (0.0, 1e-12, 300.0, 5000.0):
            c = irid.film_color([(layer, t)], thickness=t, angle=angles, substrate=substrate,
                                integration=integration)
            assert np.all(np.isfinite(c.xyz)) and np.all(np.isfinite(c.rgb)), (layer, t)
    # Zero thickness between like media is no interface at all; at grazing a real film mirrors.
    zero = irid.film_color([("1.33", 0.0)], thickness=0.0, angle=89.9999999, integration=integration)
    np.testing.assert_allclose(zero.xyz, 0.0, atol=1e-9)
    mirror = irid.film_color([("1.33", 300.0)], thickness=300.0, angle=89.9999999,
                             integration=integration)
    assert abs(mirror.xyz[..., 1] - 1.0) < 1e-6


def test_a_multilayer_of_no_film_is_refused():
    with pytest.raises(ValueError, match="1..1000000"):
        irid.Film.thesis_multilayer("1.56", 100.0, 0)
    with pytest.raises(ValueError, match="1..1000000"):
        irid.thesis_unit_peak_k(0)
