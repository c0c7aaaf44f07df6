#!/usr/bin/env python3
"""Figures of the documentation. Run from the repository's root: python -m bench.figures

docs/derivations/line_disk.png: the line-disk split of docs/derivations/line_disk.md. Left, the scene: the line's
projection enters the disk at the rim crossing t1 and leaves it at t2, cutting the line into
two outside rays and the inside segment; the closest pair. Right, the distance to the disk
along the line: |z(t)| over the inside segment, the circle distance over the rays, every
candidate of the derivation and the minimum of each piece.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import circledist as cd  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "docs" / "derivations" / "line_disk.png"

# The scene, in the disk's own frame (center 0, normal +z, so U = x, V = y): a line coming down
# over the disk. Its lowest point over the disk is at t2, but the distance keeps falling a little
# past the rim: the closest point is on the right outside ray, a root of the line-circle quartic.
R = 1.0
B = np.array([-2.4, 0.3, 1.6])
M = np.array([1.0, 0.1, -0.42])

BLUE, ORANGE, GREEN, RED, GRAY = "tab:blue", "tab:orange", "tab:green", "tab:red", "0.45"


def rim_crossings():
    """b1 t^2 + 2 b0 t + (c0 - R^2) = 0, stable form."""
    b1 = M[0] ** 2 + M[1] ** 2
    b0 = M[0] * B[0] + M[1] * B[1]
    c = np.hypot(B[0], B[1]) ** 2 - R**2
    disc = b0 * b0 - b1 * c
    q = -(b0 + np.copysign(np.sqrt(disc), b0))
    return tuple(sorted((q / b1, c / q)))


def quartic_roots():
    """Note 000's quartic (C = 0, N = z): the real roots, as line parameters."""
    D = B
    a0, a1 = M @ D, M @ M
    b0 = M @ D - M[2] * D[2]
    b1 = M @ M - M[2] ** 2
    c0, c1, c2 = D @ D - D[2] ** 2, b0, b1
    r2 = R * R
    d = [
        a1 * a1 * c2,
        2 * (a1 * a1 * c1 + a0 * a1 * c2),
        a1 * a1 * c0 + 4 * a0 * a1 * c1 + a0 * a0 * c2 - b1 * b1 * r2,
        2 * (a0 * a1 * c0 + a0 * a0 * c1 - b0 * b1 * r2),
        a0 * a0 * c0 - b0 * b0 * r2,
    ]
    roots = np.roots(d)
    return np.sort(roots[np.abs(roots.imag) < 1e-9].real)


def point(t):
    return B + np.multiply.outer(t, M)


def circle_distance(t):
    p = point(t)
    return np.hypot(p[..., 2], np.hypot(p[..., 0], p[..., 1]) - R)


def height(t):
    return np.abs(point(t)[..., 2])


def main():
    t1, t2 = rim_crossings()
    roots = quartic_roots()
    t_plane = -B[2] / M[2]
    best = cd.closest_points(cd.Line(B, M), cd.Disk([0, 0, 0], [0, 0, 1], R))
    t_best = best.param_a[0]

    lo, hi = -0.3, 4.6
    fig = plt.figure(figsize=(15, 7.2))

    # ---- left: the scene ----------------------------------------------------------------------
    ax = fig.add_axes([0.0, 0.2, 0.5, 0.76], projection="3d")
    theta = np.linspace(0, 2 * np.pi, 200)
    rim = np.stack([R * np.cos(theta), R * np.sin(theta), 0 * theta], axis=1)
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    ax.add_collection3d(Poly3DCollection([rim], facecolor="0.82", edgecolor="none", alpha=0.55))
    ax.plot(*rim.T, color="k", lw=1.2)
    ax.text(-0.35, -0.75, 0, "disk (center C, radius R)", color="0.25", fontsize=8)
    ax.plot([0, 0], [0, 0], [0, 0.5], color="k", lw=1)
    ax.text(0.02, 0.0, 0.52, "N", fontsize=9)

    def seg(a, b, **kw):
        p = point(np.array([a, b]))
        ax.plot(*p.T, **kw)

    seg(lo, t1, color=BLUE, lw=2.5, label="outside ray $t \\leq t_1$: disk distance = circle distance")
    seg(t1, t2, color=ORANGE, lw=3.5, label="inside segment $[t_1, t_2]$: disk distance = $|z(t)|$")
    seg(t2, hi, color=GREEN, lw=2.5, label="outside ray $t \\geq t_2$: disk distance = circle distance")
    # The projection on the disk's plane, its chord, and the drops from the rim crossings.
    proj = point(np.array([lo, hi]))
    proj[:, 2] = 0
    ax.plot(*proj.T, color=GRAY, lw=1, ls="--", label="projection of the line on the plane")
    chord = point(np.array([t1, t2]))
    chord[:, 2] = 0
    ax.plot(*chord.T, color=ORANGE, lw=1.5, ls="--")
    for t, name in ((t1, "$P(t_1)$"), (t2, "$P(t_2)$")):
        p = point(t)
        ax.plot([p[0], p[0]], [p[1], p[1]], [p[2], 0], color=GRAY, lw=1, ls=":")
        ax.scatter(*p, color="k", s=18, zorder=5)
        ax.scatter(p[0], p[1], 0, color="k", s=10)
        ax.text(p[0] - 0.25, p[1] + 0.1, p[2] + 0.12, name, fontsize=9)
    pa, pb = best.point_a, best.point_b
    ax.plot([pa[0], pb[0]], [pa[1], pb[1]], [pa[2], pb[2]], color=RED, lw=2)
    ax.scatter(*pa, color=RED, s=30, zorder=6, label=f"closest pair (on the rim), distance {best.distance:.3f}")
    ax.scatter(*pb, color=RED, s=30, zorder=6)
    ax.set_xlim(-2.2, 2.2)
    ax.set_ylim(-1.3, 1.3)
    ax.set_zlim(-0.2, 1.6)
    ax.set_box_aspect((4.4, 2.6, 1.8), zoom=1.15)
    ax.view_init(elev=20, azim=-60)
    ax.set_xlabel("x (along U)", fontsize=8)
    ax.set_ylabel("y (along V)", fontsize=8)
    ax.set_zlabel("z (along N)", fontsize=8)
    ax.tick_params(labelsize=7)
    ax.set_title("The split of the line P(t) = B + tM by the disk's cylinder", fontsize=11)
    ax.legend(loc="upper center", fontsize=8, framealpha=0.9, bbox_to_anchor=(0.5, 0.0))

    # ---- right: the distance along the line -------------------------------------------------------
    bx = fig.add_axes([0.575, 0.3, 0.41, 0.63])
    t = np.linspace(lo, hi, 4000)
    bx.axvspan(t1, t2, color=ORANGE, alpha=0.08)
    bx.text((t1 + t2) / 2, 2.45, "inside: $x^2 + y^2 \\leq R^2$", ha="center", fontsize=8, color="0.3")
    left, inside, right = t <= t1, (t >= t1) & (t <= t2), t >= t2
    bx.plot(
        t[inside],
        circle_distance(t[inside]),
        color=GRAY,
        lw=1,
        ls=":",
        label="circle distance over the chord (not the disk's)",
    )
    bx.plot(
        t,
        np.abs(point(t)[:, 2]),
        color=ORANGE,
        lw=0.8,
        ls="--",
        alpha=0.6,
        label="$|z(t)|$ continued: kink at the plane crossing",
    )
    bx.plot(t[left], circle_distance(t[left]), color=BLUE, lw=2.2)
    bx.plot(t[inside], height(t[inside]), color=ORANGE, lw=2.8)
    bx.plot(t[right], circle_distance(t[right]), color=GREEN, lw=2.2)

    bx.scatter(
        roots,
        circle_distance(roots),
        marker="x",
        color="k",
        s=45,
        zorder=5,
        label="real roots of the quartic (candidates)",
    )
    bx.scatter(
        [t1, t2],
        height(np.array([t1, t2])),
        marker="o",
        facecolor="white",
        edgecolor="k",
        s=40,
        zorder=5,
        label="rim crossings $t_1, t_2$: ray origins, segment ends",
    )
    bx.scatter(
        [t_plane], [0], marker="D", color=GRAY, s=30, zorder=5, label="plane crossing z = 0: outside $[t_1, t_2]$ here"
    )
    # The minimum of each piece, and the smallest.
    right_roots = roots[roots >= t2]
    tr = right_roots[np.argmin(circle_distance(right_roots))]
    mins = [(t1, circle_distance(t1), BLUE), (t2, height(t2), ORANGE), (tr, circle_distance(tr), GREEN)]
    for tm, dm, color in mins:
        bx.scatter([tm], [dm], marker="*", s=170, color=color, edgecolor="k", zorder=6)
    bx.scatter([], [], marker="*", s=120, color="w", edgecolor="k", label="the minimum of each piece")
    bx.scatter(
        [t_best],
        [best.distance],
        marker="o",
        s=260,
        facecolor="none",
        edgecolor=RED,
        lw=1.8,
        zorder=7,
        label=f"the smallest of the three: the distance, {best.distance:.4f}",
    )
    bx.annotate(
        "left ray: its origin $t_1$",
        (t1, circle_distance(t1)),
        (0.2, 0.45),
        fontsize=8,
        arrowprops=dict(arrowstyle="->", color=BLUE),
    )
    bx.annotate(
        "a quartic root over the chord:\nevaluated on the disk distance,\nnot a minimum",
        (roots[0], circle_distance(roots[0])),
        (1.62, 0.1),
        fontsize=8,
        arrowprops=dict(arrowstyle="->", color="k"),
    )
    bx.set_xlim(lo, hi)
    bx.set_ylim(-0.05, 2.6)
    bx.set_xlabel("t")
    bx.set_ylabel("distance from P(t) to the disk")
    bx.set_title("Distance along the line: three pieces, three minima", fontsize=11)
    bx.grid(alpha=0.3)
    bx.legend(loc="upper center", bbox_to_anchor=(0.5, -0.11), ncol=2, fontsize=8, framealpha=0.9)

    # Zoom on the rim crossing t2, where the inside minimum and the right ray's minimum are close.
    ix = bx.inset_axes([0.55, 0.53, 0.43, 0.36])
    tz = np.linspace(t2 - 0.35, t2 + 0.45, 800)
    ins, out = tz <= t2, tz >= t2
    ix.plot(tz[ins], height(tz[ins]), color=ORANGE, lw=2.4)
    ix.plot(tz[out], circle_distance(tz[out]), color=GREEN, lw=2.2)
    ix.plot(tz[out], height(tz[out]), color=ORANGE, lw=0.8, ls="--", alpha=0.6)
    ix.axvline(t2, color=GRAY, lw=0.8, ls=":")
    ix.scatter([t2], [height(t2)], marker="*", s=150, color=ORANGE, edgecolor="k", zorder=6)
    ix.scatter([tr], [circle_distance(tr)], marker="*", s=150, color=GREEN, edgecolor="k", zorder=6)
    ix.scatter([t_best], [best.distance], marker="o", s=220, facecolor="none", edgecolor=RED, lw=1.6, zorder=7)
    ix.annotate(
        "$t_2$: the inside minimum",
        (t2, height(t2)),
        (2.87, 0.18),
        fontsize=7,
        arrowprops=dict(arrowstyle="->", color=ORANGE),
    )
    ix.annotate(
        "a quartic root:\nthe right ray's minimum",
        (tr, circle_distance(tr)),
        (3.24, 0.355),
        fontsize=7,
        arrowprops=dict(arrowstyle="->", color=GREEN),
    )
    ix.set_ylim(0.16, 0.42)
    ix.tick_params(labelsize=7)
    ix.set_title("zoom near $t_2$", fontsize=8)
    bx.indicate_inset_zoom(ix, edgecolor="0.5")

    OUT.parent.mkdir(exist_ok=True)
    fig.savefig(OUT, dpi=110)
    print(
        f"written {OUT.relative_to(ROOT)}: rim crossings t1 = {t1:.4f}, t2 = {t2:.4f}; quartic roots {roots}; "
        f"closest t = {t_best:.4f}, distance {best.distance:.6f}"
    )


if __name__ == "__main__":
    main()
