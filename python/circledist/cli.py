"""circledist's command line: answer the queries of a scene file.

    python -m circledist [scene.json | scene.npz] [--json [PATH]] [--plot PATH | --no-plot] [--html PATH]
    circledist [scene] ...                            (the same, as a console script)

Without a scene file it runs the demo scene shipped in the package and draws it to
circledist_demo.png (or the --plot path). The scene format: FORMAT_HELP (--help prints it).

Three steps, a module each: loading and validation (_cli_load: the file, its queries), answering
(_cli_answer) and presentation (_cli_present: the table, JSON, the picture). This module reads the
arguments and writes the outputs, only once everything is computed.
"""

from __future__ import annotations

import argparse
import sys

from ._cli_answer import answer
from ._cli_load import FORMAT_HELP, Query, SceneError, demo_scene_text, format_help, load_scene
from ._cli_present import PICTURE_LIMIT, as_json, check_output, page, picture, table, write_output

__all__ = [
    "main",
    "answer",
    "load_scene",
    "table",
    "as_json",
    "picture",
    "demo_scene_text",
    "Query",
    "SceneError",
    "FORMAT_HELP",
    "DEMO_PICTURE",
    "PICTURE_LIMIT",
]

DEMO_PICTURE = "circledist_demo.png"


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="circledist",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description="Answer the queries of a circledist scene file (JSON or .npz): intersects, within,\n"
        "distance, closest_points, nearest, pairs_within, first_contact, closest_approach. Without\n"
        "a file: the shipped demo\n"
        f"scene, drawn to {DEMO_PICTURE}.",
        epilog=format_help(),
    )
    p.add_argument("scene", nargs="?", help="scene file (.json or .npz); default: the demo scene in the package")
    p.add_argument(
        "--json",
        nargs="?",
        const="-",
        metavar="PATH",
        help="write the answers as JSON to PATH (to standard output, instead of the table, "
        "when PATH is omitted or '-'); a number beyond a double's range (an infinite "
        "distance) is written as null",
    )
    p.add_argument(
        "--plot",
        metavar="PATH",
        help="draw the scene, its closest points and its moving shapes (at start, contact and end) "
        "to PATH (PNG, matplotlib)",
    )
    p.add_argument("--no-plot", action="store_true", help="do not draw the demo scene")
    p.add_argument(
        "--html",
        metavar="PATH",
        help="write an interactive 3-D view of the scene and its closest points to PATH: one "
        "self-contained HTML file (plotly.js inside, no network needed); needs plotly "
        "(pip install 'circledist[view]')",
    )
    p.add_argument("--version", action="version", version=f"circledist {_version()}")
    return p


def _version() -> str:
    from . import __version__

    return __version__


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    plot = args.plot
    if args.scene is None and plot is None and not args.no_plot:
        plot = DEMO_PICTURE
    if args.no_plot:
        plot = None
    try:
        for path in (args.json if args.json != "-" else None, plot, args.html):
            if path is not None:
                check_output(path)
        if args.scene is None:
            scene = load_scene("circledist/scenes/demo.json", demo_scene_text())
        else:
            scene = load_scene(args.scene)
        if plot is not None and scene.count > PICTURE_LIMIT:
            print(
                f"circledist: --plot draws at most {PICTURE_LIMIT} shapes, {scene.path} holds {scene.count}; "
                "use --no-plot",
                file=sys.stderr,
            )
            return 1
        if plot is not None:
            try:
                import matplotlib  # noqa: F401
            except ImportError:
                print(
                    "circledist: --plot needs matplotlib (pip install matplotlib); use --no-plot to skip "
                    "the picture",
                    file=sys.stderr,
                )
                return 1
        if args.html is not None:
            try:
                import plotly  # noqa: F401
            except ImportError:
                print(
                    "circledist: --html needs plotly (pip install 'circledist[view]', or pip install plotly)",
                    file=sys.stderr,
                )
                return 1
        queries = answer(scene)
        text = table(scene, queries)
        payload = as_json(scene, queries) if args.json is not None else None
        image = picture(scene, queries) if plot is not None else None
        html = page(scene) if args.html is not None else None
    except SceneError as e:
        print(f"circledist: error: {e}", file=sys.stderr)
        return 2
    # Everything is computed: only now is anything written.
    outputs = []
    if payload is not None and args.json != "-":
        outputs.append((args.json, payload.encode("utf-8")))
    if image is not None:
        outputs.append((plot, image))
    if html is not None:
        outputs.append((args.html, html))
    for path, data in outputs:
        try:
            write_output(path, data)
        except OSError as e:
            print(f"circledist: error: {path}: cannot write the output: {e.strerror}", file=sys.stderr)
            return 2
    if args.json == "-":
        sys.stdout.write(payload)
    else:
        sys.stdout.write(text)
        if payload is not None:
            print(f"answers written to {args.json}")
    if image is not None:
        print(f"picture written to {plot}")
    if html is not None:
        print(f"interactive view written to {args.html}")
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
