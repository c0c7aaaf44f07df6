"""Bezier-Bezier cases shared by tests/pairs/test_bezier_bezier.py, cpp/tests/bezier_bezier_reference.py and the
accuracy report (circledist_cases/accuracy.py)."""

import numpy as np

from . import reference_round as R

# Random curves whose closest pair a "flat" leaf's descent once missed (it ran into another
# basin): the pair is now halved further when a descent ends above what its chords promise.
MISSED_A = (
    (0.39474543867705547, -0.42444917948091332, -1.6536656591517627),
    (-1.699138253536101, -1.8319160918726984, 1.8737655599474268),
    (1.7442957767367999, -0.18004921106059824, 0.25100164667863378),
    (0.60531914564781664, -1.7493154679953511, 1.2578684001083298),
    (1.0573342279069462, -0.68592973953708514, -0.34871979198153435),
    (-1.4751657306234964, -0.022886383733474069, 1.1186187475530667),
)
MISSED_B = (
    (0.68918367564520988, -2.2712453641131716, 0.96806154723334348),
    (0.30006825230758982, -2.5191148849726726, 2.8222541915342454),
    (1.4425582671788817, -1.2817819741205687, 0.061747844195398249),
    (1.422717757521708, -1.6565285174645219, 2.9875888490803115),
    (2.9167547053385672, -0.72137933800183607, 2.1295530247378522),
    (1.4743330217926154, -0.98911081694770397, -0.073385985641913454),
    (-0.23237114587419772, -1.0586974773428661, 0.93982196594780054),
)
MISSED_C = (
    (1.6300852267430948, -1.4823250784567454, -1.8807650229301882),
    (1.7363520518527644, 0.78817408841162706, 1.537807655714913),
    (1.8945695311145339, 0.94460108639216323, 0.1064757827064966),
    (-1.5687514993468357, 0.62750025866420245, -0.89576192908983665),
    (0.70534797193760435, 0.3043629664354297, -0.68483248304606659),
    (-0.052015692483024178, 0.72748659351915812, -0.94927295231932707),
    (1.5287995969196122, -1.4566640288644939, 1.6588311243601774),
)
MISSED_D = (
    (-1.8578544124498564, 0.58430243026410555, -0.42884786932778324),
    (-1.5478785121413405, 1.7804948888882837, 0.9537805819310049),
    (1.6572131829106291, 0.95243983624782069, -0.14067249622065162),
    (1.7073801561252784, -2.0115728707494545, 0.89353975241506933),
    (-1.8916584276318542, -1.2754406790763819, 0.59911589997176817),
    (0.21070827799196953, -1.3960938657582826, -0.7238886780354824),
    (1.6505403039981872, 0.66252563211070736, 0.85291341708662005),
)

# Two nearly parallel straight cubics (hard_scenes' parallel_offset_overlap under the accuracy
# report's generic rotation, translated by 1e6: the control points rounded there), whose distance
# varies by 1.4e-12 along their overlap: the polish stopped 4.8e-13 of their size above the
# lowest point, in double and long double alike (now the valley is searched in one parameter).
VALLEY_A = (
    (1000000.0, -700000.0, 400000.0),
    (1000000.6706493164, -699999.4387242697, 400000.48497324577),
    (1000001.676623291, -699998.5968106744, 400001.2124331144),
    (1000002.0119479492, -699998.3161728093, 400001.4549197373),
)
VALLEY_B = (
    (1000000.4452836048, -699999.2462584302, 400001.0893673197),
    (1000001.1159329212, -699998.6849827, 400001.5743405655),
    (1000002.1219068958, -699997.8430691047, 400002.3018004341),
    (1000002.457231554, -699997.5624312395, 400002.544287057),
)


def shifted(ctrl, by):
    return tuple(tuple(np.array(p, dtype=float) + np.array(by, dtype=float)) for p in ctrl)


ARCH = ((-1, 0, 0), (0, 2, 0), (1, 0, 0))  # apex (0, 1, 0), curvature radius 1/2
CROSS = ((0, 1, -1), (0.5, 1, -0.3), (-0.5, 1, 0.3), (0, 1, 1))  # passes the apex at t = 1/2
CUBIC_A = ((0, 0, 0), (1, 2, 0.5), (2, -1, -0.3), (3, 1.5, 0.2))
CUBIC_B = ((0.5, 1, 1.5), (1.5, -1, 1), (2.5, 2, 0.7), (3.5, 0, 1.2))
LINE = ((0, 0, 0), (1, 0, 0), (2.5, 0, 0), (3, 0, 0))  # collinear, unevenly parametrized
SHIFT = (1e6, -1e6, 1e6)


def hard_scenes():
    """(name, control points a, control points b[, expected `unique`, where clear-cut]):
    the hard pairs of curves tests/pairs/test_bezier_bezier.py and the accuracy report
    (circledist_cases/accuracy.py) share."""
    big = tuple(tuple(1e3 * np.array(p)) for p in CUBIC_A)
    b37 = np.array(R.bezier_point(big, 0.37), dtype=float)
    small = tuple(tuple(b37 + np.array(d)) for d in ((-0.5, 0.6, -0.2), (0.2, 1.1, 0.3), (0.9, 0.65, 0.1)))
    # a small curve passing 0.3 over the big one's interior, bent toward it
    bump = tuple(tuple(b37 + np.array(d)) for d in ((-2, 0, 1), (0, 0, -0.4), (2, 0, 1)))
    return [
        ("crossing", ARCH, CROSS, True),
        ("crossing_translated", shifted(ARCH, SHIFT), shifted(CROSS, SHIFT)),
        ("nearly_touching_1e-9", ARCH, shifted(CROSS, (0, 1e-9, 0))),
        ("nearly_touching_1e-13", ARCH, shifted(CROSS, (0, 1e-13, 0))),
        ("tangent_arches", ARCH, ((-1, 2, 0), (0, 0, 0), (1, 2, 0))),
        ("arches_apart", ARCH, shifted(((-1, 2, 0), (0, 0, 0), (1, 2, 0)), (0.3, 0, 0))),
        ("nearly_parallel_crossing", CUBIC_A, shifted(CUBIC_A, (1e-3, 1e-7, 0))),
        ("parallel_offset", LINE, shifted(LINE, (0, 0.5, 0)), False),
        ("parallel_offset_overlap", LINE, shifted(LINE, (1.25, 0.375, 0.5)), False),
        ("identical", CUBIC_A, CUBIC_A, False),
        ("apart_end_to_end", LINE, shifted(LINE, (4, 0, 0)), True),
        ("big_small", big, small),
        ("big_small_interior", big, bump),
        ("translated", shifted(CUBIC_A, SHIFT), shifted(CUBIC_B, SHIFT)),
        ("translated_quadratics", shifted(ARCH, SHIFT), shifted(((-1, 2, 0.5), (0, -0.5, 0), (1, 2, -0.5)), SHIFT)),
        ("point_curve", ((0.5, 0.5, 0.25),) * 3, CUBIC_A),
        ("point_on_curve", (tuple(float(x) for x in R.bezier_point(CUBIC_A, 0.3)),) * 4, CUBIC_A),
        (
            "collinear_collinear",
            ((-1, 0.2, 0.1), (-0.2, 0.36, 0.14), (1, 0.6, 0.2)),
            ((0.3, -1, 1), (0.3, 0, 0.4), (0.3, 0.5, 0.1), (0.3, 1, -0.2)),
        ),
        ("collinear_curve", ((-1, 0.2, 0.1), (-0.2, 0.36, 0.14), (1, 0.6, 0.2)), CUBIC_B),
        ("folded_collinear", ((0, 0, 0), (3, 0, 0), (1, 0, 0)), ((1.5, 1, -1), (1.5, 1, 1))),
        # random degree 5..6 curves whose closest pair a flat leaf's descent once missed
        ("missed_basin_1", MISSED_A, MISSED_B),
        ("missed_basin_2", MISSED_C, MISSED_D),
        ("flat_valley_translated", VALLEY_A, VALLEY_B),
    ]
