"""python -m circledist [scene.json] [--json [PATH]] [--plot PATH | --no-plot]: see circledist.cli."""

import sys

from .cli import main

sys.exit(main())
