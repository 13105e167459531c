"""The plot's server-side buffer and decimation: what is new, at most the budget, peaks kept."""
import math

from sim_studio.views.plot.decimation import SampleBuffer, budget, decimate


def test_since_returns_only_what_is_new():
    buffer = SampleBuffer(capacity=100)
    assert buffer.last_seq == -1 and buffer.since(-1) == []
    for k in range(5):
        buffer.append(float(k), k * 10.0)
    assert buffer.since(-1) == [(0.0, 0.0), (1.0, 10.0), (2.0, 20.0), (3.0, 30.0), (4.0, 40.0)]
    seen = buffer.last_seq
    buffer.append(5.0, 50.0)
    assert buffer.since(seen) == [(5.0, 50.0)]
    assert buffer.since(buffer.last_seq) == []


def test_the_buffer_is_bounded_and_keeps_the_newest():
    buffer = SampleBuffer(capacity=10)
    for k in range(25):
        buffer.append(float(k), float(k))
    assert [t for t, _ in buffer.since(-1)] == [float(k) for k in range(15, 25)]
    assert [t for t, _ in buffer.since(20)] == [21.0, 22.0, 23.0, 24.0]
    assert buffer.all() == buffer.since(-1)


def test_budget():
    assert budget(200, 0.1) == 20
    assert budget(200, 0.0) == 2  # always room for one min/max pair


def test_what_fits_goes_unchanged():
    samples = [(float(k), float(k)) for k in range(10)]
    assert decimate(samples, 10) == samples


def test_decimation_keeps_each_buckets_extremes_in_order():
    # 1 kHz for a second, a sine with one spike: 20 points must keep the spike and the sine's range
    samples = [(k / 1000.0, math.sin(2 * math.pi * k / 1000.0)) for k in range(1000)]
    samples[437] = (0.437, 5.0)
    points = decimate(samples, 20)
    assert len(points) <= 20
    assert set(points) <= set(samples)                  # only received samples
    assert [t for t, _ in points] == sorted(t for t, _ in points)
    assert (0.437, 5.0) in points
    values = [v for _, v in points]
    assert min(values) == min(v for _, v in samples) and max(values) == 5.0
    # every sample lies between the extremes of its bucket: buckets of 100 here
    for b in range(10):
        bucket = samples[b * 100:(b + 1) * 100]
        sent = [p for p in points if bucket[0][0] <= p[0] <= bucket[-1][0]]
        assert min(v for _, v in sent) == min(v for _, v in bucket)
        assert max(v for _, v in sent) == max(v for _, v in bucket)


def test_a_flat_bucket_sends_one_point():
    samples = [(float(k), 1.0) for k in range(100)]
    assert len(decimate(samples, 10)) == 5
