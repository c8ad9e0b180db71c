#!/usr/bin/env python3
"""The gallery's iridescence page works from file:// without a network: built as scripts/run
builds it (web/build-iridescence-page.mjs --irid IRID -o DIR), opened from file:// in headless
Chromium (no request is made and none may fail; no console error, no page error) at 1920x1080
and at 390x844 (a phone, portrait), it draws a soap bubble and an oil film on both halves of its
canvas (side by side on the landscape screen, stacked on the portrait one), and its sliders
redraw both halves.

    python3 iridescence_page_test.py <path-to-irid> [--screenshots DIR]

Checks, on the canvas' pixels (tests/browser/iridescence_page_probe.js measures them in the page),
at each size:
- the layout: side by side on the landscape screen, stacked on the portrait one;
- each half is not blank: many distinct colours, a spread of brightness, much of it lit;
- the halves differ (irid's exact film against three.js's glTF model: same camera, light and
  geometry, so any difference is the film's colour);
- moving the bubble's thickness slider changes both halves, and moving it back restores them;
- the orbit controls keep the camera above the water.
--screenshots keeps the page's screenshots (iridescence-1920x1080.png, iridescence-390x844.png).
Needs node, web/node_modules and chromium (scripts/install-deps). Exits 1 when a check fails.
"""
import argparse
import os
import subprocess
import sys
import tempfile

from browser import Checks, node_env, run_page

HERE = os.path.dirname(os.path.abspath(__file__))
BUILDER = os.path.join(HERE, "..", "..", "web", "build-iridescence-page.mjs")

# Not blank: a flat or nearly flat half has a handful of colours (5 bits a channel) and no
# spread; the page's halves have thousands of colours, a luma spread of about 20-30 (of 255) and
# most of their pixels brighter than their darkest. Far lower bounds, so that only a broken page
# fails.
MIN_COLOURS = 500
MIN_STD_LUMA = 8.0
MIN_LIT = 0.25
SIZES = [(1920, 1080, "side-by-side"), (390, 844, "stacked")]
# The halves differ by a mean |Δ| of about 5 (of 255); an unpatched left half would give 0.
MIN_BETWEEN = 1.0
# The bubble's thickness from 900 to 300 nm changes each half by a mean |Δ| of about 3.5 over
# the whole half (the bubble is a fifth of it).
SLIDER = "bubble-thickness"
SLIDER_VALUE = 300
MIN_CHANGE = 1.0

check = Checks()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("irid")
    parser.add_argument("--screenshots", help="a folder to keep the screenshots in (PNG)")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="irid-iridescence-page-") as work:
        out = os.path.join(work, "gallery")
        build = subprocess.run(["node", BUILDER, "--irid", os.path.abspath(args.irid), "-o", out],
                               env=node_env(work), capture_output=True, text=True, timeout=300)
        page = os.path.join(out, "iridescence.html")
        check(build.returncode == 0 and os.path.isfile(page),
              "web/build-iridescence-page.mjs writes DIR/iridescence.html",
              f"exit {build.returncode} {build.stderr.strip()}")
        if build.returncode != 0:
            return check.finish()
        shader = sorted(os.listdir(os.path.join(out, "iridescence")))
        check(shader == ["irid_film_table.f32", "irid_film_table.json", "irid_iridescence.glsl"],
              "DIR/iridescence/ holds the chunk and table the page links", shader)
        size = os.path.getsize(page)
        print(f"iridescence.html: {size / 1e6:.2f} MB (three.js, its addons and the table inside)")
        folder = args.screenshots or work
        os.makedirs(folder, exist_ok=True)
        for width, height, layout in SIZES:
            screenshot = os.path.join(folder, f"iridescence-{width}x{height}.png")
            # run_page.mjs fails the run on any console error, page error or failed request.
            result = run_page(work, "/tests/iridescence_page_probe.js",
                              {"frames": 1, "slider": SLIDER, "value": SLIDER_VALUE, "timeoutMs": 60000},
                              {}, timeout=120, page=page, screenshot=screenshot, viewport=(width, height))
            check(os.path.getsize(screenshot) > 0, f"a screenshot at {width}x{height}", screenshot)
            measure(result, width, height, layout)
    return check.finish()


def measure(result, width, height, layout):
    where = f"{width}x{height}"
    print(f"{where}: canvas {result['width']} x {result['height']}, {result['frames']} frames, {result['layout']}")
    check(result["layout"] == layout, f"{where}: the halves are {layout}", result["layout"])
    for side in ("irid", "stock"):
        s = result["before"][side]
        check(s["colours"] >= MIN_COLOURS and s["stdLuma"] >= MIN_STD_LUMA and s["lit"] >= MIN_LIT,
              f"{where}: the {side} half is drawn (>= {MIN_COLOURS} colours, luma spread >= {MIN_STD_LUMA}, "
              f">= {MIN_LIT:.0%} lit)",
              f"{s['colours']} colours, spread {s['stdLuma']:.1f}, {s['lit']:.0%} lit, "
              f"mean RGB {[round(c, 1) for c in s['mean']]}")
    between = result["between"]["before"]
    check(between >= MIN_BETWEEN, f"{where}: the halves differ: irid's film against glTF's (mean |Δ| >= {MIN_BETWEEN})",
          f"{between:.2f}")
    for side in ("irid", "stock"):
        change = result["change"][side]
        check(change >= MIN_CHANGE,
              f"{where}: moving #{SLIDER} to {SLIDER_VALUE} redraws the {side} half (mean |Δ| >= {MIN_CHANGE})",
              f"{change:.2f}")
    restored = result["restoredChange"]["irid"]
    check(restored <= 0.01, f"{where}: moving #{SLIDER} back restores irid's half", f"mean |Δ| {restored:.3f}")
    check(result["cameraY"] > 0.0, f"{where}: the controls keep the camera above the water",
          f"camera put at y = -3 comes back to y = {result['cameraY']:.2f}")


if __name__ == "__main__":
    sys.exit(main())
