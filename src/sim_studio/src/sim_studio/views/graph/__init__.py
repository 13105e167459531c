"""Graph: rqt_graph. The nodes and topics the master knows, laid out by graphviz's dot on the
server (ros_graph.py) and shown as SVG; the page asks again with its Refresh button."""
import rosgraph
import rospy

from sim_studio.view import View
from sim_studio.views.graph.ros_graph import build_graph, run_dot, to_dot, GraphError


class GraphView(View):
    title = "Graph"
    order = 40

    async def handle(self, client, message):
        if message["type"] != "refresh":
            raise ValueError("graph: unknown request %r (refresh)" % message["type"])
        try:
            state = await self.studio.blocking(_system_state)
        except Exception as e:
            raise ValueError("cannot reach the ROS master: %s" % e)
        graph = build_graph(state, mode=message.get("mode", "nodes_topics"),
                            hide_debug=bool(message.get("hide_debug", True)),
                            hide_clock=bool(message.get("hide_clock", True)),
                            hide_leaf=bool(message.get("hide_leaf", False)))
        try:
            svg = await self.studio.blocking(run_dot, to_dot(graph))
        except GraphError as e:
            raise ValueError(str(e))
        client.reply(message, svg=svg, nodes=graph["nodes"], topics=graph["topics"], edges=len(graph["edges"]))


def _system_state():
    return rosgraph.Master(rospy.get_name()).getSystemState()


VIEW = GraphView
