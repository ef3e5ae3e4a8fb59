#!/usr/bin/python3
"""Makes every image of docs/gallery.md from examples/ by running the newtop program.

    /usr/bin/python3 scripts/gallery.py --newtop build/newtop --out docs/img

Each figure comes from a newtop output file (kept in OUT/data/) through newtop.plot; with Chromium
(--chromium, found on PATH by default) the 3D viewer's page is written and photographed too
(viewer.png). The script prints every newtop command it runs. CI runs it into the build folder
(tests/python/test_gallery.py) and checks each figure from its matplotlib objects."""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
from dataclasses import dataclass, field

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "python"))

from newtop import plot, results  # noqa: E402


@dataclass
class Entry:
    """One image: its file, the figure drawn, the newtop commands behind it, and the titles and
    axis labels it must show (checked by the tests)."""

    name: str
    path: str
    figure: object
    commands: list
    titles: list = field(default_factory=list)
    labels: list = field(default_factory=list)


class Gallery:
    def __init__(self, newtop, out, quiet=False):
        self.newtop = newtop
        self.out = out
        self.data = os.path.join(out, "data")
        self.quiet = quiet
        os.makedirs(self.data, exist_ok=True)
        self.entries = []

    def run(self, *args):
        """Runs newtop with args (paths relative to the repository root) in ROOT; returns the
        command line as shown in the docs."""
        cmd = [self.newtop, *(self.shown_path(str(a)) if str(a).startswith(ROOT) else str(a)
                              for a in args)]
        shown = "newtop " + " ".join(self.shown_path(str(a)) for a in args)
        if not self.quiet:
            print("  " + shown, flush=True)
        r = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
        if r.returncode != 0:
            raise RuntimeError(f"{shown}: exit {r.returncode}: {r.stderr.strip()}")
        return shown, r.stdout

    def shown_path(self, a):
        """Paths as a reader would type them: examples/… from the root, outputs by name."""
        if not os.path.isabs(a):
            return a
        rel = os.path.relpath(a, ROOT)
        return rel if not rel.startswith("..") else os.path.basename(a)

    def file(self, name):
        return os.path.join(self.data, name)

    def json(self, name, *args):
        shown, out = self.run(*args, "--json")
        with open(self.file(name), "w") as f:
            f.write(out)
        return shown + " > " + name

    def add(self, name, fig, commands, titles=(), labels=()):
        path = os.path.join(self.out, name)
        plot.save(fig, path)
        self.entries.append(Entry(name, path, fig, list(commands), list(titles), list(labels)))
        if not self.quiet:
            print(f"{path}", flush=True)


def example(name):
    return os.path.join(ROOT, "examples", name)


def trajectory_figures(g: Gallery):
    heavy = g.file("heavy_top.csv")
    c1 = g.run("simulate", example("heavy_top.toml"), "--out", heavy)[0]
    c2 = g.json("heavy_top_equilibria.json", "equilibria", example("heavy_top.toml"))
    fig = plot.trajectory_figure(results.load(heavy),
                                 results.load(g.file("heavy_top_equilibria.json")))
    g.add("trajectory_heavy_top.png", fig, [c1, c2],
          ["Drift of the first integrals", "Path of γ on the Poisson sphere",
           "Path of ω in the body frame"], ["t", "γ1", "p"])
    leo = g.file("leo_satellite.csv")
    c = g.run("simulate", example("leo_satellite.toml"), "--out", leo)[0]
    g.add("drift_leo_satellite.png", plot.trajectory_figure(results.load(leo), panel="drift"),
          [c], ["Drift of the first integrals"], ["t", "|I(t) − I(0)| / |I(0)|"])


def analysis_figures(g: Gallery):
    c = g.json("equilibria.json", "equilibria", example("equilibria_newtonian.toml"))
    g.add("equilibria_newtonian.png", plot.figure(results.load(g.file("equilibria.json"))), [c],
          ["Equilibria over the map of V", "Equilibria on the Poisson sphere"],
          ["longitude atan2(γ2, γ1) [deg]", "γ1"])
    c = g.json("beletsky.json", "stability", example("stability_beletsky.toml"), "--scan-omega",
               "0:3:121")
    g.add("beletsky_diagram.png", plot.figure(results.load(g.file("beletsky.json"))), [c],
          ["Beletsky's diagram: spin about the radius vector"], ["Ω", "max Re s"])
    grid = g.file("beletsky_map.csv")
    c = g.run("stability", example("stability_beletsky.toml"), "--axis", "z", "--scan",
              "omega=0:3:61,C=0.4:2.6:45", "--out", grid)[0]
    g.add("stability_map.png", plot.figure(results.load(grid),
                                           scenario=example("stability_beletsky.toml")), [c],
          ["Stability of the spin about the radius vector over (omega, C)",
           "fixed: A = 1, B = 1.5; M = 1"], ["omega", "C"])
    cone = g.file("staude_cone.csv")
    c = g.json("rotations.json", "rotations", example("rotation_staude_cone.toml"), "--out", cone)
    g.add("staude_cone.png", plot.staude_cone_figure(results.load(cone),
                                                     results.load(g.file("rotations.json"))),
          [c], ["Staude cone γ·(Iγ × r0) = 0", "Staude cone on the Poisson sphere"], ["γ1"])


def sweep_figures(g: Gallery):
    atlas = g.file("sweep_beletsky.csv")
    c = g.run("sweep", example("sweep_beletsky.toml"), "--quiet", "--out", atlas)[0]
    g.add("sweep_beletsky.png", plot.figure(results.load(atlas), quantity="max_real_part"), [c],
          ["Sweep: max_real_part over stability.omega × body.inertia[2]"],
          ["stability.omega", "body.inertia[2]"])
    megno = g.file("sweep_megno.csv")
    c = g.run("sweep", example("sweep_megno.toml"), "--quiet", "--out", megno)[0]
    g.add("sweep_megno.png", plot.figure(results.load(megno), quantity="megno"), [c],
          ["Sweep: megno over initial.omega[0] × initial.omega[1]"],
          ["initial.omega[0]", "initial.omega[1]"])
    level = g.file("sweep_megno_level.csv")
    c = g.run("sweep", example("sweep_megno_level.toml"), "--quiet", "--out", level)[0]
    g.add("sweep_megno_level.png", plot.figure(results.load(level), quantity="megno"), [c],
          ["Sweep: megno over initial.omega[0] × initial.omega[1]"],
          ["initial.omega[0]", "initial.omega[1]"])


def phase_figures(g: Gallery):
    for name in ("section_brun", "section_chaotic"):
        c = g.json(name + ".json", "section", example(name + ".toml"), "--surface", "gamma3 = 0",
                   "--orbits", "12")
        g.add(name + ".png", plot.figure(results.load(g.file(name + ".json")),
                                         scenario=example(name + ".toml")), [c],
              ["Poincaré section", "h = ", "A = 1, B = 1.5, C = 2.2"],
              ["ℓ = atan2(m1, m2), Andoyer angle (rad)", "L/G = m3/|m|"])
    history = g.file("chaos_spectrum.csv")
    c = g.run("chaos", example("section_chaotic.toml"), "--spectrum", "--t-end", "500", "--out",
              history)[0]
    g.add("chaos_spectrum.png", plot.figure(results.load(history)), [c],
          ["The Lyapunov spectrum's history", "MEGNO ⟨Y⟩ (mean)"], ["Lyapunov exponents", "megno", "t (log scale)"])


def other_figures(g: Gallery):
    c = g.json("analytic.json", "analytic", example("analytic_lagrange.toml"), "--samples", "40",
               "--dense", "2000")
    g.add("analytic_lagrange.png", plot.figure(results.load(g.file("analytic.json"))), [c],
          ["closed form (lines), rkf78 (dots)", "Difference", "Nutation θ (cos θ = γ3)",
           "Trace of the symmetry axis e3"], ["t", "θ (deg)"])
    c = g.json("find_integrals.json", "find-integrals", example("brun.toml"))
    g.add("find_integrals_brun.png", plot.figure(results.load(g.file("find_integrals.json"))),
          [c], ["Integral search, degree 2"], ["index of singular value"])
    c = g.json("field.json", "field", example("exact_box_multipole.toml"), "--gamma",
               "0.3,0.5,0.8", "--scan-R", "4:400:25")
    g.add("field_scan_R.png", plot.figure(results.load(g.file("field.json"))), [c],
          ["Error of the quadratic model against the distance R"], ["R"])


def viewer_screenshot(g: Gallery, chromium):
    """The 3D viewer on the Staude-cone scenario's tumbling body, photographed in Chromium."""
    sys.path.insert(0, os.path.join(ROOT, "tests", "viewer"))
    import cdp

    scenario = example("rotation_staude_cone.toml")
    csv = g.file("tumbling.csv")
    c1 = g.run("simulate", scenario, "--out", csv)[0]
    html = g.file("tumbling.html")
    c2 = g.run("view", csv, "--scenario", scenario, "-o", html)[0]
    with cdp.Browser(chromium) as b:
        page = b.new_page(1280, 760)
        page.navigate("file://" + html)
        page.wait_for("window.newtopView !== undefined && window.newtopView.ready === true")
        page.evaluate("newtopView.setTime(newtopView.times[Math.floor(newtopView.frames * 0.6)])")
        png = page.screenshot()
        problems = page.problems()
    if problems:
        raise RuntimeError("viewer page: " + "; ".join(problems))
    path = os.path.join(g.out, "viewer.png")
    with open(path, "wb") as f:
        f.write(png)
    g.entries.append(Entry("viewer.png", path, None, [c1, c2]))
    if not g.quiet:
        print(path, flush=True)


def make(newtop, out, chromium=None, quiet=False):
    """Makes every image into out; returns the entries (figure objects kept for the tests)."""
    import matplotlib

    matplotlib.use("Agg")
    g = Gallery(os.path.abspath(newtop), os.path.abspath(out), quiet)
    trajectory_figures(g)
    analysis_figures(g)
    sweep_figures(g)
    phase_figures(g)
    other_figures(g)
    if chromium:
        viewer_screenshot(g, chromium)
    return g.entries


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--newtop", default=os.path.join(ROOT, "build", "newtop"))
    p.add_argument("--out", default=os.path.join(ROOT, "docs", "img"))
    p.add_argument("--chromium", default=shutil.which("chromium"),
                   help="Chromium for the viewer's screenshot ('' to skip it)")
    p.add_argument("--keep-data", action="store_true",
                   help="keep OUT/data (the newtop outputs); removed by default")
    a = p.parse_args(argv)
    entries = make(a.newtop, a.out, a.chromium or None)
    if not a.keep_data:
        shutil.rmtree(os.path.join(os.path.abspath(a.out), "data"))
    print(f"{len(entries)} images in {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
