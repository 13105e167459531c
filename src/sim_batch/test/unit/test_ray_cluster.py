"""A batch sent to a real two-node Ray cluster on this machine (conftest.py's: a head and a
second node with one CPU each): every run ok, and runs landed on both nodes."""
import json
import os
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
RUN = os.path.join(HERE, "..", "..", "scripts", "run")


def test_a_batch_on_a_two_node_cluster_runs_on_both_nodes(tmp_path, ray_cluster):
    batch = tmp_path / "batch.yaml"
    batch.write_text("""
scenarios:
  - name: spread
    command: 'sleep 2; echo "{\\"ok\\": true}"'
    seeds: 4
    time_limit: 60
""")
    out = tmp_path / "results.jsonl"
    done = subprocess.run([RUN, str(batch), "--out", str(out), "--address", ray_cluster], capture_output=True,
                          text=True, timeout=240)
    assert done.returncode == 0, done.stderr
    records = [json.loads(line) for line in out.read_text().splitlines()]
    assert len(records) == 4 and all(r["state"] == "ok" for r in records), records
    assert len({r["node"] for r in records}) == 2, "every run on one node: %s" % [r["node"] for r in records]
