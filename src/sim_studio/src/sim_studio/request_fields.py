"""Reading a page's request fields: numbers and names, with an error that names the field.
A view raises the ValueError; the server sends its text back to the page. Pure, no ROS."""
import math


def number(message, field, default=None, low=None, high=None):
    """message[field] as a finite float (a JSON number, or a string holding one); `default`
    when absent or empty (None: the field is required)."""
    value = message.get(field)
    if value is None or (isinstance(value, str) and not value.strip()):
        if default is None:
            raise ValueError("%s: expected a number, got nothing" % field)
        return float(default)
    if isinstance(value, bool):
        raise ValueError("%s: expected a number, got %r" % (field, value))
    try:
        result = float(value)
    except (TypeError, ValueError):
        raise ValueError("%s: expected a number, got %r" % (field, value)) from None
    if not math.isfinite(result):
        raise ValueError("%s: expected a finite number, got %r" % (field, value))
    if low is not None and result < low:
        raise ValueError("%s: expected a number >= %g, got %g" % (field, low, result))
    if high is not None and result > high:
        raise ValueError("%s: expected a number <= %g, got %g" % (field, high, result))
    return result


def name(message, field):
    """message[field] as a non-empty string."""
    value = message.get(field)
    if not isinstance(value, str) or not value:
        raise ValueError("%s: expected a name (a non-empty string), got %r" % (field, value))
    return value
