"""scripts/gallery.py, run into a scratch folder: every image of docs/gallery.md is written and not
empty, and each figure shows the titles and axis labels that say what it is (read from the
matplotlib objects, not from pixels)."""

from __future__ import annotations

import importlib.util
import os
import shutil
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
EXE = os.environ.get("NEWTOP_EXE", os.path.join(ROOT, "build", "newtop"))
CHROMIUM = os.environ.get("NEWTOP_CHROMIUM") or shutil.which("chromium")
#: A PNG of a drawn figure is tens of kilobytes; an empty canvas compresses below this.
MIN_IMAGE_BYTES = 10_000


def load_gallery():
    spec = importlib.util.spec_from_file_location("gallery", os.path.join(ROOT, "scripts",
                                                                          "gallery.py"))
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod  # dataclasses look their module up there
    spec.loader.exec_module(mod)
    return mod


def test_gallery_images_and_their_labels(tmp_path):
    entries = load_gallery().make(EXE, tmp_path, CHROMIUM, quiet=True)
    docs = open(os.path.join(ROOT, "docs", "gallery.md")).read()
    names = [e.name for e in entries]
    assert len(names) == len(set(names))
    if CHROMIUM:
        assert "viewer.png" in names
    for e in entries:
        assert os.path.getsize(e.path) > MIN_IMAGE_BYTES, e.name
        assert f"img/{e.name}" in docs, f"docs/gallery.md does not show {e.name}"
        assert e.commands, e.name
        if e.figure is None:
            continue
        fig = e.figure
        shown = [ax.get_title() for ax in fig.axes] + [fig._suptitle.get_text()
                                                      if fig._suptitle else ""]
        for title in e.titles:
            assert any(title in s for s in shown), f"{e.name}: no title '{title}' in {shown}"
        labels = [ax.get_xlabel() for ax in fig.axes] + [ax.get_ylabel() for ax in fig.axes]
        for label in e.labels:
            assert label in labels, f"{e.name}: no axis label '{label}' in {labels}"
        for ax in fig.axes:
            if ax.get_label() != "<colorbar>":
                assert ax.get_title() and ax.get_xlabel(), f"{e.name}: unlabelled axes"
