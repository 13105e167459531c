"""One real two-node Ray cluster for the tests that send batches to an address
(test/two_node_cluster.py: a head and a second node, one CPU each): started once, as a user's
cluster is, instead of a local cluster per batch (each costs seconds to start)."""
import os
import shutil
import subprocess

import pytest

CLUSTER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "two_node_cluster.py")


@pytest.fixture(scope="session")
def ray_cluster():
    """The cluster's address."""
    python = shutil.which("python3")  # the venv's, with Ray (scripts/env.sh puts it first)
    cluster = subprocess.Popen([python, CLUSTER, "1", "1"], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    try:
        address = cluster.stdout.readline().strip()
        assert address, "the two-node cluster did not start"
        yield address
    finally:
        cluster.stdin.close()
        cluster.wait(timeout=60)
