"""How faithfully an ``irid ocio-config`` look stands for ``irid clip``, through PyOpenColorIO.

Shared by tests/python/test_ocio_config.py (which asserts the bounds) and
scripts/ocio-fidelity (which prints the table docs/GAMUT.md quotes).

For a source and display pair, every method's view (look, then the display's encoding) is
applied by OpenColorIO's CPU processor to three sets of source colours and compared in ΔE2000
with irid.clip of the same colours into the display (with the settings a display gets,
irid/gamut/clip.h display_clip_settings), both decoded to CIELAB:

- "inside": colours inside the display's gamut (a linear source: [0, 1]³ of the source; an
  encoded one: its code values), which a hard method leaves alone;
- "outside": the rest of the source's [0, 1]³ (code values for an encoded source);
- "hdr" (linear sources only): 2^U(-8, 4) per channel, up to 16, outside the gamut.
"""

import pathlib
import subprocess

import numpy as np

import irid

# The pairs the test and docs/GAMUT.md measure: linear and encoded sources, ACES spaces by
# their aliases, wide and narrow displays, and a source that is its display's linear form.
PAIRS = [
    ("acescg-linear", "srgb"),
    ("acescg", "display-p3"),
    ("aces2065-1", "rec2020"),
    ("rec2020-linear", "srgb"),
    ("display-p3", "srgb"),
    ("srgb-linear", "srgb"),
]


# The largest mean and p99 over every method, per pair and colour set, as measured by
# scripts/ocio-fidelity at the default 33³ and quoted in docs/GAMUT.md (rounded up). The colours
# inside the gamut are bounded for every pair alike: mean 0.1, p99 0.5.
DOCUMENTED = {
    ("acescg-linear", "srgb"): {"outside": (0.75, 6.2), "hdr": (1.05, 12.2)},
    ("acescg", "display-p3"): {"outside": (0.66, 4.0), "hdr": (0.76, 10.4)},
    ("aces2065-1", "rec2020"): {"outside": (1.42, 19.1), "hdr": (3.1, 45.7)},
    ("rec2020-linear", "srgb"): {"outside": (0.71, 6.0), "hdr": (0.93, 11.5)},
    ("display-p3", "srgb"): {"outside": (0.09, 0.7)},
    ("srgb-linear", "srgb"): {"hdr": (0.22, 4.4)},
}


def is_linear(space):
    """A source that holds linear light: "-linear" names and the ACES aliases."""
    return space.endswith("-linear") or space in ("acescg", "aces2065-1")


def colour_sets(source, display, n=20000, seed=11):
    rng = np.random.default_rng(seed)
    cube = rng.random((4 * n, 3))
    linear = irid.convert(cube, source, display + "-linear" if not display.endswith("-linear")
                          else display)
    inside = np.all((linear >= 0) & (linear <= 1), axis=1)
    sets = {"inside": cube[inside][:n], "outside": cube[~inside][:n]}
    if is_linear(source):
        hdr = np.exp2(rng.uniform(-8, 4, (4 * n, 3)))
        lin = irid.convert(hdr, source, display + "-linear" if not display.endswith("-linear")
                           else display)
        sets["hdr"] = hdr[~np.all((lin >= 0) & (lin <= 1), axis=1)][:n]
    return sets


def write_config(cli, folder, source, display, methods=None, size=None):
    args = [cli, "ocio-config", "--from", source, "--to", display, "-o", str(folder)]
    if methods:
        args += ["--methods", ",".join(methods)]
    if size:
        args += ["--size", str(size)]
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    return pathlib.Path(folder) / "config.ocio"


def measure(cli, folder, source, display, methods=None):
    """{method: {set: (mean, p99, max)}} of ΔE2000 between the view and irid.clip."""
    import PyOpenColorIO as ocio
    methods = methods or irid.clip_methods()
    config = ocio.Config.CreateFromFile(str(write_config(cli, folder, source, display, methods)))
    sets = colour_sets(source, display)
    out = {}
    for method in methods:
        processor = config.getProcessor(source, f"{display} display", method,
                                        ocio.TRANSFORM_DIR_FORWARD).getDefaultCPUProcessor()
        params = {"clip": True} if method == "aces-rgc" else {}
        out[method] = {}
        for name, rgb in sets.items():
            if len(rgb) == 0:
                continue
            viewed = np.ascontiguousarray(rgb, dtype=np.float32).copy()
            processor.applyRGB(viewed)
            want = irid.clip(rgb, method, source, display, **params)
            d = irid.delta_e(irid.convert(viewed.astype(np.float64), display, "lab"),
                             irid.convert(want, display, "lab"))
            out[method][name] = (float(d.mean()), float(np.percentile(d, 99)), float(d.max()))
    return out


def markdown(results):
    """One table per pair: method × set, "mean / p99 / max"."""
    lines = []
    for (source, display), table in results.items():
        sets = list(next(iter(table.values())).keys())
        if not sets:
            continue
        lines.append(f"`--from {source} --to {display}`\n")
        lines.append("| method | " + " | ".join(sets) + " |")
        lines.append("|---|" + "---|" * len(sets))
        for method, row in table.items():
            cells = [f"{m:.3f} / {p:.2f} / {x:.1f}" for m, p, x in (row[s] for s in sets)]
            lines.append(f"| `{method}` | " + " | ".join(cells) + " |")
        lines.append("")
    return "\n".join(lines)
