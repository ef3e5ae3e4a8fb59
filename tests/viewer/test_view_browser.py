"""newtop view in headless Chromium (DevTools protocol over a pipe, tests/viewer/cdp.py): the page
loads offline with no console error, its canvas is not blank, frames at two times differ, and the
slider set to a recorded time shows the attitude of that CSV row, read back from the three.js
objects (window.newtopView.state()) and compared with the CSV read here.

Environment (set by ctest, tests/viewer/CMakeLists.txt): NEWTOP_EXE, NEWTOP_SOURCE_DIR,
and NEWTOP_CHROMIUM; the mesh scenario reads the data/ folder of the source tree."""

from __future__ import annotations

import csv
import io
import math
import os
import subprocess
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.dirname(__file__))
import cdp  # noqa: E402

EXE = os.environ.get("NEWTOP_EXE", "newtop")
SRC = os.environ.get("NEWTOP_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
CHROMIUM = os.environ.get("NEWTOP_CHROMIUM", "/usr/bin/chromium")
WIDTH, HEIGHT = 1280, 800
#: The page holds the CSV's numbers exactly (shortest round-trip JSON) and draws −γ and q through
#: three.js's setFromUnitVectors / quaternion products: a few roundings of unit vectors.
ATTITUDE_TOLERANCE = 64 * np.finfo(float).eps
#: A canvas showing the scene has far more than this share of non-background pixels (the body
#: alone covers ~10 % of it); a blank or failed WebGL canvas has none.
MIN_DRAWN_SHARE = 0.02
#: Two frames of a moving body differ in more than this share of the canvas's pixels.
MIN_CHANGED_SHARE = 0.002


def newtop(*args):
    r = subprocess.run([EXE, *map(str, args)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return r


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    head = rows[0]
    return {n: np.array([float(r[i]) for r in rows[1:]]) for i, n in enumerate(head)}


def rotate(q, v):
    """R(q) v for q = (w, x, y, z), body -> inertial."""
    w, u = q[0], np.asarray(q[1:])
    return v + 2.0 * np.cross(u, np.cross(u, v) + w * v)


def pixels(png):
    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB"), dtype=np.int16)


def drawn_share(img):
    """Share of the pixels that differ from the most frequent colour (the background, whatever it
    is: an undrawn WebGL canvas is uniformly black or transparent)."""
    colours, counts = np.unique(img.reshape(-1, 3), axis=0, return_counts=True)
    background = colours[np.argmax(counts)]
    return np.any(np.abs(img - background) > 8, axis=2).mean()


@pytest.fixture(scope="module")
def browser():
    with cdp.Browser(CHROMIUM) as b:
        yield b


def open_page(browser, html):
    page = browser.new_page(WIDTH, HEIGHT)
    page.navigate("file://" + os.path.abspath(html))
    page.wait_for("window.newtopView !== undefined && window.newtopView.ready === true")
    return page


def canvas_shot(page):
    rect = page.evaluate("(() => { const r = document.querySelector('#scene canvas')"
                         ".getBoundingClientRect(); return {x: r.x, y: r.y, width: r.width, "
                         "height: r.height}; })()")
    return pixels(page.screenshot(rect))


def move_slider(page, t):
    """Sets the slider as a user would (value, then an input event) and returns the page state."""
    page.evaluate(f"(() => {{ const s = document.getElementById('slider'); s.value = '{t!r}'; "
                  "s.dispatchEvent(new Event('input')); })()")
    return page.evaluate("newtopView.state()")


def check_page(browser, html, csv_rows, attitude):
    page = open_page(browser, html)
    n = len(csv_rows["t"])
    assert page.evaluate("newtopView.frames") == n
    assert page.evaluate("newtopView.attitude") is attitude
    mode = page.evaluate("document.getElementById('mode').textContent")
    assert ("inertial frame" if attitude else "body frame") in mode

    first = canvas_shot(page)
    drawn = drawn_share(first)
    assert drawn > MIN_DRAWN_SHARE, f"canvas nearly blank: {drawn:.4f} drawn"

    for k in (n // 3, (2 * n) // 3, n - 1):
        t = csv_rows["t"][k]
        s = move_slider(page, t)
        assert s["t"] == t and s["index"] == k
        g = np.array([csv_rows[c][k] for c in ("gamma1", "gamma2", "gamma3")])
        g /= np.linalg.norm(g)
        if attitude:
            q = np.array([csv_rows[c][k] for c in ("q0", "q1", "q2", "q3")])
            shown = np.array(s["body_quaternion"])
            assert min(np.abs(shown - q).max(), np.abs(shown + q).max()) < ATTITUDE_TOLERANCE
            expected = -rotate(q, g)
        else:
            assert s["body_quaternion"] == [1, 0, 0, 0]
            expected = -g
        assert np.abs(np.array(s["centre_direction"]) - expected).max() < ATTITUDE_TOLERANCE

    later = canvas_shot(page)
    move_slider(page, csv_rows["t"][0])
    again = canvas_shot(page)
    changed = np.any(np.abs(later - first) > 8, axis=2).mean()
    assert changed > MIN_CHANGED_SHARE, f"frames at two times differ in {changed:.5f} only"
    assert np.array_equal(again, first), "the same time must draw the same frame"
    assert page.problems() == []
    return page


def test_body_frame_page(browser, tmp_path):
    scenario = os.path.join(SRC, "examples", "heavy_top.toml")
    out = tmp_path / "heavy.csv"
    newtop("simulate", scenario, "--out", out, "--t-end", 5)
    newtop("view", out, "--scenario", scenario, "-o", tmp_path / "heavy.html")
    check_page(browser, tmp_path / "heavy.html", read_csv(out), attitude=False)


def with_attitude(rows):
    """Adds q0..q3 of an attitude consistent with γ: R γ = e = (0, 0, 1) composed with a turn of
    0.7 t about e, so that the centre's direction stays fixed in the inertial frame."""
    qs = []
    for t, *g in zip(rows["t"], rows["gamma1"], rows["gamma2"], rows["gamma3"]):
        g = np.array(g) / np.linalg.norm(g)
        axis = np.cross(g, [0.0, 0.0, 1.0])
        s, c = np.linalg.norm(axis), g[2]
        half = 0.5 * math.atan2(s, c)
        a = axis / s if s > 0 else np.array([1.0, 0.0, 0.0])
        align = np.array([math.cos(half), *(math.sin(half) * a)])
        spin = np.array([math.cos(0.35 * t), 0.0, 0.0, math.sin(0.35 * t)])
        w1, v1, w2, v2 = spin[0], spin[1:], align[0], align[1:]
        qs.append([w1 * w2 - v1 @ v2, *(w1 * v2 + w2 * v1 + np.cross(v1, v2))])
    return np.array(qs)


def test_inertial_page_with_attitude(browser, tmp_path):
    scenario = os.path.join(SRC, "examples", "rotation_staude_cone.toml")
    plain = tmp_path / "plain.csv"
    newtop("simulate", scenario, "--out", plain, "--t-end", 4)
    rows = read_csv(plain)
    q = with_attitude(rows)
    with open(plain) as f:
        lines = f.read().splitlines()
    out = tmp_path / "attitude.csv"
    with open(out, "w") as f:
        f.write(lines[0] + ",q0,q1,q2,q3\n")
        for line, qi in zip(lines[1:], q):
            f.write(line + "," + ",".join(repr(float(x)) for x in qi) + "\n")
    newtop("view", out, "--scenario", scenario, "-o", tmp_path / "attitude.html")
    page = check_page(browser, tmp_path / "attitude.html", read_csv(out), attitude=True)
    # The physics of the attitude: the direction to the centre, −R γ = −e, is fixed in space.
    for t in rows["t"][:: max(1, len(rows["t"]) // 7)]:
        d = move_slider(page, t)["centre_direction"]
        assert np.abs(np.array(d) - [0.0, 0.0, -1.0]).max() < ATTITUDE_TOLERANCE


def test_mesh_body_page(browser, tmp_path):
    scenario = os.path.join(SRC, "examples", "exact_eros_spacecraft.toml")
    out = tmp_path / "eros.csv"
    newtop("simulate", scenario, "--out", out, "--t-end", 300)
    newtop("view", out, "--scenario", scenario, "-o", tmp_path / "eros.html")
    page = check_page(browser, tmp_path / "eros.html", read_csv(out), attitude=False)
    notes = page.evaluate("document.getElementById('notes').textContent")
    assert "mesh mass model" in notes


def test_page_without_scenario(browser, tmp_path):
    scenario = os.path.join(SRC, "examples", "brun.toml")
    out = tmp_path / "brun.csv"
    newtop("simulate", scenario, "--out", out, "--t-end", 3)
    newtop("view", out, "-o", tmp_path / "brun.html", "--max-frames", 50)
    rows = read_csv(out)
    keep = np.round(np.arange(50) * (len(rows["t"]) - 1) / 49).astype(int)
    page = check_page(browser, tmp_path / "brun.html", {k: v[keep] for k, v in rows.items()},
                      attitude=False)
    assert "No --scenario" in page.evaluate("document.getElementById('notes').textContent")


@pytest.mark.parametrize("example,options", [
    ("satellite_700km", ["--t-end", "3000", "--dt-out", "20", "--euler", "321"]),
    ("orbit_elliptic_pitch", ["--t-end", "6", "--dt-out", "0.05", "--attitude"]),
])
def test_orbit_page_shows_the_lvlh_triad_and_the_orbit(browser, tmp_path, example, options):
    """An orbit run (docs/orbit.md §12) in the body frame: at each time the drawn LVLH axes are
    the columns n × γ, −n, −γ of C(body←LVLH) built here from the row's γ and n (and the row's
    q0..q3 give the same matrix), and the orbit's circle passes through the body, lies in the
    plane normal to n and has the centre's direction −γ across it."""
    out = tmp_path / "orbit.csv"
    newtop("simulate", os.path.join(SRC, "examples", example + ".toml"), "--out", out, *options)
    newtop("view", out, "--scenario", os.path.join(SRC, "examples", example + ".toml"), "-o",
           tmp_path / "orbit.html")
    rows = read_csv(out)
    page = check_page(browser, tmp_path / "orbit.html", rows, attitude=False)
    assert page.evaluate("newtopView.orbit") is True
    assert "LVLH" in page.evaluate("document.getElementById('mode').textContent")
    n_rows = len(rows["t"])
    for k in (0, n_rows // 2, n_rows - 1):
        s = move_slider(page, rows["t"][k])
        g = np.array([rows[c][k] for c in ("gamma1", "gamma2", "gamma3")])
        n = np.array([rows[c][k] for c in ("normal1", "normal2", "normal3")])
        g, n = g / np.linalg.norm(g), n / np.linalg.norm(n)
        triad = np.array([np.cross(n, g), -n, -g])
        assert np.abs(np.array(s["lvlh"]) - triad).max() < ATTITUDE_TOLERANCE
        q0, q = rows["q0"][k], np.array([rows[c][k] for c in ("q1", "q2", "q3")])
        cross = np.array([[0, -q[2], q[1]], [q[2], 0, -q[0]], [-q[1], q[0], 0]])
        C = (q0 ** 2 - q @ q) * np.eye(3) + 2 * np.outer(q, q) - 2 * q0 * cross
        assert np.abs(C - triad.T).max() < 1e-12  # the row's own attitude, columns = LVLH axes
        # float32 vertices: 1e-6 of the circle's size
        p = np.array(s["orbit_points"])
        assert np.abs(p[0]).max() < 1e-6 and np.abs(p @ n).max() < 1e-5
        assert np.abs(p[2] - (-3.2 * g)).max() < 1e-5  # half an orbit on: across the centre
