"""The plot's completion list: numeric fields as rqt_plot paths (real message classes)."""
from sensor_msgs.msg import JointState
from std_msgs.msg import Float64, String

from sim_studio.views.plot.completion import numeric_paths


def test_numeric_fields_as_rqt_plot_paths():
    assert numeric_paths(Float64) == ["data"]
    assert numeric_paths(String) == []
    assert numeric_paths(JointState) == ["header/seq", "header/stamp", "position[0]", "velocity[0]", "effort[0]"]
