"""The topic monitor's rate and bandwidth, measured as rostopic hz and bw measure them."""
import pytest

from sim_studio.views.topics.statistics import TopicStatistics


def test_rate_is_one_over_the_mean_interval_in_ros_time():
    stats = TopicStatistics()
    for k in range(21):
        stats.add(ros_time=10.0 + k * 0.05, wall_time=1000.0 + k * 0.05, size=8)
    assert stats.rate() == pytest.approx(20.0)


def test_the_window_holds_the_last_100_messages():
    stats = TopicStatistics()
    for k in range(50):
        stats.add(1.0 + k * 1.0, 1.0 + k, 8)          # 1 Hz for a while
    for k in range(150):
        stats.add(100.0 + k * 0.1, 100.0 + k * 0.1, 8)  # then 10 Hz: the window forgets the 1 Hz part
    assert stats.rate() == pytest.approx(10.0)
    assert stats.count == 200


def test_rate_under_sim_time_ignores_wall_time():
    stats = TopicStatistics()
    for k in range(11):
        stats.add(ros_time=5.0 + k * 0.1, wall_time=1000.0 + k * 0.005, size=8)  # 20x real time
    assert stats.rate() == pytest.approx(10.0)


def test_time_going_back_starts_the_rate_again():
    stats = TopicStatistics()
    for k in range(10):
        stats.add(50.0 + k, 1.0 + k, 8)
    stats.add(0.5, 11.0, 8)           # the simulator was reset
    assert stats.rate() is None        # one message since: no interval yet
    stats.add(0.75, 11.25, 8)
    assert stats.rate() == pytest.approx(4.0)


def test_bandwidth_is_the_windows_bytes_over_wall_time_until_now():
    stats = TopicStatistics()
    for k in range(10):
        stats.add(ros_time=k * 0.1, wall_time=100.0 + k * 0.1, size=1000)
    assert stats.bandwidth(wall_now=100.9) == pytest.approx(10000 / 0.9)
    assert stats.bandwidth(wall_now=110.0) == pytest.approx(10000 / 10.0)  # falls once messages stop


def test_nothing_to_say_before_two_messages():
    stats = TopicStatistics()
    assert stats.rate() is None and stats.bandwidth(1.0) is None
    stats.add(1.0, 1.0, 8)
    summary = stats.summary(3.0)
    assert summary == {"rate": None, "bandwidth": None, "size": 8, "count": 1, "age": 2.0}
