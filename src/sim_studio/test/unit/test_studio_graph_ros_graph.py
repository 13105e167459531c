"""rqt_graph's graph from a master's system state: filters, modes, dot text, and dot's SVG."""
import shutil

import pytest

from sim_studio.views.graph.ros_graph import build_graph, run_dot, to_dot

STATE = (
    [["/chatter", ["/talker"]], ["/rosout", ["/talker", "/listener", "/sim_studio"]], ["/clock", ["/gazebo"]],
     ["/lonely", ["/talker"]], ["/rosout_agg", ["/rosout"]]],
    [["/chatter", ["/listener", "/sim_studio"]], ["/rosout", ["/rosout"]], ["/clock", ["/talker", "/listener"]]],
    [["/talker/get_loggers", ["/talker"]], ["/gazebo/reset", ["/gazebo"]]],
)


def test_nodes_and_topics_with_rqt_graphs_default_filters():
    graph = build_graph(STATE)
    assert graph["nodes"] == ["/gazebo", "/listener", "/talker"]  # no /rosout, no studio
    assert graph["topics"] == ["/chatter", "/lonely"]              # no /rosout, /rosout_agg, /clock
    assert (("node", "/talker"), ("topic", "/chatter"), "") in graph["edges"]
    assert (("topic", "/chatter"), ("node", "/listener"), "") in graph["edges"]
    assert all("/sim_studio" not in str(edge) for edge in graph["edges"])


def test_showing_debug_clock_and_hiding_leaf_topics():
    graph = build_graph(STATE, hide_debug=False, hide_clock=False, hide_leaf=True)
    assert "/rosout" in graph["nodes"] and "/sim_studio" in graph["nodes"]
    assert graph["topics"] == ["/chatter", "/clock", "/rosout"]  # /lonely and /rosout_agg have no subscriber


def test_nodes_only_labels_edges_with_topics():
    graph = build_graph(STATE, mode="nodes")
    assert graph["topics"] == []
    assert graph["edges"] == [(("node", "/talker"), ("node", "/listener"), "/chatter")]


def test_a_bad_mode():
    with pytest.raises(ValueError, match="graph mode"):
        build_graph(STATE, mode="all")


def test_dot_text_quotes_names():
    weird = '/we"ird\\node'
    dot = to_dot({"nodes": [weird], "topics": ["/t"], "edges": [(("node", weird), ("topic", "/t"), "")]})
    assert '"n:/we\\"ird\\\\node" -> "t:/t";' in dot
    assert "rankdir=LR" in dot


@pytest.mark.skipif(shutil.which("dot") is None, reason="graphviz is not installed")
def test_dot_lays_it_out_as_svg():
    svg = run_dot(to_dot(build_graph(STATE)))
    assert svg.startswith("<svg") and "<title>n:/talker</title>" in svg and ">/chatter</text>" in svg
