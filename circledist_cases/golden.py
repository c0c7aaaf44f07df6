"""Golden-section search, shared by the 50-digit references (reference_linear_round.py, reference_round.py,
reference_linear.py): each brackets a minimum of its own one-parameter function by sampling and
narrows the bracket here."""

from __future__ import annotations


def golden_section(f, a, b, invphi, tol=0, steps=1000):
    """Narrows [a, b] around a minimum of the unimodal f: each step keeps the part of the bracket
    that holds the lower of its two inner points and evaluates f once. Stops after `steps` steps
    or once the bracket is at most `tol` wide. `invphi`, (sqrt(5) - 1) / 2 in the caller's
    precision (its mpmath context). Returns (x, f(x)) of the lower inner point."""
    c = b - invphi * (b - a)
    d = a + invphi * (b - a)
    fc, fd = f(c), f(d)
    for _ in range(steps):
        if b - a <= tol:
            break
        if fc <= fd:
            b, d, fd = d, c, fc
            c = b - invphi * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + invphi * (b - a)
            fd = f(d)
    return (c, fc) if fc <= fd else (d, fd)
