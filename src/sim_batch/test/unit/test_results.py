"""results.py: records appended and read back, a rerun's skip list, a file cut short mid-write."""
import json

import pytest

from sim_batch.results import ResultsError, ResultsFile, read_results


def record(run_id, state="ok"):
    return {"run_id": run_id, "state": state, "result": {"coverage": 0.97}}


def test_records_are_read_back_in_order_and_a_rerun_skips_them(tmp_path):
    path = str(tmp_path / "results.jsonl")
    results = ResultsFile(path)
    assert results.done() == set()
    results.append(record("a[seed=1]"))
    results.append(record("a[seed=2]", "timeout"))
    results.close()
    records, warning = read_results(path)
    assert [r["run_id"] for r in records] == ["a[seed=1]", "a[seed=2]"]
    assert warning is None
    assert ResultsFile(path).done() == {"a[seed=1]", "a[seed=2]"}


def test_a_file_cut_short_is_read_to_its_last_whole_line_and_appending_goes_on_cleanly(tmp_path):
    path = tmp_path / "results.jsonl"
    whole = json.dumps(record("a[seed=1]")) + "\n" + json.dumps(record("a[seed=2]")) + "\n"
    path.write_text(whole + json.dumps(record("a[seed=3]"))[:20])  # died mid-write
    records, warning = read_results(str(path))
    assert [r["run_id"] for r in records] == ["a[seed=1]", "a[seed=2]"]
    assert "line 3 is cut short" in warning and "2 whole records" in warning
    results = ResultsFile(str(path))
    assert results.warning == warning
    results.append(record("a[seed=3]"))
    results.close()
    records, warning = read_results(str(path))
    assert [r["run_id"] for r in records] == ["a[seed=1]", "a[seed=2]", "a[seed=3]"]
    assert warning is None


def test_a_whole_last_record_without_its_newline_is_kept(tmp_path):
    path = tmp_path / "results.jsonl"
    path.write_text(json.dumps(record("a")) + "\n\n" + json.dumps(record("b")))
    results = ResultsFile(str(path))
    assert results.done() == {"a", "b"} and results.warning is None
    results.append(record("c"))
    results.close()
    assert [r["run_id"] for r in read_results(str(path))[0]] == ["a", "b", "c"]


def test_a_foreign_line_in_the_middle_is_an_error_naming_it(tmp_path):
    path = tmp_path / "results.jsonl"
    path.write_text(json.dumps(record("a")) + "\nnot json\n" + json.dumps(record("b")) + "\n")
    with pytest.raises(ResultsError, match="results.jsonl: line 2 is not a run's JSON record"):
        read_results(str(path))
