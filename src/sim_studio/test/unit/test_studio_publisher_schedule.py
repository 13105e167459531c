"""A publisher's ticks: anchored to its start, no burst after a stall, rates checked."""
import pytest

from sim_studio.views.publisher.schedule import Schedule, check_rate


def test_ticks_do_not_drift_with_the_time_a_publish_takes():
    schedule = Schedule(10.0, now=100.0)
    ticks = []
    now = 100.0
    for _ in range(5):
        now = schedule.next_after(now + 0.03)  # each publish took 30 ms
        ticks.append(round(now, 9))
    assert ticks == [100.1, 100.2, 100.3, 100.4, 100.5]


def test_a_stall_starts_again_from_now_instead_of_a_burst():
    schedule = Schedule(10.0, now=0.0)
    assert schedule.next_after(0.0) == pytest.approx(0.1)
    assert schedule.next_after(5.0) == pytest.approx(5.1)  # 5 s late: next in one period
    assert schedule.next_after(5.1) == pytest.approx(5.2)


@pytest.mark.parametrize("rate", [0, -1, 1e6, "10", None, True, float("nan")])
def test_bad_rates(rate):
    with pytest.raises(ValueError, match="rate"):
        check_rate(rate)


def test_good_rate():
    assert check_rate(100) == 100.0
