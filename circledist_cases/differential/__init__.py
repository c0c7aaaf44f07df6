"""Differential accuracy testing of circledist: a library module.

Nothing here is a test; tests/accuracy/test_differential.py (the CI slice) and tools/differential.py (the
long mode, ``python -m tools.differential``) drive it.  Every name of the modules below is
re-exported here, so ``from circledist_cases import differential as D`` and ``D.name`` reach them.

base              kinds, kind pairs, combinations, bars, case keys
frames            random frames, radii and curves the families draw from
families_round    case families of the pairs with a circle or disk
families_linear   ... of the pairs among points, lines, rays, segments and Bezier curves
families_arc      ... of the arcs
families_annulus  ... of the annuli
families          the registry (FAMILIES), the effect family, generate, case ids, scales
closed_forms      the screen's closed forms and double-double helpers
minimize          the screen's one-parameter minimisation (beam search, Lipschitz zoom)
screen            the fast screen (screen)
residuals         how far a point is from a shape
unique            the exact rule for closest_points().unique (expected_unique)
check             the checker (check_cases)
confirm           confirmation against the 50-digit references
unique_reference  closest_points().unique against the references' own minima (reference_unique)
report            finding classes, reproducers, the direct comparison (reference_check)
runner            effects against their definition, check_and_confirm
"""

from .base import (  # noqa: F401
    ANN_OTHERS, ANN_PAIRS, ANN_RR, ARC_OTHERS, ARC_PAIRS, ARC_RR, BARS, BATCH_ANSWERS, BL, BR,
    EPS32, EPS64, EPSLD, KIND_PAIRS, LD, LINEAR, LL, LL3, LLZ, LR, LR3, OUT_EPS, PRECISIONS, RIMS,
    ROUND, ROUND_PAIRS, RR, SOLVERS, TARGET_REGION, ULPS, _key, _load, _piece_points, _plain,
    answers_per_case, combos)
from .closed_forms import (  # noqa: F401
    _Form, _P, _S_GRID, _THETA_GRID, _T_GRID, _bezier_grid, _cross, _dd_add, _dd_div, _dd_dot,
    _dd_mul, _dd_neg, _diff_ld, _dot, _ld, _ld_frame, _lin_dist, _nrm, _quick, _round_dist, _span,
    _split, _tdist, _two_prod, _two_sum, _x1)
from .minimize import (  # noqa: F401
    ZOOM_CAP, ZOOM_FRACTION, ZOOM_KEEP, ZOOM_PASSES, ZOOM_SPLIT, _beam, _least, _lipschitz,
    _minimize, _minimize_bezier, _refine_ld, _sub_bezier_dd, _zoom)
from .screen import (  # noqa: F401
    LINEAR_PASSES, ScreenResult, _SINH_SPAN, _anchor, _anchor_error, _bezier_eval64,
    _bezier_linear_pass, _dd_vec, _dd_vsub, _linear_pass, _linear_target, _perp_parts, _rim_parts,
    _screen, _screen_bezier_linear, _screen_linear, _segment_extent, _stack, _window, screen)
from .residuals import _pt_minus, residuals  # noqa: F401
from .frames import (  # noqa: F401
    EZ, _Frame, _bezier_through, _elevate, _in_plane, _logu, _npts, _perp, _radius, _rot,
    _tangent_round, _tiny, _unit)
from .families_round import (  # noqa: F401
    _RHO_CHOICES, _TRANSLATED_BASES, _fam_axis, _fam_bezier_far_control, _fam_bezier_large,
    _fam_bezier_plane, _fam_concentric, _fam_coplanar, _fam_far_origin, _fam_far_translated,
    _fam_huge_circle, _fam_near_concentric, _fam_near_touching, _fam_parallel_height,
    _fam_piece_near_plane, _fam_radius_ratio, _fam_random, _fam_shadow_center, _fam_tangent,
    _far_piece, _interesting_line, _tilted_normal, _translate)
from .families_linear import (  # noqa: F401
    EX, EY, _LINEAR_TRANSLATED_BASES, _fam_bezier_crossing, _fam_bezier_far_control_linear,
    _fam_bezier_large_linear, _fam_bezier_tangent_line, _fam_linear_far_origin,
    _fam_linear_far_translated, _fam_linear_random, _fam_near_parallel, _fam_on_piece,
    _fam_zero_length, _parallel_pair, _size)
from .families_arc import (  # noqa: F401
    _ARC_TRANSLATED_BASES, _SPAN_MODES, _arc_angle, _arc_base_kind, _arc_of, _arc_pairs,
    _arc_variant, _cut, _fam_arc_angles, _fam_arc_end_on_axis, _fam_arc_ends,
    _fam_arc_far_translated, _fam_arc_spans, _feature, _offset, _snap, _unit_normal)
from .families_annulus import (  # noqa: F401
    _ANN_TRANSLATED_BASES, _HOLES, _ann_base_kind, _ann_local, _ann_pairs, _ann_variant,
    _axis_normal, _fam_ann_degenerate, _fam_ann_far_translated, _fam_ann_hole,
    _fam_ann_inner_tangent, _fam_ann_overlap, _hole, _inner_circle, _lift)
from .families import (  # noqa: F401
    EFFECT_FAMILIES, FAMILIES, _DEGENERATE_ANGLES, _DEGENERATE_MODES, _DEGENERATE_WEIGHTS,
    _SCALE_CACHE, _fam_effect_degenerate, _oblique_normal, _small_int_vector, _small_shape,
    bar_scale, case_from_id, generate, generate_one, has_round, is_annulus, is_arc, largest_radius,
    scene_scale, to_float32_case)
from .unique import (  # noqa: F401
    UNIQUE_MARGIN, UNIQUE_MIN_ARC, _SYM, _UNIQUE_CACHE, _continuum_round, _expected_unique,
    _fcross_zero, _fr, _fsub, _np, _on_axis, _point_round_unique, expected_unique)
from .check import (  # noqa: F401
    _call, _check_group, _check_hole, _check_scalar, _check_unique, _check_whole, _check_within,
    _compare_replaced, _d_array, _dtype, _eq, _finding, _group, _identical_rows, _jsonable,
    _round_fields, _run_batch, _within_limits, check_cases, make_shape, pair_scale)
from .confirm import (  # noqa: F401
    ACCURACY_CHECKS, EXACT_CHECKS, MISS_REL, _CURVE_MINIMA, _REF_CACHE, _ann_reference,
    _mp_line_point, _mp_num, _mp_piece_distance, _mp_rim, _mp_rim_distance, _mpf_ld, ann_shape,
    confirm, confirm_finding, confirm_point, confirm_separation, mp_reference, mp_screen_value)
from .unique_reference import (  # noqa: F401
    REF_UNIQUE_REL, REF_UNIQUE_RISE, REF_UNIQUE_STEP, _CONVEX, _target_point_unique, _unique_roles,
    reference_unique, unique_direct_check)
from .report import _ctor_text, _lit, finding_class, reference_check, reproducer  # noqa: F401
from .runner import (  # noqa: F401
    EFFECT_PROBES, EFFECT_SWEEPS, _check_scene_effects, _effect_finding, _with_sweep,
    check_and_confirm, check_case, check_effects_definition)
