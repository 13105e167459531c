"""The publisher's field expressions: what rqt_publisher's users type works, and nothing reaches
past math."""
import math

import pytest

from sim_studio.views.publisher.expressions import Expression, ExpressionError


def value(text, i=1, t=0.0):
    return Expression(text).evaluate(i=i, t=t)


@pytest.mark.parametrize("text, i, expected", [
    ("sin(i/100)", 7, math.sin(0.07)),                     # the tutorials (001, 004)
    ("math.sin(i/100)", 7, math.sin(0.07)),
    ("cos(i/50)", 3, math.cos(0.06)),                      # 004's table
    ("sin(i/100*1)*0.5 + 0.25", 10, math.sin(0.1) * 0.5 + 0.25),  # 001's advanced form, numbers filled in
    ("i/2", 3, 1.5),                                       # true division, as rqt's __future__ import
    ("i//2", 3, 1),
    ("2**10", 1, 1024),
    ("pi", 1, math.pi),
    ("-i if i % 2 else i", 3, -3),
    ("[i, i*2, 3.5]", 2, [2, 4, 3.5]),
    ("(1, 2)", 1, [1, 2]),
    ("{'x': i, 'y': 2}", 5, {"x": 5, "y": 2}),
    ("'hello'", 1, "hello"),
    ("[1, 2, 3][i % 3]", 4, 2),
    ("hypot(3, 4)", 1, 5.0),
    ("i > 2 and i < 5", 3, True),
    ("1 < i < 5", 7, False),
])
def test_what_rqt_users_type(text, i, expected):
    assert value(text, i) == pytest.approx(expected) if isinstance(expected, float) else value(text, i) == expected


def test_t_is_the_time_given():
    assert value("t * 2", t=1.25) == 2.5


def test_random_and_time_as_rqt_offers_them():
    assert 0.0 <= value("random()") < 1.0
    assert 2 <= value("randint(2, 4)") <= 4
    assert value("time()") > 1e9


@pytest.mark.parametrize("text, words", [
    ("__import__('os')", "name '__import__' is not defined"),
    ("__import__('os').system('true')", "attribute access (.system) is not allowed"),
    ("open('/etc/passwd')", "name 'open' is not defined"),
    ("().__class__.__bases__", "attribute access (.__bases__) is not allowed"),
    ("math.__dict__", "math.__dict__ is not available"),
    ("sin.__self__", "attribute access"),
    ("[x for x in (1, 2)]", "a comprehension is not allowed"),
    ("lambda: 1", "lambda is not allowed"),
    ("f'{i}'", "an f-string is not allowed"),
    ("(y := 2)", "':=' is not allowed"),
    ("round(1.5, ndigits=0)", "keyword arguments are not allowed"),
    ("9 ** 9 ** 9", "too large"),
    ("'x' * 10 ** 9", "more than 100000 elements"),
    ("[0] * 10 ** 6", "more than 100000 elements"),
    ("i << 3", "operator LShift is not allowed"),
    ("i is 1", "operator Is is not allowed"),
    ("sin(", "not a Python expression"),
    ("", "empty expression"),
    ("x" * 3000, "longer than"),
    ("hello", "name 'hello' is not defined (there are: i (publish count), t"),
])
def test_refused_with_a_reason(text, words):
    with pytest.raises(ExpressionError) as refused:
        value(text)
    assert words in str(refused.value)


@pytest.mark.parametrize("text, words", [
    ("1/0", "ZeroDivisionError"),
    ("sqrt(-1)", "math domain error"),
    ("'a' + 1", "TypeError"),
    ("[1][5]", "IndexError"),
    ("exp(1000)", "OverflowError"),
])
def test_python_errors_become_expression_errors(text, words):
    with pytest.raises(ExpressionError) as refused:
        value(text)
    assert words in str(refused.value)


def test_parsed_once_evaluated_many_times():
    expression = Expression("sin(i/100)")
    assert [expression.evaluate(i=k, t=0.0) for k in range(1, 4)] == [math.sin(k / 100) for k in range(1, 4)]
