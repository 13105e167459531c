#!/usr/bin/env python3
"""A real two-node Ray cluster on this machine, for test_ray_cluster.py: a head and a second
node, each with its own number of CPUs (Ray's ray.cluster_utils.Cluster starts each as its own
raylet, as `ray start` does on two machines). Prints the cluster's address on one line, then
keeps the cluster up until its stdin closes. Test-only.

  two_node_cluster.py HEAD_CPUS NODE_CPUS
"""
import sys

from ray.cluster_utils import Cluster


def main():
    head_cpus, node_cpus = int(sys.argv[1]), int(sys.argv[2])
    cluster = Cluster(initialize_head=True, head_node_args={"num_cpus": head_cpus, "include_dashboard": False})
    cluster.add_node(num_cpus=node_cpus)
    cluster.wait_for_nodes()
    print(cluster.address, flush=True)
    sys.stdin.read()
    cluster.shutdown()


if __name__ == "__main__":
    main()
