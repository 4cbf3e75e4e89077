"""The speed guard (``zener-sym bench --guard``, ``zener_sym.bench.guard``): its logic without
timing (ratio against baseline, the 1.5x limit, retries, the baseline file, the messages), the
committed baselines' provenance, the measurement of another checkout, and, with a 3-4x margin
over the limit, that an operation made slower fails it."""
from __future__ import annotations

import json
import pathlib
import statistics

import numpy as np
import pytest

from zener_sym.bench import guard, guard_measure
from zener_sym.cli import main


def base(ratio, made_from="abc1234"):
    return {"ratio": ratio, "made_from": made_from}


# --- judging one entry --------------------------------------------------------------------------
@pytest.mark.parametrize("measured, ok", [(2.0, True), (2.9, True), (3.0, True), (3.01, False),
                                          (6.0, False)])
def test_judge_fails_above_one_and_a_half_times_the_baseline(measured, ok):
    v = guard.judge("e", {"ratio": measured}, base(2.0))  # the limit: 1.5 * 2.0 = 3.0
    assert v.ok is ok
    assert v.ratio == measured and v.baseline == 2.0


def test_failure_message_says_what_how_much_and_against_what():
    v = guard.judge("exact_summary_plate_1k", {"ratio": 6.6, "what": "zs.summary, 1000 lambda"},
                    base(2.2, "8251530"))
    assert not v.ok
    for part in ("exact_summary_plate_1k", "6.6", "3.00x", "2.2", "8251530", "1.5x", "3.3",
                 "SLOWER", "zs.summary, 1000 lambda"):
        assert part in v.message, part
    text = guard.summary_text([v, guard.judge("b", {"ratio": 1.0}, base(1.0))])
    assert text.splitlines()[0].startswith("FAIL")
    assert text.splitlines()[1].startswith("ok")
    assert "1 of 2 entries" in text and "FAILED: exact_summary_plate_1k" in text


def test_an_entry_that_cannot_run_fails_with_its_reason():
    v = guard.judge("c_history_plate", {"error": "RuntimeError: no C compiler"}, base(0.4))
    assert not v.ok and v.ratio is None
    assert "could not be measured: RuntimeError: no C compiler" in v.message


# --- retries ------------------------------------------------------------------------------------
def scripted(answers):
    """A fake measurement: each call pops the next {name: ratio} and records what it was asked."""
    calls = []

    def measure(names):
        calls.append(list(names))
        step = answers.pop(0)
        return {n: {"ratio": step[n]} for n in names}
    return measure, calls


def test_a_burst_of_load_is_measured_again_and_passes():
    measure, calls = scripted([{"a": 5.0, "b": 1.0}, {"a": 1.2}])
    verdicts = guard.run_guard({"a": base(1.0), "b": base(1.0)}, measure, log=lambda s: None)
    assert [v.ok for v in verdicts] == [True, True]
    assert calls == [["a", "b"], ["a"]]  # only the failing entry again
    assert verdicts[0].ratio == 1.2


def test_a_slowed_entry_fails_every_attempt_and_keeps_its_best():
    measure, calls = scripted([{"a": 3.0}, {"a": 2.5}, {"a": 2.8}])
    (v,) = guard.run_guard({"a": base(1.0)}, measure, log=lambda s: None)
    assert not v.ok and v.ratio == 2.5
    assert len(calls) == 1 + guard.RETRIES


def test_unknown_entries_are_refused():
    with pytest.raises(ValueError, match="no baseline for nope; entries with one: a"):
        guard.run_guard({"a": base(1.0)}, lambda names: {}, names=["nope"])


# --- the baseline file --------------------------------------------------------------------------
@pytest.mark.parametrize("text, message", [
    (None, "does not exist: record it with 'zener-sym bench --guard --record'"),
    ("{", "is not JSON"),
    ('{"fail_at": 1.5}', "no 'entries' object"),
    ('{"entries": {"a": {"ratio": 0}}}', "entry 'a' has no positive 'ratio'"),
    ('{"entries": {"a": {"ratio": "2"}}}', "entry 'a' has no positive 'ratio'"),
    ('{"entries": {"a": {"ratio": true}}}', "entry 'a' has no positive 'ratio'"),
])
def test_bad_baseline_files_are_named_with_the_fault(tmp_path, text, message):
    path = tmp_path / "speed_baseline.json"
    if text is not None:
        path.write_text(text)
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)")):
        guard.load_baseline(path)


def test_record_writes_the_median_and_how_it_was_made(tmp_path):
    path = tmp_path / "speed_baseline.json"
    path.write_text(json.dumps({"entries": {"kept": base(7.0)}}))
    runs = [{"a": 1.0}, {"a": 3.0}, {"a": 2.0}]

    def measure(names):
        return {n: {"ratio": runs.pop(0)[n], "what": "thing a"} for n in names}
    guard.record(["a"], measure, 3, "8251530", "zener-sym bench --guard --record", path)
    entries = guard.load_baseline(path)
    assert entries["kept"]["ratio"] == 7.0
    a = entries["a"]
    assert a["ratio"] == 2.0 and a["runs"] == [1.0, 3.0, 2.0]
    assert a["made_from"] == "8251530" and a["command"] == "zener-sym bench --guard --record"
    assert a["what"] == "thing a" and a["machine"] and a["made_on"]


def test_the_committed_baselines_cover_every_entry_and_say_how_they_were_made():
    entries = guard.load_baseline()
    assert set(entries) == set(guard_measure.ENTRIES)
    for name, rec in entries.items():
        assert rec["ratio"] == pytest.approx(statistics.median(rec["runs"]), abs=1e-4), name
        assert len(rec["runs"]) >= 3, name
        assert rec["command"].startswith("zener-sym bench --guard --record"), name
        assert name in rec["command"].split("--entries ")[1].split(","), name
        assert rec["machine"] and rec["made_on"] and rec["made_from"], name
        assert "local changes" not in rec["made_from"], name
    # the summaries' baselines are the speed before the table engine (issue 36)
    for name in ("exact_summary_plate_1k", "exact_summary_force_1k", "ham1_summary"):
        assert entries[name]["made_from"] == "8251530"
        assert "--tree" in entries[name]["command"]


# --- the command line ---------------------------------------------------------------------------
@pytest.mark.parametrize("argv, message", [
    (["--tree", "/nonexistent/zs"], "not a zener-sym checkout"),
    (["--entries", "exact_summary_plate_1k,nope"], "unknown guard entries nope"),
    (["--record", "--runs", "0"], "--runs must be at least 1, not 0"),
])
def test_bad_guard_arguments_are_one_line_and_exit_2(capsys, argv, message):
    assert main(["bench", "--guard", *argv]) == 2
    err = capsys.readouterr().err
    assert message in err and len(err.strip().splitlines()) == 1


# --- another checkout ---------------------------------------------------------------------------
def fake_tree(root: pathlib.Path, body: str) -> pathlib.Path:
    """A checkout's shape (src/zener_sym, generated/) around a toy package ``body``."""
    (root / "src" / "zener_sym").mkdir(parents=True)
    (root / "generated").mkdir()
    (root / "src" / "zener_sym" / "__init__.py").write_text(body)
    (root / "generated" / "__init__.py").write_text("WHERE = 'toy'\n")
    return root


def test_another_checkout_is_measured_with_its_own_package(tmp_path):
    # the toy's summary is numpy work of its own; the installed package is not imported
    tree = fake_tree(tmp_path / "toy", "import numpy as np\n"
                     "def summary(lams, model=None, contact_end=None):\n"
                     "    return np.cos(np.outer(lams, np.arange(64.0))).sum(axis=1)\n")
    out = guard.measure_tree(["exact_summary_plate_1k", "ham0_history"], tree, rounds=3)
    assert out["exact_summary_plate_1k"]["ratio"] > 0
    # what the toy cannot do (its summary has no tau_d) is said, not raised
    assert out["ham0_history"]["error"].startswith("AttributeError")


def test_a_tree_whose_measurement_crashes_says_so_in_one_line(tmp_path):
    tree = fake_tree(tmp_path / "broken", "raise SystemExit('toy refuses')\n")
    with pytest.raises(RuntimeError, match="the guard's measurement failed in .*broken"):
        guard.measure_tree(["exact_summary_plate_1k"], tree, rounds=1)


# --- an operation made slower fails the guard (3-4x the work against a 1.5x limit) --------------
def test_an_operation_made_slower_fails_and_the_same_one_passes(monkeypatch):
    work = guard_measure.chebval_reference(20_000, 12, 2)
    for name, repeat in (("same", 1), ("slower", 4)):
        monkeypatch.setitem(guard_measure.ENTRIES, name, (
            f"the reference's work x {repeat}",
            lambda repeat=repeat: guard_measure.Pair(lambda: [work() for _ in range(repeat)],
                                                     guard_measure.chebval_reference(20_000, 12,
                                                                                     2))))
    baseline = {"same": base(1.0), "slower": base(1.0)}
    verdicts = guard.run_guard(baseline, lambda ns: guard_measure.measure(list(ns), rounds=7),
                               log=lambda s: None)
    ok = {v.name: v.ok for v in verdicts}
    assert ok == {"same": True, "slower": False}, [v.message for v in verdicts]


def test_a_public_function_made_slower_fails_its_entry(monkeypatch):
    import zener_sym as zs

    def measured():
        return guard_measure.measure(["exact_summary_plate_1k"], rounds=7)[
            "exact_summary_plate_1k"]

    before = measured()
    fast = zs.summary

    def slow_summary(*args, **kwargs):  # three times the work, the same answer
        for _ in range(2):
            fast(*args, **kwargs)
        return fast(*args, **kwargs)
    monkeypatch.setattr(zs, "summary", slow_summary)
    after = guard.run_guard({"exact_summary_plate_1k": {"ratio": before["ratio"]}},
                            lambda ns: {"exact_summary_plate_1k": measured()},
                            log=lambda s: None)[0]
    assert not after.ok, after.message
    np.testing.assert_array_equal(slow_summary(np.array([0.5])).e, fast(np.array([0.5])).e)


def test_ci_runs_the_guard_after_the_tests():
    lines = (pathlib.Path(__file__).resolve().parents[1] / ".ci" / "run").read_text().splitlines()
    tests = next(i for i, line in enumerate(lines) if "-m pytest" in line)
    assert ".venv/bin/zener-sym bench --guard" in lines[tests + 1:]


def test_a_checkout_that_cannot_be_measured_fails_the_guard_in_one_line(tmp_path, capsys):
    tree = fake_tree(tmp_path / "broken", "raise SystemExit('toy refuses')\n")
    assert main(["bench", "--guard", "--tree", str(tree), "--entries",
                 "exact_summary_plate_1k"]) == 1
    err = capsys.readouterr().err
    assert "the guard's measurement failed in" in err and "toy refuses" in err
    assert len(err.strip().splitlines()) == 1
