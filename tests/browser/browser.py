"""What the browser tests share: running a page module in headless Chromium (run_page.mjs),
counting checks, and ΔE2000 between linear sRGB colours in irid's CIELAB."""
import json
import os
import shutil
import subprocess
import sys

import numpy as np

import irid

HERE = os.path.dirname(os.path.abspath(__file__))


class Checks:
    """Prints "ok: ..." or "FAIL: ..." per check, with what was measured; counts them."""

    def __init__(self):
        self.passed = self.failed = 0

    def __call__(self, ok, what, measured):
        if ok:
            self.passed += 1
            print(f"ok: {what}: {measured}")
        else:
            self.failed += 1
            print(f"FAIL: {what}: {measured}")

    def finish(self):
        print(f"{self.passed} passed, {self.failed} failed")
        return 1 if self.failed else 0


def lab_of(rgb):
    """CIELAB (D65 white) of linear sRGB triples, as irid film --color prints L, a, b."""
    return irid.convert(np.asarray(rgb, dtype=np.float64), "srgb-linear", "lab")


def delta_e(rgb_a, rgb_b):
    """ΔE2000 between linear sRGB triples."""
    return irid.delta_e(lab_of(rgb_a), lab_of(rgb_b), "ciede2000")


def node_env(work):
    """The environment for node (and the Chromium it starts), with HOME in work."""
    # Chromium and node are not built with irid's sanitizers: no preloaded ASan runtime for them.
    env = {k: v for k, v in os.environ.items() if k not in ("LD_PRELOAD", "ASAN_OPTIONS", "LSAN_OPTIONS")}
    env["HOME"] = work
    return env


def run_page(work, module, page_input, serve, timeout=600, page=None, screenshot=None, viewport=None):
    """Runs the page module (a URL under /tests/) with page_input in Chromium, the folders of
    serve ({name: dir}) under /name/; returns what its run() returned. With page (an HTML file),
    the module runs in that page opened from file:// (run_page.mjs --page); with screenshot (a
    PNG path), the page is saved there after run(); viewport (width, height) sets the page's size
    in CSS pixels. Exits the test (2) when node is missing and
    (1 or 2) when the run fails, with run_page.mjs's message."""
    if shutil.which("node") is None:
        print("FAIL: node is not on PATH: run scripts/install-deps (it installs nodejs and web/node_modules)")
        sys.exit(2)
    with open(os.path.join(work, "input.json"), "w") as f:
        json.dump(page_input, f)
    cmd = ["node", os.path.join(HERE, "run_page.mjs"), "--serve", f"tests={HERE}"]
    for name, folder in serve.items():
        cmd += ["--serve", f"{name}={os.path.abspath(folder)}"]
    cmd += ["--module", module, "--input", os.path.join(work, "input.json"),
            "--output", os.path.join(work, "output.json"), "--timeout", str(timeout)]
    if page:
        cmd += ["--page", os.path.abspath(page)]
    if screenshot:
        cmd += ["--screenshot", os.path.abspath(screenshot)]
    if viewport:
        cmd += ["--viewport", f"{viewport[0]}x{viewport[1]}"]
    run = subprocess.run(cmd, env=node_env(work), timeout=timeout + 120)
    if run.returncode != 0:
        print(f"FAIL: the browser run ({' '.join(cmd)}) exited {run.returncode}")
        sys.exit(2 if run.returncode == 2 else 1)
    with open(os.path.join(work, "output.json")) as f:
        return json.load(f)


def irid_shader(cli, folder, check):
    """Runs `irid shader --lang glsl -o folder`; returns folder, or None (a failed check)."""
    run = subprocess.run([os.path.abspath(cli), "shader", "--lang", "glsl", "-o", folder],
                         capture_output=True, text=True, timeout=300)
    check(run.returncode == 0, "irid shader --lang glsl -o DIR writes irid's chunk and table",
          f"exit {run.returncode} {run.stderr.strip()}")
    return folder if run.returncode == 0 else None
