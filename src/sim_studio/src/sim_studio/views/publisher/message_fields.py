"""A message type's fields as the publisher's tree shows them, and a message filled from one
expression per field, every value checked against its field's type. No ROS master.

Field paths are written as rqt_plot writes them, without the topic: `data`, `header/stamp`,
`linear/x`. A leaf is a primitive field, a primitive array (its expression gives a list) or an
array of messages (a list of dicts, `[{'x': 1.0}]`); a nested message may also be given whole as
a dict. Values convert as rqt_publisher converts them: a number fits any numeric field (into an
integer field it is truncated as Python's int() does), a string field takes any value as its
text, and when its expression does not evaluate, the expression's own text (`hello` publishes
"hello"). What does not fit (a string in a float64, 300 in a uint8, a list of 2 in a float64[3],
a field the type lacks) is an error naming the field and why; nothing is built.
"""
import math
import re

import genpy
import roslib.message

from sim_studio.views.publisher.expressions import Expression, ExpressionError

_INT_RANGES = {"int8": (-2 ** 7, 2 ** 7 - 1), "uint8": (0, 2 ** 8 - 1), "int16": (-2 ** 15, 2 ** 15 - 1),
               "uint16": (0, 2 ** 16 - 1), "int32": (-2 ** 31, 2 ** 31 - 1), "uint32": (0, 2 ** 32 - 1),
               "int64": (-2 ** 63, 2 ** 63 - 1), "uint64": (0, 2 ** 64 - 1),
               "byte": (-2 ** 7, 2 ** 7 - 1), "char": (0, 2 ** 8 - 1)}  # ROS 1: byte is int8, char is uint8
_FLOAT32_MAX = 3.4028234663852886e38
_PRIMITIVES = set(_INT_RANGES) | {"float32", "float64", "bool", "string", "time", "duration"}
_ARRAY = re.compile(r"^([^\[\]]+)(?:\[(\d*)\])?$")


class FieldError(ValueError):
    """One or more fields that do not fit; str() names each field and why."""


def split_type(slot_type):
    """'float64[3]' -> ('float64', True, 3); 'string' -> ('string', False, None)."""
    m = _ARRAY.match(slot_type)
    if not m:
        raise FieldError("unreadable field type %r" % slot_type)
    base, length = m.group(1), m.group(2)
    is_array = "[" in slot_type
    return base, is_array, (int(length) if length else None)


def message_class(type_name):
    """The class of an installed message type, or a FieldError saying it is not one."""
    if not isinstance(type_name, str) or not re.match(r"^[A-Za-z][\w]*/[A-Za-z][\w]*$", type_name.strip()):
        raise FieldError("%r is not a message type name (package/Type, e.g. std_msgs/Float64)" % (type_name,))
    type_name = type_name.strip()
    cls = None
    try:
        cls = roslib.message.get_message_class(type_name)
    except Exception:  # roslib raises several kinds for a missing package
        cls = None
    if cls is None:
        raise FieldError("unknown message type %s: not installed (check the spelling, or build its package)"
                         % type_name)
    return cls


def _nested_class(base):
    return message_class("std_msgs/Header" if base == "Header" else base)


def describe(cls, prefix=""):
    """The field tree: [{"path", "name", "type", "children"?}]; children for nested messages."""
    fields = []
    for name, slot_type in zip(cls.__slots__, cls._slot_types):
        path = prefix + name
        base, is_array, _ = split_type(slot_type)
        entry = {"path": path, "name": name, "type": slot_type}
        if base not in _PRIMITIVES and not is_array:
            entry["children"] = describe(_nested_class(base), path + "/")
        fields.append(entry)
    return fields


def field_paths(tree):
    """Every path of the tree, nested messages included."""
    for entry in tree:
        yield entry["path"], entry["type"]
        yield from field_paths(entry.get("children", ()))


def compile_expressions(cls, expressions):
    """{path: text} -> [(path, slot_type, Expression or None, text)] ordered parents first;
    unknown paths and unparsable expressions raise one FieldError naming them all."""
    known = dict(field_paths(describe(cls)))
    errors, compiled = [], []
    if not isinstance(expressions, dict):
        raise FieldError("fields must be an object {field path: expression}")
    for path, text in expressions.items():
        clean = str(path).strip().strip("/")
        if clean not in known:
            top = ", ".join(cls.__slots__) or "none"
            errors.append("field '%s': %s has no such field (its fields: %s)" % (path, cls._type, top))
            continue
        if not isinstance(text, str):
            errors.append("field '%s': the expression must be text, got %s" % (path, type(text).__name__))
            continue
        if not text.strip():
            continue  # an empty cell: the field keeps its default, as in rqt
        slot_type = known[clean]
        try:
            compiled.append((clean, slot_type, Expression(text), text))
        except ExpressionError as e:
            if slot_type == "string":
                compiled.append((clean, slot_type, None, text))  # rqt: text that does not parse is the string
            else:
                errors.append("field '%s' (%s): %s" % (clean, slot_type, e))
    if errors:
        raise FieldError("; ".join(errors))
    return sorted(compiled, key=lambda c: c[0].count("/"))


def build(cls, compiled, variables):
    """A new message of `cls` with every compiled expression evaluated (with `variables`, e.g.
    i and t) and converted to its field's type; FieldError names every field that fails."""
    msg = cls()
    errors = []
    for path, slot_type, expression, text in compiled:
        try:
            if expression is None:
                value = text
            else:
                try:
                    value = expression.evaluate(**variables)
                except ExpressionError:
                    if slot_type != "string":
                        raise
                    value = text  # rqt: a string field's expression that fails is its own text
            _assign(msg, path, convert(value, slot_type, ""))
        except (ExpressionError, FieldError) as e:
            errors.append("field '%s' (%s): %s" % (path, slot_type, e))
    if errors:
        raise FieldError("; ".join(errors))
    return msg


def _assign(msg, path, value):
    parts = path.split("/")
    for part in parts[:-1]:
        msg = getattr(msg, part)
    setattr(msg, parts[-1], value)


def convert(value, slot_type, where=""):
    """`value` as the field type `slot_type` wants it, or FieldError saying why it cannot be;
    `where` names the part being converted inside the field ('[2]', 'x') for the message."""
    base, is_array, length = split_type(slot_type)
    if is_array:
        if base in ("uint8", "char") and isinstance(value, (bytes, bytearray)):
            value = list(value)
        if not isinstance(value, (list, tuple)):
            raise FieldError("%sexpected a list such as [1, 2, 3] (%s is an array), got %s"
                             % (_at(where, slot_type), slot_type, _what(value)))
        if length is not None and len(value) != length:
            raise FieldError("%sexpected exactly %d elements (%s), got a list of %d"
                             % (_at(where, slot_type), length, slot_type, len(value)))
        items = [convert(v, base, "%s[%d]" % (where, k)) for k, v in enumerate(value)]
        return bytes(items) if base in ("uint8", "char") else items
    if base in _INT_RANGES:
        return _integer(value, base, where)
    if base in ("float32", "float64"):
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise FieldError("%sexpected a number, got %s" % (_at(where, base), _what(value)))
        value = float(value)
        if base == "float32" and math.isfinite(value) and abs(value) > _FLOAT32_MAX:
            raise FieldError("%s%r is beyond float32's range (±3.4e38)" % (_at(where, base), value))
        return value
    if base == "bool":
        if isinstance(value, bool) or value in (0, 1):
            return bool(value)
        raise FieldError("%sexpected True or False (or 1/0), got %s" % (_at(where, base), _what(value)))
    if base == "string":
        return value if isinstance(value, str) else str(value)
    if base in ("time", "duration"):
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            raise FieldError("%sexpected a number of seconds, got %s" % (_at(where, base), _what(value)))
        if base == "time" and value < 0:
            raise FieldError("%sa time cannot be negative (%r)" % (_at(where, base), value))
        return genpy.Time.from_sec(value) if base == "time" else genpy.Duration.from_sec(value)
    # a nested message, given whole as a dict of its fields
    cls = _nested_class(base)
    if not isinstance(value, dict):
        raise FieldError("%sexpected a dict of %s's fields such as {'%s': ...}, got %s"
                         % (_at(where, base), cls._type, cls.__slots__[0] if cls.__slots__ else "field", _what(value)))
    msg = cls()
    for name, item in value.items():
        if name not in cls.__slots__:
            raise FieldError("%s%s has no field '%s' (its fields: %s)"
                             % (_at(where, base), cls._type, name, ", ".join(cls.__slots__)))
        slot = cls._slot_types[cls.__slots__.index(name)]
        setattr(msg, name, convert(item, slot, "%s/%s" % (where, name) if where else name))
    return msg


def _integer(value, base, where):
    if isinstance(value, float):
        if not math.isfinite(value):
            raise FieldError("%sexpected a finite number, got %r" % (_at(where, base), value))
        value = int(value)  # truncation, as rqt_publisher converts a float for an integer field
    if not isinstance(value, int):
        raise FieldError("%sexpected an integer, got %s" % (_at(where, base), _what(value)))
    low, high = _INT_RANGES[base]
    if not low <= value <= high:
        raise FieldError("%s%d is out of %s's range (%d to %d)" % (_at(where, base), value, base, low, high))
    return int(value)


def _at(where, base):
    """The part of a value that failed, relative to the field itself ('' for the whole field)."""
    return "%s (%s): " % (where, base) if where else ""


def _what(value):
    if isinstance(value, str):
        return "the text %r" % (value if len(value) < 40 else value[:37] + "...")
    if isinstance(value, (list, tuple)):
        return "a list of %d" % len(value)
    if isinstance(value, dict):
        return "a dict"
    return "%r (%s)" % (value, type(value).__name__)
