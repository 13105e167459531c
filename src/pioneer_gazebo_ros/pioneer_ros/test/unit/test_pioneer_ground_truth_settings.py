"""pioneer_ros.ground_truth's settings: defaults that keep clear of the drive plugin's
odom -> base_link, and checks (no ROS master needed)."""
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'src'))

pytest.importorskip('rospy')
pytest.importorskip('gazebo_msgs.srv')
from pioneer_ros.ground_truth import GroundTruthSettings  # noqa: E402


def test_defaults_do_not_clash_with_the_drive_plugin():
    s = GroundTruthSettings()
    assert (s.model_name, s.relative_entity_name) == ('pioneer', 'world')
    assert (s.frame_id, s.child_frame_id, s.topic) == ('world', 'base_link_truth', '/pioneer/odom_truth')
    assert s.child_frame_id != 'base_link' and s.topic != '/pioneer/odom'


def test_leading_slashes_are_dropped_from_frames():
    s = GroundTruthSettings(frame_id='/odom', child_frame_id='/base_link')
    assert (s.frame_id, s.child_frame_id) == ('odom', 'base_link')


@pytest.mark.parametrize('kwargs', [dict(rate=0), dict(frame_id='a', child_frame_id='a'), dict(child_frame_id='')])
def test_bad_settings_are_refused(kwargs):
    with pytest.raises(ValueError):
        GroundTruthSettings(**kwargs)
