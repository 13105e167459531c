"""The results file: one JSON line per finished run, appended as runs finish, read back to skip
what a rerun has already done. Pure: no ROS, no Ray.

A machine that dies mid-write leaves a last line cut short: it is read up to its last whole line
with a warning, and the cut tail is dropped before anything new is appended (else the next
record would be glued to it).
"""
import json
import os


class ResultsError(ValueError):
    pass


def read_results(path):
    """(records, warning): every whole record in the file (none if it does not exist), and a
    warning (or None) when its last line was cut short."""
    records, _, warning = _scan(path)
    return records, warning


def _scan(path):
    """(records, bytes to keep, warning)."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except FileNotFoundError:
        return [], 0, None
    *whole, tail = data.split(b"\n")  # tail: what follows the last newline ("" if the file ends with one)
    records, keep = [], 0
    for number, line in enumerate(whole, 1):
        keep += len(line) + 1
        if not line.strip():
            continue
        record = _record(line)
        if record is None:
            raise ResultsError("%s: line %d is not a run's JSON record; each line must be one (the file is not "
                               "this tool's, or was edited)" % (path, number))
        records.append(record)
    if not tail.strip():
        return records, keep, None
    record = _record(tail)
    if record is not None:  # whole, only its newline missing
        records.append(record)
        return records, len(data), None
    return records, keep, ("%s: line %d is cut short (the machine stopped mid-write?): read the %d whole records "
                           "before it; that run will run again" % (path, len(whole) + 1, len(records)))


def _record(line):
    try:
        record = json.loads(line)
    except ValueError:
        return None
    return record if isinstance(record, dict) and "run_id" in record else None


class ResultsFile:
    """Appends records to `path`, each flushed to disk as it is written; the records already
    there (and the cut tail dropped) on opening."""

    def __init__(self, path):
        self.path = path
        self.records, good, self.warning = _scan(path)
        if os.path.exists(path):
            with open(path, "rb+") as f:
                f.truncate(good)
                if good and not self._ends_with_newline(f, good):
                    f.seek(good)
                    f.write(b"\n")
        self._file = open(path, "a")

    @staticmethod
    def _ends_with_newline(f, size):
        f.seek(size - 1)
        return f.read(1) == b"\n"

    def done(self):
        """run_ids already recorded: a rerun skips them."""
        return {r["run_id"] for r in self.records}

    def append(self, record):
        self._file.write(json.dumps(record, sort_keys=True) + "\n")
        self._file.flush()
        os.fsync(self._file.fileno())
        self.records.append(record)

    def close(self):
        self._file.close()
