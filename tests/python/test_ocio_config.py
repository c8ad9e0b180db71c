"""``irid ocio-config``: valid for OpenColorIO for every pair of spaces, and faithful to
``irid clip`` (docs/GAMUT.md, "An OpenColorIO config of looks").

- ``ociocheck`` passes for every built-in RGB space as the source (encoded, linear, the ACES
  aliases) against displays encoded and linear, the source's own space included.
- Through PyOpenColorIO every method's view agrees with ``irid clip`` on the colours inside the
  display's gamut within mean ΔE2000 0.1 and p99 0.5, for the pairs of ocio_fidelity.PAIRS; a
  hard method leaves them alone to float rounding (max 0.01). Out-of-gamut colours stay within
  the distances docs/GAMUT.md lists (scripts/ocio-fidelity prints them), with a margin.
- The look's LUT holds the nodes 0 and 1 on every axis and its shaper is linear between nodes.
"""

import shutil
import subprocess

import numpy as np
import pytest

import irid
from ocio_fidelity import DOCUMENTED, PAIRS, measure, write_config

RGB_SPACES = ["srgb", "srgb-linear", "display-p3", "display-p3-linear", "rec2020",
              "rec2020-linear", "adobe-rgb", "adobe-rgb-linear", "smpte-c", "smpte-c-linear",
              "ntsc1953", "ntsc1953-linear", "aces2065-1", "aces2065-1-linear", "acescg",
              "acescg-linear"]
DISPLAYS = ["srgb", "display-p3", "rec2020", "srgb-linear", "acescg"]
SOFT = {"smits-soft", "aces-rgc"}


def ociocheck(config):
    tool = shutil.which("ociocheck")
    assert tool, "ociocheck is missing (scripts/install-deps installs opencolorio-tools)"
    r = subprocess.run([tool, "--iconfig", str(config)], capture_output=True, text=True)
    return r.returncode == 0 and "passed" in r.stdout and "ERROR" not in r.stdout, \
        r.stdout + r.stderr


@pytest.mark.parametrize("display", DISPLAYS)
def test_ociocheck_passes_for_every_source(irid_cli, tmp_path, display):
    for source in RGB_SPACES:
        config = write_config(irid_cli, tmp_path / f"{source}-{display}", source, display,
                              ["clamp", "smits"], size=5)
        ok, out = ociocheck(config)
        assert ok, f"--from {source} --to {display}:\n{out}"


def load_config(irid_cli, folder, source, display, methods, size=None):
    import PyOpenColorIO as ocio
    return ocio.Config.CreateFromFile(str(write_config(irid_cli, folder, source, display, methods,
                                                       size=size)))


def applied(config, rgb, *processor_args):
    """rgb (float32) through config.getProcessor(*processor_args) on the CPU."""
    out = np.array(rgb, np.float32)
    config.getProcessor(*processor_args).getDefaultCPUProcessor().applyRGB(out)
    return out


def test_aliases_and_encoded_sources_are_what_they_say(irid_cli, tmp_path):
    config = load_config(irid_cli, tmp_path / "a", "acescg", "srgb", ["clamp"], size=5)
    # The alias is the linear space: scene_linear, values above 1 kept (no [0, 1] clamp).
    assert config.getColorSpace("scene_linear").getName() == "acescg-linear"
    assert config.getColorSpace("acescg").getName() == "acescg-linear"
    assert config.getColorSpace("acescg-linear").getEncoding() == "scene-linear"
    bright = [[4.0, 2.0, 1.5]]
    np.testing.assert_allclose(applied(config, bright, "acescg", "srgb-linear"),
                               irid.convert(bright, "acescg-linear", "srgb-linear"), rtol=1e-5)
    # An encoded source decodes to its linear form, the reference.
    config = load_config(irid_cli, tmp_path / "p3", "display-p3", "srgb", ["clamp"], size=5)
    assert config.getColorSpace("scene_linear").getName() == "display-p3-linear"
    codes = [[0.2, 0.5, 0.9]]
    np.testing.assert_allclose(applied(config, codes, "display-p3", "display-p3-linear"),
                               irid.convert(codes, "display-p3", "display-p3-linear"), atol=2e-6)


def test_one_space_as_source_and_display_clips_what_the_cube_cannot_hold(irid_cli, tmp_path):
    import PyOpenColorIO as ocio
    config = ocio.Config.CreateFromFile(str(write_config(irid_cli, tmp_path / "s", "srgb-linear",
                                                          "srgb-linear", ["smits"])))
    p = config.getProcessor("srgb-linear", "srgb-linear display", "smits",
                            ocio.TRANSFORM_DIR_FORWARD).getDefaultCPUProcessor()
    rgb = np.array([[-0.2, 0.5, 0.7], [2.0, 0.5, 0.1], [0.3, 0.4, 0.5]], np.float32)
    out = rgb.copy()
    p.applyRGB(out)
    np.testing.assert_allclose(out, irid.clip(rgb, "smits", "srgb-linear", "srgb-linear"),
                               atol=2e-2)
    np.testing.assert_allclose(out[2], rgb[2], atol=1e-6)    # inside: untouched


@pytest.mark.parametrize("source,display", PAIRS, ids=[f"{s}-{d}" for s, d in PAIRS])
def test_every_look_is_faithful_to_irid_clip(irid_cli, tmp_path, source, display):
    results = measure(irid_cli, tmp_path / "cfg", source, display)
    for method, sets in results.items():
        if "inside" not in sets:
            continue
        mean, p99, worst = sets["inside"]
        assert mean <= 0.1 and p99 <= 0.5, (method, sets["inside"])
        if method not in SOFT:
            assert worst <= 0.01, (method, sets["inside"])
        # docs/GAMUT.md's out-of-gamut distances (scripts/ocio-fidelity) with a quarter's margin.
        for name, (mean_bound, p99_bound) in DOCUMENTED[(source, display)].items():
            mean, p99, _ = sets[name]
            assert mean <= 1.25 * mean_bound and p99 <= 1.25 * p99_bound, (method, name, sets[name])


def test_the_looks_nodes_hold_the_cube(irid_cli, tmp_path):
    write_config(irid_cli, tmp_path / "n", "acescg-linear", "srgb", ["clamp"], size=33)
    text = (tmp_path / "n" / "luts" / "irid-clamp.clf").read_text()
    assert "<LUT1D" in text and "<Range" in text
    # The shaper's description lists the nodes; 0 and 1 are among them.
    shaper = text.split("<LUT1D", 1)[1]
    nodes = [float(v) for v in shaper.split(" at ", 1)[1].split("</Description>", 1)[0].split()]
    assert len(nodes) == 33 and 0.0 in nodes and 1.0 in nodes
    assert all(b > a for a, b in zip(nodes, nodes[1:]))


def test_bad_requests_are_refused(irid_cli, tmp_path):
    def run(*args):
        return subprocess.run([irid_cli, "ocio-config", *args], capture_output=True, text=True)
    r = run("--methods", "smits,smits", "-o", str(tmp_path / "d"))
    assert r.returncode != 0 and "smits is named twice" in r.stderr, r.stderr
    r = run("--size", "4", "-o", str(tmp_path / "d"))
    assert r.returncode == 2 and "--size" in r.stderr, r.stderr
    with pytest.raises(ValueError, match="named twice"):
        irid.write_ocio_config(tmp_path / "e", methods=["css", "css"], size=5)
    # The success line shows a path's control bytes escaped.
    odd = tmp_path / "a\x1b[31mb"
    r = run("--methods", "clamp", "--size", "5", "-o", str(odd))
    assert r.returncode == 0 and "\x1b" not in r.stdout and "\\x1b" in r.stdout, r.stdout


def test_a_source_range_too_wide_for_the_looks_is_refused_with_the_reason(irid_cli, tmp_path):
    r = subprocess.run([irid_cli, "ocio-config", "--range", "0,30000", "--methods", "clamp",
                        "-o", str(tmp_path / "w")], capture_output=True, text=True)
    assert r.returncode == 2 and "narrow the range" in r.stderr and "4096" in r.stderr, r.stderr
    assert not (tmp_path / "w").exists()
