"""Hostile .npz scene files: every member checked from its header (dtype, shape, declared and
real size) before its data is inflated, so that bombs, lying headers, unsupported compression and
corrupt members are one-line errors with little memory allocated; and the writer's file modes.
The well-formed scenes and their good .npz reads are in test_scene_file.py."""

import os

import numpy as np
import pytest

cd = pytest.importorskip("circledist")
cli = pytest.importorskip("circledist.cli")
sf = pytest.importorskip("circledist.scenefile")

from test_scene_file import GOOD_NPZ, RING, _npz  # noqa: E402


def _zip(tmp_path, members, name="hostile.npz", method=None):
    """An .npz written member by member (the hostile-files fuzz's writer): name -> an array-like
    (written as .npy) or raw bytes, or a callable writing to the member's stream."""
    from tools.fuzz_crash import _write_npz

    path = tmp_path / name
    _write_npz(
        path,
        {
            member: value if callable(value) or isinstance(value, bytes) else np.asanyarray(value)
            for member, value in members.items()
        },
        method,
    )
    return str(path)


def _good_members(**changes):
    members = {f"{k}.npy": v for k, v in GOOD_NPZ.items()}
    for k, v in changes.items():
        members.pop(f"{k}.npy", None)
        if v is not None:
            members[f"{k}.npy"] = v
    return members


def _header_only(shape, descr="<f8", data=b""):
    """A .npy member whose header claims shape (descr) followed by `data` (none: a lying header)."""

    def write(f):
        np.lib.format.write_array_header_1_0(f, {"descr": descr, "fortran_order": False, "shape": shape})
        f.write(data)

    return write


def _zeros(count):
    """count zero bytes in 1 MiB pieces (deflated: a zip bomb)."""

    def write(f):
        piece = bytes(1 << 20)
        for _ in range(count >> 20):
            f.write(piece)
        f.write(bytes(count & ((1 << 20) - 1)))

    return write


BOMB = 64 << 20  # about the bytes a bomb member inflates to


def _bomb(shape, descr="<f8", size=None):
    """A member with a header of shape (descr) and its data (size bytes: default, the header's)."""

    def write(f):
        np.lib.format.write_array_header_1_0(f, {"descr": descr, "fortran_order": False, "shape": shape})
        _zeros(int(np.prod(shape)) * np.dtype(descr).itemsize if size is None else size)(f)

    return write


def _read_measured(path):
    """read_scene's error and the peak memory NumPy and Python allocated on the way."""
    import tracemalloc

    tracemalloc.start()
    try:
        with pytest.raises(sf.SceneFileError) as error:
            sf.read_scene(path)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    return str(error.value), peak


ROWS = BOMB // 24  # rows of 3 doubles in a bomb
HOSTILE_NPZ = [
    (
        "header claims 10^12 rows",
        {"rings/center.npy": _header_only((10**12, 3))},
        "array 'rings/center'",
        "its header says shape (1000000000000, 3) of dtype float64 (24000000000000 bytes), the member holds 0 bytes",
    ),
    (
        "header claims more than its data",
        {"rings/radius.npy": _header_only((10**6,), data=bytes(800))},
        "array 'rings/radius'",
        "the member holds 800 bytes",
    ),
    (
        "header claims less than its data",
        {"rings/radius.npy": _header_only((3,), data=bytes(800))},
        "array 'rings/radius'",
        "(24 bytes), the member holds 800 bytes",
    ),
    (
        "bomb of the wrong rows",
        {"rings/center.npy": _bomb((ROWS, 3))},
        "array 'rings/center'",
        f"expected 3 rows (the batch's count) or 1, got {ROWS}",
    ),
    (
        "bomb of the wrong shape",
        {"rings/center.npy": _bomb((BOMB // 16, 2))},
        "array 'rings/center'",
        f"expected shape [rows (count or 1)] + (3,), got ({BOMB // 16}, 2)",
    ),
    (
        "bomb under a small header",
        {"rings/radius.npy": _bomb((3,), size=BOMB)},
        "array 'rings/radius'",
        "(24 bytes), the member holds",
    ),
    (
        "bomb as the format",
        {"format.npy": _bomb((), descr=f"<U{BOMB // 4}")},
        "array 'format'",
        "expected a 0-d string array of a word",
    ),
    (
        "bomb as a kind",
        {"rail/kind.npy": _bomb((), descr=f"<U{BOMB // 4}")},
        "array 'rail/kind'",
        "expected a 0-d string array of a word",
    ),
    (
        "bomb as the names",
        {"shapes.npy": _bomb((BOMB // 40,), descr="<f8")},
        "array 'shapes'",
        "expected a non-empty 1-d string array of names",
    ),
    (
        "bomb as the version",
        {"version.npy": _bomb((BOMB // 8,), descr="<i8")},
        "array 'version'",
        "expected a 0-d integer array",
    ),
    (
        "object header",
        {"rings/radius.npy": _header_only((3,), descr="|O", data=bytes(24))},
        "array 'rings/radius'",
        "expected a plain NumPy array: dtype object holds Python objects",
    ),
    ("an unknown member", {"notes.txt": b"hello"}, "array 'notes.txt'", "unknown: not a field"),
    (
        "a member without .npy",
        {"rings/radius.npy": None, "rings/radius": b"hello"},
        "array 'rings/radius'",
        "expected a plain NumPy array (.npy): the member does not start with NumPy's magic string",
    ),
    (
        "raw bytes as a member",
        {"rings/radius.npy": b"\x00" * 30},
        "array 'rings/radius'",
        "expected a plain NumPy array (.npy)",
    ),
    (
        "npy version 9",
        {"rings/radius.npy": b"\x93NUMPY\x09\x00" + b"\x00" * 30},
        "array 'rings/radius'",
        "expected a .npy header of version 1.0 or 2.0, got (9, 0)",
    ),
    (
        "raw bytes as the names",
        {"shapes.npy": b"rings, rail"},
        "array 'shapes'",
        "the member does not start with NumPy's magic string",
    ),
]


@pytest.mark.parametrize("label, changes, where, message", HOSTILE_NPZ, ids=[h[0] for h in HOSTILE_NPZ])
def test_hostile_npz_members_are_refused_from_their_header(tmp_path, label, changes, where, message):
    """Each member's .npy header (dtype, shape) is checked against what its role allows and
    against the member's uncompressed size before its data is read: one line naming the array,
    and no more memory than a few MiB whatever the member would inflate to."""
    import zipfile

    members = _good_members()
    members.update(changes)
    members = {k: v for k, v in members.items() if v is not None}
    path = _zip(tmp_path, members, method=zipfile.ZIP_DEFLATED)
    assert os.path.getsize(path) < 1 << 20  # the bombs are small files
    text, peak = _read_measured(path)
    assert text.startswith(f"{path}: {where}: ") and message in text, text
    assert "\n" not in text
    assert peak < 8 << 20, f"{peak / 2**20:.0f} MiB allocated"


@pytest.mark.parametrize("method", [9, 12, 14, 99], ids=["deflate64", "bzip2-id", "lzma-id", "aes"])
def test_npz_of_an_unsupported_compression_method(tmp_path, method):
    """A member compressed with a method this reader cannot inflate (deflate64, AES-encrypted, or
    an id patched in): one line naming the member and the method, not zipfile's exception."""
    path = _zip(tmp_path, _good_members())
    with open(path, "rb") as f:
        data = bytearray(f.read())
    # Patch the method of the member 'format.npy' in its local header and the central directory.
    for signature, offset, name_at in ((b"PK\x03\x04", 8, 30), (b"PK\x01\x02", 10, 46)):
        at = data.find(signature)
        while at >= 0:
            if data[at + name_at : at + name_at + 10] == b"format.npy":
                data[at + offset : at + offset + 2] = method.to_bytes(2, "little")
            at = data.find(signature, at + 4)
    with open(path, "wb") as f:
        f.write(data)
    if method in (12, 14):  # bzip2 and lzma exist: the patched member is no such stream
        with pytest.raises(sf.SceneFileError, match=r"array 'format': expected a plain NumPy array"):
            sf.read_scene(path)
        return
    with pytest.raises(sf.SceneFileError) as error:
        sf.read_scene(path)
    assert str(error.value) == (
        f'{path}: member "format.npy": compressed with zip method {method}, which this '
        "reader cannot inflate (numpy.savez stores, numpy.savez_compressed deflates)"
    )


def test_npz_surrogates_and_deep_queries(tmp_path):
    """The .npz form's strings and query text meet the same checks as JSON's."""
    # (A zip member's name cannot hold it: the names are checked before their arrays are looked for.)
    path = _npz(tmp_path, {**GOOD_NPZ, "shapes": np.array(["rings", "r\ud800"])}, "surrogate.npz")
    with pytest.raises(sf.SceneFileError, match=r"array 'shapes' at index 1: expected text, got a lone surrogate"):
        sf.read_scene(path)
    path = _npz(tmp_path, {**GOOD_NPZ, "description": np.array("\udfff")}, "description.npz")
    with pytest.raises(
        sf.SceneFileError, match=r"array 'description': expected text, got a lone surrogate " r"\(U\+DFFF\)"
    ):
        sf.read_scene(path)
    for depth in [100, 500] + list(range(800, 1000, 9)) + [10**4]:
        text = '[{"a": "rail", "effects": ["nearest"], "k": %s}]' % ("[" * depth + "]" * depth)
        path = _npz(tmp_path, {**GOOD_NPZ, "queries": np.array(text)}, "deep.npz")
        with pytest.raises(sf.SceneFileError, match=r"array 'queries'") as error:
            sf.read_scene(path)
        assert "\n" not in str(error.value) and len(str(error.value)) < 400, depth


@pytest.mark.parametrize("suffix", [".json", ".npz"])
def test_write_scene_honours_the_umask_and_keeps_a_replaced_files_mode(tmp_path, umask_022, suffix):
    path = tmp_path / f"scene{suffix}"
    sf.write_scene(path, {"ring": RING})
    assert os.stat(path).st_mode & 0o777 == 0o644
    os.chmod(path, 0o604)
    sf.write_scene(path, {"ring": RING})
    assert os.stat(path).st_mode & 0o777 == 0o604
    os.umask(0o077)
    sf.write_scene(tmp_path / f"private{suffix}", {"ring": RING})
    assert os.stat(tmp_path / f"private{suffix}").st_mode & 0o777 == 0o600


def test_corrupt_deflated_members_are_one_line(tmp_path):
    """Every member of a deflated .npz with bytes of its compressed data changed (zlib's errors, a
    CRC that does not match): a SceneFileError naming the file, whichever byte it is."""
    import zipfile

    path = _zip(tmp_path, _good_members(), method=zipfile.ZIP_DEFLATED)
    with open(path, "rb") as f:
        good = f.read()
    with zipfile.ZipFile(path) as z:
        infos = z.infolist()
    refused = 0
    for info in infos:
        name_length, extra_length = (
            int.from_bytes(good[info.header_offset + 26 : info.header_offset + 28], "little"),
            int.from_bytes(good[info.header_offset + 28 : info.header_offset + 30], "little"),
        )
        start = info.header_offset + 30 + name_length + extra_length
        for at in sorted(
            {start, start + info.compress_size // 3, start + info.compress_size // 2, start + info.compress_size - 1}
        ):
            data = bytearray(good)
            data[at] ^= 0xA5
            bad = tmp_path / "bad.npz"
            bad.write_bytes(bytes(data))
            try:
                sf.read_scene(str(bad))
            except sf.SceneFileError as e:
                assert str(e).startswith(f"{bad}: ") and "\n" not in str(e), str(e)
                refused += 1
    assert refused > len(infos)  # most changes are refused (the rest still make a valid scene)
