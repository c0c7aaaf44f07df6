"""The modes of the crash-isolating fuzz (tools/fuzz_crash.py, its command line)."""

from .arguments import ARGUMENT_GROWTH, ARGUMENTS, fuzz_arguments, run_argument_case
from .cases import _group_key, fuzz, run_batch, run_case
from .files import FILE_CLASSES, _write_npz, fuzz_files
from .threads import THREAD_TIMEOUT, fuzz_threads, generate_threads, run_thread_case

__all__ = [
    "ARGUMENT_GROWTH",
    "ARGUMENTS",
    "FILE_CLASSES",
    "THREAD_TIMEOUT",
    "_group_key",
    "_write_npz",
    "fuzz",
    "fuzz_arguments",
    "fuzz_files",
    "fuzz_threads",
    "generate_threads",
    "run_argument_case",
    "run_batch",
    "run_case",
    "run_thread_case",
]
