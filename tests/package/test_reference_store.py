"""The recorded 50-digit references (tests/references/, circledist_cases/reference_store.py): every
file was recorded by the code there is now, every value reads back exactly, and a stored function
reads, samples and records as its modes say."""

from __future__ import annotations

import dataclasses
import json
import math

import numpy as np
import pytest
from mpmath import mp

from circledist_cases import reference_kit as K
from circledist_cases import reference_store as S

FILES = sorted(S.STORE.glob("*.json"))


def test_there_are_recorded_references():
    assert FILES, f"no recorded references in {S.STORE}: python -m tools.references record"


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_recorded_with_the_code_there_is_now(path):
    data = json.loads(path.read_text())
    assert data["source"] == S.source_hash(data["sources"]), (
        f"{path.name} was recorded by other reference code than today's ({', '.join(data['sources'])} or "
        "circledist_cases/reference*.py changed): python -m tools.references record"
    )


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_every_value_reads_back_exactly(path):
    values = json.loads(path.read_text())["values"]
    assert values
    for key, value in values.items():
        assert len(key) == 32 and int(key, 16) >= 0
        assert S.encode(S.decode(value)) == value


@dataclasses.dataclass
class Pair:
    value: object
    points: tuple
    t: object = None


def exact_samples():
    third = K.mpf(1) / 3
    return [
        third,
        -third * K.mpf(10) ** -300,
        K.mpf(0),
        mp.mpf(2) ** 0.5,
        0.1,
        -0.0,
        math.inf,
        5e-324,
        np.float64(1) / 3,
        np.longdouble(1) / np.longdouble(3),
        7,
        True,
        None,
        "arc",
        (1.5, [third, None], {"a": 2.0}),
        np.arange(6.0).reshape(2, 3),
        Pair(third, (third, 0.25, K.mpf(2)), t=K.mpf("0.5")),
    ]


@pytest.mark.parametrize("value", exact_samples(), ids=lambda v: type(v).__name__)
def test_values_are_stored_exactly(value):
    back = S.decode(json.loads(json.dumps(S.encode(value))))
    assert type(back) is type(value) or isinstance(value, (np.float64,)) and type(back) is float
    assert S.encode(back) == S.encode(value)
    if isinstance(value, K.ctx.mpf):
        assert back == value and isinstance(back, K.ctx.mpf)
    if isinstance(value, mp.mpf):
        assert back == value and isinstance(back, mp.mpf)
    if isinstance(value, float):
        assert math.copysign(1, back) == math.copysign(1, value) and (back == value)


def test_close_tells_recorded_from_other_values():
    third = K.mpf(1) / 3
    assert S.close(third, third + K.mpf(10) ** -45)
    assert not S.close(third, third + K.mpf(10) ** -20)
    assert S.close(1.0, np.nextafter(1.0, 2.0)) and not S.close(1.0, 1.0 + 4e-16)
    assert S.close(Pair(third, (1.0,)), Pair(third, (1.0,))) and not S.close(Pair(third, (1.0,)), Pair(third, (2.0,)))
    assert not S.close((True, "a"), (None, "a"))


calls = []


def _toy_reference(x, scale=1.0):
    """Stored afresh (S.stored, an empty in-process memo) at each step of the test below."""
    calls.append(x)
    return K.to_mp(x) * scale / 3


def _keys_in_and_out_of_the_sample():
    inside = next(x for x in range(1000) if int(S.key_of((float(x),), {}), 16) % S.SAMPLE_EVERY == 0)
    outside = next(x for x in range(1000) if int(S.key_of((float(x),), {}), 16) % S.SAMPLE_EVERY)
    return float(inside), float(outside)


def test_a_stored_function_records_reads_and_samples(tmp_path, monkeypatch):
    monkeypatch.setattr(S, "STORE", tmp_path)
    monkeypatch.setattr(S, "_files", {})
    inside, outside = _keys_in_and_out_of_the_sample()
    # record: computed and written
    monkeypatch.setenv("CIRCLEDIST_REFERENCES", "record")
    calls.clear()
    recorder = S.stored(_toy_reference)
    assert recorder(inside) == K.mpf(inside) / 3 and recorder(outside) == K.mpf(outside) / 3
    S.write_recorded()
    path = tmp_path / f"{recorder.store_name}.json"
    data = json.loads(path.read_text())
    assert len(data["values"]) == 2 and data["source"] == S.source_hash(data["sources"])
    # default mode: read, except the sampled key, which is computed and compared
    monkeypatch.delenv("CIRCLEDIST_REFERENCES")
    monkeypatch.setattr(S, "_files", {})
    calls.clear()
    reader = S.stored(_toy_reference)
    assert reader(outside) == K.mpf(outside) / 3 and calls == []
    assert reader(inside) == K.mpf(inside) / 3 and calls == [inside]
    # a recorded value that is not what the code computes is a failure when it is checked
    data["values"] = {k: S.encode(K.mpf(7)) for k in data["values"]}
    path.write_text(json.dumps(data))
    monkeypatch.setattr(S, "_files", {})
    monkeypatch.setenv("CIRCLEDIST_REFERENCES", "verify")
    with pytest.raises(S.Mismatch, match="python -m tools.references record"):
        S.stored(_toy_reference)(outside)
    # a file recorded by other code is not read
    data["source"] = "0" * 32
    path.write_text(json.dumps(data))
    monkeypatch.setattr(S, "_files", {})
    monkeypatch.delenv("CIRCLEDIST_REFERENCES")
    calls.clear()
    assert S.stored(_toy_reference)(outside) == K.mpf(outside) / 3 and calls == [outside]


def test_a_bad_mode_is_named(monkeypatch):
    monkeypatch.setenv("CIRCLEDIST_REFERENCES", "recrod")
    with pytest.raises(ValueError, match="CIRCLEDIST_REFERENCES must be one of"):
        S.mode()
