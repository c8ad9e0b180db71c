#!/usr/bin/env python3
"""web/irid-three.js beside other code that patches the same materials, in headless Chromium
(WebGL2 through SwiftShader): materials with shader patches of their own keep their own
programs, applying again swaps the table, clone() and copy() keep the patch, a table for another
space or illuminant is refused, and the table's texture is disposed with its material.

    python3 three_compose_test.py <path-to-irid>

Needs the Python module on PYTHONPATH (ctest sets it), node + web/node_modules and chromium.
Prints what it measured; exits 1 when a check fails, 2 when it cannot run.
"""
import os
import subprocess
import sys
import tempfile

import numpy as np

import irid
from browser import Checks, delta_e, run_page

SIZE = 16
# The film of the page's materials: 1.33 on a base of 1.5, 420 nm (the range's maximum), seen at
# the pixel (SIZE / 2, SIZE / 2), whose centre is at NDC (x, y) = (1 / SIZE, 1 / SIZE) on the unit
# sphere: cos θ = √(1 − x² − y²).
FILM_IOR, BASE_IOR, THICKNESS = 1.33, 1.5, 420.0
# SwiftShader's float against the exact film, at one angle.
MAX_DE = 0.05
# Two renders of one program with one table: float-identical.
SAME = 1e-6

check = Checks()


def shader(cli, folder, *args):
    run = subprocess.run([os.path.abspath(cli), "shader", "--lang", "glsl", "-o", folder, *args],
                         capture_output=True, text=True, timeout=300)
    check(run.returncode == 0, f"irid shader {' '.join(args)} writes a table", f"exit {run.returncode} {run.stderr.strip()}")
    return folder


def main():
    cli = sys.argv[1]
    with tempfile.TemporaryDirectory(prefix="irid-three-compose-") as work:
        folders = {"d65": shader(cli, os.path.join(work, "d65")),
                   "a": shader(cli, os.path.join(work, "a"), "--illuminant", "A"),
                   "p3": shader(cli, os.path.join(work, "p3"), "--space", "display-p3")}
        out = run_page(work, "/tests/three_compose_page.js",
                       {"tables": {k: f"/{k}/" for k in folders}, "size": SIZE}, folders, timeout=300)

    film = irid.Film.exact([(FILM_IOR, THICKNESS)], ambient=1.0, substrate=BASE_IOR)
    angle = np.degrees(np.arccos(np.sqrt(1.0 - 2.0 / SIZE ** 2)))
    d65 = film.color(thickness=THICKNESS, angle=angle).rgb.reshape(3)
    under_a = film.color(thickness=THICKNESS, angle=angle, illuminant="A").rgb.reshape(3)

    t = {k: np.array(v) for k, v in out["tinted"].items()}
    check(t["red"][0] > 0.01 and t["red"][1] == 0 and t["red"][2] == 0
          and t["green"][1] > 0.01 and t["green"][0] == 0 and t["green"][2] == 0,
          "two materials tinted red and green by their own onBeforeCompile keep their own tints",
          f"red {t['red']}, green {t['green']}")
    de = float(delta_e(t["plain"], d65))
    check(de <= MAX_DE and np.abs(t["plain"] - t["plainAlone"]).max() <= SAME,
          "a patched material with no patch of its own is irid's film, as when rendered alone",
          f"{t['plain']} (alone {t['plainAlone']}), ΔE2000 {de:.4f} from the exact film")
    check(out["programs"] == 3, "three programs for the three materials", f"{out['programs']}")

    s = {k: np.array(v) for k, v in out["swapped"].items()}
    de_before, de_after = float(delta_e(s["before"], d65)), float(delta_e(s["after"], under_a))
    check(de_before <= MAX_DE and de_after <= MAX_DE and np.abs(s["after"] - s["direct"]).max() <= SAME,
          "applying again swaps the table (D65, then A) without an error",
          f"before ΔE2000 {de_before:.4f} from the D65 film, after {de_after:.4f} from the film under A")

    c = {k: np.array(v) for k, v in out["copies"].items()}
    check(np.abs(c["clone"] - c["original"]).max() <= SAME and np.abs(c["copied"] - c["original"]).max() <= SAME,
          "clone() and copy() keep the patch", f"original {c['original']}, clone {c['clone']}, copy {c['copied']}")
    check(np.abs(c["uncopied"] - c["stock"]).max() <= SAME and np.abs(c["stock"] - c["original"]).max() > 1e-3,
          "copying an unpatched material removes the patch (three.js's own chunk again)",
          f"{c['uncopied']} against three's {c['stock']}")

    r = out["refusals"]
    check(r["space"] is not None and "display-p3-linear" in r["space"] and "srgb-linear" in r["space"],
          "a Display P3 table on an sRGB renderer is refused, naming both", f"{r['space']}")
    check(r["illuminant"] is not None and "illuminant A" in r["illuminant"],
          "a table under illuminant A is refused where the lights are D65", f"{r['illuminant']}")
    check(out["disposed"], "the table's texture is disposed with its material", f"{out['disposed']}")
    return check.finish()


if __name__ == "__main__":
    sys.exit(main())
