"""Drawing on the Poisson sphere |γ| = 1: the quadratic potential, a longitude–latitude map, and the
equilibria's markers. Conventions: longitude φ = atan2(γ2, γ1), latitude β = asin(γ3), in degrees;
all vectors in the body's principal axes (as newtop writes them)."""

from __future__ import annotations

import numpy as np

#: Marker and colour of each equilibrium type (newtop equilibria, docs/model.md §7).
EQUILIBRIUM_STYLE = {
    "minimum": dict(marker="v", color="#1a9850", label="minimum (stable)"),
    "saddle": dict(marker="X", color="#fdae61", label="saddle"),
    "maximum": dict(marker="^", color="#d73027", label="maximum"),
    "degenerate": dict(marker="D", color="#7570b3", label="degenerate"),
}
AXIS_INDEX = {"x": 0, "y": 1, "z": 2}


def quadratic_potential(model, gamma):
    """V(γ) = M g r0·γ + ½ λ γ·Iγ (docs/model.md §3) from the "model" block of newtop's JSON; gamma has
    shape (..., 3)."""
    inertia = np.asarray(model["inertia"], dtype=float)
    mg_r0 = model["mass"] * model["g"] * np.asarray(model["center_of_mass"], dtype=float)
    return gamma @ mg_r0 + 0.5 * model["lambda"] * np.einsum("...i,i,...i->...", gamma, inertia,
                                                            gamma)


def lon_lat(gamma):
    """Longitude and latitude (degrees) of unit vectors of shape (..., 3)."""
    g = np.asarray(gamma, dtype=float)
    lon = np.degrees(np.arctan2(g[..., 1], g[..., 0]))
    lat = np.degrees(np.arcsin(np.clip(g[..., 2], -1.0, 1.0)))
    return lon, lat


def grid(n_lon=361, n_lat=181):
    """A longitude–latitude grid (degrees) and the unit vectors on it, shape (n_lat, n_lon, 3)."""
    lon = np.linspace(-180.0, 180.0, n_lon)
    lat = np.linspace(-90.0, 90.0, n_lat)
    LON, LAT = np.meshgrid(np.radians(lon), np.radians(lat))
    g = np.stack([np.cos(LAT) * np.cos(LON), np.cos(LAT) * np.sin(LON), np.sin(LAT)], axis=-1)
    return lon, lat, g


def split_at_dateline(lon, lat, jump=180.0):
    """Breaks a path where the longitude wraps (inserts NaN) so that a map does not draw a line
    across it."""
    lon = np.asarray(lon, dtype=float)
    lat = np.asarray(lat, dtype=float)
    cut = np.nonzero(np.abs(np.diff(lon)) > jump)[0] + 1
    return np.insert(lon, cut, np.nan), np.insert(lat, cut, np.nan)


def draw_sphere(ax, alpha=0.12):
    """A light wire sphere of radius 1 and the body axes on 3D axes."""
    u = np.linspace(0.0, 2.0 * np.pi, 37)
    v = np.linspace(0.0, np.pi, 19)
    x = np.outer(np.cos(u), np.sin(v))
    y = np.outer(np.sin(u), np.sin(v))
    z = np.outer(np.ones_like(u), np.cos(v))
    ax.plot_wireframe(x, y, z, color="0.6", linewidth=0.4, alpha=alpha * 3)
    for i, name in enumerate("xyz"):
        e = np.zeros(3)
        e[i] = 1.25
        ax.plot(*[[-c, c] for c in e], color="0.45", linewidth=0.6)
        ax.text(*(e * 1.05), name, color="0.3")
    set_equal_3d(ax, 1.2)


def draw_on_top(ax):
    """Draw 3D artists in the order of their zorder, so that markers stay above a sphere's surface
    (matplotlib's own depth sort of a surface against points is unreliable)."""
    try:
        ax.computed_zorder = False
    except AttributeError:  # matplotlib < 3.5
        pass


def set_equal_3d(ax, r):
    ax.set_xlim(-r, r)
    ax.set_ylim(-r, r)
    ax.set_zlim(-r, r)
    try:
        ax.set_box_aspect((1, 1, 1))
    except AttributeError:  # matplotlib < 3.3
        pass


def equilibria_points(eq_data):
    """(type, γ) of every isolated equilibrium of an equilibria JSON."""
    return [(e["type"], np.asarray(e["gamma"], dtype=float)) for e in eq_data.get("equilibria", [])]


def circle_points(circle, n=181):
    """Points of a circle of equilibria {"axis": "x|y|z", "gamma_axis": c}: γ_axis = c."""
    a = AXIS_INDEX.get(circle["axis"], circle["axis"]) if isinstance(circle["axis"], str) else \
        int(circle["axis"])
    c = float(circle["gamma_axis"])
    s = np.sqrt(max(0.0, 1.0 - c * c))
    t = np.linspace(0.0, 2.0 * np.pi, n)
    others = [i for i in range(3) if i != a]
    g = np.zeros((n, 3))
    g[:, a] = c
    g[:, others[0]] = s * np.cos(t)
    g[:, others[1]] = s * np.sin(t)
    return g


def mark_equilibria(ax, eq_data, three_d, size=70):
    """Markers for the equilibria (one legend entry per type) and lines for circles of them."""
    seen = set()
    for kind, g in equilibria_points(eq_data):
        style = dict(EQUILIBRIUM_STYLE.get(kind, EQUILIBRIUM_STYLE["degenerate"]))
        label = style.pop("label")
        kw = dict(s=size, edgecolors="k", linewidths=0.6, zorder=5, gid="equilibrium",
                  label=None if kind in seen else label, **style)
        seen.add(kind)
        if three_d:  # just outside the sphere, drawn last (see draw_on_top)
            p = 1.04 * g
            ax.scatter([p[0]], [p[1]], [p[2]], depthshade=False, **kw)
        else:
            lon, lat = lon_lat(g)
            ax.scatter([lon], [lat], **kw)
    for i, c in enumerate(eq_data.get("circles", []) or []):
        pts = circle_points(c)
        label = "circle of equilibria" if i == 0 else None
        if three_d:
            ax.plot(pts[:, 0], pts[:, 1], pts[:, 2], color="#7570b3", linewidth=2, label=label)
        else:
            lon, lat = split_at_dateline(*lon_lat(pts))
            ax.plot(lon, lat, color="#7570b3", linewidth=2, label=label)
