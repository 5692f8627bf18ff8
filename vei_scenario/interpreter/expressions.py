"""OpenSCENARIO 1.x expressions: ``${...}`` in attribute values.

Grammar (ASAM OpenSCENARIO 1.2, section "Expressions"): numbers, ``$parameter`` references, ``+ - * /
%``, unary minus, parentheses, the functions round, floor, ceil, sqrt, pow, sin, cos, tan, asin, acos,
atan, sign, abs, max, min, and the boolean operators ``not``, ``and``, ``or`` on 0/1 values. A
recursive-descent parser; nothing is passed to Python's ``eval``.
"""

from __future__ import annotations

import functools
import math
import re
from collections.abc import Callable

_TOKEN = re.compile(
    r"\s*(?:(?P<num>\d+\.?\d*(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?)|(?P<param>\$[A-Za-z_][A-Za-z0-9_]*)"
    r"|(?P<name>[A-Za-z_][A-Za-z0-9_]*)|(?P<op>[-+*/%(),]))"
)

_FUNCTIONS = {
    "round": (1, lambda a: float(math.floor(a + 0.5)) if a >= 0 else -float(math.floor(-a + 0.5))),
    "floor": (1, lambda a: float(math.floor(a))),
    "ceil": (1, lambda a: float(math.ceil(a))),
    "sqrt": (1, math.sqrt),
    "pow": (2, math.pow),
    "sin": (1, math.sin),
    "cos": (1, math.cos),
    "tan": (1, math.tan),
    "asin": (1, math.asin),
    "acos": (1, math.acos),
    "atan": (1, math.atan),
    "sign": (1, lambda a: float((a > 0) - (a < 0))),
    "abs": (1, abs),
    "max": (2, max),
    "min": (2, min),
}


class ExpressionError(ValueError):
    pass


def _tokens(text: str) -> list[tuple[str, str]]:
    out, pos = [], 0
    text = text.rstrip()
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if not m or m.end() == pos:
            raise ExpressionError(f"unexpected character {text[pos:].strip()[:1]!r} at position {pos + 1}")
        kind = m.lastgroup
        out.append((kind, m.group(kind)))
        pos = m.end()
    return out


def evaluate(expression: str, parameters: dict[str, object]) -> float:
    """Value of ``expression`` (the text inside ``${...}``); parameters by name without ``$``."""
    return compile_expression(expression)(parameters)


def _number(value: object, name: str) -> float:
    if isinstance(value, bool):
        return 1.0 if value else 0.0
    if isinstance(value, str):
        if value in ("true", "false"):
            return 1.0 if value == "true" else 0.0
        try:
            return float(value)
        except ValueError:
            raise ExpressionError(f"parameter ${name} = {value!r} is not a number") from None
    return float(value)


Compiled = Callable[[dict[str, object]], float]


@functools.lru_cache(maxsize=1024)
def compile_expression(expression: str) -> Compiled:
    """``expression`` parsed once into a function of the parameters: a sweep evaluates the same few
    expressions for every variant. Syntax errors raise here, value errors (an undeclared or non-numeric
    parameter, division by zero, a function outside its domain) when the function is called."""
    toks = _tokens(expression)
    pos = 0

    def peek() -> tuple[str, str] | None:
        return toks[pos] if pos < len(toks) else None

    def take(expected: str | None = None) -> tuple[str, str]:
        nonlocal pos
        tok = peek()
        if tok is None or (expected is not None and tok[1] != expected):
            raise ExpressionError(
                f"expected {expected or 'a value'} at the end"
                if tok is None
                else f"expected {expected!r}, found {tok[1]!r}"
            )
        pos += 1
        return tok

    def disjunction() -> Compiled:
        left = conjunction()
        while peek() == ("name", "or"):
            take()
            a, b = left, conjunction()
            left = lambda p, a=a, b=b: 1.0 if (a(p) != 0) | (b(p) != 0) else 0.0  # noqa: E731  (both evaluated)
        return left

    def conjunction() -> Compiled:
        left = negation()
        while peek() == ("name", "and"):
            take()
            a, b = left, negation()
            left = lambda p, a=a, b=b: 1.0 if (a(p) != 0) & (b(p) != 0) else 0.0  # noqa: E731  (both evaluated)
        return left

    def negation() -> Compiled:
        if peek() == ("name", "not"):
            take()
            a = negation()
            return lambda p: 0.0 if a(p) != 0 else 1.0
        return additive()

    def additive() -> Compiled:
        left = multiplicative()
        while peek() in (("op", "+"), ("op", "-")):
            op = take()[1]
            a, b = left, multiplicative()
            left = (lambda p, a=a, b=b: a(p) + b(p)) if op == "+" else (lambda p, a=a, b=b: a(p) - b(p))
        return left

    def divide(a: Compiled, b: Compiled, op: str) -> Compiled:
        def f(p: dict[str, object]) -> float:
            left, right = a(p), b(p)
            if right == 0:
                raise ExpressionError("division by zero")
            return left / right if op == "/" else math.fmod(left, right)

        return f

    def multiplicative() -> Compiled:
        left = unary()
        while peek() in (("op", "*"), ("op", "/"), ("op", "%")):
            op = take()[1]
            a, b = left, unary()
            left = (lambda p, a=a, b=b: a(p) * b(p)) if op == "*" else divide(a, b, op)
        return left

    def unary() -> Compiled:
        if peek() == ("op", "-"):
            take()
            a = unary()
            return lambda p: -a(p)
        if peek() == ("op", "+"):
            take()
            return unary()
        return primary()

    def parameter(name: str) -> Compiled:
        def f(p: dict[str, object]) -> float:
            if name not in p:
                raise ExpressionError(f"parameter ${name} is not declared")
            return _number(p[name], name)

        return f

    def call(name: str, fn, args: list[Compiled]) -> Compiled:
        def f(p: dict[str, object]) -> float:
            values = [a(p) for a in args]
            try:
                return float(fn(*values))
            except (ValueError, OverflowError) as exc:
                raise ExpressionError(f"{name}{tuple(values)}: {exc}") from None

        return f

    def primary() -> Compiled:
        kind, text = take()
        if kind == "num":
            value = float(text)
            return lambda p: value
        if kind == "param":
            return parameter(text[1:])
        if kind == "op" and text == "(":
            inner = disjunction()
            take(")")
            return inner
        if kind == "name" and text in _FUNCTIONS:
            arity, fn = _FUNCTIONS[text]
            take("(")
            args = [disjunction()]
            while peek() == ("op", ","):
                take()
                args.append(disjunction())
            take(")")
            if len(args) != arity:
                raise ExpressionError(f"{text}() takes {arity} argument(s), got {len(args)}")
            return call(text, fn, args)
        raise ExpressionError(f"unexpected {text!r}")

    compiled = disjunction()
    if pos != len(toks):
        raise ExpressionError(f"unexpected {toks[pos][1]!r}")
    return compiled
