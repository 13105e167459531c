"""Field expressions as rqt's Message Publisher takes them, evaluated safely. No ROS.

rqt_publisher evaluates each field's text with Python's eval, its names being `i` (the publish
count, 1 at the first message) and everything in the math, random and time modules, so the
tutorials type `sin(i/100)` or `math.sin(i/100)`. Division is true division (`i/100` is a float),
as rqt imports it from __future__.

Here an expression is parsed once and walked by our own small interpreter instead of eval:
only literals, arithmetic, comparisons, conditionals, list/tuple/dict displays, indexing and calls
of the functions named below are understood, so no builtins, no imports and no attribute access
beyond `math.<name>` (or `random.`/`time.`) can be reached, and the few operations that could
take the machine's memory or time (huge powers, repeated strings) are bounded.

Names: `i`; `t`, the ROS time in seconds (sim time under /use_sim_time; ours: the issue asks for
it, rqt has none); math's functions and constants (`sin`, `pi`, ...); from random and time,
as rqt offers them, `random()`, `uniform(a, b)`, `gauss(mu, sigma)`, `randint(a, b)`, `time()`.
"""
import ast
import math
import operator
import random
import time

MAX_EXPRESSION_CHARS = 2000
MAX_SEQUENCE = 100000       # elements a list or string may reach by * or +
MAX_INT_BITS = 100000       # an int larger than this (about 30000 digits) is refused

_MATH = {name: getattr(math, name) for name in dir(math) if not name.startswith("_")}
_RANDOM = {"random": random.random, "uniform": random.uniform, "gauss": random.gauss, "randint": random.randint}
_TIME = {"time": time.time}
FUNCTIONS = dict(_MATH, **_RANDOM, **_TIME)
_MODULES = {"math": _MATH, "random": _RANDOM, "time": _TIME}
VARIABLES = ("i", "t")

_BINARY = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
           ast.FloorDiv: operator.floordiv, ast.Mod: operator.mod, ast.Pow: operator.pow}
_UNARY = {ast.UAdd: operator.pos, ast.USub: operator.neg, ast.Not: operator.not_}
_COMPARE = {ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt, ast.LtE: operator.le,
            ast.Gt: operator.gt, ast.GtE: operator.ge, ast.In: lambda a, b: a in b,
            ast.NotIn: lambda a, b: a not in b}


class ExpressionError(ValueError):
    """An expression that cannot be parsed or evaluated; the text says why."""


class Expression:
    """One field's expression, parsed once: `Expression("sin(i/100)").evaluate(i=1, t=0.0)`."""

    def __init__(self, text):
        if not isinstance(text, str):
            raise ExpressionError("an expression is text, got %s" % type(text).__name__)
        self.text = text.strip()
        if not self.text:
            raise ExpressionError("empty expression")
        if len(self.text) > MAX_EXPRESSION_CHARS:
            raise ExpressionError("expression longer than %d characters" % MAX_EXPRESSION_CHARS)
        try:
            self._tree = ast.parse(self.text, mode="eval").body
        except SyntaxError as e:
            raise ExpressionError("not a Python expression: %s" % (e.msg or e)) from None
        except (ValueError, RecursionError, MemoryError) as e:  # null bytes, absurd nesting
            raise ExpressionError("not a Python expression: %s" % e) from None
        _check(self._tree)  # refuse what can never work before the first publish

    def evaluate(self, **variables):
        try:
            return _Evaluator(variables).value(self._tree)
        except ExpressionError:
            raise
        except RecursionError:
            raise ExpressionError("expression nested too deeply") from None
        except (ArithmeticError, ValueError, TypeError, IndexError, KeyError) as e:
            # ZeroDivisionError, math domain error, 'str' + 'int', [1][5]: Python's own words
            raise ExpressionError("%s: %s" % (type(e).__name__, e)) from None


def names_help():
    return "i (publish count), t (ROS time, s), math's functions and constants (sin, cos, pi, ...), " \
           "random(), uniform(a, b), gauss(mu, sigma), randint(a, b), time()"


def _check(node):
    """Static check: every node is of a kind the evaluator understands."""
    allowed = (ast.Constant, ast.Name, ast.BinOp, ast.UnaryOp, ast.BoolOp, ast.Compare, ast.IfExp, ast.Call,
               ast.List, ast.Tuple, ast.Dict, ast.Subscript, ast.Attribute, ast.Load, ast.operator, ast.unaryop,
               ast.boolop, ast.cmpop, ast.Slice)
    for child in ast.walk(node):
        if not isinstance(child, allowed):
            raise ExpressionError("%s is not allowed in a field expression (only numbers, text, arithmetic, "
                                  "comparisons, 'a if c else b', lists and function calls)" % _describe(child))
        if isinstance(child, ast.Attribute):
            _module_function(child)
        if isinstance(child, ast.Call) and child.keywords:
            raise ExpressionError("keyword arguments are not allowed: write %s(...) with positional arguments"
                                  % ast.unparse(child.func))
        if isinstance(child, ast.Dict) and any(k is None for k in child.keys):
            raise ExpressionError("'**' in a dict is not allowed")
        if isinstance(child, (ast.BinOp, ast.UnaryOp, ast.Compare)):
            ops = child.ops if isinstance(child, ast.Compare) else [child.op]
            for op in ops:
                if type(op) not in _BINARY and type(op) not in _UNARY and type(op) not in _COMPARE:
                    raise ExpressionError("operator %s is not allowed" % type(op).__name__)


def _describe(node):
    names = {ast.Lambda: "lambda", ast.ListComp: "a comprehension", ast.GeneratorExp: "a generator",
             ast.NamedExpr: "':='", ast.JoinedStr: "an f-string", ast.Starred: "'*' unpacking",
             ast.Await: "await", ast.Yield: "yield"}
    return names.get(type(node), type(node).__name__)


def _module_function(node):
    """`math.sin` and the like: the only attribute access there is."""
    if isinstance(node.value, ast.Name) and node.value.id in _MODULES:
        functions = _MODULES[node.value.id]
        if node.attr in functions:
            return functions[node.attr]
        raise ExpressionError("%s.%s is not available (from %s: %s)"
                              % (node.value.id, node.attr, node.value.id,
                                 ", ".join(sorted(functions)) if len(functions) < 10 else "its public functions"))
    raise ExpressionError("attribute access (.%s) is not allowed; only math.<name> (or random./time.)" % node.attr)


class _Evaluator:
    def __init__(self, variables):
        self.variables = variables

    def value(self, node):
        method = getattr(self, "_" + type(node).__name__, None)
        if method is None:
            raise ExpressionError("%s is not allowed in a field expression" % _describe(node))
        return method(node)

    def _Constant(self, node):
        if isinstance(node.value, (int, float, str, bool)):
            return node.value
        raise ExpressionError("the literal %r is not allowed" % (node.value,))

    def _Name(self, node):
        if node.id in self.variables:
            return self.variables[node.id]
        if node.id in FUNCTIONS:
            return FUNCTIONS[node.id]
        raise ExpressionError("name '%s' is not defined (there are: %s)" % (node.id, names_help()))

    def _Attribute(self, node):
        return _module_function(node)

    def _BinOp(self, node):
        left, right = self.value(node.left), self.value(node.right)
        op = type(node.op)
        _bound(op, left, right)
        return _checked(_BINARY[op](left, right))

    def _UnaryOp(self, node):
        return _UNARY[type(node.op)](self.value(node.operand))

    def _BoolOp(self, node):
        result = None
        for operand in node.values:
            result = self.value(operand)
            if isinstance(node.op, ast.And) and not result:
                return result
            if isinstance(node.op, ast.Or) and result:
                return result
        return result

    def _Compare(self, node):
        left = self.value(node.left)
        for op, right_node in zip(node.ops, node.comparators):
            right = self.value(right_node)
            if not _COMPARE[type(op)](left, right):
                return False
            left = right
        return True

    def _IfExp(self, node):
        return self.value(node.body) if self.value(node.test) else self.value(node.orelse)

    def _Call(self, node):
        function = self.value(node.func)
        if not callable(function) or function not in FUNCTIONS.values():
            raise ExpressionError("%s is not a function" % ast.unparse(node.func))
        return _checked(function(*[self.value(a) for a in node.args]))

    def _List(self, node):
        return [self.value(e) for e in node.elts]

    _Tuple = _List

    def _Dict(self, node):
        out = {}
        for key, value in zip(node.keys, node.values):
            key = self.value(key)
            if not isinstance(key, str):
                raise ExpressionError("a dict's keys are field names (text), got %r" % (key,))
            out[key] = self.value(value)
        return out

    def _Subscript(self, node):
        container = self.value(node.value)
        if not isinstance(container, (list, str)):
            raise ExpressionError("only lists and text can be indexed, not %s" % type(container).__name__)
        if isinstance(node.slice, ast.Slice):
            bounds = (node.slice.lower, node.slice.upper, node.slice.step)
            parts = [None if p is None else self.value(p) for p in bounds]
            return container[slice(*parts)]
        return container[self.value(node.slice)]


def _bound(op, left, right):
    """Refuse the few operations whose result could fill memory or take minutes."""
    if op is ast.Pow and isinstance(left, int) and isinstance(right, int) and not isinstance(left, bool):
        if right > 0 and abs(left) > 1 and left.bit_length() * right > MAX_INT_BITS:
            raise ExpressionError("%d ** %d is too large" % (left, right))
    if op is ast.Mult:
        for seq, n in ((left, right), (right, left)):
            if isinstance(seq, (str, list)) and isinstance(n, int) and len(seq) * max(n, 0) > MAX_SEQUENCE:
                raise ExpressionError("a sequence of more than %d elements" % MAX_SEQUENCE)
    if op is ast.Add and isinstance(left, (str, list)) and isinstance(right, (str, list)):
        if len(left) + len(right) > MAX_SEQUENCE:
            raise ExpressionError("a sequence of more than %d elements" % MAX_SEQUENCE)


def _checked(value):
    if isinstance(value, int) and not isinstance(value, bool) and value.bit_length() > MAX_INT_BITS:
        raise ExpressionError("an integer of more than %d bits" % MAX_INT_BITS)
    return value
