"""The ROS computation graph as rqt_graph draws it: nodes (ellipses) and topics (boxes) from the
master's system state, written as graphviz dot text and laid out by `dot -Tsvg`. Pure but for
running dot.

The filters are rqt_graph's: "hide debug" leaves out the names rqt_graph calls quiet (rosout,
rqt, rviz, diagnostics, statistics; and this studio, as rqt leaves out itself), /clock may be
hidden on its own, and "hide leaf topics" the topics without a publisher or without a subscriber.
"Nodes only" draws an edge per topic from each publisher to each subscriber, labelled with it.
"""
import subprocess

DEBUG_NAMES = ("/rosout", "/rqt", "/rviz", "/diag_agg", "/runtime_logger", "/pr2_dashboard", "/cpu_monitor",
               "/hd_monitor", "/monitor", "/rxloggerlevel", "/statistics", "/sim_studio")
CLOCK = "/clock"
MODES = ("nodes_topics", "nodes")
DOT_TIMEOUT = 20.0  # s; a graph of a few hundred nodes lays out in well under one


class GraphError(RuntimeError):
    """dot missing or failing: the text says what to do."""


def is_debug(name):
    return any(name == n or name.startswith(n) for n in DEBUG_NAMES)


def build_graph(system_state, mode="nodes_topics", hide_debug=True, hide_clock=True, hide_leaf=False):
    """{'nodes': [...], 'topics': [...], 'edges': [(from, to, label)]} from getSystemState's
    (publishers, subscribers, services); edge ends are ('node', name) or ('topic', name)."""
    if mode not in MODES:
        raise ValueError("graph mode %r: one of %s" % (mode, ", ".join(MODES)))
    publishers, subscribers = dict(system_state[0]), dict(system_state[1])

    def node_kept(node):
        return not (hide_debug and is_debug(node))

    def topic_kept(topic):
        if hide_debug and is_debug(topic) or hide_clock and topic == CLOCK:
            return False
        pubs = [n for n in publishers.get(topic, ()) if node_kept(n)]
        subs = [n for n in subscribers.get(topic, ()) if node_kept(n)]
        if not pubs and not subs:
            return False
        return not hide_leaf or (pubs and subs)

    topics = sorted(t for t in set(publishers) | set(subscribers) if topic_kept(t))
    nodes = set()
    for table in (publishers, subscribers):
        for topic, names in table.items():
            nodes.update(n for n in names if node_kept(n))
    for _, names in system_state[2]:  # a node with only services is still a node
        nodes.update(n for n in names if node_kept(n))

    edges = []
    for topic in topics:
        pubs = sorted(n for n in publishers.get(topic, ()) if node_kept(n))
        subs = sorted(n for n in subscribers.get(topic, ()) if node_kept(n))
        if mode == "nodes":
            edges.extend((("node", p), ("node", s), topic) for p in pubs for s in subs)
        else:
            edges.extend((("node", p), ("topic", topic), "") for p in pubs)
            edges.extend((("topic", topic), ("node", s), "") for s in subs)
    return {"nodes": sorted(nodes), "topics": topics if mode == "nodes_topics" else [], "edges": edges}


def _quote(text):
    return '"%s"' % text.replace("\\", "\\\\").replace('"', '\\"')


def _id(kind, name):
    return _quote(("n:" if kind == "node" else "t:") + name)  # a node and a topic may share a name


def to_dot(graph):
    """graphviz text, left to right as rqt_graph lays it out."""
    lines = ["digraph ros {", '  rankdir=LR; bgcolor="transparent";',
             '  node [fontname="sans-serif", fontsize=11]; edge [fontname="sans-serif", fontsize=9];']
    for node in graph["nodes"]:
        lines.append('  %s [label=%s, shape=ellipse, class="ros-node", tooltip=%s];'
                     % (_id("node", node), _quote(node), _quote("node " + node)))
    for topic in graph["topics"]:
        lines.append('  %s [label=%s, shape=box, class="ros-topic", tooltip=%s];'
                     % (_id("topic", topic), _quote(topic), _quote("topic " + topic)))
    for (kind_a, a), (kind_b, b), label in graph["edges"]:
        lines.append("  %s -> %s%s;" % (_id(kind_a, a), _id(kind_b, b), " [label=%s]" % _quote(label) if label else ""))
    lines.append("}")
    return "\n".join(lines) + "\n"


def run_dot(dot_text, timeout=DOT_TIMEOUT):
    """SVG text of the layout; GraphError when graphviz's dot is missing or fails."""
    try:
        done = subprocess.run(["dot", "-Tsvg"], input=dot_text.encode(), stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, timeout=timeout, check=False)
    except FileNotFoundError:
        raise GraphError("graphviz's dot is not installed (apt-get install graphviz)") from None
    except subprocess.TimeoutExpired:
        raise GraphError("dot took more than %.0f s to lay the graph out" % timeout) from None
    if done.returncode != 0:
        raise GraphError("dot failed: %s" % done.stderr.decode(errors="replace").strip())
    svg = done.stdout.decode()
    return svg[svg.index("<svg"):] if "<svg" in svg else svg  # without the XML prologue and DOCTYPE
